"""Menus the example games share: title menu, settings, a see-through pause, corner HUDs.

Each is a small scene built from kge UI entities (``docs/ui-scenes-input.md``):

* :func:`title_menu` — Play (fades into the game), Settings, Quit; keyboard (Tab,
  arrows, Enter), mouse and gamepad (d-pad, A) all work;
* :func:`settings` — pushed as an overlay, in tabs: Audio (music and effects volume
  sliders), Controls (a scroll view of one button per rebindable action: "press a
  key..." rebinds it through ``app.actions``; Reset asks to confirm, then restores the
  defaults) and Display (UI size and text size, for every scene of the App);
* :func:`pause` — pushed as an overlay over the frozen game (P, Escape or Start):
  Resume, Settings, Main menu;
* :func:`hud_label` — a label anchored to a corner of the window.

A game lists its actions once (:func:`bind_defaults`); the App's ``InputMap`` keeps
them, with any rebinding, across every scene.
"""

from __future__ import annotations

import weakref
from collections.abc import Callable
from typing import Any

import kge_required  # noqa: F401  (first: names the Python to use when kge is missing)

from kge import (
    App,
    Audio,
    Behaviour,
    Button,
    ButtonClicked,
    DialogClosed,
    Fade,
    InputMap,
    Label,
    Panel,
    Script,
    ScrollView,
    Slider,
    Tabs,
    UINode,
    UISettings,
    ValueChanged,
    World,
    confirm,
    focus,
)

FADE = Fade(0.4)
#: action -> default bindings; a game passes its own to bind_defaults
Bindings = dict[str, tuple[Any, ...]]


#: each App's action map -> the defaults its game declared (what "Reset" restores)
_DEFAULTS: weakref.WeakKeyDictionary[InputMap, Bindings] = weakref.WeakKeyDictionary()


def bind_defaults(actions: InputMap, defaults: Bindings) -> None:
    """Bind each action that the map does not know yet (rebinding survives scene changes).

    A game passes this to ``App(..., bindings=...)`` or calls it from its scenes."""
    _DEFAULTS[actions] = defaults
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
    """Click an action's button, then press a key: the action is bound to that key.
    Reset asks to confirm, then gives every action its default bindings back."""

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
            elif ev.text == "Reset controls":
                confirm(world, "Give every action its default keys back?", ok="Reset",
                        title="Reset controls")  # fmt: skip
        for closed in world.events(DialogClosed):
            if closed.text == "Reset":
                self.reset(actions)

    def reset(self, actions: InputMap) -> None:
        defaults = _DEFAULTS.get(actions, {})
        for action in self.buttons.values():
            if action in defaults:
                actions.rebind(action, *defaults[action])
        for button, action in self.buttons.items():
            self.world.get(button, Button).text = _binding_text(actions, action)


def _binding_text(actions: InputMap, action: str) -> str:
    keys = [b.split(":", 1)[1] for b in actions.bindings(action) if b.startswith("key:")]
    return f"{action}: {' / '.join(keys) or '-'}"


class _Display(Script):
    """Sliders -> the App's UI scale and text scale (UISettings, shared by its scenes)."""

    def __init__(self, size: int, text: int) -> None:
        self.size, self.text = size, text

    def on_update(self, dt: float) -> None:
        settings = self.world.resource(UISettings)
        for ev in self.world.events(ValueChanged):
            if ev.entity == self.size:
                settings.scale = ev.value
            elif ev.entity == self.text:
                settings.text_scale = ev.value


def _page(world: World, tabs: int) -> int:
    return world.spawn(UINode(parent=tabs, layout="column", padding=12, spacing=8,
                              align="stretch"))  # fmt: skip


def _labelled_slider(world: World, page: int, text: str, slider: Slider) -> int:
    world.spawn(UINode(parent=page), Label(text, align="left"))
    return world.spawn(UINode(parent=page, height=26), slider)


def settings(world: World, rebindable: tuple[str, ...] = ()) -> None:
    """Audio, controls and display settings in tabs, as an overlay; Back (or Escape)
    returns. The controls scroll (one rebinding button per action)."""
    _dim(world, 150)
    col = _column(world, "Settings", width=440)
    tabs = world.spawn(UINode(parent=col, height=300), Tabs(["Audio", "Controls", "Display"]))
    audio_page = _page(world, tabs)
    audio = world.resource(Audio)
    music = _labelled_slider(world, audio_page, "Music volume",
                             Slider(0, 1, audio.music_volume, step=0.05))  # fmt: skip
    sfx = _labelled_slider(world, audio_page, "Effects volume",
                           Slider(0, 1, audio.sfx_volume, step=0.05))  # fmt: skip
    world.spawn(Behaviour(_Volumes(music, sfx)))
    controls = _page(world, tabs)
    keys = world.spawn(UINode(parent=controls, grow=1, layout="column", spacing=6,
                              align="stretch"), ScrollView())  # fmt: skip
    actions = world.resource(InputMap)
    buttons = {}
    for action in rebindable:
        label = _binding_text(actions, action)
        buttons[world.spawn(UINode(parent=keys, height=36), Button(label))] = action
    world.spawn(UINode(parent=controls, height=36), Button("Reset controls"))
    world.spawn(Behaviour(_Rebind(buttons)))
    display = _page(world, tabs)
    ui = world.resource(UISettings)
    size = _labelled_slider(world, display, "UI size",
                            Slider(0.75, 1.5, ui.scale, step=0.05))  # fmt: skip
    text = _labelled_slider(world, display, "Text size",
                            Slider(1.0, 2.0, ui.text_scale, step=0.1))  # fmt: skip
    world.spawn(Behaviour(_Display(size, text)))
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
