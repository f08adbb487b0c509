"""Decoding sound files with soundfile (libsndfile, shipped inside its wheels).

Why soundfile: pyglet decodes only 8- and 16-bit WAV by itself and needs
FFmpeg's shared libraries (absent on a fresh machine) for OGG, MP3 and FLAC.
soundfile's wheels bundle libsndfile 1.2 with Vorbis, Opus, FLAC and MP3, it is
maintained, and it reads WAV of every common depth (8/16/24/32-bit integer,
32/64-bit float) into numpy. Everything is converted to 16-bit PCM, which every
pyglet audio driver plays.

The header is checked before anything is decoded: a WAV whose sample width is
not one a WAV can have (a 7-bit WAV) is refused, and so is a sound longer than
:data:`MAX_FRAMES` (a header claiming 4 GiB): nothing is allocated for it.
"""

from __future__ import annotations

import io
import struct
from typing import Any

import numpy as np

from kge.assets.errors import AssetDecodeError

#: longest sound decoded into memory (frames); stream longer music (``streaming=True``)
MAX_FRAMES = 48000 * 60 * 20
#: sample widths a WAV may declare (PCM integer and IEEE float)
WAV_BITS = (8, 16, 24, 32, 64)


def _wav_header(data: bytes, name: str, where: str) -> None:
    """Refuse WAV headers libsndfile would misread (odd sample widths, no data)."""
    if data[:4] not in (b"RIFF", b"RIFX") or data[8:12] != b"WAVE":
        return
    pos = 12
    while pos + 8 <= len(data):
        cid, size = data[pos : pos + 4], struct.unpack("<I", data[pos + 4 : pos + 8])[0]
        if cid == b"fmt " and pos + 24 <= len(data):
            bits = struct.unpack("<H", data[pos + 22 : pos + 24])[0]
            if bits not in WAV_BITS:
                raise AssetDecodeError(
                    name, where, f"a WAV of {bits}-bit samples (WAV samples are 8, 16, 24, "
                    "32 or 64 bits)"
                )
        if cid == b"data" and pos + 8 + size > len(data):
            raise AssetDecodeError(
                name, where, f"the WAV's data chunk claims {size:,} bytes but the file holds "
                f"{len(data) - pos - 8:,}: truncated or corrupt"
            )
        pos += 8 + size + (size & 1)


def _open(data: bytes, name: str, where: str) -> Any:
    import soundfile

    if not data:
        raise AssetDecodeError(name, where, "the file is empty (0 bytes)")
    _wav_header(data, name, where)
    try:
        f = soundfile.SoundFile(io.BytesIO(data))
    except (RuntimeError, soundfile.LibsndfileError, TypeError, ValueError) as exc:
        raise AssetDecodeError(name, where, f"not a readable sound ({exc})") from None
    if f.frames <= 0 and f.format != "MPEG":
        f.close()
        raise AssetDecodeError(name, where, "the sound holds no samples")
    if f.channels < 1 or f.samplerate < 1:
        f.close()
        raise AssetDecodeError(name, where, f"{f.channels} channels at {f.samplerate} Hz")
    return f


def decode(data: bytes, name: str, where: str) -> tuple[np.ndarray, int]:
    """The whole sound as int16 frames (n, channels, at most 2) and its sample rate."""
    f = _open(data, name, where)
    with f:
        if f.frames > MAX_FRAMES:
            raise AssetDecodeError(
                name, where, f"{f.frames:,} frames is longer than kge decodes into memory "
                f"({MAX_FRAMES:,}); load it with streaming=True"
            )
        try:
            pcm = _int16(f.read(dtype="float32", always_2d=True))
        except (RuntimeError, ValueError) as exc:
            raise AssetDecodeError(name, where, f"the sound is corrupt ({exc})") from None
        rate = f.samplerate
    if not len(pcm):
        raise AssetDecodeError(name, where, "the sound holds no samples")
    return _stereo_at_most(pcm), rate


def _int16(x: np.ndarray) -> np.ndarray:
    """Float samples (any source depth, float WAVs included) as 16-bit PCM."""
    return (np.clip(np.nan_to_num(x), -1.0, 1.0) * 32767.0).round().astype(np.int16)


def _stereo_at_most(pcm: np.ndarray) -> np.ndarray:
    if pcm.shape[1] <= 2:
        return pcm
    return pcm[:, :2]  # surround files: front left and right


def static_source(media: Any, data: bytes, name: str, where: str) -> Any:
    """A pyglet StaticSource of the decoded sound (``media``: the pyglet.media module)."""
    return static_from_pcm(media, *decode(data, name, where))


def static_from_pcm(media: Any, pcm: np.ndarray, rate: int) -> Any:
    """A pyglet StaticSource over frames :func:`decode` returned (a worker thread may
    decode; this part runs where pyglet is used)."""
    fmt = media.codecs.AudioFormat(channels=pcm.shape[1], sample_size=16, sample_rate=rate)
    return _static(media, np.ascontiguousarray(pcm).tobytes(), fmt)


def _static(media: Any, data: bytes, fmt: Any) -> Any:
    """A pyglet StaticSource over decoded PCM (what ``media.load(streaming=False)`` gives)."""

    class _Decoded(media.StaticSource):
        def __init__(self) -> None:
            self.audio_format = fmt
            self._data = data
            self._duration = len(data) / fmt.bytes_per_second

    return _Decoded()


def streaming_source(media: Any, data: bytes, name: str, where: str) -> Any:
    """A pyglet StreamingSource decoding blocks as it plays (long music)."""
    f = _open(data, name, where)
    channels = min(f.channels, 2)

    class _Stream(media.StreamingSource):
        def __init__(self) -> None:
            self.audio_format = media.codecs.AudioFormat(
                channels=channels, sample_size=16, sample_rate=f.samplerate
            )
            self.video_format = None
            self._duration = f.frames / f.samplerate if f.frames > 0 else None

        def get_audio_data(self, num_bytes: int, compensation_time: float = 0.0) -> Any:
            frames = max(num_bytes // (2 * channels), 1)
            block = _int16(f.read(frames, dtype="float32", always_2d=True))
            if not len(block):
                return None
            raw = np.ascontiguousarray(_stereo_at_most(block)).tobytes()
            seconds = len(raw) / (2 * channels * f.samplerate)
            return media.codecs.AudioData(raw, len(raw), 0.0, seconds, [])

        def seek(self, timestamp: float) -> None:
            f.seek(max(0, min(int(timestamp * f.samplerate), max(f.frames - 1, 0))))

    return _Stream()
