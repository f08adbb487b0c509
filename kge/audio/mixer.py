"""The mixer: every live sound of an App, the music channel and the master volume.

One mixer serves a whole :class:`~kge.App` (every scene world shares it), which
is what lets music survive a scene change without stacking: ``play_music``
with the track that is already playing keeps that player, and any other track
replaces it. A world used without an App gets a mixer of its own.

The mixer is also where pyglet is loaded, lazily: the first sound played
imports ``pyglet.media`` (headless mode is chosen first when there is no
display). If that fails (no audio libraries, no EGL), the mixer turns *mute*,
warns once, and hands out mute handles, so a game still runs on a machine that
cannot make sound. Each frame :meth:`Mixer.update` pumps pyglet's posted
events (end-of-stream, which drives looping and "finished"), advances fades
and releases the players of finished sounds.
"""

from __future__ import annotations

import sys
import warnings
from collections.abc import Callable, Hashable
from typing import Any

from kge.audio.handle import SoundHandle
from kge.errors import ValidationError
from kge.validate import in_range

Bus = str
BUSES = ("sfx", "music")


def _from_player_worker(err: BaseException) -> bool:
    """True when ``err`` was raised inside pyglet's media player worker thread module."""
    tb = err.__traceback__
    last = None
    while tb is not None:
        last, tb = tb, tb.tb_next
    return last is not None and last.tb_frame.f_code.co_filename.endswith(
        "player_worker_thread.py"
    )


def pump_posted_events(loop: Any, attempts: int = 64) -> None:
    """Dispatch pyglet's posted events (end of stream drives looping and "finished").

    pyglet 2.1's ``PlayerWorkerThread.remove`` checks ``player in self.players`` and
    then removes it under a lock its own thread also takes: when a sound ends just as
    the worker drops it, the second removal raises ``KeyError``. The player is gone
    either way, so that one error is dropped and the rest of the queue is pumped;
    any other error is raised.
    """
    for _ in range(attempts):
        try:
            loop.dispatch_posted_events()
            return
        except KeyError as err:
            if not _from_player_worker(err):
                raise


