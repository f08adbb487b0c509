"""File format versions and the migrations between them.

Every kge file starts with ``format = N``. A file of an older format is brought
to the current one by the migrations registered for each step before anything
is read from it; a newer one is refused with a message saying so. Renamed fields
and types of a game's own components need no migration function: register the
type with ``renamed={"old": "new"}`` or ``previous_names=("Old",)``.

>>> @migration(0)
... def _add_kind(data):
...     return {**data, "kind": data.get("kind", "scene")}
>>> sorted(_MIGRATIONS)
[0]
>>> del _MIGRATIONS[0]
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

from kge.scenefile.codec import Source
from kge.scenefile.errors import SceneFileError

#: the format kge writes
FORMAT = 1

Migration = Callable[[dict[str, Any]], dict[str, Any]]
_MIGRATIONS: dict[int, Migration] = {}


def migration(from_format: int) -> Callable[[Migration], Migration]:
    """Register ``fn(data) -> data`` turning a parsed file of ``from_format`` into the next
    format (a decorator)."""

    def add(fn: Migration) -> Migration:
        _MIGRATIONS[from_format] = fn
        return fn

    return add


def migrate(data: dict[str, Any], source: Source) -> dict[str, Any]:
    """``data`` brought to :data:`FORMAT` (or a clear error)."""
    version = data.get("format")
    if isinstance(version, bool) or not isinstance(version, int):
        raise SceneFileError(
            source.where(("format",)), f"a kge file starts with format = {FORMAT}, got "
            f"{version!r}"
        )
    if version > FORMAT:
        raise SceneFileError(
            source.where(("format",)), f"format {version} was written by a newer kge (this one "
            f"reads up to {FORMAT})"
        )
    while version < FORMAT:
        step = _MIGRATIONS.get(version)
        if step is None:
            raise SceneFileError(source.where(("format",)), f"format {version} is too old to "
                                 "read (no migration from it)")
        data = step(data)
        version += 1
    return data
