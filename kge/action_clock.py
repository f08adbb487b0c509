"""Actions over time: hold duration, double taps, input buffering, combos and events.

:class:`~kge.actions.InputMap` answers "is jump held / pressed now?"; this module
adds what needs a clock. The App advances it once per frame by the frame's *real*
time (a double tap is as quick in slow motion as at full speed, and a paused game
still sees it), then emits one :class:`ActionPressed` / :class:`ActionReleased` per
edge into the top scene's world (``world.events(ActionPressed)``) and calls the
hooks added with ``InputMap.on_pressed`` / ``on_released``.

>>> from kge.input import Input
>>> from kge.keys import Key
>>> from kge.actions import InputMap
>>> inp = Input(); actions = InputMap(inp)
>>> actions.bind("dash", Key.D)
>>> inp.press(Key.D); actions.update(0.016); inp.end_frame()
>>> inp.release(Key.D); actions.update(0.1); inp.end_frame()
>>> inp.press(Key.D); actions.update(0.1)
>>> actions.double_tapped("dash"), [type(e).__name__ for e in actions.frame_events]
(True, ['ActionPressed'])
"""

from __future__ import annotations

import math
from collections import deque
from collections.abc import Callable, Iterable
from dataclasses import dataclass
from typing import Any

from kge.errors import ValidationError

#: two presses at most this many seconds apart are a double tap (``InputMap.tap_window``)
TAP_WINDOW = 0.3
#: a press stays buffered this long by default (``InputMap.buffered``)
BUFFER_WINDOW = 0.15


@dataclass(slots=True, frozen=True)
class ActionPressed:
    """An action (or a completed combo) went down this frame.

    ``taps``: 1 for a single press, 2 for a double tap (within ``tap_window`` of the
    previous press), 3 for a triple tap...
    """

    action: str
    time: float  #: the action clock's time (real seconds since the App started)
    taps: int = 1


@dataclass(slots=True, frozen=True)
class ActionReleased:
    """An action went up this frame after being held ``held_for`` seconds."""

    action: str
    time: float
    held_for: float


@dataclass(slots=True, frozen=True)
class Combo:
    """Actions pressed in this order, all within ``within`` seconds."""

    steps: tuple[str, ...]
    within: float


class _State:
    __slots__ = ("buffered_at", "down_since", "last_press", "taps")

    def __init__(self) -> None:
        self.down_since: float | None = None
        self.last_press = -math.inf
        self.taps = 0
        self.buffered_at: float | None = None


Hook = Callable[[Any], None]


class ActionClock:
    """The per-action timing state of one InputMap (it owns one; see the module)."""

    def __init__(self) -> None:
        self.now = 0.0
        self.tap_window = TAP_WINDOW
        self.states: dict[str, _State] = {}
        self.combos: dict[str, Combo] = {}
        self.completed: set[str] = set()  #: combos completed this frame
        self.pressed_now: set[str] = set()
        self.events: list[ActionPressed | ActionReleased] = []
        self.hooks: dict[tuple[str, str], list[Hook]] = {}
        self._history: deque[tuple[float, str]] = deque(maxlen=64)

    def state(self, action: str) -> _State:
        found = self.states.get(action)
        if found is None:
            found = self.states[action] = _State()
        return found

    def update(self, dt: float, actions: Iterable[str], edge: Callable[[str, str], bool]) -> None:
        """Advance by ``dt`` real seconds and record this frame's edges of ``actions``
        (``edge(action, "pressed" | "released" | "held")`` reads the map)."""
        self.now += max(float(dt), 0.0) if math.isfinite(dt) else 0.0
        now = self.now
        self.events = []
        self.pressed_now = set()
        self.completed = set()
        combo_steps = {s for c in self.combos.values() for s in c.steps}
        for action in actions:
            st = self.state(action)
            if edge(action, "released") and st.down_since is not None:
                self.events.append(ActionReleased(action, now, now - st.down_since))
                st.down_since = None
            if edge(action, "pressed"):
                st.taps = st.taps + 1 if now - st.last_press <= self.tap_window else 1
                st.last_press = st.buffered_at = now
                st.down_since = now
                self.pressed_now.add(action)
                self.events.append(ActionPressed(action, now, st.taps))
                if action in combo_steps:
                    self._history.append((now, action))
            held = edge(action, "held")
            if held and st.down_since is None:
                st.down_since = now  # held before the map knew the action
            elif not held and st.down_since is not None and action not in self.pressed_now:
                self.events.append(ActionReleased(action, now, now - st.down_since))
                st.down_since = None
        self._match_combos(now)

    def _match_combos(self, now: float) -> None:
        for name, combo in self.combos.items():
            if combo.steps[-1] not in self.pressed_now:
                continue
            mine = [(t, a) for t, a in self._history if a in combo.steps]
            tail = mine[-len(combo.steps) :]
            if tuple(a for _, a in tail) == combo.steps and now - tail[0][0] <= combo.within:
                self.completed.add(name)
                self.events.append(ActionPressed(name, now))
                self._history.clear()  # one sequence completes one combo

    def held_for(self, action: str) -> float:
        st = self.states.get(action)
        return 0.0 if st is None or st.down_since is None else self.now - st.down_since

    def buffered(self, action: str, window: float) -> bool:
        st = self.states.get(action)
        return st is not None and st.buffered_at is not None and self.now - st.buffered_at <= window

    def consume(self, action: str) -> None:
        st = self.states.get(action)
        if st is not None:
            st.buffered_at = None

    def add_hook(self, action: str, which: str, fn: Hook) -> None:
        if not callable(fn):
            raise ValidationError(f"InputMap.on_{which}({action!r}): needs a function, got {fn!r}")
        self.hooks.setdefault((action, which), []).append(fn)

    def remove_hook(self, action: str, which: str, fn: Hook) -> None:
        found = self.hooks.get((action, which), [])
        if fn in found:
            found.remove(fn)

    def deliver(self, emit: Callable[[Any], None]) -> None:
        """Emit this frame's events (into a world) and call their hooks, in order."""
        for ev in self.events:
            emit(ev)
            which = "pressed" if isinstance(ev, ActionPressed) else "released"
            for fn in list(self.hooks.get((ev.action, which), ())):
                fn(ev)

    def reset(self) -> None:
        """Forget holds, taps and buffers (the scene changed: input starts fresh)."""
        self.states.clear()
        self._history.clear()
        self.events = []
        self.pressed_now = set()
        self.completed = set()


def check_window(value: Any, what: str) -> float:
    """A time window in seconds: finite and >= 0."""
    try:
        v = float(value)
    except (TypeError, ValueError):
        raise ValidationError(f"{what} must be seconds (a number), got {value!r}") from None
    if not math.isfinite(v) or v < 0:
        raise ValidationError(f"{what} must be finite seconds >= 0, got {value!r}")
    return v
