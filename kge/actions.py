"""``InputMap``: named actions bound to keys, mouse buttons and gamepads.

Game code asks for *actions* ("jump", "move_x") instead of keys, so players can
rebind them and a gamepad works beside the keyboard with no extra code (the model:
Godot's InputMap, Arcade's InputManager). The App owns one map, shared by all its
scenes, as the ``InputMap`` resource (``app.actions``).

Bindings are written as short strings, so they save and load as plain data:

=====================  =====================================================
``"key:SPACE"``        a key, by its :class:`kge.keys.Key` name (or a key code int)
``"key:CTRL+S"``       a chord: the key while CTRL is held (CTRL, SHIFT, ALT,
                       META, COMMAND; either side; ``"key:CTRL+SHIFT+Z"``)
``"mouse:LEFT"``       a mouse button (LEFT, MIDDLE, RIGHT); ``"mouse:SHIFT+LEFT"``
``"pad:a"``            a gamepad button on any pad; ``"pad1:a"`` on pad 1 only
``"pad:lefttrigger"``  a trigger as a button: down past 0.5, up again under 0.4
``"pad:leftx"``        a gamepad axis (only in axes); ``"pad:lefty"`` is up-positive
``"touch:tap"``        a gesture (tap, double_tap, drag, pinch, rotate; :mod:`kge.touch`)
=====================  =====================================================

>>> from kge.input import Input
>>> from kge.keys import Key
>>> inp = Input()
>>> actions = InputMap(inp)
>>> actions.bind("jump", Key.SPACE, "pad:a")
>>> actions.bind_axis("move_x", negative=["key:A"], positive=["key:D"], stick="pad:leftx")
>>> actions.bind_axis("move_y", negative=["key:S"], positive=["key:W"], stick="pad:lefty")
>>> actions.bind_vector("move", "move_x", "move_y")
>>> inp.press(Key.SPACE); inp.press(Key.D)
>>> actions.pressed("jump"), actions.axis("move_x"), actions.vector("move")
(True, 1.0, (1.0, 0.0))
>>> actions.to_data()["actions"]
{'jump': ['key:SPACE', 'pad:a']}

Every query reads :class:`~kge.input.Input`, so action edges follow its rule: once
per frame for update code, once per fixed step for fixed-step code. What needs a
clock (``held_for``, ``double_tapped``, ``buffered``, combos, the ``ActionPressed``
and ``ActionReleased`` events and ``on_pressed`` hooks) is in :mod:`kge.action_clock`.
"""

from __future__ import annotations

import difflib
import json
import math
import os
from collections.abc import Callable, Iterable
from dataclasses import dataclass
from typing import Any

from kge.action_clock import BUFFER_WINDOW, ActionClock, Combo, Hook, check_window
from kge.errors import KgeError, ValidationError
from kge.input import PAD_AXES, PAD_BUTTONS, Input
from kge.keys import Key, Mouse, key_name
from kge.touch import GESTURES

BindingLike = int | str
#: what :meth:`InputMap.declare` takes
Bindings = dict[str, Any] | str | os.PathLike[str] | Callable[["InputMap"], None]


class UnknownActionError(KgeError, KeyError):
    """An action (or axis, or vector) name that the map does not have."""

    def __str__(self) -> str:
        return str(self.args[0]) if self.args else ""


_KEY_CODES: dict[str, int] = {n: v for n, v in vars(Key).items() if not n.startswith("__")}
_MOUSE_CODES: dict[str, int] = {"LEFT": Mouse.LEFT, "MIDDLE": Mouse.MIDDLE, "RIGHT": Mouse.RIGHT}
#: chord modifiers, in the order a binding string names them: (left key, right key)
MODIFIERS: dict[str, tuple[int, int]] = {
    "CTRL": (Key.LCTRL, Key.RCTRL),
    "SHIFT": (Key.LSHIFT, Key.RSHIFT),
    "ALT": (Key.LALT, Key.RALT),
    "META": (Key.LMETA, Key.RMETA),
    "COMMAND": (Key.LCOMMAND, Key.RCOMMAND),
}


