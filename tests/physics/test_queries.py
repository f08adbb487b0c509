"""Box2D query semantics (box2d-reference.md rows QueryAABB, RayCast callback,
shape TestPoint / RayCast) on hand-built pymunk spaces.

Shapes are registered in the space's shape table as the physics system does it
(collider and body entity, filter, sensor flag) and carry the 0.01 m polygon/edge
skin, so these tests see exactly what queries see inside a running kge world.
"""

from __future__ import annotations

import itertools
import math
import random
from dataclasses import dataclass

import pymunk
import pytest

from kge.components.filter import Filter
from kge.components.shapes import Box, Chain, Circle, Edge, Polygon
from kge.components.transform import Transform
from kge.errors import ComponentTypeError, ValidationError
from kge.physics.queries import QueryHit, RayHit, query_aabb, query_point, query_shape, raycast
from kge.physics.shape_table import ShapeTable

SKIN = 0.01


def _tag(
    space: pymunk.Space, shape: pymunk.Shape, collider: int, body: int | None, flt: Filter,
    sensor: bool,
) -> None:
    ShapeTable.of(space).add(shape, collider, body, filter=flt, sensor=sensor)
    shape.sensor = sensor


class Scene:
    """A pymunk space populated the way kge's physics system does it."""

    def __init__(self) -> None:
        self.space = pymunk.Space()
        self.next_entity = 1

    def _entity(self) -> int:
        e = self.next_entity
        self.next_entity += 1
        return e

    def add(
        self,
        kind: str,
        pos: tuple[float, float],
        *,
        dynamic: bool = False,
        sensor: bool = False,
        flt: Filter | None = None,
        angle: float = 0.0,
        size: float = 0.5,
    ) -> int:
        """Add a collider; returns its collider entity (the body entity is the same id)."""
        entity = self._entity()
        if dynamic:
            body = pymunk.Body()
            body_entity: int | None = entity
        else:
            body = pymunk.Body(body_type=pymunk.Body.STATIC)
            body_entity = None
        body.position = pos
        body.angle = angle
        if kind == "box":
            shapes: list[pymunk.Shape] = [pymunk.Poly.create_box(body, (2 * size, 2 * size), SKIN)]
        elif kind == "circle":
            shapes = [pymunk.Circle(body, size)]
        elif kind == "edge":
            shapes = [pymunk.Segment(body, (0, -1), (0, 1), SKIN)]
        elif kind == "chain":
            pts = [(-1.0, 0.0), (0.0, 0.0), (1.0, 0.0), (1.0, 1.0)]
            shapes = [pymunk.Segment(body, a, b, SKIN) for a, b in itertools.pairwise(pts)]
        else:
            raise AssertionError(kind)
        for s in shapes:
            if dynamic:
                s.density = 1.0
            _tag(self.space, s, entity, body_entity, flt or Filter(), sensor)
        self.space.add(body, *shapes)
        return entity

    def refresh(self) -> None:
        """Bring the spatial index up to date, as after a physics step."""
        self.space.reindex_static()
        for b in self.space.bodies:
            self.space.reindex_shapes_for_body(b)


@pytest.fixture
def reference_scene() -> tuple[Scene, dict[str, int]]:
    """box2d-reference QueryAABB / RayCast setup: boxes at 0, 3, 6, circle at 9, sensor at (0,5)."""
    sc = Scene()
    ids = {
        "box0": sc.add("box", (0, 0)),
        "box3": sc.add("box", (3, 0)),
        "box6": sc.add("box", (6, 0)),
        "circle": sc.add("circle", (9, 0), dynamic=True),
        "sensor": sc.add("box", (0, 5), sensor=True),
    }
    sc.refresh()
    return sc, ids


# ------------------------------------------------------------------------------ ray cast


