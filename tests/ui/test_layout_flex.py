"""Layout: grow, shrink, min/max, measured text, UI and text scale, nodes following an
entity, focus order and direction, resizes, and bad input (clear errors, finite boxes)."""

from __future__ import annotations

import math
from typing import Any

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from kge import App, Key, Transform, World
from kge.components.camera import Camera
from kge.components.ui import (
    Button,
    Label,
    Panel,
    ProgressBar,
    ScrollView,
    Slider,
    TextInput,
    UINode,
)
from kge.errors import ComponentTypeError, ValidationError
from kge.testing import box_of, press
from kge.ui.current import current_layout
from kge.ui.layout import Box, compute_layout
from kge.ui.measure import Font, TableMeasure, width
from kge.ui.settings import UISettings
from kge.ui.state import UIState


def _row(world: World, *nodes: UINode, layout: str = "row") -> list[int]:
    parent = world.spawn(UINode(anchor="bottom_left", width=300, height=100, layout=layout))
    out = []
    for n in nodes:
        n.parent = parent
        out.append(world.spawn(n))
    return out


def test_grow_shares_the_spare_room_by_weight_within_max() -> None:
    w = World()
    a, b, c = _row(w, UINode(width=50, grow=1), UINode(width=50, grow=2),
                   UINode(width=50, grow=1, max_width=60))  # fmt: skip
    boxes = compute_layout(w, (800, 600)).boxes
    # 150 spare: c takes 10 (its max), a and b share the other 140 as 1 : 2
    assert boxes[c].w == 60
    assert boxes[a].w == pytest.approx(50 + 140 / 3) and boxes[b].w == pytest.approx(50 + 280 / 3)
    assert boxes[a].x == 0 and boxes[b].x == pytest.approx(boxes[a].right)


def test_shrink_gives_back_overflow_by_weight_and_size_within_min() -> None:
    w = World()
    a, b, c = _row(w, UINode(width=200, shrink=1), UINode(width=100, shrink=1),
                   UINode(width=100, shrink=0))  # fmt: skip
    boxes = compute_layout(w, (800, 600)).boxes
    # 100 too wide: a and b give it back as 200 : 100; c does not shrink
    assert (boxes[a].w, boxes[b].w, boxes[c].w) == pytest.approx((200 - 200 / 3, 100 - 100 / 3, 100))
    w2 = World()
    a, b = _row(w2, UINode(width=300, shrink=1, min_width=250), UINode(width=100, shrink=1))
    boxes = compute_layout(w2, (800, 600)).boxes
    assert boxes[a].w == 250 and boxes[b].w == 50  # a stops at its min; b gives the rest


def test_min_and_max_bound_every_kind_of_size() -> None:
    w = World()
    parent = w.spawn(UINode(width=400, height=300))
    pct = w.spawn(UINode(parent=parent, width="100%", max_width=120, height="10%", min_height=50))
    auto = w.spawn(UINode(parent=parent, min_width=90), Label("x"))
    fixed = w.spawn(UINode(parent=parent, width=10, min_width=20, max_width=30))
    boxes = compute_layout(w, (800, 600)).boxes
    assert (boxes[pct].w, boxes[pct].h) == (120, 50)
    assert boxes[auto].w == 90 and boxes[fixed].w == 20


def test_auto_sizes_come_from_measured_text() -> None:
    w = World()
    narrow = w.spawn(UINode(anchor="left"), Label("iiiiiiii"))
    wide = w.spawn(UINode(anchor="right"), Label("WWWWWWWW"))
    boxes = compute_layout(w, (800, 600)).boxes
    m, f = TableMeasure(), Font(size=16)
    assert boxes[narrow].w == width(m, "iiiiiiii", f) + 4
    assert boxes[wide].w == width(m, "WWWWWWWW", f) + 4 > 2 * boxes[narrow].w
    assert boxes[narrow].h == m.line_height(f)
    lines = w.spawn(UINode(anchor="top"), Label("one\ntwo\nthree"))
    assert compute_layout(w, (800, 600)).boxes[lines].h == 3 * m.line_height(f)


def test_wrapped_labels_grow_taller_when_narrower() -> None:
    w = World()
    text = "a few words that wrap onto more lines in a narrow box " * 2
    box = w.spawn(UINode(width=300, layout="column", align="stretch"))
    lbl = w.spawn(UINode(parent=box), Label(text, wrap=True))
    tall_at_300 = compute_layout(w, (800, 600)).boxes[lbl].h
    w.get(box, UINode).width = 150
    tall_at_150 = compute_layout(w, (800, 600)).boxes[lbl].h
    assert tall_at_150 > tall_at_300 > TableMeasure().line_height(Font()) * 1.5


def hud(world: World) -> None:
    world.spawn(UINode(anchor="top_left", offset=(10, -10), width=200, height=40), Button("Menu"))
    world.spawn(UINode(anchor="bottom_right"), Label("Score 0"))


