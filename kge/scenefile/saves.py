"""Game saves read back safely: ``load_game(path)`` and ``App.restore(save)``.

A save is a text file of kind ``save``: every entity under its own id, every
field including what physics writes back (velocities, awake flags, joint
angles), the id counter and the simulation's resources. Reading one runs no code
the file names (it only builds registered types), and everything is checked
before the world changes, as for scenes.
"""

from __future__ import annotations

import os
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Any

from kge.scenefile.document import Document
from kge.scenefile.errors import SceneFileError, Where
from kge.scenefile.load import Loader, resolve_file
from kge.scenefile.registry import TypeRegistry
from kge.snapshot import SnapshotError, restore_state

if TYPE_CHECKING:
    from kge.world import World


@dataclass(slots=True)
class SavedGame:
    """A save file read and checked for shape; :meth:`restore_into` builds it into a world
    (``app.restore(save)``, ``World.restore(save)``)."""

    path: Path
    name: str
    document: Document
    registry: TypeRegistry | None = None

    def restore_into(self, world: World) -> World:
        """Fill the empty ``world`` from this save (all or nothing)."""
        loader = Loader(world, self.registry, (), save=True)
        doc = self.document
        ids = {e.key: int(e.key) for e in doc.entries}
        from kge.scenefile.codec import Decoder
        from kge.scenefile.document import Row

        entities: dict[int, list[Any]] = {}
        for entry in doc.entries:
            row = Row(entry.key, "", doc.source, entry, name=entry.name)
            entities[int(entry.key)] = loader.row(row, ids, int(entry.key))
        decoder = Decoder(loader.registry, doc.source, loader.resolver(ids, ""), save=True)
        resources = []
        for name, table in doc.resources.items():
            info = loader.registry.get(name)
            where = doc.source.where(("resources", name), component=name)
            if info is None or "resource" not in info.kinds:
                raise SceneFileError(where, f"unknown resource {name!r}")
            resources.append(decoder.component(info, table, ("resources", name), where))
        try:
            restore_state(world, entities, doc.next_id, resources)
        except SnapshotError as exc:
            raise SceneFileError(Where(path=self.path), str(exc)) from exc
        loader.maps(doc, None)
        return world


def load_game(
    path: str | os.PathLike[str], *, registry: TypeRegistry | None = None
) -> SavedGame:
    """Read the save file ``path`` (written by :func:`kge.save_game`) for ``app.restore``."""
    from kge.world import World

    scratch = World()
    try:
        target = resolve_file(scratch, path)
        doc = Loader(scratch, registry, ()).open(target)
    finally:
        scratch.close()
    if doc.kind != "save":
        raise SceneFileError(Where(path=doc.source.path), f"a {doc.kind} file, not a save "
                             "(load scenes with kge.load_scene)")
    return SavedGame(target, doc.name or "", doc, registry)
