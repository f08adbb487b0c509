"""A body restored asleep has no contact with its floor yet (sleeping bodies are not
collided): when the floor goes, it must still wake and fall, as Box2D wakes the bodies
touching a fixture or body that is destroyed."""

from __future__ import annotations

import pytest

from kge import App, Box, Collider, RigidBody, Transform, World


def _scene(world: World) -> None:
    world.spawn(Transform(0.0, -0.5), Collider(Box(5.0, 0.5)))
    world.spawn(Transform(0.0, 0.5), RigidBody(), Collider(Box(0.5, 0.5)))


@pytest.mark.parametrize("restored", [False, True])
def test_a_sleeper_falls_when_its_static_floor_is_despawned(restored: bool) -> None:
    app = App(_scene, headless=True)
    app.step(150)
    box = next(e for e, _ in app.world.query(RigidBody))
    assert not app.world.get(box, RigidBody).awake
    if restored:
        app.restore(app.world.snapshot())
        app.step(5)
        assert not app.world.get(box, RigidBody).awake  # restored asleep, and stays so
    world = app.world
    y = world.get(box, Transform).y
    floor = next(e for e, _ in world.query(Collider) if not world.has(e, RigidBody))
    world.despawn(floor)
    app.step(30)
    assert world.get(box, RigidBody).awake
    assert world.get(box, Transform).y < y - 1.0  # it fell instead of hovering
    app.close()
