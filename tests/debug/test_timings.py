"""Per-system timings: off by default (no clock read), counted per run and per frame
when on, in the schedule table, the stats overlay and ``kge schedule --timings``."""

from __future__ import annotations

import itertools

import kge.schedule
from kge import App, Box, Collider, RigidBody, Stage, System, Transform, World
from kge.components.debug import DebugDraw
from kge.timings import SystemTimings


def level(world: World) -> None:
    world.spawn(Transform(0, -1), Collider(Box(5, 1)))
    world.spawn(Transform(0, 3), RigidBody(), Collider(Box(0.5, 0.5)))


class Tick(System):
    stage = Stage.FIXED

    def process(self, dt: float) -> None:
        pass


def _fake_clock(monkeypatch, step: float = 0.001) -> None:
    counter = itertools.count()
    monkeypatch.setattr(kge.schedule.time, "perf_counter", lambda: next(counter) * step)


def test_off_by_default_the_clock_is_never_read(monkeypatch) -> None:
    app = App(level, headless=True)
    assert app.world.schedule.timings is None

    def no_clock() -> float:
        raise AssertionError("timings are off: perf_counter must not be called")

    monkeypatch.setattr(kge.schedule.time, "perf_counter", no_clock)
    app.step(3)


def test_each_run_is_counted_and_a_frame_sums_its_fixed_steps(monkeypatch) -> None:
    app = App(level, headless=True)
    tick = app.world.add_system(Tick())
    timings = app.world.schedule.enable_timings()
    _fake_clock(monkeypatch)  # every system run takes exactly 1 ms
    app.advance(3 / 60 + 1e-6)  # a frame of three fixed steps
    row = timings.of(tick)
    assert row is not None and row.calls == 3
    assert abs(row.frame - 3.0) < 1e-9 and abs(row.peak - 3.0) < 1e-9
    app.advance(1 / 60)
    row = timings.of(tick)
    assert row is not None and row.calls == 4 and abs(row.frame - 1.0) < 1e-9 and abs(row.peak - 3.0) < 1e-9
    names = [r.name for r in timings.rows()]
    assert "PhysicsSystem" in names and "Tick" in names and "UpdateBehaviours" in names
    assert "PhysicsSystem" in timings.describe()
    timings.reset()
    reset = timings.of(tick)
    assert reset is not None and reset.calls == 0
    app.world.schedule.remove(Tick)
    assert timings.of(tick) is None
    app.world.schedule.disable_timings()
    assert app.world.schedule.timings is None


def test_the_average_smooths_frames() -> None:
    t = SystemTimings()
    s = object()
    t.add(s, "UPDATE", 0.010)
    t.end_frame()
    for _ in range(30):
        t.add(s, "UPDATE", 0.001)
        t.end_frame()
    row = t.of(s)
    assert row is not None and 1.0 < row.average < 10.0 and row.peak == 10.0 and row.frame == 1.0


def test_f4_shows_the_slowest_systems_in_the_stats_overlay() -> None:
    from kge import Key
    from kge.systems.render import RenderSystem

    app = App(level, headless=True, size=(320, 200))
    app.input.press(Key.F4)
    app.step(2)
    settings = app.world.resource(DebugDraw)
    assert settings.stats and settings.timings and app.world.schedule.timings is not None
    app.render()
    render = app.world.get_system(RenderSystem)
    assert render is not None
    text = render.view.stats.table_text
    assert "PhysicsSystem" in text and "ms/frame" in text
    app.input.release(Key.F4)
    app.step(1)
    app.input.press(Key.F4)
    app.step(1)
    assert app.world.schedule.timings is None and not settings.timings


def test_kge_schedule_prints_measured_timings(capsys) -> None:
    from kge.schedule_cli import main

    assert main(["--timings", "5"]) == 0
    out = capsys.readouterr().out
    assert "avg ms" in out and "PhysicsSystem" in out


def test_timings_take_the_clock_they_are_given() -> None:
    ticks = iter(range(1000))

    class Work(System):
        stage = Stage.FIXED

        def process(self, dt: float) -> None:
            pass

    app = App(lambda world: None, headless=True)
    work = app.world.add_system(Work())
    timings = app.world.schedule.enable_timings(lambda: float(next(ticks)))
    app.step(1)
    row = timings.of(work)
    assert row is not None and row.last == 1000.0  # one tick of the fake clock, in ms
