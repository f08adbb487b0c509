"""Shape drawables and text: colours, outlines, world vs screen space."""

from __future__ import annotations

import math

import numpy as np
import pytest

from kge import Transform
from kge.components.camera import Camera
from kge.components.color import RGB, RGBA
from kge.components.drawables import Circle, Line, Polygon, Rect, Triangle
from kge.components.text import Text
from kge.errors import ValidationError
from kge.render.geometry import stroke, triangles_area, triangulate

from .conftest import BG, SIZE, bbox, mask, pixels

RED, GREEN, BLUE, YELLOW, WHITE = (
    (255, 0, 0),
    (0, 255, 0),
    (0, 0, 255),
    (255, 255, 0),
    (255, 255, 255),
)


def opaque(rgb: RGB) -> RGBA:
    """``rgb`` as the drawables' RGBA (an RGB colour means alpha 255)."""
    return (*rgb, 255)


def test_filled_shapes_in_world_units(make_app):
    def scene(world):
        world.insert_resource(Camera(pixels_per_meter=20))
        world.spawn(Transform(-2.5, 1.5), Rect(2.0, 1.0, color=opaque(RED)))
        world.spawn(Transform(2.5, 1.5), Circle(1.0, color=opaque(GREEN)))
        world.spawn(Transform(-2.5, -2.0), Triangle((-1, -1), (1, -1), (0, 1), color=opaque(BLUE)))
        world.spawn(
            Transform(2.5, -2.0),
            Polygon(((0, 0), (2, 0), (2, 2), (1, 1), (0, 2)), color=opaque(YELLOW), offset=(-1, -1)),
        )

    px = pixels(make_app(scene))
    cx, cy = SIZE[0] / 2, SIZE[1] / 2
    x0, x1, y0, y1 = bbox(mask(px, RED))
    assert (x1 - x0 + 1, y1 - y0 + 1) == (40, 20)
    assert abs((x0 + x1 + 1) / 2 - (cx - 50)) <= 1
    g = mask(px, GREEN)
    area = g.sum() / 20**2
    assert math.isclose(area, math.pi, rel_tol=0.05)
    assert mask(px, BLUE).any()
    ym = mask(px, YELLOW)
    # the concave notch of the polygon stays empty
    assert not ym[int(cy - 40 + 10), int(cx + 50)] and ym[int(cy - 40 - 10), int(cx + 50)]


def test_outline_leaves_the_inside_empty_and_line_has_thickness(make_app):
    def scene(world):
        world.insert_resource(Camera(pixels_per_meter=20))
        world.spawn(Transform(-2, 0), Rect(3.0, 3.0, color=opaque(RED), filled=False, thickness=0.2))
        world.spawn(Transform(2, 0, math.pi / 2), Line((-1, 0), (1, 0), color=opaque(GREEN), thickness=0.5))

    px = pixels(make_app(scene))
    cx, cy = SIZE[0] // 2, SIZE[1] // 2
    r = mask(px, RED)
    assert not r[cy, cx - 40] and r[cy, cx - 40 - 30 + 1]
    x0, x1, y0, y1 = bbox(mask(px, GREEN))
    assert (x1 - x0 + 1, y1 - y0 + 1) == (10, 40)  # rotated 90 deg: vertical, 0.5 m wide


def test_shape_changes_apply_and_hidden_shapes_vanish(make_app):
    def scene(world):
        world.spawn(Transform(), Rect(1.0, 1.0, color=opaque(RED)))

    app = make_app(scene)
    ((_, (rect,)),) = app.world.query(Rect)
    rect.color = (0, 0, 255, 255)
    px = pixels(app)
    assert mask(px, BLUE).any() and not mask(px, RED).any()
    rect.visible = False
    assert not mask(pixels(app), BLUE).any()


def test_world_text_renders_inside_its_box(make_app):
    def scene(world):
        world.insert_resource(Camera(pixels_per_meter=20))
        world.spawn(Transform(0.0, 1.0), Text("KGE", size=24, color=opaque(WHITE)))

    px = pixels(make_app(scene))
    lit = ~mask(px, BG, tol=30)
    x0, x1, y0, y1 = bbox(lit)
    cx, cy = SIZE[0] / 2, SIZE[1] / 2 + 20
    assert x0 < cx < x1 and y0 < cy < y1  # centred on the entity
    assert x1 - x0 < 100 and y1 - y0 < 40
    assert lit[y0 : y1 + 1, x0 : x1 + 1].mean() > 0.1  # glyphs, not a stray pixel


def test_screen_text_ignores_the_camera_and_updates(make_app):
    def scene(world):
        world.insert_resource(Camera(center=(50.0, 50.0), zoom=3))
        world.spawn(Text("0", size=16, screen_space=True, offset=(10, 10), anchor=(0, 0)))

    app = make_app(scene)
    x0, _, y0, _ = bbox(~mask(pixels(app), BG, tol=30))
    assert 10 <= x0 <= 14 and 10 <= y0 <= 16
    ((e, (t,)),) = app.world.query(Text)
    from kge.systems.render import RenderSystem

    label = app.world.get_system(RenderSystem).view.labels.labels[e]
    t.text = "12345"
    _, x1_long, _, _ = bbox(~mask(pixels(app), BG, tol=30))
    assert x1_long - x0 > 30
    assert (
        app.world.get_system(RenderSystem).view.labels.labels[e] is label
    )  # text swapped in place


def test_triangulation_covers_concave_polygons_exactly():
    l_shape = [(0, 0), (3, 0), (3, 1), (1, 1), (1, 3), (0, 3)]
    assert math.isclose(triangles_area(triangulate(l_shape)), 5.0)
    assert math.isclose(triangles_area(triangulate(l_shape[::-1])), 5.0)  # clockwise input
    square = stroke([(0, 0), (1, 0), (1, 1), (0, 1)], 0.1, closed=True)
    assert square.shape == (24, 2)


def test_drawables_refuse_bad_values():
    with pytest.raises(ValidationError, match="no area"):
        Polygon(((0, 0), (1, 1), (2, 2)))
    with pytest.raises(ValidationError, match="Rect.color"):
        Rect(1, 1, color=(0, 0, 256, 255))
    r = Rect(1, 1)
    with pytest.raises(ValidationError, match="Rect.width"):
        r.width = np.nan