def test_closest_hit_matches_box2d(reference_scene: tuple[Scene, dict[str, int]]) -> None:
    sc, ids = reference_scene
    hit = raycast(sc.space, (-2, 0), (12, 0))
    assert isinstance(hit, RayHit)
    assert hit.collider == ids["box0"] and hit.body is None  # static: implicit body
    assert hit.fraction == pytest.approx(0.10714, abs=1e-4)
    assert hit.point == pytest.approx((-0.5, 0.0), abs=1e-9)  # skin ignored, as Box2D
    assert hit.normal == pytest.approx((-1.0, 0.0))


def test_callback_protocol_clip_continue_stop_ignore(
    reference_scene: tuple[Scene, dict[str, int]],
) -> None:
    sc, ids = reference_scene
    calls: list[RayHit] = []

    def clip(hit: RayHit) -> float:
        calls.append(hit)
        return hit.fraction

    assert raycast(sc.space, (-2, 0), (12, 0), clip) is None
    assert calls[-1].collider == ids["box0"]  # the last clip is the closest hit
    assert calls[-1].fraction == pytest.approx(0.10714, abs=1e-4)

    seen: list[int] = []

    def continue_(hit: RayHit) -> float:
        seen.append(hit.collider)
        return 1.0

    raycast(sc.space, (-2, 0), (12, 0), continue_)
    assert sorted(seen) == sorted([ids["box0"], ids["box3"], ids["box6"], ids["circle"]])

    stopped: list[int] = []

    def stop(hit: RayHit) -> float:
        stopped.append(hit.collider)
        return 0.0

    raycast(sc.space, (-2, 0), (12, 0), stop)
    assert len(stopped) == 1

    closest: list[RayHit] = []

    def ignore_box0(hit: RayHit) -> float:
        if hit.collider == ids["box0"]:
            return -1.0
        closest.append(hit)
        return hit.fraction

    raycast(sc.space, (-2, 0), (12, 0), ignore_box0)
    assert closest[-1].collider == ids["box3"]
    assert closest[-1].fraction == pytest.approx(0.32143, abs=1e-4)


def test_callback_clip_hides_farther_hits_and_unclip_reveals_them(
    reference_scene: tuple[Scene, dict[str, int]],
) -> None:
    sc, ids = reference_scene
    seen: list[int] = []

    def clip_then_continue(hit: RayHit) -> float:
        seen.append(hit.collider)
        return 0.2 if len(seen) == 1 else 1.0

    raycast(sc.space, (-2, 0), (12, 0), clip_then_continue)
    assert seen == [ids["box0"]]  # box3 (0.32) lies beyond the 0.2 clip


def test_modes_all_any_closest(reference_scene: tuple[Scene, dict[str, int]]) -> None:
    sc, ids = reference_scene
    every = raycast(sc.space, (-2, 0), (12, 0), mode="all")
    assert isinstance(every, list)
    assert [h.collider for h in every] == [ids["box0"], ids["box3"], ids["box6"], ids["circle"]]
    fractions = [h.fraction for h in every]
    assert fractions == sorted(fractions)
    assert every[3].body == ids["circle"]  # dynamic: names its body entity
    assert every[3].point == pytest.approx((8.5, 0.0))
    one = raycast(sc.space, (-2, 0), (12, 0), mode="any")
    assert isinstance(one, RayHit) and one.collider in {h.collider for h in every}
    assert raycast(sc.space, (-2, 2), (12, 2), mode="any") is None
    assert raycast(sc.space, (-2, 2), (12, 2), mode="all") == []


def test_ray_starting_inside_does_not_report_that_shape(
    reference_scene: tuple[Scene, dict[str, int]],
) -> None:
    sc, ids = reference_scene
    hits = raycast(sc.space, (0, 0), (12, 0), mode="all")
    assert isinstance(hits, list)
    assert ids["box0"] not in {h.collider for h in hits}
    assert hits[0].collider == ids["box3"]
    hits = raycast(sc.space, (9, 0), (12, 0), mode="all")
    assert hits == []  # inside the circle, nothing beyond
    # start inside the box's 0.01 m skin but outside its core: the core is hit
    hit = raycast(sc.space, (-0.505, 0), (0, 0))
    assert isinstance(hit, RayHit) and hit.collider == ids["box0"]
    assert hit.point == pytest.approx((-0.5, 0.0))
    assert raycast(sc.space, (-0.505, 0), (0, 0), mode="any") == hit


