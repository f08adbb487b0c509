"""Joint samples, after the Box2D testbed: bridges, chains, cars, ragdolls, gears...

Every joint is an entity naming its two bodies (``None`` = the static ground).
"""

from __future__ import annotations

import math
from pathlib import Path

from kge.components import Behaviour, Name, Script, Transform
from kge.components.collider import Collider
from kge.components.filter import Filter
from kge.components.joints import (
    DistanceJoint,
    FrictionJoint,
    GearJoint,
    PrismaticJoint,
    PulleyJoint,
    RevoluteJoint,
    RopeJoint,
    WeldJoint,
    WheelJoint,
)
from kge.components.rigidbody import RigidBody
from kge.components.shapes import Box, Chain, Circle, Polygon
from kge.keys import Key
from kge.physics.resource import Physics
from kge.physics.settings import PhysicsSettings
from kge.testbed.registry import sample
from kge.testbed.samples.build import ball, box, ground, named
from kge.world import World


@sample("Joints", "Bridge", help="Thirty planks pinned end to end by revolute joints.")
def bridge(world: World, planks: int = 30) -> None:
    ground(world)
    prev: int | None = None
    for i in range(planks):
        plank = box(world, -14.5 + i, 5.0, 0.5, 0.125, density=20.0, friction=0.2, name="plank")
        world.spawn(RevoluteJoint(prev, plank, anchor=(-15.0 + i, 5.0)))
        prev = plank
    world.spawn(RevoluteJoint(prev, None, anchor=(-15.0 + planks, 5.0)))
    for i in range(3):
        box(world, -8.0 + 8.0 * i, 12.0, 0.5, 0.5, density=1.0, name="load")


@bridge.claim
def _bridge_holds(app) -> None:  # type: ignore[no-untyped-def]
    middle = named(app.world, "plank")[15]
    y = app.world.get(middle, Transform).y
    assert 2.0 < y < 5.0, f"the bridge's middle plank is at y={y:.2f}"


@sample("Joints", "Chain", help="A hanging chain of thirty links.")
def chain_sample(world: World, links: int = 30) -> None:
    ground(world)
    prev: int | None = None
    for i in range(links):
        link = box(world, 0.5 + i, 25.0, 0.6, 0.125, density=20.0, friction=0.2, name="link")
        world.spawn(RevoluteJoint(prev, link, anchor=(float(i), 25.0)))
        prev = link


@chain_sample.claim
def _chain_hangs_connected(app) -> None:  # type: ignore[no-untyped-def]
    world = app.world
    gaps = []
    for _, (j,) in world.query(RevoluteJoint):
        if j.body_a is None:
            continue
        pa = world.resource(Physics).world_point(j.body_a, j.local_anchor_a)
        pb = world.resource(Physics).world_point(j.body_b, j.local_anchor_b)
        gaps.append(math.dist(pa, pb))
    assert max(gaps) < 0.05, f"chain joints separated by {max(gaps):.3f} m"
    last = world.get(named(world, "link")[-1], Transform)
    assert last.y < 20.0, "the chain should swing down"


@sample("Joints", "Cantilever",
        help="Welded planks: rigid, and soft (5 Hz). The rigid one must not sag much.")
def cantilever(world: World, count: int = 8) -> None:
    ground(world)
    for y, hz in ((8.0, 0.0), (3.0, 5.0)):
        prev: int | None = None
        for i in range(count):
            name = "rigid" if hz == 0.0 else "soft"
            plank = box(world, -14.5 + i, y, 0.5, 0.125, density=20.0, name=name)
            world.spawn(WeldJoint(prev, plank, anchor=(-15.0 + i, y), frequency_hz=hz,
                                  damping_ratio=0.7))
            prev = plank


@cantilever.claim
def _rigid_cantilever_holds(app) -> None:  # type: ignore[no-untyped-def]
    tip = app.world.get(named(app.world, "rigid")[-1], Transform)
    assert tip.y > 8.0 - 2.8, f"rigid cantilever tip dropped to {tip.y:.2f} (Box2D: <= 2.77 m)"


class _Driver(Script):
    """A and D (or the arrows) drive the car's rear motor; S brakes."""

    def __init__(self, wheels: list[int], speed: float) -> None:
        self.wheels = wheels
        self.speed = speed

    def on_key_down(self, key: int) -> None:
        speed = {Key.A: self.speed, Key.LEFT: self.speed, Key.D: -self.speed,
                 Key.RIGHT: -self.speed, Key.S: 0.0, Key.DOWN: 0.0}.get(key)
        if speed is not None:
            for w in self.wheels:
                self.world.get(w, WheelJoint).motor_speed = speed


