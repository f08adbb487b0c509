"""Collision samples: sensors and filtering (categories, masks and groups)."""

from __future__ import annotations

from kge.components import Behaviour, Name, Script, Transform
from kge.components.collider import Collider
from kge.components.filter import Filter
from kge.components.shapes import Box, Circle
from kge.physics.events import ContactBegin
from kge.testbed.registry import sample
from kge.testbed.samples.build import ball, box, named, static_box
from kge.world import World


class SensorCounter(Script):
    """Counts begin/end events of the sensor it is attached to (the sample's HUD reads it)."""

    def __init__(self) -> None:
        self.begins = 0
        self.ends = 0
        self.inside: set[int] = set()

    def on_sensor_begin(self, event) -> None:  # type: ignore[no-untyped-def]
        self.begins += 1
        self.inside.add(event.collider_b)

    def on_sensor_end(self, event) -> None:  # type: ignore[no-untyped-def]
        self.ends += 1
        self.inside.discard(event.collider_b)


@sample("Collision", "Sensors",
        help="Balls fall through a sensor ring; it counts every begin and end.")
def sensors(world: World, count: int = 7) -> None:
    static_box(world, 0.0, -10.0, 50.0, 10.0, name="ground")
    world.spawn(
        Transform(0.0, 8.0),
        Collider(Circle(4.0), sensor=True),
        Behaviour(SensorCounter()),
        Name("sensor"),
    )
    for i in range(count):
        ball(world, -6.0 + 2.0 * i, 16.0 + 1.5 * i, 0.5, name="ball")


@sensors.claim
def _balanced_events(app) -> None:  # type: ignore[no-untyped-def]
    world = app.world
    sensor = named(world, "sensor")[0]
    counter = world.get(sensor, Behaviour).script
    assert counter.begins > 0, "no ball entered the sensor"
    assert counter.begins == counter.ends + len(counter.inside)


# Box2D's CollisionFiltering sample, reduced to one pair per rule.
SMALL, LARGE, GROUND = 0x0002, 0x0004, 0x0001


@sample("Collision", "Collision Filtering",
        help="Same positive group always collides; same negative group never; masks decide "
             "the rest.")
def collision_filtering(world: World) -> None:
    static_box(world, 0.0, -10.0, 50.0, 10.0, name="ground")
    # Positive group: the masks reject each other, the group forces a collision (they stack).
    box(world, -6.0, 1.0, filter=Filter(SMALL, LARGE | GROUND, group_index=3), name="pos-low")
    box(world, -6.0, 3.0, filter=Filter(SMALL, LARGE | GROUND, group_index=3), name="pos-high")
    # Negative group: would collide by masks, the group forbids it (they pass through).
    ball(world, 0.0, 1.0, 0.5, filter=Filter(SMALL, 0xFFFF, group_index=-2), name="neg-low")
    ball(world, 0.0, 3.0, 0.5, filter=Filter(SMALL, 0xFFFF, group_index=-2), name="neg-high")
    # Category/mask: this box does not accept the ground's category and falls through.
    box(world, 6.0, 1.0, filter=Filter(LARGE, LARGE | SMALL), name="ghost")


@collision_filtering.claim
def _filter_rules(app) -> None:  # type: ignore[no-untyped-def]
    w = app.world

    def y(name: str) -> float:
        return w.get(named(w, name)[0], Transform).y

    assert y("pos-high") > 1.3, "same positive group must collide (stack)"
    assert abs(y("neg-high") - y("neg-low")) < 0.1, "same negative group must pass through"
    assert y("ghost") < -1.0, "a mask excluding the ground must fall through it"


class _Destroyer(Script):
    """Box2D's CollisionProcessing: when two bodies touch, the lighter one is destroyed.

    Contacts are read after the step (never inside a callback) and the despawns
    are queued, so destroying bodies mid-simulation is always safe.
    """

    def on_fixed_update(self, dt: float) -> None:
        from kge.components.rigidbody import RigidBody
        from kge.physics.resource import Physics

        world = self.world
        physics = world.resource(Physics)
        doomed: set[int] = set()
        for ev in world.events(ContactBegin):
            a, b = ev.body_a, ev.body_b
            if a is None or b is None or a in doomed or b in doomed:
                continue
            if not (world.has(a, RigidBody) and world.has(b, RigidBody)):
                continue
            ma, mb = physics.mass_data(a).mass, physics.mass_data(b).mass
            if ma > 0 and mb > 0:
                doomed.add(b if mb < ma else a)
        for e in sorted(doomed):
            if world.exists(e):
                world.despawn(e)


@sample("Collision", "Collision Processing",
        help="Bodies of many sizes fall together; on contact the lighter one is destroyed.")
