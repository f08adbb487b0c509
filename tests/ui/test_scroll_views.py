"""Scroll views of any widgets: wheel, drag, scrollbar, focus into view, clipping, clamping."""

from __future__ import annotations

from typing import Any

from kge import App, Key, World
from kge.components.ui import Button, Panel, ScrollView, Slider, UINode
from kge.testing import UITargetError, box_of, click, focus, press, scroll
from kge.ui import geometry as geo
from kge.ui.current import current_layout
from kge.ui.state import UIState

from .conftest import SIZE, bbox, mask, pixels


def menu(world: World, rows: int = 30) -> None:
    view = world.spawn(UINode(width=160, height=100, layout="column", padding=4, spacing=4,
                              align="stretch"), Panel(), ScrollView())  # fmt: skip
    for i in range(rows):
        world.spawn(UINode(parent=view, height=20), Button(f"Item {i}"))


def _view(app: App) -> tuple[int, ScrollView]:
    e = next(e for e, _ in app.world.query(ScrollView))
    return e, app.world.get(e, ScrollView)


def test_the_wheel_scrolls_and_offsets_past_the_end_are_clamped() -> None:
    app = App(menu, headless=True, size=SIZE)
    app.step()
    e, sv = _view(app)
    scroll(app, e, -1)
    assert sv.scroll == (0.0, 48.0)  # one notch: wheel_step pixels
    area = current_layout(app.world).scroll[e]
    assert area.content_h == 30 * 20 + 29 * 4 and area.viewport.h == 100 - 8
    assert area.max_y == area.content_h - area.viewport.h
    sv.scroll = (500.0, 1e6)  # past the end (and sideways in a vertical view)
    app.step()
    assert sv.scroll == (0.0, area.max_y)
    sv.scroll = (0.0, 0.0)
    app.step()
    assert box_of(app, "Item 0").top == 130 - 4  # back at the top (window 160 high)


def test_clicks_reach_scrolled_buttons_and_hidden_ones_are_not_hit() -> None:
    app = App(menu, headless=True, size=SIZE)
    app.step()
    e, sv = _view(app)
    try:
        click(app, "Item 10")
        raise AssertionError("a scrolled-out button was clicked")
    except UITargetError as err:
        assert "scrolled out of view" in str(err)
    sv.scroll = (0.0, 10 * 24.0)
    app.step()
    b = click(app, "Item 10")
    assert app.world.resource(UIState).focused == b
    below = current_layout(app.world).boxes[e]
    app.input.click(at=(below.center[0], below.y - 5))  # under the view: item 13's box is
    app.step()  # there but clipped away: nothing is hit
    assert app.world.resource(UIState).focused is None


def test_tab_focus_scrolls_the_focused_widget_into_view() -> None:
    app = App(menu, headless=True, size=SIZE)
    app.step()
    e, sv = _view(app)
    for _ in range(9):  # Item 8: below the view's 92 px
        press(app, Key.TAB)
    view = current_layout(app.world).scroll[e].viewport
    focused = app.world.resource(UIState).focused
    assert focused is not None and sv.scroll[1] > 0
    b = current_layout(app.world).boxes[focused]
    assert view.y - 1e-6 <= b.y and b.top <= view.top + 1e-6
    for _ in range(8):  # back up to the first item
        press(app, Key.UP)
    assert sv.scroll[1] == 0.0


def test_the_scrollbar_drags_and_the_track_jumps() -> None:
    app = App(menu, headless=True, size=SIZE)
    app.step()
    e, sv = _view(app)
    area = current_layout(app.world).scroll[e]
    bar = app.world.resource(UIState).layout.sizer.theme.scrollbar  # type: ignore[union-attr]
    track, _ = geo.scroll_tracks(area, bar)
    assert track is not None
    thumb = geo.scrollbar(track, area.viewport.h, area.content_h, 0.0)
    app.input.mouse_down(at=thumb.center)
    app.step()
    app.input.move_mouse(thumb.center[0], thumb.center[1] - 30)
    app.step()
    room = track.h - thumb.h
    assert abs(sv.scroll[1] - 30 / room * area.max_y) < 1e-6
    app.input.mouse_up()
    app.step()
    app.input.click(at=(track.center[0], track.y + 2))  # the track's bottom: near the end
    app.step()
    assert sv.scroll[1] > 0.85 * area.max_y


