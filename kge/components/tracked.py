"""Write tracking for components that a system mirrors elsewhere (pymunk, pyglet).

Why: the physics system keeps a pymunk body for every RigidBody. Comparing every
component with its mirror each step would cost a Python loop over all bodies, and
kge must stay cheap with 5,000 sleeping bodies. Instead, a component that is
*bound* to a system records its entity in that system's dirty set whenever user
code assigns one of its fields, so syncing costs O(changes), not O(bodies).

Each assignment is also validated by the class's ``_checks`` table, so a NaN
position or a negative radius is refused at the line that wrote it, with the
entity, component and field in the message. Values a check would return
unchanged (a finite float for ``finite``) pass through its fast predicate in
:data:`kge.validate.FAST` without calling it or formatting the message prefix:
components are built field by field through here, thousands per frame when a
game spawns a wave.

Fields that name other entities (``Collider.body``, a joint's ``body_a``) need
the world to be checked: the entity must exist and hold a body. Such fields are
listed in the class's ``_world_fields``; a write to one of them on a bound
component runs the world's validators (the same ones ``spawn`` and ``add`` run)
on a copy holding the new value, before the write, so a bad reference is
refused at the line that wrote it and the component keeps its old value.

Systems write their own results (poses after a step) with :func:`raw_set`,
which skips both validation and dirty marking.
"""

from __future__ import annotations

import copy
import inspect
from collections.abc import Callable
from dataclasses import MISSING, dataclass, field, fields
from typing import Any, ClassVar, TypeVar

from kge.errors import where
from kge.validate import FAST as _FAST
from kge.validate import FAST_EXPR as _FAST_EXPR

Check = Callable[[Any, str, str], Any]
Validate = Callable[[int | None, Any], None]
T = TypeVar("T")

_SET = object.__setattr__


class Binding:
    """Ties a component instance to an entity and the dirty sets of the systems mirroring it.

    :meth:`Tracked.__setattr__` marks a write with ``dirty.add(entity)``. With one
    system watching (the usual case) ``dirty`` is that system's set, so a write
    costs one C-level ``set.add``. When several systems mirror the same component
    (physics and the renderer both follow Transform), ``dirty`` is the binding
    itself and :meth:`add` marks each of their sets.
    """

    __slots__ = ("dirty", "entity", "sets", "validate")

    def __init__(self, entity: int, dirty: set[int], *more: set[int]) -> None:
        self.entity = entity
        self.sets: tuple[set[int], ...] = (dirty, *more)
        self.dirty: set[int] | Binding = self if more else dirty
        #: the world's validators, for writes of ``_world_fields`` (set by :func:`bind`)
        self.validate: Validate | None = None

    def add(self, entity: int) -> None:
        """Mark ``entity`` in every bound set (the fan-out behind ``dirty.add``)."""
        for dirty in self.sets:
            dirty.add(entity)

    def joined(self, entity: int, dirty: set[int]) -> Binding:
        """This binding plus ``dirty``; a binding to another entity is replaced, not joined."""
        if entity != self.entity:
            return Binding(entity, dirty)
        if any(s is dirty for s in self.sets):  # identity: two empty sets are equal
            return self
        joined = Binding(entity, *self.sets, dirty)
        joined.validate = self.validate
        return joined

    def without(self, dirty: set[int]) -> Binding | None:
        """This binding minus ``dirty`` (None when nothing is left to mark)."""
        rest = [s for s in self.sets if s is not dirty]
        if len(rest) == len(self.sets):
            return self
        if not rest:
            return None
        left = Binding(self.entity, *rest)
        left.validate = self.validate
        return left


@dataclass(slots=True)
class Tracked:
    """Base for components whose writes are validated and (when bound) tracked."""

    _checks: ClassVar[dict[str, Check]] = {}
    #: fields naming other entities: writes are also checked by the world's validators
    _world_fields: ClassVar[frozenset[str]] = frozenset()
    # Declared first so the generated __init__ sets it before any checked field.
    _binding: Binding | None = field(default=None, init=False, repr=False, compare=False)

    def __setattr__(self, name: str, value: Any) -> None:
        check = self._checks.get(name)
        if check is not None:
            fast = _FAST.get(check)
            if fast is None or not fast(value):  # the owner's name is only formatted here
                value = check(value, self._owner(), name)
            if name in self._world_fields:
                self._check_in_world(name, value)
        _SET(self, name, value)
        try:
            binding = self._binding
        except AttributeError:  # still inside __init__, before _binding is set
            return
        if binding is not None and name != "_binding":
            binding.dirty.add(binding.entity)

    def _check_in_world(self, name: str, value: Any) -> None:
        """Run the world's validators on a copy holding ``value`` (bound components only)."""
        try:
            binding = self._binding
        except AttributeError:  # inside __init__: spawn/add validate the whole component
            return
        if binding is None or binding.validate is None:
            return
        candidate = copy.copy(self)
        _SET(candidate, name, value)
        binding.validate(binding.entity, candidate)

    def _owner(self) -> str:
        """"entity 7, Collider" (or "Collider" while unbound), for validation messages."""
        try:
            binding = self._binding
        except AttributeError:
            binding = None
        return where(None if binding is None else binding.entity, type(self).__name__)

    def __getstate__(self) -> dict[str, Any]:
        """Pickle the fields only: a binding belongs to one live system, not to the data."""
        return {f.name: getattr(self, f.name) for f in fields(self) if f.name != "_binding"}

    def __setstate__(self, state: dict[str, Any]) -> None:
        object.__setattr__(self, "_binding", None)
        for name, value in state.items():
            object.__setattr__(self, name, value)