def test_sensors_reported_unless_filtered(reference_scene: tuple[Scene, dict[str, int]]) -> None:
    sc, ids = reference_scene
    hit = raycast(sc.space, (-2, 5), (2, 5))
    assert isinstance(hit, RayHit) and hit.collider == ids["sensor"]
    assert raycast(sc.space, (-2, 5), (2, 5), sensors=False) is None


def test_miss_makes_no_callback(reference_scene: tuple[Scene, dict[str, int]]) -> None:
    sc, _ = reference_scene
    calls: list[RayHit] = []

    def record(hit: RayHit) -> float:
        calls.append(hit)
        return 1.0

    raycast(sc.space, (-2, -3), (12, -3), record)
    assert calls == []


def test_filters_select_colliders() -> None:
    sc = Scene()
    ground = sc.add("box", (0, 0), flt=Filter(category_bits=0x2))
    ghost = sc.add("box", (3, 0), flt=Filter(category_bits=0x4, mask_bits=0x4))
    team = sc.add("box", (6, 0), flt=Filter(group_index=-7))
    sc.refresh()
    every = [ground, ghost, team]

    def hits(flt: object) -> list[int]:
        result = raycast(sc.space, (-2, 0), (12, 0), mode="all", filter=flt)  # type: ignore[arg-type]
        assert isinstance(result, list)
        return [h.collider for h in result]

    assert hits(None) == every
    assert hits(Filter()) == [ground, team]  # ghost only accepts category 4
    assert hits(Filter(mask_bits=0x2)) == [ground]
    assert hits(Filter(category_bits=0x4, mask_bits=0x4)) == [ghost]
    assert hits(Filter(group_index=-7)) == [ground]  # same negative group: never
    assert hits(lambda c: c != ground) == [ghost, team]
    assert [h.collider for h in query_aabb(sc.space, (-9, -9), (9, 9), filter=Filter())] == [
        ground,
        team,
    ]


def test_chain_reports_each_segment_crossed() -> None:
    sc = Scene()
    chain = sc.add("chain", (0, 0))
    sc.refresh()
    hits = raycast(sc.space, (0.5, 2), (0.5, -2), mode="all")
    assert isinstance(hits, list) and [h.collider for h in hits] == [chain]
    hits = raycast(sc.space, (-2, 0.5), (2, 0.5), mode="all")
    assert isinstance(hits, list) and [h.collider for h in hits] == [chain]
    assert hits[0].point == pytest.approx((1.0, 0.5))


# -------------------------------------------------------------- single-shape TestPoint/RayCast


@pytest.mark.parametrize("kind", ["box", "circle"])
def test_shape_raycast_rows(kind: str) -> None:
    sc = Scene()
    e = sc.add(kind, (0, 0))
    sc.refresh()
    hit = raycast(sc.space, (-2, 0), (2, 0))
    assert isinstance(hit, RayHit) and hit.collider == e
    assert hit.fraction == pytest.approx(0.375, abs=1e-12)
    assert hit.normal == pytest.approx((-1.0, 0.0))
    back = raycast(sc.space, (2, 0), (-2, 0))
    assert isinstance(back, RayHit) and back.normal == pytest.approx((1.0, 0.0))
    assert raycast(sc.space, (-2, 0), (-2 + 0.3 * 4, 0)) is None  # maxFraction 0.3 misses
    assert raycast(sc.space, (0.1, 0), (2, 0)) is None  # starting inside misses


def test_edge_raycast_two_sided() -> None:
    sc = Scene()
    e = sc.add("edge", (0, 0))
    sc.refresh()
    hit = raycast(sc.space, (-2, 0), (2, 0))
    assert isinstance(hit, RayHit) and hit.collider == e
    assert hit.fraction == pytest.approx(0.5) and hit.normal == pytest.approx((-1.0, 0.0))
    back = raycast(sc.space, (2, 0), (-2, 0))
    assert isinstance(back, RayHit) and back.normal == pytest.approx((1.0, 0.0))
    on = raycast(sc.space, (0, 0), (2, 0))
    assert isinstance(on, RayHit) and on.fraction == 0.0


