"""Bad-input catalogue for sprite-sheet JSON: each hostile or malformed file gives a
SheetError naming the file and the field, reads nothing outside the sheet's folder and
allocates nothing large."""

from __future__ import annotations

import json
from collections.abc import Callable
from pathlib import Path
from typing import Any

import numpy as np
import pytest

from kge.render.sheets import SheetError, load_sheet
from kge.testbed import png

from .test_sheets import TAGS, aseprite, write_strip


def _with(**changes: Any) -> Callable[[dict[str, Any]], None]:
    def edit(doc: dict[str, Any]) -> None:
        for dotted, value in changes.items():
            target: Any = doc
            *path, last = dotted.split(".")
            for part in path:
                target = target[int(part)] if part.isdigit() else target[part]
            if value is _DELETE:
                del target[int(last) if last.isdigit() else last]
            else:
                target[int(last) if last.isdigit() else last] = value

    return edit


_DELETE = object()

#: (id, an edit of a valid 5-frame Aseprite export with TAGS, or raw file text, message)
CASES: list[tuple[str, Any, str]] = [
    ("empty-file", "", r"not valid JSON"),
    ("truncated-json", '{"frames": [{"frame": ', r"not valid JSON"),
    ("not-utf8", b"\xff\xfe\x00{", r"not valid JSON"),
    ("json-array", "[1, 2, 3]", r"not a sprite sheet"),
    ("deep-nesting", "[" * 100_000 + "]" * 100_000, r"not valid JSON|not a sprite sheet"),
    ("no-frames", '{"meta": {"image": "hero.png"}}', r"no 'frames'"),
    ("frames-a-number", _with(frames=7), r"'frames' is int, not a list or an object"),
    ("no-frames-at-all", _with(frames=[]), r"has no frames"),
    ("frame-not-object", _with(**{"frames.1": "x"}), r"frames\[1\] is str"),
    ("frame-no-rect", _with(**{"frames.0.frame": _DELETE}), r"frames\[0\].frame is NoneType"),
    ("frame-width-zero", _with(**{"frames.0.frame.w": 0}), r"frames\[0\].frame.w = 0 is below 1"),
    ("frame-negative-x", _with(**{"frames.2.frame.x": -8}), r"frames\[2\].frame.x = -8 is below 0"),
    ("frame-nan", _with(**{"frames.0.frame.y": float("nan")}), r"frame.y = nan is not a whole number"),
    ("frame-fractional", _with(**{"frames.0.frame.w": 7.5}), r"frame.w = 7.5 is not a whole number"),
    ("frame-huge", _with(**{"frames.0.frame.w": 2**40}), r"frame.w = 1,099,511,627,776 is above"),
    ("frame-string", _with(**{"frames.0.frame.x": "0"}), r"frame.x = '0' is not a number"),
    ("frame-bool", _with(**{"frames.0.frame.h": True}), r"frame.h = True is not a number"),
    ("frame-outside-image", _with(**{"frames.4.frame.x": 36}), r"frames\[4\].frame .* is outside the 40x8 image"),
    ("rotated-outside-image", _with(**{"frames.4.rotated": True, "frames.4.frame.x": 34, "frames.4.frame.w": 4}), r"\(34, 0, 8, 4 as stored\) is outside the 40x8 image"),
    ("rotated-not-bool", _with(**{"frames.0.rotated": "yes"}), r"rotated = 'yes' is not true or false"),
    ("trim-outside-source", _with(**{"frames.0.trimmed": True, "frames.0.spriteSourceSize.x": 3}), r"does not fit its source size 8x8"),
    ("source-size-zero", _with(**{"frames.0.sourceSize.w": 0}), r"sourceSize.w = 0 is below 1"),
    ("source-size-not-object", _with(**{"frames.0.sourceSize": [8, 8]}), r"sourceSize is list"),
    ("duration-zero", _with(**{"frames.0.duration": 0}), r"duration = 0 is below 1"),
    ("duration-negative", _with(**{"frames.3.duration": -100}), r"frames\[3\].duration = -100 is below 1"),
    ("duration-inf", _with(**{"frames.3.duration": float("inf")}), r"duration = inf is not a whole number"),
    ("pivot-nan", _with(**{"frames.0.pivot": {"x": float("nan"), "y": 0}}), r"pivot.x = nan is not a finite number"),
    ("meta-not-object", _with(meta=[1]), r"'meta' is list"),
    ("no-image", _with(**{"meta.image": _DELETE}), r"meta.image must name the sheet image"),
    ("image-empty-name", _with(**{"meta.image": ""}), r"meta.image must name the sheet image"),
    ("image-nul", _with(**{"meta.image": "he\x00ro.png"}), r"meta.image must name the sheet image"),
    ("image-climbs-out", _with(**{"meta.image": "../../../../etc/passwd"}), r"is outside the folders this sheet may read"),
    ("image-absolute", _with(**{"meta.image": "/etc/hostname"}), r"'/etc/hostname' is outside the folders"),
    ("image-missing", _with(**{"meta.image": "gone.png"}), r"the sheet image .*gone.png' not found"),
    ("image-dev-zero", _with(**{"meta.image": "zero.png"}), r"is not a regular file|outside the folders"),
    ("image-not-an-image", _with(**{"meta.image": "hero.json"}), r"is not a readable image"),
    ("image-zero-bytes", _with(**{"meta.image": "empty.png"}), r"is not a readable image"),
    ("tags-not-list", _with(**{"meta.frameTags": {"a": 1}}), r"meta.frameTags is dict"),
    ("tag-not-object", _with(**{"meta.frameTags": [3]}), r"meta.frameTags\[0\] is int"),
    ("tag-no-name", _with(**{"meta.frameTags.0.name": ""}), r"frameTags\[0\].name must be a non-empty string"),
    ("tag-past-the-end", _with(**{"meta.frameTags.0.to": 5}), r"'walk'\): frames 0..5, but the sheet has 5 frames"),
    ("tag-backwards", _with(**{"meta.frameTags.0.from": 3, "meta.frameTags.0.to": 1}), r"to = 1 is before from = 3"),
    ("tag-negative", _with(**{"meta.frameTags.0.from": -1}), r"from = -1 is below 0"),
    ("tag-direction", _with(**{"meta.frameTags.0.direction": "sideways"}), r"direction = 'sideways' \(Aseprite writes forward"),
    ("tag-repeat-junk", _with(**{"meta.frameTags.4.repeat": "two"}), r"repeat = 'two' is not a count"),
    ("tag-repeat-huge", _with(**{"meta.frameTags.4.repeat": "1000000"}), r"repeat = 1,000,000 is above 10,000"),
    ("tag-twice", _with(**{"meta.frameTags.1.name": "walk"}), r"a second tag called 'walk'"),
    ("slices-not-list", _with(**{"meta.slices": "x"}), r"meta.slices is str"),
    ("slice-no-keys", _with(**{"meta.slices": [{"name": "s", "keys": []}]}), r"'s'\).keys must be a non-empty list"),
    ("slice-bad-bounds", _with(**{"meta.slices": [{"name": "s", "keys": [{"frame": 0, "bounds": {"x": 0, "y": 0, "w": -2, "h": 1}}]}]}), r"bounds.w = -2 is below 0"),
    ("animations-not-object", _with(animations=[1]), r"'animations' is list"),
    ("animation-unknown-frame", _with(animations={"a": ["nope.png"]}), r"animations\['a'\]\[0\] names no frame: 'nope.png'"),
    ("animation-empty", _with(animations={"a": []}), r"animations\['a'\] must be a non-empty list"),
    ("multi-atlas-empty", '{"textures": []}', r"'textures' must be a non-empty list"),
    ("multi-atlas-not-object", '{"textures": [5]}', r"textures\[0\] is int"),
]  # fmt: skip


