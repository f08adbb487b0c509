"""Gymnasium environments from kge scenes (docs/rl.md).

Importing this package registers ``kge/LunarLander-v0``,
``kge/LunarLanderContinuous-v0`` and ``kge/CartPole-v0`` with Gymnasium. It is the
top floor: nothing else in kge imports it, and it needs the ``gym`` extra
(``pip install kge[gym]``).
"""

from kge.gym.cartpole import CartPole
from kge.gym.env import KgeEnv, env_plugins
from kge.gym.errors import (
    EnvError,
    InvalidActionError,
    InvalidSeedError,
    ObservationError,
    ResetNeededError,
)
from kge.gym.lander_vector import LunarLanderVector
from kge.gym.lunar_lander import LunarLander
from kge.gym.registration import CARTPOLE, LUNAR_LANDER, LUNAR_LANDER_CONTINUOUS, register_envs
from kge.gym.vector import BatchVectorEnv, KgeVectorEnv

register_envs()

__all__ = [
    "CARTPOLE",
    "LUNAR_LANDER",
    "LUNAR_LANDER_CONTINUOUS",
    "BatchVectorEnv",
    "CartPole",
    "EnvError",
    "InvalidActionError",
    "InvalidSeedError",
    "KgeEnv",
    "KgeVectorEnv",
    "LunarLander",
    "LunarLanderVector",
    "ObservationError",
    "ResetNeededError",
    "env_plugins",
    "register_envs",
]
