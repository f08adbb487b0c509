"""Loading scene and prefab files into a world: everything checked, then all at once.

The order is what makes a bad file harmless: the file is read (size and UTF-8
checked), parsed by ``tomllib`` (data only), every value checked (no NaN, no
64-bit overflow, no deep nesting), prefabs opened (paths inside the allowed
folders, no cycles), every component built by its own constructor, and every
check ``spawn`` runs run with the whole file visible (``World.spawn_linked``).
Only then is anything added; on any error a :class:`SceneFileError` names the
place and the world is as it was.
"""

from __future__ import annotations

import copy
import os
from collections.abc import Callable, Iterable, Mapping
from pathlib import Path
from typing import TYPE_CHECKING, Any

from kge.components.collider import Collider
from kge.components.name import Name
from kge.components.transform import Transform
from kge.errors import KgeError
from kge.scenefile.codec import LIMITS, Decoder, Source
from kge.scenefile.default import default_registry
from kge.scenefile.document import Document, Row, entry_pose, expand, open_file
from kge.scenefile.errors import SceneFileError, Where
from kge.scenefile.paths import AssetPaths
from kge.scenefile.registry import COMPONENT, RESOURCE, TypeRegistry
from kge.scenefile.state import Instance, MapRef, SceneState, apply, compose

if TYPE_CHECKING:
    from kge.world import World

PathLike = str | os.PathLike[str]

#: the options a ``[[tilemap]]`` table may give, and their types
MAP_OPTIONS: dict[str, tuple[type, ...]] = {
    "pixels_per_meter": (int, float),
    "origin": (list,),
    "solid_layers": (list,),
    "layer": (int,),
    "friction": (int, float),
    "restitution": (int, float),
    "unknown": (str,),
    "edits": (list,),  #: saves: [layer, col, row, gid] of the cells set since loading
}


def scene_state(world: World) -> SceneState:
    """The world's :class:`SceneState` (created empty when the world has none)."""
    found = world.try_resource(SceneState)
    return found if found is not None else world.insert_resource(SceneState())


def resolve_file(world: World, source: PathLike) -> Path:
    """A scene file named by a game: an absolute path, or a name the world's asset store
    finds next to the game (never the working directory)."""
    text = os.fspath(source)
    path = Path(text)
    if path.is_absolute():
        return path
    store = _assets_for(world)
    found = store.find(text)
    if found is None or found.path is None:
        raise SceneFileError(
            Where(path=path), f"scene file not found; searched: {', '.join(store.searched(text))}"
        )
    return found.path