def test_test_point_rows() -> None:
    sc = Scene()
    box = sc.add("box", (0, 0))
    circle = sc.add("circle", (3, 0))
    edge = sc.add("edge", (6, 0))
    sc.refresh()
    assert [h.collider for h in query_point(sc.space, (0.5, 0))] == [box]  # boundary inside
    assert query_point(sc.space, (0.5001, 0)) == []  # skin ignored
    assert query_point(sc.space, (0.505, 0)) == []
    assert [h.collider for h in query_point(sc.space, (3.5, 0))] == [circle]
    assert query_point(sc.space, (3.5001, 0)) == []
    assert query_point(sc.space, (6, 0)) == []  # an edge never contains a point
    assert edge not in {h.collider for h in query_point(sc.space, (6, 0.5))}


def test_test_point_rotated_and_moved_body() -> None:
    sc = Scene()
    box = sc.add("box", (2, 1), angle=math.pi / 4, dynamic=True)
    sc.refresh()
    corner = (2 + 0.5 * math.sqrt(2) - 1e-9, 1)
    assert [h.collider for h in query_point(sc.space, corner)] == [box]
    assert query_point(sc.space, (2 + 0.5 * math.sqrt(2) + 1e-6, 1)) == []
    assert query_point(sc.space, (2.5, 1.5)) == []  # the unrotated corner is outside
    hit = query_point(sc.space, (2, 1))[0]
    assert hit == QueryHit(box, box)


# ------------------------------------------------------------------------------ AABB


def test_query_aabb_reports_everything_including_sensors(
    reference_scene: tuple[Scene, dict[str, int]],
) -> None:
    sc, ids = reference_scene
    hits = query_aabb(sc.space, (-10, -10), (20, 20))
    assert [h.collider for h in hits] == sorted(ids.values())
    assert {h.collider: h.body for h in hits}[ids["circle"]] == ids["circle"]


@pytest.mark.parametrize("offset", [0.05, 0.12, 0.3])
def test_query_aabb_within_box2d_fat_margin(
    reference_scene: tuple[Scene, dict[str, int]], offset: float
) -> None:
    sc, ids = reference_scene
    lower, upper = (0.5 + offset, -0.2), (0.5 + offset + 0.4, 0.2)
    result = {h.collider for h in query_aabb(sc.space, lower, upper)}
    # box@0: AABB [-0.51, 0.51] with skin; Box2D's fat AABB adds 0.1 m
    exact = {ids["box0"]} if lower[0] <= 0.51 else set()
    loose = {ids["box0"]} if lower[0] <= 0.51 + 0.1 else set()
    assert exact <= result <= loose


def test_query_aabb_callback_stops_on_false(
    reference_scene: tuple[Scene, dict[str, int]],
) -> None:
    sc, _ = reference_scene
    calls: list[QueryHit] = []

    def stop(hit: QueryHit) -> bool:
        calls.append(hit)
        return False

    out = query_aabb(sc.space, (-10, -10), (20, 20), stop)
    assert len(calls) == 1 and out == calls
    calls.clear()
    query_aabb(sc.space, (-10, -10), (20, 20), lambda h: calls.append(h))  # None continues
    assert len(calls) == 5


def test_query_aabb_one_hit_per_collider() -> None:
    sc = Scene()
    chain = sc.add("chain", (0, 0))
    sc.refresh()
    assert query_aabb(sc.space, (-5, -5), (5, 5)) == [QueryHit(chain, None)]


# ------------------------------------------------------------------------------ shape overlap