@pytest.mark.parametrize(("case", "spec", "message"), CASES, ids=[c[0] for c in CASES])
def test_bad_sheet_is_refused_naming_the_file(
    tmp_path: Path, case: str, spec: Any, message: str
) -> None:
    folder = tmp_path / "game" / "art"
    folder.mkdir(parents=True)
    write_strip(folder)
    (folder / "empty.png").write_bytes(b"")
    (folder / "zero.png").symlink_to("/dev/zero")
    path = folder / "hero.json"
    if isinstance(spec, bytes):
        path.write_bytes(spec)
    elif isinstance(spec, str):
        path.write_text(spec)
    else:
        doc = aseprite(tags=[dict(t) for t in TAGS])
        spec(doc)
        path.write_text(json.dumps(doc))
    with pytest.raises(SheetError, match=message) as err:
        load_sheet(path)
    assert str(path) in str(err.value)  # names the file


def test_a_large_image_is_refused_before_decoding(tmp_path: Path) -> None:
    """A PNG header claiming 20,000 x 20,000 pixels: refused from the header."""
    import struct
    import zlib

    def chunk(kind: bytes, data: bytes) -> bytes:
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))

    ihdr = struct.pack(">IIBBBBB", 20_000, 20_000, 8, 6, 0, 0, 0)
    (tmp_path / "big.png").write_bytes(
        b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", ihdr) + chunk(b"IDAT", zlib.compress(b"")) + chunk(b"IEND", b"")
    )
    doc = aseprite(image="big.png")
    (tmp_path / "s.json").write_text(json.dumps(doc))
    with pytest.raises(SheetError, match=r"'.*big.png' claims 20000x20000 pixels"):
        load_sheet(tmp_path / "s.json")


def test_roots_let_a_sheet_read_a_shared_folder(tmp_path: Path) -> None:
    shared = tmp_path / "shared"
    shared.mkdir()
    png.write(shared / "hero.png", np.full((8, 40, 4), 255, np.uint8))
    (tmp_path / "art").mkdir()
    (tmp_path / "art" / "s.json").write_text(json.dumps(aseprite(image="../shared/hero.png")))
    with pytest.raises(SheetError, match="outside the folders"):
        load_sheet(tmp_path / "art" / "s.json")
    sheet = load_sheet(tmp_path / "art" / "s.json", roots=[shared])
    assert sheet.frames[0].ref.image == str(shared / "hero.png")
