"""``PairDraws``: blocks of pre-drawn pairs give each generator exactly its per-step stream."""

from __future__ import annotations

import numpy as np

from kge.gym.draws import PairDraws


def test_blocks_and_give_backs_leave_every_stream_as_one_draw_per_step() -> None:
    n = 3
    mine = [np.random.default_rng(s) for s in range(n)]
    ref = [np.random.default_rng(s) for s in range(n)]
    draws = PairDraws(n, block=5)
    plan = np.random.default_rng(99)
    for _ in range(60):
        got = draws.take(mine)
        want = np.array([r.uniform(-1.0, 1.0, size=2) for r in ref])
        assert got.tobytes() == want.tobytes()
        back = np.flatnonzero(plan.random(n) < 0.2).tolist()
        draws.give_back(back)
        for i in back:  # the stream is shared with other draws (a scene reset's terrain)
            k = int(plan.integers(1, 4))
            assert mine[i].uniform(0, 5, size=k).tobytes() == ref[i].uniform(0, 5, size=k).tobytes()


def test_give_back_after_a_whole_block_or_none_changes_nothing() -> None:
    rng, ref = np.random.default_rng(7), np.random.default_rng(7)
    draws = PairDraws(1, block=2)
    draws.give_back([0])  # nothing drawn yet
    draws.take([rng])
    draws.take([rng])  # the block is used up
    draws.give_back([0])
    ref.uniform(-1.0, 1.0, size=(2, 2))
    assert rng.random() == ref.random()
