"""Bad-input catalogue for maps: truncated and hostile files each give a TilemapError
naming the file and what is wrong, allocate nothing large, and leave the world unchanged.
"""

from __future__ import annotations

import base64
import gzip
import json
import zlib
from collections.abc import Callable
from pathlib import Path

import numpy as np
import pytest

from kge.systems.physics import PhysicsPlugin
from kge.testbed import png
from kge.tilemap import MapLimits, TilemapError, load_map
from kge.world import World

HEAD = '<?xml version="1.0"?>\n<map version="1.10" orientation="orthogonal" width="{w}" height="{h}" tilewidth="16" tileheight="16"{extra}>'
TS = '<tileset firstgid="{first}" name="t" tilewidth="16" tileheight="16" tilecount="{count}" columns="{cols}"><image source="{img}" width="32" height="16"/>{tiles}</tileset>'


def tmx(w: int = 2, h: int = 2, data: str = '<data encoding="csv">1,2,0,1</data>', *,
        extra: str = "", first: str = "1", count: str = "2", cols: str = "2",
        img: str = "t.png", tiles: str = "", layers: str = "", tileset: str | None = None) -> str:
    ts = tileset if tileset is not None else TS.format(
        first=first, count=count, cols=cols, img=img, tiles=tiles)
    layer = f'<layer name="L" width="{w}" height="{h}">{data}</layer>' if data else ""
    return HEAD.format(w=w, h=h, extra=extra) + ts + layer + layers + "</map>"


def b64(raw: bytes) -> str:
    return base64.b64encode(raw).decode()


U32 = np.array([1, 2, 0, 1], "<u4").tobytes()
ZLIB = zlib.compress(U32)
GZ = gzip.compress(U32)


def nested(n: int) -> str:
    return "<group name='g'>" * n + "</group>" * n


def json_map(**over: object) -> str:
    doc: dict[str, object] = {
        "type": "map", "orientation": "orthogonal", "width": 2, "height": 2, "tilewidth": 16,
        "tileheight": 16, "infinite": False, "layers": [{"type": "tilelayer", "name": "L",
        "width": 2, "height": 2, "data": [1, 2, 0, 1]}], "tilesets": [{"firstgid": 1,
        "name": "t", "tilewidth": 16, "tileheight": 16, "tilecount": 2, "columns": 2,
        "image": "t.png", "imagewidth": 32, "imageheight": 16}]}  # fmt: skip
    doc.update(over)
    return json.dumps(doc)