@sample("Joints", "Car", help="A car on wheel joints (spring suspension and a motor) over hills.",
        keys={"A/D": "drive left / right", "S": "brake"}, follow="chassis")
def car(world: World, motor_speed: float = -20.0) -> None:
    hills = [(-20.0, 0.0), (20.0, 0.0)]
    for i in range(1, 11):
        hills.append((20.0 + 5.0 * i, 0.6 * math.sin(i * 0.9) + 0.3 * (i % 3)))
    hills += [(80.0, 0.0), (120.0, 0.0), (120.0, 5.0)]
    world.spawn(Transform(), Collider(Chain(hills), friction=0.6), Name("ground"))
    chassis = world.spawn(
        Transform(0.0, 1.0), RigidBody(),
        Collider(Polygon([(-1.5, -0.5), (1.5, -0.5), (1.5, 0.0), (0.0, 0.9), (-1.15, 0.9),
                          (-1.5, 0.2)]), density=1.0),
        Name("chassis"),
    )
    wheels = []
    for x in (-1.0, 1.0):
        wheel = ball(world, x, 0.35, 0.4, density=1.0, friction=0.9, name="wheel")
        joint = world.spawn(WheelJoint(chassis, wheel, anchor=(x, 0.35), local_axis_a=(0.0, 1.0),
                                       enable_motor=x < 0, motor_speed=motor_speed,
                                       max_motor_torque=20.0, frequency_hz=4.0,
                                       damping_ratio=0.7))
        if x < 0:
            wheels.append(joint)
    world.spawn(Behaviour(_Driver(wheels, -motor_speed)))


@car.claim
def _car_drives_right(app) -> None:  # type: ignore[no-untyped-def]
    x = app.world.get(named(app.world, "chassis")[0], Transform).x
    assert x > 8.0, f"the car only reached x={x:.2f}"


def _ragdoll(world: World, x: float, y: float, group: int) -> None:
    f = Filter(group_index=-group)  # the parts of one ragdoll never collide with each other

    def part(px: float, py: float, hw: float, hh: float) -> int:
        return box(world, x + px, y + py, hw, hh, density=1.0, friction=0.4, filter=f,
                   name="ragdoll")

    head = ball(world, x, y + 1.75, 0.25, density=1.0, filter=f, name="head")
    torso = part(0.0, 1.0, 0.25, 0.5)
    world.spawn(RevoluteJoint(torso, head, anchor=(x, y + 1.5), enable_limit=True,
                              lower_angle=-0.5, upper_angle=0.5))
    for side in (-1.0, 1.0):
        upper_arm = part(side * 0.5, 1.3, 0.25, 0.1)
        world.spawn(RevoluteJoint(torso, upper_arm, anchor=(x + side * 0.25, y + 1.3),
                                  enable_limit=True, lower_angle=-1.5, upper_angle=1.5))
        lower_arm = part(side * 1.0, 1.3, 0.25, 0.08)
        world.spawn(RevoluteJoint(upper_arm, lower_arm, anchor=(x + side * 0.75, y + 1.3),
                                  enable_limit=True, lower_angle=-1.2, upper_angle=1.2))
        thigh = part(side * 0.12, 0.25, 0.1, 0.25)
        world.spawn(RevoluteJoint(torso, thigh, anchor=(x + side * 0.12, y + 0.5),
                                  enable_limit=True, lower_angle=-1.0, upper_angle=1.0))
        shin = part(side * 0.12, -0.25, 0.08, 0.25)
        world.spawn(RevoluteJoint(thigh, shin, anchor=(x + side * 0.12, y),
                                  enable_limit=True, lower_angle=-1.5, upper_angle=0.0))


@sample("Joints", "Ragdoll", help="Ragdolls with limited revolute joints tumbling down.")
def ragdoll(world: World, count: int = 4) -> None:
    ground(world)
    for i in range(count):
        _ragdoll(world, -3.0 + 2.0 * i, 3.0 + 2.5 * i, group=i + 1)


@ragdoll.claim
def _ragdolls_stay_assembled(app) -> None:  # type: ignore[no-untyped-def]
    physics = app.world.resource(Physics)
    for _, (j,) in app.world.query(RevoluteJoint):
        gap = math.dist(physics.world_point(j.body_a, j.local_anchor_a),
                        physics.world_point(j.body_b, j.local_anchor_b))
        assert gap < 0.05, f"a ragdoll joint opened by {gap:.3f} m"
        slack = math.radians(8.0)  # a hard landing may push a soft limit a few degrees
        assert j.lower_angle - slack <= j.angle <= j.upper_angle + slack, j


