"""``KgeVectorEnv``: N kge worlds stepped in one process with batched numpy arrays.

Gymnasium's ``SyncVectorEnv`` wraps N complete environments, each behind its
wrappers (time limit, order enforcing, passive checker), and moves every
observation, reward and flag through Python lists. This vector env is what
``gymnasium.make_vec("kge/LunarLander-v0", num_envs=N)`` builds through the
``vector_entry_point`` of the registration: it owns N bare kge envs (each its own
World), checks the whole action batch at once against the batched action space,
writes observations, rewards and flags straight into preallocated arrays, and
applies the time limit and Gymnasium's next-step autoreset itself.

Seeding follows Gymnasium: ``reset(seed=s)`` seeds env i with ``s + i`` (or pass a
list of N seeds), so env i replays exactly what a single env reset with that seed
does.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from typing import Any

import gymnasium as gym
import numpy as np
from gymnasium.vector import AutoresetMode, VectorEnv
from gymnasium.vector.utils import batch_space

from kge.gym.env import KgeEnv, check_seed
from kge.gym.errors import InvalidActionError, InvalidSeedError, ResetNeededError


class BatchVectorEnv(VectorEnv[Any, Any, Any]):
    """What every kge vector env shares: argument checks, batched spaces, the result
    arrays, Gymnasium's seeding rule, the action check and the time limit."""

    #: the name every error uses: "<id or class> (vector of N)"
    env_name: str = "KgeVectorEnv"

    def _setup_batch(self, label: Any, num_envs: Any, max_episode_steps: Any,
                     render_mode: str | None) -> None:
        if isinstance(num_envs, bool) or not isinstance(num_envs, int) or num_envs < 1:
            raise ValueError(f"{label}: num_envs must be an int >= 1, got {num_envs!r}")
        if max_episode_steps is not None and (
            isinstance(max_episode_steps, bool) or not isinstance(max_episode_steps, int)
            or max_episode_steps < 1
        ):
            raise ValueError(f"{label}: max_episode_steps must be an int >= 1 or None, "
                             f"got {max_episode_steps!r}")
        self.num_envs = num_envs
        self.render_mode = render_mode
        self.max_episode_steps = max_episode_steps

    def _setup_spaces(self, env: KgeEnv) -> None:
        """Spaces, metadata and result arrays from one single env (``env_name`` set first)."""
        num_envs = self.num_envs
        self.metadata = {**env.metadata, "autoreset_mode": AutoresetMode.NEXT_STEP}
        self.single_observation_space = env.observation_space
        self.single_action_space = env.action_space
        self.observation_space = batch_space(self.single_observation_space, num_envs)
        self.action_space = batch_space(self.single_action_space, num_envs)
        space = self.single_observation_space
        if not isinstance(space, gym.spaces.Box):
            raise TypeError(f"{self.env_name}: batched observations need a Box space, "
                            f"got {space}")
        self._obs = np.zeros((num_envs, *space.shape), dtype=space.dtype)
        self._rewards = np.zeros(num_envs, dtype=np.float64)
        self._terminations = np.zeros(num_envs, dtype=np.bool_)
        self._truncations = np.zeros(num_envs, dtype=np.bool_)
        self._autoreset = np.zeros(num_envs, dtype=np.bool_)
        self._steps = np.zeros(num_envs, dtype=np.int64)
        self._started = False

    def _seeds(self, seed: int | Sequence[int | None] | None) -> list[int | None]:
        """Gymnasium's rule: ``seed`` s seeds env i with s + i; or one seed per env."""
        if seed is None:
            return [None] * self.num_envs
        if isinstance(seed, (list, tuple)):
            if len(seed) != self.num_envs:
                raise InvalidSeedError(f"{self.env_name}.reset(seed=[...]) needs "
                                       f"{self.num_envs} seeds, got {len(seed)}")
            return [check_seed(self.env_name, s) for s in seed]
        first = check_seed(self.env_name, seed)
        assert first is not None
        return [first + i for i in range(self.num_envs)]

    def _check_actions(self, actions: Any) -> np.ndarray:
        """The batch as an array, or :class:`InvalidActionError` naming the env."""
        if not self._started:
            raise ResetNeededError(f"{self.env_name}.step() called before reset()")
        try:
            batch = np.asarray(actions)
            ok = self.action_space.contains(batch)
        except (TypeError, ValueError):
            ok = False
        if not ok:
            raise InvalidActionError(
                f"{self.env_name}.step(): actions {actions!r} are not in the batched action "
                f"space {self.action_space}"
            )
        return batch

    def _time_limit(self, stepped: np.ndarray) -> None:
        """Count the steps of the envs that ``stepped`` (not reset) and truncate at the limit;
        then mark what the next step resets."""
        self._steps[~stepped] = 0
        self._steps[stepped] += 1
        limit = self.max_episode_steps
        if limit is not None:
            self._truncations |= stepped & (self._steps >= limit)
        np.logical_or(self._terminations, self._truncations, out=self._autoreset)

    def _results(self, infos: dict[str, Any]) -> tuple[np.ndarray, np.ndarray, np.ndarray,
                                                      np.ndarray, dict[str, Any]]:
        return (self._obs.copy(), self._rewards.copy(), self._terminations.copy(),
                self._truncations.copy(), infos)


class KgeVectorEnv(BatchVectorEnv):
    """``num_envs`` copies of a :class:`KgeEnv`, stepped together."""

    def __init__(
        self,
        env_fn: Callable[..., KgeEnv],
        num_envs: int,
        *,
        max_episode_steps: int | None = None,
        render_mode: str | None = None,
        name: str | None = None,
        **env_kwargs: Any,
    ) -> None:
        label = name or getattr(env_fn, "__name__", "KgeVectorEnv")
        self._setup_batch(label, num_envs, max_episode_steps, render_mode)
        self.envs = [env_fn(render_mode=render_mode, **env_kwargs) for _ in range(num_envs)]
        self.env_name = f"{name or self.envs[0].env_name} (vector of {num_envs})"
        self._setup_spaces(self.envs[0])

    def reset(
        self,
        *,
        seed: int | Sequence[int | None] | None = None,
        options: dict[str, Any] | None = None,
    ) -> tuple[np.ndarray, dict[str, Any]]:
        seeds = self._seeds(seed)
        infos: dict[str, Any] = {}
        for i, (env, s) in enumerate(zip(self.envs, seeds, strict=True)):
            obs, info = env.reset(seed=s, options=options)
            self._obs[i] = obs
            infos = self._add_info(infos, info, i)
        self._autoreset[:] = False
        self._steps[:] = 0
        self._started = True
        return self._obs.copy(), infos

    def step(
        self, actions: Any
    ) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, dict[str, Any]]:
        batch = self._check_actions(actions)
        infos: dict[str, Any] = {}
        resetting = self._autoreset.copy()
        for i, env in enumerate(self.envs):
            if resetting[i]:
                obs, info = env.reset()
                reward, term = 0.0, False
            else:
                obs, reward, term, _, info = env.advance(batch[i])
            self._obs[i] = obs
            self._rewards[i] = reward
            self._terminations[i] = term
            if info:
                infos = self._add_info(infos, info, i)
        self._truncations[:] = False
        self._time_limit(~resetting)
        return self._results(infos)

    def render(self) -> tuple[Any, ...] | None:
        if self.render_mode is None:
            gym.logger.warn(f"{self.env_name}.render() without a render_mode: nothing drawn")
            return None
        return tuple(env.render() for env in self.envs)

    def close_extras(self, **kwargs: Any) -> None:
        for env in getattr(self, "envs", ()):  # also after a refused constructor
            env.close()