#: (id, file name, text or a function of the folder writing the files, expected message)
CASES: list[tuple[str, str, str | Callable[[Path], object], str]] = [
    ("huge-grid-200-bytes", "m.tmx", tmx(100_000, 100_000, ""), r"width x height in tiles is 10,000,000,000, above the limit"),
    ("negative-width", "m.tmx", tmx(-3, 2, ""), r"map: width = -3 is below 0"),
    ("tilecount-2^31", "m.tmx", tmx(count="2147483648"), r"tilecount is 2,147,483,648, above the limit"),
    ("negative-tilecount", "m.tmx", tmx(count="-5"), r"tilecount = -5 is below 0"),
    ("negative-columns", "m.tmx", tmx(cols="-1"), r"columns = -1 is below 0"),
    ("firstgid-2^40", "m.tmx", tmx(first=str(2**40)), r"firstgid is 1,099,511,627,776, above the limit"),
    ("firstgid-0", "m.tmx", tmx(first="0"), r"firstgid = 0 is below 1"),
    ("gid-2^64-csv", "m.tmx", tmx(data=f'<data encoding="csv">1,{2**64},0,1</data>'), r"tile value '18446744073709551616' is not a gid"),
    ("gid-2^32-csv", "m.tmx", tmx(data=f'<data encoding="csv">1,{2**32},0,1</data>'), r"tile value 4294967296 is not a gid"),
    ("negative-gid-csv", "m.tmx", tmx(data='<data encoding="csv">1,-2,0,1</data>'), r"tile value -2 is not a gid"),
    ("gid-in-no-tileset", "m.tmx", tmx(data='<data encoding="csv">1,9,0,1</data>'), r"tile id 9 at column 1, row 0 is in no tileset"),
    ("fewer-csv-values", "m.tmx", tmx(data='<data encoding="csv">1,2,0</data>'), r"3 tile values, expected 4"),
    ("more-csv-values", "m.tmx", tmx(data='<data encoding="csv">1,2,0,1,1</data>'), r"5 tile values, expected 4"),
    ("csv-junk", "m.tmx", tmx(data='<data encoding="csv">1,x,0,1</data>'), r"tile value 'x' is not a gid"),
    ("unknown-encoding", "m.tmx", tmx(data='<data encoding="base32">AAAA</data>'), r"unknown tile data encoding 'base32'"),
    ("unknown-compression", "m.tmx", tmx(data='<data encoding="base64" compression="lzma">AAAA</data>'), r"unknown compression 'lzma'"),
    ("corrupt-base64", "m.tmx", tmx(data='<data encoding="base64">!!!!</data>'), r"base64 tile data is corrupt"),
    ("short-base64", "m.tmx", tmx(data=f'<data encoding="base64">{b64(U32[:12])}</data>'), r"3 tile values after decoding, expected 4"),
    ("truncated-zlib", "m.tmx", tmx(data=f'<data encoding="base64" compression="zlib">{b64(ZLIB[:-6])}</data>'), r"(truncated|corrupt zlib|after decoding)"),
    ("corrupt-zlib", "m.tmx", tmx(data=f'<data encoding="base64" compression="zlib">{b64(b"xx" + ZLIB)}</data>'), r"corrupt zlib data"),
    ("truncated-gzip", "m.tmx", tmx(data=f'<data encoding="base64" compression="gzip">{b64(GZ[:-10])}</data>'), r"(truncated|corrupt gzip|after decoding)"),
    ("zlib-bomb", "m.tmx", tmx(data=f'<data encoding="base64" compression="zlib">{b64(zlib.compress(bytes(50_000_000)))}</data>'), r"oversized zlib data"),
    ("corrupt-zstd", "m.tmx", tmx(data='<data encoding="base64" compression="zstd">AAAAAAAA</data>'), r"corrupt zstd data"),
    ("image-climbs-out", "m.tmx", tmx(img="../../../../etc/passwd"), r"is outside the folders this map may read"),
    ("image-absolute", "m.tmx", tmx(img="/etc/hostname"), r"'/etc/hostname' is outside the folders this map may read"),
    ("image-missing", "m.tmx", tmx(img="nope.png"), r"tileset 't': image '.*nope.png' not found"),
    ("image-not-an-image", "m.tmx", lambda d: (d / "t.png").write_text("hello"), r"is not a readable image"),
    ("image-zero-bytes", "m.tmx", lambda d: (d / "t.png").write_bytes(b""), r"is not a readable image"),
    ("tileset-dev-zero", "m.tmx", tmx(tileset='<tileset firstgid="1" source="z.tsx"/>'), r"(not a regular file|outside the folders)"),
    ("tileset-outside", "m.tmx", tmx(tileset='<tileset firstgid="1" source="/etc/hostname"/>'), r"outside the folders this map may read"),
    ("tileset-missing", "m.tmx", tmx(tileset='<tileset firstgid="1" source="gone.tsx"/>'), r"tileset '.*gone.tsx' not found"),
    ("tileset-no-tilewidth", "m.tmx", tmx(tileset='<tileset firstgid="1" name="t"><image source="t.png"/></tileset>'), r"has no 'tilewidth' \(Tiled 0.9 and later write it\); re-save it in Tiled 1.9"),
    ("template-loop", "m.tmx", tmx(layers='<objectgroup name="o"><object id="1" template="a.tx"/></objectgroup>'), r"template loop"),
    ("template-outside", "m.tmx", tmx(layers='<objectgroup name="o"><object id="1" template="/etc/hostname"/></objectgroup>'), r"outside the folders this map may read"),
    ("nested-3000-groups", "m.tmx", tmx(layers=nested(3000)), r"group layers nest deeper than 100"),
    ("xml-entities", "m.tmx", '<?xml version="1.0"?><!DOCTYPE m [<!ENTITY a "aaaa">]><map/>', r"DOCTYPE or entities"),
    ("truncated-xml", "m.tmx", tmx()[:150], r"not well-formed XML"),
    ("not-a-map", "m.tmx", "<tileset/>", r"not a Tiled map"),
    ("zero-byte-map", "m.tmx", "", r"not well-formed XML"),
    ("unknown-orientation", "m.tmx", tmx().replace("orthogonal", "oblique"), r"orientation 'oblique' is not a Tiled orientation"),
    ("infinite-chunks-2e9-apart", "m.tmx", tmx(2, 2, '<data encoding="csv"><chunk x="0" y="0" width="2" height="2">1,1,1,1</chunk><chunk x="2000000000" y="0" width="2" height="2">1,1,1,1</chunk></data>', extra=' infinite="1"'), r"chunks' span .* above the limit"),
    ("object-gid-2^40", "m.tmx", tmx(layers=f'<objectgroup name="o"><object id="1" gid="{2**40}" x="0" y="0"/></objectgroup>'), r"gid 1099511627776 is not a gid"),
    ("animation-missing-tile", "m.tmx", tmx(tiles='<tile id="0"><animation><frame tileid="7" duration="100"/></animation></tile>'), r"animation frame names tile 7, which does not exist"),
    ("wang-color-undefined", "m.tmx", tmx(tiles='').replace("</tileset>", '<wangsets><wangset name="w" type="corner"><wangcolor name="a" color="#ff0000" tile="-1" probability="1"/><wangtile tileid="0" wangid="0,3,0,3,0,3,0,3"/></wangset></wangsets></tileset>'), r"names a colour it does not define"),
    ("json-truncated", "m.json", json_map()[:60], r"not valid JSON"),
    ("json-not-object", "m.json", "[1, 2, 3]", r"not a Tiled map"),
    ("json-layers-not-list", "m.json", json_map(layers={"a": 1}), r"'layers' is dict, not a list"),
    ("json-layer-not-object", "m.json", json_map(layers=[7]), r"a layer is int, not a JSON object"),
    ("json-data-junk", "m.json", json_map(layers=[{"type": "tilelayer", "name": "L", "width": 2, "height": 2, "data": [1, "x", 0, 1]}]), r"is not a gid"),
    ("json-gid-2^64", "m.json", json_map(layers=[{"type": "tilelayer", "name": "L", "width": 2, "height": 2, "data": [1, 2**64, 0, 1]}]), r"is not a gid"),
    ("json-width-string", "m.json", json_map(width="wide"), r"width = 'wide' is not a finite number"),
    ("json-nested-3000", "m.json", '{"type":"map","layers":' + '[{"type":"group","layers":' * 3000 + "[]" + "}]" * 3000 + "}", r"(nest)"),
    ("json-unknown-layer-type", "m.json", json_map(layers=[{"type": "hologram", "name": "h"}]), r"unknown type 'hologram'"),
    ("json-tilewidth-zero", "m.json", json_map(tilewidth=0), r"tilewidth = 0 is below 1"),
    ("json-opacity-nan", "m.json", json_map(layers=[{"type": "tilelayer", "name": "L", "width": 2, "height": 2, "data": [1, 2, 0, 1], "opacity": "nan"}]), r"opacity = 'nan' is not a finite number"),
    ("json-bad-tint", "m.json", json_map(layers=[{"type": "tilelayer", "name": "L", "width": 2, "height": 2, "data": [1, 2, 0, 1], "tintcolor": "#zz"}]), r"tintcolor '#zz' is not a colour"),
    ("tilesets-overlap", "m.tmx", tmx(tileset=TS.format(first=1, count=2, cols=2, img="t.png", tiles="") + TS.format(first=2, count=2, cols=2, img="t.png", tiles="")), r"overlap: a firstgid is wrong"),
]  # fmt: skip


