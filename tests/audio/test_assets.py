"""The asset store: resolution against the game's folder, errors, caching, preloading.

Resolution and its errors need no pyglet; decoding tests use the headless
pyglet loaders on files generated here.
"""

from __future__ import annotations

import importlib.util
import os
import subprocess
import sys
import textwrap
from pathlib import Path

import pytest

from kge.assets import (
    AssetDecodeError,
    AssetError,
    AssetNotFoundError,
    Assets,
    SoundData,
    tone,
)
from kge.assets.fontinfo import family_name
from kge.errors import KgeError

ROOT = Path(__file__).resolve().parents[2]


def _make_assets_module():
    spec = importlib.util.spec_from_file_location("make_assets", ROOT / "tools" / "make_assets.py")
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


# -- resolution and errors (no pyglet) -----------------------------------------------------
def test_missing_asset_names_the_path_and_every_search_path(store: Assets, sound_dir: Path):
    with pytest.raises(AssetNotFoundError) as info:
        store.resolve("sfx/nope.wav")
    err = info.value
    message = str(err)
    assert "'sfx/nope.wav'" in message
    assert str(sound_dir / "sfx/nope.wav") in message
    assert str(sound_dir / "sfx" / "sfx/nope.wav") in message
    assert err.searched == (
        str(sound_dir / "sfx/nope.wav"),
        str(sound_dir / "sfx" / "sfx/nope.wav"),
    )
    # catchable the way a Python user, a kge user and DESIGN.md expect
    assert isinstance(err, FileNotFoundError)
    assert isinstance(err, ValueError)
    assert isinstance(err, KgeError)


def test_names_resolve_against_the_anchor_not_the_working_directory(
    sound_dir: Path, tmp_path_factory: pytest.TempPathFactory, monkeypatch: pytest.MonkeyPatch
):
    elsewhere = tmp_path_factory.mktemp("cwd")
    (elsewhere / "decoy.wav").write_bytes(tone(100, 0.1).to_wav())
    monkeypatch.chdir(elsewhere)
    (sound_dir / "game.py").write_text("")
    store = Assets(anchor=sound_dir / "game.py")  # a file anchors at its folder
    # default locations: the anchor folder and its assets/ subfolder
    assert store.resolve("theme.wav").path == sound_dir / "theme.wav"
    assert not store.exists("decoy.wav")  # the working directory is never searched
    store.add_path("sfx")  # relative to the anchor
    assert store.resolve("beep.wav").path == sound_dir / "sfx" / "beep.wav"
    assert str(sound_dir / "assets" / "beep.wav") in store.searched("beep.wav")


def test_relative_search_path_without_anchor_is_refused():
    store = Assets(anchor=None)
    if store.anchor is None:  # no __main__ file (interactive): relative paths are ambiguous
        with pytest.raises(ValueError, match="needs an anchor"):
            store.add_path("assets")
    else:  # under pytest __main__ has a file: the folder is taken relative to it
        store.add_path("assets")
        assert str(store.anchor / "assets" / "x.png") in store.searched("x.png")


def test_parent_escape_and_absolute_paths(store: Assets, sound_dir: Path):
    assert not store.exists("../theme.wav")  # no climbing out of the search folders
    absolute = str(sound_dir / "theme.wav")
    assert store.resolve(absolute).path == sound_dir / "theme.wav"
    with pytest.raises(AssetNotFoundError, match="missing.wav"):
        store.resolve(str(sound_dir / "missing.wav"))


def test_bad_names_are_validation_errors(store: Assets):
    with pytest.raises(ValueError, match="non-empty"):
        store.resolve("")
    with pytest.raises(ValueError):
        store.resolve(42)  # type: ignore[arg-type]


def test_package_resources(tmp_path: Path, monkeypatch: pytest.MonkeyPatch):
    pkg = tmp_path / "kgetestgame"
    (pkg / "assets" / "sfx").mkdir(parents=True)
    (pkg / "__init__.py").write_text("")
    (pkg / "data.txt").write_text("top")
    (pkg / "assets" / "sfx" / "hit.wav").write_bytes(tone(300, 0.1).to_wav())
    monkeypatch.syspath_prepend(str(tmp_path))
    store = Assets.for_module("kgetestgame")
    assert store.bytes("data.txt") == b"top"
    assert store.resolve("sfx/hit.wav").read_bytes()[:4] == b"RIFF"
    assert any(
        s == "package kgetestgame: assets/sfx/none.wav" for s in store.searched("sfx/none.wav")
    )
    # explicit "package:path" names, from any store
    other = Assets(tmp_path, anchor=tmp_path)
    assert other.bytes("kgetestgame:data.txt") == b"top"
    with pytest.raises(AssetNotFoundError, match="package kgetestgame: nothing.txt"):
        other.resolve("kgetestgame:nothing.txt")
    other.add_package("kgetestgame", "assets")
    assert other.exists("sfx/hit.wav")
    with pytest.raises(ValueError, match="not an importable package"):
        other.add_package("no_such_package_kge")


# -- decoding -------------------------------------------------------------------------------
def test_sound_is_decoded_once_and_reports_duration(store: Assets):
    first = store.sound("beep.wav")
    assert store.sound("sfx/beep.wav") is first  # same file, one decode
    assert first.duration == pytest.approx(0.25, abs=1e-3)
    assert store.is_cached("beep.wav")
    stream_a = store.sound("beep.wav", streaming=True)
    stream_b = store.sound("beep.wav", streaming=True)
    assert stream_a is not stream_b  # a stream plays on one player at a time
    generated = tone(500, 0.1)
    assert store.sound(generated) is store.sound(SoundData(generated.samples, generated.rate))


