"""Small spawning helpers shared by the samples (ground, boxes, balls, walls).

They only combine public components, so a sample reads like the Box2D testbed
code it mirrors, and a user can copy one into a game unchanged.
"""

from __future__ import annotations

from typing import Any

from kge.components import Name, Transform
from kge.components.collider import Collider
from kge.components.filter import Filter
from kge.components.rigidbody import BodyType, RigidBody
from kge.components.shapes import Box, Chain, Circle, Edge, Shape
from kge.world import World

Vec2 = tuple[float, float]


def ground(world: World, half_width: float = 40.0, y: float = 0.0, friction: float = 0.6) -> int:
    """A static edge along y, as in most Box2D samples."""
    return world.spawn(
        Transform(0.0, y),
        Collider(Edge((-half_width, 0.0), (half_width, 0.0)), friction=friction),
        Name("ground"),
    )


def spawn_body(
    world: World,
    x: float,
    y: float,
    shape: Shape,
    *,
    angle: float = 0.0,
    density: float = 1.0,
    friction: float = 0.6,
    restitution: float = 0.0,
    body: BodyType = BodyType.DYNAMIC,
    name: str = "body",
    filter: Filter | None = None,
    **rigidbody: Any,
) -> int:
    """A body with one collider; extra keywords go to its RigidBody (velocity=...)."""
    return world.spawn(
        Transform(x, y, angle),
        RigidBody(type=body, **rigidbody),
        Collider(shape, density=density, friction=friction, restitution=restitution,
                 filter=filter or Filter()),
        Name(name),
    )


def box(world: World, x: float, y: float, half_width: float = 0.5, half_height: float = 0.5,
        *, name: str = "box", **options: Any) -> int:
    """A box body (half extents, like Box2D's SetAsBox); options as :func:`spawn_body`."""
    return spawn_body(world, x, y, Box(half_width, half_height), name=name, **options)


def ball(world: World, x: float, y: float, radius: float = 0.5, *, name: str = "ball",
         **options: Any) -> int:
    """A circle body; options as :func:`spawn_body`."""
    return spawn_body(world, x, y, Circle(radius), name=name, **options)


def static_box(
    world: World, x: float, y: float, half_width: float, half_height: float,
    angle: float = 0.0, friction: float = 0.6, name: str = "wall",
) -> int:
    """A static box (a collider with no RigidBody sits on the implicit static body)."""
    collider = Collider(Box(half_width, half_height), friction=friction)
    return world.spawn(Transform(x, y, angle), collider, Name(name))


def chain(world: World, points: list[Vec2], *, loop: bool = False, friction: float = 0.6,
          name: str = "chain") -> int:
    """A static chain of edges (smooth: no bumps at the joins)."""
    return world.spawn(
        Transform(0.0, 0.0), Collider(Chain(points, loop=loop), friction=friction), Name(name)
    )


def named(world: World, name: str) -> list[int]:
    """Entities carrying ``Name(name)``, sorted."""
    return sorted(e for e, (n,) in world.query(Name) if n.value == name)
