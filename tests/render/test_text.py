"""Text drawn headless at 8 bits: measured boxes against the ink, effects, fonts, zoom."""

from __future__ import annotations

import numpy as np
import pytest

from kge import Transform
from kge.components.camera import Camera
from kge.components.text import Text, TextAlign, TextStyle
from kge.errors import ValidationError
from kge.render.images import PixelImage, solid
from kge.render.text import (
    BitmapFont,
    FontWarning,
    add_font_file,
    measure,
    register_bitmap_font,
    register_icon,
)

from .conftest import BG, bbox, mask, pixels
from .fontgen import make_font

WHITE = (255, 255, 255, 255)


def ink(px: np.ndarray, tol: int = 40) -> np.ndarray:
    return ~mask(px, BG, tol=tol)


def hud(text: str, **kw) -> Text:
    kw.setdefault("offset", (20, 20))
    kw.setdefault("anchor", (0, 0))
    return Text(text, screen_space=True, **kw)


def draw(make_app, *texts: Text, **app_kw) -> np.ndarray:
    def scene(world):
        for t in texts:
            world.spawn(t)

    return pixels(make_app(scene, **app_kw))


def test_a_newline_draws_nothing_and_starts_a_line(make_app):
    assert not ink(draw(make_app, hud("\n\n", size=20))).any()
    one = bbox(ink(draw(make_app, hud("A", size=20))))
    two = bbox(ink(draw(make_app, hud("A\nA", size=20))))
    assert two[3] - two[2] > 1.8 * (one[3] - one[2])  # twice as tall: two lines
    assert two[1] - two[0] == one[1] - one[0]  # and no box glyph beside the A


def test_measured_line_boxes_hold_the_drawn_ink(make_app):
    style = TextStyle(size=14, width=120.0, line_spacing=1.3)
    text = "Measured boxes match what is drawn on screen"
    box = measure(text, style)
    assert len(box.lines) >= 3
    px = draw(make_app, hud(text, size=14, width=120.0, line_spacing=1.3), size=(200, 160))
    lit = ink(px)
    x0, x1, y0, y1 = bbox(lit)
    assert x0 >= 20 - 1 and x1 <= 20 + box.width + 1
    assert y0 >= 20 - 1 and y1 <= 20 + box.height + 1
    for line in box.lines:  # each line's ink sits in its box and spans its width
        rows = lit[int(20 + line.y) + 1 : int(20 + line.y + line.height) - 1]
        cols = np.nonzero(rows.any(axis=0))[0]
        assert len(cols), f"no ink in line {line.text!r}"
        # the box is the pen's advance; ink starts and ends a side bearing inside it
        assert abs((cols.max() + 1 - cols.min()) - line.width) <= 4, line.text
    widest = max(line.width for line in box.lines)
    assert abs((x1 + 1 - x0) - widest) <= 4


def test_right_alignment_lines_up_the_right_edges(make_app):
    px = draw(make_app, hud("wide line here\nshort\nmid one", size=14, width=150.0,
                            align=TextAlign.RIGHT), size=(200, 160))  # fmt: skip
    lit = ink(px)
    box = measure("wide line here\nshort\nmid one", size=14, width=150.0, align=TextAlign.RIGHT)
    rights = []
    for line in box.lines:
        rows = lit[int(20 + line.y) + 2 : int(20 + line.y + line.height) - 2]
        rights.append(np.nonzero(rows.any(axis=0))[0].max())
    assert max(rights) - min(rights) <= 2
    assert abs(max(rights) - (20 + 150)) <= 3


