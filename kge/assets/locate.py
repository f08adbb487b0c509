"""Where assets are looked for: folders on disk and package resources.

KGE opened ``"assets/pad.png"`` relative to the *working directory*, so a game
only started from one folder. kge resolves a name against an ordered list of
locations instead, anchored at the game's own module or package:

* a :class:`DirLocation` is a folder on disk (relative folders are taken
  relative to the anchor, never to the working directory);
* a :class:`PackageLocation` is a folder inside an importable package, read
  through :mod:`importlib.resources`, so assets also load from a wheel or zip;
* an absolute path is used as it is, and ``"package.module:sub/file.png"``
  names a package resource explicitly.

The first location holding a file of that name wins. Nothing here imports
pyglet: resolution and its errors are testable anywhere.

>>> import tempfile, pathlib
>>> root = pathlib.Path(tempfile.mkdtemp())
>>> _ = (root / "beep.wav").write_bytes(b"RIFF")
>>> DirLocation(root).find("beep.wav").read_bytes()
b'RIFF'
>>> DirLocation(root).find("nope.wav") is None
True
"""

from __future__ import annotations

import importlib
import importlib.resources
import os
import sys
from dataclasses import dataclass
from importlib.resources.abc import Traversable
from pathlib import Path, PurePosixPath
from typing import Protocol

from kge.errors import ValidationError


@dataclass(frozen=True, slots=True)
class Found:
    """A located asset: its name, a printable location and how to read it."""

    name: str
    where: str  #: printable and unique: the cache key
    resource: Traversable  #: a Path for files on disk

    @property
    def path(self) -> Path | None:
        """The file on disk, or None for a resource inside a zip or wheel."""
        return self.resource if isinstance(self.resource, Path) else None

    @property
    def suffix(self) -> str:
        return PurePosixPath(self.name).suffix.lower()

    def read_bytes(self) -> bytes:
        return self.resource.read_bytes()


class Location(Protocol):
    """One place to look: ``find`` returns the file or None; ``describe`` says where."""

    def find(self, name: str) -> Found | None: ...

    def describe(self, name: str) -> str: ...


@dataclass(frozen=True, slots=True)
class DirLocation:
    """A folder on disk."""

    root: Path

    def find(self, name: str) -> Found | None:
        path = self.root / name
        return Found(name, str(path), path) if path.is_file() else None

    def describe(self, name: str) -> str:
        return str(self.root / name)


@dataclass(frozen=True, slots=True)
class PackageLocation:
    """A folder inside an importable package (``importlib.resources``)."""

    package: str
    subdir: str = ""

    def _base(self) -> Traversable:
        base = importlib.resources.files(self.package)
        return base.joinpath(*PurePosixPath(self.subdir).parts) if self.subdir else base

    def find(self, name: str) -> Found | None:
        try:
            res = self._base().joinpath(*PurePosixPath(name).parts)
        except (ModuleNotFoundError, TypeError):
            return None
        return Found(name, self.describe(name), res) if res.is_file() else None

    def describe(self, name: str) -> str:
        inner = "/".join(p for p in (self.subdir, name) if p)
        return f"package {self.package}: {inner}"


def normalize_name(name: object, owner: str = "asset name") -> str:
    """Check an asset name and give it forward slashes.

    >>> normalize_name("sprites\\\\ship.png")
    'sprites/ship.png'
    >>> normalize_name("")
    Traceback (most recent call last):
    ...
    kge.errors.ValidationError: asset name must be a non-empty file name, got ''
    """
    if isinstance(name, os.PathLike):
        name = os.fspath(name)
    if not isinstance(name, str) or not name.strip():
        raise ValidationError(f"{owner} must be a non-empty file name, got {name!r}")
    return name.replace("\\", "/") if not os.path.isabs(name) else name


def anchor_dir(anchor: str | os.PathLike[str] | None) -> Path | None:
    """The folder a store is anchored at.

    ``anchor`` is a module name (``__name__``), a file (``__file__``) or a folder.
    None means the folder of the running script (``__main__``), which is what
    ``python examples/pong.py`` expects whatever the working directory is. There
    is no working-directory fallback on purpose.
    """
    if anchor is None:
        main_file = getattr(sys.modules.get("__main__"), "__file__", None)
        return Path(main_file).resolve().parent if main_file else None
    text = os.fspath(anchor)
    path = Path(text)
    if isinstance(anchor, os.PathLike) or path.is_absolute():
        if path.is_dir():
            return path.resolve()
        if path.is_file():
            return path.resolve().parent
        frozen = getattr(sys, "frozen", False)
        if frozen and path.suffix in (".py", ".pyc") and path.parent.is_dir():
            # a built game (kge export): modules live in an archive, so a module's
            # __file__ names no file, but its package folder holds the assets
            return path.parent.resolve()
        raise ValidationError(f"asset anchor {text!r} does not exist")
    try:  # a relative string is a module name: relative paths would depend on the cwd
        module = importlib.import_module(text)
    except (ImportError, ValueError, TypeError):
        raise ValidationError(
            f"asset anchor {text!r} is not an importable module; pass __name__, or "
            "__file__ / an absolute folder (relative paths would depend on the working "
            "directory)"
        ) from None
    file = getattr(module, "__file__", None)
    if file is None:
        return None
    return Path(file).resolve().parent


def split_package_name(name: str) -> tuple[str, str] | None:
    """``"pkg.sub:img/a.png"`` -> ``("pkg.sub", "img/a.png")``; None for plain names.

    >>> split_package_name("mygame.data:sfx/hit.wav")
    ('mygame.data', 'sfx/hit.wav')
    >>> split_package_name("C:/games/hit.wav") is None
    True
    """
    pkg, sep, rest = name.partition(":")
    if not sep or not rest or len(pkg) < 2 or "/" in pkg:
        return None
    if not all(part.isidentifier() for part in pkg.split(".")):
        return None
    return pkg, rest
