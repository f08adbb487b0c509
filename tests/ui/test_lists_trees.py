"""Tree views and 10,000-row lists: folding, keys, activation, drops, and that only the
rows in view are drawn."""

from __future__ import annotations

from typing import Any

import pytest

from kge import App, Behaviour, Key, Script, World
from kge.components.ui import ScrollList, TreeItem, TreeView, UINode
from kge.errors import ValidationError
from kge.testing import box_of, click, double_click, drag, focus, press, scroll
from kge.ui.events import (
    DragCancelled,
    Dropped,
    ItemActivated,
    ItemToggled,
    TreeDrop,
    ValueChanged,
)

from .conftest import pixels

SIZE = (200, 160)


def _tree() -> TreeView:
    return TreeView([TreeItem("root", "Scene"), TreeItem("p", "Player", "root"),
                     TreeItem("gun", "Gun", "p"), TreeItem("cam", "Camera", "root"),
                     TreeItem("sun", "Sun")], row_height=20, draggable=True)  # fmt: skip


class Activated(Script):
    def __init__(self) -> None:
        self.items: list[Any] = []

    def on_item_activated(self, event: ItemActivated) -> None:
        self.items.append(event.item)


def tree_scene(world: World, hooks: Activated) -> None:
    world.spawn(UINode(width=180, height=140), _tree(), Behaviour(hooks))


def test_tree_folds_by_arrow_click_and_keys_and_activates_on_enter_or_double_click() -> None:
    hooks = Activated()
    app = App(tree_scene, headless=True, size=SIZE, hooks=hooks)
    app.step()
    tree = next(e for e, _ in app.world.query(TreeView))
    w = app.world.get(tree, TreeView)
    with pytest.raises(Exception, match="no widget shows 'Player'"):
        click(app, "Player")  # folded: not shown
    row = box_of(app, "Scene")
    app.input.click(at=(row.x + 10, row.center[1]))  # the arrow at the row's left end
    app.step()
    assert w.expanded == {"root"} and app.world.events(ItemToggled) == [
        ItemToggled(tree, "root", True)]  # fmt: skip
    click(app, "Player")
    assert w.selected == "p"
    press(app, Key.RIGHT)  # opens Player
    press(app, Key.RIGHT)  # then moves to its first child
    assert w.expanded == {"root", "p"} and w.selected == "gun"
    press(app, Key.LEFT)  # a leaf: to its parent
    assert w.selected == "p"
    press(app, Key.LEFT)  # open: closes
    assert w.expanded == {"root"}
    press(app, Key.DOWN)
    assert w.selected == "cam"
    press(app, Key.ENTER)
    double_click(app, "Sun")
    assert hooks.items == ["cam", "sun"] and w.selected == "sun"


def test_tree_rows_drag_onto_other_rows_saying_where() -> None:
    app = App(tree_scene, headless=True, size=SIZE, hooks=Activated())
    app.step()
    tree = next(e for e, _ in app.world.query(TreeView))
    app.world.get(tree, TreeView).expanded = frozenset({"root", "p"})
    app.step()
    drops: list[Dropped] = []

    def dropped() -> None:
        drops.extend(app.world.events(Dropped))

    sun = box_of(app, "Sun")
    player = box_of(app, "Player")
    app.input.mouse_down(at=sun.center)
    app.step()
    for y in (sun.center[1] + 10, player.center[1]):
        app.input.move_mouse(sun.center[0], y)
        app.step()
    app.input.mouse_up(at=player.center)
    app.step()
    dropped()
    assert drops == [Dropped(tree, tree, TreeDrop("sun", "p", "inside"), "tree-row",
                             player.center)]  # fmt: skip
    drag(app, "Camera", (player.center[0], player.top - 2))  # the top quarter: before it
    dropped()
    assert drops[-1].payload == TreeDrop("cam", "p", "before")
    drag(app, "Player", "Gun")  # onto its own child: refused
    assert app.world.events(DragCancelled) == [
        DragCancelled(tree, TreeDrop("p"))]  # fmt: skip
    dropped()
    assert len(drops) == 2


def test_a_tree_with_a_cycle_or_a_missing_parent_is_refused_and_left_as_it_was() -> None:
    w = _tree()
    with pytest.raises(ValidationError, match=r"cycle \('root' -> 'gun' -> 'p' -> 'root'\)"):
        w.items[0] = TreeItem("root", "Scene", "gun")
    with pytest.raises(ValidationError, match="two items have the id 'p'"):
        w.items.append(TreeItem("p", "again"))
    with pytest.raises(ValidationError, match="not an item id"):
        w.selected = "nope"
    assert [i.id for i in w.items] == ["root", "p", "gun", "cam", "sun"]
    w.items.remove(w.items[4])
    w.selected = "cam"
    w.items.pop(3)  # the selected item goes: no selection
    assert w.selected is None


def big_list(world: World, rows: int = 10_000) -> None:
    world.spawn(UINode(width=180, height=120),
                ScrollList([f"Row {i}" for i in range(rows)], row_height=20))  # fmt: skip


def test_ten_thousand_rows_scroll_select_and_keep_the_selection_in_view() -> None:
    app = App(big_list, headless=True, size=SIZE)
    app.step()
    lst = next(e for e, _ in app.world.query(ScrollList))
    w = app.world.get(lst, ScrollList)
    scroll(app, lst, -5)  # five rows down
    assert w.scroll == 100
    click(app, "Row 7")
    assert w.selected == 7 and app.world.events(ValueChanged) == [
        ValueChanged(lst, 7, -1)]  # fmt: skip
    press(app, Key.PAGEDOWN)
    assert w.selected == 7 + 5  # a page: the rows in view less one
    press(app, Key.END)
    assert w.selected == 9_999 and w.scroll == 10_000 * 20 - 120
    press(app, Key.HOME)
    assert w.selected == 0 and w.scroll == 0
    scroll(app, lst, -1e6)  # far past the end: clamped
    assert w.scroll == 10_000 * 20 - 120
    w.items = ["only"]  # fewer rows than the view: the offset is clamped when drawn
    focus(app, lst)
    press(app, Key.DOWN)
    assert w.selected == 0 and w.scroll == 0


def test_a_ten_thousand_row_list_draws_a_few_labels(make_app: Any) -> None:
    from kge.render.ui import drawer_for

    app = make_app(big_list)
    pixels(app)
    drawer = drawer_for(app.world)
    rows = [k for k in drawer.texts.labels if k[1][0] == "row"]
    assert 6 <= len(rows) <= 8  # 120 px of 20 px rows, plus one partly shown
    app.world.get(next(e for e, _ in app.world.query(ScrollList)), ScrollList).scroll = 195_000
    pixels(app)
    texts = sorted(drawer.texts.labels[k].text for k in drawer.texts.labels if k[1][0] == "row")
    assert len(texts) <= 8 and "Row 9750" in texts
