"""Background asset loading: worker threads decode, the main thread finishes in order,
progress and the done event are values (workers are held back with events, never timed)."""

from __future__ import annotations

import threading
from pathlib import Path
from typing import Any

import pytest
from PIL import Image

from kge import App, World
from kge.assets import Assets, AssetsLoaded, BackgroundPreload, loaders, sounds
from kge.assets.errors import AssetError
from kge.components.ui import ProgressBar
from kge.errors import KgeError, ValidationError
from kge.sound import tone
from kge.systems.loading import LoadingScreen
from kge.transitions import Fade


@pytest.fixture
def store(tmp_path: Path) -> Assets:
    Image.new("RGBA", (6, 4), (255, 0, 0, 255)).save(tmp_path / "ship.png")
    (tmp_path / "hit.wav").write_bytes(tone(440, 0.25, rate=8000).to_wav())
    (tmp_path / "level.tmx").write_text("<map/>")
    (tmp_path / "broken.png").write_bytes(b"\x89PNG not really")
    return Assets(tmp_path, anchor=tmp_path)


@pytest.fixture
def gate(monkeypatch: pytest.MonkeyPatch) -> threading.Event:
    """Images stay in their worker until the test sets this (a slow decode, untimed)."""
    opened = threading.Event()
    real = loaders.decode_image

    def held(found: Any) -> Any:
        opened.wait()
        return real(found)

    monkeypatch.setattr(loaders, "decode_image", held)
    return opened


def _record_threads(monkeypatch: pytest.MonkeyPatch, module: Any, name: str) -> list[str]:
    seen: list[str] = []
    real = getattr(module, name)

    def spy(*args: Any) -> Any:
        seen.append(threading.current_thread().name)
        return real(*args)

    monkeypatch.setattr(module, name, spy)
    return seen


def test_workers_decode_and_the_main_thread_finishes(
    store: Assets, monkeypatch: pytest.MonkeyPatch
) -> None:
    pillow = _record_threads(monkeypatch, loaders, "decode_image")
    soundfile = _record_threads(monkeypatch, sounds, "decode")
    uploads = _record_threads(monkeypatch, loaders, "image_from_pixels")
    job = store.preload(["ship.png", "hit.wav", "level.tmx"], background=True)
    assert isinstance(job, BackgroundPreload)
    job.wait()
    assert job.decoded == 3 and job.progress == 0.0 and not store.is_cached("ship.png")
    assert job.step(budget=float("inf"), max_items=2) == 2 and job.progress == pytest.approx(2 / 3)
    assert job.step(budget=float("inf")) == 1 and job.done and job.progress == 1.0
    main = threading.current_thread().name
    assert pillow and soundfile and all(t != main for t in pillow + soundfile)
    assert uploads == [main]  # pyglet objects are made on the main thread
    image = job.result("ship.png")
    assert (image.width, image.height) == (6, 4)
    assert store.image("ship.png") is image  # cached as a plain load would be
    assert job.result("hit.wav").duration == pytest.approx(0.25, abs=1e-3)
    assert store.sound("hit.wav") is job.result("hit.wav")
    assert job.result("level.tmx") == b"<map/>"
    assert job.event() == AssetsLoaded(3, 3, ())


def test_a_step_never_waits_for_a_worker_and_keeps_the_given_order(
    store: Assets, gate: threading.Event
) -> None:
    job = BackgroundPreload(store, ["ship.png", "level.tmx"], workers=2)
    for _ in range(3):  # frames go on while the image is stuck in its worker
        assert job.step(budget=float("inf")) == 0
    assert (job.loaded, job.progress, job.done) == (0, 0.0, False)
    gate.set()
    job.wait()
    assert job.step(budget=float("inf")) == 2 and job.loaded == 2


def test_failures_are_collected_and_named_at_finish(store: Assets) -> None:
    job = store.preload(["ship.png", "broken.png", "missing.ogg"], background=True)
    with pytest.raises(AssetError, match=r"2 of 3 assets failed") as info:
        job.finish()
    assert "broken.png" in str(info.value) and "missing.ogg" in str(info.value)
    assert job.done and job.loaded == 1 and sorted(job.failed) == ["broken.png", "missing.ogg"]
    assert job.event() == AssetsLoaded(3, 1, ("broken.png", "missing.ogg"))
    with pytest.raises(ValidationError, match="'broken.png' failed"):
        job.result("broken.png")


def test_bad_arguments_are_refused_at_the_call(store: Assets) -> None:
    with pytest.raises(ValidationError, match="workers must be an int >= 1"):
        BackgroundPreload(store, ["ship.png"], workers=0)
    job = store.preload(["ship.png"], background=True)
    with pytest.raises(ValidationError, match="'ship.png' is not loaded yet"):
        job.result("ship.png")
    with pytest.raises(KgeError, match="LoadingScreen.background"):
        LoadingScreen(["ship.png"], then=lambda world: None, background="yes")  # type: ignore[arg-type]
    job.finish()


def test_the_loading_screen_draws_while_workers_decode_then_says_done(
    store: Assets, gate: threading.Event
) -> None:
    done: list[AssetsLoaded] = []

    class Level2:
        pass

    def next_level(world: World) -> None:
        world.insert_resource(Level2())

    screen = LoadingScreen(["hit.wav", "ship.png", "level.tmx"], then=next_level, store=store,
                           background=True, transition=Fade(0.1), items_per_frame=10)  # fmt: skip
    app = App(screen, headless=True)
    loading = app.world
    for _ in range(5):  # the image is held in its worker: the frames still run
        app.step()
        ((_, (bar,)),) = loading.query(ProgressBar)
        assert bar.value < 1.0
    gate.set()
    assert isinstance(screen.preload, BackgroundPreload)
    screen.preload.wait()
    app.step()
    done += loading.events(AssetsLoaded)
    assert done == [AssetsLoaded(3, 3, ())]
    ((_, (bar,)),) = loading.query(ProgressBar)
    assert bar.value == 1.0
    app.step(8)
    assert app.world is not loading and app.world.try_resource(Level2) is not None
