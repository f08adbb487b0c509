"""Systems and the order they run in.

A system is an :class:`esper.Processor` with a ``stage`` and an ``order``. Each
frame the App runs the stages in this order (see DESIGN.md "Frame order"):

=========  =======================================================================
INPUT      once per frame: input events delivered to behaviour hooks (100)
FIXED      zero or more times per frame, dt = fixed_dt:
           behaviours ``on_fixed_update`` (100) -> physics (200) -> contact
           events delivered to behaviours (300)
UPDATE     once per frame, dt = scaled frame time: behaviours ``on_update`` and
           coroutines (100), animation (200)
LATE       ``on_late_update`` (100), camera follow (200)
RENDER     drawing (never in headless tests unless asked)
=========  =======================================================================

Within a stage, lower ``order`` runs first (ties: insertion order). The world
is in deferred mode while a system runs and queued changes are flushed after
each system, so every system sees the changes of the ones before it.
"""

from __future__ import annotations

from enum import IntEnum
from typing import TYPE_CHECKING, ClassVar, TypeVar

import esper

if TYPE_CHECKING:
    from kge.world import World

#: a System subclass: ``add`` and ``get`` give back the type they were given
S = TypeVar("S", bound="System")


class Stage(IntEnum):
    INPUT = 0
    FIXED = 1
    UPDATE = 2
    LATE = 3
    RENDER = 4


class System(esper.Processor):
    """Base class for kge systems. Override :meth:`process` (and optionally the others)."""

    stage: ClassVar[Stage] = Stage.UPDATE
    order: ClassVar[int] = 500
    world: World

    def attach(self, world: World) -> None:
        """Called once when the system is added to ``world``."""
        self.world = world

    def process(self, dt: float) -> None:  # pragma: no cover - abstract
        raise NotImplementedError

    def detach(self) -> None:
        """Called when the world closes (free windows, players, spaces)."""


class Schedule:
    """The systems of one world, grouped by stage and sorted by order."""

    def __init__(self, world: World) -> None:
        self.world = world
        self._systems: list[System] = []
        self._by_stage: dict[Stage, list[System]] = {s: [] for s in Stage}

    def add(self, system: S) -> S:
        if not isinstance(system, System):
            raise TypeError(f"expected a kge.System instance, got {type(system).__name__}")
        self._systems.append(system)
        stage = self._by_stage[system.stage]
        stage.append(system)
        stage.sort(key=lambda s: s.order)  # stable: ties keep insertion order
        try:
            system.attach(self.world)
        except BaseException:
            self._systems.remove(system)
            stage.remove(system)
            raise
        return system

    def get(self, system_type: type[S]) -> S | None:
        for s in self._systems:
            if isinstance(s, system_type):
                return s
        return None

    def remove(self, system_type: type[System]) -> None:
        for s in list(self._systems):
            if isinstance(s, system_type):
                self._systems.remove(s)
                self._by_stage[s.stage].remove(s)
                s.detach()

    def run(self, stage: Stage, dt: float) -> None:
        """Run every system of ``stage``, flushing queued changes after each."""
        world = self.world
        for system in self._by_stage[stage]:
            world.run_deferred(system.process, dt)

    def systems(self, stage: Stage | None = None) -> list[System]:
        return list(self._systems if stage is None else self._by_stage[stage])

    def close(self) -> None:
        for s in reversed(self._systems):
            s.detach()
        self._systems.clear()
        for lst in self._by_stage.values():
            lst.clear()
