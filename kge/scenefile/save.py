"""Writing a world (or some of its entities) as a scene file, and game saves.

The output is canonical: entities in id order under their keys, components in
the order the entity holds them, fields in declaration order and only where they
differ from the default, resources by name. So save, load, save gives the same
bytes, and a change in the editor is a small diff.
"""

from __future__ import annotations

import os
import tempfile
from collections.abc import Iterable
from pathlib import Path
from typing import TYPE_CHECKING, Any

from kge.components.name import Name
from kge.components.transform import Transform
from kge.scenefile.codec import Encoder
from kge.scenefile.default import default_registry
from kge.scenefile.errors import SceneFileError, Where
from kge.scenefile.migrate import FORMAT
from kge.scenefile.paths import AssetPaths
from kge.scenefile.registry import RESOURCE, TypeRegistry
from kge.scenefile.state import SceneState
from kge.scenefile.toml import header, key, value

if TYPE_CHECKING:
    from kge.world import World

PathLike = str | os.PathLike[str]


def map_entities(world: World) -> set[int]:
    """Entities a loaded Tiled map made (saved as the map's reference, not one by one)."""
    from kge.tilemap.runtime import TileMaps

    maps = world.try_resource(TileMaps)
    out: set[int] = set()
    for tmap in maps.maps if maps is not None else ():
        out.update(tmap.objects)
        out.update(tmap.collider_entities)
    return out


class Writer:
    """Turns one world into the text of a scene, prefab or save file."""

    def __init__(
        self, world: World, folder: Path, registry: TypeRegistry | None, kind: str,
        asset_roots: Iterable[PathLike] = (), exclude_resources: Iterable[type] = (),
    ) -> None:
        self.world = world
        self.exclude = set(exclude_resources)
        self.kind = kind
        self.save = kind == "save"
        self.registry = registry or default_registry()
        self.paths = AssetPaths(folder, _assets_for(world), [Path(os.fspath(r))
                                                            for r in asset_roots])
        state = world.try_resource(SceneState)
        self.state = state if state is not None else SceneState()
        self.keys: dict[int, str | int] = {}

    def text(self, entities: Iterable[int] | None = None, root: str | None = None) -> str:
        world = self.world
        world.flush()
        skip = map_entities(world)
        chosen = sorted(set(world.entities() if entities is None else entities) - skip)
        for e in chosen:
            if not world.exists(e):
                raise SceneFileError(Where(entity=str(e)), f"entity {e} does not exist")
        self.assign_keys(chosen)
        encoder = Encoder(self.registry, self.paths, self.key_of, save=self.save)
        out = [f"format = {FORMAT}", f"kind = {value(self.kind)}"]
        if self.save:
            out.append(f"name = {value(world.name)}")
            out.append(f"next_id = {self.next_id()}")
        if root is not None:
            out.append(f"root = {value(root)}")
        out += self.maps_text()
        out += self.resources_text(encoder)
        done: set[str] = set()
        for e in chosen:
            member = None if self.save else self.state.members.get(e)
            if member is not None:
                if member[0] not in done:
                    done.add(member[0])
                    out += self.instance_text(member[0])
                continue
            out += self.entity_text(e, encoder)
        return "\n".join(out) + "\n"

    # -- keys ---------------------------------------------------------------------------------
    def assign_keys(self, chosen: list[int]) -> None:
        if self.save:
            self.keys = {e: e for e in chosen}
            return
        used: set[str] = set()
        for e in chosen:
            k = self.state.keys.get(e)
            if k is not None and k not in used:
                self.keys[e] = k
                used.add(k)
        for e in chosen:
            if e in self.keys:
                continue
            name = self.world.try_get(e, Name)
            k = self.state.new_key(name.value if name is not None else "entity", used)
            self.keys[e] = k
            used.add(k)
            self.state.keys[e] = k  # a new entity keeps its key from now on

    def key_of(self, entity: int, where: Where) -> str | int:
        k = self.keys.get(entity)
        if k is None:
            raise SceneFileError(
                where, f"names entity {entity}, which is not being saved (save it too, or "
                "clear the reference)"
            )
        return k

    def next_id(self) -> int:
        entities = self.world.entities()
        from kge.snapshot import _next_id

        return max(_next_id(self.world), (max(entities) + 1) if entities else 1)

    # -- parts ------------------------------------------------------------------------------------
    def resources_text(self, encoder: Encoder) -> list[str]:
        out: list[str] = []
        for name in self.registry.names(RESOURCE):
            info = self.registry.get(name)
            assert info is not None
            res = self.world.try_resource(info.cls)
            if res is None or type(res) is not info.cls or info.cls in self.exclude:
                continue
            table = encoder.fields(info, res, Where(component=name))
            if not table:
                continue  # all defaults: the world's own default serves
            out += ["", header(("resources", name))]
            out += [f"{key(k)} = {value(v)}" for k, v in table.items()]
        return out

    def maps_text(self) -> list[str]:
        from kge.tilemap.runtime import TileMaps

        maps = self.world.try_resource(TileMaps)
        recorded = {id(ref.handle): ref for ref in self.state.maps}
        out: list[str] = []
        for tmap in maps.maps if maps is not None else ():
            ref = recorded.get(id(tmap))
            options = dict(ref.options) if ref is not None else dict(tmap.load_options)
            source = self.paths.save(str(tmap.path), Where(component="tilemap", field="source"))
            out += ["", header(("tilemap",), array=True), f"source = {value(source)}"]
            out += [f"{key(k)} = {value(v)}" for k, v in options.items() if k != "layer"
                    or v != 0]
            edits = tmap.edits()
            if edits and self.save:  # a scene file is the map as authored
                out.append(f"edits = {value(edits)}")
        return out

    def entity_text(self, e: int, encoder: Encoder) -> list[str]:
        k = self.keys[e]
        out = ["", "[[entity]]", f"id = {value(k)}"]
        name = self.world.try_get(e, Name)
        if name is not None:
            out.append(f"name = {value(name.value)}")
        for comp in self.world.components(e):
            if isinstance(comp, Name):
                continue
            where = Where(entity=str(k), entity_name=None if name is None else name.value)
            cname, table = encoder.component(comp, where)
            out += ["", header(("entity", cname))]
            out += [f"{key(f)} = {value(v)}" for f, v in table.items()]
        return out

    def instance_text(self, inst_key: str) -> list[str]:
        inst = self.state.instances[inst_key]
        out = ["", "[[entity]]", f"id = {value(inst_key)}",
               f"prefab = {value(self.paths.relative(inst.prefab))}"]
        root = None if inst.root is None else inst.members.get(inst.root)
        t = None if root is None else self.world.try_get(root, Transform)
        if t is not None and (inst.at is not None or (t.x, t.y, t.angle) != inst.authored):
            out.append(f"at = {value([t.x, t.y, t.angle])}")
        for member, comps in inst.overrides.items():
            name = comps.get("name") if isinstance(comps, dict) else None
            if isinstance(name, str):
                out += ["", header(("entity", "overrides", member)), f"name = {value(name)}"]
            for cname, table in comps.items():
                if cname == "name":
                    continue
                out += ["", header(("entity", "overrides", member, cname))]
                out += [f"{key(f)} = {value(v)}" for f, v in table.items()]
        return out


