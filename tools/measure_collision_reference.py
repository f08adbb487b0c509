"""Measure Box2D 2.3 (pybox2d) collision answers for kge's collision tests.

Run once with pybox2d installed (``pip install -e .[bench]``):

    .venv/bin/python tools/measure_collision_reference.py

It builds a seeded set of shapes, poses, rays, sweeps and AABB-tree scenes,
asks pybox2d for b2Distance, b2TimeOfImpact, b2Collide*, b2WorldManifold,
RayCast, TestPoint, ComputeAABB, ComputeMass, and for world.QueryAABB /
world.RayCast / fixture fat AABBs (Box2D's dynamic tree), and writes inputs
and answers to ``tests/collision/box2d_reference.json``. The tests read that
file, so they run without pybox2d. Box2D computes in float32: the tests'
tolerances (docs/collision.md) allow for it.
"""

from __future__ import annotations

import json
import math
import random
import sys
from pathlib import Path
from typing import Any

import Box2D as B

OUT = Path(__file__).resolve().parents[1] / "tests" / "collision" / "box2d_reference.json"
SEED = 2026


# ------------------------------------------------------------------------------- shapes


def random_polygon(rng: random.Random) -> list[list[float]]:
    """Convex CCW polygon (points on a circle), starting where Box2D's hull starts."""
    n = rng.randint(3, 8)
    r = rng.uniform(0.3, 1.0)
    cx, cy = rng.uniform(-0.3, 0.3), rng.uniform(-0.3, 0.3)
    while True:
        angles = sorted(rng.uniform(0, 2 * math.pi) for _ in range(n))
        gaps = [(angles[(i + 1) % n] - angles[i]) % (2 * math.pi) for i in range(n)]
        if min(gaps) > 0.25 and max(gaps) < math.pi - 0.1:
            break
    pts = [[cx + r * math.cos(a), cy + r * math.sin(a)] for a in angles]
    # Box2D's hull starts at the right-most point (lowest y on ties) and runs CCW
    start = max(range(n), key=lambda i: (pts[i][0], -pts[i][1]))
    return pts[start:] + pts[:start]


def random_shape(rng: random.Random, kind: str) -> dict[str, Any]:
    if kind == "circle":
        return {"type": "circle", "radius": rng.uniform(0.2, 1.0),
                "center": [rng.uniform(-0.3, 0.3), rng.uniform(-0.3, 0.3)]}
    if kind == "box":
        return {"type": "box", "half_width": rng.uniform(0.2, 1.2),
                "half_height": rng.uniform(0.2, 1.2),
                "center": [rng.uniform(-0.3, 0.3), rng.uniform(-0.3, 0.3)],
                "angle": rng.uniform(-math.pi, math.pi)}
    if kind == "polygon":
        return {"type": "polygon", "vertices": random_polygon(rng)}
    if kind == "edge":
        a = rng.uniform(0, 2 * math.pi)
        half = rng.uniform(0.5, 2.0)
        return {"type": "edge", "v1": [-half * math.cos(a), -half * math.sin(a)],
                "v2": [half * math.cos(a), half * math.sin(a)]}
    if kind == "chain":
        xs = [-2.0, -1.0, 0.0, 1.0, 2.0]
        return {"type": "chain", "vertices": [[x, rng.uniform(-0.6, 0.6)] for x in xs],
                "loop": False}
    assert kind == "loop"
    n = rng.randint(4, 7)
    pts = []
    for i in range(n):
        a = 2 * math.pi * i / n
        r = rng.uniform(1.0, 2.0)
        pts.append([r * math.cos(a), r * math.sin(a)])
    return {"type": "chain", "vertices": pts, "loop": True}


def b2_shape(spec: dict[str, Any]) -> Any:
    t = spec["type"]
    if t == "circle":
        return B.b2CircleShape(radius=spec["radius"], pos=tuple(spec["center"]))
    if t == "box":
        s = B.b2PolygonShape()
        s.SetAsBox(spec["half_width"], spec["half_height"], tuple(spec["center"]), spec["angle"])
        return s
    if t == "polygon":
        s = B.b2PolygonShape(vertices=[tuple(v) for v in spec["vertices"]])
        got = [tuple(v) for v in s.vertices]
        assert all(math.dist(g, w) < 1e-5 for g, w in zip(got, spec["vertices"], strict=True)), (
            "pybox2d reordered a polygon", got, spec["vertices"])
        return s
    if t == "edge":
        return B.b2EdgeShape(vertices=[tuple(spec["v1"]), tuple(spec["v2"])])
    key = "vertices_loop" if spec["loop"] else "vertices_chain"
    return B.b2ChainShape(**{key: [tuple(v) for v in spec["vertices"]]})


