"""Random joint tangles through the public API, for tests/joints/test_tangles.py.

Why: the fuzz's joints are polite (anchors at the bodies, no frequencies, no
motors). This generator makes what a careless game would: all eleven joint
types between random bodies (dynamic, kinematic, static, massless), anchors
given in world or local coordinates far from where they can hold, reference
angles off by radians, springs up to 1e5 Hz, motors up to 1e6 N, several joints
on one body, and meanwhile writes body fields, body types, limits, velocities
and teleports. Every step must keep the world's invariants (no NaN anywhere),
no call may raise anything but a documented error, and no body may leave the
10 km around the origin.
"""

from __future__ import annotations

import contextlib
import random
from collections.abc import Callable
from typing import Any

from kge.components.collider import Collider
from kge.components.joints import (
    DistanceJoint,
    FrictionJoint,
    GearJoint,
    MotorJoint,
    MouseJoint,
    PrismaticJoint,
    PulleyJoint,
    RevoluteJoint,
    RopeJoint,
    WeldJoint,
    WheelJoint,
)
from kge.components.rigidbody import BodyType, RigidBody
from kge.components.shapes import Box, Circle, Polygon
from kge.components.transform import Transform
from kge.errors import KgeError
from tests.reliability.harness import PhysicsWorld, check_invariants, check_no_leftovers

#: how far from the origin a body may get, m
FAR = 1e4
Vec2 = tuple[float, float]


