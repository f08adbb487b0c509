"""The particle systems and ``ParticlesPlugin``.

* :class:`ParticleSystem` (UPDATE stage, ``EFFECTS`` set, after behaviours and
  animation): one vectorised update per emitter per frame on game time (so
  ``App.time_scale``, pause and single-stepping apply), births, bursts (the
  frame's :class:`~kge.components.particles.ParticleBurst` events, read from
  ``world.events``), one-shot clean-up, and collision with static colliders
  through the grid of :mod:`kge.particles.grid` (rebuilt only when static geometry
  comes or goes: dynamic bodies spawning and despawning over a large map cost
  nothing).
* :class:`ParticleTriggers` (FIXED stage, ``POST_PHYSICS`` set, after the contact
  events): turns each fixed step's physics ``Hit`` / ``ContactBegin`` on
  colliders with :class:`~kge.components.particles.BurstOnHit` into pending
  bursts.
* Drawing is a before-pass (:mod:`kge.render.passes`) that uploads each
  emitter's particles into one vertex list in the emitter's layer; it imports
  pyglet only when a frame is drawn.
"""

from __future__ import annotations

import functools
import math
import os
from typing import Any

import numpy as np

from kge.assets import assets_for
from kge.components.collider import Collider
from kge.components.particles import (
    BurstOnHit,
    EmitCollider,
    ParticleAttractor,
    ParticleBurst,
    ParticleEmitter,
)
from kge.components.rigidbody import BodyType, RigidBody
from kge.components.shapes import Box, Chain, Circle, Edge, Polygon
from kge.components.tracked import validate_writes
from kge.components.transform import Transform
from kge.errors import ValidationError, where
from kge.particles.emitter import Particles
from kge.particles.grid import StaticGrid
from kge.physics.events import ContactBegin, Hit
from kge.plugin import Plugin
from kge.render.passes import passes_for
from kge.schedule import Stage, System, SystemSet
from kge.world import World


def _is_static(world: World, entity: int, col: Collider) -> bool:
    body = entity if col.body is None else col.body
    rb = world.try_get(body, RigidBody)
    return rb is None or rb.type is BodyType.STATIC


def _body_pose(world: World, entity: int, col: Collider) -> tuple[float, float, float]:
    body = entity if col.body is None else col.body
    t = world.try_get(body, Transform)
    return (0.0, 0.0, 0.0) if t is None else (t.x, t.y, t.angle)


def _to_world(points: Any, pose: tuple[float, float, float]) -> np.ndarray:
    pts = np.asarray(points, float).reshape(-1, 2)
    x, y, a = pose
    c, s = math.cos(a), math.sin(a)
    return np.stack([x + c * pts[:, 0] - s * pts[:, 1], y + s * pts[:, 0] + c * pts[:, 1]], 1)


def static_geometry(
    world: World, members: set[int] | None = None
) -> tuple[list[np.ndarray], list[tuple[float, float, float]], list[np.ndarray]]:
    """World-space (polygons, circles, segments) of every non-sensor static collider;
    the entities of those colliders and their bodies are added to ``members``."""
    polys: list[np.ndarray] = []
    circles: list[tuple[float, float, float]] = []
    segs: list[np.ndarray] = []
    for e, (col,) in world.query(Collider):
        if col.sensor or not _is_static(world, e, col):
            continue
        if members is not None:
            members.add(e)
            if col.body is not None:
                members.add(col.body)
        pose = _body_pose(world, e, col)
        shape = col.shape
        if isinstance(shape, Circle):
            cx, cy = _to_world([shape.center], pose)[0]
            circles.append((float(cx), float(cy), shape.radius))
        elif isinstance(shape, Box):
            polys.append(_to_world(shape.vertices(), pose))
        elif isinstance(shape, Polygon):
            polys.append(_to_world(shape.vertices, pose))
        elif isinstance(shape, Edge):
            segs.append(_to_world([shape.v1, shape.v2], pose))
        elif isinstance(shape, Chain):
            segs.extend(_to_world(s, pose) for s in shape.segments())
    return polys, circles, segs


