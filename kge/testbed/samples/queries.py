"""Query samples: ray casts (closest / any / all) and AABB queries."""

from __future__ import annotations

import math
from typing import Any

from kge.components import Behaviour, Name, Script, Transform
from kge.components.drawables import Circle as Dot
from kge.components.drawables import Line, Rect
from kge.keys import Key
from kge.physics.queries import RayMode
from kge.physics.resource import Physics
from kge.testbed.registry import sample
from kge.testbed.samples.build import ball, box, static_box
from kge.world import World


class RaySweeper(Script):
    """Sweeps a ray around a point each step and keeps the hits for drawing and tests."""

    MODES: tuple[RayMode, ...] = (RayMode.CLOSEST, RayMode.ANY, RayMode.ALL)

    def __init__(self, origin: tuple[float, float], length: float) -> None:
        self.origin = origin
        self.length = length
        self.angle = 0.0
        self.mode = RayMode.CLOSEST
        self.hits: list[Any] = []
        self.end = origin
        self.markers: list[int] = []

    def on_start(self) -> None:
        for _ in range(8):
            self.markers.append(
                self.world.spawn(Transform(*self.origin), Dot(0.12, color=(255, 80, 80, 255),
                                                              visible=False, layer=5))
            )

    def on_fixed_update(self, dt: float) -> None:
        self.angle += 0.25 * math.pi * dt
        ox, oy = self.origin
        c, s = math.cos(self.angle), math.sin(self.angle)
        self.end = (ox + self.length * c, oy + self.length * s)
        result = self.world.resource(Physics).raycast(self.origin, self.end, mode=self.mode)
        if result is None:
            self.hits = []
        elif isinstance(result, list):
            self.hits = result
        else:
            self.hits = [result]
        self._draw()

    def _draw(self) -> None:
        """Show the ray (yellow up to the first hit) and a dot on every hit."""
        ray = self.get(Line)
        ray.start = self.origin
        ray.end = self.hits[0].point if self.hits and self.mode is not RayMode.ALL else self.end
        for i, marker in enumerate(self.markers):
            dot = self.world.get(marker, Transform)
            if i < len(self.hits):
                dot.x, dot.y = self.hits[i].point
                self.world.get(marker, Dot).visible = True
            else:
                self.world.get(marker, Dot).visible = False

    def on_key_down(self, key: int) -> None:
        if key == Key.M:
            self.mode = self.MODES[(self.MODES.index(self.mode) + 1) % 3]


@sample("Queries", "Ray Cast", help="A ray sweeps around; M cycles closest / any / all.",
        keys={"M": "cycle the ray cast mode"})
def ray_cast(world: World) -> None:
    static_box(world, 0.0, -10.0, 50.0, 10.0, name="ground")
    for i in range(6):
        a = i * math.pi / 3.0
        static_box(world, 6.0 * math.cos(a), 5.0 + 4.0 * math.sin(a), 0.5, 0.5, angle=a,
                   name="target")
    world.spawn(Behaviour(RaySweeper((0.0, 5.0), 12.0)), Name("ray"),
                Line((0.0, 5.0), (0.0, 5.0), color=(250, 220, 80, 255), layer=5))


@ray_cast.claim
def _ray_hits_something(app) -> None:  # type: ignore[no-untyped-def]
    from kge.testbed.samples.build import named

    sweeper = app.world.get(named(app.world, "ray")[0], Behaviour).script
    sweeper.mode = RayMode.ALL
    app.step()
    assert sweeper.hits, "a 12 m ray from the centre always reaches the ground or a target"
    fractions = [h.fraction for h in sweeper.hits]
    assert fractions == sorted(fractions)


class BoxProbe(Script):
    """Moves a query box left and right; remembers which colliders it overlaps."""

    def __init__(self, half: float) -> None:
        self.half = half
        self.t = 0.0
        self.center = (0.0, 1.0)
        self.found: list[int] = []

    def on_fixed_update(self, dt: float) -> None:
        self.t += dt
        cx = 8.0 * math.sin(0.5 * self.t)
        self.center = (cx, 1.0)
        lower = (cx - self.half, 1.0 - self.half)
        upper = (cx + self.half, 1.0 + self.half)
        hits = self.world.resource(Physics).query_aabb(lower, upper)
        self.found = sorted({h.collider for h in hits})
        t = self.transform
        t.x, t.y = self.center


@sample("Queries", "AABB Query", help="A box-shaped query sweeps over scattered bodies.")
def aabb_query(world: World) -> None:
    static_box(world, 0.0, -10.0, 50.0, 10.0, name="ground")
    for i in range(8):
        x = -7.0 + 2.0 * i
        if i % 2:
            ball(world, x, 0.5, 0.5, name="thing")
        else:
            box(world, x, 0.5, name="thing")
    world.spawn(Transform(0.0, 1.0), Behaviour(BoxProbe(1.0)), Name("probe"),
                Rect(2.0, 2.0, color=(250, 220, 80, 255), filled=False, layer=5))


@aabb_query.claim
def _query_finds_overlaps(app) -> None:  # type: ignore[no-untyped-def]
    from kge.testbed.samples.build import named

    probe = app.world.get(named(app.world, "probe")[0], Behaviour).script
    assert probe.found, "the query box overlaps the ground and at least one body"
    for e in probe.found:
        assert app.world.exists(e)  # collider entities, all live
