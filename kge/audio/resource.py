"""``Audio``: the per-world resource scripts use to play sounds.

``world.resource(Audio)`` (inserted by :class:`~kge.systems.audio.AudioSystem`)
plays one-shots and loops that belong to the scene, controls the App-wide
music channel and master volume, and starts or stops an entity's
:class:`~kge.components.audio.AudioSource`::

    audio = world.resource(Audio)
    hit = audio.play("hit.wav", volume=0.8, pitch=1.2)   # -> SoundHandle
    hit.fade(0.0, 0.5, stop=True)
    audio.play_music("theme.wav")        # same track again: keeps playing
    audio.master_volume = 0.5

Lifetime rules (what KGE got wrong): scene sounds stop when the scene's world
closes; an entity's sound stops when the entity is despawned or its
AudioSource removed; music is App-wide and is *keyed by file*, so reloading a
scene that calls ``play_music("theme.wav")`` keeps the one player instead of
stacking another. Explicit calls raise for a missing or undecodable file
(``AssetNotFoundError`` / ``AssetDecodeError``) at the line that asked.
"""

from __future__ import annotations

import os
import random
from collections.abc import Hashable
from typing import TYPE_CHECKING, Any

from kge.assets.store import assets_for
from kge.audio.handle import SoundHandle
from kge.audio.mixer import Mixer
from kge.audio.spatial import pan_and_gain
from kge.components.audio import AudioListener, AudioSource, fade_seconds, sound_ref
from kge.components.audio import pitch as check_pitch
from kge.components.transform import Transform
from kge.errors import ValidationError, where
from kge.sound import SoundData, SoundRef
from kge.validate import boolean, in_range, point, positive

if TYPE_CHECKING:
    from kge.world import World

Vec2 = tuple[float, float]

DEFAULT_PAN_WIDTH = 10.0
"""Metres from the listener at which a sound is fully left or right, with no camera."""


