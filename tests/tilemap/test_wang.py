"""Terrain autotiling: set_terrain picks the tile whose corners match (Tiled 1.5+ Wang
sets, and the terrains of Tiled 0.9-1.4 converted to them)."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from kge.testbed import png
from kge.tilemap import TilemapError, load_map
from kge.world import World

# 16 tiles: tile i has corner colours from its bits (tl=1, tr=2, br=4, bl=8): 1 = grass
BITS = {"tl": 1, "tr": 2, "br": 4, "bl": 8}


def wangid(i: int) -> list[int]:
    c = {k: (1 if i & b else 2) for k, b in BITS.items()}  # colour 1 grass, 2 sand
    return [0, c["tr"], 0, c["br"], 0, c["bl"], 0, c["tl"]]


def write(folder: Path, old: bool) -> Path:
    png.write(folder / "t.png", np.full((16, 256, 4), 255, np.uint8))
    if old:  # Tiled 1.4: terraintypes and terrain="tl,tr,bl,br" (0-based)
        tiles = "".join(
            f'<tile id="{i}" terrain="{",".join(str(v - 1) for v in (w[7], w[1], w[5], w[3]))}"/>'
            for i, w in ((i, wangid(i)) for i in range(16))
        )
        wang = ('<terraintypes><terrain name="grass" tile="15"/><terrain name="sand" tile="0"/>'
                "</terraintypes>" + tiles)  # fmt: skip
    else:
        wt = "".join(
            f'<wangtile tileid="{i}" wangid="{",".join(map(str, wangid(i)))}"/>' for i in range(16)
        )
        wang = ('<wangsets><wangset name="ground" type="corner" tile="-1">'
                '<wangcolor name="grass" color="#00ff00" tile="-1" probability="1"/>'
                '<wangcolor name="sand" color="#ffff00" tile="-1" probability="1"/>'
                f"{wt}</wangset></wangsets>")  # fmt: skip
    sand = 1  # tile 0: all corners sand (gid 1)
    data = ",".join([str(sand)] * 25)
    (folder / "m.tmx").write_text(
        '<map version="1.4" orientation="orthogonal" width="5" height="5" tilewidth="16" '
        'tileheight="16"><tileset firstgid="1" name="t" tilewidth="16" tileheight="16" '
        f'tilecount="16" columns="16"><image source="t.png" width="256" height="16"/>{wang}'
        f'</tileset><layer name="L" width="5" height="5"><data encoding="csv">{data}</data>'
        "</layer></map>"
    )
    return folder / "m.tmx"


@pytest.mark.parametrize("old", [False, True], ids=["wangset-1.5", "terrain-1.4"])
def test_painting_grass_picks_the_matching_corner_tiles(tmp_path: Path, old: bool) -> None:
    m = load_map(World(), write(tmp_path, old))
    m.set_terrain("L", 2, 2, "grass")
    g = m.data.layer("L").gids - 1  # tile ids
    assert g[2, 2] == 15  # all four corners grass
    # neighbours: the corners they share with the painted cell are grass
    assert g[1, 1] == BITS["br"] and g[1, 2] == BITS["bl"] | BITS["br"]
    assert g[1, 3] == BITS["bl"] and g[2, 1] == BITS["tr"] | BITS["br"]
    assert g[3, 3] == BITS["tl"] and g[3, 2] == BITS["tl"] | BITS["tr"]
    assert g[0, 0] == 0 and g[4, 4] == 0  # untouched sand
    m.set_terrain("L", 2, 2, "sand")
    assert (m.data.layer("L").gids == 1).all()


def test_unknown_colour_is_refused(tmp_path: Path) -> None:
    m = load_map(World(), write(tmp_path, False))
    with pytest.raises(TilemapError, match="no colour 'lava'"):
        m.set_terrain("L", 0, 0, "lava")
