"""Scrolling any widgets, and long lists: a scroll view of settings rows, one scrolling
both ways over a grid, and a 10,000-row list that costs what its visible rows do."""

from __future__ import annotations

from typing import Any

from kge.components import Behaviour
from kge.components.ui import (
    Button,
    Label,
    Panel,
    ScrollList,
    ScrollView,
    Slider,
    Toggle,
    UINode,
)
from kge.testbed.registry import sample
from kge.testbed.samples.ui_parts import Status, column, root_area
from kge.world import World


@sample("UI", "Scroll Views",
        help="Wheel, drag the content or the scrollbar; Tab scrolls the focus into view.")
def scroll_views(world: World) -> None:
    root = root_area(world)
    left = column(world, parent=root, anchor="left", offset=(16, 0), width=330, height="80%")
    world.spawn(UINode(parent=left), Label("Settings (60 rows)", size=18, align="left"))
    view = world.spawn(UINode(parent=left, grow=1, layout="column", spacing=6, padding=4,
                              align="stretch"), ScrollView())  # fmt: skip
    for i in range(60):
        row = world.spawn(UINode(parent=view, layout="row", spacing=8, align="center"))
        world.spawn(UINode(parent=row, width=90), Label(f"Option {i + 1}", align="left"))
        world.spawn(UINode(parent=row, grow=1, height=22), Slider(0, 10, i % 11, step=1))
        world.spawn(UINode(parent=row), Toggle(i % 2 == 0))
    middle = column(world, parent=root, anchor="center", offset=(30, 0), width=300, height=300)
    world.spawn(UINode(parent=middle), Label("Both ways", size=18, align="left"))
    both = world.spawn(UINode(parent=middle, grow=1, layout="grid", columns=12, spacing=4),
                       ScrollView(horizontal=True), Panel(color=(20, 23, 30, 255)))  # fmt: skip
    for i in range(12 * 20):
        world.spawn(UINode(parent=both, width=60, height=30), Button(f"{i}"))
    right = column(world, parent=root, anchor="right", offset=(-16, 0), width=240, height="80%")
    world.spawn(UINode(parent=right), Label("10,000 rows", size=18, align="left"))
    world.spawn(UINode(parent=right, grow=1),
                ScrollList([f"Row {i}" for i in range(10_000)]))  # fmt: skip
    status = world.spawn(UINode(parent=root, anchor="bottom", offset=(0, 12)), Label(""))
    world.spawn(Behaviour(Status(status)))


@scroll_views.claim
def _the_wheel_scrolls_and_the_list_reaches_its_last_row(app: Any) -> None:
    from kge.keys import Key
    from kge.ui.driving import focus, press, scroll

    world = app.world
    view = next(e for e, (s,) in world.query(ScrollView) if not s.horizontal)
    scroll(app, view, -3)
    assert world.get(view, ScrollView).scroll[1] > 0
    lst = next(e for e, _ in world.query(ScrollList))
    focus(app, lst)
    press(app, Key.END)
    assert world.get(lst, ScrollList).selected == 9_999
