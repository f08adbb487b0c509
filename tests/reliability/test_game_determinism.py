"""Cross-process determinism of the game layer: particles, tweens, animation, UI state
and poses hash the same in two processes with other hash seeds and in this one."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

from .game_determinism import game_hash

ROOT = Path(__file__).resolve().parents[2]
FRAMES = 120


def _child(seed: str) -> subprocess.Popen[str]:
    env = {**os.environ, "PYTHONHASHSEED": seed, "PYGLET_HEADLESS": "1",
           "PYGLET_AUDIO": "silent", "PYTHONPATH": str(ROOT)}
    return subprocess.Popen(
        [sys.executable, "-m", "tests.reliability.game_determinism", str(FRAMES)],
        cwd=ROOT, env=env, stdout=subprocess.PIPE, text=True,
    )  # fmt: skip


def test_the_game_layer_is_the_same_in_every_process() -> None:
    children = [_child(seed) for seed in ("1", "12345")]
    here = game_hash(FRAMES)
    outs = []
    for child in children:
        out, _ = child.communicate(timeout=600)
        assert child.returncode == 0
        outs.append(out.strip())
    assert outs == [here, here], "a different PYTHONHASHSEED changed the game layer"


def test_the_hash_sees_the_game_layer() -> None:
    # a hash that did not move with the frames could not catch a divergence
    assert game_hash(30) != game_hash(31)
