"""kge.collision query throughput beside pybox2d and beside brute force, in one run.

Rows (queries per second, median over interleaved blocks, so background load hits
every variant alike):

* ``distance``: :func:`kge.collision.distance` on a fixed set of polygon / box /
  circle pairs, beside pybox2d's ``b2Distance`` on the same pairs (when pybox2d is
  installed). pybox2d's C++ is compiled; kge's GJK is Python, so the ratio says
  what a Python collision query costs, not that it wins;
* ``collide``: :func:`kge.collision.collide` on overlapping polygon pairs beside
  ``b2CollidePolygons``;
* ``tree query``: :class:`kge.collision.DynamicTree` answering box queries over
  N boxes, beside a brute-force scan of the same boxes (numpy, vectorised over
  all boxes per query) and a pure-Python scan; the tree's answer must contain
  the scan's (checked), so the speed is for the same question.

Run ``python -m benchmarks.collision`` for the table alone.
"""

from __future__ import annotations

import math
import random
import statistics
import time
from collections.abc import Callable
from typing import Any

import numpy as np

from benchmarks.engines import box2d_available
from kge import collision
from kge.components.shapes import Box, Circle, Polygon

Variant = Callable[[], int]


def _rate(variants: dict[str, Variant], blocks: int) -> dict[str, float]:
    """Queries per second of each variant: median over interleaved blocks."""
    samples: dict[str, list[float]] = {name: [] for name in variants}
    for _ in range(blocks):
        for name, run in variants.items():
            t0 = time.perf_counter()
            n = run()
            samples[name].append(n / (time.perf_counter() - t0))
    return {name: statistics.median(s) for name, s in samples.items()}


def _pairs(n: int, spread: float) -> list[tuple[Any, tuple[float, float, float], Any,
                                                tuple[float, float, float]]]:
    rng = random.Random(5)
    shapes = [Box(0.5, 0.3), Circle(0.4),
              Polygon([(0.6, 0.0), (0.2, 0.5), (-0.4, 0.3), (-0.4, -0.3), (0.2, -0.5)])]
    out = []
    for _ in range(n):
        a, b = rng.choice(shapes[::2]), rng.choice(shapes)
        pa = (rng.uniform(-spread, spread), rng.uniform(-spread, spread), rng.uniform(-3, 3))
        pb = (rng.uniform(-spread, spread), rng.uniform(-spread, spread), rng.uniform(-3, 3))
        out.append((a, pa, b, pb))
    return out


def _b2(shape: Any) -> Any:
    import Box2D as b2

    if isinstance(shape, Circle):
        return b2.b2CircleShape(radius=shape.radius, pos=shape.center)
    verts = shape.vertices() if isinstance(shape, Box) else shape.vertices
    return b2.b2PolygonShape(vertices=list(verts))


def _b2_transform(p: tuple[float, float, float]) -> Any:
    import Box2D as b2

    t = b2.b2Transform()
    t.SetIdentity()
    t.position = (p[0], p[1])
    t.angle = p[2]
    return t


def distance_row(n: int, blocks: int) -> dict[str, Any]:
    pairs = _pairs(n, 2.0)

    def kge_run() -> int:
        for a, pa, b, pb in pairs:
            collision.distance(a, pa, b, pb)
        return len(pairs)

    variants: dict[str, Variant] = {"kge": kge_run}
    if box2d_available() is None:
        import Box2D as b2

        cache: dict[int, Any] = {}
        native = [(cache.setdefault(id(a), _b2(a)), _b2_transform(pa),
                   cache.setdefault(id(b), _b2(b)), _b2_transform(pb)) for a, pa, b, pb in pairs]

        def box2d_run() -> int:
            for a, ta, b, tb in native:
                b2.b2Distance(shapeA=a, shapeB=b, transformA=ta, transformB=tb, useRadii=True)
            return len(native)

        variants["pybox2d"] = box2d_run
    return {"row": "distance", "size": n, "unit": "pairs", **_rate(variants, blocks)}


def collide_row(n: int, blocks: int) -> dict[str, Any]:
    polys = [p for p in _pairs(4 * n, 0.5) if not isinstance(p[2], Circle)][:n]

    def kge_run() -> int:
        for a, pa, b, pb in polys:
            collision.collide(a, pa, b, pb)
        return len(polys)

    variants: dict[str, Variant] = {"kge": kge_run}
    if box2d_available() is None:
        import Box2D as b2

        native = [(_b2(a), _b2_transform(pa), _b2(b), _b2_transform(pb))
                  for a, pa, b, pb in polys]
        manifold = b2.b2Manifold()

        def box2d_run() -> int:
            for a, ta, b, tb in native:
                b2.b2CollidePolygons(manifold, a, ta, b, tb)
            return len(native)

        variants["pybox2d"] = box2d_run
    return {"row": "collide", "size": len(polys), "unit": "pairs", **_rate(variants, blocks)}


