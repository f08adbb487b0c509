"""Physics debug view: collider outlines, joints, AABBs, centres of mass, contacts.

It draws from pure components (``Collider`` shapes, joint components,
``RigidBody`` state) and the contact events (``world.events``), never from pymunk,
so it shows what the game *asked for*, and works before physics runs.

Retained, like Box2D's recommended renderers: each collider's outline is
built once in its body's frame and moved each frame by the bulk poser; only
its colour is rewritten when the body changes state (asleep, disabled...).
Joint lines, AABBs and contact markers change shape every frame, so their
vertex lists are kept and only their positions rewritten.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np
from pyglet import gl

from kge.components import joints as _joints
from kge.components.collider import Collider
from kge.components.debug import DebugDraw
from kge.components.rigidbody import BodyType, RigidBody
from kge.components.transform import Transform
from kge.physics.events import ContactBegin
from kge.render import geometry
from kge.render.groups import OVERLAY_LAYER, WORLD, Groups
from kge.render.meshes import MeshStore
from kge.render.poses import PoseTable

JOINT_TYPES: tuple[type, ...] = tuple(getattr(_joints, n) for n in _joints.__all__ if n != "Joint")

_LINES = gl.GL_LINES
_NO_POSE = (0.0, 0.0, 0.0)


def _rot(a: float) -> tuple[float, float]:
    return math.cos(a), math.sin(a)


def _to_world(pose: Any, p: tuple[float, float]) -> tuple[float, float]:
    c, s = _rot(pose[2])
    return (pose[0] + c * p[0] - s * p[1], pose[1] + s * p[0] + c * p[1])


def _to_local(pose: Any, p: tuple[float, float]) -> tuple[float, float]:
    c, s = _rot(pose[2])
    dx, dy = p[0] - pose[0], p[1] - pose[1]
    return (c * dx + s * dy, -s * dx + c * dy)


def _fill_color(outline: tuple[int, ...]) -> tuple[int, int, int, int]:
    """The translucent fill under an outline of that colour (Box2D v3 samples' look)."""
    r, g, b = outline[:3]
    return (r // 2, g // 2, b // 2, int(outline[3] * 0.5) if len(outline) > 3 else 128)


class DebugDrawer:
    """Keeps the debug meshes of one world in step with its physics components."""

    def __init__(self, world: Any, batch: Any, groups: Groups, poses: PoseTable) -> None:
        self.world = world
        self.meshes = MeshStore(batch, poses)
        self.poses = poses
        self.parent = groups.get(OVERLAY_LAYER, WORLD, 0)
        self.fill_parent = groups.get(OVERLAY_LAYER, WORLD, -1)  # fills under outlines
        self._shape_of: dict[int, Any] = {}  # collider entity -> (shape, pose entity)
        self._color_of: dict[Any, tuple[int, ...]] = {}
        # (joint, field) -> (world point, local anchor): world anchors resolved at first
        # sight, as physics does when it builds the joint (Box2D's Initialize)
        self._resolved: dict[tuple[int, str], tuple[Any, tuple[float, float]]] = {}
        self._contacts: list[tuple[float, tuple[float, float], tuple[float, float]]] = []
        self._contact_cap = 0
        self.contacts_drawn = 0

    # -- inputs from the fixed step ----------------------------------------------------
    def record_contacts(self, now: float) -> None:
        """Keep this step's new contact points (events last one step; markers linger for
        ``contact_seconds``). Nothing is kept while contact markers are not drawn."""
        settings = self.world.try_resource(DebugDraw)
        if settings is None or not (settings.enabled and settings.contacts):
            self._contacts.clear()
            return
        keep = now - settings.contact_seconds
        if self._contacts and self._contacts[0][0] < keep:
            self._contacts = [c for c in self._contacts if c[0] >= keep]
        for c in self.world.events(ContactBegin):  # this step's (the recorder runs last)
            for p in c.points:
                self._contacts.append((now, tuple(p), tuple(c.normal)))

    # -- per frame ----------------------------------------------------------------------------
    def sync(self, settings: DebugDraw) -> None:
        """Structural pass, before poses are blended: outlines appear, vanish, recolour."""
        if not settings.enabled:
            self.clear()
            return
        self._colliders(settings)
        self._centers(settings)

    def update(self, settings: DebugDraw, poses: np.ndarray, now: float) -> None:
        """Per-frame pass with the blended poses: joints, AABBs and contact markers."""
        if not settings.enabled:
            return
        self._joints(settings, poses)
        self._aabbs(settings, poses)
        self._contact_markers(settings, now)

    def _pose_entity(self, entity: int, col: Any) -> int:
        return col.body if getattr(col, "body", None) is not None else entity

    def _transform(self, entity: int) -> Any:
        return self.world.try_get(entity, Transform)

    def _body_color(self, settings: DebugDraw, body: int) -> tuple[int, int, int, int]:
        rb = self.world.try_get(body, RigidBody)
        if rb is None:
            return settings.static_color
        return settings.color_for(
            static=rb.type is BodyType.STATIC,
            kinematic=rb.type is BodyType.KINEMATIC,
            awake=bool(rb.awake),
            enabled=bool(rb.enabled),
        )

    def _colliders(self, settings: DebugDraw) -> None:
        if not settings.shapes:
            for key in [k for k in self.meshes.lists if k[0] in ("shape", "fill")]:
                self.meshes.remove(key)
            self._shape_of.clear()
            return
        seen = set()
        for entity, (col,) in self.world.query(Collider):
            seen.add(entity)
            body = self._pose_entity(entity, col)
            key = ("shape", entity)
            color = self._body_color(settings, body)
            fill_key = ("fill", entity)
            fill_color = _fill_color(color)
            if self._shape_of.get(entity) != (col.shape, body):
                self._shape_of[entity] = (col.shape, body)
                tris = geometry.shape_fill(col.shape)
                if tris is None:
                    self.meshes.remove(fill_key)
                else:
                    self.meshes.put(
                        fill_key, body, self._transform(body), tris, fill_color, self.fill_parent
                    )
                    self._color_of[fill_key] = fill_color
                self.meshes.put(
                    key,
                    body,
                    self._transform(body),
                    geometry.shape_outline(col.shape),
                    color,
                    self.parent,
                    _LINES,
                )
                self._color_of[key] = color
            elif self._color_of.get(key) != color:
                self.meshes.recolor(key, color)
                if fill_key in self.meshes.lists:
                    self.meshes.recolor(fill_key, fill_color)
                    self._color_of[fill_key] = fill_color
                self._color_of[key] = color
        for entity in [e for e in self._shape_of if e not in seen]:
            del self._shape_of[entity]
            for kind in ("shape", "fill"):
                self.meshes.remove((kind, entity))
                self._color_of.pop((kind, entity), None)

    def _pose_of(self, entity: int | None, poses: np.ndarray) -> tuple[float, float, float]:
        if entity is None:
            return _NO_POSE
        row = self.poses.row_of.get(entity)
        if row is not None and row < len(poses):
            x, y, a = poses[row]
            return (float(x), float(y), float(a))
        t = self._transform(entity)
        return _NO_POSE if t is None else (t.x, t.y, t.angle)

    def _local(self, joint: int, name: str, world: Any, pose: Any) -> tuple[float, float]:
        """Local anchor for a world point, frozen when first seen (re-resolved if changed)."""
        got = self._resolved.get((joint, name))
        if got is None or got[0] != world:
            got = (world, _to_local(pose, (float(world[0]), float(world[1]))))
            self._resolved[(joint, name)] = got
        return got[1]

    def _joint_points(self, entity: int, j: Any, poses: np.ndarray) -> list[tuple[float, float]]:
        """Segment end points for one joint, as Box2D's DrawJoint lays them out."""
        pa = self._pose_of(getattr(j, "body_a", None), poses)
        pb = self._pose_of(getattr(j, "body_b", None), poses)
        kind = type(j).__name__
        if kind == "MouseJoint":
            target = (float(j.target[0]), float(j.target[1]))
            lb = j.local_anchor_b
            if lb is None:  # Box2D anchors a mouse joint where the target was at creation
                lb = self._first_target(entity, target, pb)
            return [target, _to_world(pb, lb)]
        la = self._anchor(entity, j, "a", pa)
        lb = self._anchor(entity, j, "b", pb)
        xa, xb = _to_world(pa, la), _to_world(pb, lb)
        if kind == "PulleyJoint":
            ga = (float(j.ground_anchor_a[0]), float(j.ground_anchor_a[1]))
            gb = (float(j.ground_anchor_b[0]), float(j.ground_anchor_b[1]))
            return [ga, xa, gb, xb, ga, gb]
        if kind in ("DistanceJoint", "RopeJoint"):
            return [xa, xb]
        return [(pa[0], pa[1]), xa, xa, xb, (pb[0], pb[1]), xb]

    def _first_target(self, entity: int, target: Any, pose: Any) -> tuple[float, float]:
        got = self._resolved.get((entity, "target"))
        if got is None:
            got = (target, _to_local(pose, target))
            self._resolved[(entity, "target")] = got
        return got[1]

    def _anchor(self, entity: int, j: Any, side: str, pose: Any) -> tuple[float, float]:
        for name in (f"anchor_{side}", "anchor"):
            world = getattr(j, name, None)
            if world is not None:
                return self._local(entity, name + side, world, pose)
        local = getattr(j, f"local_anchor_{side}", None) or (0.0, 0.0)
        return (float(local[0]), float(local[1]))

    def _joints(self, settings: DebugDraw, poses: np.ndarray) -> None:
        live = set()
        if settings.joints:
            for jt in JOINT_TYPES:
                for entity, (j,) in self.world.query(jt):
                    if not hasattr(j, "body_a"):
                        continue
                    pts = np.asarray(self._joint_points(entity, j, poses), np.float32)
                    key = ("joint", entity)
                    live.add(key)
                    vl = self.meshes.lists.get(key)
                    if vl is None or vl.count != len(pts):
                        vl = self.meshes.put(
                            key,
                            entity,
                            None,
                            pts,
                            settings.joint_color,
                            self.parent,
                            _LINES,
                            posed=False,
                        )
                    else:
                        vl.position[:] = pts.ravel().tolist()
        for key in [k for k in self.meshes.lists if k[0] == "joint" and k not in live]:
            self.meshes.remove(key)
        alive = {k[1] for k in live}
        for rk in [rk for rk in self._resolved if rk[0] not in alive]:
            del self._resolved[rk]

    def _aabbs(self, settings: DebugDraw, poses: np.ndarray) -> None:
        live = set()
        if settings.aabbs:
            for entity, (shape, body) in self._shape_of.items():
                pose = self._pose_of(body, poses)
                pts, _ = geometry.shape_polyline(shape)
                if type(shape).__name__ == "Circle":
                    c = _to_world(pose, tuple(getattr(shape, "center", (0.0, 0.0))))
                    r = shape.radius
                    lo, hi = (c[0] - r, c[1] - r), (c[0] + r, c[1] + r)
                else:
                    cs, sn = _rot(pose[2])
                    w = pts @ np.array([[cs, sn], [-sn, cs]]) + (pose[0], pose[1])
                    lo, hi = tuple(w.min(axis=0)), tuple(w.max(axis=0))
                box = geometry.segments(
                    [(lo[0], lo[1]), (hi[0], lo[1]), (hi[0], hi[1]), (lo[0], hi[1])], closed=True
                ).astype(np.float32)
                key = ("aabb", entity)
                live.add(key)
                vl = self.meshes.lists.get(key)
                if vl is None:
                    self.meshes.put(
                        key,
                        entity,
                        None,
                        box,
                        settings.aabb_color,
                        self.parent,
                        _LINES,
                        posed=False,
                    )
                else:
                    vl.position[:] = box.ravel().tolist()
        for key in [k for k in self.meshes.lists if k[0] == "aabb" and k not in live]:
            self.meshes.remove(key)

    def _mass_center(self, body: int) -> tuple[float, float]:
        from kge.physics.resource import Physics

        phys = self.world.try_resource(Physics)
        if phys is None or not hasattr(phys, "mass_data"):
            return (0.0, 0.0)
        try:
            md = phys.mass_data(body)
        except Exception:  # a body physics has not built yet
            return (0.0, 0.0)
        c = getattr(md, "center", None) or getattr(md, "local_center", None) or (0.0, 0.0)
        return (float(c[0]), float(c[1]))

    def _centers(self, settings: DebugDraw) -> None:
        live = set()
        if settings.centers_of_mass:
            for body, _ in self.world.query(RigidBody):
                for axis, color in ((0, (230, 76, 76, 255)), (1, (76, 230, 76, 255))):
                    key = ("com", body, axis)
                    live.add(key)
                    if key not in self.meshes.lists:
                        cx, cy = self._mass_center(body)
                        tip = (cx + 0.4, cy) if axis == 0 else (cx, cy + 0.4)
                        self.meshes.put(
                            key,
                            body,
                            self._transform(body),
                            np.array([(cx, cy), tip], np.float32),
                            color,
                            self.parent,
                            _LINES,
                        )
        for key in [k for k in self.meshes.lists if k[0] == "com" and k not in live]:
            self.meshes.remove(key)

    def _contact_markers(self, settings: DebugDraw, now: float) -> None:
        keep = now - settings.contact_seconds
        self._contacts = [c for c in self._contacts if c[0] >= keep]
        key = ("contacts",)
        if not settings.contacts or not self._contacts:
            self.meshes.remove(key)
            self._contact_cap = 0
            self.contacts_drawn = 0
            return
        s = 0.06  # marker half size, metres
        seg: list[tuple[float, float]] = []
        colors: list[tuple[int, int, int, int]] = []
        for _, (x, y), (nx, ny) in self._contacts:
            square = [(x - s, y - s), (x + s, y - s), (x + s, y + s), (x - s, y + s)]
            for i in range(4):
                seg += [square[i], square[(i + 1) % 4]]
            colors += [settings.contact_color] * 8
            if settings.contact_normals:
                seg += [(x, y), (x + 0.3 * nx, y + 0.3 * ny)]
                colors += [settings.normal_color] * 2
        n = len(seg)
        if n > self._contact_cap:
            self._contact_cap = max(64, 1 << (n - 1).bit_length())
            self.meshes.put(
                key,
                -1,
                None,
                np.zeros((self._contact_cap, 2), np.float32),
                (0, 0, 0, 0),
                self.parent,
                _LINES,
                posed=False,
            )
        vl = self.meshes.lists[key]
        pos = np.zeros((self._contact_cap, 2), np.float32)
        pos[:n] = seg
        col = np.zeros((self._contact_cap, 4), np.uint8)
        col[:n] = colors
        vl.position[:] = pos.ravel().tolist()
        vl.colors[:] = col.ravel().tolist()
        self.contacts_drawn = len(self._contacts)

    def clear(self) -> None:
        self.meshes.clear()
        self._shape_of.clear()
        self._color_of.clear()
        self._contact_cap = 0
