"""Sprite sheets described by JSON: Aseprite's export and texture packers' atlases.

Aseprite (*File > Export Sprite Sheet*, with JSON data) and texture packers
(TexturePacker, free-tex-packer, Phaser's multi-atlas) write one family of JSON: a
list (``"frames": [...]``, the *array* form) or an object keyed by frame name
(``"frames": {...}``, the *hash* form) of frames, each a rectangle of the sheet
image, perhaps trimmed of its transparent border or rotated a quarter turn to pack
tighter. Aseprite adds per-frame durations, tags (frame ranges with a direction
and a repeat count) and slices (named rectangles with an optional nine-slice
centre and pivot); texture packers add pivots and, for some engines, named
animations (lists of frame names).

:func:`load_sheet` reads either form and gives a :class:`SpriteSheet`:

* ``sheet.clips()``: one :class:`~kge.components.animation.Clip` per tag (or per
  packer animation), with the file's frame durations, ready for an ``Animator``;
* ``sheet.clip("walk", loop=Loop.ONCE)``: one of them, with other options;
* ``sheet.sprite("coin.png")``: a :class:`~kge.components.sprite.Sprite` of one
  frame, anchored at its pivot;
* ``sheet.slices["hitbox"].at(frame)``: a slice's rectangle on a frame.

Trimmed frames are put back in their untrimmed box and rotated ones turned back
upright, so every frame of a clip has its sprite's full size and the sprite does
not jump. Aseprite tag directions map to kge's loop modes: ``forward`` and
``reverse`` loop, ``pingpong`` and ``pingpong_reverse`` play ``ping_pong``; a tag
with a repeat count plays that many passes (for ping-pong each direction is one)
and holds its last frame.

The file is read through the world's asset store when ``assets`` is given (the
image is then an asset name beside the JSON), else from the path; either way the
image must sit in the JSON's folder or below it (``roots`` adds folders), and a
malformed file raises :class:`SheetError` naming the file and the field.
"""

from __future__ import annotations

import io
import json
import os
from collections.abc import Iterable, Iterator, Mapping
from dataclasses import dataclass, field
from pathlib import Path, PurePosixPath
from typing import Any

import numpy as np

from kge.components.animation import Clip, FrameRef, Loop
from kge.components.sprite import Sprite
from kge.errors import ValidationError
from kge.platform import regular_file_size
from kge.render.images import PixelImage

#: Aseprite's tag directions -> (frames reversed?, kge loop mode)
DIRECTIONS = {
    "forward": (False, Loop.LOOP),
    "reverse": (True, Loop.LOOP),
    "pingpong": (False, Loop.PING_PONG),
    "pingpong_reverse": (True, Loop.PING_PONG),
}
DEFAULT_DURATION = 0.1  #: seconds per frame when the file gives none (texture packers)
MAX_FILE_BYTES = 64 * 1024 * 1024
MAX_IMAGE_PIXELS = 16384 * 16384
MAX_FRAMES = 65536
Box = tuple[int, int, int, int]


class SheetError(ValidationError):
    """A sprite sheet's JSON or image is missing, malformed or out of bounds."""


@dataclass(frozen=True, slots=True)
class SheetFrame:
    """One frame: its name, pixels (untrimmed, upright), duration and pivot.

    ``size`` is the untrimmed size in pixels; ``pivot`` is kge's anchor convention
    (fractions of the size from the bottom-left), or None when the file has none.
    """

    name: str
    ref: FrameRef
    duration: float
    size: tuple[int, int]
    pivot: tuple[float, float] | None = None


