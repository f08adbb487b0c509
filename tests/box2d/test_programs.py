"""The pybox2d-style programs give pybox2d 2.3.10's results (measured once, committed).

``tools/box2d_reference.py`` ran each program in tests/box2d/programs with real
pybox2d and wrote reference.json; here the same files run unchanged with
``Box2D`` = kge.box2d. Tolerances are physical bands, not bit-exactness: kge is
a different solver (pymunk) with Box2D's rules.
"""

from __future__ import annotations

import json
import runpy
from pathlib import Path
from types import ModuleType

import pytest

HERE = Path(__file__).parent
REFERENCE = json.loads((HERE / "reference.json").read_text())["results"]

#: (absolute, relative) tolerance per program and result; exact where no tolerance is given
TOLERANCE: dict[str, dict[str, tuple[float, float]]] = {
    "hello_world": {"y": (0.01, 0.0), "x": (0.001, 0.0), "angle": (0.001, 0.0),
                    "mass": (1e-9, 0.0)},
    "pyramid": {"top_y": (0.05, 0.0), "top_x": (0.05, 0.0), "max_drift": (0.02, 0.0)},
    "pendulum": {"period": (0.0, 0.02), "arm": (0.005, 0.0)},
    "raycast": {"x": (1e-6, 0.0), "nx": (1e-6, 0.0), "fraction": (1e-6, 0.0),
                "skip_x": (1e-6, 0.0)},
    "distance_toi": {"distance": (1e-5, 0.0), "ax": (1e-5, 0.0), "ay": (1e-5, 0.0),
                     "bx": (1e-5, 0.0), "ball_distance": (1e-5, 0.0), "toi": (1e-4, 0.0),
                     "miss_t": (1e-4, 0.0)},
    "manifold": {"nx": (1e-6, 0.0), "ny": (1e-6, 0.0), "x0": (1e-4, 0.0), "y0": (1e-4, 0.0),
                 "x1": (1e-4, 0.0), "y1": (1e-4, 0.0), "box_y": (0.01, 0.0)},
    "contacts": {"first_touch": (1.0, 0.0), "bounces": (1.0, 0.0), "ends": (1.0, 0.0),
                 "rest_y": (0.01, 0.0)},
}


@pytest.mark.parametrize("name", sorted(REFERENCE))
def test_program_matches_pybox2d(name: str, installed: ModuleType) -> None:
    got = runpy.run_path(str(HERE / "programs" / f"{name}.py"))["result"]
    want = REFERENCE[name]
    assert set(got) == set(want)
    for key, ref in want.items():
        abs_tol, rel_tol = TOLERANCE.get(name, {}).get(key, (0.0, 0.0))
        assert got[key] == pytest.approx(ref, abs=abs_tol, rel=rel_tol), f"{name}.{key}"