@sample("Joints", "Web", help="Four boxes held by soft distance joints (2 Hz).")
def web(world: World) -> None:
    ground(world)
    corners = [(-5.0, 5.0), (5.0, 5.0), (5.0, 15.0), (-5.0, 15.0)]
    bodies = [box(world, x, y, 0.5, 0.5, density=5.0, name="node") for x, y in corners]
    anchors = [(-10.0, 0.0), (10.0, 0.0), (10.0, 20.0), (-10.0, 20.0)]
    for b, (cx, cy), anchor in zip(bodies, corners, anchors, strict=True):
        world.spawn(DistanceJoint(None, b, anchor_a=anchor, anchor_b=(cx, cy),
                                  frequency_hz=2.0, damping_ratio=0.0))
    for i in range(4):
        a, b = bodies[i], bodies[(i + 1) % 4]
        world.spawn(DistanceJoint(a, b, anchor_a=corners[i], anchor_b=corners[(i + 1) % 4],
                                  frequency_hz=2.0, damping_ratio=0.0))


@sample("Joints", "Pulleys",
        help="Two boxes on a pulley (ratio 1.5): length_a + 1.5 length_b holds.")
def pulleys(world: World, ratio: float = 1.5) -> None:
    ground(world)
    a = box(world, -10.0, 10.0, 2.0, 0.5, density=5.0, name="left")
    b = box(world, 10.0, 10.0, 2.0, 0.5, density=5.0, name="right")
    world.spawn(PulleyJoint(a, b, ground_anchor_a=(-10.0, 20.0), ground_anchor_b=(10.0, 20.0),
                            anchor_a=(-10.0, 10.5), anchor_b=(10.0, 10.5), ratio=ratio),
                Name("pulley"))


@pulleys.claim
def _pulley_conserves_length(app) -> None:  # type: ignore[no-untyped-def]
    world = app.world
    j = world.get(named(world, "pulley")[0], PulleyJoint)
    total = j.length_a + j.ratio * j.length_b
    assert abs(total - (9.5 + 1.5 * 9.5)) < 0.05, f"pulley length drifted to {total:.3f}"


class _GearProbe(Script):
    """Remembers the two geared wheels' speeds (the claim compares them)."""

    def __init__(self, small: int, big: int) -> None:
        self.small, self.big = small, big


@sample("Joints", "Gears", help="A motor disc geared to a bigger disc (ratio 2) and to a rack.")
def gears(world: World) -> None:
    ground(world)
    small = ball(world, -3.0, 10.0, 1.0, density=5.0, name="small")
    big = ball(world, 0.0, 10.0, 2.0, density=5.0, name="big")
    j1 = world.spawn(RevoluteJoint(None, small, anchor=(-3.0, 10.0), enable_motor=True,
                                   motor_speed=2.0, max_motor_torque=1000.0))
    j2 = world.spawn(RevoluteJoint(None, big, anchor=(0.0, 10.0)))
    world.spawn(GearJoint(j1, j2, ratio=2.0))
    rack = box(world, 4.0, 10.0, 0.25, 2.0, density=1.0, name="rack")
    j3 = world.spawn(RevoluteJoint(None, ball(world, 4.0, 13.0, 1.0, name="pinion"),
                                   anchor=(4.0, 13.0)))
    j4 = world.spawn(PrismaticJoint(None, rack, anchor=(4.0, 10.0), local_axis_a=(0.0, 1.0),
                                    enable_limit=True, lower_translation=-5.0,
                                    upper_translation=5.0))
    world.spawn(GearJoint(j3, j4, ratio=-1.0))
    world.spawn(Behaviour(_GearProbe(small, big)))


@gears.claim
def _gear_ratio(app) -> None:  # type: ignore[no-untyped-def]
    world = app.world
    w1 = world.get(named(world, "small")[0], RigidBody).angular_velocity
    w2 = world.get(named(world, "big")[0], RigidBody).angular_velocity
    assert abs(w1 - 2.0) < 0.02 and abs(w2 + w1 / 2.0) < 0.02, (w1, w2)


