"""UI layout (anchors, percents, rows, columns, grids, resizes), bad input, and pixels."""

from __future__ import annotations

from typing import Any

import numpy as np
import pytest

from kge import App, World
from kge.components.ui import Button, Label, Panel, ProgressBar, Slider, TextInput, UINode
from kge.errors import ValidationError
from kge.ui import DEFAULT_THEME, Theme, compute_layout
from kge.ui.layout import Box

from .conftest import SIZE, bbox, mask, pixels


def test_anchors_and_offsets_follow_the_window_size() -> None:
    w = World()
    corners = {
        name: w.spawn(UINode(anchor=name, offset=off, width=20, height=10))
        for name, off in (("top_left", (5, -5)), ("bottom_right", (-5, 5)), ("center", (0, 0)))
    }
    for size in ((800, 600), (300, 200)):
        boxes = compute_layout(w, size).boxes
        assert boxes[corners["top_left"]] == Box(5, size[1] - 15, 20, 10)
        assert boxes[corners["bottom_right"]] == Box(size[0] - 25, 5, 20, 10)
        assert boxes[corners["center"]].center == (size[0] / 2, size[1] / 2)


def test_percent_sizes_row_grid_nesting_and_auto_size() -> None:
    w = World()
    bar = w.spawn(UINode(anchor="bottom", width="50%", height="10%", layout="row", padding=4,
                         spacing=2, justify="center", align="center"))  # fmt: skip
    a = w.spawn(UINode(parent=bar, width=30, height=20))
    b = w.spawn(UINode(parent=bar, width=40, height="100%"))
    grid = w.spawn(UINode(anchor="top_left", width=210, layout="grid", columns=3, spacing=5,
                          padding=0))  # fmt: skip
    cells = [w.spawn(UINode(parent=grid, height=10, order=-i)) for i in range(5)]
    auto = w.spawn(UINode(anchor="right", layout="column", padding=3, spacing=1))
    w.spawn(UINode(parent=auto, width=50, height=10))
    w.spawn(UINode(parent=auto, width=70, height=10))
    boxes = compute_layout(w, (400, 300)).boxes
    assert boxes[bar] == Box(100, 0, 200, 30)
    # inner 192 wide: 30 + 2 + 40 = 72 centred -> starts at 104 + 60
    assert boxes[a] == Box(164, 5, 30, 20) and boxes[b] == Box(196, 4, 40, 22)
    # grid: cells (210 - 2 * 5) / 3 wide plus 5 between; order=-i puts the last spawned first
    ordered = sorted(cells, key=lambda e: -cells.index(e))
    xs = [boxes[e].x for e in ordered]
    ys = [boxes[e].y for e in ordered]
    step = 200 / 3 + 5
    assert xs == pytest.approx([0, step, 2 * step, 0, step])
    assert boxes[ordered[0]].w == pytest.approx(200 / 3)  # "auto" width fills the cell
    assert ys == [290, 290, 290, 275, 275]
    assert boxes[auto].w == 76 and boxes[auto].h == 27  # fits its children plus padding


def test_percent_layout_survives_a_resize_of_a_running_app() -> None:
    def scene(world: World) -> None:
        world.spawn(UINode(anchor="top_right", width="25%", height="25%"), Panel())

    app = App(scene, headless=True, size=(800, 600))
    app.step()
    from kge.ui.interact import UIState

    ((e, _),) = app.world.query(UINode)
    assert app.world.resource(UIState).layout.boxes[e] == Box(600, 450, 200, 150)
    app.size = (400, 400)  # what the window's on_resize does
    app.step()
    assert app.world.resource(UIState).layout.boxes[e] == Box(300, 300, 100, 100)


def test_hidden_nodes_missing_parents_and_cycles_are_not_drawn_and_never_hang() -> None:
    w = World()
    root = w.spawn(UINode(width=10, height=10, visible=False))
    child = w.spawn(UINode(parent=root, width=5, height=5))
    x = w.spawn(UINode(width=10, height=10))
    y = w.spawn(UINode(parent=x, width=10, height=10))
    w.get(x, UINode).parent = y  # a cycle written later
    lay = compute_layout(w, (100, 100))
    assert root not in lay.boxes and child not in lay.boxes
    assert x not in lay.boxes and y not in lay.boxes