def test_outline_and_shadow_surround_and_follow_the_glyphs(make_app):
    red, blue = (255, 0, 0, 255), (0, 0, 255, 255)
    plain = mask(draw(make_app, hud("H", size=40, color=WHITE)), WHITE[:3], 30)
    px = draw(make_app, hud("H", size=40, color=WHITE, outline=3, outline_color=red,
                            shadow=(6, -6), shadow_color=blue))  # fmt: skip
    white, reds, blues = mask(px, WHITE[:3], 30), mask(px, red[:3], 60), mask(px, blue[:3], 60)
    assert white.sum() > 0.8 * plain.sum()
    assert reds.sum() > 0.5 * plain.sum()  # a ring around the H
    wx0, wx1, wy0, wy1 = bbox(white)
    rx0, rx1, ry0, ry1 = bbox(reds)
    assert rx0 <= wx0 - 2 and rx1 >= wx1 + 2 and ry0 <= wy0 - 2 and ry1 >= wy1 + 2
    _, bx1, by0, _ = bbox(blues)  # the shadow: down and to the right
    assert bx1 > rx1 + 3 and by0 < ry0 - 3


def _edge_share(px: np.ndarray) -> float:
    """Share of the text's pixels that are neither background nor full white (blur)."""
    lum = px[..., :3].astype(int).mean(axis=-1)
    mid = (lum > 60) & (lum < 190)
    return float(mid.sum()) / max(int((lum >= 60).sum()), 1)


def test_zoomed_world_text_is_rasterised_at_its_screen_size(make_app):
    def scene(world):
        world.insert_resource(Camera(pixels_per_meter=20, zoom=5.0))
        world.spawn(Transform(0, 0), Text("Zoom", size=9, color=WHITE))

    app = make_app(scene, size=(240, 160))
    px = pixels(app)
    crisp = _edge_share(px)
    hud_px = draw(make_app, hud("Zoom", size=45, color=WHITE), size=(240, 160))
    assert crisp < 1.5 * _edge_share(hud_px) + 0.05  # as sharp as text drawn at that size
    from kge.systems.render import RenderSystem

    store = app.world.get_system(RenderSystem).view.labels
    (label,) = store.labels.values()
    assert label.scale == pytest.approx(5.0)
    app.world.resource(Camera).zoom = 1.0
    pixels(app)
    assert label.scale == pytest.approx(1.0, rel=0.3)  # zooming moves it in big steps...
    pixels(app)
    assert label.scale == pytest.approx(1.0)  # ...and once it rests, to the exact size


def test_weight_and_italic_pick_other_faces(make_app):
    normal = ink(draw(make_app, hud("llll", size=30, font="DejaVu Sans")))
    bold = ink(draw(make_app, hud("llll", size=30, font="DejaVu Sans", weight="bold")))
    light = ink(draw(make_app, hud("llll", size=30, font="DejaVu Sans", weight=200)))
    assert bold.sum() > 1.3 * normal.sum() > 1.3 * light.sum()
    italic = ink(draw(make_app, hud("l", size=40, font="DejaVu Sans", italic=True)))
    _, _, y0, y1 = bbox(italic)
    top = np.nonzero(italic[y1 - 2])[0].mean()
    bottom = np.nonzero(italic[y0 + 2])[0].mean()
    assert top - bottom > 3  # the stroke leans right going up
    upright = ink(draw(make_app, hud("l", size=40, font="DejaVu Sans")))
    _, _, u0, u1 = bbox(upright)
    assert abs(np.nonzero(upright[u1 - 2])[0].mean() - np.nonzero(upright[u0 + 2])[0].mean()) < 1


def _fill(lit: np.ndarray) -> float:
    x0, x1, y0, y1 = bbox(lit)
    return float(lit[y0 : y1 + 1, x0 : x1 + 1].mean())


def test_a_light_italic_font_file_is_used_for_its_family(make_app):
    add_font_file(make_font("Kge Probe LI", "Light Italic", 300, True))
    block = ink(draw(make_app, hud("A", size=40, font="Kge Probe LI")))
    assert _fill(block) > 0.9  # the file's A is a solid block
    assert _fill(ink(draw(make_app, hud("A", size=40, font="DejaVu Sans")))) < 0.6
    from kge.render.text import book

    face = book().primary("Kge Probe LI", 400, False)
    assert getattr(face, "name", "").lower() == "kge probe li"


