"""``EditorModel``: the scene being edited, the selection, and every edit as an undoable step.

The editor's window is a view of this model; tests drive the model and the window
alike. Edits are commands kept in a history:

* field edits (a number typed in the inspector, a gizmo drag, a shape or anchor
  handle) are :class:`SetFields` steps: the entity's key, the component type, and
  each field's value before and after;
* structural edits (create, delete, duplicate, reparent, add or remove a component,
  place a prefab, paint) are :class:`Rebuild` steps holding the scene's text before
  and after: undo loads the text back, so ids and references come back exactly.

Entities are named in steps by their key (the scene file's ``id``), not their
number, because a rebuild renumbers them.
"""

from __future__ import annotations

import copy
import dataclasses
import math
import os
from collections.abc import Callable, Iterable
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from kge.components.camera import Camera
from kge.components.collider import Collider
from kge.components.joints.base import Joint
from kge.components.name import Name
from kge.components.shapes import Box, Chain, Circle, Edge, Polygon
from kge.components.sprite import Sprite
from kge.components.transform import Transform
from kge.components.ui import UINode
from kge.scenefile import (
    SceneFileError,
    SceneState,
    default_registry,
    dumps,
    instantiate,
    load_scene,
    load_scene_text,
    save_scene,
    scene_state,
)
from kge.scenefile.codec import Encoder
from kge.scenefile.paths import AssetPaths
from kge.scenefile.state import compose, inverse
from kge.world import World

Vec2 = tuple[float, float]


@dataclass(slots=True)
class EditorOnly:
    """Marks the editor's own entities in the edited world (its camera): never saved."""


@dataclass(slots=True)
class SetFields:
    """Field values of one component of one entity, before and after."""

    key: str
    component: type
    before: dict[str, Any]
    after: dict[str, Any]
    label: str = "edit"


@dataclass(slots=True)
class Rebuild:
    """The whole scene's text before and after a structural edit."""

    before: str
    after: str
    label: str = "change"
    selection: tuple[str, ...] = ()


@dataclass(slots=True)
class Compound:
    """Several steps undone and redone together (one drag of many entities)."""

    steps: list[SetFields | Rebuild]
    label: str = "edit"


Step = SetFields | Rebuild | Compound