def _prepare(folder: Path, name: str, spec: str | Callable[[Path], object]) -> Path:
    png.write(folder / "t.png", np.full((16, 32, 4), 200, np.uint8))
    (folder / "a.tx").write_text('<template><object template="b.tx"/></template>')
    (folder / "b.tx").write_text('<template><object template="a.tx"/></template>')
    z = folder / "z.tsx"
    if not z.exists():
        z.symlink_to("/dev/zero")
    path = folder / name
    if callable(spec):
        path.write_text(tmx())
        spec(folder)
    else:
        path.write_text(spec)
    return path


@pytest.mark.parametrize(("case", "name", "spec", "message"), CASES, ids=[c[0] for c in CASES])
def test_bad_map_is_refused_at_load_and_leaves_the_world_unchanged(
    tmp_path: Path, case: str, name: str, spec: str | Callable[[Path], object], message: str
) -> None:
    folder = tmp_path / "game" / "levels"
    folder.mkdir(parents=True)
    path = _prepare(folder, name, spec)
    world = World()
    world.add_plugins(PhysicsPlugin())
    before = len(list(world.entities()))
    with pytest.raises(TilemapError, match=message) as err:
        load_map(world, path)
    assert name in str(err.value) or str(folder) in str(err.value)  # names the file
    assert len(list(world.entities())) == before


def test_limits_are_a_game_setting(tmp_path: Path) -> None:
    path = _prepare(tmp_path, "m.tmx", tmx(40, 40, '<data encoding="csv">' + ",".join(["1"] * 1600) + "</data>"))
    world = World()
    with pytest.raises(TilemapError, match=r"MapLimits.tiles"):
        load_map(world, path, limits=MapLimits(tiles=1000))
    assert load_map(world, path, limits=MapLimits(tiles=1600)).data.cols == 40


def test_roots_let_a_map_read_a_shared_folder(tmp_path: Path) -> None:
    shared = tmp_path / "shared"
    shared.mkdir()
    png.write(shared / "t.png", np.full((16, 32, 4), 200, np.uint8))
    (tmp_path / "levels").mkdir()
    path = tmp_path / "levels" / "m.tmx"
    path.write_text(tmx(img="../shared/t.png"))
    with pytest.raises(TilemapError, match="outside the folders"):
        load_map(World(), path)
    assert load_map(World(), path, roots=[shared]).data.tiles.images == [shared / "t.png"]


def test_set_tile_on_an_unloaded_map_spawns_nothing(tmp_path: Path) -> None:
    path = _prepare(tmp_path, "m.tmx", tmx())
    world = World()
    world.add_plugins(PhysicsPlugin())
    m = load_map(world, path, solid_layers=["L"])
    m.unload()
    world.flush()
    n = len(list(world.entities()))
    with pytest.raises(TilemapError, match="unloaded"):
        m.set_tile("L", 1, 1, 1)
    assert len(list(world.entities())) == n