class Loader:
    """One load: the registry, how asset paths resolve, and the prefab files opened."""

    def __init__(
        self,
        world: World,
        registry: TypeRegistry | None,
        asset_roots: Iterable[PathLike],
        *,
        save: bool = False,
    ) -> None:
        self.world = world
        self.save = save
        self.registry = registry or default_registry()
        self.store = _assets_for(world)
        self.roots = [Path(os.fspath(r)) for r in asset_roots]
        self._opened: dict[Path, Document] = {}

    def paths(self, folder: Path) -> AssetPaths:
        return AssetPaths(folder, self.store, self.roots)

    def preload(self, texts: Mapping[Path, str]) -> None:
        """Read these files from the given texts, not from disk (the state a world was
        loaded from, which hot reload compares with a changed prefab)."""
        from kge.scenefile.document import parse

        for path, text in texts.items():
            self._opened[path] = parse(text, path, self.paths(path.parent))

    def open(self, path: Path) -> Document:
        real = Path(os.path.realpath(path))
        doc = self._opened.get(real)
        if doc is None:
            doc = self._opened[real] = open_file(real, self.paths)
        return doc

    def texts(self) -> dict[Path, str]:
        """The text of every file this load read, by path."""
        return {path: doc.text for path, doc in self._opened.items()}

    @property
    def files(self) -> list[Path]:
        """Every file this load read (the scene and its prefabs): hot reload watches them."""
        return list(self._opened)

    # -- building ----------------------------------------------------------------------------
    def spawn(
        self, doc: Document, rows: list[Row], *, spawners: Any = None
    ) -> list[int]:
        """Spawn ``rows`` (and ``doc``'s resources and maps) into the world, all or nothing."""
        if len(rows) > LIMITS.max_entities:
            raise SceneFileError(Where(path=doc.source.path),
                                 f"{len(rows)} entities (at most {LIMITS.max_entities})")
        world = self.world
        keys: dict[str, int] = {}
        resources: list[Any] = []

        def build(ids: list[int]) -> list[list[Any]]:
            keys.update((row.key, e) for row, e in zip(rows, ids, strict=True))
            out = [self.row(row, keys, e) for row, e in zip(rows, ids, strict=True)]
            resources.extend(self.resources(doc, keys))
            return out

        maps = self.maps(doc, spawners)
        try:
            ids = world.spawn_linked(len(rows), build)
        except BaseException as exc:
            for ref in maps:
                ref.handle.unload()
            if isinstance(exc, KgeError) and not isinstance(exc, SceneFileError):
                raise SceneFileError(Where(path=doc.source.path),
                                     _by_key(str(exc), keys)) from exc
            raise
        for res in resources:
            world.insert_resource(res)
        self.remember(doc, rows, ids, maps)
        return ids

    def resolver(self, keys: Mapping[str, int], scope: str) -> Callable[[Any, Where], int]:
        def resolve(key: Any, where: Where) -> int:
            if isinstance(key, int):  # a save's reference: an id of the save
                key = str(key)
            if scope and scope + key in keys:
                return keys[scope + key]
            if key in keys:
                return keys[key]
            raise SceneFileError(where, f"names entity {key!r}, which is not in this file")

        return resolve

    def component_info(self, name: str, where: Where) -> Any:
        if name == "Behaviour":
            from kge.components.behaviour import Behaviour

            return Behaviour
        info = self.registry.get(name)
        if info is not None and COMPONENT not in info.kinds:
            hint = " (put it under [resources])" if RESOURCE in info.kinds else ""
            raise SceneFileError(
                where, f"{name} is a {sorted(info.kinds)[0]}, not a component{hint}"
            )
        if info is None:
            raise SceneFileError(
                where, f"unknown component {name!r}{self.registry.suggest(name, COMPONENT)} "
                "(only registered components can appear in a file; register the game's own "
                "with kge.register_type)"
            )
        return info

    def row(self, row: Row, keys: Mapping[str, int], entity: int) -> list[Any]:
        """The components of one row: its tables, its instance's overrides, its placement."""
        from kge.scenefile.registry import TypeInfo

        decoder = Decoder(self.registry, row.source, self.resolver(keys, row.scope),
                          save=self.save)
        tables: dict[str, Any] = dict(row.entry.components)
        presets: dict[str, dict[str, Any]] = {}
        for layer in row.layers:
            ldec = Decoder(self.registry, layer.source, self.resolver(keys, layer.scope))
            for cname, ctable in layer.tables.items():
                lwhere = layer.source.where((*layer.toml_path, cname), entity=row.key,
                                            entity_name=row.name, component=cname)
                if cname == "name":
                    if not isinstance(ctable, str):
                        raise SceneFileError(lwhere, "name must be a string")
                    continue
                info = self.component_info(cname, lwhere)
                if not isinstance(ctable, dict):
                    raise SceneFileError(lwhere, "an override is a table of fields")
                if not isinstance(info, TypeInfo) or cname not in tables:
                    merged = dict(tables.get(cname, {}))
                    merged.update(ctable)  # a Behaviour's attributes, or a component added
                    tables[cname] = merged
                    continue
                for fname, raw in ctable.items():
                    fwhere = layer.source.where((*layer.toml_path, cname, fname),
                                                entity=row.key, entity_name=row.name,
                                                component=cname, field=fname)
                    spec = info.field_named(fname)
                    if spec is None or not spec.init:
                        raise SceneFileError(fwhere, f"{cname} has no field {fname!r}")
                    presets.setdefault(cname, {})[fname] = ldec.field(info, fname, raw, fwhere)
        comps: list[Any] = []
        for cname, table in tables.items():
            path = (*row.entry.toml_path, cname)
            where = row.source.where(path, entity=row.key, entity_name=row.name, component=cname)
            info = self.component_info(cname, where)
            if not isinstance(info, TypeInfo):
                comps.append(decoder.behaviour(table, path, where))
                continue
            if cname == "Name" and row.name is not None:
                raise SceneFileError(where, "give the name once: name = \"...\" or [Name]")
            comps.append(decoder.component(info, table, path, where, preset=presets.get(cname)))
        if row.name is not None:
            comps.append(Name(row.name))
        if row.place is not None or row.root_pose is not None:
            self.place(row, comps, entity)
        return comps

    def place(self, row: Row, comps: list[Any], entity: int) -> None:
        """Move a prefab member to its instance: its Transform (unless it is a part of a
        compound body, placed in that body's frame) and its world points (joint anchors)."""
        frame = row.place
        for comp in comps:
            if isinstance(comp, Transform):
                col = next((c for c in comps if isinstance(c, Collider)), None)
                if col is not None and col.body is not None and col.body != entity:
                    continue
                if row.root_pose is not None:
                    comp.x, comp.y, comp.angle = row.root_pose
                elif frame is not None:
                    comp.x, comp.y, comp.angle = compose(frame, (comp.x, comp.y, comp.angle))
                continue
            info = self.registry.info(type(comp))
            if info is None or frame is None:
                continue
            for name in info.point_fields:
                p = getattr(comp, name)
                if p is not None:
                    setattr(comp, name, apply(frame, p))

    def resources(self, doc: Document, keys: Mapping[str, int]) -> list[Any]:
        out = []
        decoder = Decoder(self.registry, doc.source, self.resolver(keys, ""),
                          save=doc.kind == "save")
        for name, table in doc.resources.items():
            path = ("resources", name)
            where = doc.source.where(path, component=name)
            info = self.registry.get(name)
            if info is None or RESOURCE not in info.kinds:
                raise SceneFileError(
                    where, f"unknown resource {name!r}{self.registry.suggest(name, RESOURCE)} "
                    "(only registered resources can appear in a file)"
                )
            out.append(decoder.component(info, table, path, where))
        return out

    def maps(self, doc: Document, spawners: Any) -> list[MapRef]:
        """Load the ``[[tilemap]]`` maps (each one all or nothing; all unloaded on error)."""
        from kge.tilemap import load_map

        refs: list[MapRef] = []
        try:
            for i, raw in enumerate(doc.maps):
                path = ("tilemap", i)
                where = doc.source.where(path, component="tilemap")
                unknown = set(raw) - set(MAP_OPTIONS) - {"source"}
                if unknown:
                    raise SceneFileError(where, f"unknown tilemap option {sorted(unknown)[0]!r}"
                                         f" (options: source, {', '.join(MAP_OPTIONS)})")
                for key, types in MAP_OPTIONS.items():
                    if key in raw and (isinstance(raw[key], bool)
                                       or not isinstance(raw[key], types)):
                        raise SceneFileError(
                            doc.source.where((*path, key), component="tilemap", field=key),
                            f"{key} has the wrong type: {raw[key]!r}",
                        )
                source = doc.source.paths.load(raw.get("source"), doc.source.where(
                    (*path, "source"), component="tilemap", field="source"))
                options = {k: v for k, v in raw.items() if k not in ("source", "edits")}
                kwargs = dict(options)
                if "origin" in kwargs:
                    kwargs["origin"] = tuple(kwargs["origin"])
                try:
                    handle = load_map(self.world, source, spawners=spawners, **kwargs)
                except Exception as exc:
                    raise SceneFileError(where, f"{exc}") from exc
                refs.append(MapRef(source, options, handle))
                try:
                    handle.apply_edits(raw.get("edits", ()))
                except Exception as exc:
                    raise SceneFileError(doc.source.where(
                        (*path, "edits"), component="tilemap", field="edits"), f"{exc}") from exc
        except BaseException:
            for ref in refs:
                ref.handle.unload()
            raise
        return refs

    def remember(self, doc: Document, rows: list[Row], ids: list[int], maps: list[MapRef]) -> None:
        """Record keys, instances and maps in the world's SceneState (for saving)."""
        state = scene_state(self.world)
        taken = {k.split("/", 1)[0] for k in state.keys.values()}
        renamed: dict[str, str] = {}
        for entry in doc.entries:
            top = entry.key
            if top in taken:
                renamed[top] = state.new_key(top, taken)
            taken.add(renamed.get(top, top))
        for row, e in zip(rows, ids, strict=True):
            head, _, rest = row.key.partition("/")
            head = renamed.get(head, head)
            state.keys[e] = head + ("/" + rest if rest else "")
        for entry in doc.entries:
            if entry.prefab is None:
                continue
            key = renamed.get(entry.key, entry.key)
            prefab = doc.source.paths.prefab(entry.prefab, Where())
            inst = Instance(key, prefab, entry.at, copy.deepcopy(entry.overrides))
            sub = self.open(prefab)
            inst.root = sub.root or (sub.entries[0].key if sub.entries else None)
            inst.authored = entry_pose(sub, inst.root)
            for row, e in zip(rows, ids, strict=True):
                if row.instance == entry.key and row.member is not None:
                    inst.members[row.member] = e
                    state.members[e] = (key, row.member)
            state.instances[key] = inst
        state.maps.extend(maps)
        state.files.update(self.texts())