@dataclass(frozen=True, slots=True)
class SheetTag:
    """An Aseprite tag: frames ``first`` to ``last`` (inclusive), a direction, a repeat.

    >>> SheetTag("t", 2, 4, "pingpong", repeat=3).order()
    [2, 3, 4, 3, 2, 3, 4]
    >>> SheetTag("t", 2, 4, "reverse").order()
    [4, 3, 2]
    """

    name: str
    first: int
    last: int
    direction: str = "forward"
    repeat: int = 0  #: 0: until told otherwise (a loop); n: n passes, then hold

    def order(self) -> list[int]:
        """Frame indices in play order: one pass, or ``repeat`` passes expanded."""
        backwards, mode = DIRECTIONS[self.direction]
        one = list(range(self.first, self.last + 1))
        if backwards:
            one.reverse()
        if self.repeat <= 0:
            return one
        out = list(one)
        for k in range(1, self.repeat):
            if mode == Loop.PING_PONG:
                nxt = one[::-1] if k % 2 else one
                out += nxt[1:] if len(nxt) > 1 else nxt
            else:
                out += one
        return out

    @property
    def loop(self) -> Loop:
        """kge's loop mode for this tag (``HOLD`` once a repeat count has played)."""
        return Loop.HOLD if self.repeat > 0 else DIRECTIONS[self.direction][1]


@dataclass(frozen=True, slots=True)
class SliceKey:
    """A slice from ``frame`` on: ``bounds`` (x, y, w, h) in pixels from the frame's
    top-left, a nine-slice ``center`` inside them and a ``pivot``, when set."""

    frame: int
    bounds: Box
    center: Box | None = None
    pivot: tuple[int, int] | None = None


@dataclass(frozen=True, slots=True)
class SheetSlice:
    """An Aseprite slice: keys by frame, its colour and user data."""

    name: str
    keys: tuple[SliceKey, ...]
    color: str | None = None
    data: str | None = None

    def at(self, frame: int) -> SliceKey | None:
        """The key in effect on ``frame`` (the last one starting at or before it).

        >>> s = SheetSlice("hit", (SliceKey(0, (0, 0, 4, 4)), SliceKey(3, (1, 1, 2, 2))))
        >>> s.at(2).bounds, s.at(5).bounds
        ((0, 0, 4, 4), (1, 1, 2, 2))
        """
        found = None
        for key in self.keys:
            if key.frame <= frame:
                found = key
        return found


@dataclass(frozen=True, slots=True)
class SpriteSheet:
    """A loaded sheet: frames in file order, tags, slices and packer animations."""

    path: str
    frames: tuple[SheetFrame, ...]
    tags: dict[str, SheetTag] = field(default_factory=dict)
    slices: dict[str, SheetSlice] = field(default_factory=dict)
    #: texture packers' named animations: name -> frame indices
    animations: dict[str, tuple[int, ...]] = field(default_factory=dict)

    def index(self, name: str) -> int:
        """The index of the frame called ``name`` (the first, if names repeat)."""
        for i, f in enumerate(self.frames):
            if f.name == name:
                return i
        sample = ", ".join(repr(f.name) for f in self.frames[:5])
        raise SheetError(f"{self.path}: no frame called {name!r} (frames: {sample}, ...)")

    def frame(self, which: int | str) -> SheetFrame:
        """A frame by index or name."""
        if isinstance(which, str):
            return self.frames[self.index(which)]
        if isinstance(which, bool) or not isinstance(which, int):
            raise SheetError(f"{self.path}: a frame is named or numbered, not {which!r}")
        if not 0 <= which < len(self.frames):
            raise SheetError(
                f"{self.path}: frame {which} is outside the sheet's {len(self.frames)} frames"
            )
        return self.frames[which]

    def sprite(self, which: int | str, **options: Any) -> Sprite:
        """A :class:`Sprite` showing one frame, anchored at its pivot unless
        ``anchor=`` is given; other options (size, layer, tint...) pass through."""
        f = self.frame(which)
        if f.pivot is not None:
            options.setdefault("anchor", f.pivot)
        ref = f.ref
        if ref.region is not None:
            return Sprite(ref.image, region=ref.region, **options)
        return Sprite(ref.image, **options)

    def clip(
        self,
        name: str | None = None,
        *,
        loop: Loop | str | None = None,
        speed: float = 1.0,
        flip_x: bool = False,
        flip_y: bool = False,
        events: Mapping[int, str] | None = None,
    ) -> Clip:
        """The clip of tag (or packer animation) ``name``; every frame in order when
        ``name`` is None. ``loop`` overrides the tag's own mode; ``events`` count the
        clip's frames (after a tag's direction and repeats are applied)."""
        if name is None:
            order, mode = list(range(len(self.frames))), Loop.LOOP
        elif name in self.tags:
            tag = self.tags[name]
            order, mode = tag.order(), tag.loop
        elif name in self.animations:
            order, mode = list(self.animations[name]), Loop.LOOP
        else:
            known = sorted([*self.tags, *self.animations])
            raise SheetError(
                f"{self.path}: no tag or animation called {name!r} "
                f"(there are: {', '.join(known) or 'none'})"
            )
        frames = [self.frames[i] for i in order]
        sizes = {f.size for f in frames}
        if len(sizes) > 1:
            raise SheetError(
                f"{self.path}: clip {name!r} mixes frame sizes {sorted(sizes)}; an animated "
                "sprite's frames share one size (export them untrimmed, or trimmed with "
                "their source size kept)"
            )
        return Clip(
            tuple(f.ref for f in frames),
            tuple(f.duration for f in frames),
            mode if loop is None else loop,  # type: ignore[arg-type]  # Clip checks a str
            speed,
            flip_x,
            flip_y,
            _clip_events(events, len(frames), self.path),
        )

    def clips(self, **options: Any) -> dict[str, Clip]:
        """One clip per tag and packer animation (or ``{"default": every frame}`` when
        the file has neither), each with ``options`` (see :meth:`clip`)."""
        names = [*self.tags, *(a for a in self.animations if a not in self.tags)]
        if not names:
            return {"default": self.clip(None, **options)}
        return {n: self.clip(n, **options) for n in names}


