"""Random operation sequences against the physics world (hypothesis stateful testing).

:class:`PhysicsMachine` spawns and despawns bodies, colliders (own, compound
and static), resting stacks and joints, puts bodies to sleep (alone, in groups,
or by stepping long enough), changes body types, filters, sensors, enabled flags
and mass, teleports, applies forces and impulses, runs queries, removes and
replaces components, and steps. After every step :func:`check_invariants`
compares pymunk with the ECS (nothing leaked, nothing orphaned, counts equal,
begin/end events balanced, no NaN) and :func:`contact_graph_problems` reads
Chipmunk's contact graph (no arbiter threaded twice or naming a dead shape,
the damage that used to crash the interpreter later). The only exceptions allowed are kge's
documented refusals, and only where the operation really is invalid (an op on
a despawned entity must raise ``EntityNotFoundError``; a valid op must not raise).

Budgets: ``KGE_FUZZ`` selects a hypothesis profile: unset = CI (a few
seconds), ``long`` = the documented long run (see docs/reliability.md).
"""

from __future__ import annotations

import os

from hypothesis import HealthCheck, settings
from hypothesis import strategies as st
from hypothesis.stateful import RuleBasedStateMachine, initialize, precondition, rule

from kge.components.collider import MIN_DENSITY, Collider
from kge.components.filter import Filter
from kge.components.joints import (
    DistanceJoint,
    GearJoint,
    PrismaticJoint,
    RevoluteJoint,
    RopeJoint,
    WeldJoint,
    WheelJoint,
)
from kge.components.rigidbody import BodyType, RigidBody
from kge.components.shapes import Box, Circle, Edge, Polygon
from kge.components.transform import Transform
from kge.errors import EntityNotFoundError
from kge.physics.queries import RayMode

from .harness import (
    PhysicsWorld,
    check_invariants,
    check_no_leftovers,
    contact_graph_problems,
)

settings.register_profile(
    "ci",
    max_examples=25,
    stateful_step_count=50,
    deadline=None,
    suppress_health_check=[HealthCheck.too_slow],
    derandomize=True,
)
settings.register_profile(
    "long",
    max_examples=400,
    stateful_step_count=100,
    deadline=None,
    suppress_health_check=[HealthCheck.too_slow],
)
PROFILE = "long" if os.environ.get("KGE_FUZZ") == "long" else "ci"

coord = st.floats(-6.0, 6.0, allow_nan=False)
height = st.floats(0.0, 3.0, allow_nan=False)  # low: contacts within a few steps
index = st.integers(0, 10_000)
body_type = st.sampled_from([BodyType.DYNAMIC, BodyType.DYNAMIC, BodyType.KINEMATIC,
                             BodyType.STATIC])
shape = st.one_of(
    st.builds(Circle, st.floats(0.05, 1.0)),
    st.builds(Box, st.floats(0.05, 1.0), st.floats(0.05, 1.0)),
    st.just(Polygon([(0.0, 0.0), (0.6, 0.0), (0.0, 0.4)])),
)
bits = st.integers(0, 0xFFFF)
a_filter = st.builds(Filter, bits, bits, st.integers(-2, 2))
JOINTS = ["revolute", "distance", "weld", "prismatic", "rope", "wheel"]


