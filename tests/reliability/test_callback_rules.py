"""Callbacks and hooks: no re-entrant frames, no closing mid-step, one delivery rule.

Delivery rule (docs/reliability.md): every physics event goes to the world's
handlers (``world.set_handler``, esper's) and to the Behaviour scripts of the
entities it names that are still alive when its turn comes. An entity despawned by
an earlier hook in the same delivery gets no more calls; handlers and the other
entities' scripts still get the event, and the matching end follows at the next
step, so both paths see begins and ends in pairs.
"""

from __future__ import annotations

import pytest

from kge import App, Behaviour, Box, Circle, Collider, RigidBody, Script, Transform, World
from kge.errors import WorldLockedError
from kge.physics.contacts import PreSolve
from kge.physics.events import ContactBegin, ContactEnd
from kge.physics.resource import Physics


def drop(world: World) -> tuple[int, int]:
    world.spawn(Transform(0.0, -1.0), Collider(Box(10.0, 1.0)))
    a = world.spawn(Transform(0.0, 0.45), RigidBody(), Collider(Box(0.5, 0.5), contact_hooks=True))
    return 1, a


def test_closing_the_world_inside_a_physics_callback_is_refused() -> None:
    app = App(lambda w: None, headless=True)
    world = app.world
    drop(world)
    closing = world.resource(Physics).on_pre_solve(lambda c: world.close())
    with pytest.raises(WorldLockedError, match=r"world\.close\(\) inside a physics callback"):
        app.step()
    assert not world.closed
    world.resource(Physics).remove_hook(closing)
    app.step(3)  # still running


def test_a_frame_inside_a_frame_is_refused_and_the_outer_events_arrive() -> None:
    app = App(lambda w: None, headless=True)
    world = app.world
    drop(world)
    errors: list[BaseException] = []
    begins: list[ContactBegin] = []

    def pre(contact: PreSolve) -> None:
        try:
            app.step()
        except WorldLockedError as err:
            errors.append(err)

    class Nested(Script):
        def on_fixed_update(self, dt: float) -> None:
            try:
                app.advance(1 / 60)
            except WorldLockedError as err:
                errors.append(err)

        def on_contact_begin(self, ev: ContactBegin) -> None:
            begins.append(ev)

    world.resource(Physics).on_pre_solve(pre)
    world.add(2, Behaviour(Nested()))
    app.step()
    assert len(errors) >= 2 and all("inside a running frame" in str(e) for e in errors)
    assert [(b.collider_a, b.collider_b) for b in begins] == [(1, 2)]


def test_handlers_and_scripts_follow_one_delivery_rule() -> None:
    app = App(lambda w: None, headless=True)
    world = app.world
    world.spawn(Transform(0.0, -1.0), Collider(Box(10.0, 1.0)))
    log: list[tuple[str, str, int, int]] = []

    class Bomb(Script):  # despawns the ball it touches, during the delivery
        def on_contact_begin(self, ev: ContactBegin) -> None:
            log.append(("bomb", "begin", ev.collider_a, ev.collider_b))
            other = ev.collider_b if ev.collider_a == self.entity else ev.collider_a
            if world.exists(other) and other != 1:
                world.despawn(other)

        def on_contact_end(self, ev: ContactEnd) -> None:
            log.append(("bomb", "end", ev.collider_a, ev.collider_b))

    class Ball(Script):
        def on_contact_begin(self, ev: ContactBegin) -> None:
            log.append(("ball", "begin", ev.collider_a, ev.collider_b))

        def on_contact_end(self, ev: ContactEnd) -> None:
            log.append(("ball", "end", ev.collider_a, ev.collider_b))

    bomb = world.spawn(Transform(0.0, 0.45), RigidBody(), Collider(Box(0.5, 0.5)),
                       Behaviour(Bomb()))
    ball = world.spawn(Transform(0.0, 1.4), RigidBody(), Collider(Circle(0.45)), Behaviour(Ball()))
    for kind in ("contact_begin", "contact_end"):
        world.set_handler(kind, lambda ev, kind=kind: log.append(
            ("handler", kind.split("_")[1], ev.collider_a, ev.collider_b)))
    app.step(3)

    def seen(who: str, a: int, b: int) -> list[str]:
        return [k for w, k, x, y in log if w == who and (x, y) == (a, b)]

    # the bomb's begin with the ball came first (lower ids), so the ball was dead
    # when the event reached its own script: only handlers and the bomb saw it
    assert seen("handler", bomb, ball) == ["begin", "end"]
    assert seen("bomb", bomb, ball) == ["begin", "end"]
    assert seen("ball", bomb, ball) == []
    assert not world.exists(ball)