def _clip_events(
    events: Mapping[int, str] | None, n: int, path: str
) -> tuple[tuple[int, str], ...]:
    if not events:
        return ()
    out = []
    for k, v in events.items():
        if isinstance(k, bool) or not isinstance(k, int) or not 0 <= k < n:
            raise SheetError(f"{path}: clip event frame {k!r} is outside the clip's {n} frames")
        if not isinstance(v, str) or not v:
            raise SheetError(f"{path}: clip event {k} needs a non-empty name, got {v!r}")
        out.append((k, v))
    return tuple(sorted(out))


# -- reading ------------------------------------------------------------------------------


class _Source:
    """Where the JSON and its image come from: the asset store, or confined files."""

    def __init__(self, path: Any, assets: Any, roots: Iterable[Any]) -> None:
        self.assets = assets
        if assets is not None:
            self.name = str(PurePosixPath(os.fspath(path).replace("\\", "/")))
            self.folder: Any = PurePosixPath(self.name).parent
            self.roots: list[Path] = []
        else:
            p = Path(os.path.abspath(os.fspath(path)))
            self.name = str(p)
            self.folder = p.parent
            self.roots = [p.parent.resolve(), *(Path(r).resolve() for r in roots)]

    def read(self, name: str, what: str) -> bytes:
        if self.assets is not None:
            from kge.assets import AssetError

            try:
                data = bytes(self.assets.bytes(name))
            except AssetError as exc:
                raise SheetError(f"{self.name}: {what}: {exc}") from None
        else:
            path = Path(name)
            try:
                size = regular_file_size(path)
            except ValueError as exc:
                raise SheetError(f"{self.name}: {what} {name!r} {exc}") from None
            if size > MAX_FILE_BYTES:
                raise SheetError(
                    f"{self.name}: {what} {name!r} is {size:,} bytes, above {MAX_FILE_BYTES:,}"
                )
            with open(path, "rb") as fh:
                data = fh.read(MAX_FILE_BYTES + 1)
        if len(data) > MAX_FILE_BYTES:
            raise SheetError(f"{self.name}: {what} is above {MAX_FILE_BYTES:,} bytes")
        return data

    def image_name(self, written: Any) -> str:
        """The sheet image named in the JSON, as a store name or a confined path."""
        if not isinstance(written, str) or not written.strip() or "\x00" in written:
            raise SheetError(f"{self.name}: meta.image must name the sheet image, got {written!r}")
        rel = written.replace("\\", "/")
        if self.assets is not None:
            if os.path.isabs(rel) or ".." in PurePosixPath(rel).parts:
                raise SheetError(
                    f"{self.name}: meta.image {written!r} leaves the sheet's folder in the "
                    "asset store"
                )
            return str(self.folder / rel)
        path = Path(os.path.abspath(self.folder / rel))
        real = path.resolve()
        if not any(real == r or real.is_relative_to(r) for r in self.roots):
            allowed = ", ".join(str(r) for r in self.roots)
            raise SheetError(
                f"{self.name}: meta.image {written!r} is outside the folders this sheet may "
                f"read ({allowed}); pass load_sheet(..., roots=[folder]) to allow another"
            )
        return str(path)


