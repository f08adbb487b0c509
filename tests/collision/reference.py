"""The Box2D reference answers (tests/collision/box2d_reference.json) as kge inputs.

The file is written by tools/measure_collision_reference.py with pybox2d 2.3.10;
these tests only read it, so they run without pybox2d.
"""

from __future__ import annotations

import json
import math
from functools import cache
from pathlib import Path
from typing import Any

from kge.collision import Sweep
from kge.components.shapes import Box, Chain, Circle, Edge, Polygon

PATH = Path(__file__).with_name("box2d_reference.json")

#: Box2D computes in float32 (about 7 significant digits); kge in float64. Positions,
#: distances and fractions of these metre-sized cases agree to this, in metres.
TOL = 2e-5
#: unit normals agree to this per component
NORMAL_TOL = 1e-4


@cache
def data() -> dict[str, Any]:
    return json.loads(PATH.read_text())


def shape(spec: dict[str, Any]) -> Any:
    t = spec["type"]
    if t == "circle":
        return Circle(spec["radius"], tuple(spec["center"]))
    if t == "box":
        return Box(spec["half_width"], spec["half_height"], tuple(spec["center"]), spec["angle"])
    if t == "polygon":
        return Polygon([tuple(v) for v in spec["vertices"]])
    if t == "edge":
        return Edge(tuple(spec["v1"]), tuple(spec["v2"]))
    return Chain([tuple(v) for v in spec["vertices"]], loop=spec["loop"])


@cache
def shapes() -> tuple[Any, ...]:
    return tuple(shape(s) for s in data()["shapes"])


def sweep(s: dict[str, Any]) -> Sweep:
    return Sweep(tuple(s["local_center"]), tuple(s["c0"]), tuple(s["c"]), s["a0"], s["a"])


def close(a: Any, b: Any, tol: float = TOL) -> bool:
    return all(math.isclose(x, y, abs_tol=tol) for x, y in zip(a, b, strict=True))
