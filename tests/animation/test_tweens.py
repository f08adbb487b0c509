"""Tweens: easing curves against their formulas, timing, repeat/yoyo, sequences, coroutines,
physics bodies moved kinematically, bad input."""

from __future__ import annotations

import math
from typing import Any

import numpy as np
import pytest

from kge import (
    App,
    Behaviour,
    BodyType,
    Box,
    Camera,
    Collider,
    Delay,
    Parallel,
    RigidBody,
    Script,
    Sprite,
    Transform,
    Tween,
    TweenFinished,
    Tweens,
    TweenSequence,
    ValidationError,
    World,
    ease,
)
from kge.animation.easing import EASINGS
from kge.components.tween import EASING_NAMES
from kge.render.images import solid

P = np.linspace(0.0, 1.0, 101)


def _bounce_out(x: float) -> float:
    n1, d1 = 7.5625, 2.75
    if x < 1 / d1:
        return n1 * x * x
    if x < 2 / d1:
        x -= 1.5 / d1
        return n1 * x * x + 0.75
    if x < 2.5 / d1:
        x -= 2.25 / d1
        return n1 * x * x + 0.9375
    x -= 2.625 / d1
    return n1 * x * x + 0.984375


c1 = 1.70158
c3 = c1 + 1
c4 = 2 * math.pi / 3
FORMULAS = {
    "linear": lambda x: x,
    "quad_in": lambda x: x * x,
    "quad_out": lambda x: 1 - (1 - x) ** 2,
    "cubic_in": lambda x: x**3,
    "cubic_out": lambda x: 1 - (1 - x) ** 3,
    "cubic_in_out": lambda x: 4 * x**3 if x < 0.5 else 1 - (-2 * x + 2) ** 3 / 2,
    "quart_in": lambda x: x**4,
    "quint_out": lambda x: 1 - (1 - x) ** 5,
    "sine_in": lambda x: 1 - math.cos(x * math.pi / 2),
    "sine_in_out": lambda x: -(math.cos(math.pi * x) - 1) / 2,
    "expo_out": lambda x: 1.0 if x == 1 else 1 - 2 ** (-10 * x),
    "circ_in": lambda x: 1 - math.sqrt(1 - x * x),
    "back_in": lambda x: c3 * x**3 - c1 * x * x,
    "back_out": lambda x: 1 + c3 * (x - 1) ** 3 + c1 * (x - 1) ** 2,
    "elastic_out": lambda x: x if x in (0, 1) else 2 ** (-10 * x) * math.sin((x * 10 - 0.75) * c4) + 1,
    "bounce_out": _bounce_out,
    "bounce_in": lambda x: 1 - _bounce_out(1 - x),
}


@pytest.mark.parametrize("name", sorted(FORMULAS))
def test_easing_matches_its_formula(name: str) -> None:
    want = np.array([FORMULAS[name](float(x)) for x in P])
    np.testing.assert_allclose(ease(name, P), want, atol=1e-9)


@pytest.mark.parametrize("name", EASING_NAMES)
def test_every_easing_starts_at_0_ends_at_1_and_in_out_is_symmetric(name: str) -> None:
    v = ease(name, P)
    assert abs(v[0]) < 1e-9 and abs(v[-1] - 1) < 1e-9
    if name.endswith("_in_out"):
        np.testing.assert_allclose(v + v[::-1], 1.0, atol=1e-9)
    if name.endswith("_out") and not name.endswith("_in_out"):
        inner = ease(name[:-4] + "_in", 1 - P)
        np.testing.assert_allclose(v, 1 - inner, atol=1e-9)
    assert len(EASINGS) == 31


def _world() -> tuple[World, Tweens]:
    from kge.systems.animation import AnimationPlugin

    w = World()
    w.add_plugins(AnimationPlugin())
    return w, w.resource(Tweens)


def _run(w: World, dt: float, n: int = 1) -> None:
    from kge.schedule import Stage

    for _ in range(n):
        w.schedule.run(Stage.INPUT, dt)
        w.schedule.run(Stage.UPDATE, dt)


def test_a_tween_follows_its_easing_over_time() -> None:
    w, tweens = _world()
    e = w.spawn(Transform(1.0, 0.0))
    tweens.to(e, Transform, "x", 3.0, 1.0, ease="cubic_in")
    xs = []
    for _ in range(10):
        _run(w, 0.1)
        xs.append(w.get(e, Transform).x)
    want = [1 + 2 * (k / 10) ** 3 for k in range(1, 11)]
    np.testing.assert_allclose(xs, want, atol=1e-9)
    _run(w, 0.1)
    assert w.get(e, Transform).x == pytest.approx(3.0)