class EditorModel:
    """The edited world, its file, the selection and the undo history."""

    def __init__(self, world: World, path: str | os.PathLike[str] | None = None) -> None:
        self.world = world
        self.path = None if path is None else Path(os.path.realpath(path))
        #: resources the editor puts in the edited world (its debug overlay): not saved
        self.own_resources: set[type] = set()
        self.selection: list[int] = []
        self.undo_stack: list[Step] = []
        self.redo_stack: list[Step] = []
        self.grid = 0.5  #: snapping step in metres (0: no snapping)
        self.snap = True
        #: the camera the viewport draws through (an editor-only entity, lowest id)
        self.camera_entity = world.spawn(EditorOnly(), Camera(pixels_per_meter=48.0),
                                         Name("editor camera"))
        if self.path is not None and self.path.exists():
            load_scene(world, self.path)
        scene_state(world).source = self.path
        self.listeners: list[Callable[[str], None]] = []
        #: bumped by every change (views cache what they show by it)
        self.revision = 0
        self._saved_at: tuple[int, Any] = self._history_mark()

    # -- reading ----------------------------------------------------------------------------
    @property
    def camera(self) -> Camera:
        return self.world.get(self.camera_entity, Camera)

    @property
    def state(self) -> SceneState:
        return scene_state(self.world)

    def entities(self) -> list[int]:
        """The scene's entities, in id order: not the editor's own, nor those a Tiled map
        made (the map is one ``[[tilemap]]`` reference in the file)."""
        from kge.scenefile.save import map_entities

        skip = map_entities(self.world)
        return [e for e in self.world.entities()
                if e not in skip and not self.world.has(e, EditorOnly)]

    def key(self, entity: int) -> str:
        k = self.state.keys.get(entity)
        if k is None:
            name = self.world.try_get(entity, Name)
            k = self.state.new_key(name.value if name is not None else "entity")
            self.state.keys[entity] = k
        return k

    def entity(self, key: str) -> int:
        e = self.state.entity(key)
        if e is None:
            raise KeyError(f"no entity {key!r} in the scene")
        return e

    def name(self, entity: int) -> str:
        n = self.world.try_get(entity, Name)
        return n.value if n is not None else self.key(entity)

    def parent(self, entity: int) -> int | None:
        """The entity shown above this one in the hierarchy (UI parent, compound body,
        or the root of its prefab instance)."""
        node = self.world.try_get(entity, UINode)
        if node is not None and node.parent is not None:
            return node.parent
        col = self.world.try_get(entity, Collider)
        if col is not None and col.body is not None and col.body != entity:
            return col.body
        member = self.state.members.get(entity)
        if member is not None:
            inst = self.state.instances.get(member[0])
            root = None if inst is None or inst.root is None else inst.members.get(inst.root)
            if root is not None and root != entity:
                return root
        return None

    def hierarchy(self, search: str = "") -> list[tuple[int, int]]:
        """(entity, depth) rows in tree order; ``search`` keeps the matching names."""
        ents = self.entities()
        children: dict[int | None, list[int]] = {}
        alive = set(ents)
        for e in ents:
            p = self.parent(e)
            children.setdefault(p if p in alive else None, []).append(e)
        rows: list[tuple[int, int]] = []

        def walk(e: int, depth: int, seen: set[int]) -> None:
            if e in seen:
                return
            seen.add(e)
            rows.append((e, depth))
            for c in children.get(e, []):
                walk(c, depth + 1, seen)

        seen: set[int] = set()
        for e in children.get(None, []):
            walk(e, 0, seen)
        for e in ents:  # anything in a cycle
            walk(e, 0, seen)
        if search:
            s = search.lower()
            rows = [(e, d) for e, d in rows if s in self.name(e).lower() or s in self.key(e)]
        return rows

    def _history_mark(self) -> tuple[int, Any]:
        """Where the history stands: the undo stack's depth and its top step (the step
        itself, not its id: a freed step's id can come back on a new one)."""
        return (len(self.undo_stack), self.undo_stack[-1] if self.undo_stack else None)

    @property
    def dirty(self) -> bool:
        """Unsaved changes? (Undoing back to the saved state makes it clean again.)"""
        (n, top), (saved_n, saved_top) = self._history_mark(), self._saved_at
        return n != saved_n or top is not saved_top

    def text(self) -> str:
        folder = self.path.parent if self.path is not None else Path.cwd()
        return dumps(self.world, folder, entities=self.entities(),
                     exclude_resources=self.own_resources)

    def pick(self, point: Vec2) -> int | None:
        """The entity under a world point: inside a collider, else near its position
        (topmost first: highest id)."""
        from kge.collision import test_point

        best: int | None = None
        near = 0.35 / max(self.camera.zoom, 0.1)
        for e in reversed(self.entities()):
            t = self.world.try_get(e, Transform)
            if t is None:
                continue
            col = self.world.try_get(e, Collider)
            pose = self.world_pose(e)
            if col is not None and not isinstance(col.shape, Edge | Chain):
                if test_point(col.shape, pose, point):
                    return e
            elif math.dist(pose[:2], point) <= near and best is None:
                best = e
        return best

    def world_pose(self, entity: int) -> tuple[float, float, float]:
        t = self.world.get(entity, Transform)
        col = self.world.try_get(entity, Collider)
        if col is not None and col.body is not None and col.body != entity:
            body = self.world.try_get(col.body, Transform)
            if body is not None:
                return compose((body.x, body.y, body.angle), (t.x, t.y, t.angle))
        return (t.x, t.y, t.angle)

    # -- selection --------------------------------------------------------------------------
    def select(self, entity: int | None, *, add: bool = False) -> None:
        if entity is None:
            if not add:
                self.selection = []
        elif add:
            if entity in self.selection:
                self.selection.remove(entity)
            else:
                self.selection.append(entity)
        else:
            self.selection = [entity]
        self._notify("select")

    # -- history ----------------------------------------------------------------------------
    def _push(self, step: Step) -> None:
        self.undo_stack.append(step)
        self.redo_stack.clear()
        self._notify(step.label)

    def _notify(self, what: str) -> None:
        self.revision = getattr(self, "revision", 0) + 1
        for fn in list(getattr(self, "listeners", [])):
            fn(what)

    def undo(self) -> bool:
        if not self.undo_stack:
            return False
        step = self.undo_stack.pop()
        self._apply(step, backwards=True)
        self.redo_stack.append(step)
        self._notify("undo")
        return True

    def redo(self) -> bool:
        if not self.redo_stack:
            return False
        step = self.redo_stack.pop()
        self._apply(step, backwards=False)
        self.undo_stack.append(step)
        self._notify("redo")
        return True

    def _apply(self, step: Step, backwards: bool) -> None:
        if isinstance(step, Compound):
            for part in reversed(step.steps) if backwards else step.steps:
                self._apply(part, backwards)
        elif isinstance(step, SetFields):
            comp: Any = self.world.get(self.entity(step.key), step.component)
            for name, value in (step.before if backwards else step.after).items():
                setattr(comp, name, value)
            self._record_overrides(self.entity(step.key), comp, list(step.after))
        else:
            keys = [self.key(e) for e in self.selection if self.world.exists(e)]
            self._reload(step.before if backwards else step.after)
            self.selection = [e for k in (keys or step.selection)
                              if (e := self.state.entity(k)) is not None]

    def _reload(self, text: str) -> None:
        """Replace the scene's entities with those of ``text`` (keys kept)."""
        for e in self.entities():
            self.world.despawn(e)
        self.world.flush()
        from kge.tilemap.runtime import TileMaps

        maps = self.world.try_resource(TileMaps)
        for tmap in list(maps.maps) if maps is not None else []:
            tmap.unload()
        self.world.flush()
        state = self.state
        state.keys.clear()
        state.instances.clear()
        state.members.clear()
        state.maps.clear()
        path = self.path or Path.cwd() / "untitled.scene.toml"
        load_scene_text(self.world, text, path)
        state.source = self.path

    def structural(self, label: str, change: Callable[[], Any]) -> Any:
        """Run ``change`` (which adds or removes entities or components) as one undo step;
        on an error the scene is put back as it was and the error is raised."""
        before = self.text()
        keys = tuple(self.key(e) for e in self.selection if self.world.exists(e))
        try:
            result = change()
            self.world.flush()
            after = self.text()
        except BaseException:
            self._reload(before)
            raise
        if after != before:
            self._push(Rebuild(before, after, label, keys))
        return result

    # -- field edits ------------------------------------------------------------------------
    def set_fields(self, entity: int, component: type, values: dict[str, Any],
                   label: str = "edit", before: dict[str, Any] | None = None) -> None:
        """Set fields of one component (validated by the component); one undo step.

        ``before`` gives the values to return to on undo when the fields were already
        changed live (a gizmo drag updates them as the mouse moves)."""
        comp: Any = self.world.get(entity, component)
        old = dict(before) if before is not None else {
            k: copy.copy(getattr(comp, k)) for k in values}
        try:
            for k, v in values.items():
                setattr(comp, k, v)
        except BaseException:
            for k, v in old.items():
                setattr(comp, k, v)
            raise
        new = {k: getattr(comp, k) for k in values}
        if all(_same(old[k], new[k]) for k in values):
            return
        self._record_overrides(entity, comp, list(values))
        self._push(SetFields(self.key(entity), component, old, new, label))

    def set_field(self, entity: int, component: type, field: str, value: Any) -> None:
        self.set_fields(entity, component, {field: value}, f"{component.__name__}.{field}")

    def _record_overrides(self, entity: int, comp: Any, fields: list[str]) -> None:
        """An edit of a prefab instance's member is an override of that instance."""
        member = self.state.members.get(entity)
        if member is None:
            return
        inst = self.state.instances[member[0]]
        info = default_registry().info(type(comp))
        if info is None:
            return
        if isinstance(comp, Transform):
            if member[1] == inst.root:
                return  # the root's pose is the instance's `at`
            root = inst.members.get(inst.root or "")
            rt = None if root is None else self.world.try_get(root, Transform)
            if rt is None:
                return
            frame = compose((rt.x, rt.y, rt.angle), inverse(inst.authored))
            local = compose(inverse(frame), (comp.x, comp.y, comp.angle))
            values = dict(zip(("x", "y", "angle"), local, strict=True))
            table = inst.overrides.setdefault(member[1], {}).setdefault("Transform", {})
            table.update({k: values[k] for k in ("x", "y", "angle")})
            return
        folder = self.path.parent if self.path is not None else Path.cwd()
        encoder = Encoder(default_registry(), AssetPaths(folder), lambda e, w: self.key(e))
        from kge.scenefile.errors import Where

        table = inst.overrides.setdefault(member[1], {}).setdefault(info.name, {})
        for f in fields:
            value = getattr(comp, f)
            if f in info.entity_fields:
                table[f] = {} if value is None else self.key(value)
            elif value is None:
                table[f] = {}
            else:
                table[f] = encoder.value(value, Where(), 0)

    # -- structural edits ----------------------------------------------------------------------
    def create(self, *components: Any, name: str | None = None) -> int:
        """A new entity (selected); one undo step."""
        comps = list(components)
        if name is not None:
            comps.append(Name(name))

        def change() -> int:
            e = self.world.spawn(*comps)
            self.key(e)
            return e

        e: int = self.structural("create", change)
        self.selection = [e]
        return e

    def delete(self, entities: Iterable[int] | None = None) -> None:
        """Delete the entities (default: the selection), and what depends on them
        (joints naming them, colliders attached to them)."""
        targets = set(self.selection if entities is None else entities)
        if not targets:
            return
        doomed = set(targets)
        for e in self.entities():
            j = _joint_of(self.world, e)
            if j is not None and ({j.body_a, j.body_b} & targets):
                doomed.add(e)
            col = self.world.try_get(e, Collider)
            if col is not None and col.body in targets:
                doomed.add(e)

        def change() -> None:
            for e in sorted(doomed):
                self._forget_member(e)
                self.world.despawn(e)

        self.structural("delete", change)
        self.selection = []

    def _forget_member(self, entity: int) -> None:
        """An instance member deleted: the instance is unpacked into plain entities."""
        member = self.state.members.get(entity)
        if member is None:
            return
        inst = self.state.instances.pop(member[0], None)
        if inst is None:
            return
        for m, e in inst.members.items():
            self.state.members.pop(e, None)
            self.state.keys[e] = f"{inst.key}-{m}".replace("/", "-")

    def duplicate(self, entities: Iterable[int] | None = None, offset: Vec2 = (0.5, -0.5)
                  ) -> list[int]:
        """Copies of the entities (references among them point at the copies)."""
        chosen = sorted(set(self.selection if entities is None else entities))
        if not chosen:
            return []
        folder = self.path.parent if self.path is not None else Path.cwd()
        text = dumps(self.world, folder, entities=chosen)
        taken = set(self.state.keys.values())

        def change() -> list[int]:
            scratch = World()
            ids = load_scene_text(scratch, text, folder / "copy.scene.toml")
            comps = {e: scratch.components(e) for e in ids}
            old_keys = [scratch.resource(SceneState).keys[e] for e in ids]
            scratch_ids = list(ids)

            def build(new_ids: list[int]) -> list[list[Any]]:
                remap = dict(zip(scratch_ids, new_ids, strict=True))
                rows = []
                for e in scratch_ids:
                    row = []
                    for c in comps[e]:
                        c2 = _remapped(c, remap)
                        if isinstance(c2, Transform) and not _is_part(comps[e]):
                            c2 = Transform(c2.x + offset[0], c2.y + offset[1], c2.angle)
                        row.append(c2)
                    rows.append(row)
                return rows

            new = self.world.spawn_linked(len(scratch_ids), build)
            scratch.close()
            for e, k in zip(new, old_keys, strict=True):
                key = self.state.new_key(k.replace("/", "-"), taken)
                taken.add(key)
                self.state.keys[e] = key
            return new

        new: list[int] = self.structural("duplicate", change)
        self.selection = list(new)
        return new

    def rename(self, entity: int, name: str) -> None:
        if self.world.has(entity, Name):
            self.set_field(entity, Name, "value", name)
        else:
            self.add_component(entity, Name(name))

    def add_component(self, entity: int, component: Any) -> None:
        key = self.key(entity)
        self.structural(f"add {type(component).__name__}",
                        lambda: self.world.add(self.entity(key), component))

    def remove_component(self, entity: int, component: type) -> None:
        key = self.key(entity)
        self.structural(f"remove {component.__name__}",
                        lambda: self.world.remove(self.entity(key), component))

    def reparent(self, entity: int, parent: int | None) -> None:
        """Drag in the hierarchy: a UI node's parent, or a collider's body (compound)."""
        if self.world.has(entity, UINode):
            self.set_field(entity, UINode, "parent", parent)
            return
        col = self.world.try_get(entity, Collider)
        if col is None:
            raise SceneFileError(_where(self.key(entity)), "only UI nodes and colliders have a "
                                 "parent (a collider's body)")
        t = self.world.try_get(entity, Transform)
        pose = self.world_pose(entity) if t is not None else None
        self.set_fields(entity, Collider, {"body": parent}, "reparent")
        if t is None or pose is None or not self.undo_stack:
            return
        step = self.undo_stack.pop()
        assert not isinstance(step, Compound)
        frame = (0.0, 0.0, 0.0)  # keep it where it is on screen: into the new body's frame
        if parent is not None:
            pt = self.world.get(parent, Transform)
            frame = (pt.x, pt.y, pt.angle)
        local = compose(inverse(frame), pose)
        self.set_fields(entity, Transform, {"x": local[0], "y": local[1], "angle": local[2]},
                        "reparent")
        moved = self.undo_stack.pop() if self.undo_stack else None
        parts = [step] if not isinstance(moved, SetFields) else [step, moved]
        self._push(Compound(parts, "reparent"))

    def add_map(self, source: str | os.PathLike[str], **options: Any) -> None:
        """Load a Tiled map into the scene (saved as a ``[[tilemap]]`` reference with
        these ``load_map`` options); one undo step."""
        from kge.scenefile.state import MapRef
        from kge.tilemap import load_map

        def change() -> None:
            handle = load_map(self.world, os.fspath(source), unknown="ignore", **options)
            self.state.maps.append(MapRef(os.fspath(source), dict(options), handle))

        self.structural("add map", change)

    def place_prefab(
        self, prefab: str | os.PathLike[str], at: Vec2, angle: float = 0.0
    ) -> list[int]:
        """An instance of the prefab file with its root at ``at`` (snapped)."""
        x, y = self.snapped(at)

        def change() -> list[int]:
            return instantiate(self.world, prefab, at=(x, y, angle))

        ids: list[int] = self.structural("place prefab", change)
        self.selection = ids[:1]
        return ids

    def paint(self, brush: int, cells: Iterable[Vec2]) -> list[int]:
        """Copies of ``brush`` at each grid cell of ``cells`` (world points, snapped to the
        grid; cells already holding a copy are skipped): one undo step per stroke."""
        points = []
        seen: set[Vec2] = set()
        occupied = {self.snapped(self.world_pose(e)[:2]) for e in self.entities()
                    if self.world.has(e, Transform)}
        for p in cells:
            s = self.snapped(p)
            if s not in seen and s not in occupied:
                seen.add(s)
                points.append(s)
        if not points:
            return []
        t = self.world.get(brush, Transform)
        made: list[int] = []

        def change() -> None:
            for x, y in points:
                (e,) = self.duplicate_one(brush, (x - t.x, y - t.y))
                made.append(e)

        self.structural("paint", change)
        return made

    def duplicate_one(self, entity: int, offset: Vec2) -> list[int]:
        comps = [_remapped(c, {}) for c in self.world.components(entity)]
        out = []
        for i, c in enumerate(comps):
            if isinstance(c, Transform):
                comps[i] = Transform(c.x + offset[0], c.y + offset[1], c.angle)
        e = self.world.spawn(*comps)
        name = self.world.try_get(e, Name)
        self.state.keys[e] = self.state.new_key(name.value if name else self.key(entity))
        out.append(e)
        return out

    # -- tools: gizmos and handles -------------------------------------------------------------
    def snapped(self, p: Vec2) -> Vec2:
        if not self.snap or self.grid <= 0:
            return (float(p[0]), float(p[1]))
        g = self.grid
        return (round(p[0] / g) * g, round(p[1] / g) * g)

    def move(self, entities: Iterable[int], delta: Vec2, *, live: bool = False,
             start: dict[int, Vec2] | None = None) -> None:
        """Move entities by ``delta`` (from ``start`` positions when dragging). With
        ``live`` the fields change without an undo step (mid-drag); the final call of a
        drag is not live and makes one step for the whole drag."""
        ents = list(entities)
        steps: list[SetFields | Rebuild] = []
        for e in ents:
            t = self.world.get(e, Transform)
            x0, y0 = (start or {}).get(e, (t.x, t.y))
            x, y = self.snapped((x0 + delta[0], y0 + delta[1]))
            if live:
                t.x, t.y = x, y
                continue
            self.set_fields(e, Transform, {"x": x, "y": y}, "move", before={"x": x0, "y": y0})
            last = self.undo_stack[-1] if self.undo_stack else None
            if isinstance(last, SetFields):
                steps.append(self.undo_stack.pop())  # type: ignore[arg-type]
        if steps:
            self._push(Compound(list(steps), "move"))

    def rotate(self, entity: int, angle: float, *, before: float | None = None) -> None:
        step = math.radians(15.0) if self.snap else 0.0
        a = round(angle / step) * step if step else angle
        self.set_fields(entity, Transform, {"angle": a}, "rotate",
                        before=None if before is None else {"angle": before})

    def scale(self, entity: int, factor: float) -> None:
        """Scale the entity's collider shape and sprite size by ``factor``."""
        if not math.isfinite(factor) or factor <= 0:
            raise SceneFileError(_where(self.key(entity)), f"scale factor {factor!r}")
        steps: list[SetFields | Rebuild] = []
        col = self.world.try_get(entity, Collider)
        if col is not None:
            self.set_fields(entity, Collider, {"shape": _scaled(col.shape, factor)}, "scale")
            last = self.undo_stack.pop()
            assert not isinstance(last, Compound)
            steps.append(last)
        sp = self.world.try_get(entity, Sprite)
        if sp is not None and sp.size is not None:
            self.set_fields(entity, Sprite, {"size": (sp.size[0] * factor,
                                                      sp.size[1] * factor)}, "scale")
            last = self.undo_stack.pop()
            assert not isinstance(last, Compound)
            steps.append(last)
        if steps:
            self._push(Compound(steps, "scale"))

    def shape_handles(self, entity: int) -> list[Vec2]:
        """World positions of the entity's collider handles (box corner, circle rim,
        polygon/chain vertices, edge ends)."""
        col = self.world.try_get(entity, Collider)
        if col is None:
            return []
        pose = self.world_pose(entity)
        from kge.scenefile.state import apply

        s = col.shape
        if isinstance(s, Box):
            local = [apply((s.center[0], s.center[1], s.angle), (s.half_width, s.half_height))]
        elif isinstance(s, Circle):
            local = [(s.center[0] + s.radius, s.center[1])]
        elif isinstance(s, Polygon | Chain):
            local = list(s.vertices)
        else:
            assert isinstance(s, Edge)
            local = [s.v1, s.v2]
        return [apply(pose, p) for p in local]

    def drag_shape_handle(self, entity: int, index: int, point: Vec2) -> None:
        """Move handle ``index`` of the entity's collider to the world ``point``."""
        col = self.world.get(entity, Collider)
        pose = self.world_pose(entity)
        from kge.scenefile.state import apply

        local = apply(inverse(pose), self.snapped(point))
        s = col.shape
        new: Any
        if isinstance(s, Box):
            inner = apply(inverse((s.center[0], s.center[1], s.angle)), local)
            new = dataclasses.replace(s, half_width=abs(inner[0]), half_height=abs(inner[1]))
        elif isinstance(s, Circle):
            new = dataclasses.replace(s, radius=math.dist(s.center, local))
        elif isinstance(s, Polygon | Chain):
            verts = list(s.vertices)
            verts[index] = local
            new = dataclasses.replace(s, vertices=verts)
        else:
            assert isinstance(s, Edge)
            new = Edge(local, s.v2) if index == 0 else Edge(s.v1, local)
        self.set_fields(entity, Collider, {"shape": new}, "shape handle")

    def joint_anchor(self, entity: int) -> Vec2 | None:
        """The world point of a joint's anchor handle."""
        j = _joint_of(self.world, entity)
        if j is None:
            return None
        anchor = getattr(j, "anchor", None)
        if anchor is not None:
            return anchor
        if j.body_a is not None and hasattr(j, "local_anchor_a"):
            from kge.scenefile.state import apply

            return apply(self.world_pose(j.body_a), j.local_anchor_a)
        return None

    def drag_joint_anchor(self, entity: int, point: Vec2) -> None:
        """Put the joint's anchor at the world ``point`` (its local anchors follow)."""
        j = _joint_of(self.world, entity)
        if j is None or not hasattr(j, "anchor"):
            raise SceneFileError(_where(self.key(entity)), "this entity has no one-point joint")
        self.set_fields(entity, type(j), {"anchor": self.snapped(point)}, "joint anchor")

    # -- files ---------------------------------------------------------------------------------
    def save(self, path: str | os.PathLike[str] | None = None) -> Path:
        """Save (or save as ``path``); the model's file becomes ``path``."""
        target = Path(os.path.realpath(path)) if path is not None else self.path
        if target is None:
            raise SceneFileError(_where(None), "no file yet: save as a path first")
        saved = save_scene(self.world, target, entities=self.entities(),
                           exclude_resources=self.own_resources)
        self.path = Path(os.path.realpath(saved))
        self.state.source = self.path
        self._saved_at = self._history_mark()
        self._notify("save")
        return saved


