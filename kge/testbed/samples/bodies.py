"""Body samples: static, kinematic and dynamic bodies; fast bodies and CCD."""

from __future__ import annotations

from kge.components import Behaviour, Script, Transform
from kge.components.rigidbody import BodyType, RigidBody
from kge.keys import Key
from kge.testbed.registry import sample
from kge.testbed.samples.build import ball, box, ground, named, static_box
from kge.world import World


class _Shuttle(Script):
    """Moves a platform back and forth between -limit and +limit; keys change its type."""

    def __init__(self, limit: float, speed: float) -> None:
        self.limit = limit
        self.speed = speed

    def on_fixed_update(self, dt: float) -> None:
        rb = self.get(RigidBody)
        if rb.type is not BodyType.KINEMATIC:
            return
        x = self.transform.x
        if (x > self.limit and rb.velocity[0] > 0) or (x < -self.limit and rb.velocity[0] < 0):
            rb.velocity = (-rb.velocity[0], 0.0)
        elif rb.velocity[0] == 0.0:
            rb.velocity = (self.speed, 0.0)

    def on_key_down(self, key: int) -> None:
        kinds = {Key.D: BodyType.DYNAMIC, Key.S: BodyType.STATIC, Key.K: BodyType.KINEMATIC}
        if key in kinds:
            self.get(RigidBody).type = kinds[key]


@sample("Bodies", "Body Types",
        help="A platform that is kinematic (moving), static or dynamic; a box rides on it.",
        keys={"D": "dynamic platform", "S": "static platform", "K": "kinematic platform"})
def body_types(world: World) -> None:
    ground(world)
    platform = box(world, 0.0, 3.0, 4.0, 0.25, body=BodyType.KINEMATIC, friction=0.6,
                   density=2.0, velocity=(2.0, 0.0), name="platform")
    world.add(platform, Behaviour(_Shuttle(limit=6.0, speed=2.0)))
    box(world, 0.0, 4.0, 0.5, 0.5, friction=0.6, name="rider")


@body_types.claim
def _rider_stays_on_platform(app) -> None:  # type: ignore[no-untyped-def]
    world = app.world
    p = world.get(named(world, "platform")[0], Transform)
    r = world.get(named(world, "rider")[0], Transform)
    assert abs(r.x - p.x) < 4.0 and r.y > p.y, f"rider fell off: platform {p}, rider {r}"


@sample("Bodies", "Bullet",
        help="Fast projectiles against a thin static wall and a dynamic plank (bullet=True).")
def bullet(world: World, speed: float = 500.0) -> None:
    ground(world)
    static_box(world, 10.0, 2.0, 0.05, 2.0, name="wall")
    box(world, 16.0, 6.0, 0.05, 2.0, density=1.0, name="plank", gravity_scale=0.0)
    ball(world, 0.0, 2.0, 0.05, density=1.0, velocity=(speed, 0.0), gravity_scale=0.0,
         name="shot")
    ball(world, 0.0, 6.0, 0.05, density=1.0, velocity=(speed, 0.0), gravity_scale=0.0,
         bullet=True, name="bullet")


@bullet.claim
def _nothing_tunnels(app) -> None:  # type: ignore[no-untyped-def]
    world = app.world
    shot = world.get(named(world, "shot")[0], Transform)
    assert shot.x < 10.0, f"shot tunnelled through the static wall: {shot}"
    b = world.get(named(world, "bullet")[0], Transform)
    plank = world.get(named(world, "plank")[0], Transform)
    assert b.x < plank.x + 0.1, f"bullet tunnelled through the plank: {b} vs {plank}"
