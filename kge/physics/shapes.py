"""Building pymunk shapes from a :class:`~kge.components.collider.Collider`.

Every pymunk shape kge builds is registered in the space's
:class:`~kge.physics.shape_table.ShapeTable` (collider and body entity, chain
child index, filter, material, hit threshold, Box2D's side-A rank), so queries
and contact callbacks map it back to entities by its slot; nothing of kge's is
stored on the pymunk object.

Material: pymunk multiplies the two shapes' friction, so each shape gets
``sqrt(friction)`` and the pair gets sqrt(a)*sqrt(b) = sqrt(a*b), Box2D's mixing,
with no callback. Elasticity stays 0; restitution is set once per new contact
(see :mod:`kge.physics.contacts`). Density stays 0 in pymunk: kge computes the
mass itself (:mod:`kge.physics.mass`).
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import Any, cast

import pymunk

from kge.components.collider import Collider
from kge.components.shapes import Box, Chain, Circle, Edge, Polygon, Shape
from kge.physics.cp.static_bulk import chain_ends, chain_segments, reinit_segments
from kge.physics.filtering import DEFAULT_FILTER, to_pymunk
from kge.physics.shape_table import ShapeTable
from kge.physics.tiny import flush_point, flush_points


def build_shapes(
    body: pymunk.Body,
    collider: Collider,
    collider_entity: int,
    body_entity: int | None,
    skin: float,
    table: ShapeTable,
) -> list[pymunk.Shape]:
    """The pymunk shapes of one collider (several for a chain), not yet in a space,
    registered in ``table``."""
    shapes = _build(body, collider, skin)
    table.add_collider(shapes, collider, collider_entity, body_entity)
    return shapes


def _build(body: pymunk.Body, collider: Collider, skin: float) -> list[pymunk.Shape]:
    geom = collider.shape
    friction = math.sqrt(collider.friction)
    pf = to_pymunk(collider.filter)
    # coordinates below 1e-100 m are zero to Chipmunk (see kge.physics.tiny)
    if isinstance(geom, Chain):
        # one tight loop: a tile map's outlines are 100,000s of segments
        return list(
            chain_segments(
                body,
                geom.vertices,
                geom.loop,
                skin,
                friction,
                None if pf == DEFAULT_FILTER else pf,
                collider.sensor,
            )
        )
    if isinstance(geom, Circle):
        shape: pymunk.Shape = pymunk.Circle(body, geom.radius, flush_point(geom.center))
    elif isinstance(geom, Box):
        shape = pymunk.Poly(body, flush_points(geom.vertices()), radius=skin)
    elif isinstance(geom, Polygon):
        shape = pymunk.Poly(body, flush_points(geom.vertices), radius=skin)
    else:
        shape = pymunk.Segment(body, flush_point(geom.v1), flush_point(geom.v2), skin)
        if geom.vertex0 is not None or geom.vertex3 is not None:
            shape.set_neighbors(*edge_neighbors(geom))
    # what apply_material does, minus the writes a fresh shape does not need
    # (elasticity is already 0, the filter and sensor flag are pymunk's defaults)
    shape.friction = friction
    if pf != DEFAULT_FILTER:
        shape.filter = pf
    if collider.sensor:
        shape.sensor = True
    return [shape]


def edge_neighbors(edge: Edge) -> tuple[tuple[float, float], tuple[float, float]]:
    """Chipmunk's neighbours of a lone edge: its ghost vertices, or its own ends
    where it has none (which Chipmunk reads as "no neighbour", as for a chain's ends)."""
    prev = edge.vertex0 if edge.vertex0 is not None else edge.v1
    nxt = edge.vertex3 if edge.vertex3 is not None else edge.v2
    return flush_point(prev), flush_point(nxt)


def same_segments(old: object, new: Shape) -> bool:
    """Whether ``new`` is built of as many segments, joined the same way, as ``old``:
    an edge and an edge, or chains of as many vertices both open or both loops.

    Then :func:`rebuild_in_place` can give the shapes built for ``old`` the
    geometry of ``new``.
    """
    if type(old) is Edge:
        return type(new) is Edge
    return (
        type(old) is Chain
        and type(new) is Chain
        and old.loop == new.loop
        and len(old.vertices) == len(new.vertices)
    )


def rebuild_in_place(
    shapes: list[pymunk.Shape],
    body: pymunk.Body,
    collider: Collider,
    collider_entity: int,
    body_entity: int | None,
    skin: float,
    table: ShapeTable,
) -> None:
    """Turn ``shapes`` (out of any space; built for a shape of which
    ``collider.shape`` is :func:`same_segments`) into what :func:`build_shapes`
    would build for ``collider`` now, keeping the Python objects.

    Chipmunk's fields are initialised as for a new segment
    (:func:`~kge.physics.cp.static_bulk.reinit_segments`) and their rows of
    ``table`` written again (same slots), so nothing of the old geometry or
    material survives.
    """
    geom = collider.shape
    pf = to_pymunk(collider.filter)
    ends: tuple[Sequence[Any], ...]
    if isinstance(geom, Chain):
        ends = chain_ends(geom.vertices, geom.loop)
    elif isinstance(geom, Edge):
        prev, nxt = edge_neighbors(geom)
        ends = ([flush_point(geom.v1)], [flush_point(geom.v2)], [prev], [nxt])
    else:
        raise TypeError(f"rebuild_in_place: {type(geom).__name__} is not made of segments")
    segments = cast(list[pymunk.Segment], shapes)
    reinit_segments(
        segments,
        body,
        ends,
        skin,
        math.sqrt(collider.friction),
        None if pf == DEFAULT_FILTER else pf,
        collider.sensor,
    )
    table.add_collider(segments, collider, collider_entity, body_entity)


def apply_material(shape: pymunk.Shape, collider: Collider, table: ShapeTable) -> None:
    """Copy the collider's material, filter and flags onto an existing shape (and its row)."""
    shape.friction = math.sqrt(collider.friction)
    shape.elasticity = 0.0
    table.set_material(shape, collider)
    if shape.filter != (pf := to_pymunk(collider.filter)):
        shape.filter = pf
    if shape.sensor != collider.sensor:
        shape.sensor = collider.sensor


def spread(shapes: list[pymunk.Shape]) -> list[pymunk.Shape]:
    """The same shapes in an order that keeps Chipmunk's static tree balanced.

    Chipmunk's bounding-box tree degenerates when many neighbouring boxes are
    inserted in spatial order: adding a 20,000-segment chain in chain order took
    10.6 s, in a scattered order 0.23 s (pymunk 7.3). The order is a fixed
    stride permutation, so it is the same on every run (determinism).

    >>> spread(list(range(10)))
    [0, 7, 4, 1, 8, 5, 2, 9, 6, 3]
    """
    n = len(shapes)
    stride = _coprime_stride(n)
    return [shapes[(i * stride) % n] for i in range(n)]


def _coprime_stride(n: int) -> int:
    """A stride near n * 0.618 that visits every index of range(n) once."""
    s = max(1, int(n * 0.6180339887))
    while math.gcd(s, n) != 1:
        s += 1
    return s
