"""kge.gcpause: the collector is off inside, restored after, also on errors and when nested."""

from __future__ import annotations

import gc

import pytest

from kge.gcpause import paused_gc, without_gc


def test_without_gc_pauses_and_restores() -> None:
    seen = []

    @without_gc
    def inner() -> None:
        seen.append(gc.isenabled())

    @without_gc
    def outer() -> None:
        inner()
        seen.append(gc.isenabled())  # the nested call did not turn it back on

    outer()
    assert seen == [False, False] and gc.isenabled()


def test_the_collector_comes_back_after_an_error() -> None:
    @without_gc
    def boom() -> None:
        raise ValueError("x")

    with pytest.raises(ValueError):
        boom()
    assert gc.isenabled()
    with pytest.raises(KeyError), paused_gc():
        raise KeyError("y")
    assert gc.isenabled()


def test_a_collector_switched_off_by_the_caller_stays_off() -> None:
    gc.disable()
    try:
        with paused_gc():
            pass
        without_gc(lambda: None)()
        assert not gc.isenabled()
    finally:
        gc.enable()