def _by_key(message: str, keys: Mapping[str, int]) -> str:
    """A world validator's message with the file's keys beside the entity ids it names."""
    import re

    names = {e: k for k, e in keys.items()}

    def sub(m: re.Match[str]) -> str:
        key = names.get(int(m.group(1)))
        return m.group(0) if key is None else f"{m.group(0)} ({key!r})"

    return re.sub(r"\bentity (\d+)", sub, message)


def load_scene(
    world: World,
    source: PathLike,
    *,
    registry: TypeRegistry | None = None,
    asset_roots: Iterable[PathLike] = (),
    spawners: Any = None,
) -> list[int]:
    """Load the scene file ``source`` into ``world`` and return the new entities.

    ``source`` is a path, or a name the world's asset store finds. Assets and
    prefabs named by the file resolve relative to it, inside the folders the game
    allows (the file's folder, the asset store's folders, ``asset_roots``).
    ``spawners`` (a :class:`~kge.tilemap.Spawners`) builds the objects of the file's
    Tiled maps. On any error a :class:`SceneFileError` names the file, line, entity,
    component and field, and ``world`` is left unchanged.
    """
    path = resolve_file(world, source)
    loader = Loader(world, registry, asset_roots)
    doc = loader.open(path)
    if doc.kind != "scene":
        raise SceneFileError(Where(path=doc.source.path), f"a {doc.kind} file, not a scene "
                             f"({'use kge.load_game' if doc.kind == 'save' else 'instance it'})")
    rows = expand(doc, loader.open)
    ids = loader.spawn(doc, rows, spawners=spawners)
    state = scene_state(world)
    if state.source is None:
        state.source = doc.source.path
    return ids