def child_edge(shape: Any, child: int) -> Any:
    edge = B.b2EdgeShape()
    shape._b2ChainShape__GetChildEdge(edge, child)
    return edge


def children(spec: dict[str, Any]) -> int:
    if spec["type"] != "chain":
        return 1
    n = len(spec["vertices"])
    return n if spec["loop"] else n - 1


def xf(p: list[float]) -> Any:
    t = B.b2Transform()
    t.SetIdentity()
    t.position = (p[0], p[1])
    t.angle = p[2]
    return t


def vec(v: Any) -> list[float]:
    return [float(v[0]), float(v[1])]


def random_pose(rng: random.Random, spread: float) -> list[float]:
    return [rng.uniform(-spread, spread), rng.uniform(-spread, spread),
            rng.uniform(-math.pi, math.pi)]


# ----------------------------------------------------------------------------- measures


def measure_shape_queries(rng: random.Random, shapes: list[dict[str, Any]]) -> dict[str, Any]:
    points, rays, boxes, masses = [], [], [], []
    for i, spec in enumerate(shapes):
        shape = b2_shape(spec)
        for _ in range(8):
            child = rng.randrange(children(spec))
            pose = random_pose(rng, 1.0)
            p = [pose[0] + rng.uniform(-1.5, 1.5), pose[1] + rng.uniform(-1.5, 1.5)]
            points.append({"shape": i, "child": child, "pose": pose, "p": p,
                           "inside": bool(shape.TestPoint(xf(pose), tuple(p)))})
            aabb = shape.getAABB(xf(pose), child)
            boxes.append({"shape": i, "child": child, "pose": pose,
                          "lower": vec(aabb.lowerBound), "upper": vec(aabb.upperBound)})
            p1 = [pose[0] + rng.uniform(-4, 4), pose[1] + rng.uniform(-4, 4)]
            toward = [pose[0] + rng.uniform(-0.5, 0.5), pose[1] + rng.uniform(-0.5, 0.5)]
            stretch = rng.uniform(1.2, 3.0)
            p2 = [p1[0] + stretch * (toward[0] - p1[0]), p1[1] + stretch * (toward[1] - p1[1])]
            max_fraction = rng.choice([1.0, 1.0, 0.5, 0.3])
            out = B.b2RayCastOutput()
            hit = shape.RayCast(out, B.b2RayCastInput(p1=tuple(p1), p2=tuple(p2),
                                                      maxFraction=max_fraction), xf(pose), child)
            rays.append({"shape": i, "child": child, "pose": pose, "p1": p1, "p2": p2,
                         "max_fraction": max_fraction, "hit": bool(hit),
                         "fraction": float(out.fraction) if hit else None,
                         "normal": vec(out.normal) if hit else None})
        density = rng.uniform(0.5, 3.0)
        md = shape.getMass(density) if spec["type"] != "chain" else None
        masses.append({"shape": i, "density": density,
                       "mass": float(md.mass) if md else 0.0,
                       "inertia_origin": float(md.I) if md else 0.0,
                       "center": vec(md.center) if md else [0.0, 0.0]})
    return {"test_point": points, "ray_cast": rays, "aabb": boxes, "mass": masses}


def random_pair(rng: random.Random, shapes: list[dict[str, Any]]) -> tuple[int, int, int, int]:
    """Two shape indices and a child index of each."""
    a, b = rng.randrange(len(shapes)), rng.randrange(len(shapes))
    return a, b, rng.randrange(children(shapes[a])), rng.randrange(children(shapes[b]))


def measure_distance(rng: random.Random, shapes: list[dict[str, Any]]) -> list[dict[str, Any]]:
    out = []
    for _ in range(300):
        a, b, ca, cb = random_pair(rng, shapes)
        pa, pb = random_pose(rng, 2.5), random_pose(rng, 2.5)
        use_radii = rng.random() < 0.7
        r = B.b2Distance(shapeA=b2_shape(shapes[a]), idxA=ca, shapeB=b2_shape(shapes[b]),
                         idxB=cb, transformA=xf(pa), transformB=xf(pb), useRadii=use_radii)
        out.append({"a": a, "child_a": ca, "pose_a": pa, "b": b, "child_b": cb, "pose_b": pb,
                    "use_radii": use_radii, "point_a": vec(r.pointA), "point_b": vec(r.pointB),
                    "distance": float(r.distance), "iterations": int(r.iterations)})
    return out


