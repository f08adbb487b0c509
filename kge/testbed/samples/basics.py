"""Basic samples: the manual's hello world and a tumbler full of bodies."""

from __future__ import annotations

import math

from kge.components import Behaviour, Name, Script, Transform
from kge.components.collider import Collider
from kge.components.rigidbody import BodyType, RigidBody
from kge.components.shapes import Box
from kge.testbed.registry import sample
from kge.testbed.samples.build import box, named, static_box
from kge.world import World


@sample("Basics", "Hello World", help="The manual's first program: a box falls onto the ground.")
def hello_world(world: World) -> None:
    static_box(world, 0.0, -10.0, 50.0, 10.0, name="ground")
    box(world, 0.0, 4.0, 1.0, 1.0, density=1.0, friction=0.3, name="box")


@hello_world.claim
def _rests_at_box2d_height(app) -> None:  # type: ignore[no-untyped-def]
    t = app.world.get(named(app.world, "box")[0], Transform)
    assert 0.99 <= t.y <= 1.02 and abs(t.angle) < 0.01, f"box at {t}"


class _Feeder(Script):
    """Drops one small box into the tumbler per step until ``count`` are in."""

    def __init__(self, count: int) -> None:
        self.left = count

    def on_fixed_update(self, dt: float) -> None:
        if self.left > 0:
            self.left -= 1
            box(self.world, 0.0, 10.0, 0.125, 0.125, density=1.0, name="tumbled")


@sample("Basics", "Tumbler", help="A motorised box slowly turning, filling with small boxes.")
def tumbler(world: World, count: int = 200, speed: float = 0.05 * math.pi) -> None:
    drum = world.spawn(
        Transform(0.0, 10.0),
        RigidBody(type=BodyType.KINEMATIC, angular_velocity=speed),
        Name("drum"),
    )
    for hw, hh, cx, cy in ((0.5, 10.0, 10.0, 0.0), (0.5, 10.0, -10.0, 0.0),
                           (10.0, 0.5, 0.0, 10.0), (10.0, 0.5, 0.0, -10.0)):
        world.spawn(Transform(0.0, 10.0), Collider(Box(hw, hh, center=(cx, cy)), body=drum))
    world.spawn(Behaviour(_Feeder(count)))


@tumbler.claim
def _nothing_escapes(app) -> None:  # type: ignore[no-untyped-def]
    world = app.world
    inside = 0
    for e in named(world, "tumbled"):
        t = world.get(e, Transform)
        assert math.hypot(t.x, t.y - 10.0) < 15.0, f"box escaped the drum: {t}"
        inside += 1
    assert inside > 0
