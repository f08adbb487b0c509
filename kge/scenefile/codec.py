"""Field values to TOML and back, guided by each registered type's fields.

Written forms (TOML has no null, no tuple and no enum):

===================  =========================================================
Python value         in the file
===================  =========================================================
bool, int, str       themselves
float                ``repr`` (reads back to the same double); NaN and inf refused
tuple, list          an array (a field annotated ``list`` reads back as a list)
Enum member          its name: ``type = "KINEMATIC"``
registered value     an inline table tagged with its name:
                     ``shape = { type = "Box", half_width = 1.0, half_height = 0.5 }``
None                 the key is left out when None is the default, else ``{}``
entity reference     the other entity's key: ``body = "chassis"``
asset                a path relative to the file: ``image = "../art/ship.png"``
Behaviour            ``script = "Player"`` and the script's data attributes
===================  =========================================================

Fields equal to their default are not written, so a file says only what differs
and a later kge's better default reaches old files.
"""

from __future__ import annotations

import collections.abc
import dataclasses
import enum
import math
import re
import types
import typing
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from kge.components.behaviour import Behaviour
from kge.scenefile.errors import SceneFileError, Where
from kge.scenefile.paths import AssetPaths
from kge.scenefile.registry import VALUE, TypeInfo, TypeRegistry
from kge.scenefile.toml import LineIndex


@dataclass(slots=True)
class Limits:
    """Sizes a file may not exceed, checked before anything is built (raise them if a
    game needs more: ``kge.scenefile.LIMITS.max_entities = 5_000_000``)."""

    max_bytes: int = 64 * 1024 * 1024  #: file size
    max_entities: int = 1_000_000  #: entities after prefabs are expanded
    max_depth: int = 24  #: arrays and tables nested inside one field
    max_items: int = 1_000_000  #: items in one array or table
    max_string: int = 1_000_000  #: characters in one string
    max_prefab_depth: int = 16  #: prefabs inside prefabs


LIMITS = Limits()

#: the largest integer a file may hold (TOML's 64-bit range)
INT_RANGE = 2**63

#: keys of a Behaviour table that are not the script's attributes
BEHAVIOUR_KEYS = ("script", "started")
#: script attributes the runner owns
_SCRIPT_RUNTIME = ("entity", "world")


@dataclass(slots=True)
class Source:
    """One file being read: where errors point, and how its asset paths resolve."""

    path: Path | None
    lines: LineIndex | None
    paths: AssetPaths

    def where(self, toml_path: tuple[Any, ...], **parts: Any) -> Where:
        line = None if self.lines is None else self.lines.line(toml_path)
        return Where(path=self.path, line=line, **parts)


# -- checks on raw parsed data --------------------------------------------------------------
def check_raw(data: Any, source: Source) -> None:
    """Refuse what no field may hold, anywhere in a parsed file: NaN and infinities,
    integers beyond 64 bits, dates, too deep nesting, too long arrays and strings."""
    _check(data, source, data, (), 0)


def _place(source: Source, root: Any, path: tuple[Any, ...]) -> Where:
    """The entity, component and field a raw path points at (for messages)."""
    parts: dict[str, Any] = {}
    if len(path) >= 2 and path[0] == "entity" and isinstance(path[1], int):
        try:
            entry = root["entity"][path[1]]
            parts["entity"] = str(entry.get("id", f"#{path[1] + 1}"))
            parts["entity_name"] = entry.get("name") if isinstance(entry.get("name"), str) else None
        except (KeyError, IndexError, TypeError, AttributeError):
            pass
        rest = path[2:]
    elif len(path) >= 2 and path[0] == "resources":
        rest = path[1:]
    else:
        rest = ()
    names = [p for p in rest if isinstance(p, str)]
    if names:
        parts["component"] = names[0]
    if len(names) > 1:
        parts["field"] = names[1]
    return source.where(path, **parts)


