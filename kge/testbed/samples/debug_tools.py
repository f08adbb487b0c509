"""Debug-tool samples: gizmos drawn from physics, a console command, the inspector."""

from __future__ import annotations

import math

from kge.components import Behaviour, Name, Script, Transform
from kge.components.rigidbody import RigidBody
from kge.debug import Console, Gizmos
from kge.physics.resource import Physics
from kge.testbed.registry import sample
from kge.testbed.samples.build import ball, named, static_box
from kge.world import World


class _Sensors(Script):
    """Every fixed step: a fan of rays from the eye, velocity arrows on the balls."""

    def on_fixed_update(self, dt: float) -> None:
        world = self.world
        g = world.resource(Gizmos)
        physics = world.resource(Physics)
        ex, ey = self.transform.x, self.transform.y
        for i in range(9):
            a = -math.pi / 2 + (i - 4) * 0.15
            end = (ex + 12 * math.cos(a), ey + 12 * math.sin(a))
            hit = physics.raycast((ex, ey), end)
            if hit is None:
                g.line((ex, ey), end, (90, 90, 110))
                continue
            g.line((ex, ey), hit.point, (255, 210, 60))
            g.cross(hit.point, 0.25, (255, 90, 60))
        for _, (rb, t) in world.query(RigidBody, Transform):
            vx, vy = rb.velocity
            if vx * vx + vy * vy > 0.01:
                g.arrow((t.x, t.y), (t.x + 0.3 * vx, t.y + 0.3 * vy), (80, 200, 255))
        g.text((-9.5, 9.0), "backquote: console   F3: inspector   F4: system timings",
               (230, 230, 230), size=11)


@sample("Debug", "Gizmos And Console", help="Rays and velocity arrows drawn as gizmos each "
        "step; the console has a `ball x y` command (backquote), F3 inspects, F4 times the "
        "systems.", camera=(0.0, 2.0, 1.0))
def gizmos_and_console(world: World, balls: int = 6) -> None:
    static_box(world, 0.0, -1.0, 10.0, 0.5, name="ground")
    static_box(world, -10.0, 4.0, 0.5, 5.0, name="wall")
    static_box(world, 10.0, 4.0, 0.5, 5.0, name="wall")
    for i in range(balls):
        ball(world, -5.0 + 2.0 * i, 4.0 + 1.5 * (i % 3), 0.4, restitution=0.7, name="ball")
    world.spawn(Transform(0.0, 9.0), Name("eye"), Behaviour(_Sensors()))
    world.resource(Console).add_command(_drop_ball, "ball", help="drop a ball at x, y")


def _drop_ball(world: World, x: float = 0.0, y: float = 8.0) -> str:
    return f"ball {ball(world, x, y, 0.4, restitution=0.7, name='ball')}"


@gizmos_and_console.claim
def _rays_hit_and_the_console_spawns(app) -> None:  # type: ignore[no-untyped-def]
    g = app.world.resource(Gizmos)
    segments, _ = g.segments()
    assert len(segments) > 9, f"only {len(segments)} gizmo segments"
    before = len(named(app.world, "ball"))
    result = app.world.resource(Console).run("ball 1 6")
    assert result.ok, result.text
    app.step(1)
    assert len(named(app.world, "ball")) == before + 1
