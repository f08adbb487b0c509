"""Aseprite JSON exports and texture-packer atlases (array and hash forms) as clips and sprites.

The sheets are generated here the way the tools write them: frames packed in a PNG,
the JSON beside it; trimmed frames cut to their opaque pixels with their offset in
the source size, rotated frames turned a quarter clockwise.
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import numpy as np
import pytest

from kge import Animator, Sprite, Transform, load_sheet
from kge.components.animation import Clip, Loop
from kge.render.images import PixelImage
from kge.render.sheets import SheetError, SheetTag, SpriteSheet
from kge.testbed import png

from .conftest import centre_colour

CELL = 8
COLOURS = [(255, 0, 0), (0, 255, 0), (0, 0, 255), (255, 255, 255), (255, 0, 255)]


def write_strip(folder: Path, name: str = "hero.png", n: int = 5) -> Path:
    """``n`` solid 8x8 frames in one row, each with a black top-left pixel."""
    arr = np.zeros((CELL, CELL * n, 4), np.uint8)
    for i in range(n):
        arr[:, i * CELL : (i + 1) * CELL, :3] = COLOURS[i % len(COLOURS)]
        arr[0, i * CELL, :3] = 0
    arr[..., 3] = 255
    png.write(folder / name, arr)
    return folder / name


def aseprite(
    n: int = 5,
    durations: list[int] | None = None,
    tags: list[dict[str, Any]] | None = None,
    slices: list[dict[str, Any]] | None = None,
    form: str = "array",
    image: str = "hero.png",
) -> dict[str, Any]:
    """What Aseprite writes for a 5-frame 8x8 sprite exported as one row."""
    durations = durations or [100] * n
    frames = [
        {
            "filename": f"hero {i}.aseprite",
            "frame": {"x": i * CELL, "y": 0, "w": CELL, "h": CELL},
            "rotated": False,
            "trimmed": False,
            "spriteSourceSize": {"x": 0, "y": 0, "w": CELL, "h": CELL},
            "sourceSize": {"w": CELL, "h": CELL},
            "duration": durations[i],
        }
        for i in range(n)
    ]
    meta: dict[str, Any] = {
        "app": "https://www.aseprite.org/",
        "version": "1.3.7-x64",
        "image": image,
        "format": "RGBA8888",
        "size": {"w": CELL * n, "h": CELL},
        "scale": "1",
        "frameTags": tags or [],
        "layers": [{"name": "Layer 1", "opacity": 255, "blendMode": "normal"}],
        "slices": slices or [],
    }
    if form == "hash":
        return {"frames": {f.pop("filename"): f for f in frames}, "meta": meta}
    return {"frames": frames, "meta": meta}


def save(folder: Path, doc: Any, name: str = "hero.json") -> Path:
    path = folder / name
    path.write_text(json.dumps(doc) if not isinstance(doc, str) else doc)
    return path


TAGS = [
    {"name": "walk", "from": 0, "to": 3, "direction": "forward", "color": "#000000ff"},
    {"name": "back", "from": 0, "to": 3, "direction": "reverse", "color": "#000000ff"},
    {"name": "bounce", "from": 1, "to": 3, "direction": "pingpong", "color": "#000000ff"},
    {"name": "bounce_back", "from": 1, "to": 3, "direction": "pingpong_reverse"},
    {"name": "twice", "from": 2, "to": 4, "direction": "pingpong", "repeat": "2"},
    {"name": "thrice", "from": 0, "to": 1, "direction": "forward", "repeat": "3"},
]


@pytest.mark.parametrize("form", ["array", "hash"])
def test_aseprite_tags_become_clips_with_the_files_durations(tmp_path: Path, form: str) -> None:
    write_strip(tmp_path)
    doc = aseprite(durations=[100, 200, 300, 400, 500], tags=TAGS, form=form)
    sheet = load_sheet(save(tmp_path, doc))
    assert [f.name for f in sheet.frames] == [f"hero {i}.aseprite" for i in range(5)]
    clips = sheet.clips()
    assert list(clips) == [t["name"] for t in TAGS]
    image = str(tmp_path / "hero.png")

    def regions(c: Clip) -> list[int]:
        assert all(f.image == image and f.region is not None for f in c.frames)
        return [f.region[0] // CELL for f in c.frames]  # type: ignore[index]

    assert regions(clips["walk"]) == [0, 1, 2, 3] and clips["walk"].loop == Loop.LOOP
    assert clips["walk"].durations == (0.1, 0.2, 0.3, 0.4)
    assert regions(clips["back"]) == [3, 2, 1, 0] and clips["back"].loop == Loop.LOOP
    assert clips["back"].durations == (0.4, 0.3, 0.2, 0.1)
    assert regions(clips["bounce"]) == [1, 2, 3] and clips["bounce"].loop == Loop.PING_PONG
    assert regions(clips["bounce_back"]) == [3, 2, 1] and clips["bounce_back"].loop == Loop.PING_PONG
    # a repeat count: that many passes (each ping-pong direction is one), then hold
    assert regions(clips["twice"]) == [2, 3, 4, 3, 2] and clips["twice"].loop == Loop.HOLD
    assert regions(clips["thrice"]) == [0, 1, 0, 1, 0, 1] and clips["thrice"].loop == Loop.HOLD
    assert sheet.clip("walk", loop=Loop.ONCE).loop == Loop.ONCE
    assert sheet.clip().frames == tuple(f.ref for f in sheet.frames)  # no tag: every frame


def test_a_sheet_without_tags_gives_one_default_clip(tmp_path: Path) -> None:
    write_strip(tmp_path)
    sheet = load_sheet(save(tmp_path, aseprite(n=3)))
    assert list(sheet.clips(speed=2.0)) == ["default"]
    clip = sheet.clips(speed=2.0)["default"]
    assert len(clip.frames) == 3 and clip.speed == 2.0


def test_slices_keys_centres_and_pivots(tmp_path: Path) -> None:
    write_strip(tmp_path)
    slices = [
        {"name": "hitbox", "color": "#0000ffff", "data": "solid", "keys": [
            {"frame": 0, "bounds": {"x": 1, "y": 2, "w": 5, "h": 6}},
            {"frame": 3, "bounds": {"x": 2, "y": 2, "w": 4, "h": 6},
             "pivot": {"x": 2, "y": 5}},
        ]},
        {"name": "panel", "keys": [
            {"frame": 0, "bounds": {"x": 0, "y": 0, "w": 8, "h": 8},
             "center": {"x": 2, "y": 2, "w": 4, "h": 4}},
        ]},
    ]  # fmt: skip
    sheet = load_sheet(save(tmp_path, aseprite(slices=slices)))
    hit = sheet.slices["hitbox"]
    assert hit.color == "#0000ffff" and hit.data == "solid"
    assert hit.at(0).bounds == (1, 2, 5, 6) and hit.at(2).bounds == (1, 2, 5, 6)  # type: ignore[union-attr]
    assert hit.at(4).bounds == (2, 2, 4, 6) and hit.at(4).pivot == (2, 5)  # type: ignore[union-attr]
    assert sheet.slices["panel"].at(0).center == (2, 2, 4, 4)  # type: ignore[union-attr]


def _sprite(colour: tuple[int, int, int], w: int, h: int) -> np.ndarray:
    """A sprite with a transparent border and an asymmetric mark (rotation shows)."""
    arr = np.zeros((h, w, 4), np.uint8)
    arr[2 : h - 1, 1 : w - 2] = (*colour, 255)
    arr[2, 1] = (0, 0, 0, 255)  # the opaque part's top-left pixel is black
    arr[2 : h - 1, w - 3] = (255, 255, 0, 255)  # its right column is yellow
    return arr


def texture_packer(folder: Path, form: str) -> tuple[Path, dict[str, np.ndarray]]:
    """Three sprites packed as TexturePacker does: 'plain' as is, 'trim' trimmed of its
    transparent border, 'turn' trimmed and turned a quarter clockwise."""
    sprites = {
        "plain.png": _sprite((200, 40, 40), 10, 12),
        "trim.png": _sprite((40, 200, 40), 10, 12),
        "turn.png": _sprite((40, 40, 200), 10, 12),
    }
    sheet = np.zeros((16, 40, 4), np.uint8)
    entries: dict[str, dict[str, Any]] = {}
    sheet[0:12, 0:10] = sprites["plain.png"]
    entries["plain.png"] = {
        "frame": {"x": 0, "y": 0, "w": 10, "h": 12}, "rotated": False, "trimmed": False,
        "spriteSourceSize": {"x": 0, "y": 0, "w": 10, "h": 12}, "sourceSize": {"w": 10, "h": 12},
        "pivot": {"x": 0.5, "y": 1.0},
    }  # fmt: skip
    opaque = sprites["trim.png"][2:11, 1:8]  # rows 2..10, columns 1..7: 7 x 9
    sheet[0:9, 12:19] = opaque
    entries["trim.png"] = {
        "frame": {"x": 12, "y": 0, "w": 7, "h": 9}, "rotated": False, "trimmed": True,
        "spriteSourceSize": {"x": 1, "y": 2, "w": 7, "h": 9}, "sourceSize": {"w": 10, "h": 12},
    }  # fmt: skip
    turned = np.rot90(sprites["turn.png"][2:11, 1:8], -1)  # a quarter clockwise: 9 wide, 7 tall
    sheet[0:7, 22:31] = turned
    entries["turn.png"] = {
        "frame": {"x": 22, "y": 0, "w": 7, "h": 9}, "rotated": True, "trimmed": True,
        "spriteSourceSize": {"x": 1, "y": 2, "w": 7, "h": 9}, "sourceSize": {"w": 10, "h": 12},
    }  # fmt: skip
    png.write(folder / "atlas.png", sheet)
    meta = {"app": "https://www.codeandweb.com/texturepacker", "version": "1.0",
            "image": "atlas.png", "format": "RGBA8888", "size": {"w": 40, "h": 16}, "scale": "1"}
    frames: Any = entries
    if form == "array":
        frames = [{"filename": k, **v} for k, v in entries.items()]
    doc = {"frames": frames, "meta": meta, "animations": {"spin": ["trim.png", "turn.png"]}}
    return save(folder, doc, "atlas.json"), sprites


def _pixels(ref: Any) -> np.ndarray:
    img = ref.image
    assert isinstance(img, PixelImage)
    return np.frombuffer(img.pixels, np.uint8).reshape(img.height, img.width, 4)[::-1]


@pytest.mark.parametrize("form", ["array", "hash"])
def test_texture_packer_frames_are_untrimmed_and_turned_back_upright(
    tmp_path: Path, form: str
) -> None:
    path, sprites = texture_packer(tmp_path, form)
    sheet = load_sheet(path)
    plain = sheet.frame("plain.png")
    assert plain.ref.region == (0, 0, 10, 12) and plain.size == (10, 12)
    assert plain.pivot == (0.5, 0.0)  # TexturePacker's (0.5, 1) from the top: bottom centre
    for name in ("trim.png", "turn.png"):
        f = sheet.frame(name)
        assert f.size == (10, 12)
        np.testing.assert_array_equal(_pixels(f.ref), sprites[name])
    spin = sheet.clips()["spin"]
    assert len(spin.frames) == 2 and spin.durations == (0.1, 0.1)
    s = sheet.sprite("plain.png", layer=3)
    assert isinstance(s, Sprite) and s.region == (0, 0, 10, 12) and s.anchor == (0.5, 0.0)
    assert s.layer == 3 and sheet.sprite("turn.png").image == sheet.frame("turn.png").ref.image


def test_phaser_multi_atlas_frames_name_their_own_image(tmp_path: Path) -> None:
    write_strip(tmp_path, "a.png", 2)
    write_strip(tmp_path, "b.png", 3)

    def tex(image: str, n: int) -> dict[str, Any]:
        return {"image": image, "format": "RGBA8888", "size": {"w": CELL * n, "h": CELL},
                "frames": [{"filename": f"{image}:{i}", "frame": {"x": i * CELL, "y": 0,
                            "w": CELL, "h": CELL}} for i in range(n)]}  # fmt: skip

    sheet = load_sheet(save(tmp_path, {"textures": [tex("a.png", 2), tex("b.png", 3)]}))
    assert [Path(f.ref.image).name for f in sheet.frames] == ["a.png"] * 2 + ["b.png"] * 3
    assert sheet.frame("b.png:2").ref.region == (16, 0, 8, 8)


def test_sheet_clips_play_in_an_app_with_the_files_timing(
    tmp_path: Path, make_app: Any
) -> None:
    """8-bit headless frames: the 'back' tag (reverse, 0.4/0.3/0.2/0.1 s) then 'bounce'."""
    write_strip(tmp_path)
    doc = aseprite(durations=[100, 200, 300, 400, 500], tags=TAGS)
    sheet = load_sheet(save(tmp_path, doc))

    def scene(world: Any) -> None:
        world.spawn(Transform(), sheet.sprite(0, size=(1.0, 1.0)),
                    Animator(sheet.clips(), current="back"))  # fmt: skip

    app = make_app(scene, fixed_dt=0.05)
    seen = []
    for _ in range(24):  # 1.2 s: frame 3 for 0.4 s, 2 for 0.3, 1 for 0.2, 0 for 0.1, 3...
        seen.append(centre_colour(app))
        app.step(1)
    starts = np.cumsum([0.0, 0.4, 0.3, 0.2, 0.1])
    expected = []
    for k in range(24):
        t = (k * 0.05 + 1e-9) % 1.0
        expected.append(COLOURS[[3, 2, 1, 0][int(np.searchsorted(starts, t, "right")) - 1]])
    assert seen == expected
    app.world.get(1, Animator).play("bounce")  # frames 1, 2, 3, 2, 1, ...: 0.2/0.3/0.4/0.3
    seen = []
    for _ in range(24):
        seen.append(centre_colour(app))
        app.step(1)
    bounce = [1, 2, 3, 2]
    starts = np.cumsum([0.0, 0.2, 0.3, 0.4, 0.3])
    expected = []
    for k in range(24):
        t = (k * 0.05 + 1e-9) % 1.2
        expected.append(COLOURS[bounce[int(np.searchsorted(starts, t, "right")) - 1]])
    assert seen == expected


def test_trimmed_frames_draw_in_their_full_box(tmp_path: Path, make_app: Any) -> None:
    path, _ = texture_packer(tmp_path, "hash")
    sheet = load_sheet(path)

    def scene(world: Any) -> None:  # 10 x 12 px frames drawn 40 x 48 px
        world.spawn(Transform(), Animator({"spin": sheet.clip("spin")}),
                    sheet.sprite("trim.png", size=(40 / 64, 48 / 64), anchor=(0.5, 0.5)))  # fmt: skip

    app = make_app(scene, fixed_dt=0.05)
    from kge.render.setup import frame_pixels

    app.render()
    px = frame_pixels(app)[..., :3].astype(int)
    # the window is 64 px: the sprite spans x 12..52, y 8..56; its opaque green body
    # covers source columns 1..6 and rows 2..10 (from the top): x 16..40, y 12..48
    assert tuple(px[30, 28]) == (40, 200, 40)
    assert tuple(px[52, 28]) == (0, 0, 0)  # the transparent top rows (trimmed away)
    app.step(2)  # 0.1 s: the rotated frame, upright again: blue body, yellow right column
    app.render()
    px = frame_pixels(app)[..., :3].astype(int)
    assert tuple(px[30, 28]) == (40, 40, 200)
    assert tuple(px[30, 42]) == (255, 255, 0)  # source column 7: x 40..44


def test_frames_of_a_clip_must_share_a_size(tmp_path: Path) -> None:
    write_strip(tmp_path)
    doc = aseprite(n=2, tags=[{"name": "t", "from": 0, "to": 1, "direction": "forward"}])
    doc["frames"][1]["frame"]["w"] = 4
    doc["frames"][1]["sourceSize"] = {"w": 4, "h": CELL}
    sheet = load_sheet(save(tmp_path, doc))
    with pytest.raises(SheetError, match="mixes frame sizes"):
        sheet.clip("t")


def test_sheets_through_the_asset_store(tmp_path: Path) -> None:
    from kge.assets import Assets

    (tmp_path / "art").mkdir()
    write_strip(tmp_path / "art")
    save(tmp_path / "art", aseprite(tags=TAGS[:1]))
    store = Assets(tmp_path, anchor=tmp_path)
    sheet = load_sheet("art/hero.json", store)
    assert sheet.frames[0].ref.image == "art/hero.png"
    assert isinstance(sheet, SpriteSheet) and len(sheet.clip("walk").frames) == 4
    bad = aseprite(image="../secret.png")
    save(tmp_path / "art", bad, "bad.json")
    with pytest.raises(SheetError, match="leaves the sheet's folder"):
        load_sheet("art/bad.json", store)


def test_tag_order_doctest_cases() -> None:
    assert SheetTag("t", 0, 0, "pingpong", repeat=3).order() == [0, 0, 0]
    assert SheetTag("t", 0, 2, "pingpong_reverse", repeat=2).order() == [2, 1, 0, 1, 2]