def _check(data: Any, source: Source, root: Any, toml_path: tuple[Any, ...], depth: int) -> None:
    if depth > LIMITS.max_depth + 6:  # the document's own tables sit a few levels down
        raise SceneFileError(
            _place(source, root, toml_path), f"nested deeper than {LIMITS.max_depth} levels"
        )
    if isinstance(data, bool):
        return
    if isinstance(data, int):
        if not -INT_RANGE <= data < INT_RANGE:
            raise SceneFileError(_place(source, root, toml_path),
                                 f"integer {data} is beyond 64 bits")
        return
    if isinstance(data, float):
        if not math.isfinite(data):
            raise SceneFileError(
                _place(source, root, toml_path), f"{data!r} is not a finite number (NaN and "
                "inf are refused everywhere)"
            )
        return
    if isinstance(data, str):
        if len(data) > LIMITS.max_string:
            raise SceneFileError(
                _place(source, root, toml_path), f"a string of {len(data)} characters (at most "
                f"{LIMITS.max_string})"
            )
        return
    if isinstance(data, dict):
        if len(data) > LIMITS.max_items:
            raise SceneFileError(_place(source, root, toml_path), f"a table of {len(data)} keys")
        for k, v in data.items():
            _check(v, source, root, (*toml_path, k), depth + 1)
        return
    if isinstance(data, list):
        if len(data) > LIMITS.max_items:
            raise SceneFileError(_place(source, root, toml_path), f"an array of {len(data)} items")
        for i, v in enumerate(data):
            _check(v, source, root, (*toml_path, i) if depth < 4 else toml_path, depth + 1)
        return
    raise SceneFileError(
        _place(source, root, toml_path), f"{type(data).__name__} values (dates, times) are not "
        "used in kge files"
    )


# -- type hints ----------------------------------------------------------------------------
def _union_args(hint: Any) -> tuple[Any, ...]:
    origin = typing.get_origin(hint)
    if origin is typing.Union or origin is types.UnionType:
        return tuple(a for a in typing.get_args(hint) if a is not type(None))
    return (hint,)


_SEQUENCES = (tuple, list, collections.abc.Sequence, typing.Sequence)


def _seq_hint(hint: Any) -> Any:
    for h in _union_args(hint):
        if h in (tuple, list) or typing.get_origin(h) in _SEQUENCES:
            return h
    return Any


def _map_hint(hint: Any) -> Any:
    for h in _union_args(hint):
        if h is dict or typing.get_origin(h) in (dict, collections.abc.Mapping):
            return h
    return Any


def _admits_none(hint: Any) -> bool:
    origin = typing.get_origin(hint)
    return (origin is typing.Union or origin is types.UnionType) and type(None) in typing.get_args(
        hint
    )


def _enum_hint(hint: Any) -> type[enum.Enum] | None:
    for h in _union_args(hint):
        if isinstance(h, type) and issubclass(h, enum.Enum):
            return h
    return None


def _element_hint(seq: Any, index: int) -> Any:
    args = typing.get_args(seq)
    if not args:
        return Any
    if len(args) == 2 and args[1] is Ellipsis:
        return args[0]
    if typing.get_origin(seq) is tuple:
        return args[index] if index < len(args) else Any
    return args[0]


