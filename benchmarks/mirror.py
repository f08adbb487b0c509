"""Read a kge scene back as plain data, so raw pymunk and pybox2d build the same thing.

Benchmarks must compare engines on *identical* geometry. Instead of writing each
scene three times, a scene is written once (as a testbed sample), built in a kge
World, and :func:`describe` reads its bodies, colliders and revolute joints back
from the components. The raw-engine runners then build from that description.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from itertools import pairwise

from kge.components import Transform
from kge.components.collider import Collider
from kge.components.joints import RevoluteJoint
from kge.components.rigidbody import BodyType, RigidBody
from kge.components.shapes import Box, Chain, Circle, Edge, Polygon
from kge.physics.settings import PhysicsSettings
from kge.world import World

Vec2 = tuple[float, float]


@dataclass(slots=True)
class ShapeSpec:
    kind: str  # "circle" | "poly" | "edge"
    radius: float = 0.0
    center: Vec2 = (0.0, 0.0)
    vertices: tuple[Vec2, ...] = ()
    density: float = 1.0
    friction: float = 0.2
    restitution: float = 0.0
    sensor: bool = False
    category: int = 1
    mask: int = 0xFFFF
    group: int = 0
    events: bool = False  # wants contact events (hit_threshold set)


@dataclass(slots=True)
class BodySpec:
    entity: int
    type: str  # "static" | "kinematic" | "dynamic"
    position: Vec2
    angle: float
    velocity: Vec2 = (0.0, 0.0)
    angular_velocity: float = 0.0
    gravity_scale: float = 1.0
    bullet: bool = False
    fixed_rotation: bool = False
    shapes: list[ShapeSpec] = field(default_factory=list)


@dataclass(slots=True)
class JointSpec:
    """A revolute joint; ``None`` for a body is the static ground (Box2D's ground body)."""

    body_a: int | None
    body_b: int | None
    anchor: Vec2  # world anchor at build time
    local_a: Vec2 = (0.0, 0.0)  # anchor in body A's frame (world frame for the ground)
    local_b: Vec2 = (0.0, 0.0)


@dataclass(slots=True)
class SceneSpec:
    bodies: list[BodySpec]
    joints: list[JointSpec]
    settings: PhysicsSettings = field(default_factory=PhysicsSettings)

    def body(self, entity: int) -> BodySpec:
        for b in self.bodies:
            if b.entity == entity:
                return b
        raise KeyError(entity)

    @property
    def dynamic_count(self) -> int:
        return sum(b.type == "dynamic" for b in self.bodies)


def _box_vertices(b: Box) -> tuple[Vec2, ...]:
    c, s = math.cos(b.angle), math.sin(b.angle)
    cx, cy = b.center
    out = []
    for x, y in ((-b.half_width, -b.half_height), (b.half_width, -b.half_height),
                 (b.half_width, b.half_height), (-b.half_width, b.half_height)):
        out.append((cx + c * x - s * y, cy + s * x + c * y))
    return tuple(out)


def _shape_specs(col: Collider) -> list[ShapeSpec]:
    shape = col.shape
    geometry: list[tuple[str, float, Vec2, tuple[Vec2, ...]]]
    if isinstance(shape, Circle):
        geometry = [("circle", shape.radius, shape.center, ())]
    elif isinstance(shape, Box):
        geometry = [("poly", 0.0, (0.0, 0.0), _box_vertices(shape))]
    elif isinstance(shape, Polygon):
        geometry = [("poly", 0.0, (0.0, 0.0), tuple(shape.vertices))]
    elif isinstance(shape, Edge):
        geometry = [("edge", 0.0, (0.0, 0.0), (shape.v1, shape.v2))]
    elif isinstance(shape, Chain):
        vs = list(shape.vertices) + ([shape.vertices[0]] if shape.loop else [])
        geometry = [("edge", 0.0, (0.0, 0.0), pair) for pair in pairwise(vs)]
    else:
        raise TypeError(f"benchmarks cannot mirror {type(shape).__name__}")
    return [
        ShapeSpec(kind, radius, center, tuple(vertices), col.density, col.friction,
                  col.restitution, col.sensor, col.filter.category_bits, col.filter.mask_bits,
                  col.filter.group_index, col.hit_threshold is not None)
        for kind, radius, center, vertices in geometry
    ]


def describe(world: World) -> SceneSpec:
    """Bodies (with their colliders) and revolute joints of ``world``, sorted by entity."""
    bodies: dict[int, BodySpec] = {}
    for e, (t, rb) in sorted(world.query(Transform, RigidBody), key=lambda item: item[0]):
        kind = {BodyType.STATIC: "static", BodyType.KINEMATIC: "kinematic",
                BodyType.DYNAMIC: "dynamic"}[rb.type]
        bodies[e] = BodySpec(e, kind, (t.x, t.y), t.angle, rb.velocity, rb.angular_velocity,
                             rb.gravity_scale, rb.bullet, rb.fixed_rotation)
    for e, (col,) in sorted(world.query(Collider), key=lambda item: item[0]):
        owner = col.body if col.body is not None else e
        if owner not in bodies:  # a collider with no body: its own static body
            t = world.get(e, Transform)
            bodies[owner] = BodySpec(owner, "static", (t.x, t.y), t.angle)
        bodies[owner].shapes.extend(_shape_specs(col))
    joints: list[JointSpec] = []
    for _, (j,) in sorted(world.query(RevoluteJoint), key=lambda item: item[0]):
        if j.body_a is None and j.body_b is None:
            raise TypeError("a revolute joint needs at least one body")
        anchor = _world_anchor(j, world)
        joints.append(JointSpec(j.body_a, j.body_b, anchor,
                                _to_local(world, j.body_a, anchor),
                                _to_local(world, j.body_b, anchor)))
    settings = world.try_resource(PhysicsSettings) or PhysicsSettings()
    return SceneSpec([bodies[k] for k in sorted(bodies)], joints, settings)


def _pose(world: World, entity: int | None) -> tuple[float, float, float]:
    if entity is None:  # the ground: the world frame
        return (0.0, 0.0, 0.0)
    t = world.get(entity, Transform)
    return (t.x, t.y, t.angle)


def _world_anchor(joint: RevoluteJoint, world: World) -> Vec2:
    if joint.anchor is not None:
        return (float(joint.anchor[0]), float(joint.anchor[1]))
    return to_world(_pose(world, joint.body_a), joint.local_anchor_a)


def _to_local(world: World, entity: int | None, point: Vec2) -> Vec2:
    x, y, a = _pose(world, entity)
    c, s = math.cos(a), math.sin(a)
    dx, dy = point[0] - x, point[1] - y
    return (c * dx + s * dy, -s * dx + c * dy)


def to_world(pose: tuple[float, float, float], local: Vec2) -> Vec2:
    """A point given in a body's frame, in world coordinates."""
    x, y, a = pose
    c, s = math.cos(a), math.sin(a)
    return (x + c * local[0] - s * local[1], y + s * local[0] + c * local[1])
