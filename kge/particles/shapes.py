"""Where particles are born: sampling an emission shape in the emitter's frame.

Every sampler takes the emitter's numpy ``Generator`` and a count and returns
``(n, 2)`` local offsets, so a burst of 1,000 particles is a handful of
vectorised draws. :class:`~kge.components.particles.EmitCollider` samples the
entity's physics shape: discs and polygons by area (a triangle fan picked by
area, then uniform barycentric coordinates), edges and chains by length.

>>> import numpy as np
>>> from kge.components.particles import EmitBox
>>> pts = sample_shape(EmitBox(2.0, 1.0), np.random.default_rng(1), 1000, None)
>>> bool(np.all(np.abs(pts[:, 0]) <= 1.0) and np.all(np.abs(pts[:, 1]) <= 0.5))
True
"""

from __future__ import annotations

from typing import Any

import numpy as np

from kge.components import shapes as physics_shapes
from kge.components.particles import (
    EmitBox,
    EmitCircle,
    EmitCollider,
    EmitLine,
    EmitPoint,
    EmitShape,
)


def _disc(rng: np.random.Generator, n: int, radius: float, edge: bool) -> np.ndarray:
    theta = rng.uniform(0.0, 2.0 * np.pi, n)
    r = np.full(n, radius) if edge else radius * np.sqrt(rng.random(n))
    return np.stack([r * np.cos(theta), r * np.sin(theta)], axis=1)


def _segments(rng: np.random.Generator, n: int, segs: np.ndarray) -> np.ndarray:
    """Uniform along segments (m, 2, 2), weighted by length."""
    d = segs[:, 1] - segs[:, 0]
    length = np.hypot(d[:, 0], d[:, 1])
    pick = (
        rng.choice(len(segs), n, p=length / length.sum()) if len(segs) > 1 else np.zeros(n, np.intp)
    )
    u = rng.random(n)[:, None]
    return segs[pick, 0] + d[pick] * u


def _polygon(rng: np.random.Generator, n: int, verts: np.ndarray) -> np.ndarray:
    """Uniform inside a convex polygon (k, 2): fan triangles by area, then barycentric."""
    a = verts[0]
    b, c = verts[1:-1], verts[2:]
    area = np.abs((b[:, 0] - a[0]) * (c[:, 1] - a[1]) - (b[:, 1] - a[1]) * (c[:, 0] - a[0]))
    pick = rng.choice(len(b), n, p=area / area.sum()) if len(b) > 1 else np.zeros(n, np.intp)
    u, v = rng.random(n), rng.random(n)
    flip = u + v > 1.0
    u[flip], v[flip] = 1.0 - u[flip], 1.0 - v[flip]
    return a + (b[pick] - a) * u[:, None] + (c[pick] - a) * v[:, None]


def _collider(rng: np.random.Generator, n: int, shape: Any) -> np.ndarray:
    if isinstance(shape, physics_shapes.Circle):
        return _disc(rng, n, shape.radius, False) + np.asarray(shape.center)
    if isinstance(shape, physics_shapes.Box):
        return _polygon(rng, n, np.asarray(shape.vertices(), float))
    if isinstance(shape, physics_shapes.Polygon):
        return _polygon(rng, n, np.asarray(shape.vertices, float))
    if isinstance(shape, physics_shapes.Edge):
        return _segments(rng, n, np.asarray([[shape.v1, shape.v2]], float))
    if isinstance(shape, physics_shapes.Chain):
        return _segments(rng, n, np.asarray(shape.segments(), float))
    return np.zeros((n, 2))


def sample_shape(shape: EmitShape, rng: np.random.Generator, n: int, collider: Any) -> np.ndarray:
    """``n`` birth offsets (entity frame) inside ``shape``; ``collider`` is the entity's shape."""
    if isinstance(shape, EmitPoint) or n == 0:
        return np.zeros((n, 2))
    if isinstance(shape, EmitCircle):
        return _disc(rng, n, shape.radius, shape.edge)
    if isinstance(shape, EmitBox):
        return (rng.random((n, 2)) - 0.5) * np.array([shape.width, shape.height])
    if isinstance(shape, EmitLine):
        return _segments(rng, n, np.array([[shape.start, shape.end]], float))
    if isinstance(shape, EmitCollider):
        return _collider(rng, n, collider) if collider is not None else np.zeros((n, 2))
    raise TypeError(f"unknown emission shape {shape!r}")  # pragma: no cover - validated