TOI_STATES = {0: "unknown", 1: "failed", 2: "overlapped", 3: "touching", 4: "separated"}


def random_sweep(rng: random.Random, spread: float) -> dict[str, Any]:
    lc = [rng.uniform(-0.3, 0.3), rng.uniform(-0.3, 0.3)]
    a0 = rng.uniform(-math.pi, math.pi)
    return {"local_center": lc,
            "c0": [rng.uniform(-spread, spread), rng.uniform(-spread, spread)],
            "c": [rng.uniform(-spread, spread), rng.uniform(-spread, spread)],
            "a0": a0, "a": a0 + rng.choice([0.0, rng.uniform(-1.0, 1.0)])}


def b2_sweep(s: dict[str, Any]) -> Any:
    return B.b2Sweep(localCenter=tuple(s["local_center"]), c0=tuple(s["c0"]), c=tuple(s["c"]),
                     a0=s["a0"], a=s["a"], alpha0=0.0)


def measure_toi(rng: random.Random, shapes: list[dict[str, Any]]) -> list[dict[str, Any]]:
    out = []
    for _ in range(200):
        a, b, ca, cb = random_pair(rng, shapes)
        sa, sb = random_sweep(rng, 4.0), random_sweep(rng, 4.0)
        t_max = rng.choice([1.0, 1.0, 0.7])
        state, t = B.b2TimeOfImpact(shapeA=b2_shape(shapes[a]), idxA=ca,
                                    shapeB=b2_shape(shapes[b]), idxB=cb,
                                    sweepA=b2_sweep(sa), sweepB=b2_sweep(sb), tMax=t_max)
        out.append({"a": a, "child_a": ca, "sweep_a": sa, "b": b, "child_b": cb,
                    "sweep_b": sb, "t_max": t_max, "state": TOI_STATES[state], "t": float(t)})
    return out


KINDS = {"circle": "circle", "box": "polygon", "polygon": "polygon", "edge": "edge",
         "chain": "edge"}
COLLIDERS = {
    ("circle", "circle"): B.b2CollideCircles,
    ("polygon", "circle"): B.b2CollidePolygonAndCircle,
    ("polygon", "polygon"): B.b2CollidePolygons,
    ("edge", "circle"): B.b2CollideEdgeAndCircle,
    ("edge", "polygon"): B.b2CollideEdgeAndPolygon,
}
MANIFOLD_TYPES = {0: "circles", 1: "face_a", 2: "face_b"}


def measure_manifolds(rng: random.Random, shapes: list[dict[str, Any]]) -> list[dict[str, Any]]:
    out: list[dict[str, Any]] = []
    while len(out) < 400:
        a, b = rng.randrange(len(shapes)), rng.randrange(len(shapes))
        fn = COLLIDERS.get((KINDS[shapes[a]["type"]], KINDS[shapes[b]["type"]]))
        if fn is None:
            continue
        ca, cb = rng.randrange(children(shapes[a])), rng.randrange(children(shapes[b]))
        pa = random_pose(rng, 1.0)
        pb = random_pose(rng, 1.0)
        sa, sb = b2_shape(shapes[a]), b2_shape(shapes[b])
        if shapes[a]["type"] == "chain":
            sa = child_edge(sa, ca)
        m = B.b2Manifold()
        fn(m, sa, xf(pa), sb, xf(pb))
        wm = B.b2WorldManifold()
        wm.Initialize(m, xf(pa), sa.radius, xf(pb), sb.radius)
        n = m.pointCount
        out.append({
            "a": a, "child_a": ca, "pose_a": pa, "b": b, "child_b": cb, "pose_b": pb,
            "point_count": n, "type": MANIFOLD_TYPES[m.type_] if n else None,
            "local_normal": vec(m.localNormal), "local_point": vec(m.localPoint),
            "points": [{"local_point": vec(m.points[i].localPoint), "key": m.points[i].id.key}
                       for i in range(n)],
            "normal": vec(wm.normal) if n else None,
            "world_points": [vec(wm.points[i]) for i in range(n)],
        })
    return out


