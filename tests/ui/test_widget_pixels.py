"""What each widget draws, read back from 8-bit headless frames: anti-aliased edges, the
check mark, the dropdown arrow, radio dots, tabs, the colour picker's gradients, the
caret where the measure puts it, styles from components and themes, elided text that
stays in its box, the modal scrim and UI following an entity."""

from __future__ import annotations

from typing import Any

import numpy as np

from kge import Transform, World
from kge.components.camera import Camera
from kge.components.ui import (
    Button,
    ColorPicker,
    Dialog,
    Dropdown,
    Label,
    Panel,
    ProgressBar,
    RadioGroup,
    RichText,
    Slider,
    SpinBox,
    Style,
    Tabs,
    TextInput,
    Toggle,
    TreeItem,
    TreeView,
    UINode,
)
from kge.testing import box_of, focus
from kge.ui import DEFAULT_THEME as T
from kge.ui import Theme
from kge.ui import geometry as geo
from kge.ui.layout import Box
from kge.ui.state import UIState

from .conftest import SIZE, bbox, mask, pixels


def _region(px: np.ndarray, b: Box) -> np.ndarray:
    return px[int(b.y) : int(b.top), int(b.x) : int(b.right), :3]


def _one(world: World, widget: Any, w: float = 120, h: float = 40, **node: Any) -> int:
    return world.spawn(UINode(width=w, height=h, **node), widget)


def test_toggle_draws_a_check_mark_not_a_square(make_app: Any) -> None:
    app = make_app(lambda world: _one(world, Toggle(True, "On"), h=28))
    app.step()
    px = pixels(app)
    b = box_of(app, "On")
    square = Box(b.x, b.y, b.h, b.h)
    tick = mask(_region(px, square), T.accent[:3], tol=40)
    area = square.w * square.h
    assert 0.08 * area < tick.sum() < 0.35 * area  # strokes, not a filled box
    ys, xs = tick.nonzero()  # rows counted from the bottom
    left, right = xs < square.w / 2, xs >= square.w / 2
    # a check: the left stroke stays low, the right one climbs higher
    assert ys[right].max() > ys[left].max() + 3
    app.world.get(next(e for e, _ in app.world.query(Toggle)), Toggle).value = False
    px = pixels(app)
    assert mask(_region(px, square), T.accent[:3], tol=40).sum() == 0


def test_rounded_corners_and_the_slider_knob_are_anti_aliased(make_app: Any) -> None:
    def scene(world: World) -> None:
        world.spawn(UINode(anchor="top", offset=(0, -10), width=120, height=60),
                    Panel(color=(255, 255, 255), radius=16))  # fmt: skip
        world.spawn(UINode(anchor="bottom", offset=(0, 20), width=160, height=30),
                    Slider(0, 1, 0.5))  # fmt: skip

    app = make_app(scene)
    app.step()
    px = pixels(app).astype(int)
    # the panel's top-left corner: a run of partly covered pixels along the arc
    corner = px[SIZE[1] - 10 - 16 : SIZE[1] - 10, 40 : 40 + 16, :3].sum(-1) / 3
    partial = ((corner > 20) & (corner < 235)).sum()
    assert partial >= 10
    # the knob: a circle of radius 13 around the slider's middle, smooth at its edge
    s = box_of(app, next(e for e, _ in app.world.query(Slider)))
    cx, cy = int(s.center[0]), int(s.center[1])
    around = px[cy - 16 : cy + 16, cx - 16 : cx + 16, :3].sum(-1) / 3
    knob = sum(T.text[:3]) / 3
    assert (np.abs(around[14:18, 14:18] - knob) < 4).all()  # the knob's middle
    blended = ((around > sum(T.track[:3]) / 3 + 20) & (around < knob - 20)).sum()
    assert blended >= 12  # partly covered pixels all round its edge


