"""Text input: measured caret placement, selection by mouse, scrolling fields, multi-line
editing, the clipboard (system through pyglet, in-process headless), IME composition,
key repeat, passwords and control characters."""

from __future__ import annotations

from typing import Any

import pytest

from kge import App, Key, Mod, World
from kge.components.ui import TextArea, TextInput, UINode
from kge.errors import ValidationError
from kge.testing import box_of, click, compose, focus, press, type_text
from kge.ui.events import TextSubmitted
from kge.ui.measure import Font, positions
from kge.ui.state import UIState
from kge.ui.style import look
from kge.ui.theme import DEFAULT_THEME

from .conftest import pixels

SIZE = (400, 300)
PAD = DEFAULT_THEME.padding


def field(world: World, text: str = "iiiiWWWW", width: float = 200, **kw: Any) -> None:
    world.spawn(UINode(width=width, height=36), TextInput(text, **kw))


def _app(scene: Any = field, **kwargs: Any) -> tuple[App, int]:
    app = App(scene, headless=True, size=SIZE, **kwargs)
    app.step()
    return app, next(e for e, _ in app.world.query(TextInput))


def _xs(app: App, text: str) -> list[float]:
    st = app.world.resource(UIState)
    return positions(st.measure, text, Font(size=DEFAULT_THEME.font_size))


def test_a_click_puts_the_caret_at_the_measured_character() -> None:
    app, e = _app()
    w = app.world.get(e, TextInput)
    box = box_of(app, e)
    xs = _xs(app, w.text)
    assert xs[4] < 4 * xs[8] / 8  # narrow i's, wide W's: an estimate by count would miss
    for i in (0, 2, 4, 5, 8):
        app.input.click(at=(box.x + PAD + xs[i] + 1, box.center[1]))
        app.step()
        app.step()  # past the double-click time of the previous click's position
        assert w.caret == i, i
    app.input.click(at=(box.x + PAD + xs[4] + 1, box.center[1]), modifiers=Mod.SHIFT)
    app.step()
    app.input.click(at=(box.x + PAD + xs[1] + 1, box.center[1]), modifiers=Mod.SHIFT)
    app.step()
    assert w.selection == (1, 8)


def test_double_click_selects_a_word_and_dragging_selects_text() -> None:
    app, e = _app(field, text="hello brave world", width=300)  # fits: no scroll
    w = app.world.get(e, TextInput)
    box = box_of(app, e)
    xs = _xs(app, w.text)
    at = (box.x + PAD + (xs[7] + xs[8]) / 2, box.center[1])  # inside "brave"
    app.input.click(at=at)
    app.step()
    app.input.click(at=at)
    app.step()
    assert w.selection == (6, 11)
    for _ in range(30):
        app.step()
    app.input.mouse_down(at=(box.x + PAD + xs[1], box.center[1]))
    app.step()
    app.input.move_mouse(box.x + PAD + xs[4], box.center[1])
    app.step()
    app.input.mouse_up()
    app.step()
    assert w.selection == (1, 4)


def test_a_long_line_scrolls_to_keep_the_caret_in_the_field() -> None:
    app, e = _app(field, text="", width=120)
    w = app.world.get(e, TextInput)
    focus(app, e)
    type_text(app, "the quick brown fox jumps over the lazy dog")
    st = app.world.resource(UIState)
    box = box_of(app, e)
    scroll = st.text_scroll[e]
    caret_x = box.x + PAD + _xs(app, w.text)[w.caret] - scroll
    assert scroll > 0 and box.x + PAD <= caret_x <= box.right - PAD
    press(app, Key.HOME)
    assert st.text_scroll[e] == 0.0
    click(app, e)  # at the middle: a character near the field's middle, not its end
    assert 0 < w.caret < len(w.text) // 2


def area(world: World, text: str = "", **kw: Any) -> None:
    world.spawn(UINode(width=220, height=90), TextArea(text, **kw))


