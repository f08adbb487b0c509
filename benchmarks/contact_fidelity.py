"""Box2D fidelity of contacts and sleep: velocity writes, landings, jointed islands.

Measures, on kge alone (imports nothing but kge, so the same file measures any
checkout: ``PYTHONPATH=path/to/kge python benchmarks/contact_fidelity.py``):

* **walk**: a body whose ``RigidBody.velocity`` (or an impulse to that velocity) is
  written every step, walking into a wall: a static box 3 m thick, an edge, a chain
  of either winding, a dynamic box pressed against a static wall and a free dynamic
  box. Speeds 1-60 m/s, a box and a circle; every substep count 1-8 against the
  static box wall (the other walls at 1, 2, 4 and 8).
* **land**: a box or circle landing on the ground at 0.2-50 m/s, 1-8 substeps.
* **sleep**: the step at which bodies held by each joint type, starting at rest,
  fall asleep (pybox2d 2.3.10 on the same scenes: 30 steps, the wheel 113).

Depth is the overlap of the two outlines with their skins (Box2D's polygon radius,
0.01 m on polygons, edges and chains; circles have none), measured from the poses
after each step: what a pre-solve hook, a renderer or a query sees. Box2D holds a
velocity written every step at its linear slop, 0.005 m.

``python benchmarks/contact_fidelity.py --out benchmarks/results/contact-fidelity-after.json``
(and, with a checkout before a change on ``PYTHONPATH``, ``...-before.json``);
``python benchmarks/contact_fidelity.py --markdown BEFORE.json AFTER.json`` prints the
tables of ``benchmarks/results/contact-fidelity.md``.
"""

from __future__ import annotations

import argparse
import json
import math
import sys
from collections.abc import Callable
from typing import Any

from kge.components import joints
from kge.components.collider import Collider
from kge.components.rigidbody import BodyType, RigidBody
from kge.components.shapes import Box, Chain, Circle, Edge
from kge.components.transform import Transform
from kge.physics.resource import Physics
from kge.physics.settings import PhysicsSettings
from kge.schedule import Stage
from kge.systems.physics import PhysicsSystem
from kge.world import World

DT = 1.0 / 60.0
SKIN = 0.01
FACE = 5.0  # x of the wall's face the walker meets
SPEEDS = (1.0, 3.0, 6.0, 12.0, 30.0, 60.0)
SUBSTEPS = (1, 2, 4, 8)
#: against the static box wall and on landings: every substep count
ALL_SUBSTEPS = tuple(range(1, 9))
WALLS = ("box", "edge", "chain-ccw", "chain-cw", "pressed-box", "free-box")
LANDINGS = (0.2, 0.5, 1.0, 2.0, 3.0, 5.0, 10.0, 20.0, 50.0)


class _Sim:
    def __init__(self, substeps: int) -> None:
        self.world = World()
        self.world.insert_resource(PhysicsSettings(substeps=substeps))
        self.world.add_system(PhysicsSystem())
        self.physics = self.world.resource(Physics)

    def step(self) -> None:
        self.world.clear_events()
        self.world.schedule.run(Stage.FIXED, DT)

    def ground(self) -> None:
        self.world.spawn(Transform(0.0, -10.0), Collider(Box(50.0, 10.0)))

    def close(self) -> None:
        self.world.close()


def _half(mover: str) -> tuple[Any, float]:
    """(shape, half width with skin) of the walker."""
    if mover == "box":
        return Box(0.5, 0.5), 0.5 + SKIN
    return Circle(0.5), 0.5


