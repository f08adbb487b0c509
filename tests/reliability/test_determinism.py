"""Determinism: the falling-hinges scene gives the same bits every run, everywhere we support.

Box2D's own determinism test: 4 x 30 boxes hinged in pairs by limited revolute
joints fall into a heap; after 500 steps every pose is hashed. The result must
be identical in one process (two runs), across processes with different hash
seeds (set and dict ordering of ids must not leak into the solver), and equal
to the pinned value on the supported platform.
"""

from __future__ import annotations

import os
import platform
import subprocess
import sys
from pathlib import Path

import pymunk
import pytest

from kge.testbed.samples.determinism import falling_hinges_hash

ROOT = Path(__file__).resolve().parents[2]
STEPS = 500
#: pose hash after 500 steps on x86_64 Linux, CPython 3.11, pymunk 7.3.1 (re-pinned when
#: new contacts started settling at the linear slop and jointed islands sleeping by
#: Box2D's clock changed the heap)
PINNED = "0ec1bfa782297d2d4e022fe81f92df32981406ceda2e65d6a945131ad5d97cbd"
SUPPORTED = (
    platform.machine() == "x86_64"
    and sys.platform.startswith("linux")
    and sys.version_info[:2] == (3, 11)
    and pymunk.version == "7.3.1"
)


def _hash_in_subprocess(seed: str) -> subprocess.Popen[str]:
    env = {**os.environ, "PYTHONHASHSEED": seed, "PYGLET_HEADLESS": "1"}
    code = f"from kge.testbed.samples.determinism import falling_hinges_hash as h; print(h({STEPS}))"
    return subprocess.Popen(
        [sys.executable, "-c", code], cwd=ROOT, env=env, stdout=subprocess.PIPE, text=True
    )


def test_two_runs_in_one_process_are_identical() -> None:
    # CI: 60 steps (boxes landing, hinges reaching their limits, new contacts every
    # step); KGE_FUZZ=long: the full 500
    steps = STEPS if os.environ.get("KGE_FUZZ") == "long" else 60
    first = falling_hinges_hash(steps=steps)
    second = falling_hinges_hash(steps=steps)
    assert first == second


def test_separate_processes_with_other_hash_seeds_agree_and_match_the_pin() -> None:
    # A child process with its own hash seed runs the full 500 steps. On the supported
    # platform its hash must equal the pin (itself made by other processes with other
    # seeds), which is the cross-process comparison; elsewhere it is compared with a
    # run in this process instead, and the pin is skipped.
    child = _hash_in_subprocess("12345")
    if SUPPORTED and os.environ.get("KGE_FUZZ") != "long":
        out, _ = child.communicate(timeout=300)
        assert child.returncode == 0
        assert out.strip() == PINNED, (
            f"pose hash changed: {out.strip()}. If the solver changed on purpose (and the "
            "physics tests pass), re-pin with `python -m kge.testbed.samples.determinism`"
        )
        return
    here = falling_hinges_hash(steps=STEPS)
    out, _ = child.communicate(timeout=300)
    assert child.returncode == 0
    assert out.strip() == here, "a different PYTHONHASHSEED changed the simulation"
    if not SUPPORTED:
        pytest.skip(
            f"the pinned hash is for x86_64 Linux, Python 3.11, pymunk 7.3.1; this is "
            f"{platform.machine()} {sys.platform}, Python {platform.python_version()}, "
            f"pymunk {pymunk.version} (cross-process determinism was still checked)"
        )
    assert here == PINNED, f"pose hash changed: {here} (re-pin only if the solver changed)"
