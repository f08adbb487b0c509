"""kge.box2d tests: ``Box2D`` is kge.box2d while a test runs (``b2`` fixture)."""

from __future__ import annotations

import sys
from collections.abc import Iterator
from types import ModuleType

import pytest

import kge.box2d

# the programs import Box2D at module level: they run only through test_programs
# (with kge.box2d installed), never by doctest collection
collect_ignore_glob = ["programs/*"]


@pytest.fixture
def installed() -> Iterator[ModuleType]:
    """``import Box2D`` gives kge.box2d during the test; the previous modules come back after."""
    saved = {k: sys.modules.get(k) for k in ("Box2D", "Box2D.b2", "Box2D.Box2D")}
    kge.box2d.install()
    yield kge.box2d
    for k, v in saved.items():
        if v is None:
            sys.modules.pop(k, None)
        else:
            sys.modules[k] = v
