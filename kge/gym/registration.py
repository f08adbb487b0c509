"""Register the kge environments with Gymnasium under the ``kge/`` namespace.

``import kge.gym`` registers ``kge/LunarLander-v0``, ``kge/LunarLanderContinuous-v0``
and ``kge/CartPole-v0``, after which::

    env = gymnasium.make("kge/LunarLander-v0")
    envs = gymnasium.make_vec("kge/LunarLander-v0", num_envs=64)   # LunarLanderVector

``make_vec`` uses the ``vector_entry_point`` (one process, batched arrays: the landers
share one world, CartPole steps one world per env) unless
``vectorization_mode="sync"`` or ``"async"`` asks for Gymnasium's wrappers.
"""

from __future__ import annotations

from typing import Any

import gymnasium as gym

from kge.gym.cartpole import CartPole
from kge.gym.lander_vector import LunarLanderVector
from kge.gym.vector import KgeVectorEnv

LUNAR_LANDER = "kge/LunarLander-v0"
LUNAR_LANDER_CONTINUOUS = "kge/LunarLanderContinuous-v0"
CARTPOLE = "kge/CartPole-v0"


def lunar_lander_vector(num_envs: int = 1, **kwargs: Any) -> LunarLanderVector:
    """The ``vector_entry_point`` of ``kge/LunarLander-v0``: N landers in one world."""
    return LunarLanderVector(num_envs, name=LUNAR_LANDER, **kwargs)


def lunar_lander_continuous_vector(num_envs: int = 1, **kwargs: Any) -> LunarLanderVector:
    """The ``vector_entry_point`` of ``kge/LunarLanderContinuous-v0``."""
    return LunarLanderVector(num_envs, name=LUNAR_LANDER_CONTINUOUS,
                             **{"continuous": True, **kwargs})


def cartpole_vector(num_envs: int = 1, **kwargs: Any) -> KgeVectorEnv:
    """The ``vector_entry_point`` of ``kge/CartPole-v0``."""
    return KgeVectorEnv(CartPole, num_envs, name=CARTPOLE, **kwargs)


ENVS: dict[str, dict[str, Any]] = {
    LUNAR_LANDER: {"entry_point": "kge.gym.lunar_lander:LunarLander",
                   "vector_entry_point": "kge.gym.registration:lunar_lander_vector",
                   "max_episode_steps": 1000, "reward_threshold": 200.0},
    LUNAR_LANDER_CONTINUOUS: {
        "entry_point": "kge.gym.lunar_lander:LunarLander", "kwargs": {"continuous": True},
        "vector_entry_point": "kge.gym.registration:lunar_lander_continuous_vector",
        "max_episode_steps": 1000, "reward_threshold": 200.0},
    CARTPOLE: {"entry_point": "kge.gym.cartpole:CartPole",
               "vector_entry_point": "kge.gym.registration:cartpole_vector",
               "max_episode_steps": 500, "reward_threshold": 475.0},
}


def register_envs() -> None:
    """Register every kge env once (safe to call again, e.g. inside Ray workers)."""
    for env_id, spec in ENVS.items():
        if env_id not in gym.registry:
            gym.register(id=env_id, **spec)
