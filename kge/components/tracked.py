"""Write tracking for components that a system mirrors elsewhere (pymunk, pyglet).

Why: the physics system keeps a pymunk body for every RigidBody. Comparing every
component with its mirror each step would cost a Python loop over all bodies, and
kge must stay cheap with 5,000 sleeping bodies. Instead, a component that is
*bound* to a system records its entity in that system's dirty set whenever user
code assigns one of its fields, so syncing costs O(changes), not O(bodies).

Each assignment is also validated by the class's ``_checks`` table, so a NaN
position or a negative radius is refused at the line that wrote it, with the
entity, component and field in the message.

Systems write their own results (poses after a step) with :func:`raw_set`,
which skips both validation and dirty marking.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field, fields
from typing import Any, ClassVar

from kge.errors import where

Check = Callable[[Any, str, str], Any]


class Binding:
    """Ties a component instance to an entity and a system's dirty set."""

    __slots__ = ("dirty", "entity")

    def __init__(self, entity: int, dirty: set[int]) -> None:
        self.entity = entity
        self.dirty = dirty


@dataclass(slots=True)
class Tracked:
    """Base for components whose writes are validated and (when bound) tracked."""

    _checks: ClassVar[dict[str, Check]] = {}
    # Declared first so the generated __init__ sets it before any checked field.
    _binding: Binding | None = field(default=None, init=False, repr=False, compare=False)

    def __setattr__(self, name: str, value: Any) -> None:
        check = self._checks.get(name)
        binding: Binding | None
        try:
            binding = object.__getattribute__(self, "_binding")
        except AttributeError:  # still inside __init__, before _binding is set
            binding = None
        if check is not None:
            owner = where(None if binding is None else binding.entity, type(self).__name__)
            value = check(value, owner, name)
        object.__setattr__(self, name, value)
        if binding is not None and name != "_binding":
            binding.dirty.add(binding.entity)

    def __getstate__(self) -> dict[str, Any]:
        """Pickle the fields only: a binding belongs to one live system, not to the data."""
        return {f.name: getattr(self, f.name) for f in fields(self) if f.name != "_binding"}

    def __setstate__(self, state: dict[str, Any]) -> None:
        object.__setattr__(self, "_binding", None)
        for name, value in state.items():
            object.__setattr__(self, name, value)


raw_set: Callable[[object, str, Any], None] = object.__setattr__
"""Assign a field without validation or dirty marking (for systems writing results)."""


def bind(component: Tracked, entity: int, dirty: set[int]) -> None:
    """Start tracking writes to ``component`` as changes of ``entity``."""
    raw_set(component, "_binding", Binding(entity, dirty))


def unbind(component: Tracked) -> None:
    raw_set(component, "_binding", None)
