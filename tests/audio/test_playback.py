"""Playing sounds through the Audio resource on pyglet's silent driver.

The silent driver keeps real pyglet ``Player`` objects (volume, pitch, loop,
playing, source, end-of-stream events) without a sound device, so these tests
check what the players are told, not what a speaker does.
"""

from __future__ import annotations

import time
from pathlib import Path

import pytest

from kge import World
from kge.assets import AssetNotFoundError, Assets, tone
from kge.audio import Audio, SoundHandle
from tests.audio.conftest import BEEP_SECONDS, make_app, with_store


def audio_of(app) -> Audio:
    return app.world.resource(Audio)


def test_generated_wav_plays_and_reports_its_duration(store: Assets):
    app = make_app(with_store(store))
    audio = audio_of(app)
    handle = audio.play("beep.wav")
    assert isinstance(handle, SoundHandle)
    assert audio.mixer.driver_name == "SilentDriver"
    assert handle.duration == pytest.approx(BEEP_SECONDS, abs=1e-3)
    assert handle.player.source.duration == pytest.approx(BEEP_SECONDS, abs=1e-3)
    assert handle.playing and handle.player.playing
    app.step(1)
    assert handle in audio.handles
    # a SoundData made in code plays the same way
    blip = audio.play(tone(1000, 0.1))
    assert blip.duration == pytest.approx(0.1, abs=1e-3) and blip.playing


def test_volume_pitch_loop_pause_stop_reach_the_player(store: Assets):
    app = make_app(with_store(store))
    audio = audio_of(app)
    h = audio.play("beep.wav", volume=0.5, pitch=1.5, loop=True)
    player = h.player
    assert (player.volume, player.pitch, player.loop) == (0.5, 1.5, True)
    h.volume = 0.25
    h.pitch = 0.5
    h.loop = False
    assert (player.volume, player.pitch, player.loop) == (0.25, 0.5, False)
    audio.master_volume = 0.5
    assert player.volume == pytest.approx(0.125)
    audio.sfx_volume = 0.5
    assert player.volume == pytest.approx(0.0625)
    audio.master_volume = 1.0
    audio.sfx_volume = 1.0
    h.pause()
    assert h.paused and not h.playing and not player.playing
    h.resume()
    assert h.playing and player.playing
    h.stop()
    assert h.finished and not h.playing and h.player is None
    assert player.source is None or not player.playing
    assert h not in audio.mixer.handles
    h.stop()  # twice is harmless
    with pytest.raises(ValueError, match="volume"):
        h.volume = 1.5
    with pytest.raises(ValueError, match=r"audio.play.pitch"):
        audio.play("beep.wav", pitch=0)


def test_fade_moves_volume_with_frame_time_and_can_stop(store: Assets):
    app = make_app(with_store(store))
    h = audio_of(app).play("beep.wav", volume=1.0, loop=True)
    h.fade(0.0, 0.5, stop=True)
    app.step(15)  # 15 x 1/60 s = 0.25 s: half way
    assert h.volume == pytest.approx(0.5, abs=0.02)
    assert h.player.volume == pytest.approx(h.volume)
    app.step(16)
    assert h.finished and h.player is None


def test_one_shot_finishes_and_loop_keeps_playing(store: Assets):
    """End-of-stream arrives through pyglet's event queue, which the mixer pumps."""
    app = make_app(with_store(store))
    audio = audio_of(app)
    once = audio.play("blip.wav")
    looping = audio.play("blip.wav", loop=True)
    deadline = time.monotonic() + 10.0  # generous: the silent driver follows real time
    while not once.finished and time.monotonic() < deadline:
        time.sleep(0.02)
        app.step(1)
    assert once.finished and once.player is None
    assert looping.playing and looping.player.source is not None
    assert audio.handles == [looping]


def test_missing_file_raises_at_the_call(store: Assets, sound_dir: Path):
    app = make_app(with_store(store))
    with pytest.raises(AssetNotFoundError) as info:
        audio_of(app).play("boom.wav")
    assert str(sound_dir / "boom.wav") in str(info.value)
    assert str(sound_dir / "sfx" / "boom.wav") in str(info.value)
    assert "audio.play" in str(info.value)
    with pytest.raises(TypeError, match="never pyglet objects"):
        audio_of(app).play(object())  # type: ignore[arg-type]


def test_scene_sounds_stop_when_the_scene_closes(store: Assets):
    app = make_app(with_store(store))
    h = audio_of(app).play("beep.wav", loop=True)
    app.replace_scene(with_store(store))
    assert h.finished and h.player is None
    assert audio_of(app).handles == []


def test_world_without_app_owns_its_mixer(store: Assets):
    from kge.systems.audio import AudioSystem

    world = World()
    world.insert_resource(store)
    world.add_system(AudioSystem())
    audio = world.resource(Audio)
    music = audio.play_music("theme.wav")
    assert music.playing
    world.close()
    assert music.finished


def test_no_audio_system_means_no_pyglet(store: Assets):
    """A plain World never touches pyglet.media (headless physics tests stay light)."""
    world = World()
    world.insert_resource(store)
    assert not world.has_resource(Audio)


def test_without_an_audio_backend_sounds_are_mute_not_fatal(
    store: Assets, monkeypatch: pytest.MonkeyPatch
):
    import kge.assets.loaders as loaders

    def broken(name: str):
        raise OSError("libGL.so.1: cannot open shared object file")

    monkeypatch.setattr(loaders, "pyglet_module", broken)
    app = make_app(with_store(store))
    audio = audio_of(app)
    with pytest.warns(RuntimeWarning, match="libGL"):
        h = audio.play("beep.wav", loop=True)
    assert h.player is None and h.mute and h.playing
    assert audio.mixer.driver_name == "mute"
    with pytest.raises(AssetNotFoundError):  # missing files are still reported
        audio.play("nope.wav")
    app.step(2)
    h.stop()
    assert h.finished


def test_a_second_audio_system_is_refused(store: Assets):
    from kge.systems.audio import AudioSystem

    world = World()
    world.add_system(AudioSystem())
    with pytest.raises(ValueError, match="already has an AudioSystem"):
        world.add_system(AudioSystem())
    world.close()


def test_streamed_music_loops(store: Assets):
    """Music streams from disk by default; end-of-stream rewinds it instead of ending."""
    app = make_app(with_store(store))
    music = audio_of(app).play_music("theme.wav")  # 0.5 s
    assert type(music.player.source).__name__ != "StaticSource"
    peak, wrapped = 0.0, False
    deadline = time.monotonic() + 10.0
    while not wrapped and time.monotonic() < deadline:
        time.sleep(0.02)
        app.step(1)
        now = music.time
        wrapped = peak > 0.25 and now < peak - 0.1
        peak = max(peak, now)
    assert wrapped and music.playing and music.player.source is not None
