"""kge.gym: the Env adapter, the registered envs, seeding, rendering and bad input."""

from __future__ import annotations

import math
from typing import Any

import gymnasium as gym
import numpy as np
import pytest
from gymnasium.utils.env_checker import check_env

import kge.gym
from kge import BodyType, Box, Collider, RevoluteJoint, RigidBody, Transform, World
from kge.gym import (
    CARTPOLE,
    LUNAR_LANDER,
    LUNAR_LANDER_CONTINUOUS,
    InvalidActionError,
    InvalidSeedError,
    KgeEnv,
    ObservationError,
    ResetNeededError,
    cartpole,
    lunar_lander,
)

IDS = [LUNAR_LANDER, LUNAR_LANDER_CONTINUOUS, CARTPOLE]


def make(env_id: str, **kwargs: Any) -> Any:
    """gymnasium.make, typed loosely: the tests reach into the kge env behind it."""
    return gym.make(env_id, **kwargs)


def make_vec(env_id: str, **kwargs: Any) -> Any:
    return gym.make_vec(env_id, **kwargs)



@pytest.mark.parametrize("env_id", IDS)
@pytest.mark.parametrize("render_mode", [None, "rgb_array"])
def test_check_env_passes(env_id, render_mode):
    env = make(env_id, render_mode=render_mode)
    check_env(env.unwrapped, skip_render_check=False)
    env.close()


def _rollout(env, seed, steps=150):
    env.action_space.seed(123)  # the same actions every time
    obs, _ = env.reset(seed=seed)
    trace = [obs]
    rewards = []
    for _ in range(steps):
        obs, r, term, trunc, _ = env.step(env.action_space.sample())
        trace.append(obs)
        rewards.append(r)
        if term or trunc:
            obs, _ = env.reset()
            trace.append(obs)
    return np.array(trace), np.array(rewards)


@pytest.mark.parametrize("env_id", IDS)
def test_same_seed_replays_bit_for_bit(env_id):
    a, ra = _rollout(make(env_id), seed=7)
    b, rb = _rollout(make(env_id), seed=7)
    assert a.tobytes() == b.tobytes() and ra.tobytes() == rb.tobytes()
    c, _ = _rollout(make(env_id), seed=8)
    assert not np.array_equal(a[:10], c[:10])


def test_reset_without_seed_continues_the_stream():
    env = make(LUNAR_LANDER)
    first, _ = env.reset(seed=3)
    second, _ = env.reset()
    again, _ = env.reset(seed=3)
    assert np.array_equal(first, again) and not np.array_equal(first, second)


def _episode(env, policy, seed, limit):
    obs, _ = env.reset(seed=seed)
    total, steps = 0.0, 0
    while True:
        obs, r, term, trunc, info = env.step(policy(obs))
        total += r
        steps += 1
        if term or trunc or steps >= limit:
            return total, term, info, obs


@pytest.mark.parametrize("seed", range(4))
def test_lunar_lander_heuristic_lands(seed):
    env = make(LUNAR_LANDER)
    total, term, info, obs = _episode(env, lunar_lander.heuristic, seed, 1000)
    assert term and not info["game_over"] and not info["awake"]  # came to rest
    assert obs[6] == 1.0 and obs[7] == 1.0  # both legs down
    assert abs(obs[0]) < 0.2  # between the flags
    assert total > 200.0  # Gymnasium's "solved" score


@pytest.mark.parametrize("seed", range(2))
def test_continuous_lander_lands_with_the_same_pilot(seed):
    env = make(LUNAR_LANDER_CONTINUOUS)
    assert env.action_space.shape == (2,)

    def pilot(obs):
        return np.array(lunar_lander.AS_CONTINUOUS[lunar_lander.heuristic(obs)], np.float32)

    total, term, info, _ = _episode(env, pilot, seed, 1000)
    assert term and not info["game_over"] and not info["awake"] and total > 200.0


