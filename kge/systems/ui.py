"""The UI plugin: screen-space widgets handled before the game sees the input, drawn on top.

:class:`UIInput` (INPUT stage, before behaviours' input hooks) lays the UI out for the
current window size, turns this frame's pointer, keyboard and gamepad input into
widget changes (:func:`kge.ui.interact.handle_input`), removes what the UI took from
the game's view of the input, emits the UI events (``world.events(ButtonClicked)``;
the per-frame :class:`~kge.ui.events.UIEvents` resource is kept filled, deprecated,
for one release) and calls the widget entities' Behaviour hooks (``on_click``,
``on_value_changed``, ``on_text_submitted``). The drawing is a render after-pass
(``kge/render/ui.py``), imported only when a frame is drawn.
"""

from __future__ import annotations

from typing import Any

from kge.components.tracked import validate_writes
from kge.components.ui import (
    Dropdown,
    Label,
    ProgressBar,
    ScrollList,
    Slider,
    TextInput,
    Toggle,
    UINode,
)  # fmt: skip
from kge.errors import ValidationError, where
from kge.host import Host
from kge.input import Input
from kge.plugin import Plugin
from kge.render.passes import Frame, passes_for
from kge.schedule import Stage, System, SystemSet
from kge.systems.behaviour import BehaviourRunner
from kge.systems.ui_images import check_ui_images
from kge.ui.events import ButtonClicked, TextSubmitted, UIEvents, ValueChanged
from kge.ui.interact import UIState, handle_input
from kge.ui.theme import DEFAULT_THEME, Theme
from kge.world import World, deprecate_resource, stored_resource

deprecate_resource(
    UIEvents,
    "read world.events(ButtonClicked) (or ValueChanged, TextSubmitted, FocusChanged), "
    "or the widget's Behaviour hooks (on_click...)",
)

_HOOKS: dict[type, str] = {
    ButtonClicked: "on_click",
    ValueChanged: "on_value_changed",
    TextSubmitted: "on_text_submitted",
}


class UIInput(System):
    """Handles the UI's input and emits its events (see the module docstring)."""

    stage = Stage.INPUT
    in_set = SystemSet.UI  # before the SCRIPTS' input hooks: the game sees what the UI left

    def process(self, dt: float) -> None:
        world = self.world
        events = stored_resource(world, UIEvents)
        if events is not None:
            events.clear()
        inp = world.try_resource(Input)
        if inp is None or not world.query(UINode):
            return
        host = world.try_resource(Host)
        size = host.size if host is not None else (960, 540)
        theme = world.try_resource(Theme) or DEFAULT_THEME
        made = handle_input(world, inp, size, world.resource(UIState), theme)
        if events is not None:
            events.items.extend(made)
        for ev in made:
            world.emit(ev)
        runner = world.try_resource(BehaviourRunner)
        if runner is None:
            return
        for ev in made:
            hook = _HOOKS.get(type(ev))
            if hook is not None and world.exists(ev.entity):
                runner.call_one(ev.entity, hook, ev)


#: UI components whose writes are bound to their entity (Button, Panel and UIImage are
#: bound by :func:`check_ui_images`)
WRITE_CHECKED = (UINode, Label, Toggle, Slider, ProgressBar, TextInput, Dropdown, ScrollList)
#: the deepest a UI tree may nest (layout walks it from the root)
MAX_DEPTH = 100


def _check_parent(world: World) -> Any:
    def check(entity: int | None, node: UINode) -> None:
        p = node.parent
        if p is None:
            return
        if p == entity:
            raise ValidationError(
                f"entity {entity}, UINode.parent: a node cannot be its own parent"
            )
        if not world.exists(p) or world.try_get(p, UINode) is None:
            raise ValidationError(
                f"{'entity ' + str(entity) + ', ' if entity is not None else ''}UINode.parent: "
                f"entity {p} is not a UI node"
            )
        depth, up = 1, world.get(p, UINode).parent
        while up is not None:  # a loop (a parent that is a descendant) or a nest too deep
            if up == entity:
                raise ValidationError(
                    f"entity {entity}, UINode.parent: entity {p} is inside this node (a loop)"
                )
            depth += 1
            if depth >= MAX_DEPTH:
                raise ValidationError(
                    f"{where(entity, 'UINode', 'parent')}: entity {p} is {depth} levels deep, "
                    f"the most a UI nests is {MAX_DEPTH}"
                )
            above = world.try_get(up, UINode) if world.exists(up) else None
            up = None if above is None else above.parent

    return check


class UIPlugin(Plugin):
    """Screen-space UI: layout, widgets, focus, UI events and drawing (docs/ui-scenes-input.md)."""

    def build(self, world: World) -> None:
        world.insert_resource(UIState())
        world.insert_resource(UIEvents())
        if world.try_resource(Theme) is None:
            world.insert_resource(DEFAULT_THEME)
        world.validator(UINode, _check_parent(world))
        for ctype in WRITE_CHECKED:  # writes name their entity; UINode.parent is checked
            validate_writes(world, ctype)
        check_ui_images(world)
        world.add_system(UIInput())

        def draw(frame: Frame) -> None:
            from kge.render.ui import draw_ui

            draw_ui(frame, world)

        passes_for(world).add(draw, phase="after", name="ui")


def focus(world: World, entity: int | None) -> None:
    """Give keyboard/gamepad focus to ``entity`` (a menu's first button), or clear it."""
    if entity is not None and world.try_get(entity, UINode) is None:
        raise ValidationError(f"focus: entity {entity} is not a UI node")
    world.resource(UIState).focused = entity
