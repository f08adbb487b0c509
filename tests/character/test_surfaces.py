"""Floors, slopes, walls, corners, gaps and stairs: where a character stops and slides.

Distances are measured independently with kge.collision (Box2D's GJK); "no jitter" is
the variance of the pose over a second of standing, which must be nil.
"""

from __future__ import annotations

import math
import statistics

import pytest

from kge import Box, Capsule, CharacterBody, CharacterMode, Circle, Collider, Edge, Transform
from kge.character.contacts import SKIN
from tests.character.conftest import gap_to, ground

SHAPES = {
    "capsule": Capsule(0.3, 0.9),
    "box": Box(0.4, 0.9),
    "circle": Circle(0.45),
}


def _standing(world, shape, x=0.0, y=3.0, **settings):
    return world.spawn(Transform(x, y), CharacterBody(shape, **settings))


def _variance(samples):
    xs, ys = zip(*samples, strict=True)
    return statistics.pvariance(xs) + statistics.pvariance(ys)


@pytest.mark.parametrize("name", SHAPES)
def test_lands_and_stands_at_the_skin_without_jitter(app_of, name) -> None:
    def scene(world):
        ground(world)
        _standing(world, SHAPES[name])

    app = app_of(scene)
    app.step(120)
    world = app.world
    body, t = world.get(2, CharacterBody), world.get(2, Transform)
    assert body.on_floor and body.floor_normal == pytest.approx((0.0, 1.0))
    assert body.floor_collider == 1
    gap = gap_to(world, 2, 1)
    assert SKIN - 1e-9 <= gap <= SKIN + 1e-3
    poses = []
    for _ in range(60):
        app.step()
        poses.append((t.x, t.y))
    assert _variance(poses) == 0.0
    assert body.velocity == (0.0, 0.0)


@pytest.mark.parametrize("degrees", [0, 10, 20, 30, 40, 45, 50, 60])
def test_slopes_from_0_to_60_degrees(app_of, degrees) -> None:
    """Within max_floor_angle (45): stands still, walks up and down staying on the floor.
    Steeper: a wall, slid down, not walked up."""
    angle = math.radians(degrees)

    def scene(world):
        ground(world, angle=angle, half_width=60.0)
        _standing(world, SHAPES["capsule"], y=1.5)

    app = app_of(scene)
    world = app.world
    body, t = world.get(2, CharacterBody), world.get(2, Transform)
    app.step(60)
    walkable = degrees <= 45
    n = (-math.sin(angle), math.cos(angle))
    if walkable:
        assert body.on_floor and body.floor_normal == pytest.approx(n, abs=1e-9)
        poses = []
        for _ in range(60):
            app.step()
            poses.append((t.x, t.y))
        assert _variance(poses) == 0.0, "it slides or jitters standing on the slope"
        x0 = t.x
        for _ in range(30):  # uphill (the slope rises to the right)
            body.velocity = (3.0, body.velocity[1])
            app.step()
            assert body.on_floor
        assert t.x - x0 == pytest.approx(1.5 * math.cos(angle) ** 2, rel=0.02)
        for _ in range(60):  # and down again, never leaving the slope
            body.velocity = (-3.0, body.velocity[1])
            app.step()
            assert body.on_floor
            assert gap_to(world, 2, 1) < SKIN + 1e-3
    else:
        assert not body.on_floor and body.on_wall
        y0 = t.y
        app.step(10)
        assert t.y < y0 - 0.05, "it should slide down a slope steeper than max_floor_angle"
        for _ in range(30):
            before = t.y
            body.velocity = (3.0, body.velocity[1])
            app.step()
            assert t.y <= before + 1e-12, "it walked up a slope steeper than max_floor_angle"
            assert gap_to(world, 2, 1) >= SKIN - 1e-9


@pytest.mark.parametrize("name", SHAPES)
@pytest.mark.parametrize("speed", [1.0, 3.0, 6.0, 12.0, 30.0, 60.0, 100.0])
def test_walls_hold_at_any_speed(app_of, name, speed) -> None:
    def scene(world):
        ground(world)
        world.spawn(Transform(4.0, 2.0), Collider(Box(0.5, 2.0)))
        _standing(world, SHAPES[name], y=1.0)

    app = app_of(scene)
    world = app.world
    body = world.get(3, CharacterBody)
    app.step(30)
    closest = math.inf
    for _ in range(int(60 * 6.0 / speed) + 20):
        body.velocity = (speed, body.velocity[1])
        app.step()
        closest = min(closest, gap_to(world, 3, 2))
    assert body.on_wall and body.wall_normal == pytest.approx((-1.0, 0.0))
    assert body.velocity[0] == 0.0 and body.on_floor
    assert SKIN - 1e-9 <= closest <= SKIN + 1e-3