def test_a_text_area_edits_lines_moves_by_line_scrolls_and_submits_on_ctrl_enter() -> None:
    app = App(area, headless=True, size=SIZE)
    app.step()
    e = next(x for x, _ in app.world.query(TextArea))
    w = app.world.get(e, TextArea)
    focus(app, e)
    type_text(app, "first")
    for n in range(2, 9):
        press(app, Key.ENTER)
        type_text(app, f"line {n}")
    assert w.text.count("\n") == 7 and w.caret == len(w.text)
    assert w.scroll > 0  # eight lines do not fit 90 px: scrolled to the caret
    press(app, Key.UP)
    press(app, Key.HOME)
    assert w.text[w.caret :].startswith("line 7")
    press(app, Key.END, Mod.SHIFT)
    assert w.selection is not None and w.text[slice(*w.selection)] == "line 7"
    press(app, Key.HOME, Mod.CTRL)
    assert w.caret == 0 and w.scroll == 0
    press(app, Key.PAGEDOWN)
    assert w.text[: w.caret].count("\n") >= 2
    app.input.press(Key.ENTER, Mod.CTRL)
    app.step()
    assert app.world.events(TextSubmitted) == [TextSubmitted(e, w.text)]
    app.input.release(Key.ENTER, Mod.CTRL)


def test_a_click_on_a_text_area_line_puts_the_caret_there_and_long_lines_wrap() -> None:
    text = "short\n" + "word " * 20 + "\nend"
    app = App(area, headless=True, size=SIZE, text=text)
    app.step()
    e = next(x for x, _ in app.world.query(TextArea))
    w = app.world.get(e, TextArea)
    from kge.ui.textview import area_view

    st = app.world.resource(UIState)
    assert st.layout.sizer is not None
    view = area_view(st.layout.sizer, st, e, w, box_of(app, e), look(DEFAULT_THEME, "TextArea"))
    assert len(view.lines) > 3  # the long line wrapped
    top = view.view.top
    app.input.click(at=(view.view.x + 1, top - 1.5 * view.line_h))  # the second line's start
    app.step()
    assert w.caret == len("short\n")


def test_tab_size_inserts_spaces_and_read_only_refuses_edits_but_copies() -> None:
    app = App(area, headless=True, size=SIZE, text="ab", tab_size=2)
    app.step()
    e = next(x for x, _ in app.world.query(TextArea))
    w = app.world.get(e, TextArea)
    focus(app, e)
    press(app, Key.TAB)
    assert w.text == "ab  " and app.world.resource(UIState).focused == e
    w.read_only = True
    app.step()
    type_text(app, "x")
    press(app, Key.BACKSPACE)
    assert w.text == "ab  "
    press(app, Key.A, Mod.CTRL)
    press(app, Key.C, Mod.CTRL)
    assert app.world.resource(UIState).clipboard == "ab  "


class FakeWindow:
    """pyglet's window clipboard methods, recording what crosses them."""

    def __init__(self) -> None:
        self.system = "from another program"
        self.sets: list[str] = []

    def get_clipboard_text(self) -> str:
        return self.system

    def set_clipboard_text(self, text: str) -> None:
        self.sets.append(text)
        self.system = text


def test_the_clipboard_goes_through_a_window_and_falls_back_headless(make_app: Any) -> None:
    app, e = _app(field, text="copy me")
    w = app.world.get(e, TextInput)
    st = app.world.resource(UIState)
    window = FakeWindow()
    st.store.attach(window)
    focus(app, e)
    press(app, Key.V, Mod.CTRL)  # paste what another program copied
    assert w.text == "copy mefrom another program" and st.store.system
    press(app, Key.A, Mod.CTRL)
    press(app, Key.X, Mod.CTRL)
    assert window.sets == ["copy mefrom another program"] and w.text == ""
    # drawn headless, pyglet's EGL window has no system clipboard: the in-process one works
    headless = make_app(field)
    pixels(headless)
    hs = headless.world.resource(UIState)
    hs.clipboard = "kept"
    assert hs.clipboard == "kept" and not hs.store.system


def test_ime_composition_shows_at_the_caret_until_typed(make_app: Any) -> None:
    app, e = _app(field, text="ab")
    w = app.world.get(e, TextInput)
    focus(app, e)
    press(app, Key.LEFT)  # caret between a and b
    compose(app, "にほ", 1)
    st = app.world.resource(UIState)
    assert st.composition == (e, "にほ", 1) and w.text == "ab"  # not typed yet
    app.input.type_text("日本")  # the IME commits
    app.step()
    assert w.text == "a日本b" and st.composition is None and w.caret == 3
    compose(app, "x")
    compose(app, "")  # cancelled
    assert st.composition is None and w.text == "a日本b"


