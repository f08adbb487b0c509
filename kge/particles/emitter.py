"""One emitter's running state, and the ``Particles`` resource that holds them all.

:class:`EmitterState` turns a :class:`~kge.components.particles.ParticleEmitter`
and the entity's pose into particles: it keeps the fractional emission carried
between frames (a rate of 30/s at 60 fps emits every other frame), the pending
bursts, the time since the emitter started, the previous position (for
per-metre rates and for spreading a frame's births along the path travelled,
so a fast smoke trail is a line, not a row of puffs), the random generator
(seeded by the emitter's ``seed`` or the entity id: the same seed gives the same
particles) and the over-life tables.

:class:`Particles` is the world resource the particle system owns: entity ->
state, plus the code API to start, stop and burst emitters and to read their
particles back (tests, gameplay).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from kge.components.particles import LIMIT, TAU, ParticleCollision, ParticleEmitter, span
from kge.errors import EntityNotFoundError, ValidationError, where
from kge.particles.curves import color_table, life_index, size_table
from kge.particles.grid import StaticGrid
from kge.particles.pool import ParticlePool
from kge.particles.shapes import sample_shape
from kge.snapshot import carry_running
from kge.validate import at_most, positive

Pose = tuple[float, float, float]
#: prewarm is simulated in steps of this many seconds
PREWARM_STEP = 1.0 / 30.0


@dataclass(slots=True)
class Burst:
    count: int
    position: tuple[float, float] | None = None  #: world metres
    direction: float | None = None  #: world radians


def carried_velocity(velocity: tuple[float, float], share: float) -> np.ndarray:
    """``share`` of a body's ``velocity``, no faster than :data:`~kge.components.particles.
    LIMIT` (a body's velocity is only bounded by float64, the particle rows are float32).

    >>> carried_velocity((3e307, 4e307), 100.0).tolist()
    [600000.0, 800000.0]
    """
    vx, vy = velocity
    scale = max(abs(vx), abs(vy))
    if scale == 0.0 or share == 0.0:
        return np.zeros(2)
    ux, uy = vx / scale, vy / scale
    norm = math.hypot(ux, uy)
    speed = min(LIMIT, scale * norm * abs(share))  # an overflow to inf is capped here
    k = math.copysign(speed / norm, share)
    return np.array([ux * k, uy * k])


class EmitterState:
    """Particles and emission bookkeeping of one emitter entity."""

    def __init__(self, entity: int, em: ParticleEmitter) -> None:
        self.entity = entity
        self.pool = ParticlePool(em.max_particles)
        self.rng = np.random.default_rng(entity if em.seed is None else em.seed)
        self.carry = 0.0
        self.elapsed = 0.0  #: seconds since the emitter (re)started
        self.started = False
        self.was_emitting = False
        self.prev: Pose | None = None
        self.pending: list[Burst] = []
        self.finished = False
        self.born = 0  #: particles emitted so far (dropped ones not counted)
        self.bursts = 0  #: bursts fired so far (the emitter's own and requested ones)
        self.pose: Pose = (0.0, 0.0, 0.0)  #: the entity pose at the last update
        self._style: tuple[Any, ...] = ()
        self.sizes = size_table((0.1,))
        self.colors = color_table(((255, 255, 255),), (255.0,))

    # -- looks --------------------------------------------------------------------------------
    def refresh_style(self, em: ParticleEmitter) -> None:
        """Rebuild the over-life tables when size, colour or alpha changed."""
        style = (em.size, em.color, em.opacity)
        if style != self._style:
            self._style = style
            self.sizes = size_table(em.size)  # type: ignore[arg-type]
            self.colors = color_table(em.color, em.opacity)  # type: ignore[arg-type]
        if em.max_particles != self.pool.max_particles:
            self.pool.set_max(em.max_particles)

    def looks(self) -> tuple[np.ndarray, np.ndarray]:
        """(sizes, RGBA) of the live particles from their life fractions.

        The colours come back as one uint32 per particle (its 4 RGBA bytes): a
        gather of 4-byte words is several times faster than of (n, 4) bytes.
        ``.view(np.uint8).reshape(-1, 4)`` gives the channels.
        """
        p = self.pool
        idx = life_index(p.age[: p.count], p.life[: p.count])
        return self.sizes[idx], self.colors.view(np.uint32)[idx, 0]

    # -- emission -------------------------------------------------------------------------------
    def continuous(self, em: ParticleEmitter) -> bool:
        """Whether the rate-driven emission is on this frame."""
        if not em.emitting:
            return False
        if em.duration is not None:
            return self.elapsed + 1e-9 < em.duration  # 30 x (1/60) is a hair under 0.5
        return not em.one_shot  # a one-shot without a duration is its burst only

    def spawn(
        self,
        em: ParticleEmitter,
        n: int,
        pose: Pose,
        prev: Pose,
        velocity: tuple[float, float],
        collider: Any,
        dt: float,
        position: tuple[float, float] | None = None,
        direction: float | None = None,
    ) -> None:
        """Make ``n`` particles born over the last ``dt`` seconds along prev -> pose."""
        room = self.pool.max_particles - self.pool.count
        if n > room:  # full: drop the rest (the arrays never grow past the cap)
            self.pool.dropped += n - room
            n = room
        if n <= 0:
            return
        rng = self.rng
        frac = rng.random(n) if dt > 0 else np.zeros(n)
        age = frac * dt
        local = em.space == "local"
        offsets = sample_shape(em.shape, rng, n, collider) + np.asarray(em.offset)
        half = em.spread * 0.5
        jitter = rng.uniform(-half, half, n) if half > 0 else np.zeros(n)
        lo, hi = span(em.speed)
        speed = rng.uniform(lo, hi, n) if hi > lo else np.full(n, lo)
        lo, hi = span(em.lifetime)
        life = rng.uniform(lo, hi, n) if hi > lo else np.full(n, lo)
        lo, hi = span(em.spin)
        spin = rng.uniform(lo, hi, n) if hi > lo else np.full(n, lo)
        x, y, a = pose
        # angles are kept below 2 pi before they reach the float32 rows: a finite
        # Transform.angle or direction of 1e300 (or their sum) would overflow there
        a = math.remainder(a, TAU)
        if direction is not None:
            direction = math.remainder(direction, TAU)
        if local:
            base = em.direction if direction is None else direction - a
            pos = offsets
            if position is not None:  # a world point into the entity frame
                c, s = math.cos(-a), math.sin(-a)
                dx, dy = position[0] - x, position[1] - y
                pos = offsets + np.array([c * dx - s * dy, s * dx + c * dy])
            carried = np.zeros(2)
        else:
            base = a + em.direction if direction is None else direction
            c, s = math.cos(a), math.sin(a)
            rotated = np.stack(
                [c * offsets[:, 0] - s * offsets[:, 1], s * offsets[:, 0] + c * offsets[:, 1]],
                axis=1,
            )
            if position is not None:
                origin = np.broadcast_to(np.asarray(position, float), (n, 2))
            else:  # spread births along the path travelled this frame
                d = np.array([x - prev[0], y - prev[1]])
                origin = np.array([x, y]) - frac[:, None] * d
            pos = origin + rotated
            carried = carried_velocity(velocity, em.inherit_velocity)
        theta = math.remainder(base, TAU) + jitter
        vel = np.stack([np.cos(theta) * speed, np.sin(theta) * speed], axis=1) + carried
        pos = pos + vel * age[:, None]
        self.born += self.pool.add(pos, vel, life, theta, spin, age)

    def advance(
        self,
        em: ParticleEmitter,
        dt: float,
        pose: Pose,
        velocity: tuple[float, float],
        collider: Any = None,
        grid: StaticGrid | None = None,
        attractors: list[tuple[float, float, float, float]] | None = None,
    ) -> None:
        """One frame of game time: move the live particles, then emit the new ones
        (``attractors``: (x, y, strength, radius) pulling world-space particles)."""
        self.refresh_style(em)
        if not self.started:
            self.started = True
            self.prev = pose
            if em.prewarm > 0:
                self._prewarm(em, pose, velocity, collider, grid)
        if em.emitting and not self.was_emitting:
            self.elapsed = 0.0
            self.carry = 0.0
            if em.burst:
                self.pending.append(Burst(em.burst))
        self.was_emitting = em.emitting
        prev = self.prev if self.prev is not None else pose
        self._move(em, dt, grid, pose, attractors if em.space == "world" else None)
        on = self.continuous(em)
        if on and dt > 0:
            moved = math.hypot(pose[0] - prev[0], pose[1] - prev[1])
            self.carry += em.rate * dt + em.rate_per_meter * moved
            n = int(self.carry)
            self.carry -= n
            if n:
                self.spawn(em, n, pose, prev, velocity, collider, dt)
        pending, self.pending = self.pending, []
        self.bursts += len(pending)
        for b in pending:
            self.spawn(em, b.count, pose, pose, velocity, collider, 0.0, b.position, b.direction)
        if dt > 0:
            self.elapsed += dt
        self.prev = pose
        self.pose = pose
        self.finished = (
            em.one_shot and not self.continuous(em) and not self.pending and self.pool.count == 0
        )

    def _move(self, em: ParticleEmitter, dt: float, grid: StaticGrid | None,
              pose: Pose | None = None,
              attractors: list[tuple[float, float, float, float]] | None = None) -> None:
        use_grid = grid if em.collide != "none" and em.space == "world" else None
        bounce = em.bounciness if em.collide == "bounce" else None
        around = None
        if em.radial_acceleration or em.tangential_acceleration or em.orbit:
            ox, oy = em.offset
            if em.space == "local" or pose is None:
                cx, cy = ox, oy
            else:  # the emitter's origin in the world: the entity plus its turned offset
                x, y, a = pose
                c, s = math.cos(a), math.sin(a)
                cx, cy = x + c * ox - s * oy, y + s * ox + c * oy
            around = (cx, cy, em.radial_acceleration, em.tangential_acceleration, em.orbit)
        self.pool.step(dt, em.acceleration, em.drag, use_grid, bounce, around, attractors)

    def _prewarm(
        self,
        em: ParticleEmitter,
        pose: Pose,
        velocity: tuple[float, float],
        collider: Any,
        grid: StaticGrid | None,
    ) -> None:
        steps = math.ceil(em.prewarm / PREWARM_STEP)
        for _ in range(steps):
            self._move(em, PREWARM_STEP, grid, pose)
            if self.continuous(em):
                self.carry += em.rate * PREWARM_STEP
                n = int(self.carry)
                self.carry -= n
                self.spawn(em, n, pose, pose, velocity, collider, PREWARM_STEP)
            self.elapsed += PREWARM_STEP


@carry_running
class Particles:
    """The particle system's resource: every emitter's state, and the code API.

    >>> from kge.world import World
    >>> from kge.components import Transform
    >>> w = World()
    >>> p = w.insert_resource(Particles(w))
    >>> e = w.spawn(Transform(), ParticleEmitter(rate=0.0))
    >>> p.burst(e, 10); p.count(e)   # counted once the system has run
    0
    """

    def __init__(self, world: Any) -> None:
        self.world = world
        self.states: dict[int, EmitterState] = {}
        #: the static-collider grid, rebuilt when static colliders change
        self.grid: StaticGrid | None = None
        self.grid_dirty = True
        self._cell = 0.1

    @property
    def cell(self) -> float:
        """Grid cell size (metres) for particle collisions, in (0, 1e6]; a change
        rebuilds the grid."""
        return self._cell

    @cell.setter
    def cell(self, value: float) -> None:
        v = at_most(positive(value, "Particles", "cell"), LIMIT, "Particles", "cell", "m")
        if v != self._cell:
            self._cell = v
            self.grid_dirty = True

    # -- snapshots (kge.snapshot.carry_running) ------------------------------------------
    def export_running(self) -> dict[int, EmitterState]:
        """Every emitter's state (particles, emission bookkeeping, random generator)."""
        return dict(self.states)

    def import_running(self, states: dict[int, EmitterState]) -> None:
        """Continue the emitters of a restored world from their snapshotted states."""
        for entity, st in states.items():
            if self.world.exists(entity) and self.world.has(entity, ParticleEmitter):
                self.states[entity] = st

    def state(self, entity: int) -> EmitterState:
        em = self._emitter(entity, "state")
        st = self.states.get(entity)
        if st is None:
            st = self.states[entity] = EmitterState(entity, em)
        return st

    def _emitter(self, entity: int, op: str) -> ParticleEmitter:
        em = self.world.try_get(entity, ParticleEmitter) if self.world.exists(entity) else None
        if em is None:
            raise EntityNotFoundError(f"Particles.{op}: entity {entity} has no ParticleEmitter")
        return em

    def burst(
        self,
        entity: int,
        count: int,
        position: tuple[float, float] | None = None,
        direction: float | None = None,
    ) -> None:
        """Emit ``count`` particles on the next update (at ``position`` along ``direction``)."""
        from kge.components.particles import ParticleBurst

        b = ParticleBurst(entity, count, position, direction)  # validates
        self._emitter(entity, "burst")
        self.state(entity).pending.append(Burst(b.count, b.position, b.direction))

    def start(self, entity: int) -> None:
        """Turn continuous emission on (the emitter's ``burst`` fires again)."""
        self._emitter(entity, "start").emitting = True

    def stop(self, entity: int) -> None:
        """Stop emitting; live particles finish their lives."""
        self._emitter(entity, "stop").emitting = False

    def clear(self, entity: int) -> None:
        """Remove every live particle of the emitter at once."""
        self._emitter(entity, "clear")
        self.state(entity).pool.clear()

    def count(self, entity: int) -> int:
        st = self.states.get(entity)
        return 0 if st is None else st.pool.count

    def total(self) -> int:
        """Live particles over all emitters."""
        return sum(st.pool.count for st in self.states.values())

    def positions(self, entity: int) -> np.ndarray:
        """World positions of the emitter's live particles, (n, 2) (a copy)."""
        em = self._emitter(entity, "positions")
        st = self.states.get(entity)
        if st is None:
            return np.zeros((0, 2), np.float32)
        pts = st.pool.pos[: st.pool.count].astype(float)
        if em.space == "local":
            x, y, a = st.pose
            c, s = math.cos(a), math.sin(a)
            pts = np.stack(
                [x + c * pts[:, 0] - s * pts[:, 1], y + s * pts[:, 0] + c * pts[:, 1]], 1
            )
        return pts

    def check(self, entity: int | None, em: ParticleEmitter) -> None:
        """Refuse settings no state could honour (called by the plugin's validator)."""
        if em.collide != "none" and em.space == "local":
            collide = ParticleCollision(em.collide).name
            raise ValidationError(
                f"{where(entity, 'ParticleEmitter', 'collide')} = ParticleCollision.{collide} "
                "needs space=ParticleSpace.WORLD (particles that move with the emitter cannot "
                "collide)"
            )
