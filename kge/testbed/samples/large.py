"""Large scenes: the benchmark workloads, also browsable in the testbed.

Each takes its size as a keyword argument so ``benchmarks/`` can build the very
same geometry at 1,000 or 5,000 bodies while the testbed shows a small default.
Helpers that a benchmark needs to repeat a scene's dynamic behaviour on the raw
engines (:func:`churn_position`, :func:`burst`) live here too, so the two cannot
drift apart.
"""

from __future__ import annotations

import math
from collections import deque

from kge.components import Behaviour, Script, Transform
from kge.components.collider import Collider
from kge.components.filter import Filter
from kge.components.joints import RevoluteJoint
from kge.components.rigidbody import BodyType, RigidBody
from kge.components.shapes import Box, Circle
from kge.physics.resource import Physics
from kge.physics.settings import PhysicsSettings
from kge.testbed.registry import sample
from kge.testbed.samples.basics import tumbler
from kge.testbed.samples.build import ball, box, named, static_box
from kge.world import World


def _rain_box(world: World, half: float = 20.0) -> None:
    static_box(world, 0.0, -0.5, half + 1.0, 0.5, name="wall")
    static_box(world, -half - 0.5, 2.0 * half, 0.5, 2.0 * half, name="wall")
    static_box(world, half + 0.5, 2.0 * half, 0.5, 2.0 * half, name="wall")


@sample("Large", "Rain", help="Circles raining into a 40 m open box.")
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
        camera=(0.0, 3.0, 0.4))  # a 750 m row: show its middle, not a hairline
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


def churn_position(k: int) -> tuple[float, float]:
    """Where the ``k``-th box spawned by the churn goes (shared with the benchmarks)."""
    return (-10.0 + 20.0 * (k * 0.618034 % 1.0), 12.0 + (k % 5))


class _Churn(Script):
    """Every ``period`` steps, despawns the oldest ``batch`` boxes and spawns as many new ones."""

    def __init__(self, batch: int, period: int) -> None:
        self.batch = batch
        self.period = period
        self.tick = 0
        self.spawned = 0
        self.despawned = 0
        self.alive: deque[int] | None = None  # oldest first

    def on_fixed_update(self, dt: float) -> None:
        self.tick += 1
        if self.tick % self.period:
            return
        if self.alive is None:
            self.alive = deque(named(self.world, "churn"))
        for _ in range(min(self.batch, len(self.alive))):
            self.world.despawn(self.alive.popleft())
            self.despawned += 1
        for _ in range(self.batch):
            x, y = churn_position(self.spawned)
            self.alive.append(box(self.world, x, y, 0.4, 0.4, name="churn"))
            self.spawned += 1


@sample("Large", "Churn", help="Boxes spawned and despawned every few steps (memory, events).")
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
        help="A pyramid struck by a heavy ball; every collider reports contact and hit events.")
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
    fallen = sum(1 for _, (t, _rb) in app.world.query(Transform, RigidBody) if abs(t.angle) > 0.3)
    assert fallen > 0, "the ball should have knocked boxes over"


def _max_joint_gap(world: World) -> float:
    """Largest distance between the two anchors of any revolute joint (m)."""
    physics = world.resource(Physics)
    gap = 0.0
    for _, (j,) in world.query(RevoluteJoint):
        pa = j.local_anchor_a if j.body_a is None else physics.world_point(
            j.body_a, j.local_anchor_a)
        pb = j.local_anchor_b if j.body_b is None else physics.world_point(
            j.body_b, j.local_anchor_b)
        gap = max(gap, math.dist(pa, pb))
    return gap