def dumps(
    world: World,
    folder: PathLike,
    *,
    entities: Iterable[int] | None = None,
    kind: str = "scene",
    root: str | None = None,
    registry: TypeRegistry | None = None,
    exclude_resources: Iterable[type] = (),
) -> str:
    """The text of ``world`` (or of ``entities``) as a file in ``folder``
    (``exclude_resources``: resource types left out, e.g. a tool's own settings)."""
    if kind not in ("scene", "prefab", "save"):
        raise SceneFileError(Where(), f"kind must be scene, prefab or save, got {kind!r}")
    writer = Writer(world, Path(os.fspath(folder)), registry, kind,
                    exclude_resources=exclude_resources)
    return writer.text(entities, root)


def write_text(path: PathLike, text: str) -> Path:
    """Write ``text`` to ``path`` atomically (a crash never leaves half a file)."""
    target = Path(os.fspath(path))
    fd, tmp = tempfile.mkstemp(prefix=f".{target.name}.", dir=target.parent or ".")
    try:
        with os.fdopen(fd, "w", encoding="utf-8", newline="\n") as f:
            f.write(text)
        os.replace(tmp, target)
    except BaseException:
        if os.path.exists(tmp):
            os.unlink(tmp)
        raise
    return target


def save_scene(
    world: World,
    path: PathLike,
    *,
    entities: Iterable[int] | None = None,
    registry: TypeRegistry | None = None,
    exclude_resources: Iterable[type] = (),
) -> Path:
    """Write ``world`` (or just ``entities``) as the scene file ``path``; returns the path.

    Nothing is written when something cannot be saved (an in-memory image, an
    unregistered component or script, a reference to an entity left out): the
    :class:`SceneFileError` names the entity, component and field.
    """
    target = Path(os.fspath(path)).absolute()
    text = dumps(world, target.parent, entities=entities, registry=registry,
                 exclude_resources=exclude_resources)
    state = world.try_resource(SceneState)
    if state is not None and entities is None:
        state.source = target
    return write_text(target, text)


def save_prefab(
    world: World,
    path: PathLike,
    entities: Iterable[int],
    *,
    root: int | None = None,
    registry: TypeRegistry | None = None,
) -> Path:
    """Write ``entities`` as the prefab file ``path``; ``root`` (default: the first)
    is the member whose Transform places an instance."""
    target = Path(os.fspath(path)).absolute()
    chosen = sorted(entities)
    if not chosen:
        raise SceneFileError(Where(path=target), "a prefab needs at least one entity")
    writer = Writer(world, target.parent, registry, "prefab")
    writer.assign_keys(chosen)
    root_key = None if root is None else str(writer.keys.get(root, ""))
    if root is not None and root not in writer.keys:
        raise SceneFileError(Where(path=target), f"root {root} is not one of the entities")
    text = writer.text(chosen, root_key)
    return write_text(target, text)


def save_game(world: World, path: PathLike, *, registry: TypeRegistry | None = None) -> Path:
    """Save everything a game needs to continue (every entity with its id, every field
    including the state physics writes, the simulation's resources) as a text file
    that :func:`kge.load_game` reads back without running any code it names."""
    target = Path(os.fspath(path)).absolute()
    text = dumps(world, target.parent, kind="save", registry=registry)
    return write_text(target, text)


def dumps_value(v: Any) -> str:
    """The TOML text of a plain value (for tools writing overrides by hand)."""
    return value(v)


def _assets_for(world: World) -> Any:
    """The world's asset store (imported when a file is read: a physics-only App never
    loads the asset modules)."""
    from kge.assets.store import assets_for

    return assets_for(world)