def measure_overlap(rng: random.Random, shapes: list[dict[str, Any]]) -> list[dict[str, Any]]:
    out = []
    for _ in range(300):
        a, b, ca, cb = random_pair(rng, shapes)
        pa, pb = random_pose(rng, 1.5), random_pose(rng, 1.5)
        hit = B.b2TestOverlap(b2_shape(shapes[a]), ca, b2_shape(shapes[b]), cb, xf(pa), xf(pb))
        out.append({"a": a, "child_a": ca, "pose_a": pa, "b": b, "child_b": cb, "pose_b": pb,
                    "overlap": bool(hit)})
    return out


STATES = {0: "null", 1: "add", 2: "persist", 3: "remove"}


def measure_point_states(rng: random.Random, shapes: list[dict[str, Any]]
                         ) -> list[dict[str, Any]]:
    """b2GetPointStates between the manifolds of one pair at two nearby poses of B."""
    out: list[dict[str, Any]] = []
    while len(out) < 150:
        a, b = rng.randrange(len(shapes)), rng.randrange(len(shapes))
        fn = COLLIDERS.get((KINDS[shapes[a]["type"]], KINDS[shapes[b]["type"]]))
        if fn is None:
            continue
        ca = rng.randrange(children(shapes[a]))
        pa, pb1 = random_pose(rng, 0.5), random_pose(rng, 0.8)
        pb2 = [pb1[0] + rng.uniform(-0.3, 0.3), pb1[1] + rng.uniform(-0.3, 0.3),
               pb1[2] + rng.uniform(-0.5, 0.5)]
        sa, sb = b2_shape(shapes[a]), b2_shape(shapes[b])
        if shapes[a]["type"] == "chain":
            sa = child_edge(sa, ca)
        m1, m2 = B.b2Manifold(), B.b2Manifold()
        fn(m1, sa, xf(pa), sb, xf(pb1))
        fn(m2, sa, xf(pa), sb, xf(pb2))
        if not (m1.pointCount or m2.pointCount):
            continue
        s1, s2 = B.b2GetPointStates(m1, m2)
        out.append({"a": a, "child_a": ca, "pose_a": pa, "b": b, "pose_b1": pb1, "pose_b2": pb2,
                    "states1": [STATES[x] for x in s1[:m1.pointCount]],
                    "states2": [STATES[x] for x in s2[:m2.pointCount]]})
    return out


def fat_aabb(world: Any, proxy_id: int) -> Any:
    """The tree's fat AABB of a proxy (fixture.GetAABB gives the tight one).

    pybox2d does not expose proxy ids; in a world where proxies are only
    added, the tree allocates leaf, parent, leaf, parent..., so the k-th
    proxy has id 0 for k = 0 and 2k - 1 after.
    """
    return world.contactManager.broadPhase.GetFatAABB(proxy_id)


