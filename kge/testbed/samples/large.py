"""Large scenes: the benchmark workloads, also browsable in the testbed.

Each takes its size as a keyword argument so ``benchmarks/`` can build the very
same geometry at 1,000 or 5,000 bodies while the testbed shows a small default.
"""

from __future__ import annotations

from kge.components import Behaviour, Script, Transform
from kge.components.collider import Collider
from kge.components.rigidbody import RigidBody
from kge.components.shapes import Box, Circle
from kge.testbed.registry import sample
from kge.testbed.samples.build import box, named, static_box
from kge.world import World


def _rain_box(world: World, half: float = 20.0) -> None:
    static_box(world, 0.0, -0.5, half + 1.0, 0.5, name="wall")
    static_box(world, -half - 0.5, 2.0 * half, 0.5, 2.0 * half, name="wall")
    static_box(world, half + 0.5, 2.0 * half, 0.5, 2.0 * half, name="wall")


@sample("Large", "Rain", help="Circles raining into a 40 m open box.", camera=(0.0, 12.0, 0.3))
def rain(world: World, count: int = 300, radius: float = 0.25) -> None:
    _rain_box(world)
    per_row = 60
    for i in range(count):
        row, col = divmod(i, per_row)
        x = -19.0 + (col + 0.5 * (row % 2)) * (38.0 / per_row)
        y = 2.0 + row * 0.6
        world.spawn(Transform(x, y), RigidBody(), Collider(Circle(radius), friction=0.6))


@rain.claim
def _rain_stays_in_the_box(app) -> None:  # type: ignore[no-untyped-def]
    escaped = [t for _, (t, _rb) in app.world.query(Transform, RigidBody)
               if abs(t.x) > 21.0 or t.y < -1.0]
    assert not escaped, f"{len(escaped)} circles escaped"


@sample("Large", "Sleeping Boxes", help="Boxes resting on a long floor: they fall asleep at once.",
        camera=(0.0, 2.0, 0.5))
def sleeping_boxes(world: World, count: int = 500) -> None:
    span = 1.5 * count
    static_box(world, 0.0, -10.0, span / 2 + 2.0, 10.0, name="ground")
    for i in range(count):
        box(world, -span / 2 + 1.5 * i, 0.515, name="sleeper")


@sleeping_boxes.claim
def _all_asleep(app) -> None:  # type: ignore[no-untyped-def]
    world = app.world
    awake = [e for e in named(world, "sleeper") if world.get(e, RigidBody).awake]
    assert not awake, f"{len(awake)} boxes still awake"


class _Churn(Script):
    """Every ``period`` steps, despawns the oldest ``batch`` boxes and spawns as many new ones."""

    def __init__(self, batch: int, period: int) -> None:
        self.batch = batch
        self.period = period
        self.tick = 0
        self.spawned = 0
        self.despawned = 0

    def on_fixed_update(self, dt: float) -> None:
        self.tick += 1
        if self.tick % self.period:
            return
        old = named(self.world, "churn")[: self.batch]
        for e in old:
            self.world.despawn(e)
        self.despawned += len(old)
        for i in range(self.batch):
            x = -10.0 + 20.0 * ((self.spawned + i) * 0.618034 % 1.0)
            box(self.world, x, 12.0 + (i % 5), 0.4, 0.4, name="churn")
        self.spawned += self.batch


@sample("Large", "Churn", help="Boxes spawned and despawned every few steps (memory, events).",
        camera=(0.0, 6.0, 0.6))
def churn(world: World, count: int = 100, period: int = 5) -> None:
    static_box(world, 0.0, -10.0, 50.0, 10.0, name="ground")
    for i in range(count):
        box(world, -10.0 + 20.0 * (i * 0.618034 % 1.0), 1.0 + 0.9 * (i // 20), 0.4, 0.4,
            name="churn")
    world.spawn(Behaviour(_Churn(max(1, count // 10), period)))


@churn.claim
def _churn_keeps_its_population(app) -> None:  # type: ignore[no-untyped-def]
    assert len(named(app.world, "churn")) == 100


@sample("Large", "Event Storm",
        help="A pyramid struck by a heavy ball; every collider reports contact and hit events.",
        camera=(0.0, 6.0, 0.6))
def event_storm(world: World, rows: int = 15) -> None:
    static_box(world, 0.0, -10.0, 50.0, 10.0, name="ground")
    x0 = -0.5625 * (rows - 1)
    for i in range(rows):
        for j in range(rows - i):
            world.spawn(
                Transform(x0 + 0.5625 * i + 1.125 * j, 0.75 + 1.25 * i),
                RigidBody(),
                Collider(Box(0.5, 0.5), density=5.0, friction=0.2, hit_threshold=0.5),
            )
    world.spawn(Transform(-30.0, 3.0), RigidBody(velocity=(40.0, 2.0), bullet=True),
                Collider(Circle(1.5), density=20.0, hit_threshold=0.5))


@event_storm.claim
def _events_flow(app) -> None:  # type: ignore[no-untyped-def]
    from kge.physics.events import PhysicsEvents

    ev = app.world.resource(PhysicsEvents)
    assert isinstance(ev.contact_begin, list) and isinstance(ev.hits, list)
    fallen = sum(1 for _, (t, _rb) in app.world.query(Transform, RigidBody) if abs(t.angle) > 0.3)
    assert fallen > 0, "the ball should have knocked boxes over"
