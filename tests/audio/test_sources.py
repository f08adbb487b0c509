"""AudioSource entities, music across scene reloads, and positional sound."""

from __future__ import annotations

from pathlib import Path

import pytest

from kge import Transform, World
from kge.assets import AssetNotFoundError, Assets
from kge.audio import Audio
from kge.audio.mixer import Mixer
from kge.components.audio import AudioListener, AudioSource
from tests.audio.conftest import make_app, with_store


def audio_of(app) -> Audio:
    return app.world.resource(Audio)


def count_starts(monkeypatch: pytest.MonkeyPatch) -> list[str]:
    """Record every player the mixer creates."""
    started: list[str] = []
    original = Mixer.start

    def start(self, source, **kwargs):
        started.append(kwargs["name"])
        return original(self, source, **kwargs)

    monkeypatch.setattr(Mixer, "start", start)
    return started


def test_play_on_start_plays_once(store: Assets, monkeypatch: pytest.MonkeyPatch):
    started = count_starts(monkeypatch)
    ids: dict[str, int] = {}

    def setup(world: World) -> None:
        ids["auto"] = world.spawn(AudioSource("beep.wav", play_on_start=True, loop=True))
        ids["manual"] = world.spawn(AudioSource("blip.wav"))

    app = make_app(with_store(store, setup))
    audio = audio_of(app)
    app.step(10)
    assert started == ["beep.wav"]
    handle = audio.source_handle(ids["auto"])
    assert handle is not None and handle.playing and handle.loop
    assert audio.source_handle(ids["manual"]) is None
    # a later spawn in a running scene also starts once
    late = app.world.spawn(AudioSource("blip.wav", play_on_start=True, loop=True))
    app.step(5)
    assert started == ["beep.wav", "blip.wav"]
    assert audio.source_handle(late) is not None
    # playing by hand restarts the source (one player per source)
    again = audio.play_source(ids["manual"])
    app.step(1)
    assert audio.source_handle(ids["manual"]) is again and len(started) == 3


def test_despawned_entity_sound_stops(store: Assets):
    app = make_app(with_store(store))
    e = app.world.spawn(AudioSource("beep.wav", play_on_start=True, loop=True))
    app.step(1)
    handle = audio_of(app).source_handle(e)
    assert handle is not None and handle.playing
    player = handle.player
    app.world.despawn(e)
    app.step(1)
    assert handle.finished and handle.player is None and not player.playing
    assert audio_of(app).handles == []
    assert audio_of(app).mixer.handles == []


def test_removing_or_replacing_the_component_stops_its_sound(store: Assets):
    app = make_app(with_store(store))
    e = app.world.spawn(AudioSource("beep.wav", play_on_start=True, loop=True))
    app.step(1)
    first = audio_of(app).source_handle(e)
    app.world.add(e, AudioSource("blip.wav", play_on_start=True, loop=True))
    app.step(1)
    second = audio_of(app).source_handle(e)
    assert first is not None and first.finished
    assert second is not None and second.playing and second is not first
    app.world.remove(e, AudioSource)
    app.step(1)
    assert second.finished and audio_of(app).mixer.handles == []


def test_source_edits_reach_the_player(store: Assets):
    app = make_app(with_store(store))
    src = AudioSource("beep.wav", play_on_start=True, loop=True)
    e = app.world.spawn(src)
    app.step(1)
    handle = audio_of(app).source_handle(e)
    assert handle is not None
    player = handle.player
    src.volume = 0.3
    src.pitch = 2.0
    src.loop = False
    app.step(1)
    assert (player.volume, player.pitch, player.loop) == (pytest.approx(0.3), 2.0, False)
    with pytest.raises(ValueError, match="AudioSource.volume"):
        src.volume = -1.0


def test_spawn_with_missing_sound_is_refused_and_world_unchanged(store: Assets, sound_dir: Path):
    app = make_app(with_store(store))
    before = app.world.entities()
    with pytest.raises(AssetNotFoundError) as info:
        app.world.spawn(Transform(), AudioSource("sfx/missing.wav", play_on_start=True))
    message = str(info.value)
    assert "AudioSource.sound" in message
    assert str(sound_dir / "sfx/missing.wav") in message
    assert str(sound_dir / "sfx" / "sfx/missing.wav") in message
    assert app.world.entities() == before
    e = app.world.spawn(Transform())
    with pytest.raises(FileNotFoundError, match=f"entity {e}, AudioSource.sound"):
        app.world.add(e, AudioSource("nope.wav"))
    app.step(2)  # the scene keeps running
    assert audio_of(app).handles == []


def test_reloading_a_scene_keeps_one_music_player(store: Assets, monkeypatch: pytest.MonkeyPatch):
    started = count_starts(monkeypatch)

    def level(world: World) -> None:
        world.resource(Audio).play_music("theme.wav", volume=0.6)
        world.spawn(AudioSource("beep.wav", play_on_start=True, loop=True))

    scene = with_store(store, level)
    app = make_app(scene)
    app.step(2)
    music = audio_of(app).music
    assert music is not None and music.playing
    for _ in range(2):
        app.replace_scene(scene)
        app.step(2)
    mixer = audio_of(app).mixer
    musics = [h for h in mixer.handles if h.bus == "music"]
    assert musics == [music]  # one music player, the same one: it never restarted
    assert started.count("theme.wav") == 1
    assert len(mixer.handles) == 2  # the music and this scene's looping beep
    assert music.player.volume == pytest.approx(0.6)

    # another track replaces it, once
    app.world.resource(Audio).play_music("other.wav")
    assert music.finished
    assert [h.name for h in mixer.handles if h.bus == "music"] == ["other.wav"]
    audio_of(app).music_volume = 0.5
    current = audio_of(app).music
    assert current is not None and current.player.volume == pytest.approx(0.5)
    audio_of(app).stop_music()
    assert audio_of(app).music is None