def test_ime_composition_is_drawn_underlined_in_the_field(make_app: Any) -> None:
    app = make_app(field, text="")
    app.step()
    e = next(x for x, _ in app.world.query(TextInput))
    focus(app, e)
    plain = pixels(app).copy()
    compose(app, "abc")
    px = pixels(app)
    box = box_of(app, e)
    xs = (px != plain).any(axis=-1).nonzero()[1]
    assert len(xs) > 30  # the composed text and its underline appeared
    assert xs.min() >= box.x + PAD - 1 and xs.max() <= box.right - PAD


def test_a_held_backspace_repeats_through_the_systems_auto_repeat() -> None:
    app, e = _app(field, text="abcdef")
    focus(app, e)
    app.input.press(Key.BACKSPACE)
    app.step()
    for _ in range(3):
        app.input.repeat_key(Key.BACKSPACE)
        app.step()
    app.input.release(Key.BACKSPACE)
    app.step()
    assert app.world.get(e, TextInput).text == "ab"


def test_passwords_show_dots_and_are_not_copied() -> None:
    app, e = _app(field, text="secret", password=True)
    focus(app, e)
    press(app, Key.A, Mod.CTRL)
    press(app, Key.C, Mod.CTRL)
    assert app.world.resource(UIState).clipboard == ""


def test_control_characters_are_dropped_or_refused_and_writes_are_clamped() -> None:
    app, e = _app(field, text="")
    w = app.world.get(e, TextInput)
    focus(app, e)
    type_text(app, "a\x07\tb\r\nc\x00")  # typed line breaks are Enter's: left out
    assert w.text == "a    bc"
    app.world.resource(UIState).clipboard = "\r\nd\ne"
    press(app, Key.V, Mod.CTRL)  # pasted into one line: line breaks become spaces
    assert w.text == "a    bc d e"
    app2 = App(area, headless=True, size=SIZE)
    app2.step()
    a = next(x for x, _ in app2.world.query(TextArea))
    focus(app2, a)
    app2.world.resource(UIState).clipboard = "one\r\ntwo\x1b"
    press(app2, Key.V, Mod.CTRL)
    assert app2.world.get(a, TextArea).text == "one\ntwo"
    w.caret, w.anchor = 2, 4
    with pytest.raises(ValidationError, match=r"caret must be a character index 0\.\.11"):
        w.caret = 99
    with pytest.raises(ValidationError, match=r"anchor must be a character index"):
        w.anchor = -7
    assert (w.caret, w.anchor) == (2, 4)  # a refused write leaves the field as it was
    w.caret = -1  # at the end, as in the constructor
    assert w.caret == len(w.text)
    with pytest.raises(ValidationError, match="more than max_length 8"):
        TextInput("x" * 9, max_length=8)
    with pytest.raises(ValidationError, match="max_length must be >= 0"):
        TextInput(max_length=-1)
    with pytest.raises(ValidationError, match="hold the text's 11 characters, got 2"):
        w.max_length = 2


def test_a_windows_text_motions_after_the_press_are_repeats(make_app: Any) -> None:
    from kge.render.setup import ensure_renderer
    from kge.render.window import connect, disconnect

    app = make_app(field, text="abcdef")
    e = next(x for x, _ in app.world.query(TextInput))
    window = ensure_renderer(app).window
    app.render()
    focus(app, e)
    connect(app, window)

    def send(name: str, *args: Any) -> None:
        window.dispatch_event(name, *args)
        window.dispatch_events()

    try:
        send("on_key_press", Key.BACKSPACE, 0)
        send("on_text_motion", Key.BACKSPACE)  # pyglet's motion for the press itself
        app.step()
        send("on_text_motion", Key.BACKSPACE)  # held: the system repeats it
        send("on_text_motion", Key.BACKSPACE)
        app.step()
        send("on_key_release", Key.BACKSPACE, 0)
        app.step()
        assert app.world.get(e, TextInput).text == "abc"
    finally:
        disconnect(window)