def test_bad_input_is_refused_at_the_call_and_changes_nothing() -> None:
    w = World()
    with pytest.raises(ValidationError, match="UINode.width"):
        UINode(width=-10)
    with pytest.raises(ValidationError, match="UINode.height"):
        UINode(height="-5%")
    with pytest.raises(ValidationError, match="anchor"):
        UINode(anchor="middle")
    with pytest.raises(ValidationError, match="layout"):
        UINode(layout="flex")
    node = UINode(width=10)
    with pytest.raises(ValidationError, match="width"):
        node.width = float("nan")
    assert node.width == 10
    with pytest.raises(ValidationError, match=r"min \(5.0\) must be <= max \(1.0\)"):
        Slider(min=5, max=1)
    s = Slider(0, 10, 3)
    with pytest.raises(ValidationError, match="min"):
        s.min = 20
    assert (s.min, s.max, s.value) == (0, 10, 3)
    s.value = 99  # values are clamped into the range
    assert s.value == 10
    with pytest.raises(ValidationError, match="more than max_length 3"):
        TextInput("long", max_length=3)
    t = TextInput("ab", max_length=3)
    with pytest.raises(ValidationError, match="more than max_length 3"):
        t.text = "abcd"
    assert t.text == "ab"
    with pytest.raises(ValidationError, match="ProgressBar"):
        ProgressBar(value=1, max=-1, min=0)
    from kge.systems.ui import UIPlugin

    w.add_plugins(UIPlugin())
    before = len(w.query(UINode))
    with pytest.raises(ValidationError, match="entity 999 is not a UI node"):
        w.spawn(UINode(parent=999))
    plain = w.spawn()
    with pytest.raises(ValidationError, match="is not a UI node"):
        w.spawn(UINode(parent=plain))
    assert len(w.query(UINode)) == before
    with pytest.raises(ValidationError, match="accent"):
        Theme.from_data({"accent": [1, 2]})
    with pytest.raises(ValidationError, match="font_size"):
        Theme(font_size=0)


def test_themes_round_trip_as_data() -> None:
    t = Theme.from_data({"accent": [200, 10, 10, 255], "padding": 4})
    assert Theme.from_data(t.to_data()) == t and t != DEFAULT_THEME


# -- pixels ------------------------------------------------------------------------------------
ACCENT = DEFAULT_THEME.accent[:3]


def menu(world: World) -> None:
    col = world.spawn(
        UINode(width=120, layout="column", padding=8, spacing=6, align="stretch"), Panel()
    )
    world.spawn(UINode(parent=col, height=30), Button("Play"))
    world.spawn(UINode(parent=col, height=14), ProgressBar(0.5))
    world.spawn(UINode(anchor="top_left", offset=(4, -4)), Label("HUD", align="left"))


def test_menu_pixels_panel_button_bar_and_corner_hud(make_app: Any) -> None:
    app = make_app(menu)
    app.step()
    px = pixels(app)
    from kge.ui.interact import UIState

    boxes = app.world.resource(UIState).layout.boxes
    bar = next(e for e, _ in app.world.query(ProgressBar))
    button = next(e for e, _ in app.world.query(Button))
    panel_rgb = np.array(DEFAULT_THEME.panel[:3])
    col = next(e for e, _ in app.world.query(Panel))
    pb = boxes[col]
    # the see-through panel, blended over the black background at its alpha (the
    # headless pbuffer may hold 5-6 bits per channel: colours match within 8 levels)
    inside = px[int(pb.y + 3), int(pb.x + pb.w / 2), :3].astype(int)
    assert np.all(np.abs(inside - panel_rgb * tuple(DEFAULT_THEME.panel)[3] / 255) <= 8)
    assert px[int(pb.y) - 2, int(pb.x + pb.w / 2), :3].max() == 0  # just below: background
    # the bar is half filled with the accent colour
    x0, x1, y0, y1 = bbox(mask(px, ACCENT, tol=10))
    b = boxes[bar]
    assert abs(x0 - b.x) <= 1 and abs((x1 + 1) - (b.x + b.w / 2)) <= 1
    assert abs(y0 - b.y) <= 1 and abs((y1 + 1) - b.top) <= 1
    # the button's fill, and white-ish text inside it
    bb = boxes[button]
    fill = px[int(bb.y + 2), int(bb.x + bb.w / 2), :3].astype(int)
    assert np.all(np.abs(fill - np.array(DEFAULT_THEME.button[:3])) <= 8)
    text = mask(px[int(bb.y) : int(bb.top), int(bb.x) : int(bb.right)], DEFAULT_THEME.text[:3], 40)
    assert text.sum() > 20
    # HUD text in the top-left corner
    assert mask(px[SIZE[1] - 30 :, :60], DEFAULT_THEME.text[:3], 40).sum() > 20


def test_hover_and_focus_change_the_drawn_button(make_app: Any) -> None:
    app = make_app(menu)
    app.step()
    from kge.systems.ui import focus
    from kge.ui.interact import UIState

    button = next(e for e, _ in app.world.query(Button))
    bb = app.world.resource(UIState).layout.boxes[button]
    app.input.move_mouse(*bb.center)
    app.step()
    px = pixels(app)
    fill = px[int(bb.y + 2), int(bb.x + bb.w / 2), :3].astype(int)
    assert np.all(np.abs(fill - np.array(DEFAULT_THEME.button_hover[:3])) <= 8)
    app.input.move_mouse(1, 1)
    focus(app.world, button)
    app.step()
    px = pixels(app)
    ring = mask(px, DEFAULT_THEME.focus[:3], tol=10)
    x0, x1, y0, y1 = bbox(ring)
    assert x0 < bb.x and x1 >= bb.right and y0 < bb.y and y1 >= bb.top