class ParticleSystem(System):
    """Updates and emits every emitter's particles (UPDATE stage). See the module docstring."""

    stage = Stage.UPDATE
    in_set = SystemSet.EFFECTS

    #: entities changed since the grid was built, past which it is simply rebuilt
    MAX_PENDING = 100_000

    def attach(self, world: World) -> None:
        super().attach(world)
        self.particles = world.try_resource(Particles) or world.insert_resource(Particles(world))
        world.on_remove(ParticleEmitter, self._emitter_removed)
        #: entities whose colliders or bodies came or went since the grid was built
        self._pending: set[int] = set()
        #: the grid's collider entities and their bodies
        self._members: set[int] = set()
        #: body entity -> how many colliders elsewhere attach to it (Collider.body)
        self._attached: dict[int, int] = {}
        world.on_add(Collider, self._collider_added)
        world.on_remove(Collider, self._collider_removed)
        world.on_add(RigidBody, self._changed)
        world.on_remove(RigidBody, self._changed)

    def _emitter_removed(self, entity: int, em: Any) -> None:
        self.particles.states.pop(entity, None)

    def _changed(self, entity: int, comp: Any) -> None:
        if self.particles.grid_dirty:
            return  # rebuilt from scratch when next needed: nothing to sort out
        self._pending.add(entity)
        if len(self._pending) > self.MAX_PENDING:
            self.particles.grid_dirty = True
            self._pending.clear()

    def _collider_added(self, entity: int, col: Collider) -> None:
        if col.body is not None:
            self._attached[col.body] = self._attached.get(col.body, 0) + 1
        self._changed(entity, col)

    def _collider_removed(self, entity: int, col: Collider) -> None:
        if col.body is not None:
            left = self._attached.get(col.body, 0) - 1
            if left > 0:
                self._attached[col.body] = left
            else:
                self._attached.pop(col.body, None)
        self._changed(entity, col)

    def _static_changed(self) -> bool:
        """Did any pending entity add or take away static geometry?"""
        world = self.world
        for e in self._pending:
            if e in self._members:
                return True  # it was in the grid: removed, or no longer static
            col = world.try_get(e, Collider)
            if col is not None and not col.sensor and _is_static(world, e, col):
                return True  # a new static collider
            if e in self._attached:
                rb = world.try_get(e, RigidBody)
                if rb is None or rb.type is BodyType.STATIC:
                    return True  # colliders attached to it became static
        return False

    def _fold_pending(self) -> None:
        """Sort the changes since the last frame out now (is the grid stale?), so they
        never pile up while no emitter collides."""
        if self._pending:
            p = self.particles
            p.grid_dirty = p.grid_dirty or self._static_changed()
            self._pending.clear()

    def _grid(self) -> StaticGrid | None:
        p = self.particles
        self._fold_pending()
        if p.grid_dirty:
            self._members = set()
            p.grid = StaticGrid.from_geometry(
                *static_geometry(self.world, self._members), cell=p.cell
            )
            p.grid_dirty = False
        return p.grid

    def process(self, dt: float) -> None:
        world = self.world
        particles = self.particles
        for ev in world.events(ParticleBurst):  # every burst of the frame, once
            if world.exists(ev.emitter) and world.has(ev.emitter, ParticleEmitter):
                particles.burst(ev.emitter, ev.count, ev.position, ev.direction)
        emitters = world.query(ParticleEmitter, Transform)
        grid = None
        if any(em.collide != "none" for _, (em, _t) in emitters):
            grid = self._grid()
        else:
            self._fold_pending()
        attractors: list[tuple[float, ...]] = [(at.x, at.y, a.strength, a.radius, a.falloff)
                      for _, (a, at) in world.query(ParticleAttractor, Transform) if a.enabled]
        finished = []
        for e, (em, t) in emitters:
            st = particles.state(e)
            rb = world.try_get(e, RigidBody)
            velocity = rb.velocity if rb is not None else (0.0, 0.0)
            collider = None
            if isinstance(em.shape, EmitCollider):
                col = world.try_get(e, Collider)
                collider = col.shape if col is not None else None
            st.advance(em, dt, (t.x, t.y, t.angle), velocity, collider, grid, attractors)
            if st.finished:
                finished.append(e)
        for e in finished:
            world.despawn(e)


