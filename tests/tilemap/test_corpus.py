"""The corpus: every orientation, in the file formats of several Tiled versions, drawn as
Tiled draws it (8-bit headless EGL frames compared with pictures painted from Tiled's rules).
"""

from __future__ import annotations

import os

os.environ.setdefault("PYGLET_HEADLESS", "1")

from pathlib import Path
from typing import Any

import numpy as np
import pytest

from kge import App
from kge.components.camera import Camera
from kge.tilemap import load_map
from kge.tilemap.parse import read_map

from . import corpus

CASES = [(o, f) for o in corpus.ORIENTATIONS for f in corpus.FLAVOURS]



def draw(apps: list[App], path: Path, orientation: str) -> np.ndarray:
    from kge.render.setup import frame_pixels

    tw, _ = corpus.TILE[orientation]
    w, h = corpus.map_size(orientation)

    def setup(world: Any) -> None:
        world.insert_resource(Camera(center=(w / 2 / tw, h / 2 / tw), pixels_per_meter=tw))
        load_map(world, path)

    app = App(setup, headless=True, size=(w, h), background=(0, 0, 0))
    apps.append(app)
    app.render()
    return np.asarray(frame_pixels(app))[::-1, :, :3]  # rows top-down, like the map


@pytest.mark.parametrize(("orientation", "flavour"), CASES, ids=[f"{o}-{f}" for o, f in CASES])
def test_corpus_map_draws_as_tiled(
    tmp_path: Path, apps: list[App], orientation: str, flavour: str
) -> None:
    path = corpus.write(tmp_path, orientation, flavour)
    data = read_map(path)
    assert data.orientation == orientation
    assert data.properties.get("level", 3) == 3
    # what older files omit gets Tiled's defaults: counts from the image, ids numbered
    assert data.tilesets[0].count == len(corpus.COLORS)
    (obj,) = data.object_layers[0].objects
    assert obj.id == 1 and obj.name == "spot"
    if flavour.startswith("json"):
        assert data.tiles.properties[1]["solid"] is True
    got = draw(apps, path, orientation)
    want = corpus.expected(orientation)
    assert got.shape == want.shape
    diff = np.abs(got.astype(int) - want.astype(int)).max(axis=-1) > 8
    assert diff.mean() < 0.01, f"{diff.sum()} of {diff.size} pixels differ"
    # and the picture is not trivially empty: every colour of the sheet is there
    for c in corpus.COLORS:
        assert (np.abs(got.astype(int) - np.array(c)).max(axis=-1) <= 8).any()
