"""``AudioSystem``: plays AudioSources and ImpactSounds and keeps sounds in step.

Added to a world, the system

* inserts the :class:`~kge.audio.resource.Audio` resource (and the default
  :class:`~kge.assets.Assets` store when the scene has none), sharing one
  :class:`~kge.audio.mixer.Mixer` per App so music is App-wide;
* checks every ``AudioSource`` / ``ImpactSound`` at spawn: a sound file that no
  search location holds is refused there, with the places searched, and the
  world is left unchanged (KGE aborted the whole scene later instead);
* starts ``play_on_start`` sources once, follows later edits of ``volume``,
  ``pitch`` and ``loop`` (write-tracked, so unchanged sources cost nothing),
  and re-pans positional sources from their Transform every frame;
* stops an entity's sound when the entity is despawned or the component
  removed, and every scene sound when the world closes (``detach``);
* once a world has an ``ImpactSound``, reads the frame's physics
  ``ContactBegin`` events (``world.events``) and plays an entity's
  ``ImpactSound`` once per contact whose ``approach_speed`` reaches its
  ``hit_threshold``, at a volume scaled by the speed.

It runs in the LATE stage's ``AUDIO`` set, after camera follow, so panning uses this frame's
camera. Importing this module does not import pyglet; the mixer does, when the
first sound plays. Sounds started by the system itself (play-on-start,
impacts) cannot raise to a caller, so a file that fails to *decode* there is
reported with a warning and skipped.
"""

from __future__ import annotations

import warnings
import weakref
from typing import Any

from kge.assets.errors import AssetError
from kge.assets.store import Assets, assets_for, default_assets
from kge.audio.mixer import Mixer
from kge.audio.resource import Audio
from kge.components.audio import AudioSource, ImpactSound
from kge.components.tracked import bind, unbind, validate_writes
from kge.components.transform import Transform
from kge.errors import where
from kge.host import Host
from kge.physics.events import ContactBegin
from kge.plugin import Plugin
from kge.schedule import Stage, System, SystemSet
from kge.sound import SoundData
from kge.world import World

__all__ = ["Audio", "AudioSystem", "mixer_for"]

_app_mixers: weakref.WeakKeyDictionary[Any, Mixer] = weakref.WeakKeyDictionary()

#: mixers of Apps collected without ``close()``, waiting to be closed on the main thread
_orphans: list[Mixer] = []


def _orphaned(mixer: Mixer) -> None:
    """An App was collected: its mixer is closed at the next safe point, not here.

    A garbage-collection pass runs finalizers on whatever thread triggered it,
    pyglet's media thread included, in the middle of pyglet's own code. Stopping a
    player from there deadlocked against the main thread starting one (each waits
    for the media thread's lock the other holds). So this only queues the mixer.
    """
    _orphans.append(mixer)


def close_orphans() -> None:
    """Close the mixers of collected Apps (main thread, between frames)."""
    while _orphans:
        _orphans.pop().close()


def mixer_for(world: World) -> tuple[Mixer, bool]:
    """The mixer of ``world``'s App (shared), or a new one owned by the world.

    Returns ``(mixer, owned)``; an owned mixer is closed with the world.
    """
    close_orphans()
    app = world.try_resource(Host)
    if app is None:
        return Mixer(), True
    mixer = _app_mixers.get(app)
    if mixer is None:
        mixer = Mixer()
        _app_mixers[app] = mixer
        weakref.finalize(app, _orphaned, mixer).atexit = False
    return mixer, False


def close_app_audio(app: Any) -> None:
    """Stop every sound of ``app``, music included (for ``App.close``)."""
    close_orphans()
    mixer = _app_mixers.pop(app, None)
    if mixer is not None:
        mixer.close()


