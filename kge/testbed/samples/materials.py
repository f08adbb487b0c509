"""Material samples: restitution and friction, with Box2D's mixing rules."""

from __future__ import annotations

import math

from kge.components import Transform
from kge.components.rigidbody import RigidBody
from kge.testbed.registry import sample
from kge.testbed.samples.build import ball, box, named, static_box
from kge.world import World

RESTITUTIONS = (0.0, 0.1, 0.3, 0.5, 0.75, 0.9, 1.0)


@sample("Materials", "Restitution",
        help="Balls with restitution 0 to 1 dropped from the same height.")
def restitution(world: World) -> None:
    static_box(world, 0.0, -10.0, 50.0, 10.0, name="ground")
    for i, e in enumerate(RESTITUTIONS):
        ball(world, -9.0 + 3.0 * i, 10.0, 0.5, density=1.0, restitution=e, name=f"e={e}")


@restitution.claim
def _inelastic_rests_elastic_bounces(app) -> None:  # type: ignore[no-untyped-def]
    world = app.world
    dead = world.get(named(world, "e=0.0")[0], Transform)
    assert abs(dead.y - 0.5) < 0.03, f"e=0 ball should rest on the ground: {dead}"
    live = named(world, "e=1.0")[0]
    t, rb = world.get(live, Transform), world.get(live, RigidBody)
    energy = 10.0 * (t.y - 0.5) + 0.5 * (rb.velocity[0] ** 2 + rb.velocity[1] ** 2)
    assert energy > 0.8 * 10.0 * 9.5, f"e=1 ball lost energy: {energy:.2f} J/kg"


FRICTIONS = (0.0, 0.3, 0.5, 0.6, 1.0)


@sample("Materials", "Varying Friction",
        help="Boxes on 30-degree slopes: friction >= tan(30) = 0.577 sticks, less slides.")
def varying_friction(world: World) -> None:
    slope = math.radians(30.0)
    c, s = math.cos(slope), math.sin(slope)
    static_box(world, 0.0, -10.0, 50.0, 10.0, name="ground")
    for i, mu in enumerate(FRICTIONS):
        x0 = -20.0 + 10.0 * i
        static_box(world, x0, 5.0, 4.0, 0.25, angle=-slope, friction=mu, name="slope")
        # on the upper end of the slope, resting on its surface
        bx = x0 - 2.5 * c - 0.75 * s
        by = 5.0 + 2.5 * s + 0.75 * c
        box(world, bx, by, 0.5, 0.5, angle=-slope, friction=mu, name=f"mu={mu}")


@varying_friction.claim
def _stick_or_slide(app) -> None:  # type: ignore[no-untyped-def]
    world = app.world
    sticky = world.get(named(world, "mu=1.0")[0], RigidBody)
    assert math.hypot(*sticky.velocity) < 0.05, f"mu=1 box should stick: {sticky.velocity}"
    slick = world.get(named(world, "mu=0.0")[0], Transform)
    assert slick.y < 2.0, f"frictionless box should have slid off: {slick}"