def test_dropdown_draws_an_arrow_head_that_flips_when_open(make_app: Any) -> None:
    app = make_app(lambda world: _one(world, Dropdown(["Easy", "Hard"]), w=150, h=36))
    app.step()
    d = next(e for e, _ in app.world.query(Dropdown))
    b = box_of(app, d)
    arrow_area = Box(b.right - 36, b.y, 36, b.h)
    px = pixels(app)
    ys, xs = mask(_region(px, arrow_area), T.text_muted[:3], tol=45).nonzero()
    assert len(xs) > 15
    mid = (xs.min() + xs.max()) / 2
    ends = ys[(xs < mid - 4) | (xs > mid + 4)]
    tip = ys[np.abs(xs - mid) < 2]
    assert tip.min() < ends.min() - 2  # pointing down: the tip is below both ends
    app.world.get(d, Dropdown).open = True
    px = pixels(app)
    ys, xs = mask(_region(px, arrow_area), T.text_muted[:3], tol=45).nonzero()
    mid = (xs.min() + xs.max()) / 2
    assert ys[np.abs(xs - mid) < 2].max() > ys[(xs < mid - 4) | (xs > mid + 4)].max() + 2


def test_radio_dot_tabs_and_bars_show_their_values(make_app: Any) -> None:
    def scene(world: World) -> None:
        col = world.spawn(UINode(width=180, layout="column", spacing=8, align="stretch"))
        world.spawn(UINode(parent=col), RadioGroup(["a", "b"], 1))
        tabs = world.spawn(UINode(parent=col, height=60), Tabs(["One", "Two"], 1))
        world.spawn(UINode(parent=tabs), Label("1"))
        world.spawn(UINode(parent=tabs), Label("2"))
        world.spawn(UINode(parent=col, height=12), ProgressBar(0.25))

    app = make_app(scene)
    app.step()
    px = pixels(app)
    radio = box_of(app, next(e for e, _ in app.world.query(RadioGroup)))
    upper, lower = Box(radio.x, radio.center[1], 30, radio.h / 2), Box(radio.x, radio.y, 30,
                                                                        radio.h / 2)  # fmt: skip
    assert mask(_region(px, lower), T.accent[:3], tol=30).sum() > 20  # "b" has the dot
    assert mask(_region(px, upper), T.accent[:3], tol=30).sum() == 0
    two = box_of(app, "Two")
    assert mask(_region(px, two), T.accent[:3], tol=10).sum() > 0.5 * two.w * two.h
    bar = box_of(app, next(e for e, _ in app.world.query(ProgressBar)))
    fill = mask(_region(px, bar), T.accent[:3], tol=30)
    x0, x1, _, _ = bbox(fill)
    assert abs((x1 + 1) - bar.w * 0.25) <= 1 and x0 == 0


def test_the_colour_picker_draws_its_gradients(make_app: Any) -> None:
    app = make_app(lambda world: _one(world, ColorPicker((0, 255, 0, 255)), w=180, h=140))
    app.step()
    cp = next(e for e, _ in app.world.query(ColorPicker))
    parts = geo.picker_parts(box_of(app, cp), True)
    sv, hue = parts["sv"], parts["hue"]
    px = pixels(app).astype(int)

    def at(x: float, y: float) -> np.ndarray:
        return px[int(y), int(x), :3]

    assert (at(sv.x + 2, sv.top - 2) > 240).all()  # white at top left
    assert (at(sv.right - 3, sv.y + 1) < 15).all()  # black along the bottom
    near_top_right = at(sv.right - 12, sv.top - 12)  # (beside the marker at the corner)
    assert near_top_right[1] > 200 and near_top_right[0] < 40 and near_top_right[2] < 40
    bottom_hue = at(hue.center[0], hue.y + 2)
    assert bottom_hue[0] > 230 and bottom_hue[1] < 40  # red at the bottom of the hue bar
    third = at(hue.center[0], hue.y + hue.h * 0.36)  # green (the marker sits at 1/3)
    assert third[1] > 230 and third[0] < 40 and third[2] < 40


def test_the_caret_is_drawn_where_the_measured_text_ends(make_app: Any) -> None:
    app = make_app(lambda world: _one(world, TextInput("WWii"), w=180, h=36))
    app.step()
    field = next(e for e, _ in app.world.query(TextInput))
    focus(app, field)
    app.world.resource(UIState).time = 0.0  # the caret's blink: shown
    px = pixels(app)
    b = box_of(app, field)
    text = mask(_region(px, b.inset(4)), T.text[:3], tol=60)
    xs = text.nonzero()[1]
    # the rightmost text-coloured column is the caret, just after the glyphs end
    caret_x = xs.max()
    glyphs = xs[xs < caret_x - 2]
    assert 0 < caret_x - glyphs.max() <= 5


