"""The fixed-step accumulator, fed with explicit frame times."""

import pytest

from kge import FixedTimestep

DT = 1 / 60


def run(ts: FixedTimestep, frames: list[float]) -> list[int]:
    return [ts.advance(f) for f in frames]


def test_one_step_per_frame_at_the_fixed_rate() -> None:
    ts = FixedTimestep(fixed_dt=DT)
    assert run(ts, [DT] * 10) == [1] * 10
    assert ts.alpha == pytest.approx(0.0, abs=1e-6)


def test_fast_frames_accumulate_and_alpha_is_the_leftover_fraction() -> None:
    ts = FixedTimestep(fixed_dt=DT)
    assert run(ts, [DT / 4] * 3) == [0, 0, 0]
    assert ts.alpha == pytest.approx(0.75)
    assert ts.advance(DT / 4) == 1
    assert ts.alpha == pytest.approx(0.0, abs=1e-6)


def test_slow_frame_runs_several_steps_and_keeps_the_remainder() -> None:
    ts = FixedTimestep(fixed_dt=0.01)
    assert ts.advance(0.035) == 3
    assert ts.alpha == pytest.approx(0.5)


def test_max_steps_clamp_drops_the_backlog() -> None:
    ts = FixedTimestep(fixed_dt=0.01, max_steps_per_frame=4, max_frame_dt=1.0)
    assert ts.advance(0.5) == 4  # 50 steps worth, capped at 4
    assert ts.accumulator < 0.01  # the backlog is gone, not carried into the next frame
    assert ts.advance(0.01) == 1


def test_max_frame_dt_clamps_a_hitch() -> None:
    ts = FixedTimestep(fixed_dt=0.01, max_steps_per_frame=100, max_frame_dt=0.05)
    assert ts.advance(3.0) == 5


def test_time_scale_zero_freezes_and_two_doubles() -> None:
    frozen = FixedTimestep(fixed_dt=DT, time_scale=0.0)
    assert run(frozen, [DT] * 5) == [0] * 5
    fast = FixedTimestep(fixed_dt=DT, time_scale=2.0)
    assert run(fast, [DT] * 5) == [2] * 5
    slow = FixedTimestep(fixed_dt=DT, time_scale=0.5)
    assert sum(run(slow, [DT] * 10)) == 5


def test_pause_runs_nothing_and_single_step_runs_exactly_one() -> None:
    ts = FixedTimestep(fixed_dt=DT)
    ts.paused = True
    assert run(ts, [DT] * 3) == [0, 0, 0]
    ts.single_step()
    assert run(ts, [DT] * 3) == [1, 0, 0]
    ts.paused = False
    assert ts.advance(DT) == 1


def test_bad_settings_are_refused() -> None:
    with pytest.raises(ValueError, match="fixed_dt"):
        FixedTimestep(fixed_dt=0.0)
    with pytest.raises(ValueError, match="time_scale"):
        FixedTimestep(time_scale=-1.0)
