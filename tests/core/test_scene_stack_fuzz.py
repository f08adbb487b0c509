"""Random scene-stack changes asked for from everywhere a game can ask for them
(between frames, in on_update and on_fixed_update, in on_destroy and on_exit while
another change is being made, in a setup, with and without transitions, with setups
that raise), with the stack's invariants checked after every frame."""

from __future__ import annotations

import contextlib
from typing import Any

from hypothesis import settings
from hypothesis import strategies as st
from hypothesis.stateful import RuleBasedStateMachine, initialize, invariant, rule

from kge import App, Behaviour, Script, World
from kge.errors import SceneStackError
from kge.scene import Scene
from kge.transitions import Crossfade, Fade

OPS = ("push", "overlay", "overlay_run_below", "pop", "replace", "replace_fade",
       "replace_crossfade", "push_failing", "replace_failing")
HOOKS = ("on_update", "on_fixed_update", "on_destroy", "on_exit", "setup")


class SetupFailed(RuntimeError):
    pass


class Probe(Scene):
    def __init__(self, machine: StackMachine, fail: bool = False) -> None:
        self.m, self.fail = machine, fail
        self.world: World | None = None
        self.exits = 0
        machine.scenes.append(self)

    def setup(self, world: World, **kwargs: Any) -> None:
        self.world = world
        self.m.fire("setup")
        if self.fail:
            raise SetupFailed("setup failed")
        world.spawn(Behaviour(Chaos(self.m)))

    def on_exit(self, world: World) -> None:
        assert world is self.world
        self.exits += 1
        self.m.fire("on_exit")


class Chaos(Script):
    def __init__(self, machine: StackMachine) -> None:
        self.m = machine

    def on_update(self, dt: float) -> None:
        self.m.fire("on_update")

    def on_fixed_update(self, dt: float) -> None:
        self.m.fire("on_fixed_update")

    def on_destroy(self) -> None:
        self.m.fire("on_destroy")


class Named(Scene):
    """A scene that runs ``on_setup`` / ``on_exit`` callbacks (None: nothing)."""

    def __init__(self, name: str, on_setup: Any = None, on_exit: Any = None) -> None:
        self.name, self.on_setup, self.exit_cb = name, on_setup, on_exit

    def setup(self, world: World, **kwargs: Any) -> None:
        if self.on_setup is not None:
            self.on_setup()

    def on_exit(self, world: World) -> None:
        if self.exit_cb is not None:
            self.exit_cb()

    def __repr__(self) -> str:
        return self.name


def _names(app: App) -> list[str]:
    return [repr(s) for s in app.scenes]


def test_a_pop_asked_while_a_crossfade_replace_closes_the_old_scenes_is_refused_at_once(
) -> None:
    """Found by the machine below: [A, C, E] replaced by B behind a crossfade; E's on_exit
    pops. Only B will be left, so the pop must be refused at the call, not accepted and
    then raised out of App.step when it is made."""
    refused: list[SceneStackError] = []

    def pop() -> None:
        try:
            app.pop_scene()
        except SceneStackError as err:
            refused.append(err)

    app = App(Named("A"), headless=True, size=(64, 64), plugins=[])
    app.replace_scene(Named("B"), transition=Crossfade(0.1))
    app.push_scene(Named("C"))
    app.push_scene(Named("E", on_exit=pop))
    for _ in range(20):
        app.step()
    assert len(refused) == 1 and _names(app) == ["B"]
    app.close()


def test_a_pop_from_on_exit_after_a_push_from_the_new_setup_is_made_in_order() -> None:
    """The crossfade's new scene B pushes D in its setup; A's on_exit (A closes after B's
    setup) pops: D is pushed, then popped, and B runs."""
    def pop() -> None:
        app.pop_scene()

    app: App = App(Named("A", on_exit=pop), headless=True, size=(64, 64), plugins=[])
    app.replace_scene(Named("B", on_setup=lambda: app.push_scene(Named("D"))),
                      transition=Crossfade(0.1))
    for _ in range(20):
        app.step()
    assert _names(app) == ["B"] and not app.world.closed
    app.close()


class StackMachine(RuleBasedStateMachine):
    @initialize()
    def start(self) -> None:
        self.scenes: list[Probe] = []
        self.pending: dict[str, list[str]] = {hook: [] for hook in HOOKS}
        #: the scene on top when the newest transition was asked for: it must leave
        self.leaving: Scene | None = None
        self.in_hook = False
        self.app = App(Probe(self), headless=True, size=(64, 64), plugins=[])

    def teardown(self) -> None:
        if hasattr(self, "app"):
            self.app.close()

    def fire(self, hook: str) -> None:
        if self.pending[hook]:
            self.in_hook = True
            try:
                self.perform(self.pending[hook].pop(0))
            finally:
                self.in_hook = False

    def perform(self, op: str) -> None:
        app = self.app
        try:
            if op == "push":
                app.push_scene(Probe(self))
            elif op == "overlay":
                app.push_scene(Probe(self), overlay=True)
            elif op == "overlay_run_below":
                app.push_scene(Probe(self), overlay=True, run_below=True)
            elif op == "pop":
                app.pop_scene()
            elif op == "replace":
                app.replace_scene(Probe(self))
            elif op in ("replace_fade", "replace_crossfade"):
                kind = Fade(0.1) if op == "replace_fade" else Crossfade(0.1)
                top = app.scenes[-1] if app.scenes else None
                app.replace_scene(Probe(self), transition=kind)
                # asked between frames it starts at once, so the top is known; asked
                # from a hook it starts at the frame's end and supersedes the tracked one
                self.leaving = top if not self.in_hook else None
            elif op == "push_failing":
                app.push_scene(Probe(self, fail=True))
            elif op == "replace_failing":
                app.replace_scene(Probe(self, fail=True))
        except SceneStackError:
            pass  # refused at the call: popping the last scene

    @rule(op=st.sampled_from(OPS), hook=st.sampled_from(HOOKS))
    def ask_in_a_hook(self, op: str, hook: str) -> None:
        self.pending[hook].append(op)

    @rule(op=st.sampled_from(OPS))
    def ask_between_frames(self, op: str) -> None:
        with contextlib.suppress(SetupFailed):
            self.perform(op)

    @rule(frames=st.integers(1, 12))
    def run_frames(self, frames: int) -> None:
        for _ in range(frames):
            try:
                self.app.step()
            except SetupFailed:
                continue
            # a clean frame made every queued change: a finished transition took the
            # scene it was asked to replace (and anything pushed over it) away
            if self.leaving is not None and self.app.transition is None:
                assert self.leaving not in self.app.scenes, "a replaced scene stayed"
                self.leaving = None

    @invariant()
    def the_stack_is_consistent(self) -> None:
        if not hasattr(self, "app"):
            return
        app = self.app
        worlds = app.worlds
        assert worlds, "the App lost its last scene"
        assert len(set(map(id, worlds))) == len(worlds)
        assert not any(w.closed for w in worlds), "a closed world is on the stack"
        assert app.world is worlds[-1]
        on_stack = {id(s) for s in app.scenes}
        for probe in self.scenes:
            if probe.world is None:
                continue  # queued, not set up yet
            if id(probe) in on_stack:
                assert probe.exits == 0 and not probe.world.closed
            elif probe.fail:
                assert probe.world.closed and probe.exits == 0  # never entered the stack
            else:
                assert probe.world.closed, "a scene left the stack without closing"
                assert probe.exits == 1, f"a scene exited {probe.exits} times"


StackMachine.TestCase.settings = settings(max_examples=200, stateful_step_count=30, deadline=None)
TestSceneStack = StackMachine.TestCase
