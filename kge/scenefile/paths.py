"""Asset and prefab paths in scene files: relative to the file, never outside the game.

In a file, an image, sound or prefab is a relative POSIX path from the file's own
folder (``"../assets/ship.png"`` from ``levels/one.scene.toml``), so a folder of
levels and art can move as a whole. Loading resolves it and checks that it stays
inside the folders the game allows: the scene file's folder, every folder of the
world's asset store, and any ``asset_roots`` the game adds. An absolute path, a
drive letter, a NUL byte, or a ``..`` that climbs out of those folders is refused
before any file is opened. A name that is no file next to the scene but that the
asset store finds (``"ship.png"`` from the game's ``assets/`` folder, or a packaged
asset) is kept as the store's name.

Saving writes each file-backed asset relative to the new file's folder (save-as to
another folder keeps every reference working).
"""

from __future__ import annotations

import os
from collections.abc import Iterable
from pathlib import Path, PurePosixPath, PureWindowsPath
from typing import TYPE_CHECKING, Any

from kge.scenefile.errors import SceneFileError, Where

if TYPE_CHECKING:
    from kge.assets.store import Assets

#: longest asset path accepted, characters
MAX_PATH = 1024


def _inside(path: Path, root: Path) -> bool:
    try:
        path.relative_to(root)
    except ValueError:
        return False
    return True


class AssetPaths:
    """Resolves (on load) and relativises (on save) the asset paths of one file."""

    def __init__(
        self, folder: Path, store: Assets | None = None, roots: Iterable[Path] = ()
    ) -> None:
        self.folder = Path(os.path.realpath(folder))
        self.store = store
        allowed = [self.folder, *(Path(os.path.realpath(r)) for r in roots)]
        if store is not None:
            from kge.assets.locate import DirLocation

            allowed += [
                Path(os.path.realpath(loc.root)) for loc in store.locations
                if isinstance(loc, DirLocation)
            ]
        self.roots = list(dict.fromkeys(allowed))

    def check_text(self, text: Any, where: Where) -> str:
        """The path as written, checked for form (not yet for existence)."""
        if not isinstance(text, str):
            raise SceneFileError(
                where, f"an asset path must be a string, got {type(text).__name__} {text!r}"
            )
        if not text or len(text) > MAX_PATH:
            raise SceneFileError(where, f"an asset path must be 1..{MAX_PATH} characters")
        if "\0" in text or "\\" in text:
            raise SceneFileError(
                where, f"asset path {text!r}: use '/' between folders (no '\\\\' or NUL)"
            )
        if PurePosixPath(text).is_absolute() or PureWindowsPath(text).drive:
            raise SceneFileError(
                where, f"asset path {text!r} is absolute; write it relative to the scene file"
            )
        return text

    def load(self, text: Any, where: Where) -> str:
        """A path from a file -> the value the component holds (absolute path, or a store name)."""
        text = self.check_text(text, where)
        candidate = Path(os.path.normpath(self.folder / text))
        real = Path(os.path.realpath(candidate))
        if not any(_inside(real, root) for root in self.roots):
            raise SceneFileError(
                where,
                f"asset path {text!r} leads outside the folders this game allows "
                f"({', '.join(str(r) for r in self.roots)})",
            )
        if real.is_file():
            return str(real)
        climbs = ".." in PurePosixPath(text).parts
        if not climbs and self.store is not None and self.store.find(text) is not None:
            return text
        searched = [str(candidate)]
        if self.store is not None and ".." not in PurePosixPath(text).parts:
            searched += self.store.searched(text)
        raise SceneFileError(
            where, f"asset {text!r} not found; searched: {', '.join(searched)}"
        )

    def save(self, value: Any, where: Where) -> str:
        """A component's asset value -> the path written in the file."""
        if isinstance(value, os.PathLike):
            value = os.fspath(value)
        if not isinstance(value, str):
            raise SceneFileError(
                where,
                f"an in-memory {type(value).__name__} cannot be written to a file; give the "
                "component an asset name or path (save the image or sound as a file first)",
            )
        path: Path | None = None
        if os.path.isabs(value):
            path = Path(value)
        elif self.store is not None:
            found = self.store.find(value)
            path = None if found is None else found.path
        if path is None:
            return self.check_text(value, where)
        real = Path(os.path.realpath(path))
        if not any(_inside(real, root) for root in self.roots):
            raise SceneFileError(
                where, f"{value} is outside the folders a file may name (the file's folder and "
                f"the asset store's: {', '.join(map(str, self.roots))}); it would not load back"
            )
        return self.relative(real)

    def prefab(self, text: Any, where: Where) -> Path:
        """A prefab file named by a scene: the same rules, and it must be a file."""
        text = self.check_text(text, where)
        real = Path(os.path.realpath(self.folder / text))
        if not any(_inside(real, root) for root in self.roots):
            raise SceneFileError(
                where, f"prefab path {text!r} leads outside the folders this game allows"
            )
        if not real.is_file():
            raise SceneFileError(where, f"prefab {text!r} not found (looked for {real})")
        return real

    def relative(self, path: Path) -> str:
        """``path`` relative to this file's folder, POSIX style."""
        rel = os.path.relpath(os.path.realpath(path), self.folder)
        return PurePosixPath(*Path(rel).parts).as_posix()
