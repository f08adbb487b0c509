"""Tween control sample: custom easings side by side, relative steps with calls, and
per-tween pause and speed."""

from __future__ import annotations

from typing import Any

from kge.animation.easing import CubicBezier, EaseCurve
from kge.animation.tweens import Tweens
from kge.components import Behaviour, Name, Script, Transform
from kge.components.drawables import Circle, Line
from kge.components.tween import Call, Delay, Tween, TweenSequence
from kge.keys import Key
from kge.testbed.registry import sample
from kge.testbed.samples.build import named
from kge.world import World

#: the curves raced left to right, one lane each (top to bottom)
CURVES: list[tuple[str, Any]] = [
    ("linear", "linear"),
    ("css ease", CubicBezier(0.25, 0.1, 0.25, 1.0)),
    ("css ease-in-out", CubicBezier(0.42, 0.0, 0.58, 1.0)),
    ("overshoot curve", EaseCurve([(0, 0), (0.6, 1.15), (0.8, 0.95), (1, 1)])),
    ("sqrt (a function)", lambda p: p**0.5),
]
LANE_SECONDS = 2.0


class _Keys(Script):
    """P pauses and resumes the racers; 1, 2, 3 set their speed."""

    def on_update(self, dt: float) -> None:
        from kge.input import Input

        inp = self.world.resource(Input)
        handles = self.world.resource(_Racers).handles
        if inp.pressed(Key.P):
            for h in handles:
                h.resume() if h.paused else h.pause()
        for key, speed in ((Key._1, 0.5), (Key._2, 1.0), (Key._3, 2.0)):
            if inp.pressed(key):
                for h in handles:
                    h.speed = speed


class _Racers:
    """The sample's resource: the racers' handles and the stepper's call count."""

    def __init__(self) -> None:
        self.handles: list[Any] = []
        self.steps = 0


@sample("Animation", "Custom Easing", help="Dots race with a linear tween, two CSS "
        "cubic-beziers, a curve through points and a plain function; below, a box steps "
        "by relative tweens and a Call drops a marker at each stop. P pauses the racers, "
        "1/2/3 set their speed.", keys={"P": "pause racers", "1/2/3": "racer speed"})
def custom_easing(world: World) -> None:
    tweens = world.resource(Tweens)
    racers = world.insert_resource(_Racers())
    for i, (label, curve) in enumerate(CURVES):
        y = 3.0 - 1.0 * i
        world.spawn(Transform(0.0, y), Line((-4.0, 0.0), (4.0, 0.0), color=(70, 70, 90)))
        dot = world.spawn(Transform(-4.0, y), Circle(0.2, color=(255, 200, 60)), Name(label))
        racers.handles.append(tweens.start(dot, TweenSequence(
            Tween(Transform, "x", 4.0, LANE_SECONDS, ease=curve),
            Delay(0.5),
            Tween(Transform, "x", -4.0, LANE_SECONDS, ease=curve),
            Delay(0.5), repeat=-1,
        )))  # fmt: skip
    box = world.spawn(Transform(-4.0, -2.5), Circle(0.3, color=(90, 200, 255)), Name("stepper"))

    def drop_marker() -> None:
        racers.steps += 1
        x = world.get(box, Transform).x
        world.spawn(Transform(x, -3.1), Circle(0.08, color=(255, 90, 90)), Name("marker"))

    step = [Tween(Transform, "x", 1.0, 0.3, relative=True, ease="back_out"), Call(drop_marker),
            Delay(0.2)]  # fmt: skip
    tweens.start(box, TweenSequence(*step * 8))
    world.spawn(Behaviour(_Keys()))


@custom_easing.claim
def _curves_and_steps(app: Any) -> None:
    world = app.world
    # 300 steps = 5 s: every stepper stop has dropped its marker, at whole metres
    markers = sorted(round(world.get(e, Transform).x, 6) for e in named(world, "marker"))
    assert markers == [-3.0 + i for i in range(8)], markers
    assert world.resource(_Racers).steps == 8
    racers = world.resource(_Racers).handles
    assert all(not h.done for h in racers)  # looping forever