def test_styles_from_components_and_themes_change_the_look(make_app: Any) -> None:
    red = (200, 30, 30, 255)

    def scene(world: World) -> None:
        world.insert_resource(Theme.from_data({"styles": {"Label": {"text": [0, 255, 0]}}}))
        world.spawn(UINode(anchor="top", width=120, height=40), Button("Red"),
                    Style(background=red, radius=0, border_width=3,
                          border=(255, 255, 0, 255)))  # fmt: skip
        world.spawn(UINode(anchor="bottom"), Label("Green", size=20))

    app = make_app(scene)
    app.step()
    px = pixels(app)
    b = box_of(app, "Red")
    inner = _region(px, b.inset(6))
    assert mask(inner, red[:3], tol=3).mean() > 0.6
    assert mask(_region(px, b), (255, 255, 0), tol=3).sum() >= 2 * 3 * (b.w + b.h) - 40
    corner = px[int(b.top) - 1, int(b.x)]
    assert tuple(corner[:3]) == (255, 255, 0)  # radius 0: the corner pixel is filled
    assert mask(px, (0, 255, 0), tol=60).sum() > 30  # the theme's Label style
    app.input.move_mouse(*b.center)  # no hover colour given: the red is shaded lighter
    app.step()
    px = pixels(app)
    lighter = np.median(_region(px, b.inset(8)).reshape(-1, 3), axis=0)
    assert lighter[0] > red[0] and lighter[1] > red[1]


def test_long_text_is_elided_and_nothing_leaves_its_box(make_app: Any) -> None:
    huge = "W" * 100_000 + "\x00\x07"

    def scene(world: World) -> None:
        world.spawn(UINode(width=100, height=24), Label(huge))
        world.spawn(UINode(anchor="bottom", width=80, height=30), Button("A very long caption"))

    app = make_app(scene)
    app.step()
    px = pixels(app)
    lbl = box_of(app, next(e for e, _ in app.world.query(Label)))
    btn = box_of(app, "A very long caption")
    drawn = px[..., :3].max(-1) > 0
    inside = np.zeros_like(drawn)
    for b in (lbl, btn):
        inside[int(b.y) : int(np.ceil(b.top)), int(b.x) : int(np.ceil(b.right))] = True
    assert drawn.any() and not (drawn & ~inside).any()
    from kge.render.ui import drawer_for

    shown = [lab.text for lab in drawer_for(app.world).texts.labels.values()]
    assert any(t.endswith("…") and len(t) < 20 for t in shown)


def test_rich_text_runs_have_their_colours_and_weights(make_app: Any) -> None:
    app = make_app(lambda world: _one(world, RichText(
        "plain [color=#ff0000]red[/color] [b][color=#00ff00]bold[/color][/b]"), w=190, h=30))
    app.step()
    px = pixels(app)
    assert mask(px, (255, 0, 0), tol=50).sum() > 15
    assert mask(px, (0, 255, 0), tol=50).sum() > 15
    from kge.render.ui import drawer_for

    fonts = {lab.text: lab.weight for lab in drawer_for(app.world).texts.labels.values()}
    assert fonts.get("bold") == "bold" and fonts.get("red") == "normal"


def test_the_modal_scrim_darkens_what_is_behind_a_dialog(make_app: Any) -> None:
    def scene(world: World) -> None:
        world.spawn(UINode(width="100%", height="100%"), Panel(color=(200, 200, 200), radius=0))
        d = world.spawn(UINode(width=100, height=60), Dialog("Hi"))
        world.spawn(UINode(parent=d, height=20), Label("x"))

    app = make_app(scene)
    app.step()
    px = pixels(app).astype(int)
    behind = px[5, 5, :3]
    assert (behind < 200 - 50).all()  # dimmed by the scrim's alpha
    d = box_of(app, next(e for e, _ in app.world.query(Dialog)))
    assert abs(px[int(d.y) + 4, int(d.center[0]), 0] - T.panel[0]) < 12


