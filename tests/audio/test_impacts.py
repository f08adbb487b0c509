"""ImpactSound: one sound per qualifying contact, louder for faster hits."""

from __future__ import annotations

import pytest

from kge import App, Transform, World
from kge.assets import AssetNotFoundError, Assets
from kge.audio.mixer import Mixer
from kge.components.audio import ImpactSound
from kge.physics.events import ContactBegin
from tests.audio.conftest import make_app, with_store


def record_plays(monkeypatch: pytest.MonkeyPatch) -> list[tuple[str, float]]:
    plays: list[tuple[str, float]] = []
    original = Mixer.start

    def start(self, source, **kwargs):
        plays.append((kwargs["name"], kwargs["volume"]))
        return original(self, source, **kwargs)

    monkeypatch.setattr(Mixer, "start", start)
    return plays


def contact(a: int, b: int, speed: float, body_a: int | None = None, body_b: int | None = None):
    return ContactBegin(
        collider_a=a,
        collider_b=b,
        body_a=a if body_a is None else body_a,
        body_b=b if body_b is None else body_b,
        normal=(0.0, -1.0),
        points=((0.0, 0.0),),
        separation=-0.001,
        approach_speed=speed,
    )


def test_impacts_fire_once_per_qualifying_hit_with_speed_scaled_volume(
    store: Assets, monkeypatch: pytest.MonkeyPatch
):
    plays = record_plays(monkeypatch)
    app = make_app(with_store(store))
    world = app.world
    ball = world.spawn(
        Transform(), ImpactSound("blip.wav", hit_threshold=1.0, max_speed=10.0, volume=0.8)
    )
    wall = world.spawn(Transform())  # no ImpactSound: silent
    world.emit(contact(ball, wall, 0.5))  # too slow
    app.step(1)
    assert plays == []
    world.emit(contact(ball, wall, 5.0))
    app.step(1)
    assert plays == [("blip.wav", pytest.approx(0.4))]
    world.emit(contact(wall, ball, 25.0))  # B side, capped volume
    world.emit(contact(ball, wall, 2.0))
    app.step(1)
    assert [v for _, v in plays[1:]] == [pytest.approx(0.8), pytest.approx(0.16)]
    app.step(3)
    assert len(plays) == 3  # nothing replays


def test_both_entities_and_compound_bodies_play_once_each(
    store: Assets, monkeypatch: pytest.MonkeyPatch
):
    plays = record_plays(monkeypatch)
    app = make_app(with_store(store))
    world = app.world
    body = world.spawn(Transform(), ImpactSound("beep.wav", hit_threshold=0.0))
    part = world.spawn(ImpactSound("blip.wav", hit_threshold=0.0))  # a collider of `body`
    other = world.spawn(Transform(), ImpactSound("blip.wav", hit_threshold=3.0))
    world.emit(contact(part, other, 2.0, body_a=body, body_b=other))
    app.step(1)
    assert sorted(name for name, _ in plays) == ["beep.wav", "blip.wav"]  # other: too slow
    world.emit(contact(body, other, 4.0))  # body is its own collider
    app.step(1)
    assert sorted(name for name, _ in plays[2:]) == ["beep.wav", "blip.wav"]


def test_cooldown_limits_replays(store: Assets, monkeypatch: pytest.MonkeyPatch):
    plays = record_plays(monkeypatch)
    app = make_app(with_store(store))
    world = app.world
    e = world.spawn(ImpactSound("blip.wav", hit_threshold=0.0, cooldown=0.1))
    for _ in range(3):
        world.emit(contact(e, 999, 5.0))
        app.step(1)
    assert len(plays) == 1
    app.step(6)  # 0.1 s later
    world.emit(contact(e, 999, 5.0))
    app.step(1)
    assert len(plays) == 2


def test_impact_sound_with_missing_file_is_refused(store: Assets):
    app = make_app(with_store(store))
    with pytest.raises(AssetNotFoundError, match="ImpactSound.sound"):
        app.world.spawn(ImpactSound("clang.wav"))
    with pytest.raises(ValueError, match="max_speed"):
        ImpactSound("blip.wav", hit_threshold=5.0, max_speed=2.0)


def test_bouncing_ball_plays_once_per_bounce(store: Assets, monkeypatch: pytest.MonkeyPatch):
    """Real physics: every contact_begin at >= hit_threshold plays exactly one sound."""
    import kge.systems.physics as physics
    from kge.components.collider import Collider
    from kge.components.rigidbody import RigidBody
    from kge.components.shapes import Box, Circle

    plays = record_plays(monkeypatch)
    impact = ImpactSound("blip.wav", hit_threshold=1.5, max_speed=12.0, volume=1.0)

    def setup(world: World) -> None:
        world.spawn(Transform(0.0, -1.0), Collider(Box(10.0, 1.0)))
        world.spawn(
            Transform(0.0, 5.0), RigidBody(), Collider(Circle(0.25), restitution=0.6), impact
        )

    app = App(with_store(store, setup), headless=True)
    assert app.world.get_system(physics.PhysicsEventDelivery) is not None
    qualifying: list[float] = []
    for _ in range(240):
        app.step(1)
        for ev in app.world.events(ContactBegin):
            if ev.approach_speed >= impact.hit_threshold:
                qualifying.append(ev.approach_speed)
    assert len(qualifying) >= 2  # the drop and at least one bounce
    assert len(plays) == len(qualifying)
    assert [v for _, v in plays] == [pytest.approx(impact.gain(s)) for s in qualifying]
    # free fall from 4.75 m: about sqrt(2 * 10 * 4.75) = 9.7 m/s at first touch
    assert qualifying[0] == pytest.approx(9.75, rel=0.05)
    assert plays[0][1] > plays[1][1]  # the bounce is slower, so quieter


def test_min_speed_is_the_old_name_of_hit_threshold() -> None:
    from kge.components.particles import BurstOnHit

    with pytest.warns(DeprecationWarning, match=r"ImpactSound\(min_speed=\.\.\.\) is now hit_threshold="):
        impact = ImpactSound("blip.wav", min_speed=2.0)  # type: ignore[call-arg]
    assert impact.hit_threshold == 2.0
    with pytest.warns(DeprecationWarning, match="BurstOnHit.min_speed is now"):
        assert BurstOnHit(3, min_speed=4.0).min_speed == 4.0  # type: ignore[call-arg,attr-defined]
