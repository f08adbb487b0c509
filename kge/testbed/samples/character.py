"""Character samples: CharacterBody on slopes, stairs, moving and one-way platforms, and a
crowd pushing crates (docs/character.md).

In each, the character named "player" answers the keys (A/D or the arrows run, W, up or
space jump, S or down drops through a one-way plank) and walkers patrol by themselves:
they run one way, turn round at a wall and jump now and then.
"""

from __future__ import annotations

import math

from kge.components import Name, Transform
from kge.components.behaviour import Behaviour, Script
from kge.components.character import Capsule, CharacterBody
from kge.components.collider import Collider
from kge.components.platform import OneWayPlatform
from kge.components.rigidbody import BodyType, RigidBody
from kge.components.shapes import Box, Chain, Circle
from kge.keys import Key
from kge.testbed.registry import sample
from kge.testbed.samples.build import box, named, static_box
from kge.world import World

KEYS = {"A/D": "run", "W/space": "jump (hold: higher)", "S": "drop through a one-way plank"}


class _Player(Script):
    """The keys drive it."""

    speed = 5.0

    def on_fixed_update(self, dt: float) -> None:
        from kge.input import Input

        keys = self.world.resource(Input)
        body = self.get(CharacterBody)
        run = keys.axis((Key.A, Key.LEFT), (Key.D, Key.RIGHT)) * self.speed
        body.velocity = (run, body.velocity[1])
        body.jump = keys.any_held(Key.W, Key.UP, Key.SPACE)
        body.drop_through = keys.any_held(Key.S, Key.DOWN)


class _Walker(Script):
    """Runs at ``speed`` one way, turns round at static walls (not at crates it pushes),
    jumps every ``every`` seconds (holding the button half a second: a full jump)."""

    def __init__(self, speed: float, every: float = 0.0, phase: float = 0.0) -> None:
        self.speed = speed
        self.every = every
        self.t = phase

    def on_fixed_update(self, dt: float) -> None:
        body = self.get(CharacterBody)
        wall = body.wall_collider
        if (body.on_wall and body.wall_normal[0] * self.speed < 0.0 and wall is not None
                and not self.world.has(wall, RigidBody)):
            self.speed = -self.speed
        body.velocity = (self.speed, body.velocity[1])
        self.t += dt
        body.jump = self.every > 0.0 and (self.t % self.every) < 0.5


class Shuttle(Script):
    """Moves its kinematic body by ``velocity`` for ``period`` seconds, then back."""

    def __init__(self, velocity: tuple[float, float], period: float) -> None:
        self.velocity = velocity
        self.period = period
        self.t = 0.0

    def on_fixed_update(self, dt: float) -> None:
        forward = int(self.t / self.period) % 2 == 0
        self.t += dt
        vx, vy = self.velocity
        self.get(RigidBody).velocity = (vx, vy) if forward else (-vx, -vy)


def _character(world: World, x: float, y: float, script: Script, name: str, **settings: object
               ) -> int:
    return world.spawn(Transform(x, y), CharacterBody(Capsule(0.3, 0.8), **settings),  # type: ignore[arg-type]
                       Behaviour(script), Name(name))


def _player(world: World, x: float, y: float, **settings: object) -> int:
    settings.setdefault("jump_speed", 8.0)
    return _character(world, x, y, _Player(), "player", **settings)


def _inside_nothing(app: object, name: str) -> None:
    """Every character ``name`` stands clear of every static collider (kge.collision)."""
    from kge import collision
    from kge.components.shapes import Edge

    world = app.world  # type: ignore[attr-defined]
    for e in named(world, name):
        t = world.get(e, Transform)
        assert all(map(math.isfinite, (t.x, t.y))), f"{name} {e} at {t}"
        body = world.get(e, CharacterBody)
        (x0, y0), (x1, y1) = body.shape.segment
        core = Edge((x0, y0), (x1, y1))
        for c, (col,) in world.query(Collider):
            if col.sensor or world.try_get(c, RigidBody) is not None or col.body is not None:
                continue
            ct = world.get(c, Transform)
            pose = (ct.x, ct.y, ct.angle)
            for child in range(collision.child_count(col.shape)):
                d = collision.distance(core, (t.x, t.y, 0.0), col.shape, pose,
                                       child_b=child, use_radii=False).distance
                skin = collision.geometry.convex(col.shape, child).radius
                assert d - body.shape.radius - skin > 0.004, f"{name} {e} sank into {c}: {t}"