def test_music_crossfade(store: Assets):
    app = make_app(with_store(store))
    audio = audio_of(app)
    old = audio.play_music("theme.wav")
    new = audio.play_music("other.wav", fade=0.5)
    assert new.volume == 0.0 and old.fading
    app.step(30)
    assert old.finished and new.volume == pytest.approx(1.0)


def _pan_of(store: Assets, x: float, listener: tuple[float, float] | None = None) -> tuple:
    ids: dict[str, int] = {}

    def setup(world: World) -> None:
        if listener is not None:
            world.spawn(Transform(*listener), AudioListener(pan_width=8.0))
        ids["e"] = world.spawn(
            Transform(x, 0.0),
            AudioSource(
                "beep.wav", play_on_start=True, loop=True, positional=True, max_distance=20.0
            ),
        )

    app = make_app(with_store(store, setup))
    app.step(1)
    handle = audio_of(app).source_handle(ids["e"])
    assert handle is not None
    return handle.pan, handle.gain, handle.player.position, app, ids["e"]


def test_positional_pan_follows_the_side_of_the_listener(store: Assets):
    pan_l, gain_l, pos_l, _, _ = _pan_of(store, -3.0)
    pan_r, gain_r, pos_r, _, _ = _pan_of(store, 3.0)
    assert pan_l < 0 and pos_l[0] < 0
    assert pan_r > 0 and pos_r[0] > 0
    assert pan_l == pytest.approx(-pan_r)
    assert gain_l == pytest.approx(gain_r) and 0 < gain_l < 1
    # with a listener entity at x = 10, an entity at x = 5 is on its left
    pan, _, _, _, _ = _pan_of(store, 5.0, listener=(10.0, 0.0))
    assert pan == pytest.approx(-5.0 / 8.0)
    pan, _, _, _, _ = _pan_of(store, 15.0, listener=(10.0, 0.0))
    assert pan == pytest.approx(5.0 / 8.0)


def test_positional_source_is_repanned_and_attenuated_as_it_moves(store: Assets):
    _, gain_near, _, app, e = _pan_of(store, -2.0)
    t = app.world.get(e, Transform)
    t.x = 12.0
    app.step(1)
    handle = audio_of(app).source_handle(e)
    assert handle is not None
    assert handle.pan == 1.0  # beyond the pan width: fully right
    assert handle.gain < gain_near
    assert handle.player.volume == pytest.approx(handle.gain)
    t.x = 25.0  # beyond max_distance: silent but still playing
    app.step(1)
    assert handle.gain == 0.0 and handle.player.volume == 0.0 and handle.playing


def test_camera_is_the_default_listener(store: Assets):
    import kge.components.camera as camera_mod
    ids: dict[str, int] = {}

    def setup(world: World) -> None:
        world.spawn(camera_mod.Camera(center=(20.0, 0.0), pixels_per_meter=64.0))
        ids["e"] = world.spawn(
            Transform(17.0, 0.0),
            AudioSource("beep.wav", play_on_start=True, loop=True, positional=True),
        )

    app = make_app(with_store(store, setup), size=(960, 540))
    app.step(1)
    handle = audio_of(app).source_handle(ids["e"])
    assert handle is not None
    # half the view is 960 / 2 / 64 = 7.5 m: 3 m left of the camera centre pans -0.4
    assert handle.pan == pytest.approx(-3.0 / 7.5)


def test_audio_system_added_later_adopts_existing_sources(store: Assets):
    from kge.systems.audio import AudioSystem

    world = World()
    world.insert_resource(store)
    e = world.spawn(Transform(), AudioSource("beep.wav", play_on_start=True, loop=True))
    world.add_system(AudioSystem())
    world.schedule.run(AudioSystem.stage, 1 / 60)
    handle = world.resource(Audio).source_handle(e)
    assert handle is not None and handle.playing
    world.despawn(e)
    world.flush()
    assert handle.finished
    world.close()


def test_one_shot_at_a_position_and_generated_sources(store: Assets):
    from kge.assets import tone

    ids: dict[str, int] = {}

    def setup(world: World) -> None:
        ids["gen"] = world.spawn(AudioSource(tone(300, 0.2), play_on_start=True, volume=0.5))

    app = make_app(with_store(store, setup))
    app.step(1)
    audio = audio_of(app)
    gen = audio.source_handle(ids["gen"])
    assert gen is not None and gen.duration == pytest.approx(0.2, abs=1e-3)
    assert gen.player.volume == pytest.approx(0.5)
    left = audio.play("blip.wav", position=(-5.0, 0.0), min_distance=1.0, max_distance=9.0)
    assert left.pan == pytest.approx(-0.5)  # default pan width: 10 m
    assert left.gain == pytest.approx(0.5)  # 5 m between 1 m (full) and 9 m (silent)
    assert left.player.position[0] < 0
    audio.master_volume = 0.5
    assert left.player.volume == pytest.approx(0.25)
