"""Errors raised by the asset store.

Why they subclass two builtins: a caller that knows nothing about kge catches
``FileNotFoundError`` (or ``ValueError``) the way it would for ``open()``; a kge
user catches :class:`kge.KgeError`; and DESIGN.md lists an unknown asset path as
bad input, which kge reports as a ``ValueError``. Every message names the asset,
the path that was tried and every place that was searched, because "file not
found" with no context is what made KGE scenes hard to debug.
"""

from __future__ import annotations

from collections.abc import Sequence

from kge.errors import KgeError


class AssetError(KgeError):
    """Base of every asset failure (missing, unreadable, undecodable)."""


class AssetNotFoundError(AssetError, FileNotFoundError, ValueError):
    """No search location holds the asset. ``searched`` lists where kge looked."""

    def __init__(self, name: str, searched: Sequence[str], owner: str = "") -> None:
        self.name = name
        self.searched = tuple(searched)
        places = "\n".join(f"  - {p}" for p in self.searched) or "  (no search paths)"
        prefix = f"{owner}: " if owner else ""
        super().__init__(
            f"{prefix}asset {name!r} not found. Searched, in order:\n{places}\n"
            "Paths are resolved against the game's own module or package (never the "
            "working directory); add folders with Assets.add_path() or "
            "Assets.add_package()."
        )

    def __str__(self) -> str:  # OSError would format (errno, strerror) otherwise
        return str(self.args[0]) if self.args else ""


class AssetDecodeError(AssetError, ValueError):
    """The file exists but could not be read or decoded."""

    def __init__(self, name: str, path: str, reason: str, owner: str = "") -> None:
        self.name = name
        self.path = path
        self.reason = reason
        prefix = f"{owner}: " if owner else ""
        super().__init__(f"{prefix}asset {name!r} ({path}) could not be loaded: {reason}")


class DecoderMissingError(AssetDecodeError):
    """No decoder for a format is installed. kge no longer raises it (soundfile decodes
    WAV, OGG, MP3 and FLAC with no system library); kept so code catching it imports."""
