"""The process-wide registry: kge's own types (registered on first use) and the game's."""

from __future__ import annotations

from typing import Any, TypeVar

from kge.scenefile.builtin import register_builtin
from kge.scenefile.registry import TypeRegistry

T = TypeVar("T")

_default: TypeRegistry | None = None
_builtins_loaded = False


def default_registry() -> TypeRegistry:
    """The process-wide registry: kge's own types (registered on first use) and the game's."""
    global _default, _builtins_loaded
    if _default is None:
        _default = TypeRegistry()
    if not _builtins_loaded:
        _builtins_loaded = True
        register_builtin(_default)
    return _default


def register_type(cls: type[T] | None = None, **options: Any) -> Any:
    """Register a component, resource or value type in the default registry
    (see :meth:`TypeRegistry.register`); usable as a decorator."""
    return default_registry().register(cls, **options)


def register_script(cls: type[T] | None = None, *, name: str | None = None) -> Any:
    """Register a Behaviour script class in the default registry; usable as a decorator."""
    return default_registry().register_script(cls, name=name)