def test_dragging_the_content_pans_it_like_a_touch_screen() -> None:
    def scene(world: World) -> None:
        view = world.spawn(UINode(width=160, height=100, layout="column", spacing=40),
                           Panel(), ScrollView())  # fmt: skip
        for i in range(6):
            world.spawn(UINode(parent=view, height=30, width=60), Button(f"B{i}"))

    app = App(scene, headless=True, size=SIZE)
    app.step()
    _e, sv = _view(app)
    gap = box_of(app, "B0")
    start = (gap.right + 30, gap.center[1])  # on the panel, beside the buttons
    app.input.mouse_down(at=start)
    app.step()
    app.input.move_mouse(start[0], start[1] + 50)
    app.step()
    app.input.mouse_up()
    app.step()
    assert sv.scroll == (0.0, 50.0)


def test_a_slider_inside_a_scroll_view_takes_the_wheel_only_when_focused() -> None:
    def scene(world: World) -> None:
        view = world.spawn(UINode(width=160, height=100, layout="column", spacing=10,
                                  align="stretch"), ScrollView())  # fmt: skip
        world.spawn(UINode(parent=view, height=24), Slider(0, 10, 5, step=1))
        for i in range(6):
            world.spawn(UINode(parent=view, height=30), Button(f"B{i}"))

    app = App(scene, headless=True, size=SIZE)
    app.step()
    _e, sv = _view(app)
    slider = next(x for x, _ in app.world.query(Slider))
    scroll(app, slider, -1)
    assert sv.scroll[1] > 0 and app.world.get(slider, Slider).value == 5
    sv.scroll = (0.0, 0.0)
    focus(app, slider)
    scroll(app, slider, 1)
    assert sv.scroll[1] == 0 and app.world.get(slider, Slider).value == 6


def test_scrolled_content_is_clipped_to_the_view(make_app: Any) -> None:
    def scene(world: World) -> None:
        view = world.spawn(UINode(width=120, height=60, layout="column", align="stretch"),
                           ScrollView(scrollbar=False))  # fmt: skip
        for _i in range(8):
            world.spawn(UINode(parent=view, height=20), Panel(color=(255, 0, 255), radius=0))

    app = make_app(scene)
    app.step()
    px = pixels(app)
    ys, xs = (px[..., :3].max(axis=-1) > 0).nonzero()  # anything drawn on the black window
    assert ys.min() == SIZE[1] // 2 - 30 and ys.max() == SIZE[1] // 2 + 29  # 60 px, no more
    assert xs.min() == SIZE[0] // 2 - 60 and xs.max() == SIZE[0] // 2 + 59
    assert mask(px, (255, 0, 255), tol=10).sum() > 100 * 50


def test_the_scrollbar_is_drawn_beside_the_content_and_its_thumb_follows_the_scroll(
    make_app: Any,
) -> None:
    def scene(world: World) -> None:
        view = world.spawn(UINode(width=120, height=60, layout="column", align="stretch"),
                           ScrollView())  # fmt: skip
        for _i in range(8):
            world.spawn(UINode(parent=view, height=20), Panel(color=(255, 0, 255), radius=0))

    app = make_app(scene)
    app.step()
    left, right = SIZE[0] // 2 - 60, SIZE[0] // 2 + 59
    bottom, top = SIZE[1] // 2 - 30, SIZE[1] // 2 + 29
    px = pixels(app)
    cx0, cx1, cy0, cy1 = bbox(mask(px, (255, 0, 255), tol=10))  # (edges are anti-aliased)
    assert cx0 <= left + 1 and right - 12 <= cx1 <= right - 10  # the bar's 10 px stay clear
    assert cy0 <= bottom + 1 and cy1 >= top - 1
    thumb_colour = (150, 158, 172)  # the theme's text_muted
    x0, x1, y0, y1 = bbox(mask(px, thumb_colour, tol=12))
    assert right - 10 <= x0 and x1 <= right  # in the bar
    assert y1 >= top - 4 and y0 > bottom + 20  # at the top: 60 of 160 px shown
    _, sv = _view(app)
    sv.scroll = (0.0, 100.0)  # the end
    app.step()
    x0, x1, y0, y1 = bbox(mask(pixels(app), thumb_colour, tol=12))
    assert y0 <= bottom + 4 and y1 < top - 20  # at the bottom
