"""The ``Input`` resource: what the keyboard and mouse did this frame.

Three views per key or button, as in most engines: *held* (down now), *pressed*
(went down this frame) and *released* (went up this frame). The edges last one
frame: the App clears them at the end of each frame (after the update pass), so
a ``pressed`` seen in ``on_fixed_update`` is also seen in ``on_update`` of the
same frame.

A window feeds it from pyglet events; headless tests drive it directly:

>>> from kge.keys import Key
>>> inp = Input()
>>> inp.press(Key.SPACE)
>>> inp.pressed(Key.SPACE), inp.held(Key.SPACE)
(True, True)
>>> inp.end_frame(); inp.pressed(Key.SPACE), inp.held(Key.SPACE)
(False, True)
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field

from kge.errors import ValidationError
from kge.keys import Mouse
from kge.validate import finite, integer, vec2

Vec2 = tuple[float, float]


def _check_code(code: object, call: str, what: str, example: str) -> None:
    """Key and button codes are ints (``kge.Key.A``); a name such as ``"space"`` is a typo
    that would otherwise be held forever and match nothing."""
    if isinstance(code, bool) or not isinstance(code, int):
        raise ValidationError(
            f"Input.{call}: {what} must be a kge code such as kge.{example}, got {code!r}"
        )


@dataclass(slots=True, frozen=True)
class KeyEvent:
    """A key went down or up. ``modifiers`` is a :class:`kge.keys.Mod` bit mask."""

    key: int
    down: bool
    modifiers: int = 0


@dataclass(slots=True, frozen=True)
class MouseEvent:
    """A mouse button, motion or wheel event, in screen pixels and world metres."""

    kind: str  # "down", "up", "move", "scroll"
    button: int
    screen: Vec2
    world: Vec2
    scroll: Vec2 = (0.0, 0.0)
    modifiers: int = 0


@dataclass(slots=True)
class Input:
    """Keyboard and mouse state for the current frame."""

    _held: set[int] = field(default_factory=set)
    _pressed: set[int] = field(default_factory=set)
    _released: set[int] = field(default_factory=set)
    _buttons: set[int] = field(default_factory=set)
    _buttons_pressed: set[int] = field(default_factory=set)
    _buttons_released: set[int] = field(default_factory=set)
    modifiers: int = 0
    mouse_screen: Vec2 = (0.0, 0.0)
    mouse_world: Vec2 = (0.0, 0.0)
    scroll: Vec2 = (0.0, 0.0)
    events: list[KeyEvent | MouseEvent] = field(default_factory=list)
    screen_to_world: Callable[[Vec2], Vec2] = field(default=lambda p: p, repr=False)

    # -- queries -------------------------------------------------------------------
    def held(self, key: int) -> bool:
        return key in self._held

    def pressed(self, key: int) -> bool:
        return key in self._pressed

    def released(self, key: int) -> bool:
        return key in self._released

    def any_held(self, *keys: int) -> bool:
        return any(k in self._held for k in keys)

    def any_pressed(self, *keys: int) -> bool:
        return any(k in self._pressed for k in keys)

    def axis(self, negative: tuple[int, ...], positive: tuple[int, ...]) -> float:
        """-1, 0 or +1 from two groups of keys (e.g. ``(Key.S, Key.DOWN)``, ``(Key.W, Key.UP)``)."""
        return float(self.any_held(*positive)) - float(self.any_held(*negative))

    def mouse_held(self, button: int = Mouse.LEFT) -> bool:
        return button in self._buttons

    def mouse_pressed(self, button: int = Mouse.LEFT) -> bool:
        return button in self._buttons_pressed

    def mouse_released(self, button: int = Mouse.LEFT) -> bool:
        return button in self._buttons_released

    # -- feeding (window events or tests) -------------------------------------------
    def press(self, key: int, modifiers: int = 0) -> None:
        """A key goes down (a repeat while held is not a new press)."""
        _check_code(key, "press", "key", "Key.SPACE")
        self.modifiers = integer(modifiers, "Input.press", "modifiers")
        if key not in self._held:
            self._held.add(key)
            self._pressed.add(key)
            self.events.append(KeyEvent(key, True, modifiers))

    def release(self, key: int, modifiers: int = 0) -> None:
        _check_code(key, "release", "key", "Key.SPACE")
        self.modifiers = integer(modifiers, "Input.release", "modifiers")
        if key in self._held:
            self._held.discard(key)
            self._released.add(key)
            self.events.append(KeyEvent(key, False, modifiers))

    def move_mouse(self, x: float, y: float) -> None:
        """The pointer moves to screen pixel (x, y) (origin bottom-left)."""
        self.mouse_screen = (finite(x, "Input.move_mouse", "x"), finite(y, "Input.move_mouse", "y"))
        self.mouse_world = self.screen_to_world(self.mouse_screen)
        self.events.append(
            MouseEvent("move", 0, self.mouse_screen, self.mouse_world, modifiers=self.modifiers)
        )

    def mouse_down(
        self, button: int = Mouse.LEFT, at: Vec2 | None = None, modifiers: int = 0
    ) -> None:
        """A button goes down (at screen pixel ``at``, or where the pointer is)."""
        self._button("down", button, at, modifiers)

    def mouse_up(
        self, button: int = Mouse.LEFT, at: Vec2 | None = None, modifiers: int = 0
    ) -> None:
        self._button("up", button, at, modifiers)

    def _button(self, kind: str, button: int, at: Vec2 | None, modifiers: int) -> None:
        _check_code(button, f"mouse_{kind}", "button", "Mouse.LEFT")
        owner = f"Input.mouse_{kind}"
        integer(modifiers, owner, "modifiers")
        point = None if at is None else vec2(at, owner, "at")  # before any change
        self.modifiers = modifiers
        if point is not None:
            self.mouse_screen = point
        self.mouse_world = self.screen_to_world(self.mouse_screen)
        held, edge = (self._buttons, self._buttons_pressed)
        if kind == "down" and button not in held:
            held.add(button)
            edge.add(button)
        elif kind == "up" and button in held:
            held.discard(button)
            self._buttons_released.add(button)
        self.events.append(
            MouseEvent(kind, button, self.mouse_screen, self.mouse_world, modifiers=modifiers)
        )

    def click(self, button: int = Mouse.LEFT, at: Vec2 | None = None, modifiers: int = 0) -> None:
        """Down and up in the same frame: both edges are visible this frame."""
        self.mouse_down(button, at, modifiers)
        self.mouse_up(button, at, modifiers)

    def scroll_by(self, dx: float, dy: float) -> None:
        dx, dy = finite(dx, "Input.scroll_by", "dx"), finite(dy, "Input.scroll_by", "dy")
        self.scroll = (self.scroll[0] + dx, self.scroll[1] + dy)
        self.events.append(
            MouseEvent("scroll", 0, self.mouse_screen, self.mouse_world, (dx, dy), self.modifiers)
        )

    def refresh_world_position(self) -> None:
        """Recompute ``mouse_world`` (the camera may have moved under a still pointer)."""
        self.mouse_world = self.screen_to_world(self.mouse_screen)

    def end_frame(self) -> None:
        """Forget this frame's edges, events and scroll (the App calls it)."""
        self._pressed.clear()
        self._released.clear()
        self._buttons_pressed.clear()
        self._buttons_released.clear()
        self.scroll = (0.0, 0.0)
        self.events.clear()

    def reset(self) -> None:
        """Release everything (a scene change or a lost window focus)."""
        self._held.clear()
        self._buttons.clear()
        self.end_frame()
