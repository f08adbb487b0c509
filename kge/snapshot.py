"""Save and restore a world: every entity, component and physics-relevant resource.

A snapshot is bytes (pickle, protocol 5) holding the entity table with the
original ids, the id counter, and the resources that describe the simulation
(:class:`~kge.physics.settings.PhysicsSettings`). Everything the physics
system needs to continue lives in components (poses in ``Transform``, velocities
and the awake flag in ``RigidBody``, joint settings in the joint components), so
a restored world rebuilds its pymunk space from them and carries on.

What is not saved, and why:

* pymunk's contact cache (warm-starting impulses): pymunk cannot export it, so a
  restored world re-solves resting contacts from zero. The effect is measured in
  the tests: bodies at rest stay within millimetres, and a restored falling
  scene matches the original exactly until the first contact.
* running coroutines (Python generators cannot be pickled) and the
  back-references scripts hold to their world; ``on_start`` does not run again.
* pyglet and audio objects: they are rebuilt from components by their systems.

Behaviour scripts are saved when their classes are importable (module level),
as with any pickle.

>>> from kge.components import Transform
>>> from kge.world import World
>>> w = World()
>>> e = w.spawn(Transform(1.0, 2.0))
>>> copy = World.restore(snapshot(w))
>>> copy.get(e, Transform)
Transform(x=1.0, y=2.0, angle=0.0)
"""

from __future__ import annotations

import copy
import itertools
import os
import pickle
from typing import TYPE_CHECKING, Any

import esper

from kge.errors import KgeError

if TYPE_CHECKING:
    from kge.world import World

FORMAT = 1


class SnapshotError(KgeError, ValueError):
    """The data is not a kge snapshot, or one of an unsupported format."""


#: resource types that are simulation state, kept in snapshots (registered by their
#: modules, e.g. ``PhysicsSettings``); other resources belong to the running systems
_KEPT: list[type] = []


def keep_resource(resource_type: type) -> type:
    """Keep resources of ``resource_type`` in snapshots (usable as a class decorator)."""
    if resource_type not in _KEPT:
        _KEPT.append(resource_type)
    return resource_type


def _state_resources(world: World) -> list[Any]:
    return [r for t in _KEPT if (r := world.try_resource(t)) is not None]


def _next_id(world: World) -> int:
    world._use()
    counter = esper._entity_count
    return int(next(copy.copy(counter)))


def snapshot(world: World) -> bytes:
    """Bytes that :func:`restore` turns back into an equal world."""
    if world.is_locked:
        raise KgeError("snapshot() inside a physics callback: take it between steps")
    if world._defer_depth:
        raise KgeError("snapshot() inside a running system: take it between steps")
    world.flush()
    entities = {e: world.components(e) for e in world.entities()}
    data = {
        "format": FORMAT,
        "name": world.name,
        "next_id": _next_id(world),
        "entities": entities,
        "resources": _state_resources(world),
    }
    try:
        return pickle.dumps(data, protocol=5)
    except (pickle.PicklingError, TypeError, AttributeError) as err:
        raise SnapshotError(
            f"cannot snapshot world {world.name!r}: {err} (components and scripts must be "
            "picklable: define their classes at module level)"
        ) from err


def _load(data: bytes) -> dict[str, Any]:
    try:
        loaded = pickle.loads(data)
    except Exception as err:  # pickle raises many types on garbage
        raise SnapshotError(f"not a kge snapshot: {err}") from err
    if not isinstance(loaded, dict) or loaded.get("format") != FORMAT:
        raise SnapshotError("not a kge snapshot (or a format this version cannot read)")
    return loaded


def restore_into(world: World, data: bytes) -> World:
    """Fill an empty ``world`` (with its systems already added) from a snapshot."""
    loaded = _load(data)
    if world.entities():
        raise SnapshotError(f"restore needs an empty world; {world.name!r} has entities")
    for resource in loaded["resources"]:
        world.insert_resource(resource)
    world._use()
    table = esper._entities
    for entity in sorted(loaded["entities"]):
        table[entity] = {}
        for component in loaded["entities"][entity]:
            world._apply_add(entity, component)
    world._use()
    esper._entity_count = itertools.count(start=loaded["next_id"])
    esper.clear_cache()
    return world


def world_name(data: bytes) -> str:
    """The name of the world a snapshot was taken from (``World.restore`` reuses it)."""
    name: str = _load(data)["name"]
    return name


def save(world: World, path: str | os.PathLike[str]) -> None:
    """Write a snapshot of ``world`` to ``path``."""
    with open(path, "wb") as f:
        f.write(snapshot(world))


def load(path: str | os.PathLike[str]) -> bytes:
    """Read snapshot bytes from ``path`` (give them to ``restore`` or ``App.restore``)."""
    with open(path, "rb") as f:
        return f.read()