def measure_tree(rng: random.Random) -> dict[str, Any]:
    """Box2D's dynamic tree through a world: fat AABBs, QueryAABB, RayCast, moves."""
    world = B.b2World(gravity=(0, 0))
    fixtures: list[dict[str, Any]] = []
    index: dict[Any, int] = {}
    for i in range(60):
        spec = random_shape(rng, rng.choice(["circle", "box", "polygon"]))
        pose = [rng.uniform(-15, 15), rng.uniform(-15, 15), rng.uniform(-math.pi, math.pi)]
        body = world.CreateStaticBody(position=(pose[0], pose[1]), angle=pose[2])
        f = body.CreateFixture(shape=b2_shape(spec))
        index[f] = i
        fat = fat_aabb(world, 0 if i == 0 else 2 * i - 1)
        tight = f.GetAABB(0)  # the fixture's own (tight) box: the fat one is 0.1 m larger
        assert math.dist(vec(fat.lowerBound), vec(tight.lowerBound)) < 0.1415, "proxy id"
        fixtures.append({"shape": spec, "pose": pose, "fat_lower": vec(fat.lowerBound),
                         "fat_upper": vec(fat.upperBound)})

    class Query(B.b2QueryCallback):
        def __init__(self) -> None:
            super().__init__()
            self.hits: list[int] = []

        def ReportFixture(self, fixture: Any) -> bool:
            self.hits.append(index[fixture])
            return True

    queries = []
    for _ in range(40):
        cx, cy = rng.uniform(-15, 15), rng.uniform(-15, 15)
        hx, hy = rng.uniform(0.1, 4.0), rng.uniform(0.1, 4.0)
        q = Query()
        box = B.b2AABB(lowerBound=(cx - hx, cy - hy), upperBound=(cx + hx, cy + hy))
        world.QueryAABB(q, box)
        queries.append({"lower": [cx - hx, cy - hy], "upper": [cx + hx, cy + hy],
                        "hits": sorted(q.hits)})

    class Ray(B.b2RayCastCallback):
        def __init__(self, mode: str) -> None:
            super().__init__()
            self.mode = mode
            self.hits: list[dict[str, Any]] = []

        def ReportFixture(self, fixture: Any, point: Any, normal: Any, fraction: float) -> float:
            self.hits.append({"fixture": index[fixture], "point": vec(point),
                              "normal": vec(normal), "fraction": float(fraction)})
            return float(fraction) if self.mode == "closest" else 1.0

    rays = []
    for _ in range(40):
        p1 = [rng.uniform(-18, 18), rng.uniform(-18, 18)]
        p2 = [rng.uniform(-18, 18), rng.uniform(-18, 18)]
        closest, every = Ray("closest"), Ray("all")
        world.RayCast(closest, tuple(p1), tuple(p2))
        world.RayCast(every, tuple(p1), tuple(p2))
        rays.append({"p1": p1, "p2": p2, "closest": closest.hits[-1] if closest.hits else None,
                     "all": sorted(every.hits, key=lambda h: h["fixture"])})

    motions = []
    for _ in range(6):
        spec = random_shape(rng, rng.choice(["circle", "box", "polygon"]))
        w = B.b2World(gravity=(0, 0))
        body = w.CreateDynamicBody(position=(rng.uniform(-2, 2), rng.uniform(-2, 2)),
                                   angle=rng.uniform(-1, 1))
        f = body.CreateFixture(shape=b2_shape(spec), density=1.0)
        body.linearVelocity = (rng.uniform(-8, 8), rng.uniform(-8, 8))
        body.angularVelocity = rng.uniform(-3, 3)
        first = fat_aabb(w, 0)  # a live reference into the tree: copy it now
        first_lower, first_upper = vec(first.lowerBound), vec(first.upperBound)
        start = [body.position[0], body.position[1], body.angle]
        steps = []
        for _ in range(12):
            before = [body.position[0], body.position[1], body.angle]
            w.Step(1 / 60, 8, 3)
            after = [body.position[0], body.position[1], body.angle]
            fat = fat_aabb(w, 0)
            steps.append({"pose_before": before, "pose_after": after,
                          "fat_lower": vec(fat.lowerBound), "fat_upper": vec(fat.upperBound)})
        motions.append({"shape": spec, "start_pose": start,
                        "start_fat_lower": first_lower, "start_fat_upper": first_upper,
                        "steps": steps})
    return {"fixtures": fixtures, "queries": queries, "rays": rays, "motions": motions}


def _rounded(value: Any) -> Any:
    """Floats to 9 significant digits (Box2D's float32 holds about 7): a smaller file."""
    if isinstance(value, float):
        return float(f"{value:.9g}")
    if isinstance(value, list):
        return [_rounded(v) for v in value]
    if isinstance(value, dict):
        return {k: _rounded(v) for k, v in value.items()}
    return value


def main() -> int:
    rng = random.Random(SEED)
    kinds = ["circle"] * 5 + ["box"] * 6 + ["polygon"] * 6 + ["edge"] * 4 + ["chain"] * 3 + [
        "loop"] * 2
    shapes = [random_shape(rng, k) for k in kinds]
    data: dict[str, Any] = {
        "about": "Box2D 2.3 collision answers measured with pybox2d by "
                 "tools/measure_collision_reference.py; inputs are float64, Box2D used float32",
        "pybox2d": B.__version__,
        "seed": SEED,
        "shapes": shapes,
    }
    data.update(measure_shape_queries(rng, shapes))
    data["distance"] = measure_distance(rng, shapes)
    data["toi"] = measure_toi(rng, shapes)
    data["manifold"] = measure_manifolds(rng, shapes)
    data["tree"] = measure_tree(rng)
    data["overlap"] = measure_overlap(rng, shapes)
    data["point_states"] = measure_point_states(rng, shapes)
    OUT.write_text(json.dumps(_rounded(data), separators=(",", ":")) + "\n")
    print(f"wrote {OUT} ({OUT.stat().st_size // 1024} KiB)", file=sys.stderr)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