@pytest.mark.parametrize(("action", "powers"), [
    ((0.0, 0.4), (0.0, 0.0, 0.0)),       # main off at <= 0, side dead zone |x| <= 0.5
    ((0.5, 0.0), (0.75, 0.0, 0.0)),      # main 50-100 % over (0, 1]
    ((1.0, -0.75), (1.0, 0.75, -1.0)),   # both engines at once, left side at 75 %
    ((-1.0, 1.0), (0.0, 1.0, 1.0)),
])
def test_continuous_throttles_follow_gymnasium(action, powers):
    env = lunar_lander.LunarLander(continuous=True)
    assert env.throttle(np.array(action, np.float32)) == pytest.approx(powers)


def _leg_joints(env):
    world = env.unwrapped.world
    joints = {j.body_b: j for _, (j,) in world.query(RevoluteJoint)}
    return [joints[leg] for leg in env.unwrapped.legs]


def test_lunar_lander_legs_are_hinged_and_held_on_their_limits():
    env = make(LUNAR_LANDER)
    _, term, info, _ = _episode(env, lunar_lander.heuristic, 0, 1000)
    assert term and not info["game_over"] and not info["awake"]
    world = env.unwrapped.world
    for i, (leg, joint) in zip((-1, 1), zip(env.unwrapped.legs, _leg_joints(env), strict=True),
                               strict=True):
        assert world.get(leg, RigidBody).type == BodyType.DYNAMIC
        assert joint.body_a == env.unwrapped.lander
        assert joint.enable_motor and joint.enable_limit
        # the motor presses each leg outwards onto its 0.4 rad stop, under the hull's weight
        assert joint.angle == pytest.approx(-i * 0.4, abs=0.04)


def test_lunar_lander_doing_nothing_crashes():
    env = make(LUNAR_LANDER)
    env.reset(seed=0)
    folded = 0.0
    while True:
        _, total, term, _, info = env.step(lunar_lander.NOOP)
        folded = max(folded, *(abs(j.angle) for j in _leg_joints(env)))
        if term:
            break
    assert info["game_over"] and total == -100.0
    assert folded > 0.5  # the legs gave way towards their 0.9 rad stop before the hull hit


def test_lunar_lander_main_engine_lifts_and_costs_fuel():
    env = lunar_lander.LunarLander()
    env.reset(seed=0)
    env.step(lunar_lander.NOOP)
    vy_noop = float(env.world.get(env.lander, RigidBody).velocity[1])
    env.reset(seed=0)
    env.step(lunar_lander.MAIN)
    vy_main = float(env.world.get(env.lander, RigidBody).velocity[1])
    assert vy_main > vy_noop + 0.3  # 13 * 4/30 N s on a ~5 kg hull, a little dispersion
    assert env.m_power == 1.0


def test_cartpole_heuristic_balances_and_passive_pole_falls():
    env = make(CARTPOLE)
    total, term, _, _ = _episode(env, cartpole.heuristic, 0, 500)
    assert total == 500.0 and not term
    total, term, _, obs = _episode(env, lambda obs: 1, 0, 500)
    assert term and total < 100  # always pushing right: the pole falls left
    assert obs[2] < -cartpole.THETA_LIMIT or abs(obs[0]) > cartpole.X_LIMIT


def _gym_cartpole(state, force, seconds, dt=1e-4):
    """Gymnasium's CartPole equations, integrated finely (the reference dynamics)."""
    x, x_dot, th, th_dot = (float(v) for v in state)
    m, big_m, half, g = cartpole.POLE_MASS, cartpole.CART_MASS, cartpole.POLE_HALF_LENGTH, 9.8
    for _ in range(round(seconds / dt)):
        temp = (force + m * half * th_dot**2 * math.sin(th)) / (m + big_m)
        th_acc = (g * math.sin(th) - math.cos(th) * temp) / (
            half * (4.0 / 3.0 - m * math.cos(th) ** 2 / (m + big_m)))
        x_acc = temp - m * half * th_acc * math.cos(th) / (m + big_m)
        x, x_dot = x + dt * x_dot, x_dot + dt * x_acc
        th, th_dot = th + dt * th_dot, th_dot + dt * th_acc
    return np.array([x, x_dot, th, th_dot])


