"""The frame order: named sets, before/after, ties reported, cycles refused, the old
integer ``order`` still placed (with a DeprecationWarning), and ``kge schedule``."""

from __future__ import annotations

import warnings

import pytest

import kge
from kge import App, ScheduleError, Stage, System, SystemSet, World
from kge.schedule import FRAME
from kge.schedule_cli import frame_table, main

#: the frame of the default plugins, stage by stage (kge schedule prints it)
DEFAULT_FRAME = {
    Stage.INPUT: [
        ("AnimationFrameStart", "first"),
        ("GizmoFrameStart", "first"),
        ("DebugInput", "debug"),
        ("DebugKeys", "debug"),
        ("UIInput", "ui"),
        ("InputBehaviours", "scripts"),
    ],
    Stage.FIXED: [
        ("GizmoStepStart", "first"),
        ("FixedBehaviours", "scripts"),
        ("FixedTweens", "pre_physics"),
        ("CharacterSystem", "characters"),
        ("PhysicsSystem", "physics"),
        ("CharacterSensorSystem", "physics"),
        ("PhysicsEventDelivery", "physics_events"),
        ("ParticleTriggers", "post_physics"),
    ],
    Stage.UPDATE: [
        ("ShakeRestore", "first"),
        ("GizmoUpdateStart", "first"),
        ("UpdateBehaviours", "scripts"),
        ("AnimationSystem", "animation"),
        ("TileAnimationSystem", "animation"),
        ("TweenSystem", "animation"),
        ("TimelineSystem", "animation"),
        ("ParticleTurbulenceSystem", "effects"),
        ("ParticleSystem", "effects"),
        ("ParticleEffectsSystem", "effects"),
    ],
    Stage.LATE: [
        ("LateBehaviours", "scripts"),
        ("CameraFollow", "camera"),
        ("AudioSystem", "audio"),
        ("ShakeApply", "camera_effects"),
    ],
    Stage.RENDER: [("_LightMapOwner", "last")],
}


def _frame(world: World) -> dict[Stage, list[tuple[str, str]]]:
    rows = world.schedule.table()
    return {st: [(r.system, r.set) for r in rows if r.stage is st] for st in Stage}


def test_the_default_plugins_run_in_the_documented_order_with_no_tie() -> None:
    app = App(lambda world: None, headless=True)
    assert _frame(app.world) == DEFAULT_FRAME
    assert app.world.schedule.ties() == []


def test_the_drawing_systems_join_at_the_first_render_with_no_tie() -> None:
    app = App(lambda world: None, headless=True)
    app.render()
    frame = _frame(app.world)
    assert frame[Stage.FIXED][0] == ("RenderStepClock", "first")
    assert frame[Stage.FIXED][-1] == ("RenderStepRecorder", "last")
    assert frame[Stage.RENDER] == [("RenderSystem", "draw"), ("_LightMapOwner", "last")]
    assert app.world.schedule.ties() == []


class Log(System):
    """A system that records its name when it runs."""

    stage = Stage.FIXED

    def __init__(self, log: list[str], label: str) -> None:
        self.log = log
        self.label = label

    def process(self, dt: float) -> None:
        self.log.append(self.label)


class A(Log):
    pass


class B(Log):
    pass


class C(Log):
    pass


def test_sets_run_in_frame_order_whatever_the_order_of_adding() -> None:
    log: list[str] = []
    world = World()
    world.add_system(A(log, "game"))
    world.add_system(B(log, "physics"), in_set=SystemSet.PHYSICS)
    world.add_system(C(log, "scripts"), in_set=SystemSet.SCRIPTS)
    world.schedule.run(Stage.FIXED, 1 / 60)
    assert log == ["scripts", "physics", "game"]
    assert FRAME[Stage.FIXED].index(SystemSet.SCRIPTS) < FRAME[Stage.FIXED].index(SystemSet.GAME)


def test_before_and_after_order_systems_inside_a_set() -> None:
    log: list[str] = []
    world = World()
    a = world.add_system(A(log, "a"), after=[C])
    b = world.add_system(B(log, "b"), before=[A])
    c = world.add_system(C(log, "c"))
    world.schedule.run(Stage.FIXED, 1 / 60)
    assert log == ["b", "c", "a"]
    # b and c have no order between them: a tie, run in the order they were added
    assert world.schedule.ties() == [(Stage.FIXED, b, c)]
    assert [r.order for r in world.schedule.table()] == ["before A", "", "after C"]
    assert a.world is world


def test_an_unordered_pair_in_one_set_is_reported_as_a_tie() -> None:
    world = World()
    a = world.add_system(A([], "a"))
    b = world.add_system(B([], "b"))
    assert world.schedule.ties() == [(Stage.FIXED, a, b)]
    assert "TIE with B" in world.schedule.describe()
    world.schedule.remove(B)
    world.add_system(b, after=[A])
    assert world.schedule.ties() == []
    assert "TIE" not in world.schedule.describe()


def test_a_cycle_is_refused_and_the_schedule_is_unchanged() -> None:
    world = World()
    world.add_system(A([], "a"), after=[B])
    b = B([], "b")
    b.before = ()
    with pytest.raises(ScheduleError, match=r"cycle: .*A.*B|cycle: .*B.*A"):
        world.add_system(b, after=[A])
    assert [type(s).__name__ for s in world.schedule.systems()] == ["A"]
    assert not hasattr(b, "world")  # never attached
    with pytest.raises(ScheduleError, match="cycle"):  # a set it runs before
        world.add_system(C([], "c"), in_set=SystemSet.GAME, before=[SystemSet.PHYSICS])
    assert [type(s).__name__ for s in world.schedule.systems()] == ["A"]


