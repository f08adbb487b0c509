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
import dataclasses
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


def _recheck(value: Any, where: str) -> None:
    """Run the checks ``value``'s constructor runs (unpickling bypasses them).

    A dataclass is rebuilt from its init fields with :func:`dataclasses.replace`
    (the rebuilt copy is discarded: the restored object keeps its read-back
    fields), after its nested dataclasses (a collider's shape, filter).
    """
    if not dataclasses.is_dataclass(value) or isinstance(value, type):
        return
    for f in dataclasses.fields(value):
        if f.init:
            _recheck(getattr(value, f.name, None), where)
    try:
        dataclasses.replace(value)
    except KgeError as err:
        raise SnapshotError(f"{where}: {err}") from err
    except (TypeError, ValueError) as err:
        raise SnapshotError(f"{where}: {type(value).__name__} is not valid: {err}") from err


def _validate(world: World, entities: Any, next_id: Any) -> None:
    """Every check ``spawn`` would run, before anything is added (then nothing is).

    Field checks run per component; the world's validators (a collider's body, a
    joint's bodies...) run with every restored entity visible through the queued
    table, so references between restored entities resolve whatever their order.
    """
    if not isinstance(entities, dict) or not isinstance(next_id, int):
        raise SnapshotError("not a kge snapshot: bad entity table")
    for entity in entities:
        if isinstance(entity, bool) or not isinstance(entity, int) or entity < 1:
            raise SnapshotError(f"not a kge snapshot: entity id {entity!r}")
    seen: dict[int, int] = {}
    for entity in sorted(entities):
        comps = entities[entity]
        if entity >= next_id:
            raise SnapshotError(f"snapshot entity {entity} is not below its id counter {next_id}")
        if not isinstance(comps, tuple | list):
            raise SnapshotError(f"snapshot entity {entity}: bad component list")
        types = [type(c) for c in comps]
        if len(set(types)) != len(types):
            raise SnapshotError(f"snapshot entity {entity}: two components of one type")
        for comp in comps:
            if id(comp) in seen:
                raise SnapshotError(
                    f"snapshot entities {seen[id(comp)]} and {entity} share one "
                    f"{type(comp).__name__} instance"
                )
            seen[id(comp)] = entity
            _recheck(comp, f"snapshot entity {entity}, {type(comp).__name__}")
    world._use()
    table = esper._entities
    for entity in entities:
        table[entity] = {}
        world._pending[entity] = {type(c): c for c in entities[entity]}
    try:
        for entity in sorted(entities):
            for comp in entities[entity]:
                try:
                    world.validate(entity, comp)
                except KgeError as err:
                    raise SnapshotError(f"snapshot entity {entity}: {err}") from err
    finally:
        world._pending.clear()
        for entity in entities:
            table.pop(entity, None)


def restore_into(world: World, data: bytes) -> World:
    """Fill an empty ``world`` (with its systems already added) from a snapshot.

    Everything is validated first, as ``spawn`` validates (NaN fields, bad shapes,
    references to missing bodies, shared instances); on any error a
    :class:`SnapshotError` is raised and ``world`` is left empty and unchanged.
    """
    loaded = _load(data)
    if world.entities():
        raise SnapshotError(f"restore needs an empty world; {world.name!r} has entities")
    resources = loaded.get("resources", [])
    for resource in resources:
        _recheck(resource, f"snapshot resource {type(resource).__name__}")
    _validate(world, loaded.get("entities"), loaded.get("next_id"))
    for resource in resources:
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
