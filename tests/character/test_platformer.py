"""The platformer helpers: jumps, coyote time, jump buffering, variable height, landings."""

from __future__ import annotations

import pytest

from kge import Box, Capsule, CharacterBody, Collider, PhysicsSettings, Transform

G = 10.0
JUMP = 8.0


def _scene(world, **settings):
    world.spawn(Transform(-3.0, -0.5), Collider(Box(3.0, 0.5)))  # a ledge ending at x = 0
    world.spawn(Transform(0.0, -20.5), Collider(Box(50.0, 0.5)))  # far below
    world.spawn(Transform(-2.0, 1.0), CharacterBody(Capsule(0.3, 0.9), jump_speed=JUMP, **settings))


def _apex(app, body, t, hold: int) -> float:
    """Jump holding the button ``hold`` steps; the highest the feet get above the start."""
    start = t.y
    body.jump = True
    top = start
    for k in range(120):
        if k == hold:
            body.jump = False
        app.step()
        top = max(top, t.y)
        if body.on_floor and k > 2:
            break
    body.jump = False
    app.step()
    return top - start


def test_a_held_jump_reaches_v2_over_2g_and_a_tapped_one_is_cut(app_of) -> None:
    app = app_of(_scene)
    body, t = app.world.get(3, CharacterBody), app.world.get(3, Transform)
    app.step(30)
    full = _apex(app, body, t, hold=1000)
    assert full == pytest.approx(JUMP**2 / (2 * G), rel=0.03)
    assert body.on_floor and body.landed is False
    short = _apex(app, body, t, hold=3)
    assert short < 0.45 * full  # released early: cut to jump_cut (0.5) of the speed
    body.jump_cut = 1.0
    assert _apex(app, body, t, hold=3) == pytest.approx(full, rel=0.01)


def test_jumped_and_landed_are_set_for_one_step(app_of) -> None:
    app = app_of(_scene)
    body = app.world.get(3, CharacterBody)
    app.step(30)
    body.jump = True
    app.step()
    assert body.jumped and not body.on_floor
    app.step()
    assert not body.jumped
    landed = []
    for _ in range(120):
        app.step()
        landed.append((body.landed, body.landing_speed))
    assert [s for flag, s in landed if flag] == [pytest.approx(JUMP, rel=0.03)]
    assert body.on_floor and landed[-1] == (False, 0.0)


def test_coyote_time_lets_it_jump_just_after_walking_off_a_ledge(app_of) -> None:
    for late, jumps in ((3, True), (12, False)):  # 0.05 s and 0.2 s after; coyote 0.1 s
        app = app_of(_scene)
        body = app.world.get(3, CharacterBody)
        app.step(20)
        while body.on_floor:
            body.velocity = (3.0, body.velocity[1])
            app.step()
        for _ in range(late - 1):
            app.step()
        body.jump = True
        app.step()
        assert body.jumped is jumps, late
        assert (body.velocity[1] > 0.0) is jumps


def test_a_jump_pressed_just_before_landing_is_buffered(app_of) -> None:
    for early, jumps in ((4, True), (12, False)):  # 0.067 s and 0.2 s before; buffer 0.1 s
        app = app_of(_scene)
        body = app.world.get(3, CharacterBody)
        app.step(30)
        body.jump = True
        app.step()
        body.jump = False
        # the steps of the fall, recorded, then the same jump with a press before landing
        steps = 0
        while True:
            app.step()
            steps += 1
            if body.on_floor:
                break
        app.step(10)
        body.jump = True
        app.step()
        body.jump = False
        for _ in range(steps - early):
            app.step()
        body.jump = True  # pressed `early` steps before the landing step
        fired = False
        for _ in range(early + 2):
            app.step()
            fired |= body.jumped
        assert fired is jumps, early


def test_landing_speed_and_a_hard_landing(app_of) -> None:
    def scene(world):
        world.spawn(Transform(0.0, -0.5), Collider(Box(5.0, 0.5)))
        world.spawn(Transform(0.0, 12.0), CharacterBody(Capsule(0.3, 0.9), hard_landing_speed=12.0))

    app = app_of(scene)
    body = app.world.get(2, CharacterBody)
    while not body.landed:
        app.step()
    fall = 12.0 - 0.9 - 0.015
    assert body.landing_speed == pytest.approx((2 * G * fall) ** 0.5, rel=0.03)
    assert body.hard_landing
    app.step()
    assert not body.landed and not body.hard_landing and body.landing_speed == 0.0


def test_gravity_comes_from_the_physics_settings_and_gravity_scale(app_of) -> None:
    def scene(world):
        world.insert_resource(PhysicsSettings(gravity=(0.0, -5.0)))
        world.spawn(Transform(0.0, 0.0), CharacterBody(Capsule(0.3, 0.9)))
        world.spawn(Transform(3.0, 0.0), CharacterBody(Capsule(0.3, 0.9), gravity_scale=2.0))

    app = app_of(scene)
    app.step(60)
    ya, yb = app.world.get(1, Transform).y, app.world.get(2, Transform).y
    assert ya == pytest.approx(-0.5 * 5.0, rel=0.03) and yb == pytest.approx(-0.5 * 10.0, rel=0.03)