# -- slopes -------------------------------------------------------------------------------


def _hills() -> list[tuple[float, float]]:
    """Flat, up 15, 30 and 45 degrees with flats between, a 60 degree wall, and down."""
    pts = [(-30.0, 0.0), (-20.0, 0.0)]
    x, y = -20.0, 0.0
    for degrees in (15.0, 30.0, 45.0):
        run = 3.0
        x, y = x + run, y + run * math.tan(math.radians(degrees))
        pts.append((x, y))
        x += 2.0
        pts.append((x, y))
    x, y = x + 1.5, y + 1.5 * math.tan(math.radians(60.0))
    pts.append((x, y))
    x += 3.0
    pts.append((x, y))
    pts += [(x + 8.0, 0.0), (x + 20.0, 0.0)]
    return pts


@sample("Character", "Slopes", keys=KEYS, follow="player",
        help="Capsule characters on 15, 30 and 45 degree slopes: they stand still on them and "
             "walk up and down; a 60 degree face is a wall they slide off.")
def slopes(world: World) -> None:
    hills = _hills()
    world.spawn(Transform(), Collider(Chain(hills), friction=0.6), Name("hills"))
    _player(world, -26.0, 1.5)
    for k in range(4):
        _character(world, -24.0 + 1.5 * k, 1.5, _Walker(3.0 + 0.5 * k, every=2.5, phase=0.6 * k),
                   "walker", jump_speed=6.0)


@slopes.claim
def _slopes_hold(app) -> None:  # type: ignore[no-untyped-def]
    _inside_nothing(app, "walker")
    world = app.world
    top = max(y for _, y in _hills())
    for e in named(world, "walker"):
        # the 60 degree face is a wall: no walker stands above it
        assert world.get(e, Transform).y < top, "a walker climbed the 60 degree face"


# -- stairs -------------------------------------------------------------------------------


@sample("Character", "Stairs", keys=KEYS, follow="player",
        help="Stairs of 0.25 m steps, up and down: step_height 0.3 climbs them, snap_length "
             "keeps the characters on them going down.")
def stairs(world: World) -> None:
    static_box(world, 0.0, -0.5, 30.0, 0.5, name="ground")
    for k in range(8):  # up...
        static_box(world, -4.0 + 0.6 * k + 0.3, 0.25 * (k + 1) - 0.125, 0.3, 0.125,
                   name="step")
    static_box(world, 2.0, 1.0, 1.5, 1.0, name="landing")
    for k in range(8):  # ...and down
        static_box(world, 3.8 + 0.6 * k, 2.0 - 0.25 * (k + 1) + 0.125 - 0.25, 0.3, 0.125,
                   name="step")
    settings = {"step_height": 0.3, "snap_length": 0.35}
    _player(world, -9.0, 1.0, **settings)
    for k in range(3):
        _character(world, -8.0 + 1.2 * k, 1.0, _Walker(2.5 + 0.4 * k), "walker", **settings)


@stairs.claim
def _stairs_climbed(app) -> None:  # type: ignore[no-untyped-def]
    world = app.world
    xs = [world.get(e, Transform).x for e in named(world, "walker")]
    assert max(xs) > 0.5, f"no walker reached the landing: {xs}"
    for e in named(world, "walker"):
        assert world.get(e, CharacterBody).on_floor


# -- moving platforms -------------------------------------------------------------------


@sample("Character", "Moving Platforms", keys=KEYS, follow="player",
        help="A shuttle, a lift, a diagonal platform and a slowly turning one, each with a "
             "rider: platforms carry them with no jitter; the turning one tips its rider "
             "off past 45 degrees.")