class Mixer:
    """Owns the players. See the module docstring."""

    def __init__(self) -> None:
        self._handles: list[SoundHandle] = []
        self._master = 1.0
        self._bus: dict[str, float] = {"sfx": 1.0, "music": 1.0}
        self._music: SoundHandle | None = None
        self._music_key: Hashable | None = None
        self._media: Any = None
        self.mute = False
        self.mute_reason = ""

    # -- backend ------------------------------------------------------------------------
    def backend(self) -> Any:
        """``pyglet.media``, imported on first use; None when audio is unavailable."""
        if self._media is None and not self.mute:
            try:
                from kge.assets.loaders import pyglet_module

                self._media = pyglet_module("media")
            except Exception as exc:  # no display libs, no EGL, broken driver...
                self.mute = True
                self.mute_reason = f"{type(exc).__name__}: {exc}"
                warnings.warn(
                    "kge audio is disabled (sounds play silently): pyglet.media could not "
                    f"be loaded ({self.mute_reason}). Set PYGLET_HEADLESS=1 on machines "
                    "without a display.",
                    RuntimeWarning,
                    stacklevel=3,
                )
        return self._media

    @property
    def driver_name(self) -> str:
        """The pyglet audio driver class in use ("SilentDriver" in tests), or "mute"."""
        media = self.backend()
        if media is None:
            return "mute"
        return type(media.get_audio_driver()).__name__

    # -- volumes ------------------------------------------------------------------------
    @property
    def master_volume(self) -> float:
        return self._master

    @master_volume.setter
    def master_volume(self, value: float) -> None:
        self._master = in_range(value, 0.0, 1.0, "Audio", "master_volume")
        self._reapply()

    def add_bus(self, name: Bus, volume: float = 1.0) -> None:
        """A bus of your own ("voices", "ui"): its sounds get its volume times the master."""
        if not isinstance(name, str) or not name.isidentifier():
            raise ValidationError(f"Audio.add_bus: a bus name is one word, got {name!r}")
        if name in self._bus:
            raise ValidationError(f"Audio.add_bus: there is a bus {name!r} already")
        self._bus[name] = in_range(volume, 0.0, 1.0, "Audio", f"{name}_volume")

    @property
    def buses(self) -> list[Bus]:
        return list(self._bus)

    def check_bus(self, bus: Bus, owner: str) -> Bus:
        if bus not in self._bus:
            raise ValidationError(
                f"{owner}: unknown audio bus {bus!r}; buses are {', '.join(self._bus)} "
                "(add one with audio.add_bus(name))"
            )
        return bus

    def set_bus_volume(self, bus: Bus, value: float) -> None:
        if bus not in self._bus:
            raise ValueError(f"unknown audio bus {bus!r}; use one of {', '.join(self._bus)}")
        self._bus[bus] = in_range(value, 0.0, 1.0, "Audio", f"{bus}_volume")
        self._reapply()

    def get_bus_volume(self, bus: Bus) -> float:
        """The bus's own volume (without the master volume)."""
        return self._bus[bus]

    def bus_volume(self, bus: Bus) -> float:
        """The bus's volume times the master volume."""
        return self._bus.get(bus, 1.0) * self._master

    def _reapply(self) -> None:
        for h in self._handles:
            h.apply_volume()

    # -- playing ------------------------------------------------------------------------
    def start(
        self,
        source: Any,
        *,
        name: str,
        volume: float = 1.0,
        pitch: float = 1.0,
        loop: bool = False,
        bus: Bus = "sfx",
        pan: float = 0.0,
        gain: float = 1.0,
        paused: bool = False,
    ) -> SoundHandle:
        """Play a loaded pyglet ``source`` (None: a mute handle) and return its handle."""
        player = None
        duration = None
        if source is not None and self.backend() is not None:
            player = self._media.Player()
            player.queue(source)
            duration = source.duration
        handle = SoundHandle(
            self,
            player,
            name=name,
            duration=duration,
            volume=volume,
            pitch=pitch,
            loop=loop,
            bus=bus,
        )
        handle.gain = gain
        handle.pan = pan
        self._handles.append(handle)
        if paused:
            handle.pause()
        elif player is not None:
            player.play()
        return handle

    def forget(self, handle: SoundHandle) -> None:
        """Drop a stopped handle (called by ``SoundHandle.stop``)."""
        if handle in self._handles:
            self._handles.remove(handle)
        if handle is self._music:
            self._music = None
            self._music_key = None

    @property
    def handles(self) -> list[SoundHandle]:
        """Every sound that has not finished, music included."""
        return [h for h in self._handles if not h.finished]

    # -- music --------------------------------------------------------------------------
    @property
    def music(self) -> SoundHandle | None:
        m = self._music
        return m if m is not None and not m.finished else None

    @property
    def music_key(self) -> Hashable | None:
        return self._music_key if self.music is not None else None

    def play_music(
        self,
        key: Hashable,
        load: Callable[[], Any],
        *,
        name: str,
        volume: float = 1.0,
        loop: bool = True,
        fade: float = 0.0,
    ) -> SoundHandle:
        """Make ``key`` the one music track: keep it if already playing, else replace.

        ``load`` is called only when a new player is needed. ``fade`` seconds
        cross-fade the old track out and the new one in.
        """
        current = self.music
        if current is not None and self._music_key == key:
            if current.paused:
                current.resume()
            if fade > 0:
                current.fade(volume, fade)
            else:
                current.volume = volume
            return current
        self.stop_music(fade=fade)
        handle = self.start(
            load(), name=name, volume=0.0 if fade > 0 else volume, loop=loop, bus="music"
        )
        if fade > 0:
            handle.fade(volume, fade)
        self._music = handle
        self._music_key = key
        return handle

    def stop_music(self, fade: float = 0.0) -> None:
        """Stop the music (fading out over ``fade`` seconds)."""
        m = self._music
        self._music = None
        self._music_key = None
        if m is None or m.finished:
            return
        if fade > 0:
            m.fade(0.0, fade, stop=True)
        else:
            m.stop()

    # -- per frame ----------------------------------------------------------------------
    def update(self, dt: float) -> None:
        """Pump pyglet's events, advance fades, release finished players."""
        if self._media is not None:
            app_mod = sys.modules.get("pyglet.app")
            if app_mod is not None:
                pump_posted_events(app_mod.platform_event_loop)
        for h in list(self._handles):
            h.update(dt)
            if h.finished:
                h.stop()

    def close(self) -> None:
        """Stop every sound (the App is gone)."""
        for h in list(self._handles):
            h.stop()
        self._music = None
        self._music_key = None