class Tangle:
    """One random sequence: a few bodies, then joints and writes between the steps."""

    def __init__(self, seed: int) -> None:
        self.r = random.Random(seed)
        self.pw = PhysicsWorld()
        self.world = self.pw.world
        self.bodies: list[int] = []
        self.joints: list[int] = []

    # -- random values ----------------------------------------------------------------
    def point(self, scale: float = 6.0) -> Vec2:
        return (self.r.uniform(-scale, scale), self.r.uniform(-scale, scale))

    def frequency(self) -> float:
        return self.r.choice([0.0, 0.0, 1.0, 4.0, 30.0, 200.0, 1e5])

    def force(self) -> float:
        return self.r.choice([0.0, 1.0, 50.0, 1e3, 1e6])

    # -- building ---------------------------------------------------------------------
    def spawn_bodies(self) -> None:
        r = self.r
        self.world.spawn(Transform(0.0, -1.0), Collider(Box(10.0, 1.0)))
        shapes: list[Callable[[], Any]] = [
            lambda: Circle(r.uniform(0.05, 1.0)),
            lambda: Box(r.uniform(0.05, 1.0), r.uniform(0.05, 1.0)),
            lambda: Polygon([(0.0, 0.0), (0.6, 0.0), (0.0, 0.4)]),
        ]
        for _ in range(r.randint(2, 7)):
            kind = r.choice([BodyType.DYNAMIC] * 4 + [BodyType.KINEMATIC, BodyType.STATIC])
            x, y = (0.0, 0.0) if r.random() < 0.25 else (r.uniform(-6, 6), r.uniform(0, 3))
            self.bodies.append(self.world.spawn(
                Transform(x, y, r.uniform(-3, 3)), RigidBody(type=kind),
                Collider(r.choice(shapes)(), density=r.choice([0.0, 0.0, 1.0, 5.0, 1e-3])),
            ))

    def anchors(self) -> dict[str, Any]:
        """A world anchor, explicit local anchors (which need not meet), or neither."""
        p = self.r.random()
        if p < 0.15:
            return {"anchor": self.point()}
        if p < 0.3:
            return {"local_anchor_a": self.point(3.0), "local_anchor_b": self.point(3.0)}
        return {}

    def joint(self) -> Any:
        r = self.r
        a, b = r.choice([*self.bodies, None]), r.choice(self.bodies)
        if a == b:
            return None
        makers: dict[str, Callable[[], Any]] = {
            "revolute": lambda: RevoluteJoint(
                a, b, **self.anchors(), enable_limit=r.random() < 0.5,
                lower_angle=-r.random(), upper_angle=r.random(), enable_motor=r.random() < 0.5,
                motor_speed=r.uniform(-20, 20), max_motor_torque=self.force(),
                reference_angle=r.choice([None, r.uniform(-4, 4)])),
            "prismatic": lambda: PrismaticJoint(
                a, b, **self.anchors(), local_axis_a=self.point(1.0), enable_limit=r.random() < 0.5,
                lower_translation=-1.0, upper_translation=r.uniform(-1, 3),
                enable_motor=r.random() < 0.5, motor_speed=r.uniform(-20, 20),
                max_motor_force=self.force(), reference_angle=r.choice([None, r.uniform(-4, 4)])),
            "wheel": lambda: WheelJoint(
                a, b, **self.anchors(), local_axis_a=self.point(1.0), frequency_hz=self.frequency(),
                damping_ratio=r.choice([0.0, 0.7, 5.0]), enable_motor=r.random() < 0.5,
                motor_speed=r.uniform(-50, 50), max_motor_torque=self.force()),
            "weld": lambda: WeldJoint(
                a, b, **self.anchors(), frequency_hz=self.frequency(),
                damping_ratio=r.choice([0.0, 0.7]),
                reference_angle=r.choice([None, r.uniform(-4, 4)])),
            "distance": lambda: DistanceJoint(
                a, b, anchor_a=self.point(), length=r.choice([None, r.uniform(0.1, 8)]),
                frequency_hz=self.frequency(), damping_ratio=r.choice([0.0, 0.5])),
            "rope": lambda: RopeJoint(a, b, max_length=r.choice([None, r.uniform(0.1, 5)])),
            "pulley": lambda: PulleyJoint(
                a, b, ground_anchor_a=self.point(), ground_anchor_b=self.point(),
                ratio=r.choice([1.0, 2.0, 0.3])),
            "mouse": lambda: MouseJoint(
                a, b, target=self.point(), max_force=self.force(),
                frequency_hz=r.choice([1.0, 5.0, 60.0, 1e4])),
            "friction": lambda: FrictionJoint(
                a, b, **self.anchors(), max_force=self.force(), max_torque=self.force()),
            "motor": lambda: MotorJoint(
                a, b, linear_offset=self.point(), angular_offset=r.uniform(-3, 3),
                max_force=self.force(), max_torque=self.force(), correction_factor=r.random()),
            "gear": self.gear,
        }
        kind = r.choice([*makers, "gear"])
        if kind == "pulley" and a is None:
            return None
        return makers[kind]()

    def gear(self) -> GearJoint | None:
        hinges = [
            j for j in self.joints
            if self.world.exists(j)
            and (self.world.has(j, RevoluteJoint) or self.world.has(j, PrismaticJoint))
        ]
        if len(hinges) < 2:
            return None
        ja, jb = self.r.sample(hinges, 2)
        return GearJoint(ja, jb, ratio=self.r.choice([1.0, -1.0, 2.0, -0.5, 10.0]))

    # -- changing ---------------------------------------------------------------------
    def write(self) -> None:
        r, w = self.r, self.world
        live = [j for j in self.joints if w.exists(j)]
        op = r.randrange(8)
        if op == 0 and live:  # move a joint to other bodies (or a gear to other joints)
            joint = next(c for c in w.components(r.choice(live)) if hasattr(c, "reaction_force"))
            if isinstance(joint, GearJoint):
                setattr(joint, r.choice(["joint_a", "joint_b"]), r.choice(live))
            else:
                setattr(joint, r.choice(["body_a", "body_b"]), r.choice([*self.bodies, None]))
        elif op == 1 and self.bodies:
            w.get(r.choice(self.bodies), RigidBody).type = r.choice(list(BodyType))
        elif op == 2 and self.bodies:
            t = w.get(r.choice(self.bodies), Transform)
            t.x, t.y = self.point()
            t.angle = r.uniform(-10, 10)
        elif op == 3 and self.bodies:
            w.get(r.choice(self.bodies), RigidBody).enabled = r.random() < 0.7
        elif op == 4 and self.bodies:
            w.get(r.choice(self.bodies), RigidBody).mass = r.choice([None, 0.01, 1.0, 100.0])
        elif op == 5 and live:
            for c in w.components(r.choice(live)):
                if hasattr(c, "enable_limit"):
                    lower = r.uniform(-5, 5)
                    c.set_limits(lower, lower + r.uniform(0, 2))
                    c.enable_limit = True
        elif op == 6 and live:
            w.despawn(r.choice(live))
        elif op == 7 and self.bodies:
            rb = w.get(r.choice(self.bodies), RigidBody)
            rb.velocity = self.point(50.0)
            rb.fixed_rotation = r.random() < 0.3

    # -- running ----------------------------------------------------------------------
    def run(self) -> None:
        """Raise if any step breaks an invariant or a body leaves the 10 km."""
        try:
            self.spawn_bodies()
            for _ in range(self.r.randint(60, 200)):
                self.maybe(0.15, self.add_joint)
                self.maybe(0.08, self.write)
                self.pw.step()
                check_invariants(self.pw)
                self.check_near()
            for e in self.world.entities():
                self.world.despawn(e)
            self.pw.step()
            check_invariants(self.pw)
            check_no_leftovers(self.pw)
        finally:
            self.pw.close()

    def maybe(self, p: float, op: Callable[[], None]) -> None:
        """Run ``op`` with probability ``p``; documented validation errors are fine."""
        if self.r.random() < p:
            with contextlib.suppress(ValueError, TypeError, KgeError):
                op()

    def add_joint(self) -> None:
        joint = self.joint()
        if joint is not None:
            self.joints.append(self.world.spawn(joint))

    def check_near(self) -> None:
        for e, rec in self.pw.sim.bodies.items():
            p = rec.body.position
            assert abs(p.x) < FAR and abs(p.y) < FAR, f"body {e} thrown to {p}"
