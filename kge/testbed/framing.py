"""Frame a sample: fit the camera to what the sample built, beside the testbed's text.

Each sample gets its own camera: the world AABB of what it built is fitted into the
part of the window the sample list and the help text leave free. The view follows the
action: when a sample has moving bodies, static geometry counts only where it lies
near them (the floor and the lower walls of a 40 m box holding a pile, not the empty
top of the box), and static colliders much larger than the rest (a 200 m floor) are
left out. A sample with no collider (sprites, shape drawables: the animation samples)
is fitted to those instead.
"""

from __future__ import annotations

import math

import numpy as np

from kge.components.camera import Camera
from kge.components.collider import Collider
from kge.components.drawables import DRAWABLE_TYPES
from kge.components.rigidbody import BodyType, RigidBody
from kge.components.shapes import Circle
from kge.components.sprite import Sprite
from kge.components.transform import Transform
from kge.render.geometry import circle_points, shape_polyline
from kge.testbed.registry import Sample
from kge.world import World

Rect = tuple[float, float, float, float]  # left, bottom, right, top

#: a static collider wider or taller than this is "the ground", left out of the fit
HUGE = 80.0


def collider_bounds(world: World, entity: int, col: Collider) -> Rect | None:
    """The world AABB of one collider (at its body's current pose), or None."""
    body = col.body if col.body is not None else entity
    t = world.try_get(body, Transform)
    if t is None:
        return None
    shape = col.shape
    if isinstance(shape, Circle):
        cx, cy = shape.center
        pts = circle_points(shape.radius, 16, (float(cx), float(cy)))
    else:
        pts, _ = shape_polyline(shape)
    c, s = math.cos(t.angle), math.sin(t.angle)
    w = np.asarray(pts, float) @ np.array([[c, s], [-s, c]]) + (t.x, t.y)
    lo, hi = w.min(axis=0), w.max(axis=0)
    return (float(lo[0]), float(lo[1]), float(hi[0]), float(hi[1]))


def scene_bounds(world: World) -> Rect | None:
    """The AABB of what moves and the static geometry near it (see the module docstring)."""
    moving: list[Rect] = []
    still: list[Rect] = []
    huge: list[Rect] = []
    for entity, (col,) in world.query(Collider):
        r = collider_bounds(world, entity, col)
        if r is None:
            continue
        body = col.body if col.body is not None else entity
        rb = world.try_get(body, RigidBody)
        if rb is not None and rb.type is not BodyType.STATIC:
            moving.append(r)
        elif r[2] - r[0] > HUGE or r[3] - r[1] > HUGE:
            huge.append(r)
        else:
            still.append(r)
    if moving:
        near = _grow(_union(moving), 0.25, 2.0)
        clipped = [c for c in (_clip(r, near) for r in still + huge) if c is not None]
        return _union(moving + clipped)
    rects = still or huge or _drawn_bounds(world)
    return _union(rects) if rects else None


def _union(rects: list[Rect]) -> Rect:
    a = np.array(rects)
    return (float(a[:, 0].min()), float(a[:, 1].min()), float(a[:, 2].max()), float(a[:, 3].max()))


def _grow(r: Rect, fraction: float, least: float) -> Rect:
    """``r`` grown on every side by ``fraction`` of its size, and at least ``least``."""
    dx = max((r[2] - r[0]) * fraction, least)
    dy = max((r[3] - r[1]) * fraction, least)
    return (r[0] - dx, r[1] - dy, r[2] + dx, r[3] + dy)


def _clip(r: Rect, to: Rect) -> Rect | None:
    """The part of ``r`` inside ``to``, or None when they do not overlap."""
    out = (max(r[0], to[0]), max(r[1], to[1]), min(r[2], to[2]), min(r[3], to[3]))
    return out if out[0] <= out[2] and out[1] <= out[3] else None


def _drawn_bounds(world: World) -> list[Rect]:
    """Rough AABBs of sprites (their size, else 1 m) and drawables (their local points)."""
    out: list[Rect] = []
    for _, (t, sp) in world.query(Transform, Sprite):
        w, h = sp.size if sp.size is not None else (1.0, 1.0)
        r = math.hypot(w, h) / 2
        out.append((t.x - r, t.y - r, t.x + r, t.y + r))
    for dtype in DRAWABLE_TYPES:
        found: list[tuple[int, tuple[Transform, object]]] = world.query(Transform, dtype)
        for _, (tf, drawn) in found:
            reach = _reach(drawn)
            out.append((tf.x - reach, tf.y - reach, tf.x + reach, tf.y + reach))
    return out


def _reach(d: object) -> float:
    """How far a drawable reaches from its entity's origin (metres)."""
    pts = [getattr(d, name) for name in ("start", "end", "a", "b", "c") if hasattr(d, name)]
    pts += list(getattr(d, "vertices", ()))
    reach = max((math.hypot(*p) for p in pts), default=0.0)
    for name in ("radius", "width", "height"):
        reach = max(reach, float(getattr(d, name, 0.0)))
    ox, oy = getattr(d, "offset", (0.0, 0.0))
    return reach + math.hypot(ox, oy)


def fit_camera(bounds: Rect, size: tuple[int, int], free: Rect, margin: float = 0.08) -> Camera:
    """A camera showing ``bounds`` (metres) inside ``free`` (window pixels: left, bottom,
    right, top), with ``margin`` of the free area left around it."""
    bw = max(bounds[2] - bounds[0], 1.0)
    bh = max(bounds[3] - bounds[1], 1.0)
    fw, fh = (free[2] - free[0]) * (1 - 2 * margin), (free[3] - free[1]) * (1 - 2 * margin)
    scale = min(fw / bw, fh / bh)
    # the bounds' centre goes to the free area's centre
    fcx, fcy = (free[0] + free[2]) / 2, (free[1] + free[3]) / 2
    bcx, bcy = (bounds[0] + bounds[2]) / 2, (bounds[1] + bounds[3]) / 2
    cx = bcx - (fcx - size[0] / 2) / scale
    cy = bcy - (fcy - size[1] / 2) / scale
    # the scale goes into pixels_per_meter: zoom is clamped to [0.1, 10], too narrow
    # for an 80 m box in a 400-pixel tile
    return Camera(center=(cx, cy), pixels_per_meter=scale)


#: the window width the explicit ``camera=`` zooms of samples were chosen for
REFERENCE_WIDTH = 960.0


def sample_camera(world: World, sample: Sample, size: tuple[int, int], free: Rect) -> Camera:
    """The camera a sample is shown through: its own ``camera=`` if it has one, else a
    fit of what it built into ``free``; following ``sample.follow`` when it names one."""
    if sample.camera is not None:
        cx, cy, zoom = sample.camera
        cam = Camera(center=(cx, cy), zoom=zoom * size[0] / REFERENCE_WIDTH)
    else:
        bounds = scene_bounds(world) or (-10.0, -1.0, 10.0, 19.0)
        cam = fit_camera(bounds, size, free)
    if sample.follow is not None:
        from kge.testbed.samples.build import named

        found = named(world, sample.follow)
        if found:
            cam.follow = found[0]
    return cam