def _where(key: str | None) -> Any:
    from kge.scenefile.errors import Where

    return Where(entity=key)


def _same(a: Any, b: Any) -> bool:
    from kge.scenefile.codec import same

    return same(a, b)


def _joint_of(world: World, entity: int) -> Any:
    for c in world.components(entity):
        if isinstance(c, Joint):
            return c
    return None


def _is_part(comps: tuple[Any, ...]) -> bool:
    """A collider attached to another entity's body: its Transform is in that body's frame."""
    return any(isinstance(c, Collider) and c.body is not None for c in comps)


def _remapped(comp: Any, remap: dict[int, int]) -> Any:
    """A fresh copy of ``comp`` (unbound), entity references mapped through ``remap``."""
    info = default_registry().info(type(comp))
    if info is None or not dataclasses.is_dataclass(comp):
        return copy.deepcopy(comp)
    kwargs = {}
    cls: Any = type(comp)
    for f in dataclasses.fields(comp):
        if not f.init or f.name.startswith("_"):
            continue
        v = getattr(comp, f.name)
        if f.name in info.entity_fields and v is not None:
            v = remap.get(v, v)
        kwargs[f.name] = copy.deepcopy(v)
    return cls(**kwargs)


def _scaled(shape: Any, k: float) -> Any:
    if isinstance(shape, Box):
        return Box(shape.half_width * k, shape.half_height * k,
                   (shape.center[0] * k, shape.center[1] * k), shape.angle)
    if isinstance(shape, Circle):
        return Circle(shape.radius * k, (shape.center[0] * k, shape.center[1] * k))
    if isinstance(shape, Polygon):
        return Polygon([(x * k, y * k) for x, y in shape.vertices])
    if isinstance(shape, Chain):
        return Chain([(x * k, y * k) for x, y in shape.vertices], shape.loop)
    if isinstance(shape, Edge):
        return Edge((shape.v1[0] * k, shape.v1[1] * k), (shape.v2[0] * k, shape.v2[1] * k))
    return shape
