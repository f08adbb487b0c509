"""Make ``docs/images/rl-envs.png``: the kge LunarLander and CartPole as rgb_array frames.

Run ``python docs/rl_screenshot.py`` (headless is fine: frames are drawn offscreen
through EGL). The lander is flown by the heuristic pilot for 110 steps (seed 2), the
cart-pole balanced for 60 steps (seed 0); the two frames are put side by side.
"""

from __future__ import annotations

import os
import sys
from collections.abc import Callable
from pathlib import Path

os.environ.setdefault("PYGLET_HEADLESS", "1")
sys.path.insert(0, str(Path(__file__).resolve().parent.parent))

import gymnasium as gym
import numpy as np

import kge.gym  # noqa: F401  (registers the kge/ ids)
from kge.gym import cartpole, lunar_lander
from kge.testbed.png import write

OUT = Path(__file__).resolve().parent / "images" / "rl-envs.png"


def frame(env_id: str, policy: Callable[[np.ndarray], int], steps: int, seed: int) -> np.ndarray:
    env = gym.make(env_id, render_mode="rgb_array")
    obs, _ = env.reset(seed=seed)
    for _ in range(steps):
        obs, *_ = env.step(policy(obs))
    pixels = np.asarray(env.render())
    env.close()
    return pixels


def main(path: Path = OUT) -> Path:
    lander = frame("kge/LunarLander-v0", lunar_lander.heuristic, 110, 2)
    cart = frame("kge/CartPole-v0", cartpole.heuristic, 60, 0)
    gap = np.full((lander.shape[0], 8, 3), 128, np.uint8)
    path.parent.mkdir(parents=True, exist_ok=True)
    write(path, np.concatenate([lander, gap, cart], axis=1))
    return path


if __name__ == "__main__":
    print(main())
