"""Plugins: an App or a World composed of chosen subsystems, with clear errors."""

from __future__ import annotations

import subprocess
import sys
import textwrap
from dataclasses import dataclass

import pytest

import kge
from kge import (
    App,
    BehaviourPlugin,
    Box,
    Collider,
    PhysicsPlugin,
    Plugin,
    PluginError,
    RigidBody,
    Transform,
    World,
)
from kge.schedule import Stage, System


@dataclass(slots=True)
class Spin:
    rate: float = 1.0


class SpinSystem(System):
    stage = Stage.UPDATE

    def process(self, dt: float) -> None:
        for _, (t, s) in self.world.query(Transform, Spin):
            t.angle += s.rate * dt


class SpinPlugin(Plugin):
    def build(self, world: World) -> None:
        world.add_system(SpinSystem())


class NeedsPhysics(Plugin):
    requires = (PhysicsPlugin,)

    def build(self, world: World) -> None:
        world.insert_resource(Spin(2.0))


def hello(world: World) -> None:
    world.spawn(Transform(0, -10), Collider(Box(50, 10)))
    world.spawn(Transform(0, 4), RigidBody(), Collider(Box(1, 1), density=1, friction=0.3))


def test_default_app_has_the_default_plugins_in_order() -> None:
    app = App(hello, headless=True)
    names = [p.name for p in app.plugins]
    assert names == [
        "BehaviourPlugin", "PhysicsPlugin", "CharacterPlugin", "AudioPlugin", "RenderPlugin",
        "AnimationPlugin", "ParticlesPlugin", "LightingPlugin", "UIPlugin", "TilemapPlugin",
        "DebugPlugin",
    ]
    assert [p.name for p in app.world.plugins] == names
    assert [type(p).__name__ for p in kge.default_plugins()] == names


def test_physics_only_app_steps_hello_world_without_render_or_audio() -> None:
    # a child interpreter: this one has imported rendering for other tests
    code = textwrap.dedent(
        """
        import sys
        from kge import App, Box, Collider, PhysicsPlugin, RigidBody, Transform

        def hello(world):
            world.spawn(Transform(0, -10), Collider(Box(50, 10)))
            world.spawn(Transform(0, 4), RigidBody(), Collider(Box(1, 1), density=1, friction=0.3))

        app = App(hello, headless=True, plugins=[PhysicsPlugin()])
        app.step(120)
        y = app.world.get(2, Transform).y
        assert abs(y - 1.015) < 0.01, y
        loaded = sorted(
            m for m in sys.modules
            if m.split(".")[0] == "pyglet"
            or m.startswith(("kge.render", "kge.audio", "kge.assets", "kge.systems.render",
                             "kge.systems.audio"))
        )
        print("LOADED", loaded)
        """
    )
    out = subprocess.run(
        [sys.executable, "-c", code], capture_output=True, text=True, timeout=120, check=True
    ).stdout
    assert "LOADED []" in out


def test_world_takes_a_plugin_without_an_app() -> None:
    world = World()
    world.add_plugins(SpinPlugin)  # a Plugin class is instantiated
    e = world.spawn(Transform(), Spin(3.0))
    world.schedule.run(Stage.UPDATE, 0.5)
    assert world.get(e, Transform).angle == pytest.approx(1.5)
    assert world.has_plugin(SpinPlugin)
    assert [p.name for p in world.plugins] == ["SpinPlugin"]


def test_function_plugin_runs_for_every_scene_world() -> None:
    seen: list[str] = []

    def tag(world: World) -> None:
        seen.append(world.name)

    app = App(hello, headless=True, plugins=[PhysicsPlugin(), tag])
    app.replace_scene(hello)
    assert len(seen) == 2
    assert app.world.has_plugin(tag)


def test_same_plugin_twice_is_refused_naming_it() -> None:
    with pytest.raises(PluginError, match=r"plugin PhysicsPlugin was added twice \(listed twice\)"):
        App(hello, headless=True, plugins=[PhysicsPlugin(), PhysicsPlugin()])
    app = App(hello, headless=True, plugins=[PhysicsPlugin()])
    with pytest.raises(PluginError, match="this App already has PhysicsPlugin"):
        app.add_plugins(PhysicsPlugin)


def test_missing_requirement_names_both_and_builds_nothing() -> None:
    world = World()
    with pytest.raises(PluginError, match="NeedsPhysics requires PhysicsPlugin.*before NeedsPhysics"):
        world.add_plugins(SpinPlugin(), NeedsPhysics())
    assert world.plugins == ()  # SpinPlugin was not built either
    assert world.schedule.systems() == []


def test_requirements_are_built_first_whatever_the_order() -> None:
    app = App(hello, headless=True, plugins=[NeedsPhysics(), PhysicsPlugin()])
    assert [p.name for p in app.plugins] == ["PhysicsPlugin", "NeedsPhysics"]
    assert app.world.resource(Spin).rate == 2.0


def test_not_a_plugin_is_refused() -> None:
    with pytest.raises(PluginError, match="int 5"):
        World().add_plugins(5)
    with pytest.raises(PluginError, match="Spin is not a plugin"):
        World().add_plugins(Spin)


def test_app_add_plugins_reaches_the_running_scene() -> None:
    app = App(hello, headless=True, plugins=[PhysicsPlugin()])
    e = app.world.spawn(Transform(), Spin(1.0))
    app.add_plugins(SpinPlugin())
    app.step(60)
    assert app.world.get(e, Transform).angle == pytest.approx(1.0)


def test_render_without_the_render_plugin_says_which_plugin_is_missing() -> None:
    app = App(hello, headless=True, plugins=[BehaviourPlugin(), PhysicsPlugin()])
    with pytest.raises(PluginError, match="needs the RenderPlugin.*BehaviourPlugin, PhysicsPlugin"):
        app.render()


def test_close_lets_each_plugin_clean_up_in_reverse_order() -> None:
    calls: list[str] = []

    class First(Plugin):
        def cleanup(self, app: object) -> None:
            calls.append("first")

    class Second(Plugin):
        def cleanup(self, app: object) -> None:
            calls.append("second")

    app = App(hello, headless=True, plugins=[First(), Second()])
    app.close()
    assert calls == ["second", "first"]


def test_the_readme_lists_every_default_plugin() -> None:
    from pathlib import Path

    readme = (Path(__file__).resolve().parents[2] / "README.md").read_text()
    table = readme.split("## Architecture", 1)[1].split("**Floors.**", 1)[0]
    for plugin in kge.default_plugins():
        assert f"| `{plugin.name}` |" in table, plugin.name
