"""The moving bodies characters meet this step: where they are, how they move.

Poses and velocities come from ``Physics.states`` in one bulk read. A kinematic
body moves by its velocity only, so where it will be after the step is known
exactly (its pieces are placed there, and a character standing on it is carried
by the same motion); a dynamic body is taken where it is, and a point on it moves
with the body's velocity at that point (Box2D's velocity is the centre of mass's,
so the centre comes from ``Physics.mass_data``, asked once per body and step).
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from kge.character.obstacles import KINEMATIC
from kge.components.rigidbody import RigidBody
from kge.components.transform import Transform
from kge.errors import KgeError


class Bodies:
    """Moving bodies by entity: pose (x, y, angle), velocity (vx, vy, w), kind."""

    def __init__(self, physics: Any, world: Any, owners: np.ndarray, kinds: np.ndarray,
                 dt: float) -> None:
        self.physics = physics
        self.dt = dt
        self.entities = owners
        self.row = {e: k for k, e in enumerate(owners.tolist())}
        n = len(owners)
        states = np.zeros((n, 6))
        if n:
            try:
                states, _awake = physics.states(owners)
            except KgeError:  # a body not in the pose table (changed this step): one by one
                states = np.array([_state(world, e) for e in owners.tolist()]).reshape(n, 6)
            # kinematic bodies (platforms, lifts) are driven by the game, which sets their
            # velocity in on_fixed_update, before this step: their components say where
            # they go now (the bulk read holds the last step's; they are few)
            for k in np.flatnonzero(kinds == KINEMATIC).tolist():
                states[k] = _state(world, int(owners[k]))
        self.pose = states[:, :3].copy()
        self.velocity = states[:, 3:6].copy()
        self.kind = kinds
        #: where the step leaves each body: kinematic ones by their velocity, the rest here
        self.end = self.pose.copy()
        kin = self.kind == KINEMATIC
        self.end[kin] += self.velocity[kin] * dt
        self._centers: dict[int, tuple[float, float]] = {}

    def motion(self, entities: np.ndarray, points: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """(displacement over the step, velocity) of material points ``points`` (n, 2) of
        bodies ``entities`` (n,); zero for entities that are not moving bodies."""
        n = len(entities)
        move = np.zeros((n, 2))
        vel = np.zeros((n, 2))
        for k, e in enumerate(entities.tolist()):
            r = self.row.get(e)
            if r is None:
                continue
            x, y, a = self.pose[r]
            vx, vy, w = self.velocity[r]
            px, py = points[k]
            if self.kind[r] == KINEMATIC:  # rotates about its origin (no centre of mass)
                cx, cy = x, y
            else:
                lx, ly = self._center(e)
                c, s = math.cos(a), math.sin(a)
                cx, cy = x + c * lx - s * ly, y + s * lx + c * ly
            rx, ry = px - cx, py - cy
            vel[k] = (vx - w * ry, vy + w * rx)
            if self.kind[r] == KINEMATIC:
                c, s = math.cos(w * self.dt), math.sin(w * self.dt)
                move[k] = (cx + vx * self.dt + c * rx - s * ry - px,
                           cy + vy * self.dt + s * rx + c * ry - py)
            else:
                move[k] = vel[k] * self.dt
        return move, vel

    def kind_of(self, entities: np.ndarray) -> np.ndarray:
        """Each entity's body kind (KINEMATIC, DYNAMIC), -1 when it is not a moving body."""
        get = self.row.get
        return np.array([-1 if (r := get(e)) is None else int(self.kind[r])
                         for e in entities.tolist()], dtype=np.int64)

    def center_world(self, e: int) -> tuple[float, float]:
        """Where body ``e``'s centre of mass is now."""
        x, y, a = self.pose[self.row[e]]
        lx, ly = self._center(e)
        c, s = math.cos(a), math.sin(a)
        return (x + c * lx - s * ly, y + s * lx + c * ly)

    def _center(self, e: int) -> tuple[float, float]:
        c = self._centers.get(e)
        if c is None:
            c = self._centers[e] = self.physics.mass_data(e).center
        return c


def _state(world: Any, e: int) -> tuple[float, ...]:
    t = world.try_get(e, Transform)
    rb = world.try_get(e, RigidBody)
    x, y, a = (0.0, 0.0, 0.0) if t is None else (t.x, t.y, t.angle)
    vx, vy = (0.0, 0.0) if rb is None else rb.velocity
    w = 0.0 if rb is None else rb.angular_velocity
    return (x, y, a, vx, vy, w)