@sample("Joints", "Prismatic", help="A box on a slanted prismatic axis with limits and a motor.")
def prismatic(world: World) -> None:
    ground(world)
    body = box(world, 0.0, 10.0, 2.0, 0.5, density=5.0, angle=0.5 * math.pi, name="slider")
    axis = (2.0 / math.sqrt(5.0), 1.0 / math.sqrt(5.0))
    world.spawn(PrismaticJoint(None, body, anchor=(0.0, 10.0), local_axis_a=axis,
                               enable_limit=True, lower_translation=-10.0, upper_translation=2.0,
                               enable_motor=True, motor_speed=-10.0, max_motor_force=10000.0),
                Name("prismatic"))


@prismatic.claim
def _stays_in_limits(app) -> None:  # type: ignore[no-untyped-def]
    j = app.world.get(named(app.world, "prismatic")[0], PrismaticJoint)
    assert -10.05 <= j.translation <= 2.05, j.translation


@sample("Joints", "Revolute", help="A motorised wheel and a pendulum swinging into a limit.",
        keys={"L": "toggle the limit", "M": "toggle the motor"})
def revolute(world: World) -> None:
    ground(world)
    wheel = ball(world, -5.0, 10.0, 0.5, density=5.0, name="wheel")
    world.spawn(RevoluteJoint(None, wheel, anchor=(-5.0, 10.0), enable_motor=True,
                              motor_speed=math.pi, max_motor_torque=10000.0))
    arm = box(world, 2.5, 10.0, 2.5, 0.1, density=5.0, name="arm")
    world.spawn(RevoluteJoint(None, arm, anchor=(0.0, 10.0), enable_limit=True,
                              lower_angle=-0.25 * math.pi, upper_angle=0.5 * math.pi),
                Name("limited"), Behaviour(_Toggler()))


class _Toggler(Script):
    def on_key_down(self, key: int) -> None:
        j = self.get(RevoluteJoint)
        if key == Key.L:
            j.enable_limit = not j.enable_limit
        elif key == Key.M:
            j.enable_motor = not j.enable_motor
            j.motor_speed, j.max_motor_torque = 1.0, 1000.0


@revolute.claim
def _limit_holds(app) -> None:  # type: ignore[no-untyped-def]
    j = app.world.get(named(app.world, "limited")[0], RevoluteJoint)
    assert -0.25 * math.pi - math.radians(2.5) <= j.angle <= 0.5 * math.pi + math.radians(2.5)


@sample("Joints", "Rope", help="A chain whose end is held by a rope joint: never farther than max.")
def rope(world: World, links: int = 12) -> None:
    ground(world)
    y = 20.0
    prev: int | None = None
    first = None
    for i in range(links):
        link = box(world, 0.5 + i, y, 0.5, 0.125, density=20.0, friction=0.2, name="link")
        world.spawn(RevoluteJoint(prev, link, anchor=(float(i), y)))
        prev = link
        first = first or link
    weight = ball(world, links + 0.5, y, 1.0, density=50.0, name="weight")
    world.spawn(RevoluteJoint(prev, weight, anchor=(float(links), y)))
    world.spawn(RopeJoint(None, weight, anchor_a=(0.0, y), anchor_b=(links + 0.5, y),
                          max_length=links - 1.0 + 0.01), Name("rope"))


@rope.claim
def _rope_holds(app) -> None:  # type: ignore[no-untyped-def]
    world = app.world
    w = world.get(named(world, "weight")[0], Transform)
    j = world.get(named(world, "rope")[0], RopeJoint)
    assert math.dist((0.0, 20.0), (w.x, w.y)) <= (j.max_length or 0.0) + 0.05


@sample("Joints", "Mobile", help="A balanced mobile: a tree of weighted bars on revolute joints.")
def mobile(world: World, depth: int = 4) -> None:
    ground(world)
    a = 0.5

    def node(parent: int | None, anchor: tuple[float, float], level: int, offset: float) -> int:
        x, y = anchor[0], anchor[1] - a
        body = world.spawn(Transform(x, y), RigidBody(),
                           Collider(Box(0.25 * a, a), density=20.0), Name("mobile"))
        world.spawn(RevoluteJoint(parent, body, anchor=anchor))
        if level < depth:
            world.spawn(Transform(x, y), Collider(Box(offset, 0.25 * a, center=(0.0, -a)),
                                                  density=20.0, body=body))
            node(body, (x - offset, y - a), level + 1, 0.5 * offset)
            node(body, (x + offset, y - a), level + 1, 0.5 * offset)
        return body

    node(None, (0.0, 20.0), 0, 4.0)


