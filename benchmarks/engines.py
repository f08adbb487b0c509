"""The three engines a benchmark scene runs on, behind one small interface.

* :class:`KgeRunner`: the full kge frame (sync in, step with substeps, sync out,
  events, update pass), built from a testbed sample.
* :class:`PymunkRunner`: raw pymunk with kge's exact space settings (substeps,
  iterations, slop, polygon skin, sleeping, sqrt friction). It is the floor:
  kge can only add cost on top of it. With ``read=True`` ("pymunk+read") it also
  reads every body's pose out each frame in bulk (``pymunk.batch`` into numpy), the
  least a game on raw pymunk pays to draw its bodies.
* :class:`Box2DRunner`: pybox2d 2.3.10 at 8 velocity / 3 position iterations,
  its ``world.Step`` alone ("box2d"); with ``sync=True`` ("box2d+sync") plus the
  minimal property-sync loop an ECS engine on pybox2d runs (copy every awake body's
  pose into plain Python objects each frame, through SWIG), which is what KGE 1.0
  did. Optional: skipped with a message when ``Box2D`` is not installed.

The raw runners build from a :class:`~benchmarks.mirror.SceneSpec` (what the
kge scene holds, read back as plain data), can add and remove bodies between
steps (for the churn and spawn scenes), and pin a joint whose body is ``None``
to a static ground body, as Box2D's samples do. Each runner exposes ``poses()``
(entity -> (x, y, angle) of the dynamic bodies, keyed by the kge entity ids of
the description) so quality figures are computed the same way for all three.
"""

from __future__ import annotations

import functools
import math
from typing import Any

import numpy as np
import pymunk
import pymunk.batch

from benchmarks.mirror import BodySpec, SceneSpec, ShapeSpec, describe
from kge.app import App
from kge.components import Transform
from kge.components.rigidbody import BodyType, RigidBody
from kge.testbed.registry import Sample, get_sample

DT = 1.0 / 60.0
Pose = tuple[float, float, float]


class KgeRunner:
    """A testbed sample in a headless kge App; ``step`` is one whole frame."""

    def __init__(self, s: Sample, **kwargs: Any) -> None:
        self.app = App(s.setup, headless=True, **kwargs)

    def step(self) -> None:
        self.app.step()

    def poses(self) -> dict[int, Pose]:
        return {
            e: (t.x, t.y, t.angle)
            for e, (t, rb) in self.app.world.query(Transform, RigidBody)
            if rb.type is BodyType.DYNAMIC
        }

    def close(self) -> None:
        self.app.close()


@functools.lru_cache(maxsize=4)
def _spec_cached(slug: str, items: tuple[tuple[str, Any], ...]) -> SceneSpec:
    app = App(get_sample(slug).setup, headless=True, **dict(items))
    try:
        return describe(app.world)
    finally:
        app.close()


def spec_of(s: Sample, **kwargs: Any) -> SceneSpec:
    """Build the sample in a throwaway kge world and read its description back (cached).

    The description is read-only for the runners, so pymunk and pybox2d share one.
    """
    return _spec_cached(s.slug, tuple(sorted(kwargs.items())))


