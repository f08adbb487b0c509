from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path

import pytest

from kge.assets.store import Assets, default_assets, set_default_assets

from .scenes import make_assets


@pytest.fixture
def game_assets(tmp_path: Path) -> Iterator[Path]:
    """A game folder (art/, sfx/) that the default asset store searches, as a game's would."""
    make_assets(tmp_path)
    before = default_assets()
    set_default_assets(Assets(tmp_path, anchor=tmp_path))
    try:
        yield tmp_path
    finally:
        set_default_assets(before)
