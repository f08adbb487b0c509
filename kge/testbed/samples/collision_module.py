"""Collision Module samples: kge.collision's queries drawn live, no physics bodies.

The Box2D testbed shows its collision module with DistanceTest, TimeOfImpact,
PolyCollision and DynamicTreeTest; these are the same four on
:mod:`kge.collision`. Shapes are only drawn (drawables on entities whose
Transform is the pose); nothing is simulated, which is the point: the queries
need no World physics. Every motion runs on game time (fixed updates), so the
samples are deterministic headless.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import Any

import numpy as np

from kge import collision
from kge.components import Behaviour, Name, Script, Transform
from kge.components.drawables import Circle as Dot
from kge.components.drawables import Line, Rect
from kge.components.drawables import Polygon as Outline
from kge.components.shapes import Box, Circle, Polygon
from kge.keys import Key
from kge.testbed.registry import sample
from kge.testbed.samples.build import named
from kge.world import World

Vec2 = tuple[float, float]
GREY = (150, 150, 160, 255)
SHAPE_A = (120, 200, 255, 255)
SHAPE_B = (255, 160, 90, 255)
YELLOW = (250, 220, 80, 255)
RED = (255, 70, 70, 255)

HEXAGON = Polygon([(1.0, 0.0), (0.5, 0.87), (-0.5, 0.87), (-1.0, 0.0), (-0.5, -0.87),
                   (0.5, -0.87)])
PLANK = Box(1.2, 0.3)
_POINT = Circle(1e-9)  # a point for distance queries


def _outline(shape: Any, color: tuple[int, int, int, int], layer: int = 1) -> Outline:
    verts = shape.vertices() if isinstance(shape, Box) else shape.vertices
    return Outline(tuple(verts), color=color, filled=False, thickness=0.04, layer=layer)


def _pose(world: World, entity: int) -> tuple[float, float, float]:
    t = world.get(entity, Transform)
    return (t.x, t.y, t.angle)


def _probe(world: World, name: str) -> Any:
    """The script of the Behaviour on the entity called ``name``."""
    return world.get(named(world, name)[0], Behaviour).script


def _pair(world: World, hexagon_angle: float, plank_at: tuple[float, float],
          probe: Callable[[int], Script]) -> None:
    """A hexagon at (0, 5) and a plank driven by ``probe(hexagon_entity)``."""
    a = world.spawn(Transform(0.0, 5.0, hexagon_angle), _outline(HEXAGON, SHAPE_A),
                    Name("hexagon"))
    world.spawn(Transform(*plank_at), _outline(PLANK, SHAPE_B), Name("plank"),
                Behaviour(probe(a)))


class DistanceProbe(Script):
    """Moves shape B around A and draws the closest points; arrows / Q / E steer it."""

    def __init__(self, a: int) -> None:
        self.a = a
        self.t = 0.0
        self.steer = [0.0, 0.0, 0.0]
        self.result: collision.DistanceOutput | None = None
        self.line = 0

    def on_start(self) -> None:
        self.line = self.world.spawn(Transform(), Line((0, 0), (0, 0), color=YELLOW, layer=3,
                                                             thickness=0.06), Name("closest"))

    def on_fixed_update(self, dt: float) -> None:
        self.t += dt
        t = self.transform
        t.x = 3.0 * math.cos(0.4 * self.t) + self.steer[0]
        t.y = 5.0 + 2.0 * math.sin(0.4 * self.t) + self.steer[1]
        t.angle = 0.7 * self.t + self.steer[2]
        self.result = collision.distance(HEXAGON, _pose(self.world, self.a), PLANK,
                                         (t.x, t.y, t.angle))
        line = self.world.get(self.line, Line)
        line.start, line.end = self.result.point_a, self.result.point_b

    def on_key_down(self, key: int) -> None:
        moves = {Key.LEFT: (0, -0.2), Key.RIGHT: (0, 0.2), Key.DOWN: (1, -0.2),
                 Key.UP: (1, 0.2), Key.Q: (2, 0.2), Key.E: (2, -0.2)}
        if key in moves:
            i, d = moves[key]
            self.steer[i] += d


@sample("Collision Module", "Distance Test",
        help="GJK closest points between a hexagon and a plank (no physics).",
        keys={"arrows": "move the plank", "Q/E": "turn the plank"}, camera=(0.0, 5.0, 1.0))
def distance_test(world: World) -> None:
    _pair(world, 0.2, (3.0, 5.0), DistanceProbe)


@distance_test.claim
def _closest_points_span_the_gap(app: Any) -> None:
    world = app.world
    probe = _probe(world, "plank")
    x = world.get(named(world, "plank")[0], Transform).x
    app.input.press(Key.RIGHT)  # steering moves the plank by 0.2 m
    app.step()
    assert probe.steer[0] == 0.2
    assert math.isclose(world.get(named(world, "plank")[0], Transform).x - x,
                        0.2 + 3.0 * (math.cos(0.4 * probe.t) - math.cos(0.4 * (probe.t - 1 / 60))),
                        abs_tol=1e-6)
    out = probe.result
    assert out is not None and out.distance > 0.0
    line = world.get(named(world, "closest")[0], Line)
    assert math.isclose(math.dist(line.start, line.end), out.distance, abs_tol=1e-9)
    # the drawn points are on the shapes' rounded surfaces: B's point is not inside A
    hexagon = _pose(world, named(world, "hexagon")[0])
    assert not collision.test_point(HEXAGON, hexagon, line.end)


class ImpactProbe(Script):
    """Sweeps the plank across the hexagon; draws where the time of impact stops it."""

    def __init__(self, a: int, ghost: int) -> None:
        self.a, self.ghost = a, ghost
        self.t = 0.0
        self.result: collision.TOIOutput | None = None
        self.sweep: collision.Sweep | None = None

    def on_fixed_update(self, dt: float) -> None:
        self.t += dt
        y = 5.0 + 1.5 * math.sin(0.3 * self.t)
        start, end = (-5.0, y, 0.0), (5.0, 5.0 + 0.5 * math.cos(0.3 * self.t), 2.5)
        self.sweep = collision.Sweep.between(start, end)
        self.result = collision.time_of_impact(
            PLANK, self.sweep, HEXAGON, collision.Sweep.between(*[_pose(self.world, self.a)] * 2))
        t = self.transform
        t.x, t.y, t.angle = start
        at = self.sweep.transform(self.result.t)
        g = self.world.get(self.ghost, Transform)
        g.x, g.y, g.angle = at.x, at.y, at.angle


@sample("Collision Module", "Time of Impact",
        help="A plank sweeps 10 m in one step; red is where the time of impact stops it.",
        camera=(0.0, 5.0, 1.0))
def time_of_impact(world: World) -> None:
    a = world.spawn(Transform(0.0, 5.0, 0.3), _outline(HEXAGON, SHAPE_A), Name("hexagon"))
    world.spawn(Transform(5.0, 5.0, 2.5), _outline(PLANK, GREY), Name("end"))
    ghost = world.spawn(Transform(), _outline(PLANK, RED, layer=2), Name("impact"))
    world.spawn(Transform(-5.0, 5.0), _outline(PLANK, SHAPE_B), Name("start"),
                Behaviour(ImpactProbe(a, ghost)))


@time_of_impact.claim
def _impact_pose_touches(app: Any) -> None:
    world = app.world
    probe = _probe(world, "start")
    assert probe.result is not None and probe.result.state == "touching"
    hexagon = _pose(world, named(world, "hexagon")[0])
    at = _pose(world, named(world, "impact")[0])
    core = collision.distance(PLANK, at, HEXAGON, hexagon, use_radii=False).distance
    target = 0.02 - 3 * 0.005  # polygon radii less 3 linear slop (Box2D's TOI target)
    assert abs(core - target) <= 0.25 * 0.005 + 1e-9


class ManifoldProbe(Script):
    """Slides the plank through the hexagon and draws the manifold points and normal."""

    def __init__(self, a: int) -> None:
        self.a = a
        self.t = 0.0
        self.manifold: collision.Manifold | None = None
        self.dots: list[int] = []
        self.normal = 0

    def on_start(self) -> None:
        for _ in range(2):
            self.dots.append(self.world.spawn(Transform(), Dot(0.1, color=RED, layer=3,
                                                               visible=False)))
        self.normal = self.world.spawn(Transform(), Line((0, 0), (0, 0), color=YELLOW, layer=3,
                                                         thickness=0.06, visible=False),
                                       Name("normal"))

    def on_fixed_update(self, dt: float) -> None:
        self.t += dt
        t = self.transform
        t.x, t.y, t.angle = 2.2 * math.sin(0.5 * self.t), 5.9, 0.3 * math.sin(0.7 * self.t)
        m = collision.collide(HEXAGON, _pose(self.world, self.a), PLANK, (t.x, t.y, t.angle))
        self.manifold = m
        for i, dot in enumerate(self.dots):
            self.world.get(dot, Dot).visible = i < m.point_count
            if i < m.point_count:
                d = self.world.get(dot, Transform)
                d.x, d.y = m.points[i]
        line = self.world.get(self.normal, Line)
        line.visible = bool(m)
        if m:
            p = m.points[0]
            line.start, line.end = p, (p[0] + m.normal[0], p[1] + m.normal[1])


@sample("Collision Module", "Polygon Collision",
        help="Contact manifold (points and normal) of a plank sliding over a hexagon.",
        camera=(0.0, 5.0, 1.0))
def polygon_collision(world: World) -> None:
    _pair(world, 0.0, (0.0, 6.0), ManifoldProbe)


@polygon_collision.claim
def _manifold_points_are_in_both_shapes(app: Any) -> None:
    world = app.world
    probe = _probe(world, "plank")
    touching = 0
    for _ in range(60):
        app.step()
        m = probe.manifold
        if not m:
            continue
        touching += 1
        assert m.normal[1] > 0.0  # from the hexagon (below) up towards the plank
        plank = _pose(world, named(world, "plank")[0])
        hexagon = _pose(world, named(world, "hexagon")[0])
        for p, s in zip(m.points, m.separations, strict=True):
            assert s <= 0.0  # overlapping (skins included)
            # each point is midway between the two surfaces: within |s|/2 of both
            for shape, at in ((HEXAGON, hexagon), (PLANK, plank)):
                gap = collision.distance(_POINT, (*p, 0.0), shape, at).distance
                assert gap <= abs(s) / 2 + 1e-9
    assert touching > 10


class TreeProbe(Script):
    """Boxes drift in a field (numpy state), a tree tracks them, a query box sweeps."""

    def __init__(self, count: int, seed: int = 3) -> None:
        rng = np.random.default_rng(seed)
        self.pos = rng.uniform(-9.0, 9.0, size=(count, 2)) + np.array([0.0, 5.0])
        self.vel = rng.uniform(-1.0, 1.0, size=(count, 2))
        self.half = rng.uniform(0.1, 0.35, size=(count, 2))
        self.tree = collision.DynamicTree()
        self.proxies: list[int] = []
        self.entities: list[int] = []
        self.t = 0.0
        self.query = ((0.0, 0.0), (0.0, 0.0))
        self.found: set[int] = set()
        self.reinserted = 0

    def _box(self, i: int) -> tuple[Vec2, Vec2]:
        (x, y), (hx, hy) = self.pos[i], self.half[i]
        return ((float(x - hx), float(y - hy)), (float(x + hx), float(y + hy)))

    def on_start(self) -> None:
        for i in range(len(self.pos)):
            self.proxies.append(self.tree.insert(self._box(i), i))
            w, h = 2.0 * self.half[i]
            self.entities.append(self.world.spawn(
                Transform(*map(float, self.pos[i])),
                Rect(float(w), float(h), color=GREY)))

    def on_fixed_update(self, dt: float) -> None:
        self.t += dt
        self.pos += self.vel * dt
        bounce = np.abs(self.pos - np.array([0.0, 5.0])) > 9.0
        self.vel[bounce] *= -1.0
        for i, proxy in enumerate(self.proxies):
            shift = (float(self.vel[i, 0] * dt), float(self.vel[i, 1] * dt))
            self.reinserted += self.tree.move(proxy, self._box(i), shift)
            t = self.world.get(self.entities[i], Transform)
            t.x, t.y = float(self.pos[i, 0]), float(self.pos[i, 1])
        cx = 6.0 * math.sin(0.4 * self.t)
        self.query = ((cx - 2.0, 3.0), (cx + 2.0, 7.0))
        self.found = {self.tree.user_data(p) for p in self.tree.query(self.query)}
        for i, e in enumerate(self.entities):
            self.world.get(e, Rect).color = YELLOW if i in self.found else GREY
        q = self.transform
        q.x, q.y = cx, 5.0


@sample("Collision Module", "Dynamic Tree",
        help="A dynamic AABB tree tracks 150 drifting boxes; yellow = in the query box.",
        camera=(0.0, 5.0, 0.6))
def dynamic_tree(world: World, count: int = 150) -> None:
    world.spawn(Transform(0.0, 5.0), Rect(4.0, 4.0, color=RED, filled=False, layer=2),
                Name("query"), Behaviour(TreeProbe(count)))


@dynamic_tree.claim
def _tree_finds_every_overlap(app: Any) -> None:
    world = app.world
    probe = _probe(world, "query")
    probe.tree.validate()
    (qx0, qy0), (qx1, qy1) = probe.query
    lo, hi = probe.pos - probe.half, probe.pos + probe.half
    exact = set(np.flatnonzero((lo[:, 0] <= qx1) & (lo[:, 1] <= qy1)
                               & (hi[:, 0] >= qx0) & (hi[:, 1] >= qy0)).tolist())
    assert exact and exact <= probe.found
    assert probe.reinserted > 0
