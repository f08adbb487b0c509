"""Where a kge frame goes: sync-in, step, sync-out, events, the rest.

The timers wrap methods of one App's physics objects *on the instance* (the
class is untouched), so kge itself carries no timing code and pays nothing when
no breakdown is asked for:

* ``sync-in``: :meth:`Simulation.sync_in` (structural changes, user writes);
* ``step``: :meth:`Simulation.step` minus the other physics phases, i.e. the
  pymunk substeps with joints, continuous collision and the contact callbacks
  that record events while pymunk runs;
* ``sync-out``: :meth:`Simulation.sync_out` (bulk pose read, component writes);
* ``events``: raising the recorded events and delivering them (esper handlers,
  Behaviour hooks: :class:`~kge.systems.physics.PhysicsEventDelivery`);
* ``other``: the rest of the frame (behaviours, flushes, update pass).

Render sync has no place in a headless physics frame; it is measured on its own
(:mod:`benchmarks.render_sync`) and reported beside this table.
"""

from __future__ import annotations

import statistics
import time
from collections.abc import Callable
from typing import Any

from kge.app import App
from kge.systems.physics import PhysicsEventDelivery, PhysicsSystem

PHASES = ("sync-in", "step", "sync-out", "events", "other")


def timed(acc: dict[str, float], inner: Callable[..., Any], key: str) -> Callable[..., Any]:
    """``inner`` that adds the seconds each call takes to ``acc[key]``."""
    clock = time.perf_counter

    def run(*args: Any, **kwargs: Any) -> Any:
        t0 = clock()
        try:
            return inner(*args, **kwargs)
        finally:
            acc[key] = acc.get(key, 0.0) + clock() - t0

    return run


class PhaseTimer:
    """Accumulates time per phase for the frames of one App."""

    def __init__(self, app: App) -> None:
        self.app = app
        self.acc: dict[str, float] = {}
        world = app.world
        physics = world.get_system(PhysicsSystem)
        if physics is None:
            raise RuntimeError("breakdown needs a world with a PhysicsSystem")
        sim = physics.sim
        self._wrap(sim, "sync_in", "sync-in")
        self._wrap(sim, "sync_out", "sync-out")
        self._wrap(sim, "step", "physics")
        self._wrap(sim.recorder, "deliver_post_solve", "recorded-events")
        delivery = world.get_system(PhysicsEventDelivery)
        if delivery is not None:
            self._wrap(delivery, "process", "delivery")
        self.frames: list[dict[str, float]] = []

    def _wrap(self, obj: Any, method: str, key: str) -> None:
        setattr(obj, method, timed(self.acc, getattr(obj, method), key))

    def frame(self) -> None:
        """Run one frame and record its phases (ms)."""
        self.acc.clear()
        t0 = time.perf_counter()
        self.app.step()
        total = time.perf_counter() - t0
        a = self.acc
        physics, rec = a.get("physics", 0.0), a.get("recorded-events", 0.0)
        sync_in, sync_out = a.get("sync-in", 0.0), a.get("sync-out", 0.0)
        delivery = a.get("delivery", 0.0)
        phases = {
            "sync-in": sync_in,
            "step": physics - sync_in - sync_out - rec,
            "sync-out": sync_out,
            "events": rec + delivery,
            "other": total - physics - delivery,
            "total": total,
        }
        self.frames.append({k: v * 1000.0 for k, v in phases.items()})

    def medians(self) -> dict[str, float]:
        """Median ms per phase over the recorded frames."""
        keys = (*PHASES, "total")
        return {k: statistics.median(f[k] for f in self.frames) for k in keys}


def breakdown(app: App, warmup: int, frames: int) -> dict[str, float]:
    """Median ms per phase of ``frames`` frames of ``app`` after ``warmup`` frames."""
    app.step(warmup)
    timer = PhaseTimer(app)
    for _ in range(frames):
        timer.frame()
    return timer.medians()
