"""A playing sound you can control: stop, pause, resume, volume, pitch, fade.

A :class:`SoundHandle` owns one pyglet ``Player``. What the player hears is
the product of four factors, recomputed whenever one changes:

    player.volume = handle.volume * handle.gain * bus volume * master volume

``volume`` is the user's (and what :meth:`SoundHandle.fade` animates),
``gain`` is the distance attenuation of positional sounds, the bus is
"music" or "sfx", and the master volume belongs to the mixer. Keeping them
apart means a fade never fights the attenuation and a master-volume slider
never loses the sounds' own levels.

A handle is *finished* when a non-looping sound has played to its end (pyglet
reports end-of-stream through its event queue, which the mixer pumps every
frame) or when it was stopped; its player is then deleted. Without a usable
audio backend a handle is *mute*: it keeps its state but drives no player.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from kge.audio.spatial import pan_to_position
from kge.components.audio import fade_seconds
from kge.components.audio import pitch as check_pitch
from kge.errors import ValidationError
from kge.validate import boolean, in_range, non_negative

if TYPE_CHECKING:
    from kge.audio.mixer import Mixer

_OWNER = "SoundHandle"


class SoundHandle:
    """Control of one playing sound (returned by ``audio.play`` and ``play_music``)."""

    __slots__ = (
        "_elapsed_fade",
        "_fade",
        "_gain",
        "_loop",
        "_mixer",
        "_pan",
        "_paused",
        "_pitch",
        "_player",
        "_rate",
        "_stopped",
        "_volume",
        "bus",
        "duration",
        "name",
    )

    def __init__(
        self,
        mixer: Mixer,
        player: Any,
        *,
        name: str,
        duration: float | None,
        volume: float,
        pitch: float,
        loop: bool,
        bus: str = "sfx",
    ) -> None:
        self._mixer = mixer
        self._player = player
        self.name = name
        self.duration = duration  #: seconds; None for streams of unknown length
        self.bus = bus
        self._volume = in_range(volume, 0.0, 1.0, _OWNER, "volume")
        self._pitch = check_pitch(pitch, _OWNER, "pitch")
        self._rate = 1.0  # the game's time scale, for sounds that follow it
        self._loop = boolean(loop, _OWNER, "loop")
        self._gain = 1.0
        self._pan = 0.0
        self._paused = False
        self._stopped = False
        self._fade: tuple[float, float, float, bool] | None = None  # start, to, seconds, stop
        self._elapsed_fade = 0.0
        if player is not None:
            player.loop = self._loop
            player.pitch = self._pitch
            self.apply_volume()

    # -- state ------------------------------------------------------------------------
    @property
    def player(self) -> Any:
        """The pyglet ``Player`` (None when mute or finished). For inspection only."""
        return self._player

    @property
    def mute(self) -> bool:
        """True when no audio backend is available: state is kept, nothing sounds."""
        return self._player is None and not self._stopped and self._mixer.mute

    @property
    def finished(self) -> bool:
        """Stopped, or (not looping) played to the end."""
        if self._stopped:
            return True
        player = self._player
        if player is None:
            return not self._loop  # mute one-shots end at once
        return player.source is None

    @property
    def playing(self) -> bool:
        return not self.finished and not self._paused

    @property
    def paused(self) -> bool:
        return self._paused and not self.finished

    @property
    def time(self) -> float:
        """Playback position in seconds (0 when mute or finished)."""
        player = self._player
        return 0.0 if player is None or self.finished else float(player.time)

    # -- controls ---------------------------------------------------------------------
    def stop(self) -> None:
        """Stop now and release the player. Safe to call twice."""
        if self._stopped:
            return
        self._stopped = True
        self._fade = None
        player, self._player = self._player, None
        if player is not None:
            player.pause()
            player.delete()
        self._mixer.forget(self)

    def pause(self) -> None:
        if not self.finished and not self._paused:
            self._paused = True
            if self._player is not None:
                self._player.pause()

    def resume(self) -> None:
        if not self.finished and self._paused:
            self._paused = False
            if self._player is not None:
                self._player.play()

    def seek(self, seconds: float) -> None:
        """Jump to ``seconds`` from the start (a checkpoint's music, a scrubbed cutscene).

        Refused past the end of a sound of known length, and for a negative or
        non-finite time; a finished sound does nothing.
        """
        t = non_negative(seconds, _OWNER, "seek")
        if self.duration is not None and t > self.duration:
            raise ValidationError(
                f"{_OWNER}.seek: {t:g} s is past the end of {self.name!r} ({self.duration:g} s)"
            )
        if self._player is not None and not self.finished:
            self._player.seek(t)

    @property
    def volume(self) -> float:
        """The sound's own volume in [0, 1] (before attenuation and master volume)."""
        return self._volume

    @volume.setter
    def volume(self, value: float) -> None:
        self._volume = in_range(value, 0.0, 1.0, _OWNER, "volume")
        self._fade = None
        self.apply_volume()

    @property
    def pitch(self) -> float:
        """Playback rate: 2.0 is an octave up and twice as fast."""
        return self._pitch

    @pitch.setter
    def pitch(self, value: float) -> None:
        self._pitch = check_pitch(value, _OWNER, "pitch")
        if self._player is not None:
            self._player.pitch = self.rate

    @property
    def rate(self) -> float:
        """What the player is told: ``pitch`` times the game's time scale when the sound
        follows game time (``Audio.follow_game_time``), else ``pitch``."""
        return self._pitch * self._rate

    def set_time_scale(self, scale: float) -> None:
        """Play at ``scale`` times its pitch (the audio system's, for game-time sounds)."""
        scale = max(float(scale), 1e-3)  # a player cannot run at 0: the pause stops it
        if scale != self._rate:
            self._rate = scale
            if self._player is not None:
                self._player.pitch = self.rate

    @property
    def loop(self) -> bool:
        return self._loop

    @loop.setter
    def loop(self, value: bool) -> None:
        self._loop = boolean(value, _OWNER, "loop")
        if self._player is not None:
            self._player.loop = self._loop

    @property
    def gain(self) -> float:
        """Distance attenuation in [0, 1], set by the audio system for positional sounds."""
        return self._gain

    @gain.setter
    def gain(self, value: float) -> None:
        self._gain = in_range(value, 0.0, 1.0, _OWNER, "gain")
        self.apply_volume()

    @property
    def pan(self) -> float:
        """Stereo pan in [-1 (left), 1 (right)]."""
        return self._pan

    @pan.setter
    def pan(self, value: float) -> None:
        self._pan = in_range(value, -1.0, 1.0, _OWNER, "pan")
        if self._player is not None:
            self._player.position = pan_to_position(self._pan)

    @property
    def effective_volume(self) -> float:
        """What the player is told: volume x gain x bus volume x master volume."""
        return self._volume * self._gain * self._mixer.bus_volume(self.bus)

    def apply_volume(self) -> None:
        if self._player is not None:
            self._player.volume = self.effective_volume

    def fade(self, to: float, seconds: float, *, stop: bool = False) -> SoundHandle:
        """Move ``volume`` linearly to ``to`` over ``seconds``; ``stop=True`` stops at the end.

        Fades advance with the frame time the audio system is given. Returns self.
        """
        target = in_range(to, 0.0, 1.0, _OWNER, "fade.to")
        secs = fade_seconds(seconds, _OWNER, "fade.seconds")
        stop = boolean(stop, _OWNER, "fade.stop")
        if secs == 0.0:
            self.volume = target
            if stop:
                self.stop()
            return self
        self._fade = (self._volume, target, secs, stop)
        self._elapsed_fade = 0.0
        return self

    @property
    def fading(self) -> bool:
        return self._fade is not None

    def update(self, dt: float) -> None:
        """Advance a fade by ``dt`` seconds (called by the mixer every frame)."""
        if self._fade is None or self._stopped or self._paused:
            return
        start, target, seconds, stop = self._fade
        self._elapsed_fade += dt
        # 1e-9: thirty steps of 1/60 s must finish a 0.5 s fade despite float round-off
        t = 1.0 if self._elapsed_fade >= seconds - 1e-9 else self._elapsed_fade / seconds
        self._volume = start + (target - start) * t
        self.apply_volume()
        if t >= 1.0:
            self._fade = None
            if stop:
                self.stop()

    def __repr__(self) -> str:
        state = "finished" if self.finished else "paused" if self._paused else "playing"
        return f"<SoundHandle {self.name!r} {state} volume={self._volume:.2f}>"