@dataclass(slots=True, frozen=True)
class Binding:
    """One physical input: ``kind`` is "key", "mouse", "pad" (button), "axis" or "touch"
    (a gesture)."""

    kind: str
    code: int | str
    pad: int | None = None  #: gamepad index, None for any pad
    mods: tuple[str, ...] = ()  #: chord modifiers held with a key or mouse button

    def __str__(self) -> str:
        chord = "".join(f"{m}+" for m in self.mods)
        if self.kind == "key":
            return f"key:{chord}{key_name(int(self.code))}"
        if self.kind == "mouse":
            name = next(n for n, v in _MOUSE_CODES.items() if v == self.code)
            return f"mouse:{chord}{name}"
        if self.kind == "touch":
            return f"touch:{self.code}"
        return f"pad{'' if self.pad is None else self.pad}:{self.code}"


def _chord(value: str, kind: str, name: str) -> tuple[tuple[str, ...], str]:
    """``"CTRL+SHIFT+S"`` -> (("CTRL", "SHIFT"), "S"); modifiers checked and ordered."""
    *mods, last = name.split("+")
    seen = []
    for m in mods:
        if m.upper() not in MODIFIERS:
            raise ValidationError(
                f"binding {value!r}: unknown modifier {m!r}; modifiers are "
                f"{', '.join(MODIFIERS)} (as in 'key:CTRL+S')"
            )
        seen.append(m.upper())
    if not last:
        raise ValidationError(f"binding {value!r}: a chord ends with a {kind} ('key:CTRL+S')")
    return tuple(m for m in MODIFIERS if m in seen), last


def parse_binding(value: BindingLike | Binding, *, axis: bool = False) -> Binding:
    """A :class:`Binding` from a key code or a binding string; clear errors otherwise."""
    if isinstance(value, Binding):
        return value
    if isinstance(value, bool) or not isinstance(value, (int, str)):
        raise ValidationError(
            f"a binding is a key code or a string like 'key:SPACE', got {value!r}"
        )
    if isinstance(value, int):
        if key_name(value) == str(value):
            raise ValidationError(f"unknown key code {value} (use kge.Key names, e.g. Key.SPACE)")
        return Binding("key", value)
    kind, sep, name = value.partition(":")
    if not sep or not name:
        raise ValidationError(
            f"binding {value!r} must look like 'key:SPACE', 'mouse:LEFT', 'pad:a' or 'pad:leftx'"
        )
    mods: tuple[str, ...] = ()
    if kind in ("key", "mouse") and "+" in name:
        mods, name = _chord(value, kind, name)
    if kind == "key":
        code = _KEY_CODES.get(name.upper() if len(name) > 1 or name.isalpha() else name)
        if code is None:
            code = _KEY_CODES.get(f"_{name}")  # digits: "key:1"
        if code is None:
            near = difflib.get_close_matches(name.upper(), _KEY_CODES, n=1)
            hint = f" (did you mean {near[0]!r}?)" if near else ""
            raise ValidationError(f"binding {value!r}: unknown key {name!r}{hint}")
        return Binding("key", code, mods=mods)
    if kind == "mouse":
        if name.upper() not in _MOUSE_CODES:
            raise ValidationError(f"binding {value!r}: mouse buttons are LEFT, MIDDLE, RIGHT")
        return Binding("mouse", _MOUSE_CODES[name.upper()], mods=mods)
    if kind.startswith("pad"):
        index = kind[3:]
        if index and not index.isdigit():
            raise ValidationError(f"binding {value!r}: a pad index is a number ('pad1:a')")
        pad = int(index) if index else None
        if axis and name in PAD_AXES:
            return Binding("axis", name, pad)
        if name in PAD_BUTTONS:
            return Binding("pad", name, pad)
        allowed = sorted(PAD_AXES if axis else PAD_BUTTONS)
        raise ValidationError(f"binding {value!r}: unknown gamepad {'axis' if axis else 'button'} "
                              f"{name!r}; expected one of {', '.join(allowed)}")  # fmt: skip
    if kind == "touch":
        if name not in GESTURES:
            raise ValidationError(
                f"binding {value!r}: unknown gesture {name!r}; gestures are {', '.join(GESTURES)}"
            )
        return Binding("touch", name)
    raise ValidationError(f"binding {value!r}: kind must be key, mouse, pad or touch, got {kind!r}")


@dataclass(slots=True, frozen=True)
class AxisBinding:
    """An axis in [-1, 1]: keys/buttons pushing each way plus analogue sticks or triggers."""

    negative: tuple[Binding, ...] = ()
    positive: tuple[Binding, ...] = ()
    sticks: tuple[Binding, ...] = ()
    dead_zone: float = 0.2
    invert: bool = False