def test_undecodable_files_raise_decode_errors(store: Assets, sound_dir: Path):
    (sound_dir / "broken.wav").write_bytes(b"definitely not a wav file")
    with pytest.raises(AssetDecodeError) as info:
        store.sound("broken.wav")
    assert str(sound_dir / "broken.wav") in str(info.value)
    assert isinstance(info.value, ValueError)
    (sound_dir / "broken.png").write_bytes(b"\x89PNG nope")
    with pytest.raises(AssetDecodeError, match="broken.png"):
        store.image("broken.png")


def test_corrupt_ogg_is_refused_at_the_call_naming_the_file(store: Assets, sound_dir: Path):
    (sound_dir / "music.ogg").write_bytes(b"OggS" + bytes(200))
    with pytest.raises(AssetDecodeError) as info:
        store.sound("music.ogg")
    assert str(sound_dir / "music.ogg") in str(info.value)
    assert "not a readable sound" in str(info.value)


def test_images_load_as_pyglet_images_and_are_cached(tmp_path: Path):
    make_assets = _make_assets_module()
    png = make_assets.png_bytes(5, 3, lambda x, y: (255, 0, 0, 255) if x < 2 else (0, 0, 255, 128))
    (tmp_path / "red.png").write_bytes(png)
    store = Assets(tmp_path, anchor=tmp_path)
    image = store.image("red.png")
    assert (image.width, image.height) == (5, 3)
    assert store.image("red.png") is image
    data = image.get_image_data().get_data("RGBA", 5 * 4)
    assert tuple(data[:4]) == (255, 0, 0, 255)
    assert tuple(data[4 * 4 : 4 * 4 + 4]) == (0, 0, 255, 128)


def test_font_family_is_read_from_the_file(tmp_path: Path):
    fonts = (
        sorted(Path("/usr/share/fonts").rglob("*.ttf")) if Path("/usr/share/fonts").is_dir() else []
    )
    font_file = next((f for f in fonts if family_name(f.read_bytes())), None)
    if font_file is None:
        pytest.skip("no TrueType font installed on this machine to register")
    (tmp_path / "ui.ttf").write_bytes(font_file.read_bytes())
    store = Assets(tmp_path, anchor=tmp_path)
    font = store.font("ui.ttf")
    assert font.family == family_name(font_file.read_bytes())
    assert store.font("ui.ttf") is font
    (tmp_path / "fake.ttf").write_bytes(b"nope")
    with pytest.raises(AssetDecodeError, match="not a TrueType"):
        store.font("fake.ttf")


def test_preload_reports_progress_and_collects_failures(store: Assets):
    job = store.preload(["beep.wav", "blip.wav", "missing.wav", "theme.wav"])
    assert (job.loaded, job.queued, job.progress, job.done) == (0, 4, 0.0, False)
    assert job.step(budget=float("inf"), max_items=2) == 2  # no clock in the test
    assert (job.loaded, job.progress) == (2, 0.5)
    assert store.is_cached("beep.wav") and not store.is_cached("theme.wav")
    with pytest.raises(AssetError) as info:
        job.finish()
    assert job.done and job.loaded == 3 and list(job.failed) == ["missing.wav"]
    assert "1 of 4 assets failed" in str(info.value) and "missing.wav" in str(info.value)


# -- generated example assets ----------------------------------------------------------------
def test_make_assets_writes_small_deterministic_files(tmp_path: Path):
    make_assets = _make_assets_module()
    assert make_assets.main(["--out", str(tmp_path / "a")]) == 0
    assert make_assets.main(["--out", str(tmp_path / "b")]) == 0
    names = sorted(p.name for p in (tmp_path / "a").iterdir())
    assert {"pad_left.png", "ball.png", "ship.png", "paddle_hit.wav", "music_loop.wav"} <= set(
        names
    )
    total = 0
    for name in names:
        a = (tmp_path / "a" / name).read_bytes()
        assert a == (tmp_path / "b" / name).read_bytes(), name
        total += len(a)
    assert total < 400_000
    store = Assets(tmp_path / "a", anchor=tmp_path)
    assert store.image("pad_left.png").height == 116
    assert store.sound("music_loop.wav").duration == pytest.approx(4.0, abs=0.01)


def test_importing_assets_and_audio_does_not_import_pyglet_media():
    code = textwrap.dedent(
        """
        import sys
        import kge, kge.assets, kge.audio, kge.systems.audio, kge.components.audio
        bad = [m for m in ("pyglet.media", "pyglet.gl", "pyglet.window", "pyglet.image")
               if m in sys.modules]
        print(bad)
        """
    )
    env = {k: v for k, v in os.environ.items() if k != "PYGLET_HEADLESS"}
    out = subprocess.run(
        [sys.executable, "-c", code], capture_output=True, text=True, env=env, cwd=ROOT, check=True
    )
    assert out.stdout.strip() == "[]"


def test_relative_anchor_strings_are_module_names(tmp_path: Path, monkeypatch: pytest.MonkeyPatch):
    import kge

    assert Assets(anchor="kge").anchor == Path(kge.__file__).resolve().parent
    (tmp_path / "somewhere").mkdir()
    monkeypatch.chdir(tmp_path)
    with pytest.raises(ValueError, match="working directory"):
        Assets(anchor="somewhere")  # a folder in the cwd is not an anchor
    with pytest.raises(ValueError, match="does not exist"):
        Assets(anchor=tmp_path / "nothing")
