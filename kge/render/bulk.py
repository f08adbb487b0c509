"""Write poses of many pyglet objects into their vertex buffers with numpy.

Why: pyglet's ``Sprite.update`` / ``.position`` / ``.rotation`` are Python
calls that each slice a ctypes array (about 1.3 us per sprite). With
thousands of moving bodies that is most of a frame. pyglet keeps every
vertex list of a batch inside a *domain* whose attribute buffers are plain
ctypes arrays in system memory, uploaded at draw time from a dirty range. So
kge groups its objects by domain and, each frame, writes all translations,
rotations and scales of a domain with three numpy fancy-index assignments,
then marks the written range dirty. Python work per frame is per *domain*
(per texture and layer), not per sprite.

Vertex lists do not move inside a domain unless resized or migrated; the
stores call :meth:`BulkPoser.remove` / :meth:`BulkPoser.add` around those,
which marks the domain's index arrays for a rebuild.

Culling: a member whose bounding circle is outside the view gets scale 0
(sprites) so it covers no pixel. Shapes have no scale attribute; the GPU
clips them.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from kge.render.projection import to_pyglet_degrees


@dataclass(slots=True)
class Member:
    vertex_list: Any
    row: int
    scale: tuple[float, float]  # base scale (0, 0 when hidden)
    radius: float  # bounding radius around the pivot, metres


class _Domain:
    """The members living in one pyglet vertex domain, and their index arrays.

    Members are sorted by vertex start. When every member has the same vertex
    count (4 for sprites) and they sit back to back, the domain region is a
    plain run of ``members * count`` vertices, written with one ``np.repeat``
    per attribute (or per component); otherwise a per-vertex index is used.
    When the members' pose rows are consecutive too (sprites created in
    entity order), their poses are a slice of the table, not a gathered copy.
    """

    __slots__ = (
        "block",
        "count",
        "dirty",
        "domain",
        "index",
        "members",
        "radius",
        "row_slice",
        "rows",
        "scale",
        "span",
        "vidx",
        "vmember",
    )

    def __init__(self, domain: Any) -> None:
        self.domain = domain
        self.members: dict[Any, Member] = {}
        self.index: dict[Any, int] = {}  # key -> position in the sorted arrays
        self.dirty = True
        self.rows = np.zeros(0, np.intp)
        self.row_slice: slice | None = None  # ``rows`` as a slice when consecutive
        self.scale = np.zeros((0, 2), np.float32)
        self.radius = np.zeros(0)
        self.vidx = np.zeros(0, np.intp)
        self.vmember = np.zeros(0, np.intp)
        self.block = False  # contiguous, equal counts
        self.count = 0
        self.span = (0, 0)

    def rebuild(self) -> None:
        keys = sorted(self.members, key=lambda k: self.members[k].vertex_list.start)
        self.index = {k: i for i, k in enumerate(keys)}
        ms = [self.members[k] for k in keys]
        starts = np.fromiter((m.vertex_list.start for m in ms), np.intp, len(ms))
        counts = np.fromiter((m.vertex_list.count for m in ms), np.intp, len(ms))
        self.rows = np.fromiter((m.row for m in ms), np.intp, len(ms))
        self.scale = np.array([m.scale for m in ms], np.float32).reshape(-1, 2)
        self.radius = np.fromiter((m.radius for m in ms), float, len(ms))
        self.row_slice = _as_slice(self.rows)
        self.dirty = False
        if not len(ms):
            self.span, self.block, self.vidx = (0, 0), False, np.zeros(0, np.intp)
            return
        lo, hi = int(starts[0]), int(starts[-1] + counts[-1])
        self.span = (lo, hi)
        c = int(counts[0])
        self.count = c
        self.block = bool(np.all(counts == c)) and bool(
            np.all(starts == lo + c * np.arange(len(ms)))
        )
        # general path: vertex index = start of its list + position inside it
        self.vmember = np.repeat(np.arange(len(ms)), counts)
        offs = np.arange(int(counts.sum())) - np.repeat(np.cumsum(counts) - counts, counts)
        self.vidx = np.repeat(starts, counts) + offs

    def poses(self, table: np.ndarray) -> np.ndarray:
        """The members' rows of ``table`` (a view when the rows are consecutive)."""
        return table[self.rows] if self.row_slice is None else table[self.row_slice]

    def put(self, buffer: Any, values: np.ndarray, width: int) -> None:
        """Write one value row per member into ``width`` components of every vertex.

        Values are cast to the buffer's type by the assignment itself. In a
        block, each member's row is repeated over its vertices with
        ``np.repeat`` into a contiguous temporary and copied in: numpy
        broadcasting a ``(members, 1, width)`` array over ``(members, count,
        width)`` runs an inner loop of ``width`` elements, several times slower.
        """
        lo, hi = self.span
        arr = np.ctypeslib.as_array(buffer.data).reshape(-1, buffer.count)
        values = values.reshape(-1, width)
        if not self.block:
            arr[self.vidx, :width] = values[self.vmember]
        elif width == buffer.count:  # whole vertices: one contiguous copy
            arr[lo:hi] = np.repeat(values, self.count, axis=0)
        else:  # some components of each vertex: one strided column at a time
            region = arr[lo:hi]
            for column in range(width):
                region[:, column] = np.repeat(values[:, column], self.count)
        buffer.invalidate_region(lo, hi - lo)


