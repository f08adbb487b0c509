"""Audio tests: silent driver, headless pyglet, sounds generated in the test.

The environment is set before anything imports pyglet (the suite conftest does
the same; this keeps ``pytest tests/audio`` self-contained).
"""

from __future__ import annotations

import os

os.environ.setdefault("PYGLET_AUDIO", "silent")
os.environ.setdefault("PYGLET_HEADLESS", "1")

from collections.abc import Callable
from pathlib import Path
from typing import Any

import pytest

from kge import App, World
from kge.assets import Assets, tone

BEEP_SECONDS = 0.25


def make_app(scene: Callable[..., Any], **kwargs: Any) -> App:
    """A headless App with the default plugins (the audio plugin among them)."""
    return App(scene, headless=True, **kwargs)


@pytest.fixture
def sound_dir(tmp_path: Path) -> Path:
    """A folder with WAVs generated here: beep (0.25 s), blip (0.05 s), theme, other."""
    sfx = tmp_path / "sfx"
    sfx.mkdir()
    tone(440, BEEP_SECONDS, rate=22050).write_wav(str(sfx / "beep.wav"))
    tone(880, 0.05, shape="square", rate=22050).write_wav(str(sfx / "blip.wav"))
    tone(220, 0.5, shape="triangle", rate=11025).write_wav(str(tmp_path / "theme.wav"))
    tone(330, 0.5, shape="triangle", rate=11025).write_wav(str(tmp_path / "other.wav"))
    return tmp_path


@pytest.fixture
def store(sound_dir: Path) -> Assets:
    """A store anchored at the sound folder, searching it and its sfx/ subfolder."""
    return Assets(sound_dir, sound_dir / "sfx", anchor=sound_dir)


def with_store(store: Assets, setup: Callable[[World], None] | None = None) -> Callable[..., None]:
    """A scene that inserts ``store`` and then runs ``setup``."""

    def scene(world: World) -> None:
        world.insert_resource(store)
        if setup is not None:
            setup(world)

    return scene