def walk(speed: float, substeps: int, wall: str = "box", mover: str = "box",
         mode: str = "velocity", seconds: float = 1.0) -> dict[str, float]:
    """A walker driven at ``speed`` into ``wall``: the deepest overlap over the run,
    the deepest over its last half second, and whether it ended past the face."""
    sim = _Sim(substeps)
    sim.ground()
    w = sim.world
    block = None
    if wall == "box":
        w.spawn(Transform(FACE + 1.5, 5.0), Collider(Box(1.5, 5.0)))
    elif wall == "edge":
        w.spawn(Transform(), Collider(Edge((FACE, 0.0), (FACE, 10.0))))
    elif wall == "chain-ccw":
        w.spawn(Transform(), Collider(Chain([(FACE, 0.0), (FACE, 10.0)])))
    elif wall == "chain-cw":
        w.spawn(Transform(), Collider(Chain([(FACE, 10.0), (FACE, 0.0)])))
    elif wall in ("pressed-box", "free-box"):
        # a dynamic crate (half 0.5, 1 kg): against a static wall, or free on the ground
        block = w.spawn(Transform(FACE + 0.5 + SKIN, 0.5 + 2 * SKIN - 0.005),
                        RigidBody(type=BodyType.DYNAMIC), Collider(Box(0.5, 0.5), density=1.0))
        if wall == "pressed-box":
            # touching the crate at the slop
            w.spawn(Transform(FACE + 1.0 + SKIN - 0.005 + 1.5, 5.0), Collider(Box(1.5, 5.0)))
    shape, half = _half(mover)
    rest = 0.5 + (2 * SKIN - 0.005 if mover == "box" else SKIN - 0.005)
    start = FACE - half - SKIN - 0.5  # half a metre from the face
    e = w.spawn(Transform(start, rest), RigidBody(type=BodyType.DYNAMIC, fixed_rotation=True),
                Collider(shape, density=1.0, friction=0.2))
    steps = round(seconds / DT) + math.ceil(0.5 / speed / DT)
    depths: list[float] = []
    past = False
    for _ in range(steps):
        rb = w.get(e, RigidBody)
        if mode == "velocity":
            rb.velocity = (speed, rb.velocity[1])
        else:
            vx = rb.velocity[0]
            sim.physics.apply_linear_impulse(e, (sim.physics.mass_data(e).mass * (speed - vx), 0.0))
        sim.step()
        x = w.get(e, Transform).x
        if block is None:
            face = FACE - SKIN
        else:
            face = w.get(block, Transform).x - 0.5 - SKIN
        depths.append(x + half - face)
        past = past or x > face + SKIN  # its centre beyond the face it meets
    sim.close()
    tail = depths[-30:]
    return {"max": max(depths), "steady": max(tail), "tunnelled": float(past)}


def land(speed: float, substeps: int, mover: str = "box", steps: int = 90) -> dict[str, float]:
    """A body thrown straight down at ``speed`` onto the ground from 5 cm above it:
    the deepest overlap after any step and the overlap it rests at."""
    sim = _Sim(substeps)
    sim.ground()
    shape, _ = _half(mover)
    skin = 2 * SKIN if mover == "box" else SKIN
    e = sim.world.spawn(Transform(0.0, 0.5 + skin + 0.05),
                        RigidBody(type=BodyType.DYNAMIC, velocity=(0.0, -speed)),
                        Collider(shape, density=1.0))
    depths = []
    for _ in range(steps):
        sim.step()
        depths.append(0.5 + skin - sim.world.get(e, Transform).y)
    sim.close()
    return {"max": max(depths), "rest": depths[-1]}