class AudioSystem(System):
    """Plays the world's sounds. See the module docstring."""

    stage = Stage.LATE
    in_set = SystemSet.AUDIO
    _active = False  # True once attach succeeded; a refused duplicate stays inert

    def attach(self, world: World) -> None:
        if any(isinstance(s, AudioSystem) and s is not self for s in world.schedule.systems()):
            raise ValueError(
                "this world already has an AudioSystem (App adds one to every scene); "
                "a second one would play every sound twice"
            )
        super().attach(world)
        self.mixer, self._owns_mixer = mixer_for(world)
        if not world.has_resource(Assets):
            world.insert_resource(default_assets())
        self.audio = Audio(world, self.mixer)
        world.insert_resource(self.audio)
        self._dirty: set[int] = set()
        self._to_start: set[int] = set()
        self._impacts: list[tuple[int, ImpactSound, float, tuple[float, float] | None]] = []
        self._last_impact: dict[int, float] = {}
        self._clock = 0.0
        world.validator(AudioSource, self._check_sound)
        world.validator(ImpactSound, self._check_sound)
        validate_writes(world, ImpactSound)  # a bad write names its entity
        world.on_add(AudioSource, self._added)
        world.on_remove(AudioSource, self._removed)
        world.on_remove(ImpactSound, self._impact_removed)
        world.on_add(ImpactSound, self._impact_added)
        self._listening = False
        self._active = True
        # adopt components spawned before the system joined (app.add_system_to_all)
        for entity, (src,) in sorted(world.query(AudioSource), key=lambda item: item[0]):
            self._added(entity, src)
        for entity, (impact,) in world.query(ImpactSound):
            self._impact_added(entity, impact)

    # -- hooks ------------------------------------------------------------------------
    def _check_sound(self, entity: int | None, comp: AudioSource | ImpactSound) -> None:
        if isinstance(comp.sound, SoundData):
            return
        owner = where(entity, type(comp).__name__, "sound")
        assets_for(self.world).checked_sound(comp.sound, owner=owner)

    def _added(self, entity: int, src: AudioSource) -> None:
        bind(src, entity, self._dirty)
        if src.play_on_start:
            self._to_start.add(entity)

    def _removed(self, entity: int, src: AudioSource) -> None:
        unbind(src)
        self._to_start.discard(entity)
        self._dirty.discard(entity)
        self.audio.stop_source(entity)

    def _impact_added(self, entity: int, _: ImpactSound) -> None:
        # contacts are read once a world has an ImpactSound: one without pays nothing
        self._listening = True

    def _impact_removed(self, entity: int, _: ImpactSound) -> None:
        self._last_impact.pop(entity, None)

    def contact_begin(self, event: Any) -> None:
        """Queue the ImpactSounds of the entities touched by a new contact."""
        speed = float(getattr(event, "approach_speed", 0.0) or 0.0)
        points = getattr(event, "points", ())
        point = (float(points[0][0]), float(points[0][1])) if points else None
        seen: list[int] = []
        for entity in (event.collider_a, event.body_a, event.collider_b, event.body_b):
            if entity is None or entity in seen:
                continue
            seen.append(entity)
            impact = self.world.try_get(entity, ImpactSound)
            if impact is not None and speed >= impact.hit_threshold and impact.gain(speed) > 0:
                self._impacts.append((entity, impact, speed, point))

    # -- per frame ------------------------------------------------------------------------
    def process(self, dt: float) -> None:
        if not self._active:
            return
        if _orphans:
            close_orphans()
        self._clock += dt
        if self._listening:
            for event in self.world.events(ContactBegin):
                self.contact_begin(event)
        if self._to_start:
            self._start_sources()
        if self._dirty:
            self._sync_sources()
        if self._impacts:
            self._play_impacts()
        self.audio.update_positions()
        if self.audio.follow_game_time:
            host = self.world.try_resource(Host)
            if host is not None:
                self.audio.follow_game(bool(getattr(host, "paused", False)),
                                       float(getattr(host, "time_scale", 1.0)))  # fmt: skip
        self.mixer.update(dt)
        self.audio.reap()

    def _start_sources(self) -> None:
        starting, self._to_start = sorted(self._to_start), set()
        for entity in starting:
            if self.world.try_get(entity, AudioSource) is None:
                continue
            try:
                self.audio.play_source(entity)
            except AssetError as exc:
                warnings.warn(f"AudioSource not played: {exc}", RuntimeWarning, stacklevel=2)

    def _sync_sources(self) -> None:
        dirty, self._dirty = self._dirty, set()
        for entity in dirty:
            handle = self.audio.source_handle(entity)
            src = self.world.try_get(entity, AudioSource)
            if handle is None or src is None:
                continue
            if handle.volume != src.volume and not handle.fading:
                handle.volume = src.volume
            handle.pitch = src.pitch
            handle.loop = src.loop

    def _play_impacts(self) -> None:
        impacts, self._impacts = self._impacts, []
        for entity, impact, speed, point in impacts:
            if not self.world.exists(entity):
                continue
            last = self._last_impact.get(entity)
            if impact.cooldown > 0 and last is not None and self._clock - last < impact.cooldown:
                continue
            self._last_impact[entity] = self._clock
            position = point
            if impact.positional and position is None:
                tr = self.world.try_get(entity, Transform)
                position = None if tr is None else (tr.x, tr.y)
            try:
                self.audio.play(
                    impact.sound,
                    volume=impact.gain(speed),
                    pitch=impact.pitch,
                    position=position if impact.positional else None,
                )
            except AssetError as exc:
                warnings.warn(f"ImpactSound not played: {exc}", RuntimeWarning, stacklevel=2)

    def detach(self) -> None:
        """The world is closing: stop its sounds (music belongs to the App)."""
        if not self._active:
            return
        self._active = False
        self.audio.stop_all()
        if self._owns_mixer:
            self.mixer.close()


class AudioPlugin(Plugin):
    """Sounds: :class:`AudioSystem` in every world (the ``Audio`` resource, AudioSource,
    ImpactSound), one mixer per App whose music survives scene changes and stops
    when the App closes."""

    def build(self, world: World) -> None:
        world.add_system(AudioSystem())

    def cleanup(self, app: Host) -> None:
        close_app_audio(app)