def test_ui_scale_fits_a_design_size_and_the_players_scale() -> None:
    app = App(hud, headless=True, size=(1280, 720))
    settings_ = app.world.resource(UISettings)
    settings_.design_size = (640, 360)
    app.step()
    b = box_of(app, "Menu")
    assert (b.x, b.top, b.w, b.h) == (20, 720 - 20, 400, 80)  # everything doubled
    settings_.scale = 0.5
    app.step()
    b = box_of(app, "Menu")
    assert (b.w, b.h) == (200, 40)
    app.size = (640, 720)  # the narrower side decides the fit
    app.step()
    assert box_of(app, "Menu").w == 100


def test_text_scale_makes_text_and_its_boxes_bigger_but_not_fixed_sizes() -> None:
    app = App(hud, headless=True, size=(800, 600))
    app.step()
    before = box_of(app, "Score 0")
    app.world.resource(UISettings).text_scale = 2.0
    app.step()
    after = box_of(app, "Score 0")
    assert after.w > 1.8 * before.w and after.h > 1.8 * before.h
    assert box_of(app, "Menu").w == 200
    with pytest.raises(ValidationError, match="text_scale"):
        app.world.resource(UISettings).text_scale = float("nan")


def test_boxes_follow_the_window_after_a_resize() -> None:
    app = App(hud, headless=True, size=(800, 600))
    app.step()
    for size in ((1024, 768), (320, 240)):
        app.size = size
        app.step()
        score = box_of(app, "Score 0")
        assert (score.right, score.y) == (size[0], 0)
        assert box_of(app, "Menu").top == size[1] - 10


def nametag(world: World) -> None:
    world.insert_resource(Camera(pixels_per_meter=50))
    hero = world.spawn(Transform(2.0, 1.0))
    world.spawn(UINode(follow=hero, follow_offset=(0.0, 1.0), anchor="bottom", width=60,
                       height=8), ProgressBar(0.5))  # fmt: skip
    world.spawn(UINode(follow=hero, anchor="top", offset=(0, -4)), Label("Hero"))


def test_nodes_follow_an_entity_on_screen_and_hide_when_it_goes() -> None:
    app = App(nametag, headless=True, size=(800, 600))
    app.step()
    bar = next(e for e, _ in app.world.query(ProgressBar))
    box = current_layout(app.world).boxes[bar]
    # hero at (2, 1) m, bar 1 m above it: (400 + 100, 300 + 100) px, its bottom centre there
    assert box.center[0] == 500 and box.y == 400
    hero = next(e for e, (t,) in app.world.query(Transform))
    app.world.get(hero, Transform).x = 3.0
    app.step()
    assert current_layout(app.world).boxes[bar].center[0] == 550
    assert box_of(app, "Hero").top == 350 - 4
    app.world.despawn(hero)
    app.step()
    assert bar not in current_layout(app.world).boxes
    with pytest.raises(ValidationError, match="only a root node"):
        parent = app.world.spawn(UINode())
        app.world.spawn(UINode(parent=parent, follow=parent))


def grid(world: World) -> None:
    g = world.spawn(UINode(width=300, layout="grid", columns=3, spacing=6))
    for i in range(9):
        world.spawn(UINode(parent=g, height=30), Button(f"C{i}"))


def _focused_text(app: App) -> str:
    e = app.world.resource(UIState).focused
    return app.world.get(e, Button).text if e is not None else ""


def test_down_in_a_three_column_grid_goes_to_the_cell_below() -> None:
    app = App(grid, headless=True, size=(640, 480))
    app.step()
    press(app, Key.TAB)
    press(app, Key.RIGHT)
    assert _focused_text(app) == "C1"
    press(app, Key.DOWN)
    assert _focused_text(app) == "C4"
    press(app, Key.DOWN)
    assert _focused_text(app) == "C7"
    press(app, Key.LEFT)
    assert _focused_text(app) == "C6"
    press(app, Key.UP)
    assert _focused_text(app) == "C3"
    press(app, Key.LEFT)  # nothing left of the first column: the focus stays
    assert _focused_text(app) == "C3"
    pad = app.input.connect_gamepad()
    pad.press("dpdown")
    app.step()
    assert _focused_text(app) == "C6"


def test_focus_order_puts_numbered_nodes_first() -> None:
    def scene(world: World) -> None:
        col = world.spawn(UINode(layout="column", spacing=4))
        world.spawn(UINode(parent=col), Button("A"))
        world.spawn(UINode(parent=col, focus_order=2), Button("B"))
        world.spawn(UINode(parent=col, focus_order=1), Button("C"))
        world.spawn(UINode(parent=col, focusable=False), Button("D"))
        world.spawn(UINode(parent=col), Button("E"))

    app = App(scene, headless=True, size=(640, 480))
    app.step()
    seen = []
    for _ in range(5):
        press(app, Key.TAB)
        seen.append(_focused_text(app))
    assert seen == ["C", "B", "A", "E", "C"]