def test_query_shape_overlap_and_contact_data(
    reference_scene: tuple[Scene, dict[str, int]],
) -> None:
    sc, ids = reference_scene
    hits = query_shape(sc.space, Circle(0.3), (0.7, 0.0))
    assert [h.collider for h in hits] == [ids["box0"]]
    h = hits[0]
    assert h.distance == pytest.approx(-(0.51 - 0.4), abs=1e-9)  # skin of the collider counts
    assert h.normal == (-1.0, 0.0)  # from the query shape towards the collider
    assert h.point == pytest.approx((0.51, 0.0))
    assert query_shape(sc.space, Circle(0.3), (0.82, 0.0)) == []
    big = query_shape(sc.space, Box(5, 0.5, center=(4.5, 0)), Transform(0.0, 0.0, 0.0))
    assert [x.collider for x in big] == [ids["box0"], ids["box3"], ids["box6"], ids["circle"]]


def test_query_shape_rotation_and_shape_kinds(
    reference_scene: tuple[Scene, dict[str, int]],
) -> None:
    sc, ids = reference_scene
    # a thin bar 1.8 m long: horizontal between box@0 and box@3 it touches nothing,
    # rotated 90 degrees it still touches nothing, moved onto box@3 it does
    bar = Box(0.9, 0.05)
    assert query_shape(sc.space, bar, (1.5, 0.0, 0.0)) == []
    assert query_shape(sc.space, bar, (1.5, 0.0, math.pi / 2)) == []
    assert [h.collider for h in query_shape(sc.space, bar, (3.0, 0.0, math.pi / 2))] == [
        ids["box3"]
    ]
    tri = Polygon([(0, 0), (1, 0), (0, 1)])
    assert [h.collider for h in query_shape(sc.space, tri, (5.2, -0.2, 0.0))] == [ids["box6"]]
    edge = Edge((-1, 0), (1, 0))
    assert [h.collider for h in query_shape(sc.space, edge, (9, 0.2, 0.0))] == [ids["circle"]]
    chain = Chain([(-1, 5), (0, 5), (0, 9)])
    assert [h.collider for h in query_shape(sc.space, chain, (0, 0, 0))] == [ids["sensor"]]
    assert query_shape(sc.space, chain, (0, 0, 0), sensors=False) == []


def test_query_shape_accepts_duck_typed_shapes(
    reference_scene: tuple[Scene, dict[str, int]],
) -> None:
    sc, ids = reference_scene

    @dataclass
    class MyCircle:
        radius: float
        center: tuple[float, float] = (0.0, 0.0)

    @dataclass
    class MyBox:
        half_width: float
        half_height: float
        center: tuple[float, float] = (0.0, 0.0)
        angle: float = 0.0

    @dataclass
    class MyPolygon:
        vertices: list[tuple[float, float]]

    assert [h.collider for h in query_shape(sc.space, MyCircle(0.3), (0.7, 0))] == [ids["box0"]]
    assert [h.collider for h in query_shape(sc.space, MyBox(0.2, 0.2), (3.6, 0, 0))] == [
        ids["box3"]
    ]
    square = MyPolygon([(-0.1, -0.1), (0.1, -0.1), (0.1, 0.1), (-0.1, 0.1)])
    assert [h.collider for h in query_shape(sc.space, square, (9, 0, 1))] == [ids["circle"]]
    with pytest.raises(ValidationError, match="convex"):
        query_shape(sc.space, MyPolygon([(0, 0), (2, 0), (1, 0.2), (2, 2), (0, 2)]), (0, 0))
    with pytest.raises(ValidationError, match="radius"):
        query_shape(sc.space, MyCircle(-1.0), (0, 0))


# ------------------------------------------------------------------------------ bad input