class ParticleTriggers(System):
    """Physics hits and burst events of each fixed step -> pending bursts (FIXED stage)."""

    stage = Stage.FIXED
    in_set = SystemSet.POST_PHYSICS

    def process(self, dt: float) -> None:
        world = self.world
        if not world.query(BurstOnHit):
            return
        for hit in world.events(Hit):  # this step's, once
            self._fire(hit.collider_a, hit.collider_b, hit.point, hit.normal, hit.approach_speed)
        for c in world.events(ContactBegin):
            if c.points:
                self._fire(c.collider_a, c.collider_b, c.points[0], c.normal, c.approach_speed,
                           contact=True)  # fmt: skip

    def _fire(
        self,
        a: int,
        b: int,
        point: tuple[float, float],
        normal: tuple[float, float],
        speed: float,
        contact: bool = False,
    ) -> None:
        world = self.world
        particles = world.resource(Particles)
        for mine, sign in ((a, 1.0), (b, -1.0)):
            trig = world.try_get(mine, BurstOnHit)
            if trig is None or (contact and not trig.contacts) or speed < trig.hit_threshold:
                continue
            if not world.exists(trig.emitter) or not world.has(trig.emitter, ParticleEmitter):
                continue
            # the normal points from A to B: away from A's surface, towards B
            direction = math.atan2(sign * normal[1], sign * normal[0])
            particles.burst(trig.emitter, trig.count, point, direction)


def _emitter_of(world: World, entity: int | None, owner: str, emitter: int) -> None:
    """Refuse a reference to an entity that is not a live emitter."""
    if not world.exists(emitter):
        raise ValidationError(f"{where(entity, owner, 'emitter')}: entity {emitter} does not exist")
    if world.try_get(emitter, ParticleEmitter) is None:
        raise ValidationError(
            f"{where(entity, owner, 'emitter')}: entity {emitter} has no ParticleEmitter"
        )


def _check_burst_on_hit(world: World, entity: int | None, trig: BurstOnHit) -> None:
    _emitter_of(world, entity, "BurstOnHit", trig.emitter)


def _check_burst_event(world: World, entity: int | None, event: ParticleBurst) -> None:
    """``world.emit(ParticleBurst(...))`` naming no emitter is refused at the emit."""
    _emitter_of(world, entity, "ParticleBurst", event.emitter)


class ParticlesPlugin(Plugin):
    """Particles: the ``Particles`` resource, the systems, validation and the draw pass."""

    def build(self, world: World) -> None:
        particles = world.insert_resource(Particles(world))
        world.add_system(ParticleSystem())
        world.add_system(ParticleTriggers())

        def check(entity: int | None, em: ParticleEmitter) -> None:
            particles.check(entity, em)
            tex = em.texture
            if isinstance(tex, str) and not (assets_for(world).exists(tex) or os.path.isfile(tex)):
                raise ValidationError(
                    f"{where(entity, 'ParticleEmitter', 'texture')}: unknown texture {tex!r} "
                    "(not in the asset store, not a file)"
                )

        world.validator(ParticleEmitter, check)
        validate_writes(world, ParticleEmitter)
        world.validator(BurstOnHit, functools.partial(_check_burst_on_hit, world))
        validate_writes(world, BurstOnHit)
        world.validator(ParticleBurst, functools.partial(_check_burst_event, world))
        drawer: dict[str, Any] = {}

        def draw(frame: Any) -> None:
            from kge.render.particle_effects import EffectDrawer

            d = drawer.get("d")
            if d is None or d.batch is not frame.batch:
                if d is not None:
                    d.close()
                d = drawer["d"] = EffectDrawer(world, frame.batch, frame.groups)
            d.draw(frame)

        passes_for(world).add(
            draw, phase="before", name="particles", after=["animation", "tilemap"]
        )
