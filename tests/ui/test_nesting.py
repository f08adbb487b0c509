"""UI trees stay trees: no node is its own ancestor, and nesting is bounded so layout
(which walks the tree from the root) never meets a RecursionError."""

from __future__ import annotations

import pytest

from kge import App, UINode, ValidationError
from kge.systems.ui import MAX_DEPTH
from kge.ui.layout import compute_layout


def _chain(app: App, depth: int) -> list[int]:
    world = app.world
    nodes = [world.spawn(UINode(width=400, height=300))]
    for _ in range(depth - 1):
        nodes.append(world.spawn(UINode(parent=nodes[-1], padding=1.0)))
    return nodes


def test_the_deepest_allowed_nest_lays_out() -> None:
    app = App(lambda w: None, headless=True)
    try:
        nodes = _chain(app, MAX_DEPTH)
        app.step()
        boxes = compute_layout(app.world, (800, 600)).boxes
        assert nodes[-1] in boxes
    finally:
        app.close()


def test_one_level_deeper_is_refused_at_the_spawn() -> None:
    app = App(lambda w: None, headless=True)
    try:
        nodes = _chain(app, MAX_DEPTH)
        count = len(app.world.entities())
        with pytest.raises(ValidationError, match=r"UINode\.parent: entity \d+ is 100 levels"):
            app.world.spawn(UINode(parent=nodes[-1]))
        assert len(app.world.entities()) == count
    finally:
        app.close()


def test_a_parent_write_that_makes_a_loop_is_refused_and_kept() -> None:
    app = App(lambda w: None, headless=True)
    try:
        a, b, c = _chain(app, 3)
        with pytest.raises(ValidationError, match=rf"entity {a}, UINode\.parent: entity {c} is "
                                                  rf"inside this node \(a loop\)"):
            app.world.get(a, UINode).parent = c
        with pytest.raises(ValidationError, match=rf"entity {b}, UINode\.parent: a node cannot"):
            app.world.get(b, UINode).parent = b
        assert app.world.get(a, UINode).parent is None
        assert app.world.get(b, UINode).parent == a
        app.step()
    finally:
        app.close()
