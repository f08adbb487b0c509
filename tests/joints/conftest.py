"""A test-only JointContext over a raw pymunk Space, stepping like kge's physics
(gravity (0, -10), 1/60 s steps of 4 substeps x 10 iterations, slop 0.005).

It lets the joint compositions be checked against Box2D's figures without the
physics system: it owns the bodies, builds joints through the registered
builders and drives the handles in the contract's order (before_step, step,
read_back, break check).
"""

from __future__ import annotations

import math
from typing import Any

import pymunk
import pytest

import kge.physics.joints  # noqa: F401 - registers the builders
from kge.physics.callback_errors import CallbackErrors
from kge.physics.joint_api import BUILDERS, JointHandle


class Sim:
    def __init__(self, gravity: tuple[float, float] = (0.0, -10.0), substeps: int = 4) -> None:
        self.space = pymunk.Space()
        self.space.gravity = gravity
        self.space.iterations = 10
        self.space.collision_slop = 0.005
        self.dt = 1.0 / 60.0
        self.substeps = substeps
        self.bodies: dict[int, pymunk.Body] = {}
        self.handles: dict[int, JointHandle] = {}
        self.joints: dict[int, Any] = {}
        self.broken: list[int] = []
        self._next = 1
        self.steps = 0
        self.errors = CallbackErrors()
        #: PhysicsSettings.iterated_hinges (kge's default: off)
        self.iterated_hinges = False
        #: PhysicsSettings.hinge_limit_push (kge's default: 0.1 rad/s)
        self.hinge_limit_push = 0.1

    # -- JointContext -----------------------------------------------------------------
    @property
    def substep(self) -> float:
        return self.dt / self.substeps

    def body(self, entity: int) -> pymunk.Body:
        return self.bodies[entity]

    def joint(self, entity: int) -> JointHandle | None:
        return self.handles.get(entity)

    # -- scene building ---------------------------------------------------------------
    def _new(self) -> int:
        e = self._next
        self._next += 1
        return e

    def add_body(
        self,
        pos: tuple[float, float] = (0.0, 0.0),
        *,
        circle: float | None = None,
        box: tuple[float, float] | None = None,
        density: float = 1.0,
        friction: float = 0.2,
        kind: int = pymunk.Body.DYNAMIC,
        angle: float = 0.0,
    ) -> int:
        body = pymunk.Body(body_type=kind)
        body.position = pos
        body.angle = angle
        shapes: list[pymunk.Shape] = []
        if circle is not None:
            shapes.append(pymunk.Circle(body, circle))
        if box is not None:
            shapes.append(pymunk.Poly.create_box(body, (2 * box[0], 2 * box[1])))
        for s in shapes:
            s.friction = friction
            if kind == pymunk.Body.DYNAMIC:
                s.density = density
        if kind == pymunk.Body.DYNAMIC and not shapes:
            body.mass, body.moment = 1.0, 1.0
        self.space.add(body, *shapes)
        e = self._new()
        self.bodies[e] = body
        return e

    def ground(self) -> int:
        """Box2D's reference ground: a static box half (50, 10) centred at (0, -10)."""
        return self.add_body((0.0, -10.0), box=(50.0, 10.0), kind=pymunk.Body.STATIC)

    def add_joint(self, component: Any) -> int:
        e = self._new()
        self.joints[e] = component
        self.handles[e] = BUILDERS[type(component)](self, e, component)
        self.handles[e].apply(component)
        return e

    # -- stepping ---------------------------------------------------------------------
    def step(self, n: int = 1) -> None:
        for _ in range(n):
            for h in self.handles.values():
                h.before_step(self.dt)
            for _ in range(self.substeps):
                self.space.step(self.dt / self.substeps)
            self.errors.raise_pending()
            for e, h in list(self.handles.items()):
                h.read_back(self.joints[e], self.dt)
                if h.exceeds_break_limits(self.joints[e]):
                    h.remove(self.space)
                    del self.handles[e]
                    self.broken.append(e)
            self.steps += 1

    def pos(self, e: int) -> pymunk.Vec2d:
        return self.bodies[e].position

    def angle(self, e: int) -> float:
        return float(self.bodies[e].angle)


@pytest.fixture
def sim() -> Sim:
    return Sim()


def period_of(samples: list[float], dt: float) -> float:
    """Mean period from the upward zero crossings of ``samples`` (linearly interpolated)."""
    times = []
    for i in range(1, len(samples)):
        a, b = samples[i - 1], samples[i]
        if a < 0 <= b:
            times.append((i - 1 + a / (a - b)) * dt)
    assert len(times) >= 2, "no full oscillation"
    return (times[-1] - times[0]) / (len(times) - 1)


def turning_points(samples: list[float]) -> list[float]:
    """Local maxima of ``samples`` (the amplitude at each swing)."""
    return [
        samples[i]
        for i in range(1, len(samples) - 1)
        if samples[i - 1] < samples[i] >= samples[i + 1]
    ]


def deg(x: float) -> float:
    return math.degrees(x)
