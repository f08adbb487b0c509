"""Reading a map's files safely: size limits checked before allocating, no path outside the game.

A Tiled map names other files (tilesets, templates, images). A map from
someone else may name ``/etc/hostname``, ``../../../etc/passwd`` or
``/dev/zero``, or declare a grid of 100,000 x 100,000 tiles in 200 bytes. Every
file a map load touches goes through one :class:`MapReader` reader, which

* resolves a relative name against the file that names it (never the working
  directory), and refuses a path outside the allowed folders (the map's own
  folder and the game's asset folders by default);
* opens regular files only (``/dev/zero`` and named pipes are refused) and
  reads at most :attr:`MapLimits.file_bytes` bytes;
* carries the :class:`MapLimits` the parser checks before it allocates a grid,
  a gid table or a decompressed layer.

>>> import tempfile, pathlib
>>> root = pathlib.Path(tempfile.mkdtemp())
>>> _ = (root / "m.tmx").write_text("<map/>")
>>> files = MapReader(root / "m.tmx")
>>> files.read_text(root / "m.tmx")
'<map/>'
>>> files.resolve(root / "m.tmx", "/etc/hostname")
Traceback (most recent call last):
...
kge.tilemap.errors.TilemapError: .../m.tmx: '/etc/hostname' is outside the folders this map...
"""

from __future__ import annotations

import os
from collections.abc import Iterable
from dataclasses import dataclass
from pathlib import Path

from kge.platform import regular_file_size
from kge.tilemap.errors import TilemapError


@dataclass(frozen=True, slots=True)
class MapLimits:
    """Upper bounds a map load checks before allocating (raise them for huge maps).

    ``load_map(world, path, limits=MapLimits(tiles=64_000_000))`` lets one game
    load bigger maps; the defaults fit any map Tiled itself edits comfortably.
    """

    file_bytes: int = 64 * 1024 * 1024  #: any one file: map, tileset, template
    tiles: int = 16 * 1024 * 1024  #: cells of one layer (columns x rows, chunks' span)
    tilecount: int = 1 << 20  #: tiles of one tileset
    gids: int = 1 << 22  #: highest gid + 1 (the gid tables are this long)
    image_pixels: int = 16384 * 16384  #: width x height of one image
    nesting: int = 100  #: group layers inside group layers
    objects: int = 1_000_000  #: objects in the whole map
    files: int = 10_000  #: files one map may read (tilesets, templates, images)

    def check(self, what: str, value: int, limit_name: str) -> None:
        limit = int(getattr(self, limit_name))
        if value > limit:
            raise TilemapError(
                f"{what} is {value:,}, above the limit of {limit:,} "
                f"(MapLimits.{limit_name}; pass load_map(..., limits=MapLimits({limit_name}=...)) "
                "to allow more)"
            )


def _inside(path: Path, roots: Iterable[Path]) -> bool:
    return any(path == r or path.is_relative_to(r) for r in roots)


class MapReader:
    """The files one map load may read: under ``roots`` (default: the map's folder)."""

    def __init__(
        self,
        map_path: str | os.PathLike[str],
        roots: Iterable[str | os.PathLike[str]] = (),
        limits: MapLimits | None = None,
    ) -> None:
        self.map = Path(os.path.abspath(map_path))
        self.roots = [self.map.parent.resolve()] + [Path(r).resolve() for r in roots]
        self.limits = limits or MapLimits()
        self.read_count = 0

    def resolve(self, owner: Path, name: str) -> Path:
        """``name`` as written in the file ``owner``: an absolute path inside the roots."""
        if not isinstance(name, str) or not name.strip() or "\x00" in name:
            raise TilemapError(f"{owner}: file name {name!r} is not a file name")
        raw = Path(name.replace("\\", "/")) if not os.path.isabs(name) else Path(name)
        path = raw if raw.is_absolute() else owner.parent / raw
        path = Path(os.path.abspath(path))
        real = path.resolve()
        if not _inside(real, self.roots):
            allowed = ", ".join(str(r) for r in self.roots)
            raise TilemapError(
                f"{owner}: {name!r} is outside the folders this map may read ({allowed}); "
                "pass load_map(..., roots=[folder]) to allow another folder"
            )
        return path

    def check_file(self, owner: Path, path: Path, what: str) -> int:
        """The size of a regular file at ``path``; a clear error for anything else."""
        try:
            size = regular_file_size(path)
        except ValueError as exc:
            raise TilemapError(f"{owner}: {what} {str(path)!r} {exc}") from None
        self.read_count += 1
        self.limits.check(f"{owner}: the number of files read", self.read_count, "files")
        return size

    def read_bytes(self, path: Path, owner: Path | None = None, what: str = "file") -> bytes:
        owner = owner or path
        size = self.check_file(owner, path, what)
        cap = self.limits.file_bytes
        self.limits.check(f"{path}: the file size in bytes", size, "file_bytes")
        try:
            with open(path, "rb") as fh:
                data = fh.read(cap + 1)
        except OSError as exc:
            raise TilemapError(f"{owner}: {what} {str(path)!r} unreadable ({exc})") from None
        self.limits.check(f"{path}: the file size in bytes", len(data), "file_bytes")
        return data

    def read_text(self, path: Path, owner: Path | None = None, what: str = "file") -> str:
        data = self.read_bytes(path, owner, what)
        try:
            return data.decode("utf-8-sig")
        except UnicodeDecodeError as exc:
            raise TilemapError(f"{path}: not UTF-8 text ({exc})") from None

    def image_size(self, owner: Path, path: Path, what: str) -> tuple[int, int]:
        """(width, height) of an image from its header, checked against the pixel limit."""
        self.check_file(owner, path, what)
        from PIL import Image

        try:
            with Image.open(path) as im:
                w, h = im.size
        except Exception as exc:  # Pillow raises many kinds for a bad header
            raise TilemapError(
                f"{owner}: {what} {str(path)!r} is not a readable image "
                f"({type(exc).__name__}: {exc})"
            ) from None
        if w <= 0 or h <= 0:
            raise TilemapError(f"{owner}: {what} {str(path)!r} is {w}x{h} pixels (empty)")
        self.limits.check(f"{owner}: {what} {str(path)!r}: pixels", w * h, "image_pixels")
        return int(w), int(h)
