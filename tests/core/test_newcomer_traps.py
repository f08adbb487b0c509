"""Mistakes a newcomer makes get a loud, one-line answer that names the fix."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest

from kge import (
    App,
    Behaviour,
    Circle,
    Collider,
    ComponentTypeError,
    HookSignatureError,
    Key,
    Script,
    Transform,
    ValidationError,
    World,
    draw,
)


def empty(world: World) -> None:
    pass


def test_a_misspelled_hook_is_refused_with_the_right_name() -> None:
    class Player(Script):
        def on_udpate(self, dt: float) -> None: ...

    with pytest.raises(HookSignatureError, match="Player.on_udpate .* did you mean on_update"):
        Behaviour(Player())


def test_methods_of_ones_own_that_start_with_on_are_fine() -> None:
    class Player(Script):
        def on_death(self) -> None: ...

        def on_update(self, dt: float) -> None: ...

    Behaviour(Player())


def test_a_key_name_instead_of_a_key_code_is_refused() -> None:
    app = App(empty, headless=True)
    with pytest.raises(ValidationError, match=r"Input.press: key must be .* kge.Key.SPACE, got 'space'"):
        app.input.press("space")  # type: ignore[arg-type]
    with pytest.raises(ValidationError, match="Input.mouse_down: button"):
        app.input.click("left")  # type: ignore[arg-type]
    app.input.press(Key.SPACE)
    assert app.input.held(Key.SPACE)


def test_app_of_a_called_scene_says_to_pass_the_function() -> None:
    with pytest.raises(ComponentTypeError, match=r"App\(level\), not .* App\(level\(world\)\)"):
        App(empty(World()), headless=True)  # type: ignore[func-returns-value, arg-type]
    assert App(headless=True)._stack == []  # no scene at all is still fine


def test_a_physics_shape_spawned_as_a_component_names_both_circles() -> None:
    world = App(empty, headless=True).world
    with pytest.raises(ValidationError, match=r"kge.Circle is a physics shape.*Collider\(Circle\(...\)\).*kge.draw.Circle"):
        world.spawn(Transform(), Circle(1))
    assert world.entities() == []


def test_a_drawable_in_a_collider_names_the_physics_shape() -> None:
    with pytest.raises(ComponentTypeError, match="that is kge.draw.Circle, a drawable.*kge.Circle"):
        Collider(draw.Circle(1))  # type: ignore[arg-type]
    with pytest.raises(ComponentTypeError, match="kge.draw.Rect.*kge.Box"):
        Collider(draw.Rect(1, 1))  # type: ignore[arg-type]


def _run(code: str, env: dict[str, str]) -> subprocess.CompletedProcess[str]:
    base = {k: v for k, v in os.environ.items() if k not in ("DISPLAY", "PYGLET_HEADLESS", "KGE_HEADLESS")}
    return subprocess.run(
        [sys.executable, "-c", code], env={**base, **env}, capture_output=True, text=True,
        timeout=120,
    )  # fmt: skip


def test_a_stale_display_gives_one_line_saying_what_to_do() -> None:
    result = _run("import kge\nkge.App(lambda w: None).run(frames=2)", {"DISPLAY": ":97"})
    assert result.returncode != 0
    last = result.stderr.strip().splitlines()[-1]
    assert last.startswith("kge.errors.DisplayError: cannot open a window: the display ':97'")
    assert "unset DISPLAY" in last
    assert "Cannot connect" not in result.stderr  # pyglet's own traceback is not shown


def test_run_without_a_display_says_so_instead_of_running_silently() -> None:
    code = "import kge\napp = kge.App(lambda w: None)\napp.input.press(1)\napp.run(frames=3)\n"
    quiet = _run(code, {})
    assert quiet.stderr == ""  # frames= given: the caller knows it is a bounded run
    code = (
        "import kge\n"
        "class Stop(kge.Script):\n"
        "    def on_update(self, dt):\n"
        "        self.world.resource(kge.App).quit()\n"
        "app = kge.App(lambda w: w.spawn(kge.Behaviour(Stop())))\n"
        "app.run()\n"
    )
    told = _run(code, {})
    assert told.returncode == 0, told.stderr
    assert told.stderr.count("\n") == 1
    assert "kge: no display" in told.stderr and "set DISPLAY for a window" in told.stderr


def test_a_python_without_kge_is_told_which_python_to_use(tmp_path: Path) -> None:
    root = Path(__file__).resolve().parents[2]
    # -S: no site-packages, as the system Python in a fresh checkout (and no PYTHONPATH
    # naming a kge checkout, as the suite's own environment may)
    env = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}
    example = subprocess.run(
        [sys.executable, "-S", str(root / "examples" / "pong.py")],
        cwd=tmp_path, capture_output=True, text=True, timeout=60, env=env,
    )  # fmt: skip
    assert example.returncode == 1
    assert "has no kge" in example.stderr and ".venv/bin/python" in example.stderr
    package = subprocess.run(
        [sys.executable, "-S", "-m", "kge", "testbed", "--list"],
        cwd=root, capture_output=True, text=True, timeout=60, env=env,
    )  # fmt: skip
    assert package.returncode == 1
    last = package.stderr.strip().splitlines()[-1]
    assert "kge needs" in last and "use the virtual environment" in last
