"""The type registry: the only names a scene file may use.

A scene, prefab or save file names its components, resources, nested values
(shapes, filters, clips) and Behaviour scripts by *registered name*. Loading
looks each name up here and nowhere else: no import, no attribute lookup on a
module, no ``eval``. A name that is not registered is an error, so a file can
only build the types a game chose to expose, with their own constructors
checking every field.

kge registers its own types (every component, resource and value type it
ships). A game registers its own once, at import time::

    from dataclasses import dataclass
    import kge

    @kge.register_type
    @dataclass(slots=True)
    class Health:
        hp: int = 3

    @kge.register_script          # Behaviour scripts: Script subclasses
    class Patrol(kge.Script):
        speed = 2.0

Per type, fields can be marked as *entity references* (saved by the entity's
key, so they survive renumbering), *asset paths* (saved relative to the file),
*world points* and *directions* (moved and turned when a prefab is placed).
``renamed={"old": "new"}`` and ``previous_names=("Old",)`` are the migration
hooks: files written before a rename still load, and save under the new names.

>>> reg = TypeRegistry()
>>> @reg.register
... @dataclasses.dataclass
... class Score:
...     points: int = 0
>>> reg.get("Score").cls is Score
True
>>> reg.register(Score, name="Other")
Traceback (most recent call last):
...
kge.scenefile.errors.SceneFileError: Score is already registered as 'Score'
"""

from __future__ import annotations

import dataclasses
import difflib
import inspect
from collections.abc import Iterable, Mapping
from dataclasses import dataclass, field
from typing import Any, TypeVar

from kge.scenefile.errors import SceneFileError, Where

T = TypeVar("T")

#: kinds of registered types
COMPONENT = "component"
RESOURCE = "resource"
VALUE = "value"


@dataclass(slots=True)
class TypeInfo:
    """What the registry knows of one type."""

    name: str
    cls: type
    #: component, resource, value (nested in a field), or several ("component", "resource")
    kinds: frozenset[str]
    entity_fields: frozenset[str] = frozenset()
    asset_fields: frozenset[str] = frozenset()
    point_fields: frozenset[str] = frozenset()
    direction_fields: frozenset[str] = frozenset()
    #: old field name -> current name (files written before a rename still load)
    renamed: Mapping[str, str] = field(default_factory=dict)
    #: fields never written (derived state rebuilt by the type itself)
    skipped: frozenset[str] = frozenset()
    _fields: tuple[dataclasses.Field[Any], ...] | None = None
    _hints: dict[str, Any] | None = None

    @property
    def fields(self) -> tuple[dataclasses.Field[Any], ...]:
        """The dataclass fields that files hold (init fields and read-back state)."""
        if self._fields is None:
            self._fields = tuple(
                f for f in dataclasses.fields(self.cls)
                if not f.name.startswith("_") and f.name not in self.skipped
            )
        return self._fields

    def field_named(self, name: str) -> dataclasses.Field[Any] | None:
        return next((f for f in self.fields if f.name == name), None)

    def hint(self, name: str) -> Any:
        """The field's type annotation, resolved (``Any`` when it cannot be)."""
        if self._hints is None:
            self._hints = _resolve_hints(self.cls)
        return self._hints.get(name, Any)

    def default(self, f: dataclasses.Field[Any]) -> Any:
        """The field's default value (``MISSING`` when it is required)."""
        if f.default is not dataclasses.MISSING:
            return f.default
        if f.default_factory is not dataclasses.MISSING:
            return f.default_factory()
        return dataclasses.MISSING


def _resolve_hints(cls: type) -> dict[str, Any]:
    """Annotations of ``cls`` and its bases, resolved one by one (a name that only a
    ``TYPE_CHECKING`` import defines stays ``Any``)."""
    import sys

    out: dict[str, Any] = {}
    for klass in reversed(cls.__mro__):
        ann = inspect.get_annotations(klass)
        module = sys.modules.get(klass.__module__)
        ns = dict(vars(module)) if module is not None else {}
        ns.setdefault("Any", Any)
        for name, text in ann.items():
            if not isinstance(text, str):
                out[name] = text
                continue
            try:
                out[name] = eval(text, ns, dict(vars(klass)))  # annotations kge wrote, not a file's
            except Exception:
                out[name] = Any
    return out


