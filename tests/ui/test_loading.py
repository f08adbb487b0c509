"""The loading screen: progress per frame, then the next scene through a transition."""

from __future__ import annotations

from pathlib import Path

import pytest

from kge import App, World
from kge.assets.errors import AssetError
from kge.assets.store import Assets
from kge.components.ui import Label, ProgressBar
from kge.systems.loading import LoadingScreen
from kge.transitions import Fade


class Level:
    def __init__(self, number: int) -> None:
        self.number = number


def level(world: World, number: int = 1) -> None:
    world.insert_resource(Level(number))


def _store(tmp_path: Path, names: list[str]) -> Assets:
    for n in names:
        (tmp_path / n).write_bytes(b"data")
    return Assets(tmp_path, anchor=tmp_path)


def test_progress_is_shown_frame_by_frame_then_the_next_scene_fades_in(tmp_path: Path) -> None:
    names = ["a.txt", "b.txt", "c.txt"]
    screen = LoadingScreen(names, then=level, transition=Fade(0.2), store=_store(tmp_path, names),
                           items_per_frame=1, number=2)  # fmt: skip
    app = App(screen, headless=True)
    loading = app.world
    seen = []
    for _ in range(3):
        app.step()
        ((_, (bar,)),) = loading.query(ProgressBar)
        seen.append(round(bar.value, 3))
    assert seen == [0.333, 0.667, 1.0]
    assert any(lbl.text == "3 / 3" for _, (lbl,) in loading.query(Label))
    assert app.transition is not None and app.world is loading
    for _ in range(12):
        app.step()
    assert app.world is not loading and app.world.resource(Level).number == 2
    assert screen.preload is not None and screen.preload.loaded == 3


def test_a_missing_asset_is_reported_by_name(tmp_path: Path) -> None:
    screen = LoadingScreen(["there.txt", "gone.png"], then=level,
                           store=_store(tmp_path, ["there.txt"]), items_per_frame=5)  # fmt: skip
    app = App(screen, headless=True)
    with pytest.raises(AssetError, match="gone.png"):
        app.step()
