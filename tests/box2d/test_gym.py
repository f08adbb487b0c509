"""Gymnasium's Box2D environments run unmodified on kge.box2d (pybox2d not used).

LunarLander's own heuristic controller must land (score >= 200) and the episode
must end the way it does on pybox2d, by the lander falling asleep (Box2D's
sleep rules: 0.5 s at rest), not by the time limit.
"""

from __future__ import annotations

import sys
from types import ModuleType

import numpy as np
import pytest


@pytest.fixture
def gym(installed: ModuleType) -> ModuleType:
    for name in [m for m in sys.modules if m.startswith("gymnasium.envs.box2d")]:
        del sys.modules[name]  # re-import against kge.box2d
    import gymnasium

    return gymnasium


@pytest.mark.parametrize("continuous", [False, True])
def test_lunar_lander_heuristic_lands(gym: ModuleType, continuous: bool) -> None:
    """The heuristic lands (score >= 200, no crash, the episode ended by the lander
    falling asleep) on at least 9 of seeds 0-9, as on pybox2d 2.3.10 (9 of 10
    discrete, 10 of 10 continuous; 46 and 50 of seeds 0-49, kge 45 and 49).

    Which seeds land is chaotic: a landing leg touching down 4 mm higher (kge
    settles new contacts at the linear slop, as Box2D's time of impact does, where
    it used to sink first) turns discrete seed 0 from a landing into a slide off
    the pad, and pybox2d itself misses discrete seed 8. So the test counts.
    """
    from gymnasium.envs.box2d import lunar_lander

    import kge.box2d

    assert lunar_lander.Box2D is kge.box2d
    env = gym.make("LunarLander-v3", continuous=continuous)
    landed = []
    for seed in range(10):
        s, _ = env.reset(seed=seed)
        total = 0.0
        while True:
            s, r, term, trunc, _ = env.step(lunar_lander.heuristic(env.unwrapped, s))
            total += float(r)
            if term or trunc:
                break
        game = env.unwrapped
        asleep = not game.lander.awake  # the episode ended the Box2D way
        if term and not trunc and asleep and not game.game_over and total >= 200.0:
            landed.append(seed)
    env.close()
    assert len(landed) >= 9, f"landed on seeds {landed}"


def test_bipedal_walker_steps(gym: ModuleType) -> None:
    env = gym.make("BipedalWalker-v3")
    s, _ = env.reset(seed=0)
    assert s.shape == (24,)
    for _ in range(100):
        s, _r, term, _trunc, _ = env.step(np.array([0.3, -0.5, 0.3, -0.5], dtype=np.float32))
        assert np.all(np.isfinite(s))
        if term:
            break
    lidar = s[14:]
    assert np.all((lidar > 0.0) & (lidar <= 1.0))  # ray casts clipped at the terrain
    assert lidar.min() < 1.0
    env.close()


def test_bipedal_walker_heuristic_walks(gym: ModuleType) -> None:
    """The environment's own heuristic walks (seed 0 finishes on pybox2d, 314.6).

    It stood stiff-legged or fell within 15 m before Box2D's position iterations
    were modelled (the legs are built 0.5 m from their hips) and before the legs'
    reference angle followed pybox2d's constructor rule.
    """
    from gymnasium.envs.box2d import bipedal_walker

    env = gym.make("BipedalWalker-v3")
    walker = bipedal_walker.BipedalWalkerHeuristics()
    s, _ = env.reset(seed=0)
    a = np.zeros(4)
    total, hull = 0.0, env.unwrapped.hull
    for _ in range(600):
        s, r, term, _trunc, _ = env.step(a)
        total += float(r)
        assert not term, f"fell at x={hull.position.x:.1f}"
        a = walker.step_heuristic(s)
    assert hull.position.x > 25.0  # 12 s of walking: pybox2d 33.9 m, kge.box2d 35.6 m
    assert total > 60.0  # pybox2d 108.3, kge.box2d 113.8
    env.close()


def test_bipedal_walker_hardcore_resets(gym: ModuleType) -> None:
    env = gym.make("BipedalWalkerHardcore-v3")
    for seed in (0, 1):
        s, _ = env.reset(seed=seed)
        for _ in range(20):
            s, *_ = env.step(np.zeros(4, dtype=np.float32))
        assert np.all(np.isfinite(s))
    env.close()


def test_car_racing_steps(gym: ModuleType) -> None:
    env = gym.make("CarRacing-v3")
    obs, _ = env.reset(seed=0)
    total = 0.0
    for i in range(60):
        obs, r, _term, _trunc, _ = env.step(np.array([0.0, 1.0 if i < 40 else 0.0, 0.0]))
        total += float(r)
    assert obs.shape == (96, 96, 3)
    car = env.unwrapped.car
    assert car.hull.linearVelocity.length > 1.0  # the wheels' friction drove it
    assert env.unwrapped.tile_visited_count > 0  # sensor tiles reported BeginContact
    env.close()


def test_lunar_lander_renders_with_particles(gym: ModuleType) -> None:
    """rgb_array rendering reads shapes and transforms; engine particles are bodies
    created and destroyed every step."""
    from gymnasium.envs.box2d import lunar_lander

    env = gym.make("LunarLander-v3", render_mode="rgb_array")
    s, _ = env.reset(seed=0)
    most = 0
    for _ in range(80):
        s, *_ = env.step(lunar_lander.heuristic(env.unwrapped, s))
        frame = env.render()
        most = max(most, len(env.unwrapped.particles))
    assert frame.shape == (400, 600, 3) and frame.std() > 0
    assert most > 0
    world = env.unwrapped.world
    assert world.bodyCount == 4 + len(env.unwrapped.particles)  # moon, lander, 2 legs
    env.close()