def test_unknown_sets_and_anchors_in_another_stage_are_refused() -> None:
    world = World()
    class Update(System):
        stage = Stage.UPDATE

        def process(self, dt: float) -> None: ...

    with pytest.raises(ScheduleError, match="'physics' is not a set of UPDATE"):
        world.add_system(Update(), in_set=SystemSet.PHYSICS)
    with pytest.raises(ScheduleError, match="not a set of FIXED"):
        world.add_system(A([], "a"), after=["physics_step"])
    with pytest.raises(ScheduleError, match="runs in FIXED"):

        class Late(System):
            stage = Stage.LATE
            after = (A,)

            def process(self, dt: float) -> None: ...

        world.add_system(Late())
    assert world.schedule.systems() == []
    assert issubclass(ScheduleError, kge.KgeError) and issubclass(ScheduleError, ValueError)


def test_a_custom_set_sits_between_the_sets_it_names() -> None:
    log: list[str] = []
    world = World()
    world.schedule.add_set("ai", Stage.FIXED, after=[SystemSet.SCRIPTS],
                           before=[SystemSet.PHYSICS])  # fmt: skip
    world.add_system(A(log, "physics"), in_set=SystemSet.PHYSICS)
    world.add_system(B(log, "ai"), in_set="ai")
    world.add_system(C(log, "scripts"), in_set=SystemSet.SCRIPTS)
    world.schedule.run(Stage.FIXED, 1 / 60)
    assert log == ["scripts", "ai", "physics"]
    with pytest.raises(ScheduleError, match="already exists"):
        world.schedule.add_set("ai", Stage.FIXED)


def test_the_deprecated_integer_order_still_places_a_system() -> None:
    log: list[str] = []

    class Between(System):
        stage = Stage.FIXED
        order = 250  # between physics (200) and the contact hooks (300) before sets

        def process(self, dt: float) -> None:
            log.append("between")

    class Late(System):
        stage = Stage.FIXED
        order = 900

        def process(self, dt: float) -> None:
            log.append("late")

    class Early(System):
        stage = Stage.FIXED
        order = 600

        def process(self, dt: float) -> None:
            log.append("early")

    app = App(lambda world: None, headless=True)
    with pytest.warns(DeprecationWarning, match=r"Between.order = 250: place the system.*deprecated"):
        app.world.add_system(Between())
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", DeprecationWarning)
        app.world.add_system(Late())
        app.world.add_system(Early())
    frame = [type(s).__name__ for s in app.world.schedule.systems(Stage.FIXED)]
    assert frame.index("PhysicsSystem") < frame.index("Between") < frame.index(
        "PhysicsEventDelivery"
    )
    assert frame.index("ParticleTriggers") < frame.index("Early") < frame.index("Late")
    app.step(1)
    assert log == ["between", "early", "late"]


def test_the_plugin_that_added_each_system_is_recorded() -> None:
    app = App(lambda world: None, headless=True)
    rows = {r.system: r.plugin for r in app.world.schedule.table()}
    assert rows["PhysicsSystem"] == "PhysicsPlugin"
    assert rows["UIInput"] == "UIPlugin"
    assert rows["PhysicsEventDelivery"] == "PhysicsPlugin"


def test_kge_schedule_prints_the_live_frame(capsys: pytest.CaptureFixture[str]) -> None:
    assert main([]) == 0
    out = capsys.readouterr().out
    assert "ties: none" in out
    lines = [line.split() for line in out.splitlines() if line.startswith(("FIXED", "LATE"))]
    assert [line[2] for line in lines if line[0] == "FIXED"] == [
        name for name, _ in DEFAULT_FRAME[Stage.FIXED]
    ]
    assert main(["--plugins", "PhysicsPlugin"]) == 0
    physics_only = capsys.readouterr().out
    assert "PhysicsSystem" in physics_only and "UIInput" not in physics_only
    assert "TIE" in frame_table([kge.PhysicsPlugin()], scene=_two_game_systems)


def _two_game_systems(world: World) -> None:
    world.add_system(A([], "a"))
    world.add_system(B([], "b"))


def test_the_architecture_page_shows_the_live_frame() -> None:
    """docs/architecture.md prints the default frame: it must be the one kge runs."""
    import re
    from pathlib import Path

    page = Path(__file__).resolve().parents[2] / "docs" / "architecture.md"
    shown = re.search(r"<!-- kge schedule -->\n```text\n(.*?)\n```", page.read_text(), re.S)
    assert shown is not None
    app = App(lambda world: None, headless=True)
    assert shown.group(1) == app.world.schedule.describe(plugins=True)


def test_render_passes_run_in_named_order_with_no_tie() -> None:
    from kge.render.passes import RenderPasses

    app = App(lambda world: None, headless=True)
    passes = app.world.resource(RenderPasses)
    assert passes.names("before") == ["animation", "tilemap", "particles"]
    assert passes.names("view") == ["lighting"]  # once per camera
    assert passes.names("after") == ["gizmos", "ui", "debug_overlay"]
    assert passes.ties() == []
    log: list[str] = []
    passes.add(lambda frame: log.append("fog"), phase="view", name="fog", before=["lighting"])
    assert passes.names("view") == ["fog", "lighting"]
    with pytest.raises(ScheduleError, match="cycle"):
        passes.add(print, name="loop", after=["particles"], before=["animation"])
    assert "loop" not in passes.names("before")
    with pytest.warns(DeprecationWarning, match=r"RenderPasses.add\(order=0\)"):
        passes.add(lambda frame: None, name="old", order=0)  # between tile maps and particles
    names = passes.names("before")
    assert names.index("tilemap") < names.index("old") < names.index("particles")
