"""App: scenes (setup functions and classes), the stack, kwargs, frame order."""

from dataclasses import dataclass

import pytest

from kge import App, Behaviour, Scene, Script, Stage, System, Time, World


@dataclass(slots=True)
class Level:
    number: int


def level_scene(world: World, number: int = 1) -> None:
    world.spawn(Level(number))


def levels(app: App) -> list[int]:
    return [lv.number for _, (lv,) in app.world.query(Level)]


def test_function_scene_and_step_count() -> None:
    app = App(level_scene, headless=True)
    app.step(10)
    assert levels(app) == [1]
    assert app.world.resource(Time).step == 10
    assert app.world.resource(Time).elapsed == pytest.approx(10 / 60)


def test_replace_scene_passes_kwargs_and_closes_the_old_world() -> None:
    app = App(level_scene, headless=True, number=1)
    old = app.world
    app.replace_scene(level_scene, number=7)
    assert levels(app) == [7]
    assert old.closed and app.world is not old
    assert len(app.scenes) == 1


class Menu(Scene):
    def __init__(self) -> None:
        self.log: list[str] = []

    def setup(self, world: World, heading: str = "menu") -> None:
        world.spawn(Level(0))
        self.log.append(f"setup {heading}")

    def on_pause(self, world: World) -> None:
        self.log.append("pause")

    def on_resume(self, world: World) -> None:
        self.log.append("resume")

    def on_exit(self, world: World) -> None:
        self.log.append("exit")


def test_scene_stack_push_pop_with_hooks() -> None:
    menu = Menu()
    app = App(menu, headless=True, heading="main")
    menu_world = app.world
    app.push_scene(level_scene, number=3)
    assert levels(app) == [3]
    assert menu.log == ["setup main", "pause"]
    app.step(5)
    assert menu_world.resource(Time).step == 0  # the scene below does not run
    app.pop_scene()
    assert app.world is menu_world and levels(app) == [0]
    assert menu.log[-1] == "resume"
    app.close()
    assert menu.log[-1] == "exit"


def test_scene_class_is_instantiated() -> None:
    class Lvl(Scene):
        def setup(self, world: World, number: int = 2) -> None:
            world.spawn(Level(number))

    app = App(Lvl, headless=True, number=5)
    assert levels(app) == [5]


def test_replace_scene_from_a_script_takes_effect_after_the_frame() -> None:
    class Restart(Script):
        def on_fixed_update(self, dt: float) -> None:
            self.world.resource(App).replace_scene(level_scene, number=99)

    def first(world: World) -> None:
        world.spawn(Level(1), Behaviour(Restart()))

    app = App(first, headless=True)
    world = app.world
    app.step()
    assert world.closed
    assert levels(app) == [99]


class Recorder(System):
    stage = Stage.UPDATE

    def __init__(self, log: list[str], name: str, stage: Stage) -> None:
        self.log = log
        self.name = name
        self.stage = stage  # type: ignore[misc]

    def process(self, dt: float) -> None:
        self.log.append(self.name)


def test_frame_order_fixed_steps_then_update_then_late() -> None:
    log: list[str] = []

    class Probe(Script):
        def on_fixed_update(self, dt: float) -> None:
            log.append("fixed")

        def on_update(self, dt: float) -> None:
            log.append("update" if dt > 0 else "update dt=0")

        def on_late_update(self, dt: float) -> None:
            log.append("late")

    def scene(world: World) -> None:
        world.spawn(Behaviour(Probe()))

    app = App(scene, headless=True)
    app.advance(2.5 / 60)  # two fixed steps fit in this frame
    assert log == ["fixed", "fixed", "update", "late"]
    assert app.alpha == pytest.approx(0.5)
    log.clear()
    app.paused = True
    app.advance(1 / 60)
    # paused: no fixed step; update still runs (menus, an unpause key) with dt = 0
    assert log == ["update dt=0", "late"]
    log.clear()
    app.single_step()
    app.advance(1 / 60)
    assert log == ["fixed", "update", "late"]


def test_time_scale_scales_update_dt() -> None:
    dts: list[float] = []

    class Probe(Script):
        def on_update(self, dt: float) -> None:
            dts.append(dt)

    def scene(world: World) -> None:
        world.spawn(Behaviour(Probe()))

    app = App(scene, headless=True, time_scale=2.0)
    steps = app.advance(1 / 60)
    assert steps == 2 and dts == [pytest.approx(2 / 60)]
    app.time_scale = 0.0
    assert app.advance(1 / 60) == 0 and dts[-1] == 0.0


def test_custom_system_runs_in_its_stage() -> None:
    log: list[str] = []
    app = App(level_scene, headless=True)
    app.world.add_system(Recorder(log, "late-sys", Stage.LATE))
    app.world.add_system(Recorder(log, "fixed-sys", Stage.FIXED))
    app.step()
    assert log == ["fixed-sys", "late-sys"]


def test_headless_run_stops_after_frames_or_quit() -> None:
    class Quit(Script):
        def on_update(self, dt: float) -> None:
            if self.world.resource(Time).frame >= 5:
                self.world.resource(App).quit()

    def scene(world: World) -> None:
        world.spawn(Behaviour(Quit()))

    app = App(scene, headless=True)
    app.run(frames=100)
    assert app.world.resource(Time).frame == 5
    app2 = App(level_scene, headless=True)
    app2.run(frames=7)
    assert app2.world.resource(Time).step == 7
