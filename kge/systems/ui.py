"""The UI plugin: screen-space widgets handled before the game sees the input, drawn on top.

:class:`UIInput` (INPUT stage, before behaviours' input hooks) makes sure the layout
is current (:func:`current_layout`: redone only when a UI component changed, the
window was resized or the scale changed), turns this frame's pointer, keyboard and
gamepad input into widget changes (:func:`kge.ui.interact.handle_input`), removes
what the UI took from the game's view of the input, emits the UI events
(``world.events(ButtonClicked)``; the per-frame :class:`~kge.ui.events.UIEvents`
resource is kept filled, deprecated, for one release) and calls the widget entities'
Behaviour hooks (``on_click``, ``on_value_changed``, ...). The drawing is a render after-pass
(``kge/render/ui.py``), imported only when a frame is drawn.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

from kge.components.tracked import Tracked, bind, unbind
from kge.components.ui import (
    WIDGETS,
    Dialog,
    DialogButton,
    Draggable,
    DropTarget,
    Panel,
    ScrollView,
    Style,
    Tooltip,
    UINode,
)
from kge.errors import ValidationError, where
from kge.input import Input
from kge.plugin import Plugin
from kge.render.passes import Frame, passes_for
from kge.schedule import Stage, System, SystemSet
from kge.systems.behaviour import BehaviourRunner
from kge.systems.ui_images import check_ui_images
from kge.ui.clipboard import Clipboard
from kge.ui.current import current_layout
from kge.ui.events import HOOKS, UIEvents
from kge.ui.focus import scroll_into_view
from kge.ui.interact import handle_input
from kge.ui.layout import MAX_DEPTH
from kge.ui.settings import UISettings
from kge.ui.state import UIState
from kge.ui.theme import DEFAULT_THEME, Theme
from kge.world import World, deprecate_resource, stored_resource

deprecate_resource(
    UIEvents,
    "read world.events(ButtonClicked) (or ValueChanged, TextSubmitted, FocusChanged), "
    "or the widget's Behaviour hooks (on_click...)",
)

#: every component whose changes the UI follows (layout, looks, behaviour)
UI_COMPONENTS: tuple[type, ...] = (
    UINode, *WIDGETS, Panel, Style, ScrollView, Dialog, DialogButton, Tooltip, Draggable,
    DropTarget,
)  # fmt: skip


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
        if inp is None:
            return
        state = world.resource(UIState)
        if not current_layout(world).order:
            return  # no UI shown: the input is all the game's
        made = handle_input(world, inp, state, dt)
        if events is not None:
            events.items.extend(made)
        for ev in made:
            world.emit(ev)
        runner = world.try_resource(BehaviourRunner)
        for ev in made:
            hook = HOOKS.get(type(ev))
            if hook is None or runner is None:
                continue
            entity = getattr(ev, hook[1])
            if entity is not None and world.exists(entity):
                runner.call_one(entity, hook[0], ev)
        for e in state.doomed:
            if world.exists(e):
                world.despawn(e)
        state.doomed.clear()


def _check_node(world: World) -> Any:
    def check(entity: int | None, node: UINode) -> None:
        p = node.parent
        if p is not None:
            at = where(entity, "UINode", "parent")
            if p == entity:
                raise ValidationError(f"{at}: a node cannot be its own parent")
            if not world.exists(p) or world.try_get(p, UINode) is None:
                raise ValidationError(f"{at}: entity {p} is not a UI node")
            depth, seen = 1, {entity}
            cur: int | None = p
            while cur is not None:  # a loop (a parent that is a descendant) or a nest too deep
                if cur in seen:
                    raise ValidationError(
                        f"{at}: entity {p} is inside this node (a loop): it would make a "
                        "parent cycle"
                    )
                seen.add(cur)
                depth += 1
                if depth > MAX_DEPTH:
                    raise ValidationError(
                        f"{at}: entity {p} is {depth - 1} levels deep, the most a UI nests "
                        f"is {MAX_DEPTH}"
                    )
                up = world.try_get(cur, UINode) if world.exists(cur) else None
                cur = up.parent if up is not None else None
        if node.follow is not None:
            at = where(entity, "UINode", "follow")
            if node.parent is not None:
                raise ValidationError(
                    f"{at}: only a root node (parent None) can follow an entity"
                )
            if not world.exists(node.follow):
                raise ValidationError(f"{at}: entity {node.follow} does not exist")

    return check


class UIPlugin(Plugin):
    """Screen-space UI: layout, widgets, focus, UI events and drawing (docs/ui.md)."""

    def __init__(self) -> None:
        self.clipboard = Clipboard()  #: shared by every scene of the App
        self.settings = UISettings()  #: the App's UI and text scale, shared by its scenes

    def build(self, world: World) -> None:
        state = world.insert_resource(UIState(store=self.clipboard))
        world.insert_resource(UIEvents())
        if world.try_resource(Theme) is None:
            world.insert_resource(DEFAULT_THEME)
        if world.try_resource(UISettings) is None:
            world.insert_resource(self.settings)
        world.validator(UINode, _check_node(world))
        check_ui_images(world)  # a missing image is refused at spawn, add and write
        for ctype in UI_COMPONENTS:
            world.on_add(ctype, _tracker(world, state, added=True))
            world.on_remove(ctype, _tracker(world, state, added=False))
        world.add_system(UIInput())

        def draw(frame: Frame) -> None:
            from kge.render.ui import draw_ui

            draw_ui(frame, world)

        passes_for(world).add(draw, phase="after", name="ui")


def _tracker(world: World, state: UIState, added: bool) -> Callable[[int, Any], None]:
    def hook(entity: int, component: Any) -> None:
        state.writes.add(entity)
        state.structural.add(entity)
        if isinstance(component, Tracked):
            if added:
                bind(component, entity, state.writes, world.validate)
            else:
                unbind(component, state.writes)

    return hook


def focus(world: World, entity: int | None) -> None:
    """Give keyboard/gamepad focus to ``entity`` (a menu's first button), or clear it; a
    node inside scroll views is scrolled into view."""
    if entity is not None and world.try_get(entity, UINode) is None:
        raise ValidationError(f"focus: entity {entity} is not a UI node")
    state = world.resource(UIState)
    state.touch(state.focused, entity)
    state.focused = entity
    if entity is not None and entity in state.layout.boxes:
        scroll_into_view(world, state.layout, entity)