# -- bad input ----------------------------------------------------------------------------------
@pytest.mark.parametrize(
    ("make", "match"),
    [
        (lambda: UINode(width=float("nan")), "width must be >= 0"),
        (lambda: UINode(height=-1), "height must be >= 0"),
        (lambda: UINode(padding=1e308), "padding must be a number of pixels in 0..1e"),
        (lambda: UINode(offset=(1e308, 0)), "offset must lie within"),
        (lambda: UINode(spacing=float("inf")), "spacing must be finite"),
        (lambda: UINode(min_height=10, max_height=5), "min_height .* must be <= max_height"),
        (lambda: UINode(grow=-1), "grow must be in 0..1e6"),
        (lambda: UINode(columns=0), "columns must be >= 1"),
        (lambda: Slider(min=5, max=1), "min .* must be <= max"),
        (lambda: ScrollView(scroll=(0, float("nan"))), "scroll\\[1\\] must be finite"),
        (lambda: Label(size=0), "size must be in \\(0, 1000\\]"),
    ],
)
def test_bad_values_are_refused_at_the_call(make: Any, match: str) -> None:
    with pytest.raises(ValidationError, match=match):
        make()


def test_a_write_of_min_above_max_is_refused_and_leaves_the_node_as_it_was() -> None:
    n = UINode(min_width=10, max_width=50)
    with pytest.raises(ValidationError, match="min_width"):
        n.min_width = 60
    assert n.min_width == 10
    with pytest.raises(ComponentTypeError):
        Label(text=None)  # type: ignore[arg-type]


def test_parent_cycles_self_parents_and_deep_nests_are_refused() -> None:
    app = App(lambda w: None, headless=True)
    world = app.world
    a = world.spawn(UINode())
    b = world.spawn(UINode(parent=a))
    with pytest.raises(ValidationError, match="would make a parent cycle"):
        world.get(a, UINode).parent = b
    with pytest.raises(ValidationError, match="cannot be its own parent"):
        world.get(a, UINode).parent = a
    assert world.get(a, UINode).parent is None
    parent = a
    for _ in range(98):  # a 100-deep nest (MAX_DEPTH) lays out
        parent = world.spawn(UINode(parent=parent, padding=1))
    leaf = world.spawn(UINode(parent=parent, width=10, height=10), Button("deep"))
    app.step()
    assert leaf in current_layout(world).boxes
    with pytest.raises(ValidationError, match="is 100 levels deep, the most a UI nests is 100"):
        world.spawn(UINode(parent=leaf))


def test_a_huge_slider_range_stays_finite() -> None:
    app = App(lambda w: w.spawn(UINode(width=200, height=24), Slider(-1e300, 1e300, 0.0)),
              headless=True, size=(400, 300))  # fmt: skip
    app.step()
    s = next(e for e, _ in app.world.query(Slider))
    w = app.world.get(s, Slider)
    assert w.fraction == 0.5
    b = box_of(app, s)
    app.input.click(at=(b.right - 1, b.center[1]))
    app.step()
    assert math.isfinite(w.value) and w.value > 1e299
    from kge.testing import focus

    focus(app, s)
    press(app, Key.LEFT)
    assert math.isfinite(w.value)


def test_a_hundred_thousand_character_label_with_control_characters_lays_out() -> None:
    text = ("ab\x00c\x07" * 20_000)
    w = World()
    e = w.spawn(UINode(width=200, height=30), Label(text))
    auto = w.spawn(UINode(anchor="top"), Label(text))
    boxes = compute_layout(w, (800, 600)).boxes
    assert boxes[e] == Box(300, 285, 200, 30)
    assert all(math.isfinite(v) for v in (boxes[auto].x, boxes[auto].w)) and boxes[auto].w <= 1e7


@st.composite
def trees(draw: Any) -> list[dict[str, Any]]:
    n = draw(st.integers(1, 25))
    sizes = st.one_of(st.floats(0, 1e7), st.sampled_from(["auto", "100%", "1000%", "0%"]))
    nodes = []
    for i in range(n):
        nodes.append(dict(
            parent=draw(st.one_of(st.none(), st.integers(0, max(i - 1, 0)))) if i else None,
            width=draw(sizes), height=draw(sizes), padding=draw(st.floats(0, 1e7)),
            spacing=draw(st.floats(0, 1e7)), offset=(draw(st.floats(-1e7, 1e7)), 0.0),
            layout=draw(st.sampled_from(["free", "row", "column", "grid"])),
            grow=draw(st.floats(0, 1e6)), shrink=draw(st.floats(0, 1e6)),
            anchor=draw(st.sampled_from(["center", "top_left", "bottom_right"])),
        ))  # fmt: skip
    return nodes


@given(trees(), st.sampled_from([Label("x" * 50), Button("go"), TextInput(), Panel(), None]))
@settings(max_examples=60, deadline=None)
def test_every_box_is_finite_whatever_the_sizes(spec: list[dict[str, Any]], widget: Any) -> None:
    w = World()
    ids: list[int] = []
    for node in spec:
        p = node.pop("parent")
        comps: list[Any] = [UINode(parent=None if p is None else ids[p], **node)]
        if widget is not None:
            comps.append(type(widget)())
        ids.append(w.spawn(*comps))
    for box in compute_layout(w, (800, 600)).boxes.values():
        assert all(math.isfinite(v) for v in (box.x, box.y, box.w, box.h))
        assert 0 <= box.w <= 1e7 and 0 <= box.h <= 1e7
