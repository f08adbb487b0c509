"""Despawn spam: 100 touching bodies, one despawned per frame, from every kind of caller.

pybox2d segfaults when bodies are destroyed inside EndContact; kge queues a
despawn made anywhere in a running frame (behaviours, contact hooks) and
applies it at the next flush, so each of these runs must end with every body
gone, every begin event matched by one end, and nothing left in pymunk.
"""

from __future__ import annotations

from kge import App, Behaviour, BodyType, Box, Collider, RigidBody, Script, Transform, World
from kge.physics.events import ContactBegin, ContactEnd

from .harness import AppProbe, check_invariants

N = 100
HALF = 0.25


def row(world: World, doomed: bool = False) -> list[int]:
    """Ground plus N boxes side by side, touching (contacts with both neighbours)."""
    world.spawn(Transform(0.0, -1.0), Collider(Box(40.0, 1.0)))
    boxes = []
    for i in range(N):
        parts: list[object] = [
            Transform(-25.0 + 2 * HALF * i, HALF),
            RigidBody(),
            Collider(Box(HALF, HALF), friction=0.6),
        ]
        if doomed:
            parts.append(Behaviour(Doomed()))
        boxes.append(world.spawn(*parts))
    return boxes


class Reaper(Script):
    """Despawns the oldest remaining box every fixed step."""

    def __init__(self, boxes: list[int]) -> None:
        self.boxes = list(boxes)

    def on_fixed_update(self, dt: float) -> None:
        while self.boxes:
            e = self.boxes.pop(0)
            if self.world.exists(e):
                self.world.despawn(e)
                return


class Doomed(Script):
    """A box that despawns itself when the sweeper touches it, and its neighbour on contact end."""

    def on_contact_begin(self, event: ContactBegin) -> None:
        other = event.body_b if event.body_a == self.entity else event.body_a
        touched = other is not None and self.world.has(other, Sweeper.Tag)
        if touched and self.world.exists(self.entity):
            self.world.despawn(self.entity)

    def on_contact_end(self, event: ContactEnd) -> None:
        # an end caused by a despawn arrives for the survivor: despawning it too (in the
        # hook of the end event) is exactly what crashed pybox2d
        if self.world.exists(self.entity) and self.entity % 7 == 0:
            self.world.despawn(self.entity)


class Sweeper(Script):
    """A kinematic probe teleported onto the next box every step (one new contact a frame)."""

    class Tag:
        pass

    def __init__(self, boxes: list[int]) -> None:
        self.boxes = boxes

    def on_fixed_update(self, dt: float) -> None:
        alive = [e for e in self.boxes if self.world.exists(e)]
        if alive:
            target = self.world.get(alive[0], Transform)
            self.transform.x, self.transform.y = target.x, target.y + 2 * HALF - 0.05


def _finish(probe: AppProbe, boxes: list[int], max_steps: int) -> None:
    for _ in range(max_steps):
        probe.step()
        check_invariants(probe)
        if not any(probe.world.exists(e) for e in boxes):
            break
    probe.step(2)
    check_invariants(probe)
    assert not any(probe.world.exists(e) for e in boxes), "some boxes were never despawned"
    assert probe.balance.begins > N, "the boxes should have been touching"
    assert probe.balance.begins == probe.balance.ends
    assert not probe.balance.live_pairs()


def test_one_despawn_per_frame_from_test_code() -> None:
    boxes: list[int] = []
    app = App(lambda world: boxes.extend(row(world)), headless=True)
    probe = AppProbe(app)
    probe.step(10)  # settle: every box touches the ground and its neighbours
    for e in boxes:
        app.world.despawn(e)
        probe.step()
        check_invariants(probe)
    _finish(probe, boxes, 5)
    app.close()


def test_one_despawn_per_frame_from_a_behaviour() -> None:
    boxes: list[int] = []

    def scene(world: World) -> None:
        boxes.extend(row(world))
        world.spawn(Behaviour(Reaper(boxes)))

    app = App(scene, headless=True)
    _finish(AppProbe(app), boxes, N + 10)
    app.close()


def test_despawns_from_contact_hooks() -> None:
    boxes: list[int] = []

    def scene(world: World) -> None:
        boxes.extend(row(world, doomed=True))
        world.spawn(
            Transform(-30.0, 5.0), RigidBody(type=BodyType.KINEMATIC), Collider(Box(HALF, HALF)),
            Sweeper.Tag(), Behaviour(Sweeper(boxes)),
        )

    app = App(scene, headless=True)
    _finish(AppProbe(app), boxes, N + 10)
    app.close()
