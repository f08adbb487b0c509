"""The in-game console: registered commands only, typed arguments, errors in the log,
the overlay's keyboard, and no eval of what is typed."""

from __future__ import annotations

import enum

import pytest

from kge import App, Behaviour, Box, Collider, Key, Name, RigidBody, Script, Transform, World
from kge.debug import Console, ConsoleError, Gizmos
from kge.physics.settings import PhysicsSettings

from ..render.conftest import mask, pixels


def level(world: World) -> None:
    world.spawn(Transform(0, -1), Collider(Box(5, 1)), Name("ground"))
    world.spawn(Transform(0, 3), RigidBody(), Collider(Box(0.5, 0.5)), Name("crate"))


class Mode(enum.Enum):
    EASY = 1
    HARD = 2


def test_a_command_gets_typed_arguments_and_the_world() -> None:
    app = App(level, headless=True)
    console = app.world.resource(Console)
    seen = []

    @console.command(help="spawn a crate")
    def crate(world: World, x: float, y: float = 5.0, big: bool = False, mode: Mode = Mode.EASY
              ) -> str:
        seen.append((x, y, big, mode))
        return f"crate at {x}, {y}"

    r = console.run("crate 2 8 on hard")
    assert r.ok and r.output == ["crate at 2.0, 8.0"]
    assert seen == [(2.0, 8.0, True, Mode.HARD)]
    assert console.run("crate -1").ok and seen[-1] == (-1.0, 5.0, False, Mode.EASY)
    bad = console.run("crate fast")
    assert not bad.ok and "'fast' is not a number" in bad.text
    assert not console.run("crate").ok  # x is required: the usage is printed
    assert "usage: crate <x: float>" in console.run("crate").text
    assert not console.run("crate 1 2 yes medium").ok
    assert "help" in console.commands and "crate" in console.commands
    assert "spawn a crate" in console.run("help crate").text


def test_typed_text_is_never_evaluated() -> None:
    app = App(level, headless=True)
    console = app.world.resource(Console)
    for line in ("__import__('os').system('true')", "1 + 1", "py print(1)", "exec('x')"):
        r = console.run(line)
        assert not r.ok and "unknown command" in r.text
    r = console.run("set 2.Transform.x __import__('os')")
    assert not r.ok and "not a number" in r.text
    assert app.world.get(2, Transform).x == 0.0


def test_python_is_an_opt_in() -> None:
    console = Console(python=True)
    world = World()
    e = world.spawn(Transform(4.0, 0.0))
    assert console.run(f"py world.get({e}, Transform).x if False else 7*6", world).text == "42"


def test_set_and_get_variables_and_fields_through_validation() -> None:
    app = App(level, headless=True)
    console = app.world.resource(Console)
    assert console.run("set gravity 0,-5").ok
    assert app.world.resource(PhysicsSettings).gravity == (0.0, -5.0)
    assert console.run("get gravity").text == "gravity = 0, -5"
    assert console.run("set time_scale 0.25").ok and app.time_scale == 0.25
    r = console.run("set time_scale -1")
    assert not r.ok and app.time_scale == 0.25  # refused by the App, unchanged
    assert console.run("set 2.Transform.angle 90").ok
    assert abs(app.world.get(2, Transform).angle - 1.5707963) < 1e-6
    r = console.run("set 2.RigidBody.linear_damping -3")
    assert not r.ok and "entity 2" in r.text and "linear_damping" in r.text
    assert app.world.get(2, RigidBody).linear_damping == 0.0
    assert not console.run("set 9.Transform.x 1").ok  # no such entity
    assert not console.run("set 2.Sprite.opacity 1").ok  # no such component
    assert not console.run("get nothing").ok
    assert "paused = False" in console.run("vars").text


