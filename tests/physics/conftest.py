"""Shared helpers for physics tests: a bare World + PhysicsSystem stepped by hand."""

from __future__ import annotations

from collections.abc import Iterator

import pytest

from kge.components.collider import Collider
from kge.components.rigidbody import BodyType, RigidBody
from kge.components.shapes import Box
from kge.components.transform import Transform
from kge.physics.events import PhysicsEvents
from kge.physics.resource import Physics
from kge.physics.settings import PhysicsSettings
from kge.schedule import Stage
from kge.systems.physics import PhysicsSystem
from kge.world import World

DT = 1.0 / 60.0


class Sim:
    """A world with physics, stepped with the FIXED stage like the App does."""

    def __init__(self, settings: PhysicsSettings | None = None) -> None:
        self.world = World()
        if settings is not None:
            self.world.insert_resource(settings)
        self.system = PhysicsSystem()
        self.world.add_system(self.system)
        self.physics = self.world.resource(Physics)
        self.events = self.world.resource(PhysicsEvents)
        self.steps = 0

    def step(self, n: int = 1) -> None:
        for _ in range(n):
            self.world.clear_events()
            self.world.schedule.run(Stage.FIXED, DT)
            self.steps += 1

    def spawn(self, *components: object) -> int:
        return self.world.spawn(*components)

    def ground(self, friction: float = 0.2, restitution: float = 0.0) -> int:
        """Box2D reference ground: static box half (50, 10) centred at (0, -10)."""
        return self.world.spawn(
            Transform(0.0, -10.0),
            Collider(Box(50.0, 10.0), friction=friction, restitution=restitution),
        )

    def dynamic(self, shape: object, x: float = 0.0, y: float = 0.0, angle: float = 0.0,
                body: RigidBody | None = None, **collider: object) -> int:
        return self.world.spawn(
            Transform(x, y, angle),
            body if body is not None else RigidBody(type=BodyType.DYNAMIC),
            Collider(shape, **collider),  # type: ignore[arg-type]
        )

    def t(self, e: int) -> Transform:
        return self.world.get(e, Transform)

    def rb(self, e: int) -> RigidBody:
        return self.world.get(e, RigidBody)

    def close(self) -> None:
        self.world.close()


@pytest.fixture
def sim() -> Iterator[Sim]:
    s = Sim()
    yield s
    s.close()


@pytest.fixture
def zero_g() -> Iterator[Sim]:
    s = Sim(PhysicsSettings(gravity=(0.0, 0.0)))
    yield s
    s.close()


def snapshot(world: World) -> dict[int, tuple[str, ...]]:
    """Entity -> component type names, for 'world unchanged' checks."""
    return {e: tuple(sorted(type(c).__name__ for c in world.components(e)))
            for e in world.entities()}
