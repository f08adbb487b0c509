"""RLlib PPO on the kge LunarLander for a few iterations, printing the reward mean.

::

    python examples/rl/ppo_lander.py --iterations 20
    python examples/rl/ppo_lander.py --address auto --env-runners 8   # on a Ray cluster

The env is registered with RLlib's ``register_env`` through a creator that imports
``kge.gym`` inside each env runner (a fresh worker process on any machine), so
the same code trains on a laptop or on a cluster of machines with kge installed.
"""

from __future__ import annotations

import argparse
import math
from collections.abc import Sequence
from typing import Any

import gymnasium as gym
import ray

ENV_NAME = "kge-lunar-lander"


def make_env(config: dict[str, Any]) -> gym.Env[Any, Any]:
    """RLlib's env creator: runs in each env runner process."""
    import kge.gym  # noqa: F401  (registers the kge/ ids in this process)

    return gym.make("kge/LunarLander-v0", **dict(config))


def train(iterations: int = 2, *, env_runners: int = 0, batch: int = 512,
          minibatch: int = 128, epochs: int = 2, seed: int = 0) -> list[float]:
    """Train PPO for ``iterations``; the reward mean of each (nan until an episode ends)."""
    from ray.rllib.algorithms.ppo import PPOConfig
    from ray.rllib.core.rl_module.default_model_config import DefaultModelConfig
    from ray.tune.registry import register_env

    register_env(ENV_NAME, make_env)
    config = (
        PPOConfig()
        .environment(ENV_NAME)
        .env_runners(num_env_runners=env_runners, num_envs_per_env_runner=1)
        .training(train_batch_size_per_learner=batch, minibatch_size=minibatch,
                  num_epochs=epochs, lr=3e-4)
        .rl_module(model_config=DefaultModelConfig(fcnet_hiddens=[64, 64]))
        .debugging(seed=seed)
    )
    algo = config.build_algo()
    means = []
    try:
        for i in range(iterations):
            result = algo.train()
            runners = result.get("env_runners", {})
            mean = float(runners.get("episode_return_mean", math.nan))
            means.append(mean)
            print(f"iteration {i + 1}: reward mean {mean:8.2f} "
                  f"({runners.get('num_episodes', 0)} episodes ended)")
    finally:
        algo.stop()
    return means


def main(argv: Sequence[str] | None = None) -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--address", default=None,
                        help="Ray cluster address ('auto' = the cluster this machine joined)")
    parser.add_argument("--iterations", type=int, default=5)
    parser.add_argument("--env-runners", type=int, default=1)
    parser.add_argument("--batch", type=int, default=2000)
    args = parser.parse_args(argv)
    ray.init(address=args.address)
    train(args.iterations, env_runners=args.env_runners, batch=args.batch,
          minibatch=min(256, args.batch), epochs=4)
    ray.shutdown()


if __name__ == "__main__":
    main()