def load_sheet(
    path: str | os.PathLike[str],
    assets: Any = None,
    *,
    roots: Iterable[str | os.PathLike[str]] = (),
) -> SpriteSheet:
    """Read an Aseprite or texture-packer JSON sheet (array or hash form).

    ``assets`` (an :class:`~kge.assets.Assets` store, e.g. ``assets_for(world)``)
    makes ``path`` an asset name; without it ``path`` is a file path and its image
    must lie under the JSON's folder or one of ``roots``.
    """
    src = _Source(path, assets, roots)
    text = src.read(src.name, "the sheet")
    try:
        doc = json.loads(text.decode("utf-8-sig"))
    except (UnicodeDecodeError, ValueError, RecursionError) as exc:
        raise SheetError(f"{src.name}: not valid JSON ({type(exc).__name__}: {exc})") from None
    if not isinstance(doc, dict):
        raise SheetError(f"{src.name}: not a sprite sheet (a JSON object with 'frames')")
    return _Parser(src, doc).sheet()


def _header_size(data: bytes) -> tuple[int, int]:
    """(width, height) from a PNG header, for an image Pillow refuses to open as too big."""
    if data[:8] == b"\x89PNG\r\n\x1a\n" and len(data) >= 24:
        return int.from_bytes(data[16:20], "big"), int.from_bytes(data[20:24], "big")
    return (1 << 16, 1 << 16)  # another format: over the limit all the same