@pytest.mark.parametrize(
    ("call", "error", "match"),
    [
        (lambda s: raycast(s, (1, 1), (1, 1)), ValidationError, "same point"),
        (lambda s: raycast(s, (math.nan, 0), (1, 1)), ValidationError, "p1"),
        (lambda s: raycast(s, (0, 0), (1, math.inf)), ValidationError, "p2"),
        (lambda s: raycast(s, (0, 0), "ab"), ComponentTypeError, "p2"),
        (lambda s: raycast(s, (0, 0), (1, 0), mode="nearest"), ValidationError, "mode"),
        (lambda s: raycast(s, (0, 0), (1, 0), callback=3), ComponentTypeError, "callback"),  # type: ignore[arg-type]
        (lambda s: raycast(s, (0, 0), (1, 0), filter=0x2), ComponentTypeError, "filter"),  # type: ignore[arg-type]
        (lambda s: raycast(object(), (0, 0), (1, 0)), ComponentTypeError, "pymunk.Space"),  # type: ignore[arg-type]
        (lambda s: query_aabb(s, (1, 0), (0, 1)), ValidationError, "lower"),
        (lambda s: query_aabb(s, (0, 0), (1, math.nan)), ValidationError, "upper"),
        (lambda s: query_point(s, (None, 0)), ComponentTypeError, "p"),
        (lambda s: query_shape(s, Circle(1), (0, 0, math.nan)), ValidationError, "angle"),
        (lambda s: query_shape(s, Circle(1), "here"), ComponentTypeError, "transform"),
        (lambda s: query_shape(s, 3.0, (0, 0)), ComponentTypeError, "shape"),
    ],
)
def test_bad_input_is_refused(
    reference_scene: tuple[Scene, dict[str, int]], call: object, error: type, match: str
) -> None:
    sc, _ = reference_scene
    with pytest.raises(error, match=match):
        call(sc.space)  # type: ignore[operator]


@pytest.mark.parametrize(
    ("value", "error"), [(None, ComponentTypeError), (math.nan, ValidationError)]
)
def test_bad_callback_return_is_refused(
    reference_scene: tuple[Scene, dict[str, int]], value: object, error: type
) -> None:
    sc, _ = reference_scene
    with pytest.raises(error, match="callback"):
        raycast(sc.space, (-2, 0), (12, 0), lambda h: value)  # type: ignore[arg-type,return-value]


def test_ray_cast_matches_pymunk_on_skinless_twins() -> None:
    """Independent check: kge's exact hits on skinned shapes equal pymunk's hits on
    the same shapes without skin (for rays that start outside everything)."""
    rng = random.Random(7)
    skinned, bare = pymunk.Space(), pymunk.Space()
    for entity in range(1, 61):
        x, y, a = rng.uniform(0, 30), rng.uniform(0, 30), rng.uniform(0, math.pi)
        kind = rng.choice(["box", "circle", "edge", "poly"])
        for space, skin in ((skinned, SKIN), (bare, 0.0)):
            body = pymunk.Body(body_type=pymunk.Body.STATIC)
            body.position, body.angle = (x, y), a
            if kind == "box":
                shape: pymunk.Shape = pymunk.Poly.create_box(body, (1.0, 0.4), skin)
            elif kind == "circle":
                shape = pymunk.Circle(body, 0.6, (0.2, 0.0))
            elif kind == "edge":
                shape = pymunk.Segment(body, (-1, 0), (1, 0.5), skin)
            else:
                shape = pymunk.Poly(body, [(0, 0), (1, 0), (1.2, 0.8), (0.1, 1)], radius=skin)
            _tag(space, shape, entity, None, Filter(), False)
            space.add(body, shape)
    checked = 0
    for _ in range(300):
        p1 = (rng.uniform(-5, 35), rng.uniform(-5, 35))
        p2 = (rng.uniform(-5, 35), rng.uniform(-5, 35))
        if query_point(skinned, p1) or bare.point_query(p1, 0.02, pymunk.ShapeFilter()):
            continue  # starts inside (or on an edge): Box2D rules differ from pymunk's there
        ours = raycast(skinned, p1, p2, mode="all")
        theirs = sorted(
            bare.segment_query(p1, p2, 0.0, pymunk.ShapeFilter()), key=lambda i: i.alpha
        )
        assert isinstance(ours, list)
        assert [h.fraction for h in ours] == pytest.approx([i.alpha for i in theirs], abs=1e-9)
        table = ShapeTable.of(bare)
        assert {h.collider for h in ours} == {table.collider_of(i.shape) for i in theirs}
        closest = raycast(skinned, p1, p2)
        assert closest == (ours[0] if ours else None)
        checked += bool(ours)
    assert checked > 50