def moving_platforms(world: World) -> None:
    static_box(world, 0.0, -0.5, 40.0, 0.5, name="ground")
    for x, y, velocity, period in ((-12.0, 2.0, (3.0, 0.0), 1.5), (-3.0, 1.0, (0.0, 2.0), 1.5),
                                   (5.0, 2.0, (1.5, 1.5), 1.5)):
        world.spawn(Transform(x, y), RigidBody(type=BodyType.KINEMATIC),
                    Collider(Box(2.0, 0.2)), Behaviour(Shuttle(velocity, period)),
                    Name("platform"))
        _character(world, x, y + 0.2 + 0.01 + 0.8 + 0.005, _Walker(0.0), "rider")
    world.spawn(Transform(14.0, 3.0), RigidBody(type=BodyType.KINEMATIC, angular_velocity=0.4),
                Collider(Box(3.0, 0.2)), Name("wheel"))
    _character(world, 15.5, 3.0 + 1.015, _Walker(0.0), "wheel rider")
    _player(world, -20.0, 1.0)


@moving_platforms.claim
def _riders_ride(app) -> None:  # type: ignore[no-untyped-def]
    world = app.world
    for rider, platform in zip(named(world, "rider"), named(world, "platform"), strict=True):
        t, p = world.get(rider, Transform), world.get(platform, Transform)
        body = world.get(rider, CharacterBody)
        assert body.on_floor and body.floor_collider == platform, "a rider fell off"
        assert abs(t.x - p.x) < 0.05, f"a rider drifted on its platform: {t} {p}"


# -- one-way platforms ---------------------------------------------------------------------


@sample("Character", "One-Way Platforms", keys=KEYS, follow="player",
        help="Planks met only from above: the characters jump up through them, land on "
             "them and (S) drop back through.")
def one_way_platforms(world: World) -> None:
    static_box(world, 0.0, -0.5, 20.0, 0.5, name="ground")
    for k in range(5):
        world.spawn(Transform(-2.0 + 1.0 * (k % 2), 2.2 * (k + 1)), Collider(Box(3.0, 0.1)),
                    OneWayPlatform(), Name("plank"))
    _player(world, -6.0, 1.0, jump_speed=9.0)
    _character(world, -1.0, 1.0, _Walker(0.0, every=1.0), "climber", jump_speed=9.0)


@one_way_platforms.claim
def _climbed_through(app) -> None:  # type: ignore[no-untyped-def]
    world = app.world
    climber = named(world, "climber")[0]
    body, t = world.get(climber, CharacterBody), world.get(climber, Transform)
    assert t.y > 2.2 * 2, f"the climber did not get up through the planks: {t}"
    assert world.has(body.floor_collider or 0, OneWayPlatform) or not body.on_floor


# -- a crowd ----------------------------------------------------------------------------------


@sample("Character", "Crowd", keys=KEYS, follow="player",
        help="Forty characters walk into a row of crates and push them along (push_force "
             "500 N); they never pass through each other.")
def crowd(world: World, count: int = 40) -> None:
    static_box(world, 0.0, -0.5, 38.0, 0.5, name="ground")
    static_box(world, 37.0, 3.0, 0.5, 3.0, name="wall")
    static_box(world, -37.0, 3.0, 0.5, 3.0, name="wall")
    for k in range(8):
        box(world, 2.0 + 2.5 * k, 0.51, 0.5, 0.5, density=1.0, friction=0.5, name="crate")
    for k in range(count):
        _character(world, -32.0 + 0.75 * k, 1.0 + 0.3 * (k % 3),
                   _Walker(2.0 + 0.05 * (k % 7)), "walker")
    world.spawn(Transform(-35.0, 1.0), CharacterBody(Circle(0.4), jump_speed=7.0),
                Behaviour(_Player()), Name("player"))


@crowd.claim
def _crates_pushed(app) -> None:  # type: ignore[no-untyped-def]
    world = app.world
    xs = [world.get(e, Transform).x for e in named(world, "crate")]
    assert min(xs) > 2.5, f"the crowd did not push the crates: {xs}"
    _inside_nothing(app, "walker")
    walkers = sorted(world.get(e, Transform).x for e in named(world, "walker"))
    assert walkers[-1] - walkers[0] > 10.0  # still a crowd, not a pile