class PymunkRunner:
    def __init__(self, spec: SceneSpec, events: bool = False, read: bool = False) -> None:
        st = spec.settings
        self.read = read
        self.poses_out = np.zeros((0, 3))
        self._fields = (pymunk.batch.BodyFields.BODY_ID | pymunk.batch.BodyFields.POSITION
                        | pymunk.batch.BodyFields.ANGLE)
        self._buffer = pymunk.batch.Buffer()
        self.substeps = st.substeps
        self.skin = st.polygon_radius
        space = pymunk.Space()
        space.gravity = st.gravity
        space.iterations = st.iterations
        space.collision_slop = st.collision_slop
        if st.sleep:
            space.sleep_time_threshold = st.time_to_sleep
            space.idle_speed_threshold = st.sleep_speed
        self.space = space
        self.bodies: dict[int, pymunk.Body] = {}
        self.begins = 0
        self.ends = 0
        for spec_body in spec.bodies:
            self.add_body(spec_body)
        for j in spec.joints:
            a = space.static_body if j.body_a is None else self.bodies[j.body_a]
            b = space.static_body if j.body_b is None else self.bodies[j.body_b]
            if pymunk.Body.DYNAMIC not in (a.body_type, b.body_type):
                continue  # a joint between two fixed bodies does nothing (pymunk refuses it)
            pivot = pymunk.PivotJoint(a, b, j.local_a, j.local_b)
            pivot.collide_bodies = False
            space.add(pivot)
        if events or any(s.events for b in spec.bodies for s in b.shapes):
            space.on_collision(None, None, begin=self._begin, separate=self._separate)

    def _begin(self, arb: pymunk.Arbiter, space: pymunk.Space, data: Any) -> None:
        self.begins += 1

    def _separate(self, arb: pymunk.Arbiter, space: pymunk.Space, data: Any) -> None:
        self.ends += 1

    def add_body(self, b: BodySpec) -> None:
        kind = {"static": pymunk.Body.STATIC, "kinematic": pymunk.Body.KINEMATIC,
                "dynamic": pymunk.Body.DYNAMIC}[b.type]
        body = pymunk.Body(body_type=kind)
        body.position = b.position
        body.angle = b.angle
        shapes = [self._shape(body, s, self.skin) for s in b.shapes]
        self.space.add(body, *shapes)
        if b.type == "dynamic":
            if body.mass <= 0:
                body.mass, body.moment = 1.0, 1.0
            if b.fixed_rotation:
                body.moment = math.inf
        if b.type != "static":
            body.velocity = b.velocity
            body.angular_velocity = b.angular_velocity
        self.bodies[b.entity] = body

    def remove_body(self, entity: int) -> None:
        body = self.bodies.pop(entity)
        self.space.remove(*body.shapes, *body.constraints, body)

    @staticmethod
    def _shape(body: pymunk.Body, s: ShapeSpec, skin: float) -> pymunk.Shape:
        shape: pymunk.Shape
        if s.kind == "circle":
            shape = pymunk.Circle(body, s.radius, s.center)
        elif s.kind == "poly":
            shape = pymunk.Poly(body, s.vertices, radius=skin)
        else:
            shape = pymunk.Segment(body, s.vertices[0], s.vertices[1], skin)
        if body.body_type == pymunk.Body.DYNAMIC:
            shape.density = s.density
        shape.friction = math.sqrt(s.friction)
        shape.sensor = s.sensor
        group = -s.group if s.group < 0 else 0
        shape.filter = pymunk.ShapeFilter(group=group, categories=s.category, mask=s.mask)
        return shape

    def step(self) -> None:
        h = DT / self.substeps
        for _ in range(self.substeps):
            self.space.step(h)
        if self.read:  # one bulk read of every body's id and pose, as numpy columns
            self._buffer.clear()
            pymunk.batch.get_space_bodies(self.space, self._fields, self._buffer)
            self.poses_out = np.frombuffer(self._buffer.float_buf()).reshape(-1, 3)

    def poses(self) -> dict[int, Pose]:
        return {
            e: (b.position.x, b.position.y, b.angle)
            for e, b in self.bodies.items()
            if b.body_type == pymunk.Body.DYNAMIC
        }

    def close(self) -> None:
        self.bodies.clear()


def box2d_available() -> str | None:
    """None when the real pybox2d imports, else the reason it does not.

    ``kge.box2d.install()`` makes ``import Box2D`` give kge's own layer; that is not
    pybox2d, so it is looked up past it.
    """
    import importlib.util
    import sys

    shim = sys.modules.get("Box2D")
    if shim is not None and shim.__name__.startswith("kge"):
        del sys.modules["Box2D"]
        try:
            found = importlib.util.find_spec("Box2D") is not None
        finally:
            sys.modules["Box2D"] = shim
        if not found:
            return "pybox2d is not installed (only kge.box2d is); pip install 'box2d==2.3.10'"
        return None
    try:
        import Box2D  # noqa: F401
    except ImportError as err:
        return f"pybox2d is not installed ({err}); install it with: pip install 'box2d==2.3.10'"
    return None


