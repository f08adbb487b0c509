"""Python's cyclic garbage collector paused around bulk creation of many objects.

Why: loading a large tile map creates about half a million container objects
(pymunk segments, their attribute dicts and user-data handles, CCD rows) that
all stay alive. While they pile up, the collector's full passes, which it
starts every time the heap grew by a quarter, walk the whole growing heap again
and again: on the 1,000 x 1,000 cave map that was a third of the load time
(4.5 s -> 3.0 s with the collector paused, docs/tilemaps.md). Pausing it for the
duration of one bulk operation defers that work to a single pass afterwards.
Garbage made meanwhile is collected at the next pass as usual; reference
counting frees everything that is not in a cycle at once, paused or not.

>>> import gc
>>> with paused_gc():
...     gc.isenabled()
False
>>> gc.isenabled()
True
"""

from __future__ import annotations

import functools
import gc
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from typing import ParamSpec, TypeVar

P = ParamSpec("P")
R = TypeVar("R")


@contextmanager
def paused_gc() -> Iterator[None]:
    """The collector off inside the block, back to how it was afterwards (nesting is fine)."""
    if not gc.isenabled():
        yield
        return
    gc.disable()
    try:
        yield
    finally:
        gc.enable()


def without_gc(fn: Callable[P, R]) -> Callable[P, R]:
    """``fn`` run with the collector paused, as :func:`paused_gc` (a decorator for bulk
    builders; a plain wrapper, cheaper than the context manager on hot paths)."""

    @functools.wraps(fn)
    def run(*args: P.args, **kwargs: P.kwargs) -> R:
        if not gc.isenabled():  # already paused by a caller
            return fn(*args, **kwargs)
        gc.disable()
        try:
            return fn(*args, **kwargs)
        finally:
            gc.enable()

    return run