def load_scene_text(
    world: World,
    text: str,
    path: PathLike,
    *,
    registry: TypeRegistry | None = None,
    asset_roots: Iterable[PathLike] = (),
    spawners: Any = None,
) -> list[int]:
    """:func:`load_scene` from ``text`` (a scene file's content not written to disk yet:
    the editor's play mode and undo). ``path`` is where it would live: its folder
    resolves assets and prefabs, and errors name it."""
    from kge.scenefile.document import parse

    real = Path(os.path.realpath(os.fspath(path)))
    loader = Loader(world, registry, asset_roots)
    doc = parse(text, real, loader.paths(real.parent))
    if doc.kind != "scene":
        raise SceneFileError(Where(path=real), f"a {doc.kind} file, not a scene")
    rows = expand(doc, loader.open)
    ids = loader.spawn(doc, rows, spawners=spawners)
    state = scene_state(world)
    state.files[real] = text
    if state.source is None:
        state.source = real
    return ids


def instantiate(
    world: World,
    prefab: PathLike,
    at: tuple[float, float] | tuple[float, float, float] | None = None,
    *,
    key: str | None = None,
    overrides: Mapping[str, Mapping[str, Mapping[str, Any]]] | None = None,
    registry: TypeRegistry | None = None,
    asset_roots: Iterable[PathLike] = (),
) -> list[int]:
    """Place the prefab file ``prefab`` in ``world``: its root at ``at`` = (x, y[, angle]).

    ``overrides`` = ``{member: {Component: {field: value}}}`` in the file's written
    forms (what ``[entity.overrides...]`` would hold). Returns the new entities, in
    the prefab's order; the instance is remembered, so a saved scene keeps it as one.
    """
    path = resolve_file(world, prefab)
    loader = Loader(world, registry, asset_roots)
    pdoc = loader.open(path)
    if pdoc.kind != "prefab":
        raise SceneFileError(Where(path=pdoc.source.path), f"a {pdoc.kind} file, not a prefab")
    state = scene_state(world)
    taken = {k.split("/", 1)[0] for k in state.keys.values()}
    name = key or state.new_key(path.name.split(".")[0], taken)
    pose = None if at is None else (float(at[0]), float(at[1]),
                                     float(at[2]) if len(at) > 2 else 0.0)
    folder = pdoc.source.path.parent if pdoc.source.path else Path.cwd()
    entry_source = Source(None, None, loader.paths(folder))
    rel = entry_source.paths.relative(path)
    from kge.scenefile.document import Entry

    entry = Entry(0, name, None, rel, pose, copy.deepcopy(dict(overrides or {})), {})
    doc = Document(entry_source, "scene", [entry], {}, [])
    rows = expand(doc, loader.open)
    return loader.spawn(doc, rows)


def _assets_for(world: World) -> Any:
    """The world's asset store (imported when a file is read: a physics-only App never
    loads the asset modules)."""
    from kge.assets.store import assets_for

    return assets_for(world)
