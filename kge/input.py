"""The ``Input`` resource: what the keyboard, mouse and gamepads did.

Three views per key or button, as in most engines: *held* (down now), *pressed*
(went down) and *released* (went up). The edges are kept twice, because frames and
fixed steps do not line up:

* code running in the update pass (``on_update``, UPDATE/LATE systems) sees an edge
  in exactly one frame: the frame after it happened;
* code running in a fixed step (``on_fixed_update``, FIXED systems) sees an edge in
  exactly one fixed step: the first step after it happened, even when that step
  comes several frames later (144 Hz frames, 60 Hz steps) and never again in the
  second step of a frame that runs two (30 Hz frames). This is the classic
  FixedUpdate trap of frame-based input, closed.

The App tells the Input when a fixed step starts and ends
(:meth:`Input.begin_step` / :meth:`Input.end_step`); the queries answer for the
pass they are called from.

A window feeds it from pyglet events; headless tests drive it directly:

>>> from kge.keys import Key
>>> inp = Input()
>>> inp.press(Key.SPACE)
>>> inp.pressed(Key.SPACE), inp.held(Key.SPACE)
(True, True)
>>> inp.end_frame(); inp.pressed(Key.SPACE), inp.held(Key.SPACE)
(False, True)
>>> inp.begin_step(); inp.pressed(Key.SPACE)      # the first fixed step still sees it
True
>>> inp.end_step(); inp.begin_step(); inp.pressed(Key.SPACE)
False

Gamepads (see :class:`Gamepad`) are fed the same way: the window connects pyglet's
controllers, tests call :meth:`Input.connect_gamepad` and drive the returned pad.
Touch points and gestures (:mod:`kge.touch`) too: :meth:`Input.touch_down`,
:meth:`Input.touch_move`, :meth:`Input.touch_up`, and the mouse's left button as
touch 0 when :attr:`Input.emulate_touch_from_mouse` is set.
"""

from __future__ import annotations

from collections.abc import Callable, Hashable, Iterator
from contextlib import contextmanager
from dataclasses import dataclass, field

from kge.errors import ValidationError
from kge.keys import Mouse
from kge.touch import GESTURES, MOUSE_TOUCH_ID, TouchPoint, TouchState
from kge.validate import boolean, finite, in_range, integer, non_negative, vec2

Vec2 = tuple[float, float]

#: gamepad buttons, with pyglet's (SDL's) names; the triggers are buttons too, down
#: past :data:`TRIGGER_DOWN` and up again under :data:`TRIGGER_UP` (no chatter)
PAD_BUTTONS: frozenset[str] = frozenset(
    (
        "a", "b", "x", "y", "back", "start", "guide", "leftshoulder", "rightshoulder",
        "leftstick", "rightstick", "dpleft", "dpright", "dpup", "dpdown",
        "lefttrigger", "righttrigger",
    )
)  # fmt: skip
TRIGGER_DOWN = 0.5
TRIGGER_UP = 0.4
#: gamepad axes: sticks in [-1, 1] (y up), triggers in [0, 1]
PAD_AXES: frozenset[str] = frozenset(
    ("leftx", "lefty", "rightx", "righty", "lefttrigger", "righttrigger")
)


def _check_code(code: object, call: str, what: str, example: str) -> None:
    """Key and button codes are ints (``kge.Key.A``); a name such as ``"space"`` is a typo
    that would otherwise be held forever and match nothing."""
    if isinstance(code, bool) or not isinstance(code, int):
        raise ValidationError(
            f"Input.{call}: {what} must be a kge code such as kge.{example}, got {code!r}"
        )


@dataclass(slots=True, frozen=True)
class KeyEvent:
    """A key went down or up. ``modifiers`` is a :class:`kge.keys.Mod` bit mask.

    ``repeat`` marks the operating system's auto-repeat of a held key (text fields
    use it; edges and actions never see it).
    """

    key: int
    down: bool
    modifiers: int = 0
    repeat: bool = False


@dataclass(slots=True, frozen=True)
class MouseEvent:
    """A mouse button, motion or wheel event, in screen pixels and world metres."""

    kind: str  # "down", "up", "move", "scroll"
    button: int
    screen: Vec2
    world: Vec2
    scroll: Vec2 = (0.0, 0.0)
    modifiers: int = 0


