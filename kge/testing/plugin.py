"""kge's pytest plugin, registered through the ``pytest11`` entry point when kge is
installed: a game's tests get these fixtures with no conftest.

* ``kge_app(scene, plugins=None, **kwargs)``: a headless :class:`~kge.App` (closed after
  the test); ``plugins=`` chooses the subsystems, as for ``App``.
* ``kge_world(*plugins)``: a bare :class:`~kge.World` with only the given plugins, to
  test one system without an App.
* ``kge_golden(app, name, tolerance=8, max_differing=0.001)``: compare the rendered frame
  with ``goldens/<name>.png`` beside the test file; ``pytest --kge-update-goldens``
  rewrites the goldens from this run.

Loading the plugin selects headless pyglet (EGL) and the silent audio driver, unless
the environment already says otherwise, so game tests never open a window or a sound
device.
"""

from __future__ import annotations

import os
from collections.abc import Callable, Iterator
from pathlib import Path
from typing import Any

import pytest

os.environ.setdefault("PYGLET_HEADLESS", "1")
os.environ.setdefault("PYGLET_AUDIO", "silent")
os.environ.setdefault("KGE_HEADLESS", "1")


def pytest_addoption(parser: pytest.Parser) -> None:
    group = parser.getgroup("kge")
    group.addoption(
        "--kge-update-goldens",
        action="store_true",
        default=False,
        help="kge: rewrite golden screenshots from this run instead of comparing",
    )


@pytest.fixture
def kge_app() -> Iterator[Callable[..., Any]]:
    """A factory of headless Apps, each closed when the test ends."""
    from kge.app import NO_SCENE, App

    apps: list[App] = []

    def make(scene: Any = NO_SCENE, *, plugins: Any = None, **kwargs: Any) -> App:
        app = App(scene, headless=True, plugins=plugins, **kwargs)
        apps.append(app)
        return app

    yield make
    for app in apps:
        app.close()


@pytest.fixture
def kge_world() -> Iterator[Callable[..., Any]]:
    """A factory of bare Worlds with only the given plugins, each closed after the test."""
    from kge.world import World

    worlds: list[World] = []

    def make(*plugins: Any) -> World:
        world = World()
        world.add_plugins(*plugins)
        worlds.append(world)
        return world

    yield make
    for world in worlds:
        world.close()


@pytest.fixture
def kge_golden(request: pytest.FixtureRequest) -> Callable[..., None]:
    """Compare a rendered App with ``goldens/<name>.png`` next to the test file."""
    from kge.testing import compare_with_golden

    folder = Path(str(request.node.path)).parent / "goldens"
    update = bool(request.config.getoption("--kge-update-goldens"))

    def check(app: Any, name: str, **tolerances: Any) -> None:
        compare_with_golden(app, folder / f"{name}.png", update=update, **tolerances)

    return check