#: the parts of :meth:`InputMap.to_data`, in order
_PARTS = ("actions", "axes", "vectors", "combos")


class InputMap:
    """Named actions, axes and vectors over an :class:`~kge.input.Input` (module docstring)."""

    def __init__(self, input: Input) -> None:
        self.input = input
        self._actions: dict[str, tuple[Binding, ...]] = {}
        self._axes: dict[str, AxisBinding] = {}
        self._vectors: dict[str, tuple[str, str, float | None]] = {}
        self.clock = ActionClock()  #: holds, taps, buffers and combos (kge.action_clock)

    # -- binding ------------------------------------------------------------------------
    def bind(self, action: str, *bindings: BindingLike | Binding) -> None:
        """Add bindings to ``action`` (created if new). All are checked before any is added."""
        name = _name(action, "action")
        parsed = tuple(parse_binding(b) for b in bindings)
        old = self._actions.get(name, ())
        self._actions[name] = old + tuple(b for b in parsed if b not in old)

    def rebind(self, action: str, *bindings: BindingLike | Binding) -> None:
        """Replace every binding of an existing action (a settings menu)."""
        self._require(action, self._actions, "action")
        parsed = tuple(parse_binding(b) for b in bindings)
        self._actions[action] = tuple(dict.fromkeys(parsed))

    def unbind(self, action: str, binding: BindingLike | Binding) -> None:
        self._require(action, self._actions, "action")
        b = parse_binding(binding)
        self._actions[action] = tuple(x for x in self._actions[action] if x != b)

    def bindings(self, action: str) -> list[str]:
        """The bindings of ``action`` as strings (``["key:SPACE", "pad:a"]``)."""
        return [str(b) for b in self._require(action, self._actions, "action")]

    def rebind_from_input(self, action: str, *, keep_pad: bool = True) -> str | None:
        """Bind ``action`` to the key or button pressed this frame, if any ("press a key...").

        Returns the new binding's string, or None when nothing was pressed. Keyboard and
        mouse bindings are replaced; gamepad bindings stay when ``keep_pad``.
        """
        self._require(action, self._actions, "action")
        new: Binding | None = None
        keys = self.input.keys_pressed()
        if keys and key_name(keys[0]) != str(keys[0]):
            new = Binding("key", keys[0])
        else:
            for code in _MOUSE_CODES.values():
                if self.input.mouse_pressed(code):
                    new = Binding("mouse", code)
                    break
        if new is None:
            return None
        kept = [b for b in self._actions[action] if keep_pad and b.kind == "pad"]
        self._actions[action] = (new, *kept)
        return str(new)

    def bind_axis(
        self,
        axis: str,
        *,
        negative: Iterable[BindingLike | Binding] = (),
        positive: Iterable[BindingLike | Binding] = (),
        stick: BindingLike | Binding | Iterable[BindingLike | Binding] = (),
        dead_zone: float = 0.2,
        invert: bool = False,
    ) -> None:
        """Define (or replace) an axis from button pairs and analogue axes with a dead zone."""
        name = _name(axis, "axis")
        dz = float(dead_zone)
        if not 0.0 <= dz < 1.0:
            raise ValidationError(f"axis {axis!r}: dead_zone must be in [0, 1), got {dead_zone!r}")
        sticks_in = [stick] if isinstance(stick, (str, int, Binding)) else list(stick)
        sticks = tuple(parse_binding(s, axis=True) for s in sticks_in)
        for s in sticks:
            if s.kind != "axis":
                raise ValidationError(f"axis {axis!r}: stick {str(s)!r} is not a gamepad axis")
        self._axes[name] = AxisBinding(
            tuple(parse_binding(b) for b in negative),
            tuple(parse_binding(b) for b in positive),
            sticks,
            dz,
            bool(invert),
        )

    def bind_vector(
        self, vector: str, x_axis: str, y_axis: str, *, dead_zone: float | None = None
    ) -> None:
        """A 2D vector made of two axes (its length is capped at 1).

        With ``dead_zone`` the sticks' dead zone is *radial*: the stick's (x, y) is
        zero inside a circle of that radius and rescaled outside it, so a diagonal
        push is not cut to a cross shape as per-axis dead zones cut it; the axes'
        own dead zones are then not used for their sticks.
        """
        name = _name(vector, "vector")
        self._require(x_axis, self._axes, "axis")
        self._require(y_axis, self._axes, "axis")
        dz = None
        if dead_zone is not None:
            dz = float(dead_zone)
            if not 0.0 <= dz < 1.0:
                raise ValidationError(
                    f"vector {vector!r}: dead_zone must be in [0, 1), got {dead_zone!r}"
                )
        self._vectors[name] = (x_axis, y_axis, dz)

    def bind_combo(self, combo: str, *steps: str, within: float = 0.5) -> None:
        """A combo: the actions ``steps`` pressed in this order, all within ``within``
        seconds (presses of other actions in between do not break it). Read it with
        :meth:`combo` or as an ``ActionPressed`` event named ``combo``."""
        name = _name(combo, "combo")
        if len(steps) < 2:
            raise ValidationError(f"combo {combo!r}: needs two or more actions, got {steps!r}")
        for s in steps:
            self._require(s, self._actions, "action")
        if name in self._actions:
            raise ValidationError(f"combo {combo!r}: an action has that name")
        w = check_window(within, f"combo {combo!r}: within")
        if w <= 0:
            raise ValidationError(f"combo {combo!r}: within must be > 0, got {within!r}")
        self.clock.combos[name] = Combo(tuple(steps), w)

    # -- queries -------------------------------------------------------------------------
    def pressed(self, action: str) -> bool:
        """Did any binding of ``action`` go down (this frame / this fixed step)?"""
        return self._any(action, "pressed")

    def released(self, action: str) -> bool:
        return self._any(action, "released")

    def held(self, action: str) -> bool:
        return self._any(action, "held")

    def _any(self, action: str, which: str) -> bool:
        return any(self._edge(b, which) for b in self._require(action, self._actions, "action"))

    def axis(self, axis: str) -> float:
        """The axis value in [-1, 1]: buttons give ±1, sticks are rescaled past the dead zone."""
        a = self._require(axis, self._axes, "axis")
        value = self._buttons_value(a)
        for s in a.sticks:
            raw = self.input.pad_axis_value(str(s.code), s.pad)
            mag = abs(raw)
            if mag > a.dead_zone:
                value += math.copysign((mag - a.dead_zone) / (1.0 - a.dead_zone), raw)
        value = max(-1.0, min(1.0, value))
        return -value if a.invert else value

    def _buttons_value(self, a: AxisBinding) -> float:
        return float(any(self._edge(b, "held") for b in a.positive)) - float(
            any(self._edge(b, "held") for b in a.negative)
        )

    def _stick_raw(self, a: AxisBinding) -> float:
        return max(-1.0, min(1.0, sum(
            self.input.pad_axis_value(str(s.code), s.pad) for s in a.sticks
        )))  # fmt: skip

    def vector(self, vector: str) -> tuple[float, float]:
        """``(axis(x), axis(y))`` with its length capped at 1 (diagonals are not faster)."""
        xa, ya, dz = self._require(vector, self._vectors, "vector")
        if dz is None:
            x, y = self.axis(xa), self.axis(ya)
        else:
            ax, ay = self._axes[xa], self._axes[ya]
            sx, sy = self._stick_raw(ax), self._stick_raw(ay)
            mag = min(math.hypot(sx, sy), 1.0)
            scale = 0.0 if mag <= dz else (mag - dz) / (1.0 - dz) / math.hypot(sx, sy)
            x = max(-1.0, min(1.0, self._buttons_value(ax) + sx * scale))
            y = max(-1.0, min(1.0, self._buttons_value(ay) + sy * scale))
            x, y = (-x if ax.invert else x), (-y if ay.invert else y)
        n = math.hypot(x, y)
        return (x / n, y / n) if n > 1.0 else (x, y)

    # -- over time (kge.action_clock) ----------------------------------------------------
    def update(self, dt: float) -> None:
        """Advance the action clock by ``dt`` real seconds and record this frame's edges
        (the App calls it at the start of every frame)."""
        self.clock.update(dt, list(self._actions), self._edge_of)

    def _edge_of(self, action: str, which: str) -> bool:
        return self._any(action, which)

    @property
    def frame_events(self) -> list[Any]:
        """This frame's ``ActionPressed`` / ``ActionReleased`` events, in order."""
        return list(self.clock.events)

    def held_for(self, action: str) -> float:
        """How long ``action`` has been held, in real seconds (0 when it is up)."""
        self._require(action, self._actions, "action")
        return self.clock.held_for(action)

    def double_tapped(self, action: str) -> bool:
        """Was ``action`` pressed this frame within ``tap_window`` of its last press?"""
        self._require(action, self._actions, "action")
        st = self.clock.states.get(action)
        return action in self.clock.pressed_now and st is not None and st.taps >= 2

    @property
    def tap_window(self) -> float:
        """Seconds between two presses that make a double tap (0.3 by default)."""
        return self.clock.tap_window

    @tap_window.setter
    def tap_window(self, value: float) -> None:
        self.clock.tap_window = check_window(value, "InputMap.tap_window")

    def buffered(self, action: str, window: float = BUFFER_WINDOW) -> bool:
        """Was ``action`` pressed in the last ``window`` seconds and not yet consumed?
        (Jump pressed just before landing still jumps: check it where the jump can
        happen, then :meth:`consume` it.)"""
        self._require(action, self._actions, "action")
        return self.clock.buffered(action, check_window(window, "InputMap.buffered: window"))

    def consume(self, action: str) -> None:
        """Use up the buffered press of ``action``."""
        self._require(action, self._actions, "action")
        self.clock.consume(action)

    def combo(self, combo: str) -> bool:
        """Was the combo completed this frame?"""
        self._require(combo, self.clock.combos, "combo")
        return combo in self.clock.completed

    def on_pressed(self, action: str, fn: Hook) -> Hook:
        """Call ``fn(event)`` each time ``action`` (or a combo) goes down; returns ``fn``."""
        self._hookable(action)
        self.clock.add_hook(action, "pressed", fn)
        return fn

    def on_released(self, action: str, fn: Hook) -> Hook:
        """Call ``fn(event)`` each time ``action`` goes up (``event.held_for`` seconds)."""
        self._require(action, self._actions, "action")
        self.clock.add_hook(action, "released", fn)
        return fn

    def remove_hook(self, action: str, fn: Hook) -> None:
        for which in ("pressed", "released"):
            self.clock.remove_hook(action, which, fn)

    def _hookable(self, action: str) -> None:
        if action not in self.clock.combos:
            self._require(action, self._actions, "action")

    def _edge(self, b: Binding, which: str) -> bool:
        inp = self.input
        if b.mods and which != "released" and not all(
            inp.any_held(*MODIFIERS[m]) for m in b.mods
        ):
            return False
        if b.kind == "key":
            code = int(b.code)
            return {"held": inp.held, "pressed": inp.pressed, "released": inp.released}[which](code)
        if b.kind == "mouse":
            code = int(b.code)
            fns = {"held": inp.mouse_held, "pressed": inp.mouse_pressed}
            return fns.get(which, inp.mouse_released)(code)
        if b.kind == "touch":
            touch = {"held": inp.gesture_held, "pressed": inp.gesture_pressed}
            return touch.get(which, inp.gesture_released)(str(b.code))
        pads = {"held": inp.pad_held, "pressed": inp.pad_pressed, "released": inp.pad_released}
        return pads[which](str(b.code), b.pad)

    def _require(self, name: str, table: dict[str, Any], what: str) -> Any:
        found = table.get(name)
        if found is None:
            near = difflib.get_close_matches(str(name), list(table), n=1)
            hint = f" (did you mean {near[0]!r}?)" if near else ""
            known = ", ".join(sorted(table)) or "none"
            raise UnknownActionError(f"unknown {what} {name!r}{hint}; known: {known}")
        return found

    @property
    def actions(self) -> list[str]:
        return sorted(self._actions)

    # -- data ----------------------------------------------------------------------------
    def to_data(self) -> dict[str, Any]:
        """Every binding as JSON-ready data (what :meth:`load_data` and :meth:`save` take)."""
        return {
            "actions": {a: [str(b) for b in bs] for a, bs in self._actions.items()},
            "axes": {
                n: {
                    "negative": [str(b) for b in a.negative],
                    "positive": [str(b) for b in a.positive],
                    "sticks": [str(b) for b in a.sticks],
                    "dead_zone": a.dead_zone,
                    "invert": a.invert,
                }
                for n, a in self._axes.items()
            },
            "vectors": {
                n: [x, y] if dz is None else [x, y, dz] for n, (x, y, dz) in self._vectors.items()
            },
            "combos": {
                n: {"steps": list(c.steps), "within": c.within}
                for n, c in self.clock.combos.items()
            },
        }

    def load_data(self, data: dict[str, Any]) -> None:
        """Replace every binding with ``data``; on any error the map is left unchanged."""
        if not isinstance(data, dict):
            raise ValidationError(f"InputMap data must be a dict, got {type(data).__name__}")
        unknown = sorted(map(str, set(data) - set(_PARTS)))
        if unknown:
            raise ValidationError(
                f"InputMap data has unknown keys {unknown} (it takes {', '.join(_PARTS)})"
            )
        fresh = InputMap(self.input)
        try:
            for action, bs in dict(data.get("actions", {})).items():
                fresh.bind(action, *bs)
            for axis, spec in dict(data.get("axes", {})).items():
                fresh.bind_axis(
                    axis,
                    negative=spec.get("negative", ()),
                    positive=spec.get("positive", ()),
                    stick=spec.get("sticks", ()),
                    dead_zone=spec.get("dead_zone", 0.2),
                    invert=spec.get("invert", False),
                )
            for vec, spec in dict(data.get("vectors", {})).items():
                xa, ya, *rest = spec
                fresh.bind_vector(vec, xa, ya, dead_zone=rest[0] if rest else None)
            for combo, spec in dict(data.get("combos", {})).items():
                fresh.bind_combo(combo, *spec["steps"], within=spec.get("within", 0.5))
        except (TypeError, AttributeError, ValueError, KeyError) as exc:
            if isinstance(exc, KgeError):
                raise
            raise ValidationError(f"InputMap data is malformed: {exc}") from exc
        self._actions, self._axes, self._vectors = fresh._actions, fresh._axes, fresh._vectors
        self.clock.combos = fresh.clock.combos

    def declare(self, bindings: Bindings) -> None:
        """Add the bindings a game declares, in any of these forms (``kge.run(level,
        bindings=...)`` and ``App(..., bindings=...)`` call this):

        * ``{"jump": ["key:SPACE", "pad:a"], "move_x": {"negative": ["key:A"],
          "positive": ["key:D"], "stick": "pad:leftx"}}``: actions (a list, or one
          binding) and axes (a dict of :meth:`bind_axis`'s arguments);
        * what :meth:`to_data` returns (``{"actions": ..., "axes": ..., "vectors": ...,
          "combos": ...}``);
        * a path to a JSON file of either (what :meth:`save` writes);
        * a function ``fn(actions)`` that binds in code.

        On any error the map is left as it was.
        """
        trial = InputMap(self.input)
        trial.load_data(self.to_data())
        if callable(bindings):
            bindings(trial)
        else:
            data: Any = bindings
            if isinstance(bindings, (str, os.PathLike)):
                with open(bindings, encoding="utf-8") as f:
                    try:
                        data = json.load(f)
                    except json.JSONDecodeError as exc:
                        raise ValidationError(f"{os.fspath(bindings)}: not JSON ({exc})") from exc
            if not isinstance(data, dict):
                raise ValidationError(
                    f"bindings must be a dict, a JSON path or a function, got {type(data).__name__}"
                )
            if set(data) <= set(_PARTS) and data:
                merged = trial.to_data()
                for part in _PARTS:
                    merged[part].update(dict(data.get(part, {})))
                trial.load_data(merged)
            else:
                for name, spec in data.items():
                    if isinstance(spec, dict):
                        known = {"negative", "positive", "stick", "dead_zone", "invert"}
                        unknown = set(spec) - known
                        if unknown:
                            raise ValidationError(
                                f"axis {name!r}: unknown keys {sorted(unknown)} "
                                f"(an axis takes {', '.join(sorted(known))})"
                            )
                        trial.bind_axis(name, **spec)
                    elif isinstance(spec, (str, int)):
                        trial.bind(name, spec)
                    else:
                        trial.bind(name, *spec)
        self.load_data(trial.to_data())

    def save(self, path: str | os.PathLike[str]) -> None:
        with open(path, "w", encoding="utf-8") as f:
            json.dump(self.to_data(), f, indent=2)

    def load(self, path: str | os.PathLike[str]) -> None:
        try:
            with open(path, encoding="utf-8") as f:
                data = json.load(f)
        except json.JSONDecodeError as exc:
            raise ValidationError(f"{os.fspath(path)}: not JSON ({exc})") from exc
        except (OSError, UnicodeDecodeError) as exc:
            raise ValidationError(f"{os.fspath(path)}: cannot read the bindings ({exc})") from exc
        self.load_data(data)


def _name(name: object, what: str) -> str:
    if not isinstance(name, str) or not name:
        raise ValidationError(f"an {what} name must be a non-empty string, got {name!r}")
    return name
