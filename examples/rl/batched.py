"""Fly many LunarLanders in one kge world: the batched env with the heuristic pilot.

``gymnasium.make_vec("kge/LunarLander-v0", num_envs=N)`` builds a
:class:`~kge.gym.LunarLanderVector`: N scenes side by side in one world, one
physics step per batch step. This script flies ``--episodes`` episodes with the
heuristic pilot (episodes restart as they end: Gymnasium's next-step autoreset),
prints the landing rate and the mean return, and the env steps per second::

    python examples/rl/batched.py --envs 64 --episodes 128
"""

from __future__ import annotations

import argparse
import time
from collections.abc import Sequence
from typing import Any

import gymnasium as gym
import numpy as np

import kge.gym  # noqa: F401  (registers kge/LunarLander-v0)
from kge.gym.lunar_lander import heuristic


def fly(num_envs: int, episodes: int, seed: int = 0) -> dict[str, Any]:
    """Fly until ``episodes`` episodes have ended; returns the tallies and the speed."""
    envs = gym.make_vec("kge/LunarLander-v0", num_envs=num_envs)
    obs, _ = envs.reset(seed=seed)
    totals = np.zeros(num_envs)
    returns: list[float] = []
    landed = steps = 0
    start = time.perf_counter()
    while len(returns) < episodes:
        obs, rewards, terminated, truncated, info = envs.step(
            np.array([heuristic(o) for o in obs]))
        steps += num_envs
        totals += rewards
        for i in np.flatnonzero(terminated | truncated).tolist():
            returns.append(float(totals[i]))
            landed += bool(terminated[i] and not info["game_over"][i] and not info["awake"][i])
            totals[i] = 0.0  # the next step is this env's reset step (reward 0)
    elapsed = time.perf_counter() - start
    envs.close()
    return {"episodes": len(returns), "landed": landed, "mean_return": float(np.mean(returns)),
            "steps_per_s": steps / elapsed}


def main(argv: Sequence[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=(__doc__ or "").split("\n")[0])
    parser.add_argument("--envs", type=int, default=16)
    parser.add_argument("--episodes", type=int, default=32)
    parser.add_argument("--seed", type=int, default=0)
    args = parser.parse_args(argv)
    r = fly(args.envs, args.episodes, args.seed)
    print(f"{r['episodes']} episodes in {args.envs} envs: {r['landed']} landed at rest, "
          f"mean return {r['mean_return']:.1f}, {r['steps_per_s']:,.0f} env steps/s "
          "(pilot included)")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
