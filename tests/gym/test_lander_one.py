"""The single env's float versions of the lander's rules give the row versions' bits."""

from __future__ import annotations

from typing import Any

import numpy as np
import pytest

pytest.importorskip("gymnasium")

from kge.gym import lunar_lander as L


class _Pushes:
    """Records apply_linear_impulse calls (the physics side of ``fire``)."""

    def __init__(self) -> None:
        self.calls: list[tuple[int, tuple[float, ...], tuple[float, ...]]] = []

    def apply_linear_impulse(self, e: int, impulse: Any, point: Any) -> None:
        self.calls.append((e, tuple(map(float, impulse)), tuple(map(float, point))))


def _actions(continuous: bool, rng: np.random.Generator) -> list[Any]:
    if not continuous:
        return [0, 1, 2, 3]
    edges = [(0.0, 0.0), (1.0, -1.0), (0.3, 0.5), (-0.2, 0.50001), (0.7, -0.9)]
    return edges + [tuple(v) for v in rng.uniform(-1, 1, (40, 2)).astype(np.float32)]


@pytest.mark.parametrize("continuous", [False, True])
def test_throttles_and_impulses_match_the_rows_bit_for_bit(continuous: bool) -> None:
    rng = np.random.default_rng(5)
    for action in _actions(continuous, rng):
        rows = np.asarray(action, dtype=np.float64).reshape(1, -1)
        m, s, d = L.throttles(rows, continuous)
        assert L.throttle_one(action, continuous) == (float(m[0]), float(s[0]), float(d[0]))
        pose = rng.uniform((0, 0, -3), (20, 13, 3), (1, 3))
        disp = rng.uniform(-1, 1, (1, 2))
        row, one = _Pushes(), _Pushes()
        L.fire(row, [7], pose, disp, m, s, d)  # type: ignore[arg-type]
        L.fire_one(one, 7, tuple(pose[0].tolist()), tuple(disp[0].tolist()),  # type: ignore[arg-type]
                   *L.throttle_one(action, continuous))
        assert one.calls == row.calls


def test_observation_and_reward_match_the_rows_bit_for_bit() -> None:
    rng = np.random.default_rng(9)
    for _ in range(200):
        state = rng.normal(0, 5, 6)
        legs = tuple(bool(v) for v in rng.integers(0, 2, 2))
        obs = L.observations(state[None, :], np.array([legs], np.float64), 3.3)[0]
        one = L.observation_one(tuple(state.tolist()), legs, 3.3)  # type: ignore[arg-type]
        assert one.dtype == np.float32 and one.tobytes() == obs.tobytes()
        prev = None if rng.random() < 0.2 else float(rng.normal(0, 50))
        m, s = float(rng.integers(0, 2)), float(rng.random() * rng.integers(0, 2))
        over, awake = bool(rng.random() < 0.1), bool(rng.random() < 0.9)
        r, shaped = L.rewards(obs[None, :], np.array([np.nan if prev is None else prev]),
                              np.array([m]), np.array([s]), np.array([over]), np.array([awake]))
        assert L.reward_one(obs, prev, m, s, over, awake) == (float(r[0]), float(shaped[0]))
