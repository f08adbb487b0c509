"""The live particles of one emitter: a structure of numpy arrays, updated in bulk.

Particles are not entities. Each emitter owns one :class:`ParticlePool`:
positions, velocities, ages, lifetimes, angles and spins of its live particles
in the first ``count`` rows of float32 arrays. A frame is a handful of whole-array
operations (integrate, age, compact the dead away), whatever the count; nothing
loops over particles in Python.

The arrays grow by doubling up to the emitter's ``max_particles`` and never
beyond it: particles asked for past that cap are dropped (``dropped`` counts
them), so a runaway rate cannot eat memory.

>>> import numpy as np
>>> pool = ParticlePool(max_particles=4)
>>> pool.add(np.zeros((6, 2)), np.ones((6, 2)), np.full(6, 1.0), np.zeros(6), np.zeros(6))
4
>>> pool.count, pool.dropped
(4, 2)
>>> pool.step(0.5, (0.0, 0.0), 0.0)
>>> pool.pos[0].tolist(), pool.count
([0.5, 0.5], 4)
>>> pool.step(0.5, (0.0, 0.0), 0.0); pool.count
0
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

import numpy as np

if TYPE_CHECKING:
    from kge.particles.grid import StaticGrid

F = np.float32


class ParticlePool:
    """Structure-of-arrays storage and integration of one emitter's particles."""

    FIELDS = ("pos", "vel", "age", "life", "angle", "spin")

    def __init__(self, max_particles: int) -> None:
        self.max_particles = int(max_particles)
        self.count = 0
        self.dropped = 0  #: particles refused because the pool was full
        self.capacity = 0
        self.pos = np.zeros((0, 2), F)
        self.vel = np.zeros((0, 2), F)
        self.age = np.zeros(0, F)
        self.life = np.zeros(0, F)
        self.angle = np.zeros(0, F)
        self.spin = np.zeros(0, F)

    def _reserve(self, need: int) -> None:
        """Grow the arrays (doubling, capped at ``max_particles``) to hold ``need`` rows."""
        if need <= self.capacity:
            return
        cap = min(self.max_particles, max(64, 1 << (need - 1).bit_length()))
        for name in self.FIELDS:
            old = getattr(self, name)
            new = np.zeros((cap, *old.shape[1:]), F)
            new[: self.count] = old[: self.count]
            setattr(self, name, new)
        self.capacity = cap

    def set_max(self, max_particles: int) -> None:
        """Change the cap; live particles past a lower cap are dropped (oldest kept)."""
        self.max_particles = int(max_particles)
        if self.count > self.max_particles:
            self.dropped += self.count - self.max_particles
            self.count = self.max_particles
        if self.capacity > self.max_particles:
            for name in self.FIELDS:
                setattr(self, name, getattr(self, name)[: self.max_particles].copy())
            self.capacity = self.max_particles

    def add(
        self,
        pos: np.ndarray,
        vel: np.ndarray,
        life: np.ndarray,
        angle: np.ndarray,
        spin: np.ndarray,
        age: np.ndarray | None = None,
    ) -> int:
        """Append particles (rows of each array); returns how many fitted."""
        n = min(len(pos), self.max_particles - self.count)
        self.dropped += len(pos) - n
        if n <= 0:
            return 0
        self._reserve(self.count + n)
        s = slice(self.count, self.count + n)
        self.pos[s] = pos[:n]
        self.vel[s] = vel[:n]
        self.life[s] = life[:n]
        self.angle[s] = angle[:n]
        self.spin[s] = spin[:n]
        self.age[s] = 0.0 if age is None else age[:n]
        self.count += n
        return n

    def step(
        self,
        dt: float,
        acceleration: tuple[float, float],
        drag: float,
        grid: StaticGrid | None = None,
        bounce: float | None = None,
    ) -> None:
        """Advance every live particle ``dt`` seconds, then drop the dead.

        ``grid`` collides particles with static geometry: ``bounce=None`` kills
        those that enter a solid cell, a number reflects them with that
        restitution.
        """
        n = self.count
        if n == 0 or dt <= 0.0:
            return
        pos, vel = self.pos[:n], self.vel[:n]
        age = self.age[:n]
        age += F(dt)
        ax, ay = acceleration
        if ax or ay:
            vel += np.array((ax * dt, ay * dt), F)
        if drag > 0.0:
            vel *= F(math.exp(-drag * dt))
        if grid is not None:
            old = pos.copy()
            pos += vel * F(dt)
            hit = grid.collide(old, pos, vel, bounce)
            if bounce is None and hit is not None:
                age[hit] = np.inf  # dies below
        else:
            pos += vel * F(dt)
        self.angle[:n] += self.spin[:n] * F(dt)
        alive = age < self.life[:n]
        if not alive.all():
            k = int(np.count_nonzero(alive))
            for name in self.FIELDS:
                arr = getattr(self, name)
                arr[:k] = arr[:n][alive]
            self.count = k

    def clear(self) -> None:
        self.count = 0
