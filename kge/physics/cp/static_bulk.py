"""Chain segments built and added to a space in one tight loop each.

Why: a tile map's cave outlines are some 176,000 segments. Through pymunk's
public path each segment costs about 15 us (``Segment.__init__`` with its
property writes through pymunk's ``__setattr__`` mixin, ``set_neighbors``,
the ``friction`` property, then ``Space.add`` with four asserts that each
re-read weak references), 2.7 s for the map before kge does anything. This
module makes the *same* objects, real :class:`pymunk.Segment` instances with
their Chipmunk shape, GC finaliser and user-data handle set exactly as
pymunk's own ``Shape._init`` sets them, with the per-segment work reduced to
the Chipmunk calls themselves: tiny coordinates checked with numpy and the
neighbours found by list slicing once per chain, shared attribute dicts and
weak references, and the space checks done once per body instead of once per
shape. The callers pause Python's cyclic collector around the bulk work
(:mod:`kge.gcpause`).

Everything else (queries, contact callbacks, removal, pickling, garbage
collection) sees ordinary pymunk shapes. Tied to pymunk 7.3's ``Shape``
layout (``_shape``, ``_body``, ``_h``, ``_space``), which pyproject pins;
``tests/physics/test_static_bulk.py`` checks the shapes behave like
pymunk-built ones, so a pymunk upgrade that changes the layout fails there.
"""

from __future__ import annotations

import weakref
from collections.abc import Sequence
from typing import Any

import numpy as np
import pymunk
from pymunk._util import _dead_ref

from kge.physics.cp.capi import ffi, lib
from kge.physics.tiny import TINY, flush

#: up to this many vertices a chain's tiny coordinates are looked for without numpy
_FEW_POINTS = 32


def _shape_free(cp_shape: Any) -> None:
    """pymunk's own finaliser for a shape (``Shape._init``): leave the space, then free."""
    cp_space = lib.cpShapeGetSpace(cp_shape)
    if cp_space != ffi.NULL:
        lib.cpSpaceRemoveShape(cp_space, cp_shape)
    lib.cpShapeFree(cp_shape)


def chain_ends(vertices: Sequence[tuple[float, float]], loop: bool) -> tuple[list[Any], ...]:
    """(A, B, P, N): each segment's ends and its outer neighbours, tiny coordinates flushed.

    Neighbours follow Box2D's chain: a loop's ends wrap, an open chain's end
    segments have themselves as the outer neighbour (no ghost vertex).
    """
    pts = list(vertices)
    if len(pts) > _FEW_POINTS:
        arr = np.asarray(pts, dtype=np.float64).reshape(-1, 2)
        if np.any((np.abs(arr) < TINY) & (arr != 0.0)):  # see kge.physics.tiny
            pts = np.where(np.abs(arr) < TINY, 0.0, arr).tolist()
    elif any(-TINY < v < TINY and v != 0.0 for p in pts for v in p):
        pts = [(flush(x), flush(y)) for x, y in pts]
    # by list slicing: Chipmunk takes the points as they are
    if loop:
        return pts, pts[1:] + pts[:1], pts[-1:] + pts[:-1], pts[2:] + pts[:2]
    return pts[:-1], pts[1:], pts[:1] + pts[:-2], pts[2:] + pts[-1:]


def chain_segments(
    body: pymunk.Body,
    vertices: Sequence[tuple[float, float]],
    loop: bool,
    radius: float,
    friction: float,
    shape_filter: pymunk.ShapeFilter | None = None,
    sensor: bool = False,
) -> list[pymunk.Segment]:
    """The segments of one chain on ``body``, in chain order, neighbours set, not yet
    in a space (kge's data about them lives in :mod:`kge.physics.shape_table`).

    ``shape_filter`` (None: pymunk's default) and ``sensor`` are set on each.
    Neighbours: see :func:`chain_ends`.
    """
    A, B, P, N = chain_ends(vertices, loop)
    new_segment = lib.cpSegmentShapeNew
    set_neighbors = lib.cpSegmentShapeSetNeighbors
    set_friction = lib.cpShapeSetFriction
    set_user_data = lib.cpShapeSetUserData
    set_filter = lib.cpShapeSetFilter
    set_sensor = lib.cpShapeSetSensor
    gc = ffi.gc
    new_handle = ffi.new_handle
    make = object.__new__
    cls = pymunk.Segment
    cp_body = body._body
    body_ref = weakref.ref(body)
    body_shapes = body._shapes
    out: list[pymunk.Segment] = []
    append = out.append
    for i in range(len(A)):
        seg = make(cls)
        d = seg.__dict__
        d["_body"] = body_ref
        c = new_segment(cp_body, A[i], B[i], radius)
        d["_shape"] = gc(c, _shape_free)
        h = d["_h"] = new_handle(seg)  # keeps the handle alive as long as the shape
        set_user_data(c, h)
        set_neighbors(c, P[i], N[i])
        if friction:
            set_friction(c, friction)
        if shape_filter is not None:
            set_filter(c, shape_filter)
        if sensor:
            set_sensor(c, True)
        body_shapes[seg] = None
        append(seg)
    return out


