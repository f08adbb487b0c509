"""pybox2d API samples: programs written against ``kge.box2d`` (pybox2d's names),
shown in the testbed through pybox2d's own debug drawing.

Each sample is a pybox2d program: it builds a ``b2World`` and steps it with
``Step(dt, velocityIterations, positionIterations)`` once per fixed update, then
calls ``DrawDebugData()`` with a :class:`~kge.box2d.view.KgeDraw` renderer that
turns Box2D's debug drawing into drawables of the testbed's world. The b2World
is a kge World of its own; the testbed's world holds only what is drawn.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import Any

import kge.box2d as b2
from kge.box2d.view import KgeDraw
from kge.components import Behaviour, Name, Script, Transform
from kge.keys import Key
from kge.testbed.registry import sample
from kge.testbed.samples.build import named
from kge.world import World


class Program(Script):
    """Runs one pybox2d program: its ``Step`` per fixed update, then its debug drawing."""

    def __init__(self, build: Callable[[], b2.b2World], velocity: int = 8,
                 position: int = 3, thickness: float = 0.05) -> None:
        self.b2world = build()
        self.velocity, self.position = velocity, position
        self.thickness = thickness  # of drawn lines, m (thin ones vanish when zoomed out)
        self.steps = 0

    def on_start(self) -> None:
        self.b2world.renderer = KgeDraw(self.world, thickness=self.thickness)
        self.draw()

    def on_fixed_update(self, dt: float) -> None:
        self.b2world.Step(dt, self.velocity, self.position)
        self.steps += 1
        self.draw()

    def draw(self) -> None:
        """One frame of debug drawing, framed by StartDraw/EndDraw as pybox2d's testbed does."""
        renderer = self.b2world.renderer
        renderer.StartDraw()
        self.b2world.DrawDebugData()
        renderer.EndDraw()


def _program(world: World, build: Callable[[], b2.b2World], **kw: Any) -> None:
    world.spawn(Transform(), Name("program"), Behaviour(Program(build, **kw)))


def _running(app: Any) -> Program:
    script = app.world.get(named(app.world, "program")[0], Behaviour).script
    assert isinstance(script, Program)
    return script


# -- the manual's hello world ----------------------------------------------------------------

def hello_world() -> b2.b2World:
    """The pybox2d manual's first program: a 1 m box falls onto a ground box."""
    world = b2.b2World(gravity=(0, -10), doSleep=True)
    world.CreateStaticBody(position=(0, -10), shapes=b2.b2PolygonShape(box=(50, 10)))
    body = world.CreateDynamicBody(position=(0, 4))
    body.CreatePolygonFixture(box=(1, 1), density=1, friction=0.3)
    return world


@sample("pybox2d API", "pybox2d Hello World",
        help="The pybox2d manual's hello world, unchanged, on kge.box2d.",
        camera=(0.0, 2.0, 1.0))
def hello_world_sample(world: World) -> None:
    _program(world, hello_world)


@hello_world_sample.claim
def _box_comes_to_rest_on_the_ground(app: Any) -> None:
    program = _running(app)
    box = program.b2world.bodies[-1]  # oldest first: the ground, then the box
    assert abs(box.position.y - 1.01) < 0.02 and abs(box.angle) < 0.01  # the manual: 1.00
    assert not box.awake  # Box2D's sleep: 0.5 s at rest
    # the box is drawn where it is: a solid polygon around (0, 1) in sleeping grey
    draw = program.b2world.renderer
    assert isinstance(draw, KgeDraw)
    from kge.components.drawables import Polygon

    drawn = [app.world.get(e, Polygon) for e in draw._pools[Polygon]]
    box_poly = [p for p in drawn if p.visible and max(y for _, y in p.vertices) < 3.0
                and min(y for _, y in p.vertices) > -0.5]
    assert len(box_poly) == 1 and box_poly[0].color[:3] == (153, 153, 153)


# -- a chain and a motor with limits ---------------------------------------------------------

LINKS = 12


def chain() -> b2.b2World:
    """A chain of revolute joints hung from the ground, and a motor swinging an arm
    between its limits (Box2D's revolute joint with ``enableMotor`` and ``enableLimit``)."""
    world = b2.b2World(gravity=(0, -10))
    ground = world.CreateStaticBody(shapes=b2.b2EdgeShape(vertices=[(-20, 0), (20, 0)]))
    prev = ground
    for i in range(LINKS):
        link = world.CreateDynamicBody(position=(-6.0 + 0.5 + i, 12.0))
        link.CreatePolygonFixture(box=(0.5, 0.125), density=20, friction=0.2)
        world.CreateRevoluteJoint(bodyA=prev, bodyB=link, anchor=(-6.0 + i, 12.0))
        prev = link
    arm = world.CreateDynamicBody(position=(8.0, 6.0))
    arm.CreatePolygonFixture(box=(2.0, 0.2), density=1)
    world.CreateRevoluteJoint(bodyA=ground, bodyB=arm, anchor=(6.0, 6.0), enableMotor=True,
                              motorSpeed=1.0, maxMotorTorque=500.0, enableLimit=True,
                              lowerAngle=-0.25 * math.pi, upperAngle=0.25 * math.pi)
    return world


class _Reverser(Program):
    """Space reverses the arm's motor."""

    def on_key_down(self, key: int) -> None:
        if key == Key.SPACE:
            motor = self.b2world.joints[-1]
            motor.motorSpeed = -motor.motorSpeed


@sample("pybox2d API", "pybox2d Chain and Motor",
        help="A 12-link revolute chain and a motor arm held by its limits (pybox2d code).",
        keys={"space": "reverse the motor"}, camera=(-2.0, 5.0, 0.4))
def chain_sample(world: World) -> None:
    world.spawn(Transform(), Name("program"), Behaviour(_Reverser(chain, 8, 3, thickness=0.12)))


@chain_sample.claim
def _chain_holds_and_arm_stays_in_limits(app: Any) -> None:
    program = _running(app)
    joints = program.b2world.joints  # oldest first: the chain, then the motor
    motor, links = joints[-1], joints[:-1]
    assert len(links) == LINKS
    assert max((j.anchorB - j.anchorA).length for j in links) < 0.02
    assert motor.angle <= 0.25 * math.pi + math.radians(2.0) + 1e-6  # on its upper limit
    assert motor.angle > 0.2 * math.pi
    app.input.press(Key.SPACE)
    app.step(120)
    assert motor.motorSpeed == -1.0
    assert motor.angle < -0.2 * math.pi  # driven over to the lower limit
    # every joint is drawn as three segments (Box2D's DrawJoint)
    assert program.steps >= 420
