"""The asset store: find a game's files by name, load each once, report clearly.

An :class:`Assets` store holds an ordered list of locations (see
:mod:`kge.assets.locate`) and a cache. ``assets.image("ship.png")``,
``assets.sound("hit.wav")`` and ``assets.font("ui.ttf")`` resolve the name,
decode it on first use (importing pyglet only then) and return the cached object
afterwards, so ten sprites sharing one image decode it once and a scene that is
reloaded does not read its files again.

How a game reaches its store
----------------------------
* ``Assets(anchor=__file__)`` searches the folder of that file and its
  ``assets/`` subfolder; ``Assets.for_module(__name__)`` does the same for a
  module or package (through ``importlib.resources``, so zipped packages work).
* :func:`default_assets` is a process-wide store anchored at the running script
  (``__main__``), which suits ``python my_game.py``.
* Inside a world, :func:`assets_for` returns the world's ``Assets`` resource if
  the scene inserted one (``world.insert_resource(ASSETS)``), else the default
  store. The audio system inserts the default store into every world it is
  added to, and rendering loads sprite images through :func:`assets_for` too.

A missing file raises :class:`~kge.assets.errors.AssetNotFoundError` listing
every place searched; a file that cannot be decoded raises
:class:`~kge.assets.errors.AssetDecodeError` naming the file and, for audio,
the decoder to install. Loading screens use :meth:`Assets.preload`, which loads
a list a few files at a time and reports ``loaded`` / ``queued``.

>>> import tempfile, pathlib
>>> root = pathlib.Path(tempfile.mkdtemp())
>>> (root / "sfx").mkdir()
>>> _ = (root / "sfx" / "hit.wav").write_bytes(tone(440, 0.1, rate=8000).to_wav())
>>> store = Assets(root, anchor=root)
>>> store.resolve("sfx/hit.wav").path == root / "sfx" / "hit.wav"
True
>>> store.resolve("sfx/miss.wav")
Traceback (most recent call last):
...
kge.assets.errors.AssetNotFoundError: asset 'sfx/miss.wav' not found. Searched, in order:
  - .../sfx/miss.wav
...
"""

from __future__ import annotations

import builtins
import os
import struct
from collections.abc import Iterable
from dataclasses import dataclass
from pathlib import Path, PurePosixPath
from typing import TYPE_CHECKING, Any, Literal, cast, overload

from kge.assets import headers, loaders
from kge.assets.errors import AssetDecodeError, AssetNotFoundError
from kge.assets.fontinfo import family_name
from kge.assets.locate import (
    DirLocation,
    Found,
    Location,
    PackageLocation,
    anchor_dir,
    normalize_name,
    split_package_name,
)
from kge.assets.preload import BackgroundPreload, Decoded, Preload
from kge.errors import ValidationError
from kge.sound import SoundData, SoundRef, tone  # noqa: F401  (tone: doctest)

if TYPE_CHECKING:
    from kge.world import World


@dataclass(frozen=True, slots=True)
class FontAsset:
    """A registered font file: use ``family`` as the font name in text components."""

    family: str
    where: str