def _as_slice(rows: np.ndarray) -> slice | None:
    """``rows`` as ``slice(first, last + 1)`` when they are consecutive, else None."""
    if not len(rows):
        return None
    first = int(rows[0])
    if np.array_equal(rows, np.arange(first, first + len(rows))):
        return slice(first, first + len(rows))
    return None


class BulkPoser:
    """Bulk pose writer for vertex lists sharing a shader layout.

    ``translate``/``rotation``/``scale`` name the shader attributes (the sprite
    shader has a vec3 ``translate`` and a vec2 ``scale``; the shape shader a
    vec2 ``translation`` and no scale).
    """

    def __init__(
        self, translate: str, rotation: str = "rotation", scale: str | None = None
    ) -> None:
        self.translate = translate
        self.rotation = rotation
        self.scale_attr = scale
        self._domains: dict[int, _Domain] = {}
        self._where: dict[Any, _Domain] = {}

    def __len__(self) -> int:
        return len(self._where)

    def add(
        self,
        key: Any,
        vertex_list: Any,
        row: int,
        scale: tuple[float, float] = (1.0, 1.0),
        radius: float = 0.0,
    ) -> None:
        """Start moving ``vertex_list`` with pose row ``row`` (or update its scale/radius).

        Re-adding the same vertex list with the same row only patches its scale
        and radius, so restyling a sprite never rebuilds its domain's indices.
        """
        d = self._where.get(key)
        if d is not None:
            m = d.members[key]
            if m.vertex_list is vertex_list and m.row == row:
                m.scale, m.radius = scale, radius
                if not d.dirty:
                    i = d.index[key]
                    d.scale[i] = scale
                    d.radius[i] = radius
                return
        self.remove(key)
        dom = vertex_list.domain
        d = self._domains.get(id(dom))
        if d is None:
            d = self._domains[id(dom)] = _Domain(dom)
        d.members[key] = Member(vertex_list, row, scale, radius)
        d.dirty = True
        self._where[key] = d

    def remove(self, key: Any) -> None:
        d = self._where.pop(key, None)
        if d is not None:
            del d.members[key]
            d.dirty = True
            if not d.members:
                del self._domains[id(d.domain)]

    def write(
        self, poses: np.ndarray, view: tuple[float, float, float, float] | None = None
    ) -> int:
        """Write ``poses`` (rows of x, y, angle) into every domain; returns members culled.

        ``view`` = (min_x, min_y, max_x, max_y) enables culling by scale 0.
        """
        culled = 0
        if len(poses) == 0:
            return 0
        for d in self._domains.values():
            if d.dirty:
                d.rebuild()
            if not len(d.rows):
                continue
            p = d.poses(poses)
            bufs = d.domain.attrib_name_buffers
            d.put(bufs[self.translate], p[:, :2], 2)
            d.put(bufs[self.rotation], to_pyglet_degrees(p[:, 2]), 1)
            if self.scale_attr is not None:
                if view is None:
                    scale = d.scale
                else:
                    r = d.radius
                    inside = (
                        (p[:, 0] + r >= view[0])
                        & (p[:, 0] - r <= view[2])
                        & (p[:, 1] + r >= view[1])
                        & (p[:, 1] - r <= view[3])
                    )
                    scale = d.scale * inside[:, None]
                    culled += int(len(inside) - np.count_nonzero(inside))
                d.put(bufs[self.scale_attr], scale, 2)
        return culled
