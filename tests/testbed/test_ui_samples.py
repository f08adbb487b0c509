"""The testbed's UI category shows every widget and container kind kge has."""

from __future__ import annotations

from typing import Any

from kge import App
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
from kge.testbed import all_samples


def test_the_ui_samples_show_every_widget_and_container() -> None:
    wanted = {*WIDGETS, Panel, ScrollView, Dialog, DialogButton, Tooltip, Draggable, DropTarget,
              Style}  # fmt: skip
    seen: set[type] = set()
    samples = [s for s in all_samples() if s.category == "UI"]
    assert len(samples) >= 8
    for s in samples:
        app = App(s.setup, headless=True, size=(1280, 720))
        assert app.world.query(UINode)
        seen.update(kind for kind in wanted if app.world.query(kind))

        def note(entity: int, component: Any) -> None:
            seen.add(type(component))

        for kind in wanted:  # what the claims make appear (dialogs opened by a click)
            app.world.on_add(kind, note)
        app.step(300)
        for claim in s.claims:
            claim(app)
        app.close()
    assert wanted - seen == set(), sorted(k.__name__ for k in wanted - seen)