class Audio:
    """Per-world audio control. See the module docstring."""

    def __init__(self, world: World, mixer: Mixer) -> None:
        self.world = world
        self.mixer = mixer
        self._handles: list[SoundHandle] = []
        self._sources: dict[int, SoundHandle] = {}
        #: the random numbers of ``pitch_variation`` / ``volume_variation`` (seed it in tests)
        self.rng = random.Random()
        #: scene sounds pause with the game and play at its time scale (music does not)
        self.follow_game_time = False
        self._held: list[SoundHandle] = []  # paused by the game's pause, not by the game

    # -- volumes ----------------------------------------------------------------------
    @property
    def master_volume(self) -> float:
        """App-wide volume in [0, 1] applied on top of every sound's own volume."""
        return self.mixer.master_volume

    @master_volume.setter
    def master_volume(self, value: float) -> None:
        self.mixer.master_volume = value

    @property
    def music_volume(self) -> float:
        """Volume of the music bus in [0, 1] (times the master volume)."""
        return self.mixer.get_bus_volume("music")

    @music_volume.setter
    def music_volume(self, value: float) -> None:
        self.mixer.set_bus_volume("music", value)

    @property
    def sfx_volume(self) -> float:
        """Volume of every non-music sound in [0, 1] (times the master volume)."""
        return self.mixer.get_bus_volume("sfx")

    @sfx_volume.setter
    def sfx_volume(self, value: float) -> None:
        self.mixer.set_bus_volume("sfx", value)

    def add_bus(self, name: str, volume: float = 1.0) -> None:
        """A bus of your own, App-wide ("voices", "ui", "ambience"): ``play(...,
        bus=name)`` routes a sound through it; its volume times the master volume."""
        self.mixer.add_bus(name, volume)

    def set_bus_volume(self, bus: str, value: float) -> None:
        """Set any bus's volume in [0, 1] (``sfx``, ``music`` or one of yours)."""
        self.mixer.check_bus(bus, "audio.set_bus_volume")
        self.mixer.set_bus_volume(bus, value)

    def bus_volume(self, bus: str) -> float:
        """A bus's own volume (without the master volume)."""
        return self.mixer.get_bus_volume(self.mixer.check_bus(bus, "audio.bus_volume"))

    # -- loading ----------------------------------------------------------------------
    def _load(self, sound: SoundRef, streaming: bool, owner: str) -> tuple[Any, str, Hashable]:
        """(pyglet source or None when mute, display name, identity key)."""
        ref = sound_ref(sound, owner, "sound")
        if isinstance(ref, SoundData):
            source = None if self.mixer.backend() is None else assets_for(self.world).sound(ref)
            return source, ref.name, ref
        store = assets_for(self.world)
        found = store.checked_sound(ref, owner=owner)  # raises, naming every place searched
        name = os.fspath(ref)
        if self.mixer.backend() is None:
            return None, name, found.where
        return store.sound(ref, streaming=streaming), name, found.where

    # -- playing --------------------------------------------------------------------------
    def play(
        self,
        sound: SoundRef,
        *,
        volume: float = 1.0,
        pitch: float = 1.0,
        loop: bool = False,
        position: Vec2 | None = None,
        min_distance: float = 1.0,
        max_distance: float = 30.0,
        streaming: bool = False,
        pitch_variation: float = 0.0,
        volume_variation: float = 0.0,
        max_voices: int | None = None,
        bus: str = "sfx",
    ) -> SoundHandle:
        """Play ``sound`` (asset name, path or SoundData) in this scene; return its handle.

        ``position`` (world metres) pans and attenuates it from the listener once,
        at the start. The sound stops when it ends, when ``handle.stop()`` is
        called or when the scene closes.

        ``pitch_variation=0.1`` plays it at a random pitch within ±10 % and
        ``volume_variation=0.2`` at 80-100 % of ``volume`` (footsteps and hits that do
        not sound like a machine gun; the numbers come from :attr:`rng`).
        ``max_voices=3``: at most three of this sound play at once in the scene; a
        fourth stops the oldest. ``bus`` routes it through a bus (:meth:`add_bus`).
        """
        owner = "audio.play"
        in_range(volume, 0.0, 1.0, owner, "volume")
        check_pitch(pitch, owner, "pitch")
        boolean(loop, owner, "loop")
        boolean(streaming, owner, "streaming")
        self.mixer.check_bus(bus, owner)
        pv = in_range(pitch_variation, 0.0, 0.99, owner, "pitch_variation")
        vv = in_range(volume_variation, 0.0, 1.0, owner, "volume_variation")
        if max_voices is not None and (
            isinstance(max_voices, bool) or not isinstance(max_voices, int) or max_voices < 1
        ):
            raise ValidationError(f"{owner}.max_voices must be a whole number >= 1, got "
                                  f"{max_voices!r}")  # fmt: skip
        pan, gain = 0.0, 1.0
        if position is not None:
            pos = point(position, owner, "position")
            lo = positive(min_distance, owner, "min_distance")
            hi = positive(max_distance, owner, "max_distance")
            if lo >= hi:
                raise ValidationError(
                    f"{owner}.max_distance ({hi}) must be greater than min_distance ({lo})"
                )
            pan, gain = self.spatial(pos, lo, hi)
        source, name, _ = self._load(sound, streaming, owner)
        if pv:
            pitch = pitch * self.rng.uniform(1.0 - pv, 1.0 + pv)
        if vv:
            volume = volume * self.rng.uniform(1.0 - vv, 1.0)
        if max_voices is not None:
            same = [h for h in self._handles if h.name == name and not h.finished]
            for old in same[: max(len(same) - max_voices + 1, 0)]:
                old.stop()  # the oldest voices make room
        handle = self.mixer.start(
            source, name=name, volume=volume, pitch=pitch, loop=loop, pan=pan, gain=gain,
            bus=bus,
        )
        self._handles.append(handle)
        return handle

    def follow_game(self, paused: bool, time_scale: float) -> None:
        """Pause scene sounds while the game is paused and play them at its time scale
        (the audio system calls it each frame when :attr:`follow_game_time` is on)."""
        live = [h for h in self._handles if not h.finished and h.bus != "music"]
        live += [h for h in self._sources.values() if not h.finished and h not in live]
        if paused:
            for h in live:
                if h.playing:
                    h.pause()
                    self._held.append(h)
            return
        if self._held:
            for h in self._held:
                h.resume()
            self._held = []
        for h in live:
            h.set_time_scale(time_scale)

    def play_music(
        self,
        sound: SoundRef,
        *,
        volume: float = 1.0,
        loop: bool = True,
        fade: float = 0.0,
        streaming: bool = True,
    ) -> SoundHandle:
        """Make ``sound`` the App's one music track (see the module docstring).

        Calling it again with the same file (from this scene or a reloaded
        one) keeps the playing track; another file replaces it, cross-fading
        over ``fade`` seconds. Music outlives scenes: stop it with :meth:`stop_music`.
        """
        owner = "audio.play_music"
        in_range(volume, 0.0, 1.0, owner, "volume")
        boolean(loop, owner, "loop")
        boolean(streaming, owner, "streaming")
        fade = fade_seconds(fade, owner, "fade")
        ref = sound_ref(sound, owner, "sound")
        if isinstance(ref, SoundData):
            key: Hashable = ref
            name = ref.name
        else:
            key = assets_for(self.world).resolve(ref, owner=owner).where
            name = os.fspath(ref)

        def load() -> Any:
            return self._load(ref, streaming, owner)[0]

        return self.mixer.play_music(key, load, name=name, volume=volume, loop=loop, fade=fade)

    def stop_music(self, fade: float = 0.0) -> None:
        self.mixer.stop_music(fade_seconds(fade, "audio.stop_music", "fade"))

    @property
    def music(self) -> SoundHandle | None:
        """The App's current music track, if any."""
        return self.mixer.music

    # -- entity sources -----------------------------------------------------------------
    def play_source(self, entity: int) -> SoundHandle:
        """(Re)start the entity's AudioSource with its current fields."""
        src = self.world.get(entity, AudioSource)
        self.stop_source(entity)
        pan, gain = 0.0, 1.0
        if src.positional:
            pan, gain = self._entity_spatial(entity, src)
        owner = where(entity, "AudioSource", "sound")
        source, name, _ = self._load(src.sound, src.streaming, owner)
        handle = self.mixer.start(
            source,
            name=name,
            volume=src.volume,
            pitch=src.pitch,
            loop=src.loop,
            pan=pan,
            gain=gain,
        )
        self._sources[entity] = handle
        return handle

    def stop_source(self, entity: int) -> None:
        handle = self._sources.pop(entity, None)
        if handle is not None:
            handle.stop()

    def source_handle(self, entity: int) -> SoundHandle | None:
        """The handle of the entity's AudioSource while it plays, else None."""
        handle = self._sources.get(entity)
        return handle if handle is not None and not handle.finished else None

    # -- the scene's sounds -------------------------------------------------------------
    @property
    def handles(self) -> list[SoundHandle]:
        """This scene's live sounds (one-shots, loops and entity sources; not music)."""
        return [h for h in (*self._handles, *self._sources.values()) if not h.finished]

    def pause_all(self) -> None:
        """Pause this scene's sounds (a pause menu); music keeps playing."""
        for h in self.handles:
            h.pause()

    def resume_all(self) -> None:
        for h in (*self._handles, *self._sources.values()):
            h.resume()

    def stop_all(self) -> None:
        """Stop this scene's sounds (the scene is closing). Music is left alone."""
        for h in (*self._handles, *self._sources.values()):
            h.stop()
        self._handles.clear()
        self._sources.clear()

    def reap(self) -> None:
        """Forget finished handles (called every frame by the audio system)."""
        if self._handles:
            self._handles = [h for h in self._handles if not h.finished]
        for entity in [e for e, h in self._sources.items() if h.finished]:
            del self._sources[entity]

    # -- listener -----------------------------------------------------------------------
    def listener(self) -> tuple[Vec2, float]:
        """Where the listener is and its pan width (m).

        An :class:`AudioListener` entity wins; else the first camera (its
        ``center``, with half its view width as pan width); else the origin.
        """
        world = self.world
        listeners = world.query(AudioListener, Transform)
        if listeners:
            _, (lst, tr) = min(listeners, key=lambda item: item[0])
            width = lst.pan_width if lst.pan_width is not None else self._camera_half_width()
            return (tr.x, tr.y), width
        camera = self._camera()
        if camera is not None:
            entity, cam = camera
            center = getattr(cam, "center", None)
            if center is None:
                cam_tr = world.try_get(entity, Transform)
                center = (0.0, 0.0) if cam_tr is None else (cam_tr.x, cam_tr.y)
            return (float(center[0]), float(center[1])), self._camera_half_width()
        return (0.0, 0.0), DEFAULT_PAN_WIDTH

    def _camera(self) -> tuple[int, Any] | None:
        try:
            from kge.components.camera import Camera
        except ImportError:
            return None
        cams = self.world.query(Camera)
        if not cams:
            return None
        entity, (cam,) = min(cams, key=lambda item: item[0])
        return entity, cam

    def _camera_half_width(self) -> float:
        camera = self._camera()
        if camera is None:
            return DEFAULT_PAN_WIDTH
        cam = camera[1]
        try:
            from kge.host import Host

            app = self.world.try_resource(Host)
            width_px = app.size[0] if app is not None else None
            ppm = float(getattr(cam, "pixels_per_meter", 64.0)) * float(getattr(cam, "zoom", 1.0))
        except (TypeError, ValueError):
            return DEFAULT_PAN_WIDTH
        if not width_px or ppm <= 0:
            return DEFAULT_PAN_WIDTH
        return width_px / 2.0 / ppm

    def spatial(
        self, position: Vec2, min_distance: float, max_distance: float
    ) -> tuple[float, float]:
        """(pan, gain) of a sound at ``position`` for the current listener."""
        center, width = self.listener()
        return pan_and_gain(
            position,
            center,
            pan_width=width,
            min_distance=min_distance,
            max_distance=max_distance,
        )

    def update_positions(self) -> None:
        """Re-pan and re-attenuate playing positional entity sources (once per frame)."""
        moving = [(e, h) for e, h in self._sources.items() if not h.finished]
        if not moving:
            return
        center: Vec2 | None = None
        width = DEFAULT_PAN_WIDTH
        for entity, handle in moving:
            src = self.world.try_get(entity, AudioSource)
            tr = self.world.try_get(entity, Transform)
            if src is None or tr is None or not src.positional:
                continue
            if center is None:
                center, width = self.listener()
            handle.pan, handle.gain = pan_and_gain(
                (tr.x, tr.y),
                center,
                pan_width=width,
                min_distance=src.min_distance,
                max_distance=src.max_distance,
            )

    def _entity_spatial(self, entity: int, src: AudioSource) -> tuple[float, float]:
        tr = self.world.try_get(entity, Transform)
        if tr is None:
            return 0.0, 1.0
        return self.spatial((tr.x, tr.y), src.min_distance, src.max_distance)