@mobile.claim
def _mobile_hangs_together(app) -> None:  # type: ignore[no-untyped-def]
    world = app.world
    physics = world.resource(Physics)
    for _, (j,) in world.query(RevoluteJoint):
        pa = (0.0, 20.0) if j.body_a is None else physics.world_point(j.body_a, j.local_anchor_a)
        pb = physics.world_point(j.body_b, j.local_anchor_b)
        assert math.dist(pa, pb) < 0.05, f"mobile joint opened by {math.dist(pa, pb):.3f} m"
    root = world.get(named(world, "mobile")[0], Transform)
    assert abs(root.x) < 0.05 and abs(root.y - 19.5) < 0.05, f"unbalanced: {root}"


@sample("Joints", "Theo Jansen", help="Theo Jansen's walker: a motor crank drives linkage legs.",
        keys={"A/D": "walk left / right", "S": "stop"})
def theo_jansen(world: World, motor_speed: float = 2.0) -> None:
    ground(world, half_width=60.0)
    offset = (0.0, 8.0)
    pivot = (0.0, 0.8)
    group = Filter(group_index=-1)
    chassis = world.spawn(Transform(pivot[0] + offset[0], pivot[1] + offset[1]), RigidBody(),
                          Collider(Box(2.5, 1.0), density=1.0, filter=group), Name("chassis"))
    wheel = world.spawn(Transform(pivot[0] + offset[0], pivot[1] + offset[1]), RigidBody(),
                        Collider(Circle(1.6), density=1.0, filter=group), Name("crank"))
    motor = world.spawn(RevoluteJoint(wheel, chassis, anchor=(pivot[0] + offset[0],
                                                              pivot[1] + offset[1]),
                                      enable_motor=True, motor_speed=motor_speed,
                                      max_motor_torque=400.0))
    world.spawn(Behaviour(_Walker(motor, motor_speed)))
    for phase in (0.0, 2.0 * math.pi / 3.0, -2.0 * math.pi / 3.0):
        for side in (-1.0, 1.0):
            _leg(world, side, phase, offset, chassis, wheel, pivot, group)


def _leg(world: World, s: float, phase: float, offset: tuple[float, float], chassis: int,
         wheel: int, pivot: tuple[float, float], group: Filter) -> None:
    """One leg of the linkage (Box2D testbed proportions), mirrored by ``s``.

    As in the testbed, every leg is built in the same pose and hooked to the crank
    at a point turned by ``phase``; the link lengths are those measured to the
    unturned crank point, which gives the three legs their phase difference.
    """
    ox, oy = offset
    cx, cy = pivot[0] + ox, pivot[1] + oy
    rest = (pivot[0] + ox, pivot[1] - 0.8 + oy)  # the crank point before turning
    crank = (cx + 0.8 * math.sin(phase), cy - 0.8 * math.cos(phase))
    p1, p2, p3 = (5.4 * s, -6.1), (7.2 * s, -1.2), (4.3 * s, -1.9)
    p4, p5, p6 = (3.1 * s, 0.8), (6.0 * s, 1.5), (2.5 * s, 3.7)
    tri1 = [p1, p2, p3] if s > 0 else [p1, p3, p2]
    tri2 = [(0.0, 0.0), (p5[0] - p4[0], p5[1] - p4[1]), (p6[0] - p4[0], p6[1] - p4[1])]
    if s < 0:
        tri2 = [tri2[0], tri2[2], tri2[1]]
    leg = world.spawn(Transform(ox, oy), RigidBody(angular_damping=10.0),
                      Collider(Polygon(tri1), density=1.0, filter=group), Name("leg"))
    shoulder = world.spawn(Transform(p4[0] + ox, p4[1] + oy), RigidBody(angular_damping=10.0),
                           Collider(Polygon(tri2), density=1.0, filter=group))

    def at(p: tuple[float, float]) -> tuple[float, float]:
        return (p[0] + ox, p[1] + oy)

    links = (
        (leg, shoulder, at(p2), at(p5), None),
        (leg, shoulder, at(p3), at(p4), None),
        (leg, wheel, at(p3), crank, math.dist(at(p3), rest)),
        (shoulder, wheel, at(p6), crank, math.dist(at(p6), rest)),
    )
    for a, b, pa, pb, length in links:
        world.spawn(DistanceJoint(a, b, anchor_a=pa, anchor_b=pb, length=length,
                                  frequency_hz=10.0, damping_ratio=0.5))
    world.spawn(RevoluteJoint(shoulder, chassis, anchor=at(p4)))


