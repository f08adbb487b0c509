"""Reading a file into entries, and expanding prefab instances into rows.

A :class:`Document` is a parsed file whose shape has been checked (header,
entity entries, resources, maps) but whose components are not built yet.
:func:`expand` turns its entries into :class:`Row` s, one per entity to spawn,
opening prefab files (and the prefabs inside them) on the way, with cycle and
depth checks, the instance's placement and its overrides attached.
"""

from __future__ import annotations

import os
import tomllib
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from kge.scenefile.codec import LIMITS, Source, check_raw
from kge.scenefile.errors import SceneFileError, Where
from kge.scenefile.migrate import migrate
from kge.scenefile.paths import AssetPaths
from kge.scenefile.state import IDENTITY, Pose, compose, inverse
from kge.scenefile.toml import LineIndex

KINDS = ("scene", "prefab", "save")
#: keys of an entity entry that are not component names
ENTRY_KEYS = ("id", "name", "prefab", "at", "overrides")
#: longest entity id
MAX_KEY = 200


@dataclass(slots=True)
class Entry:
    """One ``[[entity]]`` of a file."""

    index: int
    key: str
    name: str | None
    prefab: str | None
    at: Pose | None
    overrides: dict[str, Any]
    components: dict[str, Any]

    @property
    def toml_path(self) -> tuple[Any, ...]:
        return ("entity", self.index)


@dataclass(slots=True)
class Document:
    source: Source
    kind: str
    entries: list[Entry]
    resources: dict[str, Any]
    maps: list[dict[str, Any]]
    root: str | None = None
    next_id: int | None = None
    name: str | None = None
    text: str = ""  #: the file's text as read (hot reload compares a prefab's old and new)


def read_text(path: Path) -> str:
    """The file's text, refusing what is too big or not UTF-8 before parsing it."""
    where = Where(path=path)
    try:
        size = path.stat().st_size
        if not path.is_file():
            raise SceneFileError(where, "not a regular file")
        if size > LIMITS.max_bytes:
            raise SceneFileError(where, f"{size} bytes: larger than {LIMITS.max_bytes}")
        with open(path, "rb") as f:
            raw = f.read(LIMITS.max_bytes + 1)
    except OSError as exc:
        raise SceneFileError(where, f"cannot read: {exc.strerror or exc}") from None
    if len(raw) > LIMITS.max_bytes:
        raise SceneFileError(where, f"larger than {LIMITS.max_bytes} bytes")
    try:
        return raw.decode("utf-8")
    except UnicodeDecodeError as exc:
        raise SceneFileError(where, f"not UTF-8 text (byte {exc.start})") from None


def parse(text: str, path: Path | None, paths: AssetPaths) -> Document:
    """Parse and check the shape of a file's text."""
    where = Where(path=path)
    if len(text) > LIMITS.max_bytes:
        raise SceneFileError(where, f"larger than {LIMITS.max_bytes} bytes")
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise SceneFileError(_line_of(exc, where), f"not valid TOML: {exc}") from None
    except RecursionError:
        raise SceneFileError(where, f"nested deeper than {LIMITS.max_depth} levels") from None
    except ValueError as exc:  # e.g. an integer of 5,000 digits
        raise SceneFileError(where, f"not valid TOML: {exc}") from None
    source = Source(path, LineIndex(text), paths)
    check_raw(data, source)
    data = migrate(data, source)
    kind = data.get("kind", "scene")
    if kind not in KINDS:
        raise SceneFileError(source.where(("kind",)), f"kind must be one of {KINDS}, got {kind!r}")
    unknown = set(data) - {"format", "kind", "entity", "resources", "tilemap", "root", "next_id",
                           "name"}
    if unknown:
        first = sorted(unknown)[0]
        raise SceneFileError(
            source.where((first,)), f"unknown top-level key {first!r} (a kge file holds format, "
            "kind, entity, resources, tilemap; prefabs root; saves next_id and name)"
        )
    raw_entities = data.get("entity", [])
    if not isinstance(raw_entities, list):
        raise SceneFileError(source.where(("entity",)), "entity must be an array of tables "
                             "([[entity]])")
    if len(raw_entities) > LIMITS.max_entities:
        raise SceneFileError(where, f"{len(raw_entities)} entities (at most "
                             f"{LIMITS.max_entities})")
    entries = [_entry(i, e, source, kind) for i, e in enumerate(raw_entities)]
    seen: dict[str, int] = {}
    for e in entries:
        if e.key in seen:
            raise SceneFileError(
                source.where((*e.toml_path, "id"), entity=e.key),
                f"two entities have the id {e.key!r} (ids are unique in a file)",
            )
        seen[e.key] = e.index
    resources = data.get("resources", {})
    if not isinstance(resources, dict):
        raise SceneFileError(source.where(("resources",)), "resources must be a table")
    maps = data.get("tilemap", [])
    if not isinstance(maps, list) or not all(isinstance(m, dict) for m in maps):
        raise SceneFileError(source.where(("tilemap",)), "tilemap must be an array of tables "
                             "([[tilemap]])")
    doc = Document(source, kind, entries, resources, maps, text=text)
    if kind == "prefab":
        root = data.get("root")
        if root is not None and (not isinstance(root, str) or root not in seen):
            raise SceneFileError(source.where(("root",)), f"root {root!r} names no entity of "
                                 "this prefab")
        doc.root = root
    if kind == "save":
        nid = data.get("next_id")
        if isinstance(nid, bool) or not isinstance(nid, int) or nid < 1:
            raise SceneFileError(source.where(("next_id",)), "a save needs next_id = <int>")
        doc.next_id = nid
        name = data.get("name", "")
        doc.name = name if isinstance(name, str) else ""
    return doc