class PhysicsMachine(RuleBasedStateMachine):
    """One world, many random operations; the invariants after every step."""

    def __init__(self) -> None:
        super().__init__()
        self.pw = PhysicsWorld()
        self.world = self.pw.world
        self.dead: list[int] = []
        self.steps = 0

    @initialize()
    def ground(self) -> None:
        self.world.spawn(Transform(0.0, -1.0), Collider(Box(10.0, 1.0)))

    # -- helpers ----------------------------------------------------------------------
    def _live(self, *types: type) -> list[int]:
        return sorted(e for e, _ in self.world.query(*types))

    def _pick(self, pool: list[int], i: int) -> int | None:
        return pool[i % len(pool)] if pool else None

    def _bodies(self) -> list[int]:
        return self._live(RigidBody)

    # -- spawning -----------------------------------------------------------------------
    @rule(s=shape, x=coord, y=height, kind=body_type, sensor=st.booleans(),
          density=st.just(0.0) | st.floats(MIN_DENSITY, 5.0))
    def spawn_body(self, s: object, x: float, y: float, kind: BodyType, sensor: bool,
                   density: float) -> None:
        self.world.spawn(Transform(x, y), RigidBody(type=kind),
                         Collider(s, density=density, sensor=sensor))  # type: ignore[arg-type]

    @rule(s=shape, i=index, dx=st.floats(-1, 1))
    def spawn_compound_part(self, s: object, i: int, dx: float) -> None:
        body = self._pick(self._bodies(), i)
        if body is not None:
            self.world.spawn(Transform(dx, 0.0), Collider(s, body=body))  # type: ignore[arg-type]

    @rule(i=index, k=index, to_static=st.booleans())
    def move_collider(self, i: int, k: int, to_static: bool) -> None:
        """Write ``Collider.body``: onto another body, or back to its own / implicit one."""
        c = self._pick(self._live(Collider), i)
        if c is None:
            return
        target = None if to_static else self._pick(self._bodies(), k)
        self.world.get(c, Collider).body = target

    @rule(x=coord, y=height)
    def spawn_static_edge(self, x: float, y: float) -> None:
        self.world.spawn(Transform(x, y), Collider(Edge((-1.0, 0.0), (1.0, 0.0))))

    @rule(kind=st.sampled_from(JOINTS), i=index, k=index, to_ground=st.booleans())
    def spawn_joint(self, kind: str, i: int, k: int, to_ground: bool) -> None:
        bodies = self._bodies()
        a = self._pick(bodies, i)
        b = None if to_ground else self._pick(bodies, k)
        if a is None or a == b:
            return
        joint = {
            "revolute": lambda: RevoluteJoint(a, b, anchor=(0.0, 2.0), enable_limit=True,
                                              lower_angle=-0.5, upper_angle=0.5),
            "distance": lambda: DistanceJoint(a, b),
            "weld": lambda: WeldJoint(a, b, anchor=(0.0, 1.0)),
            "prismatic": lambda: PrismaticJoint(a, b, anchor=(0.0, 1.0), enable_limit=True,
                                                lower_translation=-1.0, upper_translation=1.0),
            "rope": lambda: RopeJoint(a, b, max_length=3.0),
            "wheel": lambda: WheelJoint(a, b, anchor=(0.0, 1.0), local_axis_a=(0.0, 1.0)),
        }[kind]()
        self.world.spawn(joint)

    @rule(i=index, k=index, ratio=st.sampled_from([1.0, -2.0, 0.5]))
    def spawn_gear(self, i: int, k: int, ratio: float) -> None:
        joints = self._live(RevoluteJoint) + self._live(PrismaticJoint)
        ja, jb = self._pick(joints, i), self._pick(joints, k)
        if ja is None or jb is None or ja == jb:
            return
        w = self.world
        moved = [(w.try_get(j, RevoluteJoint) or w.get(j, PrismaticJoint)).body_b for j in (ja, jb)]
        if moved[0] != moved[1]:  # a gear of two joints that move one body is refused
            self.world.spawn(GearJoint(ja, jb, ratio=ratio))

    @rule(x=coord, n=st.integers(1, 4), base=body_type)
    def build_stack(self, x: float, n: int, base: BodyType) -> None:
        """A platform of any type with boxes resting on it: contacts that last and sleep."""
        w = self.world
        w.spawn(Transform(x, 0.5), RigidBody(type=base), Collider(Box(1.0, 0.5)))
        for k in range(n):
            w.spawn(Transform(x + 0.05 * k, 1.5 + 1.0 * k), RigidBody(), Collider(Box(0.45, 0.45)))

    # -- changing -----------------------------------------------------------------------
    @rule(i=index, k=st.integers(1, 5))
    def sleep_some(self, i: int, k: int) -> None:
        """``awake = False`` on up to ``k`` bodies at once (a stack asked to sleep)."""
        bodies = self._bodies()
        for e in bodies[i % len(bodies):][:k] if bodies else []:
            self.world.get(e, RigidBody).awake = False

    @rule(i=index, kind=body_type)
    def set_body_type(self, i: int, kind: BodyType) -> None:
        e = self._pick(self._bodies(), i)
        if e is not None:
            self.world.get(e, RigidBody).type = kind

    @rule(i=index, f=a_filter)
    def set_filter(self, i: int, f: Filter) -> None:
        e = self._pick(self._live(Collider), i)
        if e is not None:
            self.world.get(e, Collider).filter = f

    @rule(i=index)
    def toggle_sensor(self, i: int) -> None:
        e = self._pick(self._live(Collider), i)
        if e is not None:
            col = self.world.get(e, Collider)
            col.sensor = not col.sensor

    @rule(i=index)
    def toggle_enabled(self, i: int) -> None:
        e = self._pick(self._bodies(), i)
        if e is not None:
            rb = self.world.get(e, RigidBody)
            rb.enabled = not rb.enabled

    @rule(i=index, mass=st.none() | st.floats(0.1, 10.0))
    def set_mass(self, i: int, mass: float | None) -> None:
        e = self._pick(self._bodies(), i)
        if e is not None:
            self.world.get(e, RigidBody).mass = mass

    @rule(i=index, s=shape)
    def reshape(self, i: int, s: object) -> None:
        e = self._pick(self._live(Collider), i)
        if e is not None:
            self.world.get(e, Collider).shape = s  # type: ignore[assignment]

    @rule(i=index, x=coord, y=height, angle=st.floats(-3.0, 3.0))
    def teleport(self, i: int, x: float, y: float, angle: float) -> None:
        e = self._pick(self._live(Transform), i)
        if e is not None:
            t = self.world.get(e, Transform)
            t.x, t.y, t.angle = x, y, angle

    @rule(i=index, vx=st.floats(-50, 50), vy=st.floats(-50, 50), awake=st.booleans())
    def set_velocity(self, i: int, vx: float, vy: float, awake: bool) -> None:
        e = self._pick(self._bodies(), i)
        if e is not None:
            rb = self.world.get(e, RigidBody)
            rb.velocity = (vx, vy)
            rb.awake = awake

    @rule(i=index, fx=st.floats(-500, 500), fy=st.floats(-500, 500), impulse=st.booleans())
    def push(self, i: int, fx: float, fy: float, impulse: bool) -> None:
        e = self._pick(self._bodies(), i)
        if e is None:
            return
        physics = self.pw.physics
        if impulse:
            physics.apply_linear_impulse(e, (fx * 0.01, fy * 0.01), point=(0.0, 0.0))
            physics.apply_angular_impulse(e, fx * 0.001)
        else:
            physics.apply_force(e, (fx, fy))
            physics.apply_torque(e, fy)

    @rule(x=coord, y=height)
    def query(self, x: float, y: float) -> None:
        physics = self.pw.physics
        physics.raycast((x, 9.0), (x, -3.0), mode=RayMode.ALL)
        physics.query_aabb((x - 1.0, y - 1.0), (x + 1.0, y + 1.0))
        physics.query_point((x, y))

    # -- removing -----------------------------------------------------------------------
    @rule(i=index, deferred=st.booleans())
    def despawn(self, i: int, deferred: bool) -> None:
        e = self._pick(self.world.entities(), i)
        if e is None:
            return
        if deferred:
            with self.world.deferred():
                self.world.despawn(e)
        else:
            self.world.despawn(e)
        self.dead.append(e)

    @rule(i=index, which=st.sampled_from([RigidBody, Collider]))
    def remove_component(self, i: int, which: type) -> None:
        e = self._pick(self._live(which), i)
        if e is not None:
            self.world.remove(e, which)

    @precondition(lambda self: bool(self.dead))
    @rule(i=index)
    def operate_on_dead(self, i: int) -> None:
        e = self.dead[i % len(self.dead)]
        if self.world.exists(e):  # ids are never reused, so this cannot happen
            raise AssertionError(f"despawned entity {e} exists again")
        for op in (
            lambda: self.world.despawn(e),
            lambda: self.world.get(e, Transform),
            lambda: self.world.add(e, Transform()),
            lambda: self.pw.physics.apply_force(e, (1.0, 0.0)),
        ):
            try:
                op()
            except EntityNotFoundError:
                continue
            raise AssertionError(f"an operation on despawned entity {e} was accepted")

    # -- stepping -----------------------------------------------------------------------
    @rule(n=st.integers(1, 8))
    def step(self, n: int) -> None:
        for _ in range(n):
            self.pw.step()
            self.steps += 1
            check_invariants(self.pw)
            problems = contact_graph_problems(self.pw.sim.space)
            assert not problems, problems

    # stepping is what finds bugs: give it more of the rule draws
    @rule(n=st.integers(1, 3))
    def step_a_little(self, n: int) -> None:
        self.step(n)

    @rule()
    def step_once(self) -> None:
        self.step(1)

    @rule(n=st.integers(25, 45))
    def step_until_asleep(self, n: int) -> None:
        """Long enough (0.5 s of rest) for bodies to fall asleep by themselves."""
        self.step(n)

    def teardown(self) -> None:
        try:
            self.pw.step()
            check_invariants(self.pw)
            check_no_leftovers(self.pw)
            for e in self.world.entities():
                self.world.despawn(e)
            self.pw.step()
            check_invariants(self.pw)
            space = self.pw.sim.space
            assert not space.bodies and not space.shapes and not space.constraints
            check_no_leftovers(self.pw)
            assert not self.pw.sim.bodies and not self.pw.sim.joints.components
            assert not self.pw.balance.live_pairs(), "begin events without an end"
            assert self.pw.balance.begins == self.pw.balance.ends
        finally:
            self.pw.close()