def test_built_in_commands_drive_the_app() -> None:
    app = App(level, headless=True)
    console = app.world.resource(Console)
    assert "crate" in console.run("entities cra").text
    assert "[RigidBody]" in console.run("inspect 2").text
    console.run("pause")
    assert app.paused
    console.run("step 3")
    before = app.world.get(2, Transform).y
    for _ in range(5):
        app.advance(1 / 60)
    assert app.world.get(2, Transform).y < before  # three single steps ran
    console.run("resume")
    assert not app.paused
    assert console.run("despawn 2").ok
    app.step(1)
    assert not app.world.exists(2)
    assert console.run("timings on").ok and app.world.schedule.timings is not None
    app.step(2)
    assert "PhysicsSystem" in console.run("timings").text
    assert console.run("timings off").ok and app.world.schedule.timings is None
    assert console.run("gizmos off").ok and not app.world.resource(Gizmos).enabled
    assert "PhysicsSystem" in console.run("schedule").text
    console.run("clear")
    assert list(console.log) == []


def test_a_command_that_raises_is_reported_and_the_game_runs_on() -> None:
    app = App(level, headless=True)
    console = app.world.resource(Console)

    @console.command
    def broken() -> None:
        raise ZeroDivisionError("boom")

    r = console.run("broken")
    assert not r.ok and r.output == ["error: ZeroDivisionError: boom"]
    assert "error: ZeroDivisionError: boom" in console.log
    app.step(1)


def test_bad_registrations_are_refused() -> None:
    console = Console()
    with pytest.raises(ConsoleError.__mro__[1]):  # KgeError: a clear error at the call
        console.add_command(lambda: None, "two words")
    with pytest.raises(ValueError, match="needs a function"):
        console.add_command("not callable")  # type: ignore[arg-type]
    with pytest.raises(ValueError, match="has no attribute"):
        console.variable("g", PhysicsSettings(), "gravityy")


def test_the_console_is_one_for_the_app_across_scenes() -> None:
    app = App(level, headless=True)
    console = app.world.resource(Console)
    console.run("echo hello")
    app.replace_scene(level)
    assert app.world.resource(Console) is console
    assert "hello" in console.log
    app.step(1)
    assert console.world is app.world


def test_the_overlay_types_runs_recalls_and_completes() -> None:
    moved = []

    class Player(Script):
        def on_update(self, dt: float) -> None:
            if self.world.resource(Input).held(Key.D):
                moved.append(1)

    from kge import Input

    def scene(w: World) -> None:
        level(w)
        w.spawn(Transform(), Behaviour(Player()))

    app = App(scene, headless=True)
    console = app.world.resource(Console)
    inp = app.input
    inp.press(Key.GRAVE)
    inp.type_text("`")
    app.step(1)
    inp.release(Key.GRAVE)
    assert console.open and console.line == ""  # the backquote itself is not typed
    inp.press(Key.D)  # typing: the game must not see D held
    inp.type_text("echo d")
    app.step(1)
    assert console.line == "echo d" and moved == []
    inp.press(Key.ENTER)
    app.step(1)
    inp.release(Key.ENTER)
    assert "d" in console.log and console.line == ""
    inp.press(Key.UP)
    app.step(1)
    inp.release(Key.UP)
    assert console.line == "echo d"
    console.line = "ent"
    inp.press(Key.TAB)
    app.step(1)
    inp.release(Key.TAB)
    assert console.line == "entities "
    inp.press(Key.ESCAPE)
    app.step(1)
    inp.release(Key.ESCAPE)
    assert not console.open
    inp.release(Key.D)
    inp.press(Key.D)
    app.step(1)
    assert moved  # closed: the game has its keys back


def test_the_overlay_is_drawn_over_the_game(make_app) -> None:
    app = make_app(level)
    console = app.world.resource(Console)
    console.open = True
    for i in range(30):
        console.print(f"line {i}")
    px = pixels(app)
    h = px.shape[0]
    panel = mask(px, (12, 14, 20), tol=4)
    assert panel[int(h * 0.8)].mean() > 0.5  # the panel covers the top of the window
    assert not panel[int(h * 0.2)].any()
    text = mask(px[int(h * 0.55) :], (225, 230, 240), tol=60)
    assert text.sum() > 50  # glyphs
    console.open = False
    assert not mask(pixels(app), (12, 14, 20), tol=4)[int(h * 0.8)].any()
