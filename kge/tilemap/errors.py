"""The errors and warnings of map loading (they name the file, layer and object)."""

from __future__ import annotations

from kge.errors import KgeError


class TilemapError(KgeError, ValueError):
    """A map could not be loaded or changed: missing file, unsupported feature, bad data.

    The message names the map file and, where it applies, the layer and object.
    Nothing of the map is left in the world when this is raised by ``load_map``.
    """


class TilemapWarning(UserWarning):
    """A map object whose class has no spawner was spawned with the default components."""
