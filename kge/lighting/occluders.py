"""Which colliders block light, as world-space edges.

Static colliders do not move, so their edges are gathered once and kept until a
collider or body is added or removed (the plugin's hooks set ``dirty``).
Entities marked :class:`~kge.components.lights.ShadowCaster` are gathered every
frame at their current pose, so their shadows move with them.

Boxes and polygons contribute their counter-clockwise outline (``closed``),
circles a 16-sided one, edges and chains their segments (two-sided).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import Any

import numpy as np

from kge.components.collider import Collider
from kge.components.lights import ShadowCaster
from kge.components.rigidbody import BodyType, RigidBody
from kge.components.shapes import Box, Chain, Circle, Edge, Polygon
from kge.components.transform import Transform

Pose = tuple[float, float, float]
CIRCLE_SIDES = 16
_RING = np.stack(
    [np.cos(np.arange(CIRCLE_SIDES) * 2 * np.pi / CIRCLE_SIDES),
     np.sin(np.arange(CIRCLE_SIDES) * 2 * np.pi / CIRCLE_SIDES)], axis=1
)  # fmt: skip


def shape_outline(shape: Any) -> tuple[np.ndarray, bool]:
    """Body-local edges (k, 2, 2) of a collider shape and whether they close a CCW outline."""
    if isinstance(shape, Circle):
        pts = np.asarray(shape.center) + shape.radius * _RING
    elif isinstance(shape, Box):
        pts = np.asarray(shape.vertices(), float)
    elif isinstance(shape, Polygon):
        pts = np.asarray(shape.vertices, float)
    elif isinstance(shape, Edge):
        return np.array([[shape.v1, shape.v2]], float), False
    elif isinstance(shape, Chain):
        return np.asarray(shape.segments(), float), False
    else:  # pragma: no cover - every shape type is handled
        return np.zeros((0, 2, 2)), False
    return np.stack([pts, np.roll(pts, -1, axis=0)], axis=1), True


def _place(edges: np.ndarray, pose: Pose) -> np.ndarray:
    x, y, a = pose
    c, s = math.cos(a), math.sin(a)
    out = np.empty_like(edges)
    out[..., 0] = x + c * edges[..., 0] - s * edges[..., 1]
    out[..., 1] = y + s * edges[..., 0] + c * edges[..., 1]
    return out


class Occluders:
    """Collects occluder edges from a world (cached for static ones)."""

    def __init__(self) -> None:
        self.dirty = True
        self._static = (np.zeros((0, 2, 2)), np.zeros(0, bool))
        #: body-local outlines by shape (shapes are frozen values: equal shapes share one)
        self._outlines: dict[Any, tuple[np.ndarray, np.ndarray]] = {}

    def _outline(self, shape: Any) -> tuple[np.ndarray, np.ndarray]:
        """The shape's local edges and a per-edge ``closed`` flag, cached."""
        found = self._outlines.get(shape)
        if found is None:
            if len(self._outlines) > 4096:  # many distinct shapes: keep the cache bounded
                self._outlines.clear()
            edges, closed = shape_outline(shape)
            found = self._outlines[shape] = (edges, np.full(len(edges), closed))
        return found

    def _body_of(self, entity: int, col: Collider) -> int:
        return entity if col.body is None else col.body

    def _static_edges(self, world: Any) -> tuple[np.ndarray, np.ndarray]:
        if self.dirty:
            parts, flags = [], []
            for e, (col,) in world.query(Collider):
                body = self._body_of(e, col)
                rb = world.try_get(body, RigidBody)
                if col.sensor or (rb is not None and rb.type is not BodyType.STATIC):
                    continue
                if world.try_get(e, ShadowCaster) or world.try_get(body, ShadowCaster):
                    continue  # gathered with the casters (it may be switched off)
                t = world.try_get(body, Transform)
                pose = (0.0, 0.0, 0.0) if t is None else (t.x, t.y, t.angle)
                edges, closed = shape_outline(col.shape)
                parts.append(_place(edges, pose))
                flags.append(np.full(len(edges), closed))
            self._static = _joined(parts, flags)
            self.dirty = False
        return self._static

    def edges(
        self, world: Any, static: bool, pose_of: Callable[[int], Pose | None] | None = None
    ) -> tuple[np.ndarray, np.ndarray]:
        """All occluder edges (E, 2, 2) and their ``closed`` flags (E,).

        ``pose_of(entity)`` may give a caster's drawn (interpolated) pose; the
        Transform is used otherwise.
        """
        parts, flags = [], []
        if static:
            static_edges, static_closed = self._static_edges(world)
            parts.append(static_edges)
            flags.append(static_closed)
        casters = {e for e, (sc,) in world.query(ShadowCaster) if sc.enabled}
        if casters:
            local, closed_flags, owners, poses = [], [], [], []
            for e, (col,) in world.query(Collider):
                body = self._body_of(e, col)
                if col.sensor or (e not in casters and body not in casters):
                    continue
                pose = pose_of(body) if pose_of is not None else None
                if pose is None:
                    t = world.try_get(body, Transform)
                    pose = (0.0, 0.0, 0.0) if t is None else (t.x, t.y, t.angle)
                edges, closed = self._outline(col.shape)
                local.append(edges)
                closed_flags.append(closed)
                owners.append(len(edges))
                poses.append(pose)
            if local:  # every caster placed at its pose in one numpy pass
                p = np.repeat(np.asarray(poses, float), owners, axis=0)[:, None, :]
                e = np.concatenate(local)
                c, s = np.cos(p[..., 2]), np.sin(p[..., 2])
                placed = np.empty_like(e)
                placed[..., 0] = p[..., 0] + c * e[..., 0] - s * e[..., 1]
                placed[..., 1] = p[..., 1] + s * e[..., 0] + c * e[..., 1]
                parts.append(placed)
                flags.append(np.concatenate(closed_flags))
        return _joined(parts, flags)


def _joined(parts: list[np.ndarray], flags: list[np.ndarray]) -> tuple[np.ndarray, np.ndarray]:
    if not parts:
        return np.zeros((0, 2, 2)), np.zeros(0, bool)
    return np.concatenate(parts), np.concatenate(flags)
