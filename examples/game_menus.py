"""Menus the example games share: title menu, settings, a see-through pause, corner HUDs.

Each is a small scene built from kge UI entities (``docs/ui-scenes-input.md``):

* :func:`title_menu` — Play (fades into the game), Settings, Quit; keyboard (Tab,
  arrows, Enter), mouse and gamepad (d-pad, A) all work;
* :func:`settings` — pushed as an overlay: music and effects volume sliders, and one
  button per rebindable action ("press a key..." rebinds it through ``app.actions``);
* :func:`pause` — pushed as an overlay over the frozen game (P, Escape or Start):
  Resume, Settings, Main menu;
* :func:`hud_label` — a label anchored to a corner of the window.

A game lists its actions once (:func:`bind_defaults`); the App's ``InputMap`` keeps
them, with any rebinding, across every scene.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import kge_required  # noqa: F401  (first: names the Python to use when kge is missing)

from kge import (
    App,
    Audio,
    Behaviour,
    Button,
    ButtonClicked,
    Fade,
    InputMap,
    Label,
    Panel,
    Script,
    Slider,
    UINode,
    ValueChanged,
    World,
    focus,
)

FADE = Fade(0.4)
#: action -> default bindings; a game passes its own to bind_defaults
Bindings = dict[str, tuple[Any, ...]]


def bind_defaults(actions: InputMap, defaults: Bindings) -> None:
    """Bind each action that the map does not know yet (rebinding survives scene changes)."""
    known = set(actions.actions)
    for action, bindings in defaults.items():
        if action not in known:
            actions.bind(action, *bindings)
    if "pause" not in known:
        actions.bind("pause", "key:P", "key:ESCAPE", "pad:start")


def _column(world: World, title: str, width: float = 300, **node: Any) -> int:
    col = world.spawn(
        UINode(width=width, layout="column", padding=18, spacing=10, align="stretch", **node),
        Panel(),
    )
    world.spawn(UINode(parent=col), Label(title, size=26))
    return col


def _button(world: World, parent: int, text: str) -> int:
    return world.spawn(UINode(parent=parent, height=42), Button(text))


def _dim(world: World, alpha: int = 120) -> None:
    """A see-through full-window panel: the scene below shows, darker."""
    world.spawn(UINode(width="100%", height="100%"), Panel(color=(0, 0, 0, alpha), radius=0))


class _Buttons(Script):
    """Runs ``handlers[button text]()`` when that button is clicked."""

    def __init__(self, handlers: dict[str, Callable[[App], None]]) -> None:
        self.handlers = handlers

    def on_update(self, dt: float) -> None:
        app = self.world.resource(App)
        for ev in self.world.events(ButtonClicked):
            handler = self.handlers.get(ev.text)
            if handler is not None:
                handler(app)


def title_menu(world: World, title: str, hint: str, play: Any, rebindable: tuple[str, ...],
               hint_color: tuple[int, int, int, int] = (220, 220, 230, 255)) -> None:  # fmt: skip
    """The title screen: Play fades into ``play``; Settings opens over it; Quit."""
    col = _column(world, title, width=340)
    for text in ("Play", "Settings", "Quit"):
        _button(world, col, text)
    world.spawn(UINode(anchor="bottom", offset=(0, 24)), Label(hint, size=14, color=hint_color))
    world.spawn(Behaviour(_Buttons({
        "Play": lambda app: app.replace_scene(play, transition=FADE),
        "Settings": lambda app: app.push_scene(settings, overlay=True, rebindable=rebindable),
        "Quit": lambda app: app.quit(),
    })))  # fmt: skip


class _Volumes(Script):
    """Slider -> the App's music / effects volume."""

    def __init__(self, music: int, sfx: int) -> None:
        self.music, self.sfx = music, sfx

    def on_update(self, dt: float) -> None:
        audio = self.world.resource(Audio)
        for ev in self.world.events(ValueChanged):
            if ev.entity == self.music:
                audio.music_volume = ev.value
            elif ev.entity == self.sfx:
                audio.sfx_volume = ev.value