class TypeRegistry:
    """Registered names -> types, plus Behaviour scripts. One process-wide default
    (:func:`default_registry`) holds kge's types and the game's."""

    def __init__(self) -> None:
        self._by_name: dict[str, TypeInfo] = {}
        self._by_type: dict[type, TypeInfo] = {}
        self._aliases: dict[str, str] = {}
        self._scripts: dict[str, type] = {}
        self._script_names: dict[type, str] = {}

    # -- registering -------------------------------------------------------------------
    def register(
        self,
        cls: type[T] | None = None,
        *,
        name: str | None = None,
        kinds: Iterable[str] = (COMPONENT,),
        entity_fields: Iterable[str] = (),
        asset_fields: Iterable[str] = (),
        point_fields: Iterable[str] = (),
        direction_fields: Iterable[str] = (),
        renamed: Mapping[str, str] | None = None,
        previous_names: Iterable[str] = (),
        skipped: Iterable[str] = (),
    ) -> Any:
        """Register the dataclass ``cls`` (usable bare as a decorator, or with options).

        ``kinds``: ``"component"`` (default), ``"resource"`` (a world singleton saved
        in ``[resources]``), ``"value"`` (nested in another type's field, written as an
        inline table with a ``type`` key), or several. Registering a class again under
        its own name replaces the old registration (a module reloaded while the game
        runs); another class under a taken name is refused.
        """
        if cls is None:
            return lambda c: self.register(
                c, name=name, kinds=kinds, entity_fields=entity_fields,
                asset_fields=asset_fields, point_fields=point_fields,
                direction_fields=direction_fields, renamed=renamed,
                previous_names=previous_names, skipped=skipped,
            )
        if not isinstance(cls, type) or not dataclasses.is_dataclass(cls):
            raise SceneFileError(
                Where(), f"register_type needs a dataclass, got {cls!r} (decorate it with "
                "@dataclass, or register a Behaviour script with register_script)"
            )
        key = name or cls.__name__
        _check_name(key)
        kind_set = frozenset(kinds)
        unknown = kind_set - {COMPONENT, RESOURCE, VALUE}
        if not kind_set or unknown:
            raise SceneFileError(Where(), f"register_type {key}: unknown kinds {sorted(unknown)}")
        old = self._by_type.get(cls)
        if old is not None and old.name != key:
            raise SceneFileError(Where(), f"{cls.__name__} is already registered as {old.name!r}")
        taken = self._by_name.get(key)
        if taken is not None and taken.cls is not cls and not _same_definition(taken.cls, cls):
            raise SceneFileError(
                Where(),
                f"the name {key!r} is taken by {_qualname(taken.cls)}; register "
                f"{_qualname(cls)} with name=...",
            )
        names = {f.name for f in dataclasses.fields(cls)}
        info = TypeInfo(
            key, cls, kind_set,
            entity_fields=_known(key, names, entity_fields),
            asset_fields=_known(key, names, asset_fields),
            point_fields=_known(key, names, point_fields),
            direction_fields=_known(key, names, direction_fields),
            renamed=dict(renamed or {}),
            skipped=_known(key, names, skipped),
        )
        if VALUE in kind_set and "type" in names:
            raise SceneFileError(Where(), f"value type {key} has a field named 'type' (the tag)")
        if taken is not None:
            self._by_type.pop(taken.cls, None)
        self._by_name[key] = info
        self._by_type[cls] = info
        for alias in previous_names:
            _check_name(alias)
            self._aliases[alias] = key
        return cls

    def register_script(self, cls: type[T] | None = None, *, name: str | None = None) -> Any:
        """Register a Behaviour script class: files name it, and give its data attributes."""
        if cls is None:
            return lambda c: self.register_script(c, name=name)
        if not isinstance(cls, type):
            raise SceneFileError(Where(), f"register_script needs a class, got {cls!r}")
        key = name or cls.__name__
        _check_name(key)
        taken = self._scripts.get(key)
        if taken is not None and taken is not cls and not _same_definition(taken, cls):
            raise SceneFileError(
                Where(), f"the script name {key!r} is taken by {_qualname(taken)}; register "
                f"{_qualname(cls)} with name=..."
            )
        if taken is not None:
            self._script_names.pop(taken, None)
        self._scripts[key] = cls
        self._script_names[cls] = key
        return cls

    # -- looking up ------------------------------------------------------------------------
    def get(self, name: str) -> TypeInfo | None:
        """The type registered as ``name`` (or under an old name), else None."""
        if not isinstance(name, str):
            return None
        info = self._by_name.get(name)
        if info is None and name in self._aliases:
            info = self._by_name.get(self._aliases[name])
        return info

    def info(self, cls: type) -> TypeInfo | None:
        return self._by_type.get(cls)

    def script(self, name: str) -> type | None:
        return self._scripts.get(name) if isinstance(name, str) else None

    def script_name(self, cls: type) -> str | None:
        return self._script_names.get(cls)

    def names(self, kind: str | None = None) -> list[str]:
        """Registered names (of one kind), sorted."""
        return sorted(n for n, i in self._by_name.items() if kind is None or kind in i.kinds)

    def script_names(self) -> list[str]:
        return sorted(self._scripts)

    def suggest(self, name: str, kind: str | None = None) -> str:
        """" (did you mean X?)" for a near miss, else ""."""
        pool = self.script_names() if kind == "script" else self.names(kind)
        close = difflib.get_close_matches(str(name), pool, n=1, cutoff=0.75)
        return f" (did you mean {close[0]}?)" if close else ""


def _same_definition(a: type, b: type) -> bool:
    """The same class defined again (its module reloaded): same module and qualified name."""
    return _qualname(a) == _qualname(b)


def _qualname(cls: type) -> str:
    return f"{cls.__module__}.{cls.__qualname__}"


def _check_name(name: str) -> None:
    if not isinstance(name, str) or not name or len(name) > 100 or not all(
        ch.isalnum() or ch in "._-" for ch in name
    ):
        raise SceneFileError(
            Where(), f"a registered name must be letters, digits, '.', '_' or '-', got {name!r}"
        )


def _known(owner: str, names: set[str], given: Iterable[str]) -> frozenset[str]:
    out = frozenset(given)
    missing = out - names
    if missing:
        raise SceneFileError(Where(), f"{owner} has no field(s) {sorted(missing)}")
    return out
