"""Light samples: a lit room where a pyramid casts shadows, and a flashlight on the mouse.

The scenes draw their walls and boxes as lit shapes (layer 0-1) and switch the
physics debug draw off, since debug draw sits on the overlay layer, above the
light map (unlit).
"""

from __future__ import annotations

import math

import numpy as np

from kge.components import Behaviour, Name, Script, Transform
from kge.components.collider import Collider
from kge.components.debug import DebugDraw
from kge.components.drawables import Circle as Disc
from kge.components.drawables import Rect
from kge.components.lights import Light, Lighting, ShadowCaster
from kge.components.rigidbody import RigidBody
from kge.components.shapes import Box
from kge.input import Input
from kge.lighting import Occluders, shadow_quads
from kge.testbed.registry import sample
from kge.testbed.samples.build import named
from kge.world import World

WALL = (120, 110, 100)
BACK = (200, 190, 170)


def _room(world: World, half_width: float, height: float) -> None:
    """Back wall (a lit rectangle), floor and side walls (static colliders, drawn lit)."""
    world.insert_resource(DebugDraw(enabled=False))
    world.spawn(Transform(0.0, height / 2), Rect(2 * half_width, height, color=BACK, layer=0))
    for x, y, hw, hh in ((0.0, -0.5, half_width + 1.0, 0.5), (-half_width - 0.5, height / 2, 0.5,
                         height / 2 + 1.0), (half_width + 0.5, height / 2, 0.5, height / 2 + 1.0)):
        world.spawn(Transform(x, y), Collider(Box(hw, hh), friction=0.6), Name("wall"),
                    Rect(2 * hw, 2 * hh, color=WALL, layer=1))  # fmt: skip


@sample("Lights", "Lit Room", help="A lamp under the ceiling lights a room; a pyramid of boxes "
        "(shadow casters) throws soft shadows on the back wall. Ambient light fills the rest.",
        camera=(0.0, 6.0, 0.75))
def lit_room(world: World, rows: int = 6) -> None:
    world.insert_resource(Lighting(ambient=(35, 35, 55)))
    _room(world, 10.0, 13.0)
    for row in range(rows):
        for i in range(rows - row):
            x = (i - (rows - row - 1) / 2) * 1.05
            world.spawn(Transform(x, 0.5 + row * 1.0), RigidBody(), Collider(Box(0.5, 0.5)),
                        ShadowCaster(), Name("crate"),
                        Rect(1.0, 1.0, color=(180, 120, 60), layer=1))  # fmt: skip
    world.spawn(Transform(-1.5, 11.0), Name("lamp"), Disc(0.3, color=(255, 240, 200), layer=100),
                Light(radius=16.0, color=(255, 235, 190), intensity=1.2, falloff=1.2,
                      shadows=True, shadow_softness=0.3))  # fmt: skip
    world.spawn(Transform(8.0, 2.0), Light(radius=4.0, color=(80, 140, 255), falloff=2.0))


@lit_room.claim
def _the_pyramid_shadows_the_wall_behind_it(app) -> None:  # type: ignore[no-untyped-def]
    world = app.world
    for e in named(world, "crate"):
        assert world.get(e, Transform).y < 6.6, "the pyramid stands"
    lamp = world.get(named(world, "lamp")[0], Transform)
    edges, closed = world.resource(Occluders).edges(world, static=True)
    quads, _ = shadow_quads(np.array([[lamp.x, lamp.y]]), np.array([16.0]), edges, closed)

    def shadowed(p: tuple[float, float]) -> bool:
        for q in quads:
            s = [(b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0])
                 for a, b in zip(q, np.roll(q, -1, axis=0), strict=True)]  # fmt: skip
            if all(v >= 0 for v in s) or all(v <= 0 for v in s):
                return True
        return False

    # the lamp is up and to the left: the pyramid's shadow falls down to its right
    assert shadowed((3.3, 0.2)) and not shadowed((-6.0, 2.0)) and not shadowed((0.0, 8.0))


class _Flashlight(Script):
    """Turns the light towards the mouse pointer every frame."""

    def on_update(self, dt: float) -> None:
        mx, my = self.world.resource(Input).mouse_world
        t = self.transform
        if (mx, my) != (t.x, t.y):
            t.angle = math.atan2(my - t.y, mx - t.x)


@sample("Lights", "Flashlight", help="A spot light at the left wall follows the mouse; "
        "pillars cast hard shadows in a dark room.", keys={"mouse": "aim the flashlight"},
        camera=(0.0, 6.0, 0.75))
def flashlight(world: World) -> None:
    world.insert_resource(Lighting(ambient=(12, 12, 20)))
    _room(world, 10.0, 13.0)
    for i, (x, y) in enumerate(((-3.0, 3.0), (1.0, 7.0), (4.0, 2.0), (6.0, 9.0), (0.0, 11.0))):
        r = 0.4 + 0.15 * i
        world.spawn(Transform(x, y, 0.3 * i), Collider(Box(r, r)), Name("pillar"),
                    Rect(2 * r, 2 * r, color=(150, 150, 160), layer=1))  # fmt: skip
    world.spawn(Transform(-9.0, 6.0), Name("flashlight"), Behaviour(_Flashlight()),
                Light(radius=22.0, cone=0.7, softness=0.35, intensity=1.4, falloff=0.8,
                      color=(255, 250, 220), shadows=True),
                Disc(0.25, color=(255, 255, 200), layer=100))  # fmt: skip


@flashlight.claim
def _it_points_at_the_mouse(app) -> None:  # type: ignore[no-untyped-def]
    app.input.move_mouse(*app.world_to_screen((5.0, 1.0)))
    app.step(1)
    t = app.world.get(named(app.world, "flashlight")[0], Transform)
    assert math.isclose(t.angle, math.atan2(1.0 - 6.0, 5.0 + 9.0), abs_tol=1e-3)