def _frame_image() -> Any:
    """24 x 24: an 8 px red frame around a green middle (a nine-patch source)."""
    from kge.render.images import PixelImage

    px = np.zeros((24, 24, 4), np.uint8)
    px[...] = (255, 0, 0, 255)
    px[8:16, 8:16] = (0, 255, 0, 255)
    return PixelImage(24, 24, px.tobytes())


def test_nine_patch_panel_keeps_its_corners_and_stretches_the_middle(make_app: Any) -> None:
    img = _frame_image()

    def scene(world: World) -> None:
        world.spawn(UINode(width=160, height=100), Panel(image=img, border=8))

    app = make_app(scene)
    app.step()
    px = pixels(app)
    x0, x1, y0, y1 = bbox(mask(px, (0, 255, 0), tol=30))
    cx, cy = SIZE[0] // 2, SIZE[1] // 2
    # the frame stays 8 px thick on a 160 x 100 panel: the middle is 144 x 84
    assert (x1 - x0 + 1, y1 - y0 + 1) == (144, 84)
    assert (x0, y0) == (cx - 80 + 8, cy - 50 + 8)
    red = mask(px, (255, 0, 0), tol=30)
    assert red[cy, cx - 80 + 3] and red[cy - 50 + 3, cx] and not red[cy, cx]


def test_image_widget_and_button_icon_draw_their_pixels(make_app: Any) -> None:
    from kge.components.ui import UIImage
    from kge.render.images import solid

    def scene(world: World) -> None:
        world.spawn(UINode(anchor="left", offset=(10, 0), width=40, height=30),
                    UIImage(solid(4, 4, (0, 0, 255))))  # fmt: skip
        world.spawn(UINode(anchor="right", offset=(-10, 0), width=60, height=40),
                    Button(image=solid(2, 2, (255, 255, 0))))  # fmt: skip

    app = make_app(scene)
    app.step()
    px = pixels(app)
    assert bbox(mask(px, (0, 0, 255), tol=10)) == (10, 49, 65, 94)
    x0, x1, _, _ = bbox(mask(px, (255, 255, 0), tol=10))
    assert SIZE[0] - 70 < x0 < x1 < SIZE[0] - 10  # the icon sits inside the button
    with pytest.raises(Exception, match="asset name, a PixelImage or an image"):
        UIImage(42)


def test_scroll_list_rows_are_clipped_to_the_list(make_app: Any) -> None:
    from kge.components.ui import ScrollList

    def scene(world: World) -> None:
        world.spawn(UINode(width=120, height=60),
                    ScrollList([f"row {i}" for i in range(10)], selected=3, scroll=40.0,
                               row_height=20))  # fmt: skip

    app = make_app(scene)
    app.step()
    px = pixels(app)
    sel = mask(px, DEFAULT_THEME.selection[:3], tol=40)
    x0, x1, y0, y1 = bbox(sel)
    assert x1 < SIZE[0] // 2 + 60
    # row 3 is the second visible row (scrolled by two rows): 20 px tall, inside the list
    top = SIZE[1] // 2 + 30
    assert (y0, y1) == (top - 40, top - 21) and x0 >= SIZE[0] // 2 - 60
    text = mask(px, DEFAULT_THEME.text[:3], tol=60)
    ys = np.nonzero(text)[0]
    assert ys.min() >= SIZE[1] // 2 - 30 and ys.max() < top  # nothing drawn outside


def test_a_theme_resource_changes_what_is_drawn(make_app: Any) -> None:
    orange = (255, 128, 0, 255)

    def scene(world: World) -> None:
        world.insert_resource(Theme.from_data({"accent": list(orange)}))
        world.spawn(UINode(width=100, height=20), ProgressBar(1.0))

    app = make_app(scene)
    app.step()
    px = pixels(app)
    assert mask(px, orange[:3], tol=10).sum() > 1500
    assert mask(px, ACCENT, tol=10).sum() == 0


def test_text_field_draws_selection_and_caret_where_the_text_ends(make_app: Any) -> None:
    def scene(world: World) -> None:
        world.spawn(UINode(width=180, height=34), TextInput("hello world", caret=5, anchor=0))

    app = make_app(scene)
    app.step()
    from kge.systems.ui import focus

    (field,) = [e for e, _ in app.world.query(TextInput)]
    focus(app.world, field)
    px = pixels(app)
    sel = mask(px, DEFAULT_THEME.selection[:3], tol=30)
    x0, x1, _, _ = bbox(sel)
    left = SIZE[0] // 2 - 90 + DEFAULT_THEME.padding
    assert abs(x0 - left) <= 2 and 25 < x1 - x0 < 60  # "hello" is selected, not the rest
    app.world.get(field, TextInput).anchor = -1  # no selection: the caret shows
    px = pixels(app)
    assert mask(px, DEFAULT_THEME.selection[:3], tol=30).sum() == 0

    # the caret: a 2 px bright bar just right of "hello", gone without the focus
    def bright_at_caret(px: np.ndarray) -> int:
        return int(mask(px, DEFAULT_THEME.text[:3], tol=20)[:, int(x1) - 2 : int(x1) + 4].sum())

    with_caret = bright_at_caret(px)
    focus(app.world, None)
    assert with_caret - bright_at_caret(pixels(app)) >= 20
