"""The ECS world: entities, components, resources, events and deferred commands.

kge stores entities and components in esper 3.9. esper keeps its state in module
globals, one "world" at a time, so every :class:`World` owns a uniquely named
esper world and switches to it before each operation. Several worlds can live at
once (one per scene, one per test) without seeing each other.

Structural changes (spawn, despawn, add, remove) follow one rule:

* Inside a running schedule (systems, behaviours, event delivery) they are
  *queued* and applied at the next flush point, in sorted entity order, so the
  same script always produces the same world and no iteration is invalidated.
  ``spawn`` still returns the new id at once, and ``get`` already sees the
  queued components of that entity.
* Outside a schedule (scene setup, test code between steps) spawn, add and
  remove apply immediately. ``despawn`` is always deferred to the next flush
  (``world.flush()`` or the next step) so that it never pulls an entity out
  from under a loop; ``exists`` is False at once.
* Inside a physics callback (pre-solve, contact filter) the world is *locked*
  and any structural change raises :class:`~kge.errors.WorldLockedError`,
  changing nothing, like Box2D's locked world.

>>> from kge.components import Transform
>>> w = World()
>>> e = w.spawn(Transform(1.0, 2.0))
>>> w.get(e, Transform).x
1.0
>>> w.despawn(e); w.exists(e)
False
>>> w.flush(); len(w)
0
"""

from __future__ import annotations

import itertools
import weakref
from collections import defaultdict
from collections.abc import Callable, Iterator, Sequence
from contextlib import contextmanager
from typing import TYPE_CHECKING, Any, TypeVar, overload

import esper

from kge import deprecation
from kge.errors import (
    ComponentTypeError,
    EntityNotFoundError,
    MissingComponentError,
    MissingResourceError,
    ValidationError,
    WorldLockedError,
)
from kge.esper_door import entity_table, next_entity_id, set_next_entity_id
from kge.events import EventLog
from kge.plugin import Plugin, PluginLike, resolve
from kge.schedule import Anchor, Schedule, System, SystemSet

if TYPE_CHECKING:
    from kge.snapshot import Restorable

T = TypeVar("T")
A = TypeVar("A")
B = TypeVar("B")
C = TypeVar("C")
S = TypeVar("S", bound=System)

Hook = Callable[[int, Any], None]
Validator = Callable[[int | None, Any], None]

_world_ids = itertools.count(1)

#: resource types kept for one release: reading one through ``world.resource`` warns
_DEPRECATED_RESOURCES: dict[type, str] = {}
#: ``set_handler`` names kept for one release (the physics events' esper names)
_DEPRECATED_HANDLERS: dict[str, str] = {}


def deprecate_resource(resource_type: type, instead: str) -> None:
    """Reading ``resource_type`` with ``world.resource`` warns, pointing at ``instead``."""
    _DEPRECATED_RESOURCES[resource_type] = instead


def deprecate_handler(name: str, instead: str) -> None:
    """``world.set_handler(name, ...)`` warns, pointing at ``instead``."""
    _DEPRECATED_HANDLERS[name] = instead


def stored_resource(world: World, resource_type: type[T]) -> T | None:
    """The resource stored under exactly ``resource_type``, without a deprecation warning
    (kge's own systems keep serving the deprecated resources for one release)."""
    found: T | None = world._resources.get(resource_type)
    return found


def _check_component(component: object, entity: int | None = None) -> None:
    if isinstance(component, type):
        target = "" if entity is None else f"entity {entity}: "
        raise ComponentTypeError(
            f"{target}expected a component instance, got the class {component.__name__} "
            f"(write {component.__name__}(...))"
        )
    if component is None or type(component).__module__ == "builtins":
        # numbers, strings, containers, functions, bare object()s: not component data
        target = "" if entity is None else f"entity {entity}: "
        raise ComponentTypeError(
            f"{target}expected a component instance, got {type(component).__name__} {component!r}"
        )


def _check_type(component_type: Any, op: str) -> None:
    """Refuse a lookup by something that is not a class (``world.get(e, "Transform")``)."""
    if not isinstance(component_type, type):
        raise ComponentTypeError(
            f"world.{op}(): the component type must be a class, got "
            f"{type(component_type).__name__} {component_type!r}"
        )