def _line_of(exc: tomllib.TOMLDecodeError, where: Where) -> Where:
    import re

    m = re.search(r"line (\d+)", str(exc))
    return Where(path=where.path, line=int(m.group(1))) if m else where


def _entry(index: int, raw: Any, source: Source, kind: str) -> Entry:
    path = ("entity", index)
    if not isinstance(raw, dict):
        raise SceneFileError(source.where(path), "an entity must be a table")
    key = raw.get("id", f"#{index + 1}")
    if kind == "save":
        if isinstance(key, bool) or not isinstance(key, int) or key < 1:
            raise SceneFileError(source.where((*path, "id")), f"a saved entity's id is a "
                                 f"positive integer, got {key!r}")
        key = str(key)
    elif not isinstance(key, str) or not key or len(key) > MAX_KEY or "/" in key:
        raise SceneFileError(
            source.where((*path, "id")),
            f"an entity id is a string of 1..{MAX_KEY} characters without '/', got {key!r}",
        )
    name = raw.get("name")
    if name is not None and not isinstance(name, str):
        raise SceneFileError(source.where((*path, "name"), entity=key), "name must be a string")
    prefab = raw.get("prefab")
    if prefab is not None and not isinstance(prefab, str):
        raise SceneFileError(source.where((*path, "prefab"), entity=key),
                             "prefab must be a path (a string)")
    at = raw.get("at")
    if at is not None:
        if prefab is None:
            raise SceneFileError(source.where((*path, "at"), entity=key),
                                 "at places a prefab instance: this entity has no prefab")
        if (not isinstance(at, list) or len(at) not in (2, 3)
                or not all(isinstance(v, int | float) and not isinstance(v, bool) for v in at)):
            raise SceneFileError(source.where((*path, "at"), entity=key),
                                 f"at must be [x, y] or [x, y, angle], got {at!r}")
        at = (float(at[0]), float(at[1]), float(at[2]) if len(at) == 3 else 0.0)
    overrides = raw.get("overrides", {})
    if not isinstance(overrides, dict) or (overrides and prefab is None):
        raise SceneFileError(source.where((*path, "overrides"), entity=key),
                             "overrides is a table, and only prefab instances have one")
    comps = {k: v for k, v in raw.items() if k not in ENTRY_KEYS}
    if prefab is not None and comps:
        first = next(iter(comps))
        raise SceneFileError(
            source.where((*path, first), entity=key),
            f"a prefab instance holds no components of its own ({first}); change its members "
            f"with [entity.overrides.MEMBER.{first}]",
        )
    return Entry(index, key, name, prefab, at, overrides, comps)


# -- expansion ---------------------------------------------------------------------------------
@dataclass(slots=True)
class Layer:
    """One instance's overrides of one member: where they were written, and what."""

    source: Source
    toml_path: tuple[Any, ...]
    scope: str  #: key prefix their entity references resolve in
    tables: dict[str, Any]


@dataclass(slots=True)
class Row:
    """One entity to spawn."""

    key: str
    scope: str  #: key prefix the entity's own references resolve in
    source: Source
    entry: Entry
    place: Pose | None = None  #: prefab frame -> world, for members of instances
    root_pose: Pose | None = None  #: the root member's exact pose
    layers: list[Layer] = field(default_factory=list)
    instance: str | None = None  #: the top-level instance this row belongs to
    member: str | None = None  #: its key inside that instance
    name: str | None = None


Opener = Callable[[Path], Document]