def test_a_health_bar_follows_its_entity_on_screen(make_app: Any) -> None:
    def scene(world: World) -> None:
        world.insert_resource(Camera(pixels_per_meter=20))
        hero = world.spawn(Transform(-3.0, 0.0))
        world.spawn(UINode(follow=hero, follow_offset=(0, 1), anchor="bottom", width=40,
                           height=6), ProgressBar(1.0, color=(0, 255, 0)))  # fmt: skip

    app = make_app(scene)
    app.step()
    x0, x1, y0, _ = bbox(mask(pixels(app), (0, 255, 0), tol=10))
    assert (x0 + x1 + 1) / 2 == SIZE[0] / 2 - 60 and y0 == SIZE[1] / 2 + 20
    hero = next(e for e, (t,) in app.world.query(Transform))
    app.world.get(hero, Transform).x = 2.0
    app.step()
    x0, x1, _, _ = bbox(mask(pixels(app), (0, 255, 0), tol=10))
    assert (x0 + x1 + 1) / 2 == SIZE[0] / 2 + 40


def test_tree_and_spin_box_glyphs(make_app: Any) -> None:
    def scene(world: World) -> None:
        world.spawn(UINode(anchor="top", width=180, height=70),
                    TreeView([TreeItem(1, "a"), TreeItem(2, "b", 1)], expanded={1}, selected=2))
        world.spawn(UINode(anchor="bottom", width=140, height=34), SpinBox(3))

    app = make_app(scene)
    app.step()
    px = pixels(app)
    tree = box_of(app, next(e for e, _ in app.world.query(TreeView)))
    assert mask(_region(px, tree), T.selection[:3], tol=40).sum() > 200  # row b selected
    assert mask(_region(px, Box(tree.x, tree.top - 30, 30, 30)), T.text_muted[:3],
                tol=45).sum() > 5  # the open arrow of row a  # fmt: skip
    spin = box_of(app, next(e for e, _ in app.world.query(SpinBox)))
    minus, _, plus = geo.spin_parts(spin)
    plus_px = mask(_region(px, plus.inset(4)), T.text[:3], tol=60)
    minus_px = mask(_region(px, minus.inset(4)), T.text[:3], tol=60)
    assert plus_px.sum() > minus_px.sum() > 4  # "+" has a vertical stroke too


def test_a_style_gives_a_button_a_nine_patch_image_per_state(make_app: Any) -> None:
    from kge.render.images import solid

    red, green = solid(12, 12, (255, 0, 0)), solid(12, 12, (0, 255, 0))
    app = make_app(lambda world: _one(world, Button("Go"), w=100, h=40))
    app.world.add(next(e for e, _ in app.world.query(Button)),
                  Style(image=red, image_border=4, hover=Style(image=green)))  # fmt: skip
    app.step()
    b = box_of(app, "Go")
    px = pixels(app)
    assert mask(_region(px, b.inset(2)), (255, 0, 0), tol=10).mean() > 0.7
    app.input.move_mouse(*b.center)
    app.step()
    px = pixels(app)
    assert mask(_region(px, b.inset(2)), (0, 255, 0), tol=10).mean() > 0.7


def test_a_text_area_draws_its_lines_and_a_selection_over_two_of_them(make_app: Any) -> None:
    from kge.components.ui import TextArea

    app = make_app(lambda world: _one(world, TextArea("one\ntwo\nthree"), w=150, h=100))
    app.step()
    area = next(e for e, _ in app.world.query(TextArea))
    focus(app, area)
    w = app.world.get(area, TextArea)
    w.anchor, w.caret = 1, 6  # "ne\ntw"
    px = pixels(app)
    b = box_of(app, area)
    sel = mask(_region(px, b), T.selection[:3], tol=45)
    rows = np.nonzero(sel.any(axis=1))[0]
    assert len(rows) > 30 and rows.max() - rows.min() > 35  # two lines of selection
    text = mask(_region(px, b), T.text[:3], tol=60)
    assert text[: int(b.h) // 2].any() and text[int(b.h) // 2 :].any()
    drawn = px[..., :3].max(-1) > 0
    inside = np.zeros_like(drawn)
    inside[int(b.y) - 4 : int(b.top) + 4, int(b.x) - 4 : int(b.right) + 4] = True  # + focus ring
    assert not (drawn & ~inside).any()