# -- decoding --------------------------------------------------------------------------------
class Decoder:
    """Builds components from the tables of one file."""

    def __init__(
        self,
        registry: TypeRegistry,
        source: Source,
        resolve: Callable[[Any, Where], int],
        *,
        save: bool = False,
    ) -> None:
        self.registry = registry
        self.source = source
        self.resolve = resolve
        self.save = save

    def component(
        self,
        info: TypeInfo,
        table: Any,
        toml_path: tuple[Any, ...],
        where: Where,
        preset: dict[str, Any] | None = None,
    ) -> Any:
        """The component (or resource) ``info`` built from ``table``; ``preset`` holds field
        values decoded elsewhere (a prefab instance's overrides), which win."""
        base = dataclasses.replace(where, component=info.name)
        if not isinstance(table, dict):
            raise SceneFileError(
                self._at(base, toml_path), f"must be a table of fields, got {table!r}"
            )
        if info.cls is Behaviour:
            return self.behaviour(table, toml_path, base)
        table = _renamed(info, table, self._at(base, toml_path))
        kwargs: dict[str, Any] = {}
        state: dict[str, Any] = {}
        for name, raw in table.items():
            here = self._at(dataclasses.replace(base, field=name), (*toml_path, name))
            f = info.field_named(name)
            if f is None:
                known = [x.name for x in info.fields if x.init or self.save]
                close = _close(name, known)
                raise SceneFileError(
                    here, f"{info.name} has no field {name!r}{close}; its fields: "
                    f"{', '.join(known)}"
                )
            if not f.init and not self.save:
                raise SceneFileError(
                    here, f"{name} is state kge writes while the game runs, not a setting "
                    "(it belongs in save files only)"
                )
            value = self.field(info, name, raw, here)
            (kwargs if f.init else state)[name] = value
        kwargs.update(preset or {})
        for f in info.fields:
            if f.init and f.name not in kwargs and info.default(f) is dataclasses.MISSING:
                if _admits_none(info.hint(f.name)):
                    kwargs[f.name] = None  # a required reference left out: None (the ground)
                    continue
                raise SceneFileError(
                    self._at(dataclasses.replace(base, field=f.name), toml_path),
                    f"{info.name}.{f.name} is required",
                )
        obj = self.construct(info, kwargs, toml_path, base)
        for name, value in state.items():
            object.__setattr__(obj, name, value)  # read-back state, checked as values above
        return obj

    def construct(
        self, info: TypeInfo, kwargs: dict[str, Any], toml_path: tuple[Any, ...], where: Where
    ) -> Any:
        try:
            return info.cls(**kwargs)
        except RecursionError:
            raise SceneFileError(self._at(where, toml_path), "nested too deeply") from None
        except Exception as exc:  # the type's own checks: say which field they name
            name = _field_in_message(info, str(exc))
            here = where if name is None else dataclasses.replace(where, field=name)
            path = toml_path if name is None else (*toml_path, name)
            raise SceneFileError(self._at(here, path), _reason(exc)) from exc

    def field(self, info: TypeInfo, name: str, raw: Any, where: Where) -> Any:
        if name in info.entity_fields:
            return self.entity_ref(raw, where)
        if name in info.asset_fields:
            if raw == {}:
                return None
            return self.source.paths.load(raw, where)
        return self.value(raw, info.hint(name), where, 0)

    def entity_ref(self, raw: Any, where: Where) -> int | None:
        if raw == {}:
            return None
        if self.save and isinstance(raw, int) and not isinstance(raw, bool):
            return self.resolve(raw, where)
        if not isinstance(raw, str):
            raise SceneFileError(
                where, f"an entity reference is the other entity's id (a string), got {raw!r}"
            )
        return self.resolve(raw, where)

    def value(self, raw: Any, hint: Any, where: Where, depth: int) -> Any:
        if depth > LIMITS.max_depth:
            raise SceneFileError(where, f"nested deeper than {LIMITS.max_depth} levels")
        if isinstance(raw, str):
            kind = _enum_hint(hint)
            if kind is not None:
                try:
                    return kind[raw]
                except KeyError:
                    if issubclass(kind, str) and raw in kind._value2member_map_:
                        return kind(raw)  # a choice that was a plain string before its enum
                    names = ", ".join(m.name for m in kind)
                    raise SceneFileError(
                        where, f"{raw!r} is not a {kind.__name__} (one of {names})"
                    ) from None
            return raw
        if isinstance(raw, list):
            seq = _seq_hint(hint)
            items = [
                self.value(x, _element_hint(seq, i), where, depth + 1) for i, x in enumerate(raw)
            ]
            if seq is Any:  # plain data (a script's attribute, user_data): lists
                return items if hint is Any else tuple(items)
            return items if seq is list or typing.get_origin(seq) is list else tuple(items)
        if isinstance(raw, dict):
            if not raw:
                return None
            if "type" in raw:
                return self.tagged(raw, where, depth)
            mapping = _map_hint(hint)
            args = typing.get_args(mapping)
            vhint = args[1] if len(args) == 2 else Any
            return {str(k): self.value(v, vhint, where, depth + 1) for k, v in raw.items()}
        return raw  # bool, int, float (checked by check_raw)

    def tagged(self, raw: dict[str, Any], where: Where, depth: int) -> Any:
        name = raw["type"]
        info = self.registry.get(name)
        if info is None or VALUE not in info.kinds:
            raise SceneFileError(
                where, f"unknown value type {name!r}{self.registry.suggest(name, VALUE)} "
                "(only registered types can appear in a file)"
            )
        body = _renamed(info, {k: v for k, v in raw.items() if k != "type"}, where)
        kwargs: dict[str, Any] = {}
        for k, v in body.items():
            f = info.field_named(k)
            if f is None or not f.init:
                known = [x.name for x in info.fields if x.init]
                raise SceneFileError(
                    where, f"{name} has no field {k!r}{_close(k, known)}; its fields: "
                    f"{', '.join(known)}"
                )
            if k in info.entity_fields:
                kwargs[k] = self.entity_ref(v, where)
            elif k in info.asset_fields:
                kwargs[k] = None if v == {} else self.source.paths.load(v, where)
            else:
                kwargs[k] = self.value(v, info.hint(k), where, depth + 1)
        try:
            return info.cls(**kwargs)
        except RecursionError:
            raise SceneFileError(where, "nested too deeply") from None
        except Exception as exc:
            raise SceneFileError(where, _reason(exc)) from exc

    def behaviour(self, table: Any, toml_path: tuple[Any, ...], where: Where) -> Any:
        if not isinstance(table, dict):
            raise SceneFileError(self._at(where, toml_path), "Behaviour must be a table")
        name = table.get("script")
        here = self._at(dataclasses.replace(where, field="script"), (*toml_path, "script"))
        if not isinstance(name, str):
            raise SceneFileError(here, "a Behaviour needs script = \"RegisteredScriptName\"")
        cls = self.registry.script(name)
        if cls is None:
            raise SceneFileError(
                here, f"unknown script {name!r}{self.registry.suggest(name, 'script')} (register "
                "the class with kge.register_script; files never import code)"
            )
        try:
            script = cls()
        except Exception as exc:
            raise SceneFileError(here, f"script {name} could not be created: {_reason(exc)} "
                                 "(a registered script's __init__ must take no arguments)"
                                 ) from exc
        for key, raw in table.items():
            if key in BEHAVIOUR_KEYS:
                continue
            at = self._at(dataclasses.replace(where, field=key), (*toml_path, key))
            if key.startswith("_") or key in _SCRIPT_RUNTIME or not key.isidentifier():
                raise SceneFileError(at, f"{key!r} is not a script attribute a file may set")
            value = self.value(raw, Any, at, 0)
            try:
                setattr(script, key, value)
            except Exception as exc:
                raise SceneFileError(at, _reason(exc)) from exc
        try:
            comp = Behaviour(script)
        except Exception as exc:
            raise SceneFileError(here, _reason(exc)) from exc
        started = table.get("started", False)
        if started is not False:
            if not self.save or started is not True:
                raise SceneFileError(
                    self._at(dataclasses.replace(where, field="started"), toml_path),
                    "started = true belongs in save files only",
                )
            object.__setattr__(comp, "started", True)
        return comp

    def _at(self, where: Where, toml_path: tuple[Any, ...]) -> Where:
        line = None if self.source.lines is None else self.source.lines.line(toml_path)
        return dataclasses.replace(where, line=line if line is not None else where.line)