@pytest.mark.parametrize("action", [0, 1])
def test_cartpole_joints_follow_gymnasiums_equations(action):
    """The prismatic + revolute scene moves as Gymnasium's hand-written model does."""
    env = cartpole.CartPole()
    start, _ = env.reset(seed=4)
    for _ in range(7):  # 0.14 s of constant push (12 degrees come at about 0.17 s)
        obs, *_ = env.step(action)
    force = cartpole.FORCE if action == 1 else -cartpole.FORCE
    want = _gym_cartpole(start, force, 0.14)
    assert obs[0] == pytest.approx(want[0], abs=0.01)
    assert obs[1] == pytest.approx(want[1], abs=0.01)
    assert obs[2] == pytest.approx(want[2], abs=0.01)
    assert obs[3] == pytest.approx(want[3], abs=0.02)


def test_rgb_array_frames_show_the_scene():
    env = make(LUNAR_LANDER, render_mode="rgb_array")
    _obs, _ = env.reset(seed=2)
    for _ in range(40):  # fall into the middle of the view
        env.step(lunar_lander.NOOP)
    frame = env.render()
    assert frame.shape == (400, 600, 3) and frame.dtype == np.uint8
    assert (frame[-1] == 255).all()  # the moon fills the bottom row (white)
    assert (frame[0] == 0).all()  # the sky at the top (black)
    lander = env.unwrapped.world.get(env.unwrapped.lander, Transform)
    col = round(lander.x * lunar_lander.SCALE)
    row = round(400 - lander.y * lunar_lander.SCALE)  # top row first
    patch = frame[row - 5 : row + 5, col - 5 : col + 5].reshape(-1, 3)
    assert (np.abs(patch.astype(int) - (128, 102, 230)).sum(axis=1) < 10).mean() > 0.9
    for _ in range(10):
        env.step(lunar_lander.NOOP)
    assert not np.array_equal(env.render(), frame)  # the lander moved


def test_render_without_mode_warns_and_returns_none():
    env = make(LUNAR_LANDER).unwrapped
    env.reset(seed=0)
    with pytest.warns(UserWarning, match="render_mode"):
        assert env.render() is None


def test_metadata_render_fps_matches_the_step():
    assert lunar_lander.LunarLander().metadata["render_fps"] == 50
    assert cartpole.CartPole().metadata["render_fps"] == 50


# -- bad input -----------------------------------------------------------------------------
@pytest.mark.parametrize("action", [4, -1, 1.5, "2", None, np.array([1, 2])])
def test_action_outside_the_space_is_refused(action):
    env = make(LUNAR_LANDER).unwrapped
    env.reset(seed=0)
    before = env.world.get(env.lander, Transform).y
    with pytest.raises(InvalidActionError, match=r"kge/LunarLander-v0.*action"):
        env.step(action)
    assert env.world.get(env.lander, Transform).y == before  # nothing stepped
    env.step(2)  # still usable


@pytest.mark.parametrize("seed", ["1", 1.5, -1, True, [1]])
def test_bad_seed_is_refused(seed):
    env = make(CARTPOLE).unwrapped
    with pytest.raises(InvalidSeedError, match=r"kge/CartPole-v0.*seed") as err:
        env.reset(seed=seed)
    assert repr(seed) in str(err.value)


def test_step_before_reset_and_after_termination():
    env = lunar_lander.LunarLander()
    with pytest.raises(ResetNeededError, match=r"LunarLander.step\(\) called before reset"):
        env.step(0)
    env.reset(seed=0)
    while not env.step(lunar_lander.NOOP)[2]:
        pass
    with pytest.raises(ResetNeededError, match="after the episode terminated"):
        env.step(0)
    env.reset(seed=1)
    env.step(0)


def test_observation_with_nan_is_refused():
    env = _ball_env(observe=lambda world: np.array([world.get(1, Transform).y, math.nan]))
    with pytest.raises(ObservationError, match=r"BallEnv.*non-finite.*index \[1\]"):
        env.reset(seed=0)


# -- building envs from plain functions or a subclass ------------------------------------------
def _build_ball(world: World, rng: np.random.Generator) -> None:
    world.spawn(Transform(0.0, float(rng.uniform(2.0, 4.0))), RigidBody(),
                Collider(Box(0.25, 0.25)))
    world.spawn(Transform(0.0, -0.5), Collider(Box(5.0, 0.5)))


