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

What systems are running goes along: each system-owned resource registered with
:func:`carry_running` exports its running state, keyed by entity ids, and the
restored world's resource continues from it. So running tweens go on from where
they were, live particles keep flying (and one-shot bursts do not fire again),
animators keep their clip time, and characters go on mid-jump, in the sensors they
were in. Handles game code kept (a ``TweenHandle``) belong
to the old world: ask the restored world's resources for new ones.

Behaviour scripts are saved when their classes are importable (module level),
as with any pickle.

Snapshots are for memory only. Unpickling runs whatever code the bytes name, so
the bytes are signed with a key made when the process starts, and :func:`restore`
refuses bytes it did not sign: a snapshot written to disk and read back (or sent
from another process) is refused before pickle sees it. Files go through the
safe text format instead: ``kge.save_game(world, path)`` and
``kge.load_game(path)`` (:mod:`kge.scenefile`), which never run code.

>>> from kge.components import Transform
>>> from kge.world import World
>>> w = World()
>>> e = w.spawn(Transform(1.0, 2.0))
>>> copy = World.restore(snapshot(w))
>>> copy.get(e, Transform)
Transform(x=1.0, y=2.0, angle=0.0)
"""

from __future__ import annotations

import dataclasses
import hashlib
import hmac
import os
import pickle
from collections.abc import Sequence
from typing import TYPE_CHECKING, Any, Protocol

import esper

from kge.errors import KgeError
from kge.esper_door import entity_table, next_entity_id, set_next_entity_id

if TYPE_CHECKING:
    from kge.world import World

FORMAT = 1


class SnapshotError(KgeError, ValueError):
    """The data is not a kge snapshot, or one of an unsupported format."""


class Restorable(Protocol):
    """A saved world read by a safe loader (``kge.load_game``): ``App.restore`` takes it."""

    name: str

    def restore_into(self, world: World) -> World: ...


#: the key snapshots are signed with: made per process, never written anywhere
_KEY = os.urandom(32)
_TAG = b"kge-snapshot-hmac"


def _sign(payload: bytes) -> bytes:
    return hmac.new(_KEY, payload, hashlib.sha256).digest()


def seal(data: dict[str, Any]) -> bytes:
    """Pickle and sign ``data`` (a snapshot's dictionary) for :func:`restore_into`.

    What :func:`snapshot` does after collecting the world; tests that craft a
    snapshot by hand (a NaN pose, a dangling reference) seal it the same way.
    """
    try:
        payload = pickle.dumps(data, protocol=5)
    except (pickle.PicklingError, TypeError, AttributeError) as err:
        raise SnapshotError(
            f"cannot snapshot world {data.get('name')!r}: {err} (components and scripts must "
            "be picklable: define their classes at module level)"
        ) from err
    return payload + _TAG + _sign(payload)


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


class RunningState(Protocol):
    """A system-owned resource whose running state (tween rows, live particles, clip
    times) a snapshot carries: what :func:`carry_running` registers."""

    def export_running(self) -> Any:
        """Picklable data of what is running, keyed by entity ids (never by objects)."""

    def import_running(self, data: Any) -> None:
        """Continue from ``data`` in a restored world (its entities are already there)."""


#: resource types whose running state snapshots carry (registered by their modules)
_RUNNING: list[type] = []


def carry_running(resource_type: type) -> type:
    """Carry what ``resource_type`` is running through snapshots (a class decorator:
    the class implements :class:`RunningState`)."""
    if resource_type not in _RUNNING:
        _RUNNING.append(resource_type)
    return resource_type


def _running(world: World) -> list[tuple[type, Any]]:
    found: list[tuple[type, RunningState | None]] = [(t, world.try_resource(t)) for t in _RUNNING]
    return [(t, r.export_running()) for t, r in found if r is not None]


def _next_id(world: World) -> int:
    world._use()
    return next_entity_id()


def snapshot(world: World) -> bytes:
    """Bytes that :func:`restore` turns back into an equal world."""
    if world.is_locked:
        raise KgeError("snapshot() inside a physics callback: take it between steps")
    if world._defer_depth:
        raise KgeError("snapshot() inside a running system: take it between steps")
    world.flush()
    entities = {e: world.components(e) for e in world.entities()}
    return seal(
        {
            "format": FORMAT,
            "name": world.name,
            "next_id": _next_id(world),
            "entities": entities,
            "resources": _state_resources(world),
            "running": _running(world),
        }
    )


def _load(data: bytes) -> dict[str, Any]:
    if not isinstance(data, bytes | bytearray):
        raise SnapshotError(f"not a kge snapshot: {type(data).__name__} (snapshots are bytes)")
    cut = len(data) - len(_TAG) - 32
    payload, tag, mac = bytes(data[:cut]), bytes(data[cut:-32]), bytes(data[-32:])
    if cut < 0 or tag != _TAG or not hmac.compare_digest(mac, _sign(payload)):
        raise SnapshotError(
            "not a kge snapshot taken in this process: snapshots live in memory only "
            "(unpickling could run code a file names); save files with kge.save_game(world, "
            "path) and read them with kge.load_game(path)"
        )
    try:
        loaded = pickle.loads(payload)
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
    table = entity_table()
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
    restore_state(
        world, loaded.get("entities"), loaded.get("next_id"), loaded.get("resources", [])
    )
    for resource_type, running in loaded.get("running", []):
        resource = world.try_resource(resource_type)
        if resource is not None:  # a world without that system has nothing to continue
            resource.import_running(running)
    return world


def restore_state(
    world: World, entities: Any, next_id: Any, resources: Sequence[Any] = ()
) -> World:
    """Fill an empty ``world`` from an entity table ``{id: [components]}`` keeping the ids.

    The safe save loader (``kge.load_game``) builds the table from a text file and
    restores it through here, with the checks :func:`restore_into` runs.
    """
    if world.entities():
        raise SnapshotError(f"restore needs an empty world; {world.name!r} has entities")
    for resource in resources:
        _recheck(resource, f"snapshot resource {type(resource).__name__}")
    _validate(world, entities, next_id)
    for resource in resources:
        world.insert_resource(resource)
    world._use()
    table = entity_table()
    for entity in sorted(entities):
        table[entity] = {}
        for component in entities[entity]:
            world._apply_add(entity, component)
    world._use()
    set_next_entity_id(next_id)
    esper.clear_cache()
    return world


def world_name(data: bytes) -> str:
    """The name of the world a snapshot was taken from (``World.restore`` reuses it)."""
    name: str = _load(data)["name"]
    return name


def __getattr__(name: str) -> Any:
    if name in ("save", "load"):
        raise AttributeError(
            f"kge.snapshot.{name} is gone: it wrote pickle to disk, and reading such a file "
            "back could run any code it names. Use kge.save_game(world, path) and "
            "kge.load_game(path) (a text format that never runs code); snapshots stay in memory"
        )
    raise AttributeError(f"module 'kge.snapshot' has no attribute {name!r}")
