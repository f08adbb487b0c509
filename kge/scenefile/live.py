"""A changed prefab file reaching the instances of a running world, field by field.

Each instance's members are built twice without spawning anything, from the
prefab as the world loaded it and from the file as it is now; every field that
differs between the two, and that the instance does not override, is written into
the live component. So a designer who changes a wheel's friction sees every car
grip differently at once, while each body keeps its position and velocity.
"""

from __future__ import annotations

import dataclasses
import os
from pathlib import Path
from typing import TYPE_CHECKING, Any

from kge.scenefile.codec import Source, same
from kge.scenefile.document import Document, Entry, expand
from kge.scenefile.load import Loader
from kge.scenefile.state import Instance, SceneState

if TYPE_CHECKING:
    from kge.world import World


def _members(loader: Loader, inst: Instance, world: World) -> dict[str, list[Any]]:
    folder = inst.prefab.parent
    entry_source = Source(None, None, loader.paths(folder))
    entry = Entry(0, inst.key, None, inst.prefab.name, inst.at, inst.overrides, {})
    doc = Document(entry_source, "scene", [entry], {}, [])
    rows = expand(doc, loader.open)
    keys = {f"{inst.key}/{m}": e for m, e in inst.members.items()}
    out: dict[str, list[Any]] = {}
    for row in rows:
        if row.member is not None and row.member in inst.members:
            out[row.member] = loader.row(row, keys, inst.members[row.member])
    return out


def patch_prefab(world: World, path: str | os.PathLike[str]) -> list[str]:
    """Write what changed in the prefab file ``path`` into every live instance using it.

    Returns one line per field written ("car/rear/tyre Collider.friction"). A bad
    file raises :class:`~kge.scenefile.SceneFileError` before anything is written.
    """
    state = world.try_resource(SceneState)
    real = Path(os.path.realpath(path))
    if state is None or real not in state.files:
        return []
    old_loader = Loader(world, None, ())
    old_loader.preload(state.files)
    new_loader = Loader(world, None, ())
    plans: list[tuple[Instance, dict[str, list[Any]], dict[str, list[Any]]]] = []
    for inst in state.instances.values():
        before = _members(old_loader, inst, world)
        after = _members(new_loader, inst, world)
        plans.append((inst, before, after))
    written: list[str] = []
    for inst, before, after in plans:
        for member, comps in after.items():
            entity = inst.members[member]
            if not world.exists(entity):
                continue
            old = {type(c): c for c in before.get(member, [])}
            for new in comps:
                live = world.try_get(entity, type(new))
                prev = old.get(type(new))
                if live is None:
                    if prev is None:
                        world.add(entity, new)
                        written.append(f"{inst.key}/{member} +{type(new).__name__}")
                    continue
                if prev is None or not dataclasses.is_dataclass(new):
                    continue
                overridden = inst.overrides.get(member, {}).get(type(new).__name__, {})
                for f in dataclasses.fields(new):
                    if not f.init or f.name.startswith("_") or f.name in overridden:
                        continue
                    value = getattr(new, f.name)
                    if not same(getattr(prev, f.name), value):
                        setattr(live, f.name, value)
                        written.append(f"{inst.key}/{member} {type(new).__name__}.{f.name}")
    state.files.update(new_loader.texts())
    return written
