"""An App dropped without ``close()``: its sounds stop on the main thread, not in GC.

A garbage-collection pass runs finalizers on the thread that triggered it, pyglet's
media thread included, inside pyglet's own code; stopping a player from there
deadlocked against the main thread starting one (a CI run hung in
``PlayerWorkerThread.add``). The finalizer now only queues the App's mixer.
"""

from __future__ import annotations

import gc
import threading

import pytest

from kge import World
from kge.assets import Assets
from kge.audio import Audio
from kge.audio.mixer import Mixer
from kge.components.audio import AudioSource
from kge.systems import audio as audio_system
from tests.audio.conftest import make_app, with_store


def test_a_collected_app_is_silenced_later_on_the_main_thread(
    store: Assets, monkeypatch: pytest.MonkeyPatch
) -> None:
    gc.collect()
    audio_system.close_orphans()  # earlier tests' dropped Apps
    closed_on: list[threading.Thread] = []
    original = Mixer.close

    def close(self: Mixer) -> None:
        closed_on.append(threading.current_thread())
        original(self)

    monkeypatch.setattr(Mixer, "close", close)
    ids: dict[str, int] = {}

    def setup(world: World) -> None:
        ids["e"] = world.spawn(AudioSource("beep.wav", play_on_start=True, loop=True))

    app = make_app(with_store(store, setup))
    app.step(1)
    handle = app.world.resource(Audio).source_handle(ids["e"])
    assert handle is not None and handle.playing
    del app
    collector = threading.Thread(target=gc.collect)  # as pyglet's media thread might
    collector.start()
    collector.join()
    gc.collect()
    assert closed_on == [] and handle.playing  # queued, not stopped inside the GC pass
    assert audio_system._orphans
    later = make_app(with_store(store))  # the next App's audio closes it, on this thread
    assert closed_on and set(closed_on) == {threading.main_thread()} and handle.finished
    assert not audio_system._orphans
    later.close()