def collision_processing(world: World, count: int = 18) -> None:
    static_box(world, 0.0, -10.0, 50.0, 10.0, name="ground")
    for i in range(count):
        x, y = -8.0 + (i % 6) * 3.2, 4.0 + (i // 6) * 3.0
        if i % 2:
            ball(world, x, y, 0.3 + 0.25 * (i % 4), name="falling")
        else:
            box(world, x, y, 0.3 + 0.2 * (i % 5), 0.3 + 0.2 * (i % 3), name="falling")
    world.spawn(Behaviour(_Destroyer()))


@collision_processing.claim
def _lighter_bodies_were_destroyed(app) -> None:  # type: ignore[no-untyped-def]
    left = len(named(app.world, "falling"))
    assert 0 < left < 18, f"{left} bodies left"


@sample("Collision", "One-Sided Platform",
        help="A ball shot up through a platform lands on top of it (OneWayPlatform).")
def one_sided_platform(world: World) -> None:
    from kge.components.platform import OneWayPlatform

    static_box(world, 0.0, -10.0, 50.0, 10.0, name="ground")
    world.spawn(Transform(0.0, 10.0), Collider(Box(3.0, 0.5)), OneWayPlatform(), Name("platform"))
    ball(world, 0.0, 5.0, 0.5, density=20.0, velocity=(0.0, 13.0), name="ball")


@one_sided_platform.claim
def _ball_lands_on_top(app) -> None:  # type: ignore[no-untyped-def]
    t = app.world.get(named(app.world, "ball")[0], Transform)
    assert abs(t.y - 11.005) < 0.03, f"the ball should rest on the platform top: {t}"


@sample("Collision", "Conveyor Belt",
        help="A pre-solve hook sets the belt's tangent speed; boxes ride along it.")
def conveyor_belt(world: World, speed: float = 5.0) -> None:
    from kge.physics.resource import Physics

    static_box(world, 0.0, -10.0, 50.0, 10.0, name="ground")
    belt = world.spawn(Transform(-5.0, 5.0), Collider(Box(10.0, 0.5), friction=0.8,
                                                      contact_hooks=True), Name("belt"))
    for i in range(5):
        box(world, -10.0 + 2.0 * i, 6.0, 0.5, 0.5, friction=0.8, name="parcel")

    def drive(contact) -> None:  # type: ignore[no-untyped-def]
        # B moves along (n.y, -n.x) relative to A; with the normal from A to B that is
        # "rightwards over the top of the belt" whichever side the belt is on.
        if belt in (contact.collider_a, contact.collider_b):
            contact.tangent_speed = speed

    world.resource(Physics).on_pre_solve(drive)


@conveyor_belt.claim
def _parcels_carried_off(app) -> None:  # type: ignore[no-untyped-def]
    xs = [app.world.get(e, Transform).x for e in named(app.world, "parcel")]
    assert min(xs) > 3.0, f"the belt should have carried every parcel right: {xs}"


@sample("Collision", "Breakable",
        help="Two halves welded with a break force: a hard landing snaps them apart.")
def breakable(world: World, break_force: float = 300.0) -> None:
    from kge.components.joints import WeldJoint

    static_box(world, 0.0, -10.0, 50.0, 10.0, name="ground")
    left = box(world, -0.5, 20.0, 0.5, 0.5, density=10.0, name="half", angle=0.0)
    right = box(world, 0.5, 20.0, 0.5, 0.5, density=10.0, name="half", angle=0.0,
                angular_velocity=0.0)
    world.spawn(WeldJoint(left, right, anchor=(0.0, 20.0), break_force=break_force),
                Name("weld"))
    world.spawn(Transform(0.0, 0.5), Collider(Box(0.25, 0.5)), Name("anvil"))


@breakable.claim
def _it_broke(app) -> None:  # type: ignore[no-untyped-def]
    assert not named(app.world, "weld"), "the weld should have broken on impact"
    assert len(named(app.world, "half")) == 2


@sample("Collision", "Character",
        help="A box slides across a chain and across separate edges without bumps.")
def character(world: World, speed: float = 5.0) -> None:
    from kge.components.shapes import Chain, Edge

    world.spawn(Transform(), Collider(Chain([(-20.0 + i, 0.0) for i in range(41)]), friction=0.0),
                Name("chain"))
    for i in range(40):
        world.spawn(Transform(), Collider(Edge((-20.0 + i, 3.0), (-19.0 + i, 3.0)), friction=0.0))
    for y, name in ((0.51, "on-chain"), (3.51, "on-edges")):
        box(world, -15.0, y, 0.5, 0.5, friction=0.0, fixed_rotation=False, name=name,
            velocity=(speed, 0.0))


@character.claim
def _no_bumps(app) -> None:  # type: ignore[no-untyped-def]
    from kge.components.rigidbody import RigidBody

    for name in ("on-chain", "on-edges"):
        rb = app.world.get(named(app.world, name)[0], RigidBody)
        assert abs(rb.velocity[0] - 5.0) < 0.05 and abs(rb.velocity[1]) < 0.05, (name, rb)