class Assets:
    """An ordered set of search locations with a cache of decoded assets.

    ``paths`` are folders; relative ones are taken relative to ``anchor`` (a
    module name, file or folder; default: the running script's folder). With no
    ``paths``, the anchor folder and its ``assets/`` subfolder are searched.
    """

    def __init__(
        self,
        *paths: str | os.PathLike[str],
        anchor: str | os.PathLike[str] | None = None,
    ) -> None:
        self._anchor = anchor_dir(anchor)
        self._locations: list[Location] = []
        self._cache: dict[tuple[str, Any], Any] = {}
        if paths:
            for p in paths:
                self.add_path(p)
        elif self._anchor is not None:
            self._locations += [DirLocation(self._anchor), DirLocation(self._anchor / "assets")]

    @classmethod
    def for_module(cls, module: str, subdir: str = "assets") -> Assets:
        """A store searching ``module``'s package (or folder) and its ``subdir``.

        Pass ``__name__``. A package is read through ``importlib.resources``, so
        the game's assets load from an installed wheel as well as a checkout.
        """
        import importlib

        mod = importlib.import_module(module)
        store = cls(anchor=module)
        if hasattr(mod, "__path__"):  # a package: use its resources
            store._locations = [PackageLocation(module), PackageLocation(module, subdir)]
        elif store._anchor is not None:
            store._locations = [DirLocation(store._anchor), DirLocation(store._anchor / subdir)]
        return store

    # -- search locations -----------------------------------------------------------
    @property
    def anchor(self) -> Path | None:
        return self._anchor

    @property
    def locations(self) -> tuple[Location, ...]:
        return tuple(self._locations)

    def add_path(self, path: str | os.PathLike[str], *, first: bool = False) -> None:
        """Search the folder ``path`` too (relative to the anchor, never the working dir)."""
        p = Path(os.fspath(path))
        if not p.is_absolute():
            if self._anchor is None:
                raise ValidationError(
                    f"Assets.add_path({os.fspath(path)!r}): a relative folder needs an anchor "
                    "(create the store with Assets(anchor=__file__)) or pass an absolute path"
                )
            p = self._anchor / p
        self._insert(DirLocation(p), first)

    def add_package(self, package: str, subdir: str = "", *, first: bool = False) -> None:
        """Search ``subdir`` inside the importable ``package`` too."""
        import importlib.resources

        try:
            importlib.resources.files(package)
        except (ModuleNotFoundError, TypeError) as exc:
            raise ValidationError(
                f"Assets.add_package({package!r}): not an importable package ({exc})"
            ) from None
        self._insert(PackageLocation(package, subdir), first)

    def _insert(self, loc: Location, first: bool) -> None:
        if loc in self._locations:
            self._locations.remove(loc)
        if first:
            self._locations.insert(0, loc)
        else:
            self._locations.append(loc)

    # -- resolution -------------------------------------------------------------------
    def _candidates(self, name: str) -> list[Location]:
        if os.path.isabs(name):
            path = Path(name)
            return [DirLocation(path.parent)] if path.name else []
        pkg = split_package_name(name)
        if pkg is not None:
            return [PackageLocation(pkg[0])]
        return list(self._locations)

    @staticmethod
    def _leaf(name: str) -> str:
        if os.path.isabs(name):
            return Path(name).name
        pkg = split_package_name(name)
        return pkg[1] if pkg is not None else name

    def searched(self, name: str | os.PathLike[str]) -> list[str]:
        """Every place :meth:`resolve` looks for ``name``, in order."""
        n = normalize_name(name)
        leaf = self._leaf(n)
        return [loc.describe(leaf) for loc in self._candidates(n)]

    def find(self, name: str | os.PathLike[str]) -> Found | None:
        """The first location holding ``name``, or None."""
        n = normalize_name(name)
        leaf = self._leaf(n)
        if ".." in PurePosixPath(leaf).parts and not os.path.isabs(n):
            return None  # no escaping the search folders with "../"
        for loc in self._candidates(n):
            hit = loc.find(leaf)
            if hit is not None:
                return hit
        return None

    def resolve(self, name: str | os.PathLike[str], owner: str = "") -> Found:
        """Like :meth:`find`, but a missing asset raises ``AssetNotFoundError``."""
        hit = self.find(name)
        if hit is None:
            n = normalize_name(name)
            raise AssetNotFoundError(n, self.searched(n), owner)
        return hit

    def exists(self, name: str | os.PathLike[str]) -> bool:
        return self.find(name) is not None

    # -- loading ------------------------------------------------------------------------
    def bytes(self, name: str | os.PathLike[str]) -> bytes:
        """The raw content of ``name`` (not cached)."""
        found = self.resolve(name)
        try:
            return found.read_bytes()
        except OSError as exc:
            raise AssetDecodeError(found.name, found.where, f"unreadable: {exc}") from exc

    def checked_image(self, name: str | os.PathLike[str], owner: str = "") -> tuple[int, int]:
        """Find ``name`` and check it is an image kge can load, without decoding it;
        its (width, height). Cached per file; see :mod:`kge.assets.headers`."""
        found = self.resolve(name, owner)
        key = ("image-header", found.where)
        if key not in self._cache:
            try:
                size = headers.image_size(found.read_bytes())
            except (OSError, ValueError) as exc:
                raise AssetDecodeError(found.name, found.where, str(exc), owner) from None
            self._cache[key] = size
        return cast(tuple[int, int], self._cache[key])

    def checked_sound(self, name: str | os.PathLike[str], owner: str = "") -> Found:
        """Find ``name`` and, for a WAV, check its header describes samples kge can play
        (other formats are checked by their decoders). Cached per file."""
        found = self.resolve(name, owner)
        key = ("sound-header", found.where)
        if found.suffix in headers.WAV_SUFFIXES and key not in self._cache:
            try:
                with found.resource.open("rb") as f:
                    self._cache[key] = headers.wav_info(f)
            except (OSError, ValueError, struct.error) as exc:
                raise AssetDecodeError(found.name, found.where, str(exc), owner) from None
        return found

    def image(self, name: str | os.PathLike[str]) -> Any:
        """``name`` decoded as a ``pyglet.image.AbstractImage`` (cached)."""
        found = self.resolve(name)
        key = ("image", found.where)
        if key not in self._cache:
            self._cache[key] = loaders.load_image(found)
        return self._cache[key]

    def sound(self, name: SoundRef, *, streaming: bool = False) -> Any:
        """A pyglet media source for ``name`` (an asset name or a :class:`SoundData`).

        Static sources (the default) are decoded once, cached and can play on many
        players at once: use them for effects. ``streaming=True`` decodes while
        playing (long music); a streaming source plays on one player at a time, so
        each call returns a fresh one.
        """
        if isinstance(name, SoundData):
            gen_key: tuple[str, Any] = ("generated", name)  # equal data share a source
            if gen_key not in self._cache:
                self._cache[gen_key] = loaders.load_generated(name)
            return self._cache[gen_key]
        found = self.resolve(name)
        if streaming:
            return loaders.load_sound(found, streaming=True)
        key = ("sound", found.where)
        if key not in self._cache:
            self._cache[key] = loaders.load_sound(found, streaming=False)
        return self._cache[key]

    def font(self, name: str | os.PathLike[str]) -> FontAsset:
        """Register a font file with pyglet (once) and return its family name."""
        found = self.resolve(name)
        if ("font", found.where) not in self._cache:
            try:
                data = found.read_bytes()
            except OSError as exc:
                raise AssetDecodeError(found.name, found.where, f"unreadable: {exc}") from exc
            self._register_font(found, data)
        font: FontAsset = self._cache[("font", found.where)]
        return font

    def _register_font(self, found: Found, data: builtins.bytes) -> None:
        family = family_name(data)
        if family is None:
            raise AssetDecodeError(
                found.name, found.where, "not a TrueType/OpenType font (no name table)"
            )
        loaders.register_font(found)
        self._cache[("font", found.where)] = FontAsset(family, found.where)

    def adopt(self, decoded: Decoded) -> Any:
        """Make an asset decoded off the main thread (:func:`decode`) ready to use and
        cache it as :meth:`load` would; its object (image, sound, font or bytes). Call
        it on the main thread: it builds pyglet objects."""
        found, kind, value = decoded.found, decoded.kind, decoded.value
        key = (kind, found.where)
        if kind == "bytes":
            return value
        if key not in self._cache:
            if kind == "image":
                self._cache[key] = loaders.image_from_pixels(*value)
            elif kind == "sound":
                self._cache[key] = loaders.sound_from_pcm(*value)
            else:
                self._register_font(found, value)
        return self._cache[key]

    def load(self, name: str | os.PathLike[str]) -> Any:
        """Load ``name`` by its suffix: image, sound (static), font or raw bytes."""
        suffix = PurePosixPath(normalize_name(name)).suffix.lower()
        if suffix in loaders.IMAGE_SUFFIXES:
            return self.image(name)
        if suffix in loaders.SOUND_SUFFIXES:
            return self.sound(name)
        if suffix in loaders.FONT_SUFFIXES:
            return self.font(name)
        return self.bytes(name)

    def is_cached(self, name: str | os.PathLike[str]) -> bool:
        hit = self.find(name)
        return hit is not None and any(key[1] == hit.where for key in self._cache)

    def clear_cache(self) -> None:
        """Forget decoded assets (they reload on next use)."""
        self._cache.clear()

    def forget(self, path: str | os.PathLike[str]) -> bool:
        """Forget what was decoded from the file ``path`` (it reloads on next use; hot
        reload calls this when the file changes). True when something was cached."""
        target = os.path.realpath(path)
        stale = [k for k in self._cache if isinstance(k[1], str)
                 and os.path.realpath(k[1]) == target]
        for k in stale:
            del self._cache[k]
        return bool(stale)

    @overload
    def preload(
        self, names: Iterable[str | os.PathLike[str]], *, background: Literal[True]
    ) -> BackgroundPreload: ...

    @overload
    def preload(
        self, names: Iterable[str | os.PathLike[str]], *, background: bool = False
    ) -> Preload: ...

    def preload(
        self, names: Iterable[str | os.PathLike[str]], *, background: bool = False
    ) -> Preload:
        """Queue ``names`` for loading a few at a time (see :class:`Preload`); with
        ``background=True``, decoding runs on worker threads
        (:class:`kge.assets.preload.BackgroundPreload`)."""
        if background:
            return BackgroundPreload(self, names)
        return Preload(self, names)

    def __repr__(self) -> str:
        where = ", ".join(loc.describe("") for loc in self._locations)
        return f"Assets([{where}])"


_default: Assets | None = None


def default_assets() -> Assets:
    """The process-wide store, anchored at the running script (created on first use)."""
    global _default
    if _default is None:
        _default = Assets()
    return _default


def set_default_assets(store: Assets) -> Assets:
    """Replace the process-wide store (e.g. with ``Assets.for_module(__name__)``)."""
    global _default
    if not isinstance(store, Assets):
        raise ValidationError(f"set_default_assets() needs an Assets store, got {store!r}")
    _default = store
    return store


def assets_for(world: World) -> Assets:
    """The store a world uses: its ``Assets`` resource, else :func:`default_assets`."""
    store = world.try_resource(Assets)
    return store if store is not None else default_assets()
