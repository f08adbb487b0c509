"""A physics world stepped by hand, for the tilemap tests."""

from __future__ import annotations

from collections.abc import Iterator
from typing import Any

import pytest

from kge.schedule import Stage
from kge.systems.physics import PhysicsPlugin
from kge.world import World

DT = 1.0 / 60.0


class Stepper:
    def __init__(self) -> None:
        self.world = World()
        self.world.add_plugins(PhysicsPlugin())

    def step(self, n: int = 1) -> None:
        for _ in range(n):
            self.world.clear_events()
            self.world.schedule.run(Stage.FIXED, DT)


@pytest.fixture
def sim() -> Stepper:
    return Stepper()


@pytest.fixture
def apps() -> Iterator[list[Any]]:
    """Apps a render test made, closed after it."""
    made: list[Any] = []
    yield made
    for a in made:
        a.close()
