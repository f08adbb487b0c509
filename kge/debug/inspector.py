"""The live inspector: a running game's entities and component fields, read and edited.

The model needs no window: it lists entities, shows each component's fields as
text and writes a field from text, through the same field widgets the editor's
inspector uses (:mod:`kge.editor.fields`: numbers, angles in degrees, vectors
"1.5, 2", enums by name, entity references, shapes as TOML). A write goes through
the component's own validation, so a bad value is refused at the call with the
entity, component and field named, and the world is left as it was. The overlay
(F3 in a window) and the console's ``inspect`` / ``set`` commands use it.

>>> from kge.world import World
>>> from kge.components import Name, Transform
>>> w = World(); e = w.spawn(Transform(1.0, 2.0), Name("crate"))
>>> ins = Inspector(w)
>>> ins.entities()
[(1, 'crate')]
>>> [(r.component, r.field, r.text) for r in ins.rows(e) if r.component == "Transform"]
[('Transform', 'x', '1'), ('Transform', 'y', '2'), ('Transform', 'angle', '0')]
>>> _ = ins.set(e, "Transform", "angle", "90"); round(w.get(e, Transform).angle, 4)
1.5708
>>> ins.set(e, "Transform", "x", "fast")
Traceback (most recent call last):
...
kge.errors.ValidationError: entity 1, Transform.x: 'fast' is not a number
"""

from __future__ import annotations

import dataclasses
import enum
import math
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from kge.components.name import Name
from kge.components.transform import Transform
from kge.errors import EntityNotFoundError, KgeError, ValidationError, where
from kge.world import World


@dataclass(slots=True, frozen=True)
class FieldRow:
    """One field of one component of the inspected entity."""

    component: str
    field: str
    text: str  #: the value as the inspector shows it (and parses it back)
    widget: str  #: "number", "angle", "numbers", "toggle", "choice", "text", "toml"
    choices: tuple[str, ...] = ()


def public_fields(component: Any) -> list[str]:
    """The fields an inspector shows: public dataclass fields (or public attributes)."""
    if dataclasses.is_dataclass(component):
        return [f.name for f in dataclasses.fields(component) if not f.name.startswith("_")]
    return [n for n in getattr(component, "__dict__", {}) if not n.startswith("_")]


def label(world: World, entity: int) -> str:
    """A short name for an entity: its Name, else its first component types."""
    name = world.try_get(entity, Name)
    if name is not None:
        return str(name.value)
    kinds = [type(c).__name__ for c in world.components(entity)]
    return "+".join(kinds[:2]) + ("..." if len(kinds) > 2 else "") if kinds else "(empty)"


def _registry_info(cls: type) -> Any:
    from kge.scenefile import default_registry

    return default_registry().info(cls)


def _plain_kind(name: str, value: Any) -> tuple[str, tuple[str, ...]]:
    from kge.editor.fields import is_angle

    if isinstance(value, bool):
        return "toggle", ()
    if isinstance(value, enum.Enum):
        return "choice", tuple(m.name for m in type(value))
    if isinstance(value, int | float):
        return ("angle" if is_angle(name) else "number"), ()
    if isinstance(value, tuple) and value and all(
        isinstance(v, int | float) and not isinstance(v, bool) for v in value
    ):
        return "numbers", ()
    if isinstance(value, str):
        return "text", ()
    return "toml", ()


