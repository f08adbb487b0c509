"""Random pitch and volume per play, voice limits, and sounds that follow game time
(pause and time scale), checked on the players the silent driver keeps."""

from __future__ import annotations

import pytest

from kge.assets import Assets
from kge.audio import Audio
from tests.audio.conftest import make_app, with_store


def test_each_play_varies_its_pitch_and_volume_within_the_range(store: Assets) -> None:
    app = make_app(with_store(store))
    audio = app.world.resource(Audio)
    audio.rng.seed(7)
    hs = [audio.play("beep.wav", pitch=2.0, volume=0.5, pitch_variation=0.1,
                     volume_variation=0.2) for _ in range(20)]  # fmt: skip
    pitches = [h.player.pitch for h in hs]
    volumes = [h.volume for h in hs]
    assert all(1.8 <= p <= 2.2 for p in pitches) and len(set(pitches)) == 20
    assert all(0.4 <= v <= 0.5 for v in volumes) and len(set(volumes)) == 20
    audio.rng.seed(7)
    again = audio.play("beep.wav", pitch=2.0, volume=0.5, pitch_variation=0.1,
                       volume_variation=0.2)  # fmt: skip
    assert again.player.pitch == pitches[0]  # seeded: the same numbers
    plain = audio.play("beep.wav", pitch=2.0)
    assert plain.player.pitch == 2.0
    with pytest.raises(ValueError, match="pitch_variation"):
        audio.play("beep.wav", pitch_variation=1.5)
    with pytest.raises(ValueError, match="volume_variation"):
        audio.play("beep.wav", volume_variation=-0.1)


def test_max_voices_stops_the_oldest(store: Assets) -> None:
    app = make_app(with_store(store))
    audio = app.world.resource(Audio)
    first = [audio.play("beep.wav", loop=True, max_voices=3) for _ in range(3)]
    other = audio.play("blip.wav", loop=True)
    fourth = audio.play("beep.wav", loop=True, max_voices=3)
    assert first[0].finished and not first[1].finished and not first[2].finished
    assert fourth.playing and other.playing  # another sound is not counted
    live = [h for h in audio.mixer.handles if h.name == fourth.name]
    assert len(live) == 3
    audio.play("beep.wav", loop=True, max_voices=1)
    assert len([h for h in audio.mixer.handles if h.name == fourth.name]) == 1
    with pytest.raises(ValueError, match="max_voices"):
        audio.play("beep.wav", max_voices=0)


def test_game_time_sounds_pause_with_the_game_and_follow_its_time_scale(store: Assets) -> None:
    app = make_app(with_store(store))
    audio = app.world.resource(Audio)
    audio.follow_game_time = True
    h = audio.play("beep.wav", loop=True, pitch=1.5)
    paused_by_me = audio.play("blip.wav", loop=True)
    paused_by_me.pause()
    app.time_scale = 0.5
    app.advance(1 / 60)
    assert h.player.pitch == pytest.approx(0.75) and h.pitch == 1.5
    app.paused = True
    app.advance(1 / 60)
    assert h.paused and not h.player.playing
    app.paused = False
    app.advance(1 / 60)
    assert h.playing and h.player.playing
    assert paused_by_me.paused  # the game's pause never resumes what you paused
    app.time_scale = 1.0
    app.advance(1 / 60)
    assert h.player.pitch == pytest.approx(1.5)


def test_sounds_ignore_game_time_unless_asked(store: Assets) -> None:
    app = make_app(with_store(store))
    audio = app.world.resource(Audio)
    h = audio.play("beep.wav", loop=True)
    app.time_scale = 0.5
    app.paused = True
    app.advance(1 / 60)
    assert h.playing and h.player.pitch == 1.0  # menus and UI sounds play on


def test_seek_moves_the_player_and_refuses_times_past_the_end(store: Assets) -> None:
    app = make_app(with_store(store))
    audio = app.world.resource(Audio)
    h = audio.play("beep.wav", loop=True)
    h.seek(0.2)
    assert h.player.time == pytest.approx(0.2, abs=1e-3)
    h.seek(0.0)
    assert h.player.time == pytest.approx(0.0, abs=1e-3)
    with pytest.raises(ValueError, match="past the end"):
        h.seek(5.0)
    with pytest.raises(ValueError, match="seek"):
        h.seek(float("nan"))
    h.stop()
    h.seek(0.1)  # finished: nothing to move


def test_a_bus_of_your_own_scales_its_sounds(store: Assets) -> None:
    app = make_app(with_store(store))
    audio = app.world.resource(Audio)
    audio.add_bus("voices", volume=0.5)
    line = audio.play("beep.wav", loop=True, volume=0.8, bus="voices")
    shot = audio.play("blip.wav", loop=True, volume=0.8)
    assert line.player.volume == pytest.approx(0.4) and shot.player.volume == pytest.approx(0.8)
    audio.set_bus_volume("voices", 0.25)
    audio.master_volume = 0.5
    assert line.player.volume == pytest.approx(0.8 * 0.25 * 0.5)
    assert shot.player.volume == pytest.approx(0.4)  # sfx bus untouched
    assert audio.bus_volume("voices") == 0.25
    with pytest.raises(ValueError, match="unknown audio bus 'voice'"):
        audio.play("beep.wav", bus="voice")
    with pytest.raises(ValueError, match="already"):
        audio.add_bus("voices")
    with pytest.raises(ValueError, match="one word"):
        audio.add_bus("two words")
    with pytest.raises(ValueError, match="unknown audio bus"):
        audio.set_bus_volume("nope", 0.5)
