"""Behaviour scripts: hooks, start order, destroy, coroutines, signature errors."""

import pytest

from kge import (
    App,
    Behaviour,
    HookSignatureError,
    Script,
    Transform,
    Wait,
    WaitFrames,
    World,
)


def make_app(*scripts: Script) -> tuple[App, list[int]]:
    ids: list[int] = []

    def scene(world: World) -> None:
        for s in scripts:
            ids.append(world.spawn(Transform(), Behaviour(s)))

    return App(scene, headless=True), ids


def test_on_start_runs_once_before_updates_and_scripts_know_their_entity() -> None:
    log: list[tuple[str, int]] = []

    class S(Script):
        def on_start(self) -> None:
            log.append(("start", self.entity))

        def on_fixed_update(self, dt: float) -> None:
            log.append(("fixed", self.entity))

    app, ids = make_app(S(), S())
    app.step(2)
    assert log == [
        ("start", ids[0]), ("start", ids[1]),
        ("fixed", ids[0]), ("fixed", ids[1]),
        ("fixed", ids[0]), ("fixed", ids[1]),
    ]


def test_script_moves_its_transform() -> None:
    class Mover(Script):
        def on_update(self, dt: float) -> None:
            self.transform.x += 2.0 * dt

    app, ids = make_app(Mover())
    app.step(30)
    assert app.world.get(ids[0], Transform).x == pytest.approx(1.0)


def test_on_destroy_runs_when_despawned_and_when_the_scene_closes() -> None:
    destroyed: list[int] = []

    class S(Script):
        def on_destroy(self) -> None:
            destroyed.append(self.entity)

    app, ids = make_app(S(), S())
    app.world.despawn(ids[0])
    app.step()
    assert destroyed == [ids[0]]
    app.replace_scene(lambda world: None)
    assert destroyed == ids


def test_wrong_hook_signature_is_named() -> None:
    class Bad(Script):
        def on_fixed_update(self) -> None:
            pass

    with pytest.raises(HookSignatureError, match=r"Bad\.on_fixed_update.*on_fixed_update\(dt\)"):
        Behaviour(Bad())

    class BadContact(Script):
        def on_contact_begin(self, a: object, b: object) -> None:
            pass

    with pytest.raises(HookSignatureError, match="on_contact_begin"):
        Behaviour(BadContact())


def test_behaviour_needs_an_instance() -> None:
    with pytest.raises(TypeError, match="class"):
        Behaviour(Script)


def test_coroutines_wait_seconds_frames_and_next_frame() -> None:
    marks: list[tuple[str, int]] = []

    class S(Script):
        frame = 0

        def on_start(self) -> None:
            self.start_coroutine(self.routine())

        def on_update(self, dt: float) -> None:
            self.frame += 1

        def routine(self):
            marks.append(("begin", self.frame))
            yield None
            marks.append(("next", self.frame))
            yield WaitFrames(3)
            marks.append(("frames", self.frame))
            yield Wait(0.5)
            marks.append(("wait", self.frame))

    app, _ = make_app(S())
    app.step(60)
    assert marks == [("begin", 1), ("next", 2), ("frames", 5), ("wait", 35)]


def test_coroutine_stops_with_its_entity_and_with_its_scene() -> None:
    ticks: list[int] = []

    class S(Script):
        def on_start(self) -> None:
            self.start_coroutine(self.forever())

        def forever(self):
            while True:
                ticks.append(self.entity)
                yield None

    app, ids = make_app(S(), S())
    app.step(3)
    assert ticks.count(ids[0]) == 3
    app.world.despawn(ids[0])
    app.step(3)
    assert ticks.count(ids[0]) == 3 and ticks.count(ids[1]) == 6
    app.replace_scene(lambda world: None)
    app.step(3)
    assert ticks.count(ids[1]) == 6


def test_coroutine_yielding_garbage_is_an_error() -> None:
    class S(Script):
        def on_start(self) -> None:
            self.start_coroutine(self.bad())

        def bad(self):
            yield 5

    app, _ = make_app(S())
    with pytest.raises(TypeError, match="yield None, Wait"):
        app.step()


def test_start_coroutine_needs_a_generator() -> None:
    s = Script()
    with pytest.raises(TypeError, match="generator"):
        s.start_coroutine(lambda: None)  # type: ignore[arg-type]