def test_vector_colour_and_integer_fields_delay_repeat_yoyo() -> None:
    w, tweens = _world()
    e = w.spawn(Transform(), Sprite(solid(2, 2), tint=(0, 0, 0), opacity=0))
    cam = Camera(center=(0.0, 0.0))
    tweens.to(e, Sprite, "tint", (200, 100, 50), 1.0)
    tweens.to(e, Sprite, "opacity", 255, 0.5, delay=0.5, ease="back_out")  # overshoot clamps
    h = tweens.to(cam, Camera, "center", (4.0, 2.0), 0.5, repeat=1, yoyo=True)
    _run(w, 0.25, 2)
    s = w.get(e, Sprite)
    assert s.tint == (100, 50, 25) and s.opacity == 0
    assert cam.center == pytest.approx((4.0, 2.0))
    _run(w, 0.25)
    assert 0 < s.opacity <= 255 and isinstance(s.opacity, int)
    assert cam.center == pytest.approx((2.0, 1.0))  # on the way back
    _run(w, 0.25)
    assert cam.center == pytest.approx((0.0, 0.0)) and h.done
    assert s.opacity == 255 and s.tint == (200, 100, 50)


def test_sequence_parallel_and_completion_events_and_hooks() -> None:
    ended: list[Any] = []

    class Watch(Script):
        def on_tween_end(self, event: Any) -> None:
            ended.append(event.name)

    from kge.systems.behaviour import BehaviourPlugin

    w = World()
    from kge.systems.animation import AnimationPlugin

    w.add_plugins(BehaviourPlugin(), AnimationPlugin())
    tweens = w.resource(Tweens)
    e = w.spawn(Transform(), Behaviour(Watch()))
    seq = TweenSequence(
        Tween(Transform, "x", 1.0, 0.5),
        Delay(0.25),
        Parallel(Tween(Transform, "y", 2.0, 0.5), Tween(Transform, "angle", 1.0, 0.25)),
        name="dance",
    )
    h = tweens.start(e, seq)
    t = w.get(e, Transform)
    _run(w, 0.25, 2)
    assert (t.x, t.y) == (pytest.approx(1.0), 0.0)
    _run(w, 0.25)
    assert t.y == 0.0  # the delay
    _run(w, 0.25)
    assert t.y == pytest.approx(1.0) and t.angle == pytest.approx(1.0)
    assert not h.done
    from kge.animation import AnimationEvents

    _run(w, 0.25)
    assert h.done and ended == ["dance"]
    assert w.resource(AnimationEvents).tweens == [TweenFinished(e, h, "dance")]


def test_forever_sequence_wraps_and_cancel_stops_it() -> None:
    w, tweens = _world()
    e = w.spawn(Transform())
    h = tweens.start(e, TweenSequence(Tween(Transform, "x", 1.0, 0.5), Tween(Transform, "x", 0.0, 0.5),
                                 repeat=-1))
    xs = []
    for _ in range(8):
        _run(w, 0.25)
        xs.append(round(w.get(e, Transform).x, 6))
    assert xs == [0.5, 1.0, 0.5, 0.0, 0.5, 1.0, 0.5, 0.0]
    h.cancel()
    _run(w, 0.25)
    assert w.get(e, Transform).x == 0.0 and h.done and h.cancelled


def test_a_coroutine_yields_until_the_tween_ends() -> None:
    log: list[tuple[str, float]] = []

    class Mover(Script):
        def on_start(self) -> None:
            self.start_coroutine(self.go())

        def go(self) -> Any:
            tweens = self.world.resource(Tweens)
            yield tweens.to(self.entity, Transform, "x", 2.0, 0.5)
            log.append(("moved", self.get(Transform).x))
            yield tweens.to(self.entity, Transform, "y", 1.0, 0.25)
            log.append(("lifted", self.get(Transform).y))

    app = App(lambda world: world.spawn(Transform(), Behaviour(Mover())), headless=True,
              fixed_dt=0.05)
    app.step(12)
    assert log == [("moved", 2.0)]
    app.step(10)
    assert log == [("moved", 2.0), ("lifted", 1.0)]


def test_tweening_a_body_moves_it_kinematically_not_by_teleport() -> None:
    def setup(world: World) -> None:
        world.spawn(Transform(0.0, 0.0), RigidBody(type=BodyType.KINEMATIC), Collider(Box(0.5, 0.5)))

    app = App(setup, headless=True, fixed_dt=1 / 60)
    tweens = app.world.resource(Tweens)
    h = tweens.to(1, Transform, "x", 3.0, 1.0, ease="sine_in_out")
    speeds = []
    for _ in range(30):
        app.step(1)
        speeds.append(app.world.get(1, RigidBody).velocity[0])
    assert max(speeds) > 2.0  # moved by velocity (a teleport leaves it at 0)
    t = app.world.get(1, Transform)
    assert t.x == pytest.approx(3 * (1 - math.cos(math.pi * 0.5)) / 2, abs=1e-6)
    app.step(40)
    assert h.done
    assert app.world.get(1, Transform).x == pytest.approx(3.0, abs=1e-6)
    assert app.world.get(1, RigidBody).velocity == (0.0, 0.0)


