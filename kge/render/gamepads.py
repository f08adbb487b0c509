"""Real gamepads: pyglet's controller API feeding the :class:`~kge.input.Input` resource.

:class:`GamepadBridge` opens every controller pyglet knows, follows hot-plug through
pyglet's ``ControllerManager`` (``on_connect`` / ``on_disconnect``), and turns
controller events into ``Input.pad_press`` / ``pad_release`` / ``pad_axis`` calls:

* buttons keep pyglet's names (``"a"``, ``"start"``, ``"leftshoulder"``...);
* the d-pad (a vector in pyglet) becomes the four buttons ``dpleft`` ... ``dpdown``;
* sticks become ``leftx``/``lefty``/``rightx``/``righty`` with y **up**, triggers
  ``lefttrigger``/``righttrigger`` in [0, 1];
* ``Gamepad.rumble`` calls pyglet's ``rumble_play_weak`` / ``rumble_play_strong``.

Only the window imports this module (lazily); it needs no GL. The bridge's handlers
take any object with pyglet's Controller interface, so tests drive it with a stand-in.
"""

from __future__ import annotations

import contextlib
from typing import Any

from kge.input import PAD_BUTTONS, Input

#: pyglet sends the d-pad as a vector, not as buttons; the trigger buttons follow the
#: trigger axes (Input.pad_axis), never a button event
_BUTTONS = PAD_BUTTONS - {"dpleft", "dpright", "dpup", "dpdown", "lefttrigger", "righttrigger"}
_DPAD = (("dpleft", 0, -1.0), ("dpright", 0, 1.0), ("dpdown", 1, -1.0), ("dpup", 1, 1.0))


class GamepadBridge:
    """Connects pyglet controllers to one Input (see the module docstring)."""

    def __init__(self, input: Input) -> None:
        self.input = input
        self.slots: dict[int, int] = {}  # id(controller) -> Input gamepad index
        self.manager: Any = None

    def start(self) -> int:
        """Open the controllers present now and follow hot-plug; returns how many opened."""
        try:
            import pyglet.input

            self.manager = pyglet.input.ControllerManager()
        except Exception:  # no controller backend on this platform: keyboard and mouse only
            return 0
        self.manager.push_handlers(on_connect=self.connect, on_disconnect=self.disconnect)
        for controller in self.manager.get_controllers():
            self.connect(controller)
        return len(self.slots)

    def connect(self, controller: Any) -> None:
        if id(controller) in self.slots:
            return
        with contextlib.suppress(Exception):  # already open, or gone since it was listed
            controller.open()

        def rumble(weak: float, strong: float, duration: float) -> None:
            if weak > 0:
                controller.rumble_play_weak(weak, duration)
            if strong > 0:
                controller.rumble_play_strong(strong, duration)

        pad = self.input.connect_gamepad(getattr(controller, "name", None) or "gamepad", rumble)
        self.slots[id(controller)] = pad.index
        controller.push_handlers(**self._handlers())

    def _handlers(self) -> dict[str, Any]:
        return {
            "on_button_press": self.on_button_press,
            "on_button_release": self.on_button_release,
            "on_stick_motion": self.on_stick_motion,
            "on_trigger_motion": self.on_trigger_motion,
            "on_dpad_motion": self.on_dpad_motion,
        }

    def disconnect(self, controller: Any) -> None:
        index = self.slots.pop(id(controller), None)
        if index is not None and index in self.input.gamepads:
            self.input.disconnect_gamepad(index)
        with contextlib.suppress(Exception):
            controller.remove_handlers(**self._handlers())

    def stop(self) -> None:
        for index in list(self.slots.values()):
            if index in self.input.gamepads:
                self.input.disconnect_gamepad(index)
        self.slots.clear()

    # -- controller events ------------------------------------------------------------------
    def _index(self, controller: Any) -> int | None:
        return self.slots.get(id(controller))

    def on_button_press(self, controller: Any, button: str) -> None:
        index = self._index(controller)
        if index is not None and button in _BUTTONS:
            self.input.pad_press(index, button)

    def on_button_release(self, controller: Any, button: str) -> None:
        index = self._index(controller)
        if index is not None and button in _BUTTONS:
            self.input.pad_release(index, button)

    def on_stick_motion(self, controller: Any, stick: str, vector: Any) -> None:
        index = self._index(controller)
        side = "left" if stick.startswith("left") else "right"
        if index is not None:
            self.input.pad_axis(index, f"{side}x", _clamp(vector[0], -1.0))
            self.input.pad_axis(index, f"{side}y", _clamp(vector[1], -1.0))

    def on_trigger_motion(self, controller: Any, trigger: str, value: float) -> None:
        index = self._index(controller)
        if index is not None and trigger in ("lefttrigger", "righttrigger"):
            self.input.pad_axis(index, trigger, _clamp(value, 0.0))

    def on_dpad_motion(self, controller: Any, vector: Any) -> None:
        index = self._index(controller)
        if index is None:
            return
        for name, component, sign in _DPAD:
            if float(vector[component]) * sign > 0.5:
                self.input.pad_press(index, name)
            else:
                self.input.pad_release(index, name)


def _clamp(value: float, lo: float) -> float:
    v = float(value)
    return 0.0 if v != v else max(lo, min(1.0, v))  # NaN from a flaky driver reads as rest