class Inspector:
    """Reads and edits one world's entities (see the module docstring)."""

    def __init__(self, world: World) -> None:
        self.world = world
        self.selected: int | None = None
        self.folder = Path.cwd()  #: asset paths are shown relative to it

    # -- entities -------------------------------------------------------------------------
    def entities(self, search: str = "") -> list[tuple[int, str]]:
        """(entity, label) of every entity, in id order; ``search`` filters labels and
        component names (case-insensitive)."""
        needle = search.lower()
        out = []
        for e in sorted(self.world.entities()):
            text = label(self.world, e)
            if needle and needle not in text.lower() and not any(
                needle in type(c).__name__.lower() for c in self.world.components(e)
            ):
                continue
            out.append((e, text))
        return out

    def select(self, entity: int | None) -> None:
        """Inspect ``entity`` (None: nothing)."""
        if entity is not None and not self.world.exists(entity):
            raise EntityNotFoundError(f"Inspector.select: entity {entity} does not exist")
        self.selected = entity

    def step(self, delta: int) -> int | None:
        """Select the entity ``delta`` places after the selected one (wrapping)."""
        ids = [e for e, _ in self.entities()]
        if not ids:
            self.selected = None
            return None
        if self.selected not in ids:
            self.selected = ids[0] if delta >= 0 else ids[-1]
        else:
            self.selected = ids[(ids.index(self.selected) + delta) % len(ids)]
        return self.selected

    def pick(self, point: tuple[float, float], radius: float = 0.5) -> int | None:
        """The entity under ``point`` (metres): a collider containing it (physics query),
        else the nearest Transform within ``radius``; selected and returned."""
        found: int | None = None
        try:
            from kge.physics.resource import Physics

            physics = self.world.try_resource(Physics)
        except ImportError:  # pragma: no cover - physics always ships
            physics = None
        if physics is not None:
            hits = physics.query_point(point)
            if hits:
                found = min(h.collider for h in hits)
        if found is None:
            best = radius
            for e, (t,) in self.world.query(Transform):
                d = math.hypot(t.x - point[0], t.y - point[1])
                if d <= best:
                    best, found = d, e
        if found is not None:
            self.selected = found
        return found

    # -- fields ---------------------------------------------------------------------------
    def component(self, entity: int, name: str) -> Any:
        """The component of ``entity`` whose class is called ``name``."""
        if not self.world.exists(entity):
            raise EntityNotFoundError(f"entity {entity} does not exist")
        comps = self.world.components(entity)
        for c in comps:
            if type(c).__name__ == name:
                return c
        have = ", ".join(type(c).__name__ for c in comps) or "none"
        raise ValidationError(f"entity {entity} has no {name} component (it has: {have})")

    def rows(self, entity: int | None = None) -> list[FieldRow]:
        """Every shown field of ``entity`` (default: the selected one)."""
        e = self.selected if entity is None else entity
        if e is None:
            return []
        if not self.world.exists(e):
            raise EntityNotFoundError(f"entity {e} does not exist")
        out = []
        for comp in self.world.components(e):
            for f in public_fields(comp):
                out.append(self._row(comp, f))
        return out

    def _row(self, comp: Any, name: str) -> FieldRow:
        from kge.editor.fields import FieldKind, kind_of, show

        value = getattr(comp, name)
        if value is None:
            return FieldRow(type(comp).__name__, name, "none", "toml")
        info = _registry_info(type(comp))
        try:
            if info is not None and info.field_named(name) is not None:
                kind = kind_of(info, name, value, [], [])
            else:
                widget, choices = _plain_kind(name, value)
                kind = FieldKind(widget, choices)
            text = show(kind, value, self.folder, str)
        except (KgeError, ValueError, TypeError, KeyError):
            kind, text = FieldKind("text"), repr(value)
        return FieldRow(type(comp).__name__, name, text, kind.widget, kind.choices)

    def value_text(self, entity: int, component: str, field: str) -> str:
        """One field as the inspector shows it."""
        comp = self.component(entity, component)
        if field not in public_fields(comp):
            raise ValidationError(f"{where(entity, component)} has no field {field!r}")
        return self._row(comp, field).text

    def set(self, entity: int, component: str, field: str, text: str) -> Any:
        """Write ``text`` (as the inspector shows values) into the field; returns the value.

        Refused with a :class:`~kge.errors.ValidationError` naming the entity, component
        and field when the text does not parse or the component refuses the value.
        """
        from kge.editor.fields import FieldKind, kind_of, parse

        comp = self.component(entity, component)
        label_ = where(entity, component, field)
        if field not in public_fields(comp):
            raise ValidationError(f"{where(entity, component)} has no field {field!r}")
        current = getattr(comp, field)
        info = _registry_info(type(comp))
        kind: Any = None
        try:
            if text.strip().lower() in ("none", "-"):
                value = None
            elif current is None and info is not None and info.field_named(field) is not None:
                value = parse(FieldKind("toml"), text, info, field, current, self.folder, int)
            elif current is None:
                raise ValueError("this field is unset: only none can be typed in here")
            elif info is not None and info.field_named(field) is not None:
                kind = kind_of(info, field, current, [], [])
                value = parse(kind, text, info, field, current, self.folder, int)
            else:
                widget, choices = _plain_kind(field, current)
                value = _parse_plain(FieldKind(widget, choices), text, current)
        except KeyError:
            names = ", ".join(getattr(kind, "choices", ())) or "the known names"
            raise ValidationError(f"{label_}: {text.strip()!r} is not one of {names}") from None
        except (KgeError, ValueError, TypeError) as exc:
            message = str(exc).split(": ", 1)[-1] if ": " in str(exc) else str(exc)
            raise ValidationError(f"{label_}: {message}") from None
        try:
            setattr(comp, field, value)
        except (KgeError, ValueError, TypeError) as exc:
            raise ValidationError(f"{label_}: {exc}") from None
        return value


def _parse_plain(kind: Any, text: str, current: Any) -> Any:
    text = text.strip()
    if kind.widget in ("number", "angle"):
        try:
            v = float(text)
        except ValueError:
            raise ValueError(f"{text!r} is not a number") from None
        if kind.widget == "angle":
            v = math.radians(v)
        return int(v) if isinstance(current, int) and v.is_integer() else v
    if kind.widget == "numbers":
        try:
            parts = tuple(float(p) for p in text.strip("()").split(","))
        except ValueError:
            raise ValueError(f"{text!r} is not numbers separated by commas") from None
        if all(isinstance(c, int) for c in current):
            return tuple(int(p) for p in parts)
        return parts
    if kind.widget == "toggle":
        lowered = text.lower()
        if lowered not in ("true", "false", "1", "0", "on", "off", "yes", "no"):
            raise ValueError(f"{text!r} is not true or false")
        return lowered in ("true", "1", "on", "yes")
    if kind.widget == "choice":
        try:
            return type(current)[text.upper()]
        except KeyError:
            raise ValueError(f"{text!r} is not one of {', '.join(kind.choices)}") from None
    if kind.widget == "text":
        return text
    raise ValueError(f"this field ({type(current).__name__}) cannot be typed in")