@dataclass(slots=True, frozen=True)
class TextEvent:
    """Text typed this frame (after the keyboard layout: ``"A"`` with shift, ``"é"``)."""

    text: str


@dataclass(slots=True, frozen=True)
class GamepadEvent:
    """A gamepad connected (``"connect"``), went away (``"disconnect"``), or a button
    went ``"down"`` / ``"up"``."""

    kind: str
    pad: int
    button: str = ""


@dataclass(slots=True, frozen=True)
class CompositionEvent:
    """An input method (IME) is composing text not yet typed: ``text`` is shown at the
    caret of the focused field with the IME's ``caret`` inside it; an empty ``text``
    ends the composition. The finished text arrives as a :class:`TextEvent`."""

    text: str
    caret: int = -1


AnyEvent = KeyEvent | MouseEvent | TextEvent | GamepadEvent | CompositionEvent


_NONE: frozenset[Hashable] = frozenset()
Codes = set[Hashable] | frozenset[Hashable]


class _Edges:
    """Held codes and their edges, per frame and per fixed step (one family of codes)."""

    __slots__ = ("held", "pending", "pressed", "released", "step_pressed", "step_released")

    def __init__(self) -> None:
        self.held: set[Hashable] = set()
        self.pressed: set[Hashable] = set()
        self.released: set[Hashable] = set()
        #: edges since the last fixed step began: (pressed, released)
        self.pending: tuple[set[Hashable], set[Hashable]] = (set(), set())
        self.step_pressed: set[Hashable] = set()
        self.step_released: set[Hashable] = set()

    def down(self, code: Hashable) -> bool:
        if code in self.held:
            return False
        self.held.add(code)
        self.pressed.add(code)
        self.pending[0].add(code)
        return True

    def up(self, code: Hashable) -> bool:
        if code not in self.held:
            return False
        self.held.discard(code)
        self.released.add(code)
        self.pending[1].add(code)
        return True

    def down_now(self, muted: bool) -> Codes:
        return _NONE if muted else self.held

    def edges(self, fixed: bool | None) -> tuple[Codes, Codes]:
        if fixed is None:
            return _NONE, _NONE
        if fixed:
            return self.step_pressed, self.step_released
        return self.pressed, self.released

    def begin_step(self) -> None:
        self.step_pressed, self.step_released = self.pending
        self.pending = (set(), set())

    def end_step(self) -> None:
        self.step_pressed = set()
        self.step_released = set()

    def end_frame(self) -> None:
        self.pressed.clear()
        self.released.clear()

    def forget(self, code: Hashable) -> None:
        """Hide a press from the game (the UI took it); it stays held."""
        self.pressed.discard(code)
        self.pending[0].discard(code)

    def reset(self) -> None:
        self.held.clear()
        self.end_frame()
        self.pending = (set(), set())
        self.end_step()


@dataclass(slots=True)
class Gamepad:
    """One connected gamepad: its index (lowest free slot), name and axis values.

    Buttons are read through :class:`Input` (``inp.pad_held("a", pad=0)``) so their
    edges follow the same frame / fixed-step rules as keys. A simulated pad is just
    one that a test drives with :meth:`press`, :meth:`release` and :meth:`move`.
    """

    index: int
    name: str
    axes: dict[str, float] = field(default_factory=lambda: dict.fromkeys(PAD_AXES, 0.0))
    connected: bool = True
    #: ``(weak, strong, duration)`` of the last rumble asked for (what a test checks)
    last_rumble: tuple[float, float, float] | None = None
    rumble_fn: Callable[[float, float, float], None] | None = field(default=None, repr=False)
    _input: Input | None = field(default=None, repr=False)

    def _owner(self) -> Input:
        if self._input is None or not self.connected:
            raise ValidationError(f"gamepad {self.index} ({self.name}) is not connected")
        return self._input

    def press(self, button: str) -> None:
        self._owner().pad_press(self.index, button)

    def release(self, button: str) -> None:
        self._owner().pad_release(self.index, button)

    def move(self, axis: str, value: float) -> None:
        self._owner().pad_axis(self.index, axis, value)

    def rumble(self, weak: float = 1.0, strong: float = 1.0, duration: float = 0.3) -> None:
        """Vibrate (where the pad and pyglet's driver can): motor strengths 0..1, seconds."""
        weak = in_range(weak, 0.0, 1.0, "Gamepad.rumble", "weak")
        strong = in_range(strong, 0.0, 1.0, "Gamepad.rumble", "strong")
        duration = non_negative(duration, "Gamepad.rumble", "duration")
        self.last_rumble = (float(weak), float(strong), float(duration))
        if self.rumble_fn is not None and self.connected:
            self.rumble_fn(float(weak), float(strong), float(duration))


