"""Sounds of every common format decoded with packages from the index only, images decoded
at the call: bad media refused where it is loaded, naming the file."""

from __future__ import annotations

import struct
from pathlib import Path

import numpy as np
import pytest
import soundfile

from kge.assets import AssetDecodeError, Assets
from kge.errors import ValidationError
from kge.sound import SoundData

RATE = 22050
#: one second of a 440 Hz sine, stereo, as floats
T = np.arange(RATE) / RATE
WAVE = np.stack([np.sin(2 * np.pi * 440 * T), 0.5 * np.sin(2 * np.pi * 440 * T)], axis=1) * 0.5

FORMATS = [
    ("pcm8.wav", "WAV", "PCM_U8"),
    ("pcm16.wav", "WAV", "PCM_16"),
    ("pcm24.wav", "WAV", "PCM_24"),
    ("pcm32.wav", "WAV", "PCM_32"),
    ("float32.wav", "WAV", "FLOAT"),
    ("vorbis.ogg", "OGG", "VORBIS"),
    ("song.mp3", "MP3", "MPEG_LAYER_III"),
    ("lossless.flac", "FLAC", "PCM_16"),
]


@pytest.fixture
def store(tmp_path: Path) -> Assets:
    return Assets(tmp_path, anchor=tmp_path)


def _pcm(source: object) -> np.ndarray:
    data = source.get_queue_source().get_audio_data(1 << 24)  # type: ignore[attr-defined]
    return np.frombuffer(data.data, "<i2").reshape(-1, 2)


@pytest.mark.parametrize(("name", "fmt", "subtype"), FORMATS, ids=[f[0] for f in FORMATS])
def test_every_common_format_decodes_static_and_streaming(
    store: Assets, tmp_path: Path, name: str, fmt: str, subtype: str
) -> None:
    soundfile.write(tmp_path / name, WAVE, RATE, format=fmt, subtype=subtype)
    src = store.sound(name)
    assert src.audio_format.channels == 2 and src.audio_format.sample_rate == RATE
    assert src.duration == pytest.approx(1.0, abs=0.06)  # MP3 pads its frames
    pcm = _pcm(src).astype(float) / 32767
    n = min(len(pcm), RATE) - 2000
    lag = int(np.argmax([np.dot(pcm[k : k + n, 0], WAVE[:n, 0]) for k in range(0, 1200)]))
    left, right = pcm[lag : lag + n, 0], pcm[lag : lag + n, 1]
    assert np.corrcoef(left, WAVE[:n, 0])[0, 1] > 0.99  # the sine itself, not noise
    assert np.std(right) == pytest.approx(np.std(left) / 2, rel=0.1)  # channels kept apart
    stream = store.sound(name, streaming=True)
    chunks = []
    while (block := stream.get_audio_data(8192)) is not None:
        chunks.append(np.frombuffer(block.data, "<i2"))
    assert abs(sum(len(c) for c in chunks) / 2 - len(_pcm(src))) <= 1


def _wav_header(bits: int, data_bytes: int, fmt_tag: int = 1) -> bytes:
    block = 2 * max(bits // 8, 1)
    fmt = struct.pack("<HHIIHH", fmt_tag, 2, RATE, RATE * block, block, bits)
    return (b"RIFF" + struct.pack("<I", 36 + data_bytes) + b"WAVEfmt " + struct.pack("<I", 16)
            + fmt + b"data" + struct.pack("<I", data_bytes))  # fmt: skip


BAD = [
    ("7-bit.wav", _wav_header(7, 16) + bytes(16), r"7-bit samples"),
    ("claims-4GiB.wav", _wav_header(16, 0xFFFFFF00) + bytes(64), r"claims 4,294,967,040 bytes but the file holds 64: truncated"),
    ("empty.wav", b"", r"empty \(0 bytes\)"),
    ("header-only.wav", _wav_header(16, 0), r"no samples"),
    ("junk.mp3", b"ID3" + bytes(5), r"not a readable sound|no samples"),
    ("truncated.flac", b"fLaC\x00\x00", r"not a readable sound"),
]  # fmt: skip


def test_empty_sound_data_is_refused() -> None:
    with pytest.raises(ValidationError, match="empty"):
        SoundData(b"")


def _png(w: int, h: int) -> bytes:
    import zlib

    def chunk(kind: bytes, body: bytes) -> bytes:
        return struct.pack(">I", len(body)) + kind + body + struct.pack(">I", zlib.crc32(kind + body))

    raw = b"".join(b"\x00" + bytes(4 * w) for _ in range(h))
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 6, 0, 0, 0))
            + chunk(b"IDAT", zlib.compress(raw)) + chunk(b"IEND", b""))  # fmt: skip


#: a 1 x 1 GIF89a with no global or local colour table
GIF_NO_TABLE = (b"GIF89a\x01\x00\x01\x00\x00\x00\x00,\x00\x00\x00\x00\x01\x00\x01\x00\x00"
                b"\x02\x02D\x01\x00;")  # fmt: skip

BAD_IMAGES = [
    ("zero-bytes.png", b"", r"empty \(0 bytes\)"),
    ("truncated.png", _png(8, 8)[:45], r"not a readable image"),
    ("zero-size.png", _png(0, 0), r"(0 x 0 pixels|not a readable image)"),
    ("huge.png", _png(1, 1).replace(struct.pack(">II", 1, 1), struct.pack(">II", 100_000, 100_000)), r"(over kge.assets.loaders.MAX_IMAGE_PIXELS|not a readable image)"),
]  # fmt: skip


@pytest.mark.parametrize(
    ("name", "data", "message"), BAD + BAD_IMAGES, ids=[b[0] for b in BAD + BAD_IMAGES]
)
def test_bad_sound_and_image_files_are_refused_at_the_call(
    store: Assets, tmp_path: Path, name: str, data: bytes, message: str
) -> None:
    (tmp_path / name).write_bytes(data)
    load = store.image if name.endswith(".png") else store.sound
    with pytest.raises(AssetDecodeError, match=message) as info:
        load(name)
    assert name in str(info.value)


def test_gif_without_a_colour_table_becomes_rgba(store: Assets, tmp_path: Path) -> None:
    (tmp_path / "dot.gif").write_bytes(GIF_NO_TABLE)
    img = store.image("dot.gif")
    assert (img.width, img.height) == (1, 1)
    assert len(img.get_data("RGBA", 4)) == 4