@pytest.mark.parametrize("name", SHAPES)
def test_never_tunnels_through_a_thin_edge_at_100_m_s(app_of, name) -> None:
    """A room of four zero-thickness edges; the character flies about it at 100 m/s."""
    corners = [(-4.0, -4.0), (4.0, -4.0), (4.0, 4.0), (-4.0, 4.0)]

    def scene(world):
        for k in range(4):
            world.spawn(Transform(), Collider(Edge(corners[k], corners[(k + 1) % 4])))
        _standing(world, SHAPES[name], y=0.0, mode="top_down")

    app = app_of(scene)
    world = app.world
    body, t = world.get(5, CharacterBody), world.get(5, Transform)
    hits = 0
    for step in range(180):
        angle = 0.37 * step
        body.velocity = (100.0 * math.cos(angle), 100.0 * math.sin(angle))
        app.step()
        assert -4.0 < t.x < 4.0 and -4.0 < t.y < 4.0
        gaps = [gap_to(world, 5, wall) for wall in range(1, 5)]
        assert min(gaps) >= SKIN - 1e-9
        hits += min(gaps) < SKIN + 1e-3
    assert hits > 60  # it really was stopped by the walls, many times


def test_falls_at_100_m_s_onto_a_thin_floor(app_of) -> None:
    def scene(world):
        world.spawn(Transform(0.0, 0.0), Collider(Edge((-5.0, 0.0), (5.0, 0.0))))
        world.spawn(Transform(0.0, 60.0), CharacterBody(Capsule(0.3, 0.9), velocity=(0.0, -100.0)))

    app = app_of(scene)
    body = app.world.get(2, CharacterBody)
    app.step(40)
    assert body.on_floor and body.landed is False
    assert gap_to(app.world, 2, 1) == pytest.approx(SKIN, abs=1e-3)


def test_an_inside_corner_holds_floor_and_wall_without_jitter(app_of) -> None:
    def scene(world):
        ground(world)
        world.spawn(Transform(2.0, 2.0), Collider(Box(0.5, 2.0)))
        _standing(world, SHAPES["capsule"], x=1.0, y=1.0)

    app = app_of(scene)
    world = app.world
    body, t = world.get(3, CharacterBody), world.get(3, Transform)
    poses = []
    for k in range(120):
        body.velocity = (4.0, body.velocity[1])
        app.step()
        if k >= 60:
            poses.append((t.x, t.y))
    assert body.on_floor and body.on_wall
    assert _variance(poses) == 0.0


def test_a_v_of_steep_slopes_holds_it_at_the_bottom(app_of) -> None:
    """Slopes steeper than max_floor_angle are walls: it slides down both to the bottom
    of the V and rests there, held by the two, with no jitter."""

    def scene(world):
        for sign in (-1.0, 1.0):
            world.spawn(Transform(sign * 2.0, 3.0, sign * math.radians(60)),
                        Collider(Box(4.0, 0.1)))
        _standing(world, SHAPES["circle"], x=0.7, y=5.0)

    app = app_of(scene)
    world = app.world
    body, t = world.get(3, CharacterBody), world.get(3, Transform)
    app.step(120)
    poses = []
    for _ in range(60):
        app.step()
        poses.append((t.x, t.y))
    assert abs(t.x) < 1e-6 and _variance(poses) < 1e-20
    assert not body.on_floor and body.on_wall
    assert min(gap_to(world, 3, 1), gap_to(world, 3, 2)) >= SKIN - 1e-9


@pytest.mark.parametrize("width", [0.5, 0.95])
def test_a_shaft_narrower_than_the_character_holds_it(app_of, width) -> None:
    """Two blocks with a gap between them: a gap narrower than the 0.9 m capsule holds
    it up; a wider one lets it fall through."""

    def scene(world):
        for sign in (-1.0, 1.0):
            world.spawn(Transform(sign * (width / 2 + 2.0), 0.0), Collider(Box(2.0, 0.5)))
        _standing(world, Capsule(0.45, 0.9), y=2.0)

    app = app_of(scene)
    t = app.world.get(3, Transform)
    app.step(90)
    fits = width > 0.9 + 2 * (0.01 + SKIN)
    if fits:
        assert t.y < -1.0
    else:
        assert t.y > 0.5 + 0.45 and app.world.get(3, CharacterBody).on_floor


@pytest.mark.parametrize("height", [1.5, 2.1])
def test_a_tunnel_lower_than_the_character_blocks_it(app_of, height) -> None:
    def scene(world):
        ground(world)
        world.spawn(Transform(4.0, height + 0.5), Collider(Box(2.0, 0.5)))  # the roof
        _standing(world, Capsule(0.3, 0.9), y=1.0)

    app = app_of(scene)
    body, t = app.world.get(3, CharacterBody), app.world.get(3, Transform)
    for _ in range(180):
        body.velocity = (3.0, body.velocity[1])
        app.step()
    if height < 1.8:
        assert t.x < 2.0 - 0.3 and body.on_wall
    else:
        assert t.x > 6.0