def _push(world: World, action) -> None:
    from kge import Physics

    world.resource(Physics).apply_force(1, (0.0, 5.0 * float(action[0])))


class BallEnv(KgeEnv):
    pass


def _ball_env(**kwargs) -> KgeEnv:
    args: dict[str, Any] = {
        "build": _build_ball,
        "act": _push,
        "observe": lambda world: np.array([world.get(1, Transform).y,
                                           world.get(1, RigidBody).velocity[1]]),
        "reward": lambda world, obs, action: -abs(float(obs[0]) - 2.0),
        "terminated": lambda world, obs: bool(obs[0] > 20.0),
        "action_space": gym.spaces.Box(-1.0, 1.0, (1,), np.float32),
        "observation_space": gym.spaces.Box(-100.0, 100.0, (2,), np.float32),
    }
    args.update(kwargs)
    return BallEnv(**args)


def test_env_from_plain_functions():
    env = _ball_env()
    check_env(env)
    obs, _ = env.reset(seed=1)
    assert 2.0 <= obs[0] <= 4.0
    for _ in range(120):
        obs, r, term, _trunc, _ = env.step(np.zeros(1, np.float32))
    assert abs(obs[0] - 0.25) < 0.02 and r == pytest.approx(-abs(obs[0] - 2.0))
    assert not term
    env.reset(seed=1)
    for _ in range(60):
        obs, *_ = env.step(np.ones(1, np.float32))  # 5 N up on a 0.25 kg box: 10 m/s^2 net
    assert obs[0] > 5.0


def test_subclass_methods():
    class Hover(KgeEnv):
        action_space = gym.spaces.Discrete(2)
        observation_space = gym.spaces.Box(-100.0, 100.0, (1,), np.float32)
        frame_skip = 2

        def build(self, world, rng):
            _build_ball(world, rng)

        def act(self, world, action):
            _push(world, [action])

        def observe(self, world):
            return np.array([world.get(1, Transform).y])

        def terminated(self, world, obs):
            return bool(obs[0] > 5.0)

    env = Hover()
    check_env(env)
    env.reset(seed=0)
    steps = 0
    while not env.step(1)[2]:
        steps += 1
    assert 5 < steps < 60
    assert env.app.world.resource(kge.Time).step == 2 * (steps + 1)


def test_constructor_refuses_bad_arguments():
    with pytest.raises(ValueError, match="render_mode"):
        _ball_env(render_mode="ascii")
    with pytest.raises(ValueError, match="frame_skip"):
        _ball_env(frame_skip=0)
    for bad in (0.0, -0.1, math.nan, math.inf):
        with pytest.raises(ValueError, match="fixed_dt"):
            _ball_env(fixed_dt=bad)
    with pytest.raises(TypeError, match="observation_space"):
        KgeEnv(build=_build_ball, action_space=gym.spaces.Discrete(2))
    with pytest.raises(TypeError, match="observe must be callable"):
        _ball_env(observe=3)


def test_human_mode_without_a_display_draws_offscreen():
    env = lunar_lander.LunarLander(render_mode="human")
    with pytest.warns(UserWarning, match="no display; frames are drawn offscreen"):
        env.reset(seed=0)
    env.step(lunar_lander.MAIN)  # each step draws its frame (warned once)
    assert env.app.headless
    env.close()
    with pytest.raises(ResetNeededError):
        env.step(0)


def test_reset_options_reach_build():
    class Dropped(KgeEnv):
        action_space = gym.spaces.Discrete(1)
        observation_space = gym.spaces.Box(-100.0, 100.0, (1,), np.float32)

        def build(self, world, rng):
            world.spawn(Transform(0.0, self.options.get("height", 2.0)), RigidBody(),
                        Collider(Box(0.25, 0.25)))

        def observe(self, world):
            return np.array([world.get(1, Transform).y])

    env = Dropped()
    assert env.reset(seed=0, options={"height": 7.5})[0][0] == pytest.approx(7.5)
    assert env.reset(seed=0)[0][0] == pytest.approx(2.0)
    with pytest.raises(TypeError, match=r"Dropped.reset\(options=...\) must be a dict"):
        env.reset(options=[1])  # type: ignore[arg-type]