def tree_row(n: int, queries: int, blocks: int) -> dict[str, Any]:
    rng = random.Random(9)
    side = 4.0 * math.sqrt(n)  # about one box per 16 m^2
    boxes = []
    for _ in range(n):
        x, y = rng.uniform(0, side), rng.uniform(0, side)
        boxes.append(((x, y), (x + rng.uniform(0.2, 1.5), y + rng.uniform(0.2, 1.5))))
    tree = collision.DynamicTree()
    for i, b in enumerate(boxes):
        tree.insert(b, i)
    arr = np.array([[lo[0], lo[1], hi[0], hi[1]] for lo, hi in boxes])
    qs = []
    for _ in range(queries):
        x, y = rng.uniform(0, side), rng.uniform(0, side)
        qs.append(((x, y), (x + 3.0, y + 3.0)))

    def numpy_scan(q: tuple[tuple[float, float], tuple[float, float]]) -> np.ndarray:
        (qx0, qy0), (qx1, qy1) = q
        hit = (arr[:, 0] <= qx1) & (arr[:, 1] <= qy1) & (arr[:, 2] >= qx0) & (arr[:, 3] >= qy0)
        return np.flatnonzero(hit)

    for q in qs[:20]:  # same question: the tree's (fat) answer contains the exact one
        assert set(numpy_scan(q).tolist()) <= {tree.user_data(p) for p in tree.query(q)}

    def tree_run() -> int:
        for q in qs:
            tree.query(q)
        return len(qs)

    def numpy_run() -> int:
        for q in qs:
            numpy_scan(q)
        return len(qs)

    def python_run() -> int:
        for (qx0, qy0), (qx1, qy1) in qs:
            [i for i, ((x0, y0), (x1, y1)) in enumerate(boxes)
             if x0 <= qx1 and y0 <= qy1 and x1 >= qx0 and y1 >= qy0]
        return len(qs)

    rates = _rate({"kge": tree_run, "numpy scan": numpy_run, "python scan": python_run}, blocks)
    return {"row": "tree query", "size": n, "unit": "boxes", **rates}


def measure(quick: bool = False) -> list[dict[str, Any]]:
    """All rows; ``quick`` uses small sizes and few blocks (for tests)."""
    blocks = 2 if quick else 15
    pairs = 50 if quick else 400
    rows = [distance_row(pairs, blocks), collide_row(pairs, blocks)]
    for n in ((200,) if quick else (1000, 10000)):
        rows.append(tree_row(n, 20 if quick else 200, blocks))
    return rows


COLUMNS = ("kge", "pybox2d", "numpy scan", "python scan")


def table(rows: list[dict[str, Any]]) -> str:
    """Queries per second per variant, and kge's ratio to each (above 1 = kge faster)."""
    head = f"{'query':<12}{'size':>7}" + "".join(f"{c:>14}" for c in COLUMNS) + "  kge ratio"
    lines = [head]
    for r in rows:
        cells = "".join(f"{r[c]:>14,.0f}" if c in r else f"{'-':>14}" for c in COLUMNS)
        ratios = ", ".join(f"{r['kge'] / r[c]:.2g}x {c}" for c in COLUMNS[1:] if c in r)
        lines.append(f"{r['row']:<12}{r['size']:>7}{cells}  {ratios}")
    return "\n".join(lines)


def markdown(rows: list[dict[str, Any]]) -> list[str]:
    out = ["", "kge.collision, queries per second (median of interleaved blocks; ratio = kge "
           "÷ other, above 1 means kge is faster):", "",
           "| query | size | " + " | ".join(COLUMNS) + " | kge ratio |",
           "|---|---:|" + "---:|" * len(COLUMNS) + "---|"]
    for r in rows:
        cells = " | ".join(f"{r[c]:,.0f}" if c in r else "-" for c in COLUMNS)
        ratios = ", ".join(f"{r['kge'] / r[c]:.2g}× {c}" for c in COLUMNS[1:] if c in r)
        out.append(f"| {r['row']} | {r['size']} {r['unit']} | {cells} | {ratios} |")
    return out


if __name__ == "__main__":
    print(table(measure()))