def test_several_faces_of_a_family_each_answer_their_style(make_app):
    add_font_file(make_font("Kge Probe Fam", "Regular", 400, False, {"A": [(50, 0, 650, 700)]}))
    add_font_file(make_font("Kge Probe Fam", "Bold", 700, False, {"A": [(50, 0, 650, 350)]}))
    regular = bbox(ink(draw(make_app, hud("A", size=40, font="Kge Probe Fam"))))
    bold = bbox(ink(draw(make_app, hud("A", size=40, font="Kge Probe Fam", bold=True))))
    assert bold[3] - bold[2] < 0.6 * (regular[3] - regular[2])  # the Bold file's half block


def test_characters_a_font_lacks_come_from_a_fallback_face(make_app):
    add_font_file(make_font("Kge Probe Few", glyphs={"A": [(50, 0, 650, 700)]}))
    fallback = draw(make_app, hud("É", size=30, font="Kge Probe Few"))
    dejavu = draw(make_app, hud("É", size=30, font="DejaVu Sans"))
    assert ink(fallback).sum() > 50
    assert np.array_equal(fallback, dejavu)  # the same glyph, not the font's missing box


def test_a_missing_family_warns_naming_it_at_the_call(make_app):
    def scene(world):
        world.spawn(Transform(), Text("hello", font="Kge Nowhere Sans"))

    with pytest.warns(FontWarning, match="Kge Nowhere Sans"):
        app = make_app(scene)
    assert ink(pixels(app)).any()  # drawn anyway, in the default family


def test_a_missing_font_file_is_refused_at_the_call(make_app):
    def scene(world):
        world.spawn(Transform(), Text("hello", font="fonts/not-there.ttf"))

    with pytest.raises(Exception, match="not-there.ttf"):
        make_app(scene)


def test_bad_markup_is_refused_at_spawn_and_at_write(make_app):
    def scene(world):
        world.spawn(Transform(), Text("[b]fine[/b]", markup=True))

    app = make_app(scene)
    ((e, (t,)),) = app.world.query(Text)
    with pytest.raises(ValidationError, match=f"entity {e}, Text.text: markup"):
        t.text = "[b]unclosed"
    assert t.text == "[b]fine[/b]"


def test_bitmap_fonts_draw_their_cells_pixel_for_pixel(make_app):
    sheet = np.zeros((4, 8, 4), np.uint8)
    sheet[:, :4] = (255, 0, 0, 255)
    sheet[:, 4:] = (0, 255, 0, 255)
    img = PixelImage(8, 4, sheet[::-1].tobytes())
    font = BitmapFont(img, "XO", cell=(4, 4), spacing=0, line_height=4)
    register_bitmap_font("kge-probe-pixels", font)
    px = draw(make_app, hud("XO", size=12, font="kge-probe-pixels"))  # 16 px: 4 x the cells
    red, green = mask(px, (255, 0, 0), 10), mask(px, (0, 255, 0), 10)
    assert bbox(red) == (20, 35, 20, 35) and bbox(green) == (36, 51, 20, 35)


def test_inline_icons_sit_in_the_line(make_app):
    register_icon("kge-probe-coin", solid(8, 8, (255, 200, 0)))
    text = "Gold [img=16x16]kge-probe-coin[/img] 3"
    px = draw(make_app, hud(text, size=16, markup=True))
    coin = mask(px, (255, 200, 0), 20)
    x0, x1, y0, y1 = bbox(coin)
    assert (x1 - x0 + 1, y1 - y0 + 1) == (16, 16)
    box = measure(text, size=16, markup=True)
    (icon,) = [g for g in box.glyphs if g.icon is not None]
    assert abs((x0 - 20) - icon.x) <= 1 and abs((y0 - 20) - icon.bottom) <= 1
    assert box.lines[0].width > icon.x + 16 > measure("Gold", size=16).lines[0].width + 16


def test_text_changes_bake_only_that_label(make_app):
    def scene(world):
        world.spawn(Transform(), Text("static"))
        world.spawn(hud("0", size=14))

    app = make_app(scene)
    pixels(app)
    from kge.systems.render import RenderSystem

    store = app.world.get_system(RenderSystem).view.labels
    before = store.baked
    pixels(app)
    assert store.baked == before  # nothing changed: nothing baked
    app.world.get(2, Text).text = "1"
    pixels(app)
    assert store.baked == before + 1