def reinit_segments(
    segments: Sequence[pymunk.Segment],
    body: pymunk.Body,
    ends: tuple[Sequence[Any], ...],
    radius: float,
    friction: float,
    shape_filter: pymunk.ShapeFilter | None = None,
    sensor: bool = False,
) -> None:
    """Make ``segments`` (out of any space) new segments of ``body`` in place.

    ``ends`` is (A, B) or (A, B, P, N) as :func:`chain_ends` gives them, one row
    per segment (P, N: the neighbours; without them none are set, as for an
    edge). Each Chipmunk shape is initialised again by ``cpSegmentShapeInit``,
    the call ``cpSegmentShapeNew`` makes after allocating: every Chipmunk field
    (normal, mass info, tangents, material, filter, type, sensor flag) is what
    a new segment of these ends has, and the same calls as
    :func:`chain_segments` then set its user data, neighbours and material. The
    Python objects and their attributes stay. Why not ``cpSegmentShapeSetEndpoints``:
    it computes the normal with the opposite sign of ``cpSegmentShapeInit`` (pymunk 7.3).

    Why at all: a new outline of the same topology (terrain rebuilt on a reset)
    reuses its segments instead of allocating new ones. The shape's hashid is
    not Chipmunk's to reset; the space gives it a new one when it is added again.
    """
    A, B = ends[0], ends[1]
    if len(A) != len(segments):
        raise ValueError(f"{len(segments)} segments, {len(A)} pairs of ends")
    in_space = lib.cpShapeGetSpace
    null = ffi.NULL
    cp_body = body._body
    for seg in segments:
        # re-initialising a shape Chipmunk indexes would corrupt the space
        if seg.__dict__["_body"]() is not body or in_space(seg._shape) != null:
            raise ValueError("reinit_segments: a segment is in a space or on another body")
    init = lib.cpSegmentShapeInit
    cast = ffi.cast
    set_user_data = lib.cpShapeSetUserData
    cps = [seg._shape for seg in segments]
    for c, seg, a, b in zip(cps, segments, A, B, strict=True):
        init(cast("cpSegmentShape *", c), cp_body, a, b, radius)
        set_user_data(c, seg._h)
    if len(ends) == 4:
        set_neighbors = lib.cpSegmentShapeSetNeighbors
        for c, p, n in zip(cps, ends[2], ends[3], strict=True):
            set_neighbors(c, p, n)
    if friction:
        set_friction = lib.cpShapeSetFriction
        for c in cps:
            set_friction(c, friction)
    if shape_filter is not None:
        set_filter = lib.cpShapeSetFilter
        pf = ffi.new("cpShapeFilter *", shape_filter)[0]  # converted once
        for c in cps:
            set_filter(c, pf)
    if sensor:
        set_sensor = lib.cpShapeSetSensor
        for c in cps:
            set_sensor(c, True)


def add_shapes(space: pymunk.Space, shapes: Sequence[pymunk.Shape]) -> None:
    """``space.add(*shapes)`` for shapes only, with pymunk's checks once per body.

    Same result and order as ``space.add``: each shape joins Chipmunk's index
    and ``space.shapes``. A locked space (inside a step) defers like
    ``space.add``. A shape already in a space (or listed twice), or whose
    body is not in this one, is refused with pymunk's message and the shapes
    added before it are taken out again.
    """
    if space._locked:  # (even one shape is faster here than through space.add)
        space.add(*shapes)
        return
    known = space._shapes
    bodies: set[int] = set()  # ids of bodies seen to be in this space
    space_ref = weakref.ref(space)
    cp_space = space._space
    add = lib.cpSpaceAddShape
    done = 0
    try:
        for s in shapes:
            body = s._body()
            if id(body) not in bodies:
                if body is None:
                    raise AssertionError("The shape's body is not set.")
                if body.space is not space:
                    raise AssertionError(
                        "The shape's body must be added to the space before "
                        "(or at the same time) as the shape."
                    )
                bodies.add(id(body))
            d = s.__dict__
            if s in known or ("_space" in d and d["_space"]() is not None):
                raise AssertionError("Shape already added to a space.")
            d["_space"] = space_ref
            known[s] = None
            add(cp_space, s._shape)
            done += 1
    except BaseException:
        space.remove(*shapes[:done])  # nothing half-added
        raise


def remove_shapes(space: pymunk.Space, shapes: Sequence[pymunk.Shape]) -> None:
    """``space.remove`` of those of ``shapes`` that are in ``space``, without pymunk's
    per-shape dispatch, asserts and attribute hooks (a replaced outline's segments).

    Same calls, order and bookkeeping as pymunk's ``Space._remove_shape``: each
    shape is kept alive until the next step, its space reference cleared,
    Chipmunk removes it (ending its contacts, with separate callbacks, and
    waking what touched it) and it leaves ``space.shapes``. Removals a separate
    callback asked for run afterwards, as ``space.remove`` runs them. A locked
    space (inside a step) defers like ``space.remove``.
    """
    if space._locked:
        space.remove(*[s for s in shapes if s.space is space])
        return
    known = space._shapes
    kept = space._removed_shapes
    cp_space = space._space
    contains = lib.cpSpaceContainsShape
    remove = lib.cpSpaceRemoveShape
    for s in shapes:
        if s not in known:
            continue
        kept[s] = None
        s.__dict__["_space"] = _dead_ref
        cp_shape = s._shape
        if contains(cp_space, cp_shape):
            remove(cp_space, cp_shape)
        del known[s]
    if space._remove_later:
        space.remove()  # what the separate callbacks asked to remove