@sample("Large", "Chains", help="Chains of 40 links (revolute joints), each pinned to the ground.")
def chains(world: World, count: int = 40, links: int = 8) -> None:
    """``count`` links in all, as chains of ``links`` (the benchmark: 5 chains of 40)."""
    never_touch = Filter(group_index=-1)  # only the joints act: no link-link contacts
    for c in range(max(1, count // links)):
        x0 = 2.0 * c
        prev: int | None = None
        for i in range(links):
            link = box(world, x0 + 0.5 + i, 45.0, 0.6, 0.125, density=20.0, friction=0.2,
                       name="link", filter=never_touch)
            world.spawn(RevoluteJoint(prev, link, anchor=(x0 + float(i), 45.0)))
            prev = link


@chains.claim
def _chains_hang_together(app) -> None:  # type: ignore[no-untyped-def]
    gap = _max_joint_gap(app.world)
    assert gap < 0.05, f"a chain joint opened by {gap:.3f} m"
    last = app.world.get(named(app.world, "link")[-1], Transform)
    assert last.y < 44.0, "the chains should swing down"


@sample("Large", "Joint Grid",
        help="A grid of circles joined to their neighbours by revolute joints, hung by its top.")
def joint_grid(world: World, side: int = 10) -> None:
    """Box2D v3's joint grid: ``side`` x ``side`` circles; the middle of the top row is fixed."""
    no_self = Filter(category_bits=2, mask_bits=0xFFFF & ~2)  # circles never touch each other
    ids: list[list[int]] = []
    mid = side // 2
    for k in range(side):
        column: list[int] = []
        for i in range(side):
            pinned = i == 0 and mid - 3 <= k <= mid + 3
            e = ball(world, float(k), -float(i), 0.4, density=1.0, name="node", filter=no_self,
                     body=BodyType.STATIC if pinned else BodyType.DYNAMIC)
            if i > 0:
                world.spawn(RevoluteJoint(column[i - 1], e, anchor=(float(k), 0.5 - i)))
            if k > 0:
                world.spawn(RevoluteJoint(ids[k - 1][i], e, anchor=(k - 0.5, -float(i))))
            column.append(e)
        ids.append(column)


@joint_grid.claim
def _grid_holds(app) -> None:  # type: ignore[no-untyped-def]
    gap = _max_joint_gap(app.world)
    assert gap < 0.1, f"a grid joint opened by {gap:.3f} m"


@sample("Large", "Full Tumbler",
        help="The tumbler, prefilled with small boxes (the benchmark's 2,000).")
def full_tumbler(world: World, count: int = 200) -> None:
    tumbler(world, count=0)
    per_row = 45
    for i in range(count):
        row, col = divmod(i, per_row)
        box(world, -6.6 + 0.3 * col, 3.4 + 0.3 * row, 0.125, 0.125, density=1.0,
            name="tumbled")


@full_tumbler.claim
def _tumbler_keeps_its_boxes(app) -> None:  # type: ignore[no-untyped-def]
    for e in named(app.world, "tumbled"):
        t = app.world.get(e, Transform)
        assert math.hypot(t.x, t.y - 10.0) < 15.0, f"box escaped the drum: {t}"


@sample("Large", "Box Pile", help="Boxes dropped close together into a 40 m box: a dense pile.")
def box_pile(world: World, count: int = 300, sleep: bool = True) -> None:
    """``sleep=False`` keeps the whole pile awake (the benchmark's worst case)."""
    if not sleep:
        world.insert_resource(PhysicsSettings(sleep=False))
    _rain_box(world)
    per_row = 64
    for i in range(count):
        row, col = divmod(i, per_row)
        box(world, -18.9 + col * 0.6 + 0.1 * (row % 2), 0.3 + row * 0.55, 0.25, 0.25,
            density=1.0, friction=0.6, name="piled")


@box_pile.claim
def _pile_stays_in_the_box(app) -> None:  # type: ignore[no-untyped-def]
    escaped = [t for _, (t, _rb) in app.world.query(Transform, RigidBody)
               if abs(t.x) > 21.0 or t.y < -1.0]
    assert not escaped, f"{len(escaped)} boxes escaped"


@sample("Large", "Sparse Field",
        help="Circles drifting without gravity, far apart: the cost of bodies, not contacts.")
def sparse_field(world: World, count: int = 200) -> None:
    world.insert_resource(PhysicsSettings(gravity=(0.0, 0.0)))
    side = max(1, math.ceil(math.sqrt(count)))
    for i in range(count):
        row, col = divmod(i, side)
        velocity = ((i * 0.37) % 1.0 - 0.5, (i * 0.61) % 1.0 - 0.5)
        ball(world, 2.0 * (col - side / 2), 2.0 * (row - side / 2), 0.25, name="drifter",
             velocity=velocity)


@sparse_field.claim
def _drifters_keep_moving(app) -> None:  # type: ignore[no-untyped-def]
    awake = sum(1 for _, (rb,) in app.world.query(RigidBody) if rb.awake)
    assert awake > 0, "drifting bodies should stay awake"


def burst_position(i: int) -> tuple[float, float]:
    """Where the ``i``-th box of a spawn burst goes: a grid, no two touching."""
    row, col = divmod(i, 50)
    return (-36.75 + 1.5 * col, 2.0 + 1.5 * row)


def burst(world: World, count: int) -> list[int]:
    """Spawn ``count`` boxes at once, as a game spawning a wave would."""
    out = []
    for i in range(count):
        x, y = burst_position(i)
        out.append(box(world, x, y, name="burst"))
    return out


class _Burst(Script):
    """Every ``period`` steps, despawns the last burst and spawns a new one."""

    def __init__(self, count: int, period: int) -> None:
        self.count = count
        self.period = period
        self.tick = 0

    def on_fixed_update(self, dt: float) -> None:
        self.tick += 1
        if self.tick % self.period == 0:
            for e in named(self.world, "burst"):
                self.world.despawn(e)
            burst(self.world, self.count)


@sample("Large", "Spawn Burst",
        help="Spawns a wave of boxes in one frame, every half second (0 = only once).")
def spawn_burst(world: World, count: int = 100, period: int = 30) -> None:
    static_box(world, 0.0, -10.0, 50.0, 10.0, name="ground")
    burst(world, count)
    if period > 0:
        world.spawn(Behaviour(_Burst(count, period)))


@spawn_burst.claim
def _bursts_replace_each_other(app) -> None:  # type: ignore[no-untyped-def]
    assert len(named(app.world, "burst")) == 100