def expand(
    doc: Document, opener: Opener, *, scope: str = "", place: Pose | None = None,
    at: Pose | None = None, instance: str | None = None, chain: tuple[Path, ...] = (),
    outer: dict[str, list[Layer]] | None = None,
) -> list[Row]:
    """Rows for ``doc``'s entries; prefab entries become their prefab's rows."""
    if len(chain) > LIMITS.max_prefab_depth:
        raise SceneFileError(Where(path=doc.source.path),
                             f"prefabs nested more than {LIMITS.max_prefab_depth} deep")
    rows: list[Row] = []
    outer = outer or {}
    frame = place
    root_key = doc.root or (doc.entries[0].key if doc.entries and doc.kind == "prefab" else None)
    if doc.kind == "prefab" and at is not None:
        root_pose = entry_pose(doc, root_key)
        frame = compose(at, inverse(root_pose))
    for entry in doc.entries:
        key = scope + entry.key
        member = key if instance is None else key[len(instance) + 1:]
        where = doc.source.where(entry.toml_path, entity=key, entity_name=entry.name)
        if entry.prefab is not None:
            target = doc.source.paths.prefab(entry.prefab, doc.source.where(
                (*entry.toml_path, "prefab"), entity=key, entity_name=entry.name))
            if target in chain or target == doc.source.path:
                trail = [p for p in (*chain, doc.source.path) if p is not None]
                loop = " -> ".join(p.name for p in (*trail, target))
                raise SceneFileError(where, f"prefab cycle: {loop}")
            sub = opener(target)
            if sub.kind != "prefab":
                raise SceneFileError(where, f"{entry.prefab} is a {sub.kind} file, not a prefab")
            nested_at = entry.at
            if nested_at is not None and frame is not None:
                nested_at = compose(frame, nested_at)
            layers = _split_overrides(entry, doc.source, scope, outer, key)
            rows += expand(
                sub, opener, scope=key + "/", place=frame if nested_at is None else None,
                at=nested_at, instance=instance or key, chain=(*chain, doc.source.path or target),
                outer=layers,
            )
            continue
        row = Row(key, scope, doc.source, entry, place=frame, instance=instance,
                  member=None if instance is None else member, name=entry.name)
        if doc.kind == "prefab" and at is not None and entry.key == root_key:
            row.root_pose = at
        row.layers = outer.get(entry.key, [])
        for layer in row.layers:
            name = layer.tables.get("name")
            if name is not None:
                row.name = name
        rows.append(row)
    plain = {e.key for e in doc.entries if e.prefab is None}
    nested = {e.key for e in doc.entries if e.prefab is not None}
    for member in outer:
        head = member.split("/", 1)[0]
        if member in plain or ("/" in member and head in nested):
            continue
        layer = outer[member][-1]
        raise SceneFileError(layer.source.where(layer.toml_path),
                             f"overrides name {member!r}, which is no member of "
                             f"{doc.source.path.name if doc.source.path else 'the prefab'}")
    return rows


def entry_pose(doc: Document, key: str | None) -> Pose:
    """The prefab-space pose of entry ``key``: its Transform, or its own ``at``."""
    for e in doc.entries:
        if e.key != key:
            continue
        if e.at is not None:
            return e.at
        t = e.components.get("Transform")
        if isinstance(t, dict):
            vals = [t.get(k, 0.0) for k in ("x", "y", "angle")]
            if all(isinstance(v, int | float) and not isinstance(v, bool) for v in vals):
                return (float(vals[0]), float(vals[1]), float(vals[2]))
    return IDENTITY


def _split_overrides(
    entry: Entry, source: Source, scope: str, outer: dict[str, list[Layer]], key: str
) -> dict[str, list[Layer]]:
    """The overrides an instance entry passes to its prefab's members: its own, then those
    an enclosing instance wrote for members inside it (``"wheel/hub"``), which win."""
    out: dict[str, list[Layer]] = {}
    for member, tables in entry.overrides.items():
        path = (*entry.toml_path, "overrides", member)
        if not isinstance(tables, dict):
            raise SceneFileError(source.where(path, entity=key), "an override is a table of "
                                 "components")
        out.setdefault(member, []).append(Layer(source, path, scope + entry.key + "/", tables))
    prefix = entry.key + "/"
    for member, layers in outer.items():
        if member.startswith(prefix):
            out.setdefault(member[len(prefix):], []).extend(layers)
    return out


def open_file(path: Path, paths_for: Callable[[Path], AssetPaths]) -> Document:
    real = Path(os.path.realpath(path))
    return parse(read_text(real), real, paths_for(real.parent))