def _check_gesture(gesture: str) -> str:
    if gesture not in GESTURES:
        raise ValidationError(f"unknown gesture {gesture!r}; gestures are {', '.join(GESTURES)}")
    return gesture


def _touch_id(id: object, call: str) -> int:
    if isinstance(id, bool) or not isinstance(id, int) or id < 0:
        raise ValidationError(f"Input.{call}: a touch id is an int >= 0, got {id!r}")
    return id


def _check_button(button: str) -> str:
    if button not in PAD_BUTTONS:
        raise ValidationError(
            f"unknown gamepad button {button!r}; buttons are {', '.join(sorted(PAD_BUTTONS))}"
        )
    return button


def _check_axis(axis: str) -> str:
    if axis not in PAD_AXES:
        raise ValidationError(
            f"unknown gamepad axis {axis!r}; axes are {', '.join(sorted(PAD_AXES))}"
        )
    return axis


@dataclass(slots=True)
class Input:
    """Keyboard, mouse and gamepad state (see the module docstring)."""

    _keys: _Edges = field(default_factory=_Edges)
    _buttons: _Edges = field(default_factory=_Edges)
    _pads: _Edges = field(default_factory=_Edges)  # codes: (pad index, button)
    _gestures: _Edges = field(default_factory=_Edges)  # codes: gesture names
    _fixed: bool = False
    _muted: bool = False
    _captured: bool = False
    modifiers: int = 0
    mouse_screen: Vec2 = (0.0, 0.0)
    mouse_world: Vec2 = (0.0, 0.0)
    scroll: Vec2 = (0.0, 0.0)
    text: str = ""  #: text typed this frame
    events: list[AnyEvent] = field(default_factory=list)
    gamepads: dict[int, Gamepad] = field(default_factory=dict)
    screen_to_world: Callable[[Vec2], Vec2] = field(default=lambda p: p, repr=False)
    #: the mouse's left button is touch 0 too (Godot's "emulate touch from mouse"):
    #: gestures can be tried on a desktop, where pyglet has no touch events
    emulate_touch_from_mouse: bool = False
    touch: TouchState = field(init=False, repr=False)

    def __post_init__(self) -> None:
        self.touch = TouchState(self._gestures, lambda p: self.screen_to_world(p))

    # -- keys --------------------------------------------------------------------------
    def held(self, key: int) -> bool:
        return key in self._keys.down_now(self._off)

    def pressed(self, key: int) -> bool:
        return key in self._keys.edges(self._view)[0]

    def released(self, key: int) -> bool:
        return key in self._keys.edges(self._view)[1]

    def any_held(self, *keys: int) -> bool:
        held = self._keys.down_now(self._off)
        return any(k in held for k in keys)

    def any_pressed(self, *keys: int) -> bool:
        edges = self._keys.edges(self._view)[0]
        return any(k in edges for k in keys)

    def keys_pressed(self) -> list[int]:
        """Keys that went down (this frame, or this fixed step inside one), sorted."""
        return sorted(k for k in self._keys.edges(self._view)[0] if isinstance(k, int))

    def axis(self, negative: tuple[int, ...], positive: tuple[int, ...]) -> float:
        """-1, 0 or +1 from two groups of keys (e.g. ``(Key.S, Key.DOWN)``, ``(Key.W, Key.UP)``)."""
        return float(self.any_held(*positive)) - float(self.any_held(*negative))

    # -- mouse -------------------------------------------------------------------------
    def mouse_held(self, button: int = Mouse.LEFT) -> bool:
        return button in self._buttons.down_now(self._off)

    def mouse_pressed(self, button: int = Mouse.LEFT) -> bool:
        return button in self._buttons.edges(self._view)[0]

    def mouse_released(self, button: int = Mouse.LEFT) -> bool:
        return button in self._buttons.edges(self._view)[1]

    # -- gamepads ----------------------------------------------------------------------
    def pad_held(self, button: str, pad: int | None = None) -> bool:
        """Is ``button`` down on gamepad ``pad`` (any pad when None)?"""
        return self._pad_in(self._pads.down_now(self._off), button, pad)

    def pad_pressed(self, button: str, pad: int | None = None) -> bool:
        return self._pad_in(self._pads.edges(self._view)[0], button, pad)

    def pad_released(self, button: str, pad: int | None = None) -> bool:
        return self._pad_in(self._pads.edges(self._view)[1], button, pad)

    def pad_axis_value(self, axis: str, pad: int | None = None) -> float:
        """The raw value of ``axis`` on ``pad`` (any pad: the one pushed furthest)."""
        _check_axis(axis)
        if self._off:
            return 0.0
        if pad is not None:
            gp = self.gamepads.get(pad)
            return gp.axes[axis] if gp is not None else 0.0
        return max((gp.axes[axis] for gp in self.gamepads.values()), key=abs, default=0.0)

    def _pad_in(self, codes: Codes, button: str, pad: int | None) -> bool:
        _check_button(button)
        if pad is not None:
            return (pad, button) in codes
        return any((i, button) in codes for i in self.gamepads)

    def connect_gamepad(
        self,
        name: str = "Simulated gamepad",
        rumble: Callable[[float, float, float], None] | None = None,
    ) -> Gamepad:
        """A gamepad joins, in the lowest free slot (a test's simulated pad, or pyglet's)."""
        index = 0
        while index in self.gamepads:
            index += 1
        pad = Gamepad(index, str(name), rumble_fn=rumble, _input=self)
        self.gamepads[index] = pad
        self.events.append(GamepadEvent("connect", index))
        return pad

    def disconnect_gamepad(self, index: int) -> None:
        """A gamepad went away: its buttons are released and its slot is free again."""
        pad = self.gamepads.pop(index, None)
        if pad is None:
            raise ValidationError(f"no gamepad {index} is connected")
        for code in [c for c in self._pads.held if isinstance(c, tuple) and c[0] == index]:
            self._pads.up(code)
        pad.connected = False
        self.events.append(GamepadEvent("disconnect", index))

    def _pad(self, index: int) -> Gamepad:
        pad = self.gamepads.get(index)
        if pad is None:
            raise ValidationError(f"no gamepad {index} is connected")
        return pad

    def pad_press(self, index: int, button: str) -> None:
        self._pad(index)
        if self._pads.down((index, _check_button(button))):
            self.events.append(GamepadEvent("down", index, button))

    def pad_release(self, index: int, button: str) -> None:
        self._pad(index)
        if self._pads.up((index, _check_button(button))):
            self.events.append(GamepadEvent("up", index, button))

    def pad_axis(self, index: int, axis: str, value: float) -> None:
        """Set an axis of pad ``index`` (sticks: -1..1, y up; triggers: 0..1)."""
        pad = self._pad(index)
        v = float(value)
        lo = 0.0 if axis.endswith("trigger") else -1.0
        if not lo <= v <= 1.0:  # NaN fails too
            raise ValidationError(f"gamepad {index} axis {axis!r}: {value!r} not in [{lo}, 1]")
        pad.axes[_check_axis(axis)] = v
        if axis.endswith("trigger"):  # the trigger as a button
            held = (index, axis) in self._pads.held
            if not held and v >= TRIGGER_DOWN:
                self.pad_press(index, axis)
            elif held and v < TRIGGER_UP:
                self.pad_release(index, axis)

    # -- touch -------------------------------------------------------------------------
    def touches(self) -> list[TouchPoint]:
        """The fingers down now and those lifted this frame (phase "ended"), by id."""
        if self._off:
            return []
        t = self.touch
        down = [f.point(f.phase) for f in t.fingers.values()]
        return sorted(down + t.ended, key=lambda p: p.id)

    def gesture_held(self, gesture: str) -> bool:
        """Is ``gesture`` (drag, pinch, rotate) going on? (Taps are never held.)"""
        return _check_gesture(gesture) in self._gestures.down_now(self._off)

    def gesture_pressed(self, gesture: str) -> bool:
        """Did ``gesture`` begin (a tap: happen) this frame, or this fixed step inside one?"""
        return _check_gesture(gesture) in self._gestures.edges(self._view)[0]

    def gesture_released(self, gesture: str) -> bool:
        return _check_gesture(gesture) in self._gestures.edges(self._view)[1]

    def drag_delta(self, world: bool = False) -> Vec2:
        """How far the dragging fingers' centre moved this frame: pixels, or metres."""
        if self._off:
            return (0.0, 0.0)
        return self.touch.drag_delta_world if world else self.touch.drag_delta

    def pinch_scale(self) -> float:
        """This frame's pinch factor (1 when none): ``camera.zoom *= inp.pinch_scale()``."""
        return 1.0 if self._off else self.touch.pinch

    def rotation_delta(self) -> float:
        """Radians two fingers turned this frame, counter-clockwise (0 when none)."""
        return 0.0 if self._off else self.touch.rotation

    def touch_down(self, id: int, at: Vec2) -> None:
        """Finger ``id`` touches screen pixel ``at`` (origin bottom-left)."""
        self.touch.down(_touch_id(id, "touch_down"), vec2(at, "Input.touch_down", "at"))

    def touch_move(self, id: int, at: Vec2) -> None:
        self.touch.move(_touch_id(id, "touch_move"), vec2(at, "Input.touch_move", "at"))

    def touch_up(self, id: int, at: Vec2 | None = None) -> None:
        """Finger ``id`` lifts (at screen pixel ``at``, or where it last was)."""
        point = None if at is None else vec2(at, "Input.touch_up", "at")
        self.touch.up(_touch_id(id, "touch_up"), point)

    def _emulate_touch(self, kind: str, button: int) -> None:
        if not boolean(self.emulate_touch_from_mouse, "Input", "emulate_touch_from_mouse"):
            return
        down = MOUSE_TOUCH_ID in self.touch.fingers
        if kind == "move" and down:
            self.touch.move(MOUSE_TOUCH_ID, self.mouse_screen)
        elif button == Mouse.LEFT and kind == "down" and not down:
            self.touch.down(MOUSE_TOUCH_ID, self.mouse_screen)
        elif button == Mouse.LEFT and kind == "up" and down:
            self.touch.up(MOUSE_TOUCH_ID, self.mouse_screen)

    # -- feeding (window events or tests) ----------------------------------------------
    def press(self, key: int, modifiers: int = 0) -> None:
        """A key goes down (a repeat while held is not a new press)."""
        _check_code(key, "press", "key", "Key.SPACE")
        self.modifiers = integer(modifiers, "Input.press", "modifiers")
        if self._keys.down(key):
            self.events.append(KeyEvent(key, True, modifiers))

    def release(self, key: int, modifiers: int = 0) -> None:
        _check_code(key, "release", "key", "Key.SPACE")
        self.modifiers = integer(modifiers, "Input.release", "modifiers")
        if self._keys.up(key):
            self.events.append(KeyEvent(key, False, modifiers))

    def repeat_key(self, key: int, modifiers: int = 0) -> None:
        """The system's auto-repeat of a held key (a held Backspace deleting on)."""
        _check_code(key, "repeat_key", "key", "Key.BACKSPACE")
        if key in self._keys.held:
            self.events.append(KeyEvent(key, True, integer(modifiers, "Input.repeat_key",
                                                           "modifiers"), repeat=True))

    def compose(self, text: str, caret: int = -1) -> None:
        """An input method's composition (preedit) text changed; ``""`` ends it."""
        if not isinstance(text, str):
            raise ValidationError(f"Input.compose needs a str, got {type(text).__name__}")
        caret = integer(caret, "Input.compose", "caret")
        self.events.append(CompositionEvent(text, caret if caret >= 0 else len(text)))

    def type_text(self, text: str) -> None:
        """Characters typed (the window's ``on_text``; tests type with it too)."""
        if not isinstance(text, str):
            raise ValidationError(f"Input.type_text needs a str, got {type(text).__name__}")
        if text:
            self.text += text
            self.events.append(TextEvent(text))

    def move_mouse(self, x: float, y: float) -> None:
        """The pointer moves to screen pixel (x, y) (origin bottom-left)."""
        self.mouse_screen = (finite(x, "Input.move_mouse", "x"), finite(y, "Input.move_mouse", "y"))
        self.mouse_world = self.screen_to_world(self.mouse_screen)
        self.events.append(
            MouseEvent("move", 0, self.mouse_screen, self.mouse_world, modifiers=self.modifiers)
        )
        self._emulate_touch("move", 0)

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
        if kind == "down":
            self._buttons.down(button)
        else:
            self._buttons.up(button)
        self.events.append(
            MouseEvent(kind, button, self.mouse_screen, self.mouse_world, modifiers=modifiers)
        )
        self._emulate_touch(kind, button)

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

    def consume_mouse(self, kinds: tuple[str, ...] = ("down", "up", "scroll")) -> None:
        """Keep this frame's mouse button and wheel events from the game (the UI took them).

        The presses vanish from ``mouse_pressed`` (frame and fixed step) and the events
        from :attr:`events`, so ``on_mouse_down`` hooks do not see them either.
        """
        kept: list[AnyEvent] = []
        for ev in self.events:
            if isinstance(ev, MouseEvent) and ev.kind in kinds:
                if ev.kind == "down":
                    self._buttons.forget(ev.button)
                elif ev.kind == "scroll":
                    self.scroll = (0.0, 0.0)
                continue
            kept.append(ev)
        self.events[:] = kept

    def consume_keys(self, *keys: int) -> None:
        """Keep these key presses from the game (a focused widget used them)."""
        drop = set(keys)
        for k in keys:
            self._keys.forget(k)
        self.events[:] = [
            ev for ev in self.events if not (isinstance(ev, KeyEvent) and ev.key in drop)
        ]

    def consume_text(self) -> None:
        """Keep this frame's typed text from the game (a focused text field took it)."""
        self.text = ""
        self.events[:] = [ev for ev in self.events if not isinstance(ev, TextEvent)]

    @property
    def _families(self) -> tuple[_Edges, ...]:
        return (self._keys, self._buttons, self._pads, self._gestures)

    @property
    def _view(self) -> bool | None:
        """Which edges queries see: fixed step (True), frame (False), none (muted)."""
        return None if self._off else self._fixed

    @property
    def _off(self) -> bool:
        return self._muted or self._captured

    @property
    def captured(self) -> bool:
        """True when :meth:`capture` hid the input from the game for this frame."""
        return self._captured

    def capture(self) -> None:
        """Hide every key, button and axis from the game until this frame ends (the
        in-game console, a modal debug view): queries answer "nothing", edges included.

        >>> from kge.keys import Key
        >>> inp = Input(); inp.press(Key.A); inp.capture()
        >>> inp.held(Key.A), inp.pressed(Key.A)
        (False, False)
        >>> inp.end_frame(); inp.held(Key.A)
        True
        """
        self._captured = True

    @contextmanager
    def muted(self, on: bool = True) -> Iterator[None]:
        """Inside, every query answers "nothing" (a scene running below an overlay)."""
        was, self._muted = self._muted, self._muted or on
        try:
            yield
        finally:
            self._muted = was

    # -- the App's clock -----------------------------------------------------------------
    def begin_step(self) -> None:
        """A fixed step starts: its queries see the edges since the previous step began."""
        for edges in self._families:
            edges.begin_step()
        self._fixed = True

    def end_step(self) -> None:
        """The fixed step ended: those edges are spent for fixed-step code."""
        for edges in self._families:
            edges.end_step()
        self._fixed = False

    def end_frame(self) -> None:
        """Forget this frame's edges, events, text and scroll (the App calls it)."""
        self._fixed = False
        self._captured = False
        for edges in self._families:
            edges.end_frame()
        self.touch.end_frame()
        self.scroll = (0.0, 0.0)
        self.text = ""
        self.events.clear()

    def reset(self) -> None:
        """Release everything (a scene change or a lost window focus)."""
        for edges in self._families:
            edges.reset()
        self.touch.reset()
        self._fixed = False
        self._captured = False
        self.scroll = (0.0, 0.0)
        self.text = ""
        self.events.clear()