class _Factory:
    """Default of a field with a default factory in a generated ``__init__``."""

    def __repr__(self) -> str:
        return "<factory>"


_FACTORY = _Factory()


def fast_init(cls: type[T]) -> type[T]:
    """Give a Tracked dataclass an ``__init__`` that validates without ``__setattr__``.

    Apply it above ``@dataclass(slots=True)`` on hot components (games build
    thousands per frame). The generated ``__init__`` does what the dataclass one
    does through :meth:`Tracked.__setattr__` (same defaults, same field order,
    same checks and messages, no dirty marks since nothing is bound yet), but
    each check's fast predicate runs inline and the owner's name is formatted
    only for a value that needs the check itself. Classes that override
    ``__setattr__`` keep their own ``__init__``.
    """
    all_fields = fields(cls)  # type: ignore[arg-type]
    params_now = list(inspect.signature(cls.__init__).parameters.values())[1:]
    if cls.__setattr__ is not Tracked.__setattr__ or [
        (p.name, p.kind) for p in params_now
    ] != [(f.name, inspect.Parameter.POSITIONAL_OR_KEYWORD) for f in all_fields if f.init]:
        return cls  # custom writes, InitVars or keyword-only fields: keep the dataclass one
    checks: dict[str, Check] = cls._checks  # type: ignore[attr-defined]
    ns: dict[str, Any] = {
        "_SET": _SET, "_where": where, "_tp": type, "_MISSING": _FACTORY,
        "_fl": float, "_bl": bool, "_in": int,
    }
    params: list[str] = []
    body: list[str] = []
    for f in all_fields:
        name = f.name
        has_factory = f.default_factory is not MISSING
        if has_factory:
            ns[f"_df_{name}"] = f.default_factory
        if not f.init:
            if f.default is not MISSING:
                ns[f"_d_{name}"] = f.default
                body.append(f"_SET(self, {name!r}, _d_{name})")
            elif has_factory:
                body.append(f"_SET(self, {name!r}, _df_{name}())")
            continue
        if f.default is not MISSING:
            ns[f"_d_{name}"] = f.default
            params.append(f"{name}=_d_{name}")
        elif has_factory:
            params.append(f"{name}=_MISSING")
            body.append(f"if {name} is _MISSING: {name} = _df_{name}()")
        else:
            params.append(name)
        check = checks.get(name)
        if check is not None:
            ns[f"_c_{name}"] = check
            slow = f"{name} = _c_{name}({name}, _where(None, _tp(self).__name__), {name!r})"
            fast = _FAST.get(check)
            expr = _FAST_EXPR.get(check)
            if expr is not None:  # inline: no call at all for the usual value
                test = expr.format(v=name, type="_tp", float="_fl", bool="_bl", int="_in")
                body.append(f"if not ({test}): {slow}")
            elif fast is None:
                body.append(slow)
            else:
                ns[f"_f_{name}"] = fast
                body.append(f"if not _f_{name}({name}): {slow}")
        body.append(f"_SET(self, {name!r}, {name})")
    if hasattr(cls, "__post_init__"):
        body.append("self.__post_init__()")
    src = f"def __init__(self, {', '.join(params)}) -> None:\n    " + "\n    ".join(body)
    exec(src, ns)  # generated from the dataclass's own field list
    init = ns["__init__"]
    init.__qualname__ = f"{cls.__qualname__}.__init__"
    init.__module__ = cls.__module__
    init.__doc__ = cls.__init__.__doc__
    cls.__init__ = init  # type: ignore[method-assign]
    return cls


raw_set: Callable[[object, str, Any], None] = object.__setattr__
"""Assign a field without validation or dirty marking (for systems writing results)."""


def bind(
    component: Tracked, entity: int, dirty: set[int], validate: Validate | None = None
) -> None:
    """Start tracking writes to ``component`` as changes of ``entity`` in ``dirty``.

    Sets other systems bound for the same entity keep being marked too.
    ``validate(entity, candidate)`` (the world's validators) checks writes of the
    class's ``_world_fields``.
    """
    old = component._binding
    new = Binding(entity, dirty) if old is None else old.joined(entity, dirty)
    if validate is not None:
        new.validate = validate
    raw_set(component, "_binding", new)


def unbind(component: Tracked, dirty: set[int] | None = None) -> None:
    """Stop tracking writes to ``component`` into ``dirty``, or into every set (None)."""
    old = component._binding
    raw_set(component, "_binding", None if old is None or dirty is None else old.without(dirty))


class NoMarks(set[int]):
    """A dirty set that keeps nothing: for bindings that only validate writes."""

    def add(self, entity: int) -> None:
        pass


def validate_writes(world: Any, component_type: type[Tracked]) -> None:
    """Check later writes of ``component_type``'s ``_world_fields`` with ``world``'s
    validators, as ``spawn`` does, for components no system binds otherwise (a sprite
    image renamed to a missing file is refused at the write, not at the next frame)."""
    marks = NoMarks()
    world.on_add(component_type, lambda e, c: bind(c, e, marks, world.validate))
    world.on_remove(component_type, lambda e, c: unbind(c, marks))
