"""App-wide resources shared by every scene (autoloads): one object across scene
changes, pushes, pops and restores; bad input refused at the call."""

from __future__ import annotations

from dataclasses import dataclass, field

import pytest

from kge import App, ComponentTypeError, Input, Transform, ValidationError, World


@dataclass
class Progress:
    score: int = 0
    levels: list[str] = field(default_factory=list)


def level(world: World, name: str = "one") -> None:
    world.resource(Progress).levels.append(name)  # setup sees the shared resource
    world.spawn(Transform())


def test_one_object_survives_every_scene_change() -> None:
    app = App(lambda world: None, headless=True)
    progress = app.autoload(Progress())
    app.replace_scene(level, name="one")
    app.world.resource(Progress).score += 10
    app.replace_scene(level, name="two")
    app.push_scene(level, name="menu")
    assert app.world.resource(Progress) is progress
    app.pop_scene()
    app.step(1)
    assert progress.score == 10 and progress.levels == ["one", "two", "menu"]
    assert app.autoloads == {Progress: progress}
    snap = app.world.snapshot()
    app.world.resource(Progress).score += 5
    app.restore(snap)
    assert app.world.resource(Progress) is progress and progress.score == 15


def test_a_new_autoload_reaches_the_running_scenes_and_replaces_its_type() -> None:
    app = App(lambda w: None, headless=True)
    first = app.autoload(Progress(score=1))
    app.push_scene(lambda w: None)
    second = app.autoload(Progress(score=2))
    assert all(w.resource(Progress) is second for w in app.worlds)
    assert first is not second


def test_bad_autoloads_are_refused_and_change_nothing() -> None:
    app = App(lambda world: None, headless=True)
    with pytest.raises(ComponentTypeError, match="instance"):
        app.autoload(Progress)
    with pytest.raises(ValidationError, match="App's own"):
        app.autoload(Input())
    with pytest.raises(ValidationError, match="App's own"):
        app.autoload(app)
    with pytest.raises(ComponentTypeError, match="is not a"):
        app.autoload(Progress(), as_type=int)
    assert app.autoloads == {} and app.world.try_resource(Progress) is None
