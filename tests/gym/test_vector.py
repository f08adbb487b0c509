"""KgeVectorEnv: N kge worlds, batched arrays, Gymnasium's next-step autoreset."""

from __future__ import annotations

from typing import Any

import gymnasium as gym
import numpy as np
import pytest

from kge.gym import (
    CARTPOLE,
    LUNAR_LANDER,
    InvalidActionError,
    InvalidSeedError,
    KgeVectorEnv,
    LunarLanderVector,
    lunar_lander,
)
from kge.gym.errors import ResetNeededError


def make(env_id: str, **kwargs: Any) -> Any:
    """gymnasium.make, typed loosely: the tests reach into the kge env behind it."""
    return gym.make(env_id, **kwargs)


def make_vec(env_id: str, **kwargs: Any) -> Any:
    return gym.make_vec(env_id, **kwargs)



def test_make_vec_uses_the_vector_entry_point():
    assert isinstance(make_vec(CARTPOLE, num_envs=2), KgeVectorEnv)
    envs = make_vec(LUNAR_LANDER, num_envs=4)
    assert isinstance(envs, LunarLanderVector)  # the landers share one world
    assert envs.max_episode_steps == 1000  # the registered time limit reaches it
    obs, _ = envs.reset(seed=0)
    assert obs.shape == (4, 8) and obs.dtype == np.float32
    assert envs.observation_space.contains(obs)
    obs, rew, term, _trunc, _ = envs.step(np.array([0, 1, 2, 3]))
    assert obs.shape == (4, 8) and rew.shape == (4,) and term.dtype == np.bool_
    envs.close()


def test_env_i_replays_a_single_env_seeded_s_plus_i():
    """KgeVectorEnv (one world per env): env i is the single env, bit for bit."""
    envs = make_vec(CARTPOLE, num_envs=3)
    batch, _ = envs.reset(seed=10)
    singles = [make(CARTPOLE) for _ in range(3)]
    firsts = [env.reset(seed=10 + i)[0] for i, env in enumerate(singles)]
    assert np.array_equal(batch, np.stack(firsts))
    rng = np.random.default_rng(0)
    for _ in range(60):
        actions = rng.integers(0, 2, size=3)
        obs, rew, term, *_ = envs.step(actions)
        for i, env in enumerate(singles):
            o, r, *_ = env.step(int(actions[i]))
            assert o.tobytes() == obs[i].tobytes() and r == rew[i]
        if term.any():  # the single envs would need a reset now
            break


def test_same_seed_same_batch_bit_for_bit():
    def run():
        envs = make_vec(CARTPOLE, num_envs=8)
        obs, _ = envs.reset(seed=5)
        out = [obs]
        for k in range(80):
            out.append(envs.step(np.full(8, k % 2))[0])
        return np.stack(out)

    assert run().tobytes() == run().tobytes()


def test_next_step_autoreset_after_termination():
    envs = make_vec(LUNAR_LANDER, num_envs=2)
    envs.reset(seed=0)
    done_at = None
    for k in range(400):  # both do nothing: they crash
        _, rew, term, _, info = envs.step(np.array([0, 0]))
        if term[0]:
            done_at = k
            assert info["game_over"][0] and info["_game_over"][0]
            break
    assert done_at is not None and rew[0] == -100.0
    obs, rew, term, _, _ = envs.step(np.array([2, 2]))  # env 0 resets instead of stepping
    assert rew[0] == 0.0 and not term[0] and obs[0, 1] > 1.0  # back at the top
    obs, rew, term, _trunc, _ = envs.step(np.array([2, 2]))
    assert rew[0] != 0.0


def test_time_limit_truncates_and_resets():
    envs = make_vec(CARTPOLE, num_envs=2, max_episode_steps=5)
    envs.reset(seed=1)
    for _ in range(4):
        _, _, term, trunc, _ = envs.step(np.array([0, 1]))
        assert not trunc.any()
    _, _, term, trunc, _ = envs.step(np.array([0, 1]))
    assert trunc.all() and not term.any()


def test_gymnasium_sync_vector_env_still_works():
    envs = make_vec(CARTPOLE, num_envs=3, vectorization_mode="sync")
    assert isinstance(envs, gym.vector.SyncVectorEnv)
    obs: Any = envs.reset(seed=0)[0]
    ours = make_vec(CARTPOLE, num_envs=3)
    assert np.array_equal(obs, ours.reset(seed=0)[0])


def test_rgb_array_render_gives_one_frame_per_env():
    envs = make_vec(LUNAR_LANDER, num_envs=2, render_mode="rgb_array")
    envs.reset(seed=0)
    frames = envs.render()
    assert len(frames) == 2 and frames[0].shape == (400, 600, 3)
    assert not np.array_equal(frames[0], frames[1])  # different terrain


@pytest.mark.parametrize("actions", [np.array([0, 4]), np.array([0]), [0.5, 1], "ab"])
def test_bad_action_batch_names_the_env(actions):
    envs = make_vec(LUNAR_LANDER, num_envs=2)
    envs.reset(seed=0)
    with pytest.raises(InvalidActionError, match=r"kge/LunarLander-v0 \(vector of 2\)"):
        envs.step(actions)


def test_bad_seeds_and_step_before_reset():
    envs = make_vec(CARTPOLE, num_envs=2)
    with pytest.raises(ResetNeededError, match="before reset"):
        envs.step(np.array([0, 0]))
    with pytest.raises(InvalidSeedError, match="needs 2 seeds"):
        envs.reset(seed=[1, 2, 3])
    with pytest.raises(InvalidSeedError, match="'x'"):
        envs.reset(seed="x")
    with pytest.raises(ValueError, match="num_envs"):
        KgeVectorEnv(lunar_lander.LunarLander, 0)
