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
    """Structure-of-arrays storage and integration of one emitter's particles.

    One float32 array ``data`` of shape (8, capacity) holds a row per field
    (x, y, vx, vy, age, life, angle, spin), so every field of the live
    particles is a contiguous run and removing the dead moves all fields in one
    fancy-indexed copy. ``pos``, ``vel``, ``age``... are views of it.
    """

    ROWS = 8

    def __init__(self, max_particles: int) -> None:
        self.max_particles = int(max_particles)
        self.count = 0
        self.dropped = 0  #: particles refused because the pool was full
        self.data = np.zeros((self.ROWS, 0), F)

    @property
    def capacity(self) -> int:
        return int(self.data.shape[1])

    @property
    def pos(self) -> np.ndarray:
        """(capacity, 2) view of the positions (rows past ``count`` are stale)."""
        return self.data[0:2].T

    @property
    def vel(self) -> np.ndarray:
        return self.data[2:4].T

    @property
    def age(self) -> np.ndarray:
        return self.data[4]

    @property
    def life(self) -> np.ndarray:
        return self.data[5]

    @property
    def angle(self) -> np.ndarray:
        return self.data[6]

    @property
    def spin(self) -> np.ndarray:
        return self.data[7]

    def _reserve(self, need: int) -> None:
        """Grow the arrays (doubling, capped at ``max_particles``) to hold ``need`` rows."""
        if need <= self.capacity:
            return
        cap = min(self.max_particles, max(64, 1 << (need - 1).bit_length()))
        new = np.zeros((self.ROWS, cap), F)
        new[:, : self.count] = self.data[:, : self.count]
        self.data = new

    def set_max(self, max_particles: int) -> None:
        """Change the cap; live particles past a lower cap are dropped."""
        self.max_particles = int(max_particles)
        if self.count > self.max_particles:
            self.dropped += self.count - self.max_particles
            self.count = self.max_particles
        if self.capacity > self.max_particles:
            self.data = self.data[:, : self.max_particles].copy()

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
        d = self.data[:, self.count : self.count + n]
        d[0:2] = pos[:n].T
        d[2:4] = vel[:n].T
        d[4] = 0.0 if age is None else age[:n]
        d[5] = life[:n]
        d[6] = angle[:n]
        d[7] = spin[:n]
        self.count += n
        return n

    def step(
        self,
        dt: float,
        acceleration: tuple[float, float],
        drag: float,
        grid: StaticGrid | None = None,
        bounce: float | None = None,
        around: tuple[float, float, float, float, float] | None = None,
        attractors: list[tuple[float, float, float, float]] | None = None,
    ) -> None:
        """Advance every live particle ``dt`` seconds, then drop the dead.

        ``around`` = (cx, cy, radial, tangential, orbit): accelerations away from and
        counter-clockwise round the point (cx, cy) (m/s^2), and an orbit (rad/s) that
        turns the positions round it. ``attractors``: (x, y, strength, radius) each,
        pulling particles within radius (strength at the centre, linear to 0).

        ``grid`` collides particles with static geometry: ``bounce=None`` kills
        those that enter a solid cell, a number reflects them with that
        restitution. The dead are replaced by live particles from the end of
        the pool (swap-remove), so the cost is the number of deaths, not the count.
        """
        n = self.count
        if n == 0 or dt <= 0.0:
            return
        d = self.data[:, :n]
        fdt = F(dt)
        d[4] += fdt
        ax, ay = acceleration
        if ax:
            d[2] += F(ax * dt)
        if ay:
            d[3] += F(ay * dt)
        if around is not None:
            self._around(d, dt, *around)
        for ax_, ay_, strength, radius in attractors or ():
            self._attract(d, dt, ax_, ay_, strength, radius)
        if drag > 0.0:
            d[2:4] *= F(math.exp(-drag * dt))
        if grid is not None:
            old = d[0:2].T.copy()
            d[0:2] += d[2:4] * fdt
            pos, vel = d[0:2].T, d[2:4].T
            hit = grid.collide(old, pos, vel, bounce)
            if bounce is None and hit is not None:
                d[4, hit] = np.inf  # dies below
        else:
            d[0:2] += d[2:4] * fdt
        d[6] += d[7] * fdt
        if around is not None and around[4]:
            self._orbit(d, dt, around[0], around[1], around[4])
        alive = d[4] < d[5]
        dead = np.flatnonzero(~alive)
        if len(dead):
            m = n - len(dead)
            holes = dead[dead < m]
            if len(holes):
                self.data[:, holes] = self.data[:, np.flatnonzero(alive[m:]) + m]
            self.count = m

    @staticmethod
    def _around(d: np.ndarray, dt: float, cx: float, cy: float, radial: float,
                tangential: float, orbit: float) -> None:
        """Radial and tangential accelerations about (cx, cy), all particles at once."""
        if not (radial or tangential):
            return
        rx, ry = d[0] - F(cx), d[1] - F(cy)
        r = np.hypot(rx, ry)
        inv = np.divide(F(dt), r, out=np.zeros_like(r), where=r > 0)  # at the centre: none
        ux, uy = rx * inv, ry * inv  # unit vectors times dt
        d[2] += F(radial) * ux - F(tangential) * uy
        d[3] += F(radial) * uy + F(tangential) * ux

    @staticmethod
    def _attract(d: np.ndarray, dt: float, x: float, y: float, strength: float,
                 radius: float) -> None:
        """Pull towards (x, y): strength x (1 - distance / radius) inside the radius."""
        dx, dy = F(x) - d[0], F(y) - d[1]
        dist = np.hypot(dx, dy)
        near = (dist < radius) & (dist > 0)
        if not near.any():
            return
        k = np.where(near, F(strength * dt) * (1 - dist / F(radius)), 0)
        k = np.divide(k, dist, out=np.zeros_like(k), where=near)
        d[2] += k * dx
        d[3] += k * dy

    @staticmethod
    def _orbit(d: np.ndarray, dt: float, cx: float, cy: float, orbit: float) -> None:
        """Turn positions (and velocities, so motion stays consistent) by orbit * dt."""
        c, s = F(math.cos(orbit * dt)), F(math.sin(orbit * dt))
        rx, ry = d[0] - F(cx), d[1] - F(cy)
        d[0], d[1] = F(cx) + c * rx - s * ry, F(cy) + s * rx + c * ry
        vx, vy = d[2].copy(), d[3].copy()
        d[2], d[3] = c * vx - s * vy, s * vx + c * vy

    def clear(self) -> None:
        self.count = 0
