"""The scene stack stays consistent when changes are asked for at awkward moments:
from on_destroy or on_exit while another change is being made, during a transition,
by a setup that raises, and when the last scene would be popped."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import pytest

from kge import App, Behaviour, Script, Transform, World
from kge.errors import SceneStackError
from kge.scene import Scene
from kge.transitions import Fade


class Logged(Scene):
    """A scene that logs its hooks into a shared list, and can run a callback on exit."""

    def __init__(self, name: str, log: list[str], on_exit: Callable[[], None] | None = None,
                 fail: bool = False) -> None:
        self.name, self.log, self.exit_hook, self.fail = name, log, on_exit, fail

    def setup(self, world: World, **kwargs: Any) -> None:
        self.log.append(f"setup {self.name}")
        world.spawn(Transform())
        if self.fail:
            raise RuntimeError(f"{self.name}'s setup failed")

    def on_pause(self, world: World) -> None:
        self.log.append(f"pause {self.name}")

    def on_resume(self, world: World) -> None:
        self.log.append(f"resume {self.name}")

    def on_exit(self, world: World) -> None:
        self.log.append(f"exit {self.name}")
        if self.exit_hook is not None:
            self.exit_hook()


def names(app: App) -> list[str]:
    return [s.name for s in app.scenes]


def test_replace_from_on_destroy_during_a_replace_queues_behind_it() -> None:
    log: list[str] = []
    app = App(Logged("menu", log), headless=True)
    app.push_scene(Logged("level", log))

    class Dying(Script):
        def on_destroy(self) -> None:
            app.replace_scene(Logged("x", log))

    app.world.spawn(Behaviour(Dying()))
    app.replace_scene(Logged("next", log))
    # next replaced the level; then x replaced next; the menu below was never touched
    assert names(app) == ["menu", "x"]
    assert log.count("exit level") == 1 and log.count("exit next") == 1
    assert "exit menu" not in log
    app.step(3)
    assert not any(w.closed for w in app.worlds)


def test_replace_from_on_exit_during_a_pop_applies_after_the_pop() -> None:
    log: list[str] = []
    app = App(Logged("menu", log), headless=True)
    app.push_scene(Logged("level", log, on_exit=lambda: app.replace_scene(Logged("x", log))))
    menu_world = app.worlds[0]
    app.pop_scene()
    assert names(app) == ["x"]
    # in order: the pop resumed the menu, then the replace closed it
    assert log[-4:] == ["exit level", "resume menu", "setup x", "exit menu"]
    assert menu_world.closed


def test_an_overlay_pushed_during_a_transition_leaves_with_the_replaced_scene() -> None:
    log: list[str] = []
    app = App(Logged("level", log), headless=True)
    level_world = app.world
    app.replace_scene(Logged("next", log), transition=Fade(0.4))
    app.step(3)  # the fade is under way; the scene has not changed yet
    app.push_scene(Logged("pause", log), overlay=True)
    assert names(app) == ["level", "pause"]
    app.step(30)  # past the swap
    assert names(app) == ["next"]
    assert level_world.closed
    assert log.count("exit level") == 1 and log.count("exit pause") == 1


def test_a_failing_push_leaves_the_stack_as_it_was() -> None:
    log: list[str] = []
    app = App(Logged("menu", log), headless=True)
    menu_world = app.world
    with pytest.raises(RuntimeError, match="broken's setup failed"):
        app.push_scene(Logged("broken", log, fail=True))
    assert names(app) == ["menu"] and app.world is menu_world and not menu_world.closed
    assert log == ["setup menu", "pause menu", "setup broken", "resume menu"]
    app.step(2)


def test_a_failing_replace_keeps_the_old_scene_running() -> None:
    log: list[str] = []
    app = App(Logged("level", log), headless=True)
    level_world = app.world
    with pytest.raises(RuntimeError, match="broken's setup failed"):
        app.replace_scene(Logged("broken", log, fail=True))
    assert names(app) == ["level"] and app.world is level_world and not level_world.closed
    assert "exit level" not in log
    app.step(2)


def test_a_failing_replace_asked_by_a_script_raises_from_the_frame_and_changes_nothing() -> None:
    log: list[str] = []
    app = App(Logged("level", log), headless=True)
    level_world = app.world

    class Asker(Script):
        def on_update(self, dt: float) -> None:
            app.replace_scene(Logged("broken", log, fail=True))
            self.world.despawn(self.entity)

    level_world.spawn(Behaviour(Asker()))
    with pytest.raises(RuntimeError, match="broken's setup failed"):
        app.step()
    assert names(app) == ["level"] and not level_world.closed
    app.step(3)  # and the game goes on
    assert names(app) == ["level"]


def test_popping_the_last_scene_is_refused_at_the_call() -> None:
    log: list[str] = []
    app = App(Logged("only", log), headless=True)
    with pytest.raises(SceneStackError, match="no scene"):
        app.pop_scene()
    assert names(app) == ["only"]
    app.step()


def test_queued_changes_count_when_a_pop_is_checked() -> None:
    log: list[str] = []
    app = App(Logged("a", log), headless=True)
    popped: list[bool] = []

    class Asker(Script):
        def on_update(self, dt: float) -> None:
            if popped:
                return
            app.push_scene(Logged("b", log))
            app.pop_scene()  # allowed: b will be on the stack by then
            with pytest.raises(SceneStackError):
                app.pop_scene()  # this one would pop a as well
            popped.append(True)

    app.world.spawn(Behaviour(Asker()))
    app.step()
    assert names(app) == ["a"] and popped