def _jointed(w: World, kind: str) -> list[int]:
    """One joint holding a body or two where they rest; returns the bodies."""
    def body(shape: Any, x: float, y: float, friction: float = 0.2) -> int:
        return w.spawn(Transform(x, y), RigidBody(type=BodyType.DYNAMIC),
                       Collider(shape, friction=friction))

    if kind in ("distance", "revolute", "rope"):
        b = body(Circle(0.25), 0.0, 7.0)
        if kind == "distance":
            w.spawn(joints.DistanceJoint(None, b, anchor_a=(0.0, 10.0), anchor_b=(0.0, 7.0)))
        elif kind == "revolute":
            w.spawn(joints.RevoluteJoint(None, b, anchor=(0.0, 10.0)))
        else:
            w.spawn(joints.RopeJoint(None, b, anchor_a=(0.0, 10.0), anchor_b=(0.0, 7.0),
                              max_length=3.0))
        return [b]
    if kind == "prismatic":
        b = body(Box(0.5, 0.5), 0.0, 0.515)
        w.spawn(joints.PrismaticJoint(None, b, anchor=(0.0, 0.515), local_axis_a=(1.0, 0.0)))
        return [b]
    if kind == "pulley":
        a, b = body(Box(0.5, 0.5), -2.0, 5.0), body(Box(0.5, 0.5), 2.0, 5.0)
        w.spawn(joints.PulleyJoint(a, b, ground_anchor_a=(-2.0, 10.0), ground_anchor_b=(2.0, 10.0),
                            anchor_a=(-2.0, 5.5), anchor_b=(2.0, 5.5)))
        return [a, b]
    if kind == "weld":
        a, b = body(Box(0.5, 0.5), 0.0, 0.515), body(Box(0.5, 0.5), 1.0, 0.515)
        w.spawn(joints.WeldJoint(a, b, anchor=(0.5, 0.515)))
        return [a, b]
    car, wheel = body(Box(1.0, 0.25), 0.0, 1.2), body(Circle(0.4), 0.0, 0.41, friction=0.9)
    w.spawn(joints.WheelJoint(car, wheel, anchor=(0.0, 0.41), local_axis_a=(0.0, 1.0)))
    return [car, wheel]


def sleep(kind: str, limit: int = 600) -> dict[str, float]:
    """The step at which the bodies of one joint ``kind`` fall asleep (-1: never)."""
    sim = _Sim(4)
    sim.ground()
    bodies = _jointed(sim.world, kind)
    at = -1
    for k in range(1, limit + 1):
        sim.step()
        if not any(sim.world.get(e, RigidBody).awake for e in bodies):
            at = k
            break
    sim.close()
    return {"asleep_step": float(at)}


def _table(fn: Callable[..., dict[str, float]], rows: list[dict[str, Any]]) -> list[dict[str, Any]]:
    out = []
    for kw in rows:
        got = fn(**kw)
        out.append({**kw, **{k: round(v, 4) for k, v in got.items()}})
        print(json.dumps(out[-1]), file=sys.stderr, flush=True)
    return out


def measure(quick: bool = False) -> dict[str, Any]:
    speeds = (6.0, 60.0) if quick else SPEEDS
    subs = (1, 4) if quick else SUBSTEPS
    every = (1, 4) if quick else ALL_SUBSTEPS
    walls = ("box", "edge") if quick else WALLS
    walks = [dict(speed=v, substeps=n, wall=wl, mover=m, mode=mode)
             for wl in walls for m in ("box", "circle") for mode in ("velocity", "impulse")
             for v in speeds for n in (every if wl == "box" else subs)
             if mode == "velocity" or (wl == "box" and m == "box")]
    lands = [dict(speed=v, substeps=n, mover=m) for m in ("box", "circle")
             for v in (LANDINGS[:3] if quick else LANDINGS) for n in every]
    kinds = ("distance", "revolute", "prismatic", "pulley", "weld", "wheel", "rope")
    sleeps = [dict(kind=k) for k in kinds]
    return {
        "walk": _table(walk, walks), "land": _table(land, lands), "sleep": _table(sleep, sleeps)
    }


def _mm(row: dict[str, Any] | None, key: str = "max") -> str:
    """A depth in mm (in m from a metre on), T when the walker's centre passed the face."""
    if row is None:
        return "-"
    d = row[key]
    text = f"{d:.2f} m" if d >= 1.0 else f"{d * 1000:.1f}"
    return text + (" T" if row.get("tunnelled") else "")


def _grid(before: list[dict[str, Any]], after: list[dict[str, Any]], cell: Callable[..., str],
          first: str, **match: Any) -> list[str]:
    """One before → after table: a row per speed, a column per substep count."""
    def pick(rows: list[dict[str, Any]]) -> dict[tuple[float, int], dict[str, Any]]:
        return {(r["speed"], r["substeps"]): r for r in rows
                if all(r.get(k) == v for k, v in match.items())}

    b, a = pick(before), pick(after)
    speeds = sorted({v for v, _ in a})
    subs = sorted({n for _, n in a})
    head = [f"{n} substep{'s' if n > 1 else ''} before → after" for n in subs]
    lines = [f"| {first} | " + " | ".join(head) + " |",
             "|---:|" + "---:|" * len(subs)]
    for v in speeds:
        cells = [f"{cell(b.get((v, n)))} → {cell(a.get((v, n)))}" for n in subs]
        lines.append(f"| {v:g} | " + " | ".join(cells) + " |")
    return lines