def _check_groups(where: str, types: list[type]) -> None:
    """Refuse two components of one exclusive group (``_one_per_entity``, e.g. joints)."""
    seen: dict[str, type] = {}
    for t in types:
        group = getattr(t, "_one_per_entity", None)
        if group is None:
            continue
        if group in seen:
            raise ComponentTypeError(
                f"{where} {seen[group].__name__} and {t.__name__} are both {group}s; an "
                f"entity holds one {group} (spawn one entity per {group})"
            )
        seen[group] = t


def _forget_esper_world(name: str) -> None:
    """Delete esper's tables of a closed or collected world (run once, by ``finalize``)."""
    if esper.current_world == name:
        esper.switch_world("default")
    if name in esper.list_worlds():
        esper.delete_world(name)


class World:
    """One isolated ECS world. See the module docstring for the change rules."""

    def __init__(self, name: str | None = None) -> None:
        serial = next(_world_ids)
        self.name = name or f"kge-world-{serial}"
        # never reused in the process (``id(self)`` is, once a world is collected, and a
        # new world would then have found the entities of an unclosed one of the same name)
        self._esper_name = f"{self.name}#{serial}"
        # an unclosed world's esper tables go with it instead of living on in esper's globals
        self._forget = weakref.finalize(self, _forget_esper_world, self._esper_name)
        self._resources: dict[type, Any] = {}
        #: every event of the world (see :mod:`kge.events`)
        self.eventlog = EventLog()
        self._handlers: dict[str, list[Callable[..., Any]]] = defaultdict(list)
        self._on_add: dict[type, list[Hook]] = defaultdict(list)
        self._on_remove: dict[type, list[Hook]] = defaultdict(list)
        self._validators: dict[type, list[Validator]] = defaultdict(list)
        self._queue: list[tuple[int, int, str, Any]] = []  # (entity, seq, op, payload)
        self._seq = itertools.count()
        self._pending: dict[int, dict[type, Any]] = {}  # queued adds, visible to get()
        self._dying: set[int] = set()  # despawned, awaiting flush
        #: id(component) -> (entity, component): one instance belongs to one entity
        self._owners: dict[int, tuple[int, Any]] = {}
        self._defer_depth = 0
        self._lock_depth = 0
        #: the components of the spawn being validated and applied (see ``spawning``)
        self._spawning: tuple[Any, ...] = ()
        self._closed = False
        self._plugins: list[Plugin] = []
        self.schedule = Schedule(self)
        self._use()

    # -- esper world switching -------------------------------------------------
    def _use(self) -> None:
        if esper.current_world != self._esper_name:
            esper.switch_world(self._esper_name)

    def _db(self) -> dict[int, dict[type, Any]]:
        """esper's entity table for this world (entity -> {type: component})."""
        self._use()
        return entity_table()

    # -- modes -------------------------------------------------------------------
    @contextmanager
    def deferred(self) -> Iterator[None]:
        """Queue structural changes until the block ends (then flush them)."""
        self._defer_depth += 1
        try:
            yield
        finally:
            self._defer_depth -= 1
        if self._defer_depth == 0:
            self.flush()

    def run_deferred(self, fn: Callable[[float], None], dt: float) -> None:
        """``fn(dt)`` inside :meth:`deferred` without a context manager (per system, per frame)."""
        self._defer_depth += 1
        try:
            fn(dt)
        finally:
            self._defer_depth -= 1
        if self._defer_depth == 0:
            self.flush()

    @contextmanager
    def locked(self) -> Iterator[None]:
        """Refuse structural changes inside the block (physics callbacks)."""
        self._lock_depth += 1
        try:
            yield
        finally:
            self._lock_depth -= 1

    @property
    def is_locked(self) -> bool:
        return self._lock_depth > 0

    def _guard(self, op: str) -> None:
        if self._lock_depth:
            raise WorldLockedError(
                f"world.{op}() inside a physics callback: the world is locked during the "
                "step (as in Box2D). Make the change from a Behaviour hook (on_contact_begin...) "
                "or a system after the step instead."
            )
        if self._closed:
            raise WorldLockedError(f"world.{op}() on a closed world ({self.name})")

    def _live(self, entity: int, op: str) -> None:
        if isinstance(entity, bool) or not isinstance(entity, int):
            raise ComponentTypeError(
                f"world.{op}(): entity must be an int id, got {type(entity).__name__} {entity!r}"
            )
        if not self.exists(entity):
            state = "was despawned" if entity in self._dying else "does not exist"
            raise EntityNotFoundError(f"world.{op}(): entity {entity} {state}")

    # -- structural changes ---------------------------------------------------------
    def spawn(self, *components: Any) -> int:
        """Create an entity with ``components`` and return its id at once."""
        self._guard("spawn")
        for c in components:
            _check_component(c)
        types = [type(c) for c in components]
        if len(set(types)) != len(types):
            dup = next(t for t in types if types.count(t) > 1)
            raise ComponentTypeError(
                f"world.spawn(): two {dup.__name__} components; an entity holds one per type"
            )
        _check_groups("world.spawn()", types)
        for c in components:
            self._check_unowned(c, None, "spawn")
        outer, self._spawning = self._spawning, components
        try:
            for c in components:
                self._validate(None, c)
            self._use()
            entity: int = esper.create_entity()
            for c in components:
                self._owners[id(c)] = (entity, c)
            if self._defer_depth:
                pend = self._pending.setdefault(entity, {})
                for c in components:
                    pend[type(c)] = c
                    self._enqueue(entity, "add", c)
            else:
                for c in components:
                    self._apply_add(entity, c)
        finally:
            self._spawning = outer
        return entity

    @property
    def spawning(self) -> tuple[Any, ...]:
        """The components of the :meth:`spawn` in progress (empty outside one).

        Validators run with ``entity=None`` inside ``spawn``, before the entity
        exists; a rule about the entity's *other* components (a character
        controller must not sit on a dynamic body) reads them here, and an
        ``on_add`` hook run by the spawn sees which components are still to come.
        """
        return self._spawning

    def spawn_linked(
        self, count: int, build: Callable[[list[int]], Sequence[Sequence[Any]]]
    ) -> list[int]:
        """Spawn ``count`` entities whose components may name each other, all or none.

        ``build(ids)`` gets the ids the entities will have and returns each one's
        components (a joint naming a body spawned later in the batch, a collider
        naming its body). Every check :meth:`spawn` runs is run first, with the whole
        batch visible to the world's validators; on any error nothing is spawned and
        the id counter is left where it was. Scene files and prefabs load through it.

        >>> from kge.components import Transform
        >>> w = World()
        >>> w.spawn_linked(2, lambda ids: [[Transform(1.0)], [Transform(float(ids[0]))]])
        [1, 2]
        """
        self._guard("spawn")
        count = int(count)
        self._use()
        start = next_entity_id()
        ids = list(range(start, start + count))
        rows = [tuple(row) for row in build(ids)]
        if len(rows) != count:
            raise ComponentTypeError(
                f"world.spawn_linked(): build() returned {len(rows)} rows for {count} entities"
            )
        seen: dict[int, int] = {}
        for entity, row in zip(ids, rows, strict=True):
            for c in row:
                _check_component(c, entity)
                self._check_unowned(c, None, "spawn_linked")
                if id(c) in seen:
                    raise ValidationError(
                        f"world.spawn_linked(): entities {seen[id(c)]} and {entity} share one "
                        f"{type(c).__name__} instance"
                    )
                seen[id(c)] = entity
            types = [type(c) for c in row]
            if len(set(types)) != len(types):
                dup = next(t for t in types if types.count(t) > 1)
                raise ComponentTypeError(
                    f"world.spawn_linked(): entity {entity}: two {dup.__name__} components"
                )
            _check_groups(f"world.spawn_linked(): entity {entity}:", types)
        db = self._db()
        for entity, row in zip(ids, rows, strict=True):
            db[entity] = {}  # visible to the validators (exists, try_get through _pending)
            self._pending[entity] = {type(c): c for c in row}
        try:
            for entity, row in zip(ids, rows, strict=True):
                for c in row:
                    self._validate(entity, c)
        finally:
            for entity in ids:
                db.pop(entity, None)
                if not self._defer_depth:
                    self._pending.pop(entity, None)
        self._use()
        set_next_entity_id(start + count)  # hooks may spawn
        if self._defer_depth:
            # queued like spawn's: get() sees them through _pending until the flush
            for entity, row in zip(ids, rows, strict=True):
                db[entity] = {}
                for c in row:
                    self._owners[id(c)] = (entity, c)
                    self._enqueue(entity, "add", c)
        else:
            for entity, row in zip(ids, rows, strict=True):
                db[entity] = {}
                for c in row:
                    self._owners[id(c)] = (entity, c)
                    self._apply_add(entity, c)
        return ids

    def add(self, entity: int, component: Any) -> None:
        """Attach ``component`` (replacing one of the same type)."""
        self._guard("add")
        self._live(entity, "add")
        _check_component(component, entity)
        self._check_unowned(component, entity, "add")
        others = [type(c) for c in self._db()[entity].values() if type(c) is not type(component)]
        others += [t for t in self._pending.get(entity, ()) if t is not type(component)]
        _check_groups(f"world.add(): entity {entity}:", [*others, type(component)])
        self._validate(entity, component)
        self._owners[id(component)] = (entity, component)
        if self._defer_depth:
            self._pending.setdefault(entity, {})[type(component)] = component
            self._enqueue(entity, "add", component)
        else:
            self._apply_add(entity, component)

    def remove(self, entity: int, component_type: type[T]) -> T:
        """Detach and return the component of ``component_type``."""
        self._guard("remove")
        self._live(entity, "remove")
        comp = self.get(entity, component_type)
        if self._defer_depth:
            pend = self._pending.get(entity)
            if pend is not None:
                pend.pop(component_type, None)
            self._enqueue(entity, "remove", component_type)
        else:
            self._apply_remove(entity, component_type)
        return comp

    def despawn(self, entity: int) -> None:
        """Mark ``entity`` for removal at the next flush. ``exists`` is False at once."""
        self._guard("despawn")
        self._live(entity, "despawn")
        self._dying.add(entity)
        self._enqueue(entity, "despawn", None)

    def _check_unowned(self, component: Any, entity: int | None, op: str) -> None:
        """Refuse an instance that already is a component of another entity."""
        owner = self._owners.get(id(component))
        if owner is not None and owner[1] is component and owner[0] != entity:
            target = "" if entity is None else f"entity {entity}: "
            raise ValidationError(
                f"world.{op}(): {target}this {type(component).__name__} instance already is "
                f"a component of entity {owner[0]}; one instance belongs to one entity "
                "(give each its own, e.g. dataclasses.replace(component))"
            )
        binding = getattr(component, "_binding", None)
        if owner is None and binding is not None:
            raise ValidationError(
                f"world.{op}(): this {type(component).__name__} instance already is a "
                f"component of entity {binding.entity} of another world"
            )

    def validate(self, entity: int | None, component: Any) -> None:
        """Run the validators of ``component``'s type (tracked writes of references use it)."""
        self._validate(entity, component)

    def _validate(self, entity: int | None, component: Any) -> None:
        for check in self._validators.get(type(component), ()):
            check(entity, component)

    def _enqueue(self, entity: int, op: str, payload: Any) -> None:
        self._queue.append((entity, next(self._seq), op, payload))

    def flush(self) -> None:
        """Apply queued changes now, in sorted entity order."""
        self._guard("flush")
        while self._queue:
            queue, self._queue = self._queue, []
            queue.sort(key=lambda item: (item[0], item[1]))
            for entity, _, op, payload in queue:
                if op == "add":
                    if self._entity_known(entity):
                        self._apply_add(entity, payload)
                    else:
                        self._disown(entity, payload)
                elif op == "remove":
                    if self._entity_known(entity) and self._has_raw(entity, payload):
                        self._apply_remove(entity, payload)
                else:
                    self._apply_despawn(entity)
            self._pending.clear()

    def _entity_known(self, entity: int) -> bool:
        return entity in self._db()

    def _has_raw(self, entity: int, component_type: type) -> bool:
        return component_type in self._db().get(entity, {})

    def _apply_add(self, entity: int, component: Any) -> None:
        ctype = type(component)
        old: Any = self._db()[entity].get(ctype)
        if old is not None and old is not component:
            for hook in self._on_remove.get(ctype, ()):
                hook(entity, old)
        if old is not None and old is not component:
            self._disown(entity, old)
        self._owners[id(component)] = (entity, component)
        self._use()
        esper.add_component(entity, component)
        if old is not component:
            for hook in self._on_add.get(ctype, ()):
                hook(entity, component)

    def _apply_remove(self, entity: int, component_type: type) -> None:
        self._use()
        comp: Any = esper.remove_component(entity, component_type)
        self._disown(entity, comp)
        for hook in self._on_remove.get(component_type, ()):
            hook(entity, comp)

    def _apply_despawn(self, entity: int) -> None:
        self._use()
        comps: dict[type, Any] | None = self._db().get(entity)
        if comps is None:
            self._dying.discard(entity)
            return
        for ctype, comp in list(comps.items()):
            for hook in self._on_remove.get(ctype, ()):
                hook(entity, comp)
        if entity in self._db():
            esper.delete_entity(entity, immediate=True)
        for comp in comps.values():
            self._disown(entity, comp)
        self._dying.discard(entity)

    def _disown(self, entity: int, component: Any) -> None:
        owner = self._owners.get(id(component))
        if owner is not None and owner[0] == entity and owner[1] is component:
            del self._owners[id(component)]

    # -- reading ---------------------------------------------------------------------
    def exists(self, entity: int) -> bool:
        """True for a spawned entity that has not been despawned."""
        try:
            if entity in self._dying:
                return False
            return entity in self._db()
        except TypeError:  # unhashable: a list, a set...
            raise ComponentTypeError(
                f"world.exists(): entity must be an int id, got {type(entity).__name__} "
                f"{entity!r}"
            ) from None

    def first_missing(self, entities: list[int]) -> int | None:
        """The first of ``entities`` (ints) that does not exist, or None when all do.

        :meth:`exists` for a batch: a controller pushing 64 bodies every step asks
        once (a set comparison with the entity table) instead of 64 times.

        >>> world = World()
        >>> a = world.spawn()
        >>> world.first_missing([a]), world.first_missing([a, 999])
        (None, 999)
        """
        db = self._db()
        dying = self._dying
        if db.keys() >= set(entities) and (not dying or dying.isdisjoint(entities)):
            return None
        return next(e for e in entities if not self.exists(e))

    def get(self, entity: int, component_type: type[T]) -> T:
        """The entity's component of ``component_type`` (queued adds included)."""
        self._live(entity, "get")
        comp: Any = self._db()[entity].get(component_type)
        if comp is None:
            pend = self._pending.get(entity)
            if pend is not None:
                comp = pend.get(component_type)
        if comp is None:
            _check_type(component_type, "get")
            raise MissingComponentError(
                f"entity {entity} has no {component_type.__name__} component"
            )
        return comp

    def try_get(self, entity: int, component_type: type[T]) -> T | None:
        """Like :meth:`get`, but None when the entity or component is missing."""
        if entity in self._dying:
            return None
        comps = self._db().get(entity)
        if comps is None:
            return None
        try:
            comp: Any = comps.get(component_type)
        except TypeError:  # unhashable: a list, a set...
            _check_type(component_type, "try_get")
            raise
        if comp is None and entity in self._pending:
            comp = self._pending[entity].get(component_type)
        if comp is None:
            _check_type(component_type, "try_get")
        return comp

    def has(self, entity: int, component_type: type) -> bool:
        return self.try_get(entity, component_type) is not None

    def components(self, entity: int) -> tuple[Any, ...]:
        """Every component of ``entity``."""
        self._live(entity, "components")
        self._use()
        return tuple(esper.components_for_entity(entity))

    @overload
    def query(self, a: type[A], /) -> list[tuple[int, tuple[A]]]: ...
    @overload
    def query(self, a: type[A], b: type[B], /) -> list[tuple[int, tuple[A, B]]]: ...
    @overload
    def query(
        self, a: type[A], b: type[B], c: type[C], /
    ) -> list[tuple[int, tuple[A, B, C]]]: ...
    @overload
    def query(self, *types: type) -> list[tuple[int, tuple[Any, ...]]]: ...
    def query(self, *types: type) -> list[tuple[int, tuple[Any, ...]]]:
        """Entities having all ``types``, as ``[(entity, (comp_a, comp_b, ...)), ...]``.

        The list is a snapshot: changing the world while iterating it is safe.
        Despawned entities awaiting the flush are left out. Order is esper's
        (deterministic for the same operations); sort by entity where it matters.
        """
        for t in types:
            if not isinstance(t, type):
                _check_type(t, "query")
        self._use()
        result: list[tuple[int, tuple[Any, ...]]] = esper.get_components(*types)
        if self._dying:
            dying = self._dying
            return [item for item in result if item[0] not in dying]
        return list(result)

    def entities(self) -> list[int]:
        """Every live entity id, sorted."""
        return sorted(e for e in self._db() if e not in self._dying)

    def __len__(self) -> int:
        return len(self.entities())

    # -- hooks -----------------------------------------------------------------------
    def on_add(self, component_type: type, hook: Hook) -> None:
        """Call ``hook(entity, component)`` whenever a ``component_type`` is attached."""
        self._on_add[component_type].append(hook)

    def on_remove(self, component_type: type, hook: Hook) -> None:
        """Call ``hook(entity, component)`` when one is detached (remove, replace, despawn)."""
        self._on_remove[component_type].append(hook)

    def validator(self, component_type: type, check: Validator) -> None:
        """Run ``check(entity, component)`` before a ``component_type`` is spawned or added.

        ``entity`` is None inside ``spawn`` (the id is not allocated yet). A check
        raises to refuse the component; nothing has been changed at that point,
        which is how "bad input leaves the world unchanged" is kept for rules
        that need the world (a joint naming a missing body, say). Validators of an
        event type run at :meth:`emit` (with ``entity`` None).
        """
        self._validators[component_type].append(check)

    # -- resources -------------------------------------------------------------------
    def insert_resource(self, resource: Any, *, as_type: type | None = None) -> Any:
        """Store a singleton, keyed by its type (or ``as_type``, a base it is an instance of)."""
        _check_component(resource)
        if as_type is not None and not isinstance(resource, as_type):
            raise ComponentTypeError(
                f"insert_resource: {type(resource).__name__} is not a {as_type.__name__}"
            )
        self._resources[as_type or type(resource)] = resource
        return resource

    def resource(self, resource_type: type[T]) -> T:
        """The singleton of ``resource_type`` (settings, physics, input...)."""
        try:
            found: T = self._resources[resource_type]
            if resource_type in _DEPRECATED_RESOURCES:
                _warn_deprecated(resource_type)
            return found
        except (KeyError, TypeError):
            _check_type(resource_type, "resource")
            for value in self._resources.values():
                if isinstance(value, resource_type):
                    return value
            raise MissingResourceError(
                f"world {self.name!r} has no {resource_type.__name__} resource "
                f"(insert one with world.insert_resource({resource_type.__name__}(...)))"
            ) from None

    def try_resource(self, resource_type: type[T]) -> T | None:
        try:
            return self.resource(resource_type)
        except MissingResourceError:
            return None

    def has_resource(self, resource_type: type) -> bool:
        return self.try_resource(resource_type) is not None

    # -- events ------------------------------------------------------------------------
    def emit(self, event: Any) -> None:
        """Send ``event`` (any object): readers of its type see it (see :mod:`kge.events`).

        Validators registered for the event's type (:meth:`validator`) run first, so
        an event naming something that does not exist is refused here, at the call.
        """
        checks = self._validators.get(type(event))
        if checks:
            for check in checks:
                check(None, event)
        self.eventlog.emit(event)

    @overload
    def events(self, event_type: type[T], /) -> list[T]: ...
    @overload
    def events(self, *event_types: type) -> list[Any]: ...
    def events(self, *event_types: type) -> list[Any]:
        """The events of ``event_type`` this code may read: those emitted since the same
        point of the previous fixed step (in fixed-step code) or frame (elsewhere).

        Reading never consumes: every reader sees every event (see :mod:`kge.events`).
        With several types, their events together, in the order they were emitted
        (``world.events(ButtonClicked, ValueChanged)``).
        """
        for t in event_types:
            if not isinstance(t, type):
                _check_type(t, "events")
        if len(event_types) == 1:
            return self.eventlog.read(event_types[0])
        if not event_types:
            raise ComponentTypeError("world.events(): name at least one event type")
        return self.eventlog.read_many(event_types)

    def clear_events(self) -> None:
        """Drop every event now (a bare World stepped by hand; an App needs no call)."""
        self.eventlog.clear()

    def set_handler(self, name: str, handler: Callable[..., Any]) -> None:
        """Call ``handler(*args)`` for every ``dispatch(name, ...)`` on this world.

        esper's immediate named events, for code written against esper; kge's own
        events are read with :meth:`events` or Behaviour hooks. The world keeps a
        strong reference (esper's own registry holds weak ones, so a lambda
        registered there vanishes at once, and its clean-up callback can fire
        against whichever esper world happens to be current).
        """
        instead = _DEPRECATED_HANDLERS.get(name)
        if instead is not None:
            deprecation.warn(f"world.set_handler({name!r}, ...): {instead}")
        self._handlers[name].append(handler)

    def remove_handler(self, name: str, handler: Callable[..., Any]) -> None:
        handlers = self._handlers.get(name, [])
        if handler in handlers:
            handlers.remove(handler)

    def dispatch(self, name: str, *args: Any) -> None:
        """Send an event to this world's handlers, then to esper's for this world."""
        for handler in list(self._handlers.get(name, ())):
            handler(*args)
        self._use()
        esper.dispatch_event(name, *args)

    # -- snapshots ---------------------------------------------------------------------
    def snapshot(self) -> bytes:
        """Every entity, component and simulation resource, as bytes (see kge.snapshot)."""
        from kge.snapshot import snapshot

        return snapshot(self)

    @classmethod
    def restore(cls, data: bytes | Restorable) -> World:
        """A new World equal to the snapshotted one (no systems; App.restore adds them).

        ``data`` is a snapshot (bytes from :meth:`snapshot`, this process only) or a
        save read from a file by ``kge.load_game``.
        """
        from kge.snapshot import restore_into, world_name

        if not isinstance(data, bytes | bytearray):
            return data.restore_into(cls(name=data.name))
        return restore_into(cls(name=world_name(data)), data)

    # -- plugins ---------------------------------------------------------------------------
    def add_plugins(self, *plugins: PluginLike) -> None:
        """Build ``plugins`` into this world (requirements first; see :mod:`kge.plugin`).

        A duplicate or a missing requirement raises :class:`~kge.plugin.PluginError`
        before any plugin is built.
        """
        for plugin in resolve(self._plugins, plugins, f"world {self.name!r}"):
            outer, self.schedule.building = self.schedule.building, plugin.name
            try:
                plugin.build(self)
            finally:
                self.schedule.building = outer
            self._plugins.append(plugin)

    @property
    def plugins(self) -> tuple[Plugin, ...]:
        """The plugins built into this world, in build order."""
        return tuple(self._plugins)

    def has_plugin(self, plugin: PluginLike) -> bool:
        """True when ``plugin`` (a Plugin class or a function plugin) is built in."""
        return any(p.key is plugin or p.key is type(plugin) for p in self._plugins)

    # -- systems -----------------------------------------------------------------------
    def add_system(
        self,
        system: S,
        *,
        in_set: SystemSet | str | None = None,
        after: tuple[Anchor, ...] | list[Anchor] | None = None,
        before: tuple[Anchor, ...] | list[Anchor] | None = None,
    ) -> S:
        """Add ``system`` to this world's schedule; returns it.

        ``in_set``, ``after`` and ``before`` override the system class's own
        placement (see :mod:`kge.schedule`; ``kge schedule`` prints the frame).
        """
        self._use()
        return self.schedule.add(system, in_set=in_set, after=after, before=before)

    def get_system(self, system_type: type[S]) -> S | None:
        return self.schedule.get(system_type)

    @property
    def closed(self) -> bool:
        return self._closed

    def close(self) -> None:
        """Despawn everything (running on_remove hooks) and delete the esper world."""
        if self._closed:
            return
        if self._lock_depth:
            raise WorldLockedError(
                "world.close() inside a physics callback: the step is still running; "
                "close the world (or change scene) from a Behaviour hook or between steps"
            )
        self.schedule.close()
        self._lock_depth = 0
        self._queue.clear()
        self._pending.clear()
        for entity in self.entities() + sorted(self._dying):
            self._apply_despawn(entity)
        self._owners.clear()
        self._closed = True
        self._forget()

    def __repr__(self) -> str:
        return f"World({self.name!r})"


def _warn_deprecated(resource_type: type) -> None:
    deprecation.warn(
        f"the {resource_type.__name__} resource: {_DEPRECATED_RESOURCES[resource_type]}"
    )
