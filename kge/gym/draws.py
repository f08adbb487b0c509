"""``PairDraws``: one ``uniform(-1, 1, size=2)`` per generator per step, drawn in blocks.

The batched LunarLander draws each env's engine dispersion from that env's own
generator, in the single env's order (so env i replays a single env seeded
alike). One ``Generator.uniform`` call costs about 1.4 µs whatever its size, so
64 envs paid 90 µs a step for 128 numbers. Here each generator draws
:attr:`PairDraws.block` steps' pairs at once (``uniform(size=(block, 2))``
yields exactly the numbers of ``block`` calls of ``size=2``, in order), and
the pairs are handed out one step at a time with one numpy index for all envs.

A generator that is also used for something else (the env's reset draws its
terrain from it) must first get back the pairs not handed out yet:
:meth:`PairDraws.give_back` restores the state it had before the block and
draws again only the pairs already used, so the stream continues exactly where
one draw per step would have left it.

>>> rngs = [np.random.default_rng(1), np.random.default_rng(2)]
>>> draws = PairDraws(2, block=4)
>>> first = draws.take(rngs)
>>> draws.give_back([0, 1])
>>> same = [np.random.default_rng(s) for s in (1, 2)]
>>> [same[0].uniform(-1.0, 1.0, size=2) for _ in range(1)][0].tolist() == first[0].tolist()
True
>>> rngs[1].random() == (same[1].uniform(-1.0, 1.0, size=2), same[1].random())[1]
True
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

import numpy as np


class PairDraws:
    """Pre-drawn ``uniform(-1, 1, size=2)`` pairs of ``n`` generators."""

    def __init__(self, n: int, block: int = 64) -> None:
        self.block = block
        self._pairs = np.empty((n, block, 2))
        self._next = np.full(n, block)  # index of each generator's next pair (block: none)
        #: (generator, its state before the block) of each generator with a block
        self._saved: list[tuple[np.random.Generator, Any] | None] = [None] * n
        self._rows = np.arange(n)

    def take(self, rngs: Sequence[np.random.Generator]) -> np.ndarray:
        """The next pair of every generator, an (n, 2) array (row i from ``rngs[i]``)."""
        for i in np.flatnonzero(self._next >= self.block).tolist():
            rng = rngs[i]
            self._saved[i] = (rng, rng.bit_generator.state)
            self._pairs[i] = rng.uniform(-1.0, 1.0, size=(self.block, 2))
            self._next[i] = 0
        out = self._pairs[self._rows, self._next]
        self._next += 1
        return out

    def give_back(self, envs: Sequence[int]) -> None:
        """Rewind these generators to just after the pairs handed out so far."""
        for i in envs:
            saved = self._saved[i]
            if saved is None:
                continue
            self._saved[i] = None
            used = int(self._next[i])
            self._next[i] = self.block
            if used >= self.block:
                continue  # the whole block was used: the generator is where it should be
            rng, state = saved
            rng.bit_generator.state = state
            if used:
                rng.uniform(-1.0, 1.0, size=(used, 2))