def markdown(before: dict[str, Any], after: dict[str, Any]) -> str:
    """The before → after tables of ``benchmarks/results/contact-fidelity.md``."""
    walk_tables = [
        ("Box walking into a static box wall 3 m thick, velocity written every step: "
         "deepest overlap", dict(wall="box", mover="box", mode="velocity"), "max"),
        ("Same, steady state (deepest over the last half second)",
         dict(wall="box", mover="box", mode="velocity"), "steady"),
        ("Impulse to the walking speed every step (box wall)",
         dict(wall="box", mover="box", mode="impulse"), "max"),
        ("Box walking into an edge", dict(wall="edge", mover="box", mode="velocity"), "max"),
        ("Box walking into a chain (ccw winding)",
         dict(wall="chain-ccw", mover="box", mode="velocity"), "max"),
        ("Box walking into a chain (cw winding)",
         dict(wall="chain-cw", mover="box", mode="velocity"), "max"),
        ("Circle walking into a static box wall",
         dict(wall="box", mover="circle", mode="velocity"), "max"),
        ("Box pressing a 1 kg crate against a static wall (walker-crate and crate-wall, "
         "deepest)", dict(wall="pressed-box", mover="box", mode="velocity"), "max"),
        ("Box pushing a free 1 kg crate (deepest walker-crate overlap, first touch included)",
         dict(wall="free-box", mover="box", mode="velocity"), "max"),
    ]
    out: list[str] = []
    for title, match, key in walk_tables:
        out += [f"### {title}", ""]
        out += _grid(before["walk"], after["walk"], lambda r, k=key: _mm(r, k),
                     "speed m/s", **match)
        out.append("")

    def landing(r: dict[str, Any] | None) -> str:
        return "-" if r is None else f"{r['max'] * 1000:.1f}/{r['rest'] * 1000:.1f}"

    for mover in ("box", "circle"):
        out += [f"### {mover.capitalize()} thrown down onto the ground from 5 cm: "
                "deepest / resting overlap (mm)", ""]
        out += _grid(before["land"], after["land"], landing, "speed m/s", mover=mover)
        out.append("")

    def asleep(rows: list[dict[str, Any]], kind: str) -> str:
        at = next((r["asleep_step"] for r in rows if r["kind"] == kind), None)
        return "-" if at is None else "never (600 steps)" if at < 0 else f"{at:.0f}"

    out += ["### Jointed bodies at rest: step at which they fall asleep "
            "(pybox2d 2.3.10: 30; wheel 113)", "", "| joint | before | after |", "|---|---:|---:|"]
    for r in after["sleep"]:
        out.append(f"| {r['kind']} | {asleep(before['sleep'], r['kind'])} | "
                   f"{asleep(after['sleep'], r['kind'])} |")
    return "\n".join(out)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=(__doc__ or "").split("\n")[0])
    parser.add_argument("--quick", action="store_true")
    parser.add_argument("--out", help="write the results as JSON here")
    parser.add_argument("--markdown", nargs=2, metavar=("BEFORE", "AFTER"),
                        help="print the before → after tables of two result files")
    args = parser.parse_args(argv)
    if args.markdown:
        loaded = []
        for path in args.markdown:
            with open(path, encoding="utf-8") as f:
                loaded.append(json.load(f))
        print(markdown(*loaded))
        return 0
    result = measure(args.quick)
    # one row per line: diffable, and a tenth of an indented dump
    text = "{\n" + ",\n".join(
        f"{json.dumps(name)}: [\n" + ",\n".join(json.dumps(row) for row in rows) + "\n]"
        for name, rows in result.items()
    ) + "\n}"
    if args.out:
        with open(args.out, "w", encoding="utf-8") as f:
            f.write(text + "\n")
    else:
        print(text)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