class _Walker(Script):
    def __init__(self, motor: int, speed: float) -> None:
        self.motor = motor
        self.speed = speed

    def on_key_down(self, key: int) -> None:
        j = self.world.get(self.motor, RevoluteJoint)
        if key in (Key.A, Key.LEFT):
            j.motor_speed = -self.speed
        elif key in (Key.D, Key.RIGHT):
            j.motor_speed = self.speed
        elif key in (Key.S, Key.DOWN):
            j.motor_speed = 0.0


@theo_jansen.claim
def _walker_moves(app) -> None:  # type: ignore[no-untyped-def]
    t = app.world.get(named(app.world, "chassis")[0], Transform)
    assert abs(t.x) > 0.5 and t.y > 2.0, f"the walker did not walk: {t}"


@sample("Joints", "Apply Force",
        help="Top-down: W thrusts, A/D turn; friction joints to the ground slow everything.",
        keys={"W": "thrust", "A/D": "turn"})
def apply_force(world: World) -> None:
    world.insert_resource(PhysicsSettings(gravity=(0.0, 0.0)))
    for x, y, hw, hh in ((0.0, 20.0, 20.0, 0.5), (0.0, -20.0, 20.0, 0.5),
                         (20.0, 0.0, 0.5, 20.0), (-20.0, 0.0, 0.5, 20.0)):
        world.spawn(Transform(x, y), Collider(Box(hw, hh)), Name("wall"))
    world.spawn(Transform(0.0, -12.0), RigidBody(angular_damping=2.0, linear_damping=0.5),
                Collider(Polygon([(-1.0, 0.0), (1.0, 0.0), (0.0, 2.0)]), density=4.0),
                Name("ship"), Behaviour(_Thruster()))
    for i in range(10):
        crate = box(world, -9.0 + 2.0 * i, 5.0, 0.5, 0.5, density=1.0, friction=0.3,
                    name="crate", velocity=(0.0, -6.0 + i))
        mass = 1.0
        world.spawn(FrictionJoint(None, crate, anchor=(-9.0 + 2.0 * i, 5.0),
                                  max_force=mass * 10.0, max_torque=mass * 1.0))


class _Thruster(Script):
    def on_fixed_update(self, dt: float) -> None:
        from kge.input import Input

        keys = self.world.resource(Input)
        physics = self.world.resource(Physics)
        if keys.held(Key.W):
            fx, fy = physics.world_vector(self.entity, (0.0, 200.0))
            physics.apply_force(self.entity, (fx, fy), physics.world_point(self.entity, (0, 2)))
        turn = keys.axis((Key.D,), (Key.A,))
        if turn:
            physics.apply_torque(self.entity, 50.0 * turn)


@apply_force.claim
def _friction_joints_stop_crates(app) -> None:  # type: ignore[no-untyped-def]
    for e in named(app.world, "crate"):
        vx, vy = app.world.get(e, RigidBody).velocity
        assert math.hypot(vx, vy) < 0.05, "friction joints should have stopped every crate"



PREFABS = Path(__file__).resolve().parent.parent / "prefabs"


@sample("Joints", "Prefabs", help="Two cars and three ragdolls placed from prefab files "
        "(kge/testbed/prefabs/*.prefab.toml); the second car overrides its motor speed.",
        follow="chassis")
def prefabs(world: World) -> None:
    from kge.scenefile import instantiate

    hills = [(-30.0, 0.0), (60.0, 0.0), (60.0, 5.0)]
    world.spawn(Transform(), Collider(Chain([(-30.0, 5.0), *hills]), friction=0.6),
                Name("ground"))
    instantiate(world, PREFABS / "car.prefab.toml", at=(0.0, 1.0), key="car")
    instantiate(world, PREFABS / "car.prefab.toml", at=(-8.0, 1.0), key="fast_car",
                overrides={"rear_axle": {"WheelJoint": {"motor_speed": -35.0}}})
    for i in range(3):
        instantiate(world, PREFABS / "ragdoll.prefab.toml", at=(-20.0 + 3.0 * i, 3.0 + 2.0 * i),
                    key=f"ragdoll{i + 1}")


@prefabs.claim
def _prefab_cars_drive_and_ragdolls_hold(app) -> None:  # type: ignore[no-untyped-def]
    xs = sorted(app.world.get(e, Transform).x for e in named(app.world, "chassis"))
    assert len(xs) == 2 and xs[1] > 6.0, f"the cars reached {xs}"
    _ragdolls_stay_assembled(app)