def test_bad_tweens_are_refused_naming_component_and_field() -> None:
    w, tweens = _world()
    e = w.spawn(Transform(), Sprite(solid(2, 2)))
    n = len(tweens)
    with pytest.raises(ValidationError, match="entity 1, Transform.z: Transform has no field 'z'"):
        tweens.to(e, Transform, "z", 1.0, 1.0)
    with pytest.raises(ValidationError, match=r"entity 1, Sprite.image: current value .* is not numeric"):
        tweens.to(e, Sprite, "image", 1.0, 1.0)
    with pytest.raises(ValidationError, match="unknown easing 'quad'"):
        tweens.to(e, Transform, "x", 1.0, 1.0, ease="quad")
    with pytest.raises(ValidationError, match="entity 1 has no Camera component"):
        tweens.to(e, Camera, "zoom", 2.0, 1.0)
    with pytest.raises(ValidationError, match="target value .* has 2 numbers, the field holds 3"):
        tweens.to(e, Sprite, "tint", (1, 2), 1.0)
    with pytest.raises(ValidationError, match="entity 1, Transform.x: target value must be finite"):
        tweens.to(e, Transform, "x", float("nan"), 1.0)
    with pytest.raises(ValidationError, match=r"Tween\(Transform.x\).duration must be > 0"):
        tweens.to(e, Transform, "x", 1.0, -1.0)
    # a sequence whose second step is bad starts nothing
    with pytest.raises(ValidationError):
        tweens.start(e, TweenSequence(Tween(Transform, "x", 1.0, 1.0), Tween(Transform, "q", 1.0, 1.0)))
    assert len(tweens) == n == 0
    _run(w, 0.5)
    assert w.get(e, Transform).x == 0.0


def test_tweens_of_a_despawned_entity_stop() -> None:
    w, tweens = _world()
    e = w.spawn(Transform())
    h = tweens.to(e, Transform, "x", 1.0, 1.0)
    w.despawn(e)
    w.flush()
    _run(w, 0.5)
    assert h.done and h.cancelled and len(tweens) == 0


def test_finished_rows_are_compacted_and_the_rest_keep_going() -> None:
    w, tweens = _world()
    short = [w.spawn(Transform()) for _ in range(600)]
    long = [w.spawn(Transform()) for _ in range(10)]
    for e in short:
        tweens.to(e, Transform, "x", 1.0, 0.1)
    handles = [tweens.to(e, Transform, "y", 2.0, 1.0, delay=0.1 * (i % 2))
               for i, e in enumerate(long)]
    _run(w, 0.25)
    assert len(tweens.live) == 10 and len(tweens.g_ids) == 10  # compacted
    assert all(w.get(e, Transform).x == 1.0 for e in short)
    _run(w, 0.25)
    ys = [w.get(e, Transform).y for e in long]
    assert ys[0] == pytest.approx(1.0) and ys[1] == pytest.approx(0.8)
    _run(w, 0.5, 2)
    assert all(h.done for h in handles) and all(w.get(e, Transform).y == 2.0 for e in long)


def test_text_colour_and_size_tween() -> None:
    from kge import Text

    w, tweens = _world()
    e = w.spawn(Transform(), Text("hi", size=10.0, color=(0, 0, 0, 255)))
    tweens.start(e, Parallel(Tween(Text, "color", (255, 255, 255, 0), 1.0),
                             Tween(Text, "size", 20.0, 1.0, ease="quad_in")))
    _run(w, 0.5)
    t = w.get(e, Text)
    assert t.color == (128, 128, 128, 128) and t.size == pytest.approx(12.5)


def test_an_overshooting_tween_near_the_world_bound_never_leaves_it() -> None:
    """Ends near the 1e7 m bound take the checked path: back easing's overshoot is clamped,
    never written as an out-of-world coordinate."""
    from kge.validate import MAX_COORDINATE

    w, tweens = _world()
    e = w.spawn(Transform(MAX_COORDINATE * 0.5, 0.0))
    tweens.to(e, Transform, "x", MAX_COORDINATE, 1.0, ease="back_out")
    for _ in range(12):
        _run(w, 0.1)
        assert w.get(e, Transform).x <= MAX_COORDINATE
    assert w.get(e, Transform).x == pytest.approx(MAX_COORDINATE)


def test_sequence_is_the_old_name_of_tween_sequence() -> None:
    """kge.Sequence shadowed typing.Sequence: it is TweenSequence now, the old name warns."""
    import kge
    import kge.components.tween as tween_module

    with pytest.warns(DeprecationWarning, match=r"kge.Sequence is now kge.TweenSequence"):
        old = kge.Sequence
    assert old is TweenSequence and "Sequence" not in kge.__all__
    with pytest.warns(DeprecationWarning, match="TweenSequence"):
        assert tween_module.Sequence is TweenSequence
    with pytest.warns(DeprecationWarning):
        from kge import Sequence  # what 2.0.0a1 programs wrote
    assert Sequence(Tween(Transform, "x", 1.0, 0.5)).total == 0.5