def _renamed(info: TypeInfo, table: dict[str, Any], where: Where) -> dict[str, Any]:
    if not info.renamed or not any(old in table for old in info.renamed):
        return table
    out = dict(table)
    for old, new in info.renamed.items():
        if old in out:
            if new in out:
                raise SceneFileError(where, f"{info.name} gives both {old!r} and its new name "
                                     f"{new!r}")
            out[new] = out.pop(old)
    return out


def _close(name: str, known: list[str]) -> str:
    import difflib

    hit = difflib.get_close_matches(name, known, n=1, cutoff=0.7)
    return f" (did you mean {hit[0]!r}?)" if hit else ""


def _field_in_message(info: TypeInfo, message: str) -> str | None:
    m = re.search(rf"\b{re.escape(info.cls.__name__)}\.(\w+)", message)
    if m and info.field_named(m.group(1)) is not None:
        return m.group(1)
    return None


def _reason(exc: BaseException) -> str:
    text = str(exc) or type(exc).__name__
    return text if isinstance(exc, ValueError | TypeError) else f"{type(exc).__name__}: {text}"


# -- encoding --------------------------------------------------------------------------------
class Encoder:
    """Turns components into plain TOML values for one file."""

    def __init__(
        self,
        registry: TypeRegistry,
        paths: AssetPaths,
        key_of: Callable[[int, Where], str | int],
        *,
        save: bool = False,
    ) -> None:
        self.registry = registry
        self.paths = paths
        self.key_of = key_of
        self.save = save

    def component(self, comp: Any, where: Where) -> tuple[str, dict[str, Any]]:
        """(registered name, table) of a component or resource."""
        if isinstance(comp, Behaviour):
            return "Behaviour", self.behaviour(comp, dataclasses.replace(where,
                                                                       component="Behaviour"))
        info = self.registry.info(type(comp))
        if info is None:
            raise SceneFileError(
                where, f"{type(comp).__name__} is not a registered type (register it with "
                "kge.register_type to save it)"
            )
        return info.name, self.fields(info, comp, dataclasses.replace(where, component=info.name))

    def fields(self, info: TypeInfo, obj: Any, where: Where) -> dict[str, Any]:
        table: dict[str, Any] = {}
        for f in info.fields:
            if not f.init and not self.save:
                continue
            value = getattr(obj, f.name)
            default = info.default(f)
            if default is not dataclasses.MISSING and same(value, default):
                continue
            if default is dataclasses.MISSING and value is None and _admits_none(
                info.hint(f.name)
            ):
                continue  # a required field that may be None reads back as None when absent
            here = dataclasses.replace(where, field=f.name)
            if value is None:
                table[f.name] = {}
            elif f.name in info.entity_fields:
                table[f.name] = self.key_of(value, here)
            elif f.name in info.asset_fields:
                table[f.name] = self.paths.save(value, here)
            else:
                table[f.name] = self.value(value, here, 0)
        return table

    def value(self, v: Any, where: Where, depth: int) -> Any:
        if depth > LIMITS.max_depth:
            raise SceneFileError(where, f"nested deeper than {LIMITS.max_depth} levels")
        if v is None:
            return {}
        if isinstance(v, enum.Enum):  # first: a StrEnum member is a str too
            return v.name
        if isinstance(v, bool | str):
            return v
        if isinstance(v, int):
            if not -INT_RANGE <= v < INT_RANGE:
                raise SceneFileError(where, f"integer {v} is beyond 64 bits")
            return int(v)
        if isinstance(v, float):
            if not math.isfinite(v):
                raise SceneFileError(where, f"{v!r} cannot be saved (not finite)")
            return float(v)
        if isinstance(v, tuple | list):
            return [self.value(x, where, depth + 1) for x in v]
        if isinstance(v, dict):
            out: dict[str, Any] = {}
            for k, x in v.items():
                if not isinstance(k, str):
                    raise SceneFileError(where, f"a table key must be a string, got {k!r}")
                out[k] = self.value(x, where, depth + 1)
            return out
        info = self.registry.info(type(v))
        if info is not None and VALUE in info.kinds:
            body: dict[str, Any] = {"type": info.name}
            for f in info.fields:
                if not f.init:
                    continue
                x = getattr(v, f.name)
                default = info.default(f)
                if default is not dataclasses.MISSING and same(x, default):
                    continue
                if x is None:
                    body[f.name] = {}
                elif f.name in info.asset_fields:
                    body[f.name] = self.paths.save(x, where)
                elif f.name in info.entity_fields:
                    body[f.name] = self.key_of(x, where)
                else:
                    body[f.name] = self.value(x, where, depth + 1)
            return body
        if hasattr(v, "dtype") and hasattr(v, "item") and getattr(v, "shape", None) == ():
            return self.value(v.item(), where, depth)  # a numpy scalar
        raise SceneFileError(
            where, f"a {type(v).__name__} cannot be written to a file (register its type with "
            "kge.register_type(..., kinds=('value',)) or keep plain data)"
        )

    def behaviour(self, comp: Behaviour, where: Where) -> dict[str, Any]:
        script = comp.script
        name = self.registry.script_name(type(script))
        if name is None:
            raise SceneFileError(
                dataclasses.replace(where, field="script"),
                f"script class {type(script).__qualname__} is not registered (decorate it with "
                "@kge.register_script so files can name it)",
            )
        table: dict[str, Any] = {"script": name}
        for key, value in sorted(getattr(script, "__dict__", {}).items()):
            if key.startswith("_") or key in _SCRIPT_RUNTIME or key in BEHAVIOUR_KEYS:
                continue
            if callable(value) and not isinstance(value, type):
                continue
            table[key] = self.value(value, dataclasses.replace(where, field=key), 0)
        if self.save and comp.started:
            table["started"] = True
        return table


def same(a: Any, b: Any) -> bool:
    """Equal and written the same (``-0.0`` is not ``0.0``, ``1`` is not ``1.0``)."""
    if type(a) is not type(b):
        return False
    if isinstance(a, float):
        return repr(a) == repr(b)
    if isinstance(a, tuple | list):
        return len(a) == len(b) and all(same(x, y) for x, y in zip(a, b, strict=True))
    try:
        return bool(a == b) and repr(a) == repr(b)
    except Exception:
        return False