class _Parser:
    def __init__(self, src: _Source, doc: dict[str, Any]) -> None:
        self.src = src
        self.doc = doc
        self.where = src.name
        self._images: dict[str, Any] = {}

    def fail(self, msg: str) -> SheetError:
        return SheetError(f"{self.where}: {msg}")

    # -- whole file
    def sheet(self) -> SpriteSheet:
        doc = self.doc
        meta = doc.get("meta", {})
        if not isinstance(meta, dict):
            raise self.fail(f"'meta' is {type(meta).__name__}, not a JSON object")
        if "textures" in doc:  # Phaser's multi-atlas: several images, frames of each
            textures = doc["textures"]
            if not isinstance(textures, list) or not textures:
                raise self.fail("'textures' must be a non-empty list")
            entries: list[tuple[str, Any, str]] = []
            for i, tex in enumerate(textures):
                if not isinstance(tex, dict):
                    raise self.fail(f"textures[{i}] is {type(tex).__name__}, not a JSON object")
                image = self.src.image_name(tex.get("image"))
                found = self._entries(tex.get("frames"), f"textures[{i}].")
                entries += [(n, e, image) for n, e in found]
        else:
            if "frames" not in doc:
                raise self.fail("not a sprite sheet: no 'frames'")
            image = self.src.image_name(meta.get("image"))
            entries = [(n, e, image) for n, e in self._entries(doc["frames"], "")]
        if not entries:
            raise self.fail("the sheet has no frames")
        if len(entries) > MAX_FRAMES:
            raise self.fail(f"{len(entries):,} frames, above the limit of {MAX_FRAMES:,}")
        frames = tuple(self._frame(n, raw, img, where) for n, (raw, where), img in entries)
        names = [f.name for f in frames]
        tags = self._tags(meta.get("frameTags", []), len(frames))
        slices = self._slices(meta.get("slices", []))
        animations = self._animations(doc.get("animations", meta.get("animations", {})), names)
        return SpriteSheet(self.src.name, frames, tags, slices, animations)

    def _entries(self, raw: Any, prefix: str) -> list[tuple[str, tuple[Any, str]]]:
        if isinstance(raw, dict):  # hash form: name -> frame, in file order
            return [(str(k), (v, f"{prefix}frames[{k!r}]")) for k, v in raw.items()]
        if isinstance(raw, list):
            out = []
            for i, v in enumerate(raw):
                name = v.get("filename", str(i)) if isinstance(v, dict) else str(i)
                out.append((str(name), (v, f"{prefix}frames[{i}]")))
            return out
        raise self.fail(f"'{prefix}frames' is {type(raw).__name__}, not a list or an object")

    # -- numbers
    def _int(self, value: Any, what: str, lo: int = 0) -> int:
        if isinstance(value, bool) or not isinstance(value, (int, float)):
            raise self.fail(f"{what} = {value!r} is not a number")
        if isinstance(value, float) and (not np.isfinite(value) or value != int(value)):
            raise self.fail(f"{what} = {value!r} is not a whole number")
        v = int(value)
        if v < lo:
            raise self.fail(f"{what} = {v} is below {lo}")
        if v > 1 << 24:
            raise self.fail(f"{what} = {v:,} is above {1 << 24:,}")
        return v

    def _box(self, raw: Any, what: str, min_size: int = 1) -> Box:
        if not isinstance(raw, dict):
            raise self.fail(f"{what} is {type(raw).__name__}, not {{x, y, w, h}}")
        return (
            self._int(raw.get("x", 0), f"{what}.x"),
            self._int(raw.get("y", 0), f"{what}.y"),
            self._int(raw.get("w"), f"{what}.w", min_size),
            self._int(raw.get("h"), f"{what}.h", min_size),
        )

    # -- images
    def _image_size(self, image: str) -> tuple[int, int]:
        entry = self._images.get(image)
        if entry is None:
            data = self.src.read(image, "the sheet image")
            from PIL import Image

            try:
                with Image.open(io.BytesIO(data)) as im:
                    w, h = im.size
            except Image.DecompressionBombError:
                w, h = _header_size(data)
            except Exception as exc:  # Pillow raises many kinds for a bad header
                raise self.fail(
                    f"the sheet image {image!r} is not a readable image ({type(exc).__name__})"
                ) from None
            if w * h > MAX_IMAGE_PIXELS or w < 1 or h < 1:
                raise self.fail(
                    f"the sheet image {image!r} claims {w}x{h} pixels (at most "
                    f"{MAX_IMAGE_PIXELS:,} pixels are read)"
                )
            entry = self._images[image] = [data, (int(w), int(h)), None]
        return entry[1]

    def _pixels(self, image: str) -> np.ndarray:
        """The sheet image decoded (top-down RGBA), for frames that need recomposing."""
        self._image_size(image)
        entry = self._images[image]
        if entry[2] is None:
            from PIL import Image

            try:
                with Image.open(io.BytesIO(entry[0])) as im:
                    entry[2] = np.asarray(im.convert("RGBA"), np.uint8)
            except Exception as exc:
                raise self.fail(
                    f"the sheet image {image!r} cannot be decoded ({type(exc).__name__}: {exc})"
                ) from None
        return entry[2]

    # -- frames
    def _frame(self, name: str, raw: Any, image: str, where: str) -> SheetFrame:
        if not isinstance(raw, dict):
            raise self.fail(f"{where} is {type(raw).__name__}, not a JSON object")
        x, y, w, h = self._box(raw.get("frame"), f"{where}.frame")
        rotated = raw.get("rotated", False)
        if not isinstance(rotated, bool):
            raise self.fail(f"{where}.rotated = {rotated!r} is not true or false")
        sw, sh = (h, w) if rotated else (w, h)  # the rectangle as stored in the sheet
        iw, ih = self._image_size(image)
        if x + sw > iw or y + sh > ih:
            raise self.fail(
                f"{where}.frame ({x}, {y}, {sw}, {sh} as stored) is outside the {iw}x{ih} "
                f"image {image!r}"
            )
        size = (w, h)
        offset = (0, 0)
        if raw.get("trimmed", False) is True or "sourceSize" in raw:
            src = raw.get("sourceSize", {"w": w, "h": h})
            if not isinstance(src, dict):
                raise self.fail(f"{where}.sourceSize is {type(src).__name__}, not {{w, h}}")
            size = (
                self._int(src.get("w"), f"{where}.sourceSize.w", 1),
                self._int(src.get("h"), f"{where}.sourceSize.h", 1),
            )
            sss = raw.get("spriteSourceSize", {"x": 0, "y": 0, "w": w, "h": h})
            ox, oy, _, _ = self._box(sss, f"{where}.spriteSourceSize")
            offset = (ox, oy)
            if ox + w > size[0] or oy + h > size[1]:
                raise self.fail(
                    f"{where}: the trimmed frame ({ox}, {oy}, {w}, {h}) does not fit its "
                    f"source size {size[0]}x{size[1]}"
                )
        duration = raw.get("duration")
        seconds = DEFAULT_DURATION
        if duration is not None:
            ms = self._int(duration, f"{where}.duration", 1)
            seconds = ms / 1000.0
        pivot = self._pivot(raw.get("pivot", raw.get("anchor")), f"{where}.pivot")
        if not rotated and offset == (0, 0) and size == (w, h):
            ref = FrameRef(image, region=(x, y, w, h))
        else:
            ref = FrameRef(self._recompose(image, (x, y, sw, sh), rotated, offset, size))
        return SheetFrame(name, ref, seconds, size, pivot)

    def _recompose(
        self, image: str, box: Box, rotated: bool, offset: tuple[int, int], size: tuple[int, int]
    ) -> PixelImage:
        """The frame's pixels upright in its untrimmed box (transparent around)."""
        x, y, sw, sh = box
        part = self._pixels(image)[y : y + sh, x : x + sw]
        if rotated:  # packers turn a frame a quarter clockwise: turn it back
            part = np.rot90(part, 1)
        out = np.zeros((size[1], size[0], 4), np.uint8)
        ph, pw = part.shape[:2]
        out[offset[1] : offset[1] + ph, offset[0] : offset[0] + pw] = part
        return PixelImage(size[0], size[1], np.ascontiguousarray(out[::-1]).tobytes())

    def _pivot(self, raw: Any, what: str) -> tuple[float, float] | None:
        if raw is None:
            return None
        if not isinstance(raw, dict):
            raise self.fail(f"{what} is {type(raw).__name__}, not {{x, y}}")
        vals = []
        for k in ("x", "y"):
            v = raw.get(k)
            if isinstance(v, bool) or not isinstance(v, (int, float)) or not np.isfinite(v):
                raise self.fail(f"{what}.{k} = {v!r} is not a finite number")
            vals.append(float(v))
        return (vals[0], 1.0 - vals[1])  # from the top-left, y down -> kge's anchor, y up

    # -- meta
    def _named(self, raw: Any, key: str) -> Iterator[tuple[str, dict[str, Any], str]]:
        """(where, entry, name) of each entry of the list ``meta.<key>``, all named."""
        if not isinstance(raw, list):
            raise self.fail(f"meta.{key} is {type(raw).__name__}, not a list")
        for i, entry in enumerate(raw):
            what = f"meta.{key}[{i}]"
            if not isinstance(entry, dict):
                raise self.fail(f"{what} is {type(entry).__name__}, not a JSON object")
            name = entry.get("name")
            if not isinstance(name, str) or not name:
                raise self.fail(f"{what}.name must be a non-empty string, got {name!r}")
            yield what, entry, name

    def _tags(self, raw: Any, n: int) -> dict[str, SheetTag]:
        out: dict[str, SheetTag] = {}
        for what, t, name in self._named(raw, "frameTags"):
            first = self._int(t.get("from"), f"{what} ({name!r}).from")
            last = self._int(t.get("to"), f"{what} ({name!r}).to")
            if last < first:
                raise self.fail(f"{what} ({name!r}): to = {last} is before from = {first}")
            if last >= n:
                raise self.fail(
                    f"{what} ({name!r}): frames {first}..{last}, but the sheet has {n} frames"
                )
            direction = t.get("direction", "forward")
            if direction not in DIRECTIONS:
                raise self.fail(
                    f"{what} ({name!r}).direction = {direction!r} (Aseprite writes "
                    f"{', '.join(DIRECTIONS)})"
                )
            repeat = t.get("repeat", 0)
            if isinstance(repeat, str):  # Aseprite writes the count as a string
                try:
                    repeat = int(repeat)
                except ValueError:
                    bad = f"{what} ({name!r}).repeat = {repeat!r}"
                    raise self.fail(f"{bad} is not a count") from None
            rep = self._int(repeat, f"{what} ({name!r}).repeat")
            if rep > 10_000:
                raise self.fail(f"{what} ({name!r}).repeat = {rep:,} is above 10,000")
            if name in out:
                raise self.fail(f"{what}: a second tag called {name!r}")
            out[name] = SheetTag(name, first, last, direction, rep)
        return out

    def _slices(self, raw: Any) -> dict[str, SheetSlice]:
        out: dict[str, SheetSlice] = {}
        for what, s, name in self._named(raw, "slices"):
            keys_raw = s.get("keys")
            if not isinstance(keys_raw, list) or not keys_raw:
                raise self.fail(f"{what} ({name!r}).keys must be a non-empty list")
            keys = []
            for j, k in enumerate(keys_raw):
                kw = f"{what} ({name!r}).keys[{j}]"
                if not isinstance(k, dict):
                    raise self.fail(f"{kw} is {type(k).__name__}, not a JSON object")
                center = k.get("center")
                pivot = k.get("pivot")
                pv = None
                if isinstance(pivot, dict):
                    lo = -(1 << 24)
                    pv = (
                        self._int(pivot.get("x"), f"{kw}.pivot.x", lo),
                        self._int(pivot.get("y"), f"{kw}.pivot.y", lo),
                    )
                keys.append(
                    SliceKey(
                        self._int(k.get("frame", 0), f"{kw}.frame"),
                        self._box(k.get("bounds"), f"{kw}.bounds", 0),
                        self._box(center, f"{kw}.center", 0) if center is not None else None,
                        pv,
                    )
                )
            keys.sort(key=lambda k: k.frame)
            color, data = s.get("color"), s.get("data")
            out[name] = SheetSlice(
                name,
                tuple(keys),
                color if isinstance(color, str) else None,
                data if isinstance(data, str) else None,
            )
        return out

    def _animations(self, raw: Any, names: list[str]) -> dict[str, tuple[int, ...]]:
        if not isinstance(raw, dict):
            raise self.fail(f"'animations' is {type(raw).__name__}, not a JSON object")
        index: dict[str, int] = {}
        for i, n in enumerate(names):
            index.setdefault(n, i)
        out: dict[str, tuple[int, ...]] = {}
        for name, frames in raw.items():
            if not isinstance(frames, list) or not frames:
                raise self.fail(f"animations[{name!r}] must be a non-empty list of frame names")
            picked = []
            for j, f in enumerate(frames):
                if f not in index:
                    raise self.fail(f"animations[{name!r}][{j}] names no frame: {f!r}")
                picked.append(index[f])
            out[str(name)] = tuple(picked)
        return out