def test_a_ceiling_stops_a_jump(app_of) -> None:
    def scene(world):
        ground(world)
        world.spawn(Transform(0.0, 3.0), Collider(Box(3.0, 0.2)))
        _standing(world, SHAPES["capsule"], y=1.0, jump_speed=9.0)

    app = app_of(scene)
    world = app.world
    body = world.get(3, CharacterBody)
    app.step(30)
    body.jump = True
    bonked = False
    for _ in range(30):
        app.step()
        bonked |= body.on_ceiling
        assert gap_to(world, 3, 2) >= SKIN - 1e-9
    assert (bonked and body.ceiling_normal == (0.0, 0.0)) or bonked


@pytest.mark.parametrize("name", ["capsule", "box"])
def test_stairs_up_and_down_with_a_step_height(app_of, name) -> None:
    rise = 0.2

    def scene(world):
        ground(world, half_width=40.0)
        for k in range(6):  # six steps of 0.2 m, 0.5 m deep
            world.spawn(Transform(12.0 + 0.5 * k, rise * (k + 1) - 10.0), Collider(Box(10.25, 10.0)))
        _standing(world, SHAPES[name], y=1.0, step_height=0.3, snap_length=0.3)

    app = app_of(scene)
    world = app.world
    body, t = world.get(8, CharacterBody), world.get(8, Transform)
    app.step(30)
    bottom = t.y
    for _ in range(120):
        body.velocity = (3.0, body.velocity[1])
        app.step()
    # up six steps at most a little slower than along the flat (6 m in 2 s)
    assert t.x > 5.0 and t.y == pytest.approx(bottom + 6 * rise, abs=1e-6) and body.on_floor
    for _ in range(120):
        body.velocity = (-3.0, body.velocity[1])
        app.step()
        assert body.on_floor, "it left the stairs going down"
    assert t.y == pytest.approx(bottom, abs=1e-6)


def test_without_a_step_height_a_box_stops_at_the_first_step(app_of) -> None:
    def scene(world):
        ground(world)
        world.spawn(Transform(3.0, 0.1), Collider(Box(1.0, 0.1)))
        _standing(world, SHAPES["box"], y=1.0)

    app = app_of(scene)
    body, t = app.world.get(3, CharacterBody), app.world.get(3, Transform)
    for _ in range(90):
        body.velocity = (3.0, body.velocity[1])
        app.step()
    assert t.x < 2.0 - 0.4 and body.on_wall


def test_snaps_down_a_small_ledge_and_falls_off_a_tall_one(app_of) -> None:
    def scene(world):
        world.spawn(Transform(-3.0, -0.5), Collider(Box(3.0, 0.5)))  # top at 0, up to x = 0
        world.spawn(Transform(1.5, -0.65), Collider(Box(1.5, 0.5)))  # top at -0.15, to x = 3
        world.spawn(Transform(10.0, -5.5), Collider(Box(5.0, 0.5)))  # far below
        _standing(world, SHAPES["box"], x=-2.0, y=1.0, snap_length=0.2)

    app = app_of(scene)
    body, t = app.world.get(4, CharacterBody), app.world.get(4, Transform)
    app.step(20)
    while t.x < 3.0 + 0.4:
        body.velocity = (3.0, body.velocity[1])
        app.step()
        assert body.on_floor, f"it left the floor at x = {t.x}"
    for _ in range(40):
        body.velocity = (3.0, body.velocity[1])
        app.step()
    assert not body.on_floor and t.y < -0.5


def test_top_down_mode_slides_along_walls_without_gravity(app_of) -> None:
    def scene(world):
        world.spawn(Transform(0.0, 2.0), Collider(Box(5.0, 0.5)))
        world.spawn(Transform(0.0, 0.0), CharacterBody(Circle(0.4), mode=CharacterMode.TOP_DOWN))

    app = app_of(scene)
    body, t = app.world.get(2, CharacterBody), app.world.get(2, Transform)
    app.step(30)
    assert (t.x, t.y) == (0.0, 0.0) and not body.on_floor
    for _ in range(60):
        body.velocity = (2.0, 2.0)
        app.step()
    assert t.y == pytest.approx(1.5 - 0.4 - 0.01 - SKIN, abs=1e-3)
    assert t.x == pytest.approx(2.0, abs=1e-6)
    assert body.on_wall and body.wall_normal == pytest.approx((0.0, -1.0))
    assert not body.on_floor and not body.on_ceiling


@pytest.mark.parametrize("snap", [0.0, 0.2])
def test_walking_into_a_steep_face_from_the_flat_never_climbs_it(app_of, snap) -> None:
    def scene(world):
        ground(world)
        world.spawn(Transform(4.0, 0.0, math.radians(60)), Collider(Box(3.0, 0.1)))
        _standing(world, SHAPES["capsule"], y=1.0, snap_length=snap)

    app = app_of(scene)
    body, t = app.world.get(3, CharacterBody), app.world.get(3, Transform)
    app.step(20)
    rest = t.y
    for _ in range(120):
        body.velocity = (3.0, body.velocity[1])
        app.step()
        assert t.y < rest + 1e-6, "it walked up a face steeper than max_floor_angle"
    assert body.on_wall and body.on_floor