class Box2DRunner:
    def __init__(self, spec: SceneSpec, events: bool = False, sync: bool = False) -> None:
        import Box2D as b2

        self.b2 = b2
        self.sync = sync
        listener = None
        self.begins = 0
        self.ends = 0
        if events or any(s.events for b in spec.bodies for s in b.shapes):
            runner = self

            class Listener(b2.b2ContactListener):
                def BeginContact(self, contact: Any) -> None:
                    runner.begins += 1

                def EndContact(self, contact: Any) -> None:
                    runner.ends += 1

            listener = Listener()
        st = spec.settings
        self.world = b2.b2World(gravity=st.gravity, doSleep=st.sleep)
        if listener is not None:
            self.world.contactListener = listener
            self._listener = listener
        self.bodies: dict[int, Any] = {}
        # The minimal ECS sync an engine on pybox2d performs every frame.
        self.mirror: dict[int, list[float]] = {}
        for spec_body in spec.bodies:
            self.add_body(spec_body)
        ground = None
        for j in spec.joints:
            if (j.body_a is None or j.body_b is None) and ground is None:
                ground = self.world.CreateStaticBody(position=(0.0, 0.0))
            a = ground if j.body_a is None else self.bodies[j.body_a]
            b = ground if j.body_b is None else self.bodies[j.body_b]
            self.world.CreateRevoluteJoint(bodyA=a, bodyB=b, anchor=j.anchor)

    def add_body(self, b: BodySpec) -> None:
        b2 = self.b2
        kind = {"static": b2.b2_staticBody, "kinematic": b2.b2_kinematicBody,
                "dynamic": b2.b2_dynamicBody}[b.type]
        body = self.world.CreateBody(type=kind, position=b.position, angle=b.angle,
                                     bullet=b.bullet, fixedRotation=b.fixed_rotation,
                                     gravityScale=b.gravity_scale)
        if b.type != "static":
            body.linearVelocity = b.velocity
            body.angularVelocity = b.angular_velocity
        for s in b.shapes:
            if s.kind == "circle":
                shape = b2.b2CircleShape(radius=s.radius, pos=s.center)
            elif s.kind == "poly":
                shape = b2.b2PolygonShape(vertices=list(s.vertices))
            else:
                shape = b2.b2EdgeShape(vertices=list(s.vertices))
            body.CreateFixture(b2.b2FixtureDef(
                shape=shape, density=s.density, friction=s.friction, restitution=s.restitution,
                isSensor=s.sensor, filter=b2.b2Filter(categoryBits=s.category, maskBits=s.mask,
                                                      groupIndex=s.group)))
        self.bodies[b.entity] = body
        if b.type == "dynamic":
            self.mirror[b.entity] = [b.position[0], b.position[1], b.angle]

    def remove_body(self, entity: int) -> None:
        self.world.DestroyBody(self.bodies.pop(entity))
        self.mirror.pop(entity, None)

    def step(self) -> None:
        self.world.Step(DT, 8, 3)
        if not self.sync:
            return
        bodies = self.bodies
        for e, pose in self.mirror.items():
            body = bodies[e]
            if body.awake:
                p = body.position
                pose[0] = p.x
                pose[1] = p.y
                pose[2] = body.angle

    def poses(self) -> dict[int, Pose]:
        return {e: (b.position.x, b.position.y, b.angle) for e, b in self.bodies.items()
                if b.type == self.b2.b2_dynamicBody}

    def close(self) -> None:
        self.bodies.clear()
        self.mirror.clear()