class _Rebind(Script):
    """Click an action's button, then press a key: the action is bound to that key."""

    def __init__(self, buttons: dict[int, str]) -> None:
        self.buttons = buttons
        self.waiting: int | None = None

    def on_update(self, dt: float) -> None:
        world = self.world
        actions = world.resource(InputMap)
        if self.waiting is not None:
            action = self.buttons[self.waiting]
            if actions.rebind_from_input(action) is not None:
                world.get(self.waiting, Button).text = _binding_text(actions, action)
                self.waiting = None
            return
        for ev in world.events(ButtonClicked):
            if ev.entity in self.buttons:
                self.waiting = ev.entity
                world.get(ev.entity, Button).text = f"{self.buttons[ev.entity]}: press a key..."


def _binding_text(actions: InputMap, action: str) -> str:
    keys = [b.split(":", 1)[1] for b in actions.bindings(action) if b.startswith("key:")]
    return f"{action}: {' / '.join(keys) or '-'}"


def settings(world: World, rebindable: tuple[str, ...] = ()) -> None:
    """Volumes and key rebinding, as an overlay; Back (or Escape) returns."""
    _dim(world, 150)
    col = _column(world, "Settings", width=380)
    audio = world.resource(Audio)
    world.spawn(UINode(parent=col), Label("Music volume", align="left"))
    music = world.spawn(UINode(parent=col, height=26), Slider(0, 1, audio.music_volume, step=0.05))
    world.spawn(UINode(parent=col), Label("Effects volume", align="left"))
    sfx = world.spawn(UINode(parent=col, height=26), Slider(0, 1, audio.sfx_volume, step=0.05))
    world.spawn(Behaviour(_Volumes(music, sfx)))
    actions = world.resource(InputMap)
    buttons = {}
    for action in rebindable:
        text = _binding_text(actions, action)
        buttons[world.spawn(UINode(parent=col, height=36), Button(text))] = action
    world.spawn(Behaviour(_Rebind(buttons)))
    back = _button(world, col, "Back")
    world.spawn(Behaviour(_Buttons({"Back": lambda app: app.pop_scene()})))
    world.spawn(Behaviour(_Escape()))
    focus(world, back)


class _Escape(Script):
    """Escape (or the gamepad's B / Start) closes an overlay."""

    def on_update(self, dt: float) -> None:
        actions = self.world.resource(InputMap)
        if actions.pressed("pause") or self.world.resource(App).input.pad_pressed("b"):
            self.world.resource(App).pop_scene()


def pause(world: World, menu: Any = None, rebindable: tuple[str, ...] = ()) -> None:
    """The see-through pause menu, pushed over the frozen game."""
    _dim(world)
    col = _column(world, "Paused")
    resume = _button(world, col, "Resume")
    _button(world, col, "Settings")
    _button(world, col, "Main menu")
    world.spawn(Behaviour(_Buttons({
        "Resume": lambda app: app.pop_scene(),
        "Settings": lambda app: app.push_scene(settings, overlay=True, rebindable=rebindable),
        "Main menu": lambda app: _to_menu(app, menu),
    })))  # fmt: skip
    world.spawn(Behaviour(_Escape()))
    focus(world, resume)


def _to_menu(app: App, menu: Any) -> None:
    """Leave the pause for the title menu: close the pause now, then fade the game out."""
    app.pop_scene()
    app.replace_scene(menu, transition=FADE)


class PauseKey(Script):
    """In a game: the "pause" action opens :func:`pause` over it."""

    def __init__(self, menu: Any, rebindable: tuple[str, ...]) -> None:
        self.menu, self.rebindable = menu, rebindable

    def on_update(self, dt: float) -> None:
        if self.world.resource(InputMap).pressed("pause"):
            self.world.resource(App).push_scene(
                pause, overlay=True, menu=self.menu, rebindable=self.rebindable
            )


def hud_label(world: World, corner: str, text: str, size: float = 20,
              color: tuple[int, int, int, int] = (255, 255, 255, 255)) -> int:  # fmt: skip
    """A label anchored to a window corner (``"top_left"``, ``"top_right"``...), 16 px in."""
    dx = 16 if "left" in corner else -16
    dy = -12 if "top" in corner else 12
    align = "left" if "left" in corner else "right" if "right" in corner else "center"
    return world.spawn(UINode(anchor=corner, offset=(dx, dy)),
                       Label(text, size=size, color=color, align=align))  # fmt: skip
