"""``Physics.apply_linear_impulses``: many impulses in one call, as if made one by one."""

from __future__ import annotations

import math

import numpy as np
import pytest

from kge.components.collider import Collider
from kge.components.rigidbody import BodyType, RigidBody
from kge.components.shapes import Box, Circle
from kge.components.transform import Transform
from kge.errors import EntityNotFoundError, ValidationError

from .conftest import Sim


def _scene() -> tuple[Sim, list[int]]:
    sim = Sim()
    sim.ground()
    es = [
        sim.dynamic(Box(0.5, 0.25), 0.0, 2.0, density=1.0),
        sim.dynamic(Circle(0.3), 2.0, 3.0, density=2.0),
        sim.dynamic(Box(0.2, 0.6), -2.0, 4.0, 0.3, density=0.5),
    ]
    sim.step()
    return sim, es


ROWS = [(0, (1.0, 2.0), (0.3, 2.1)), (1, (-0.5, 0.0), (2.0, 3.2)),
        (0, (0.25, -1.0), (-0.4, 1.9)), (2, (0.0, 3.0), (-2.1, 4.5))]


def _velocities(sim: Sim, es: list[int]) -> list[tuple[float, float, float]]:
    return [(*sim.rb(e).velocity, sim.rb(e).angular_velocity) for e in es]


def test_rows_equal_the_same_calls_one_by_one() -> None:
    one, es1 = _scene()
    bulk, es2 = _scene()
    try:
        for k, j, p in ROWS:
            one.physics.apply_linear_impulse(es1[k], j, p)
        bulk.physics.apply_linear_impulses(
            [es2[k] for k, _, _ in ROWS], [j for _, j, _ in ROWS], [p for _, _, p in ROWS])
        assert _velocities(bulk, es2) == _velocities(one, es1)  # entity 0 twice, in order
        assert _velocities(bulk, es2)[0][2] != 0.0  # off-centre: it spins
        for s in (one, bulk):
            s.step(10)
        assert [(bulk.t(e).x, bulk.t(e).y) for e in es2] == [(one.t(e).x, one.t(e).y) for e in es1]
    finally:
        one.close()
        bulk.close()


def test_without_points_every_body_is_pushed_at_its_centre() -> None:
    sim, es = _scene()
    try:
        sim.physics.apply_linear_impulses(es, [(1.0, 0.0)] * 3)
        for e in es:
            mass = sim.physics.mass_data(e).mass
            vx, _vy = sim.rb(e).velocity
            assert vx == pytest.approx(1.0 / mass)
            assert sim.rb(e).angular_velocity == pytest.approx(0.0, abs=1e-12)
    finally:
        sim.close()


@pytest.mark.parametrize(
    ("impulses", "points", "message"),
    [
        ([(1.0, 0.0), (math.nan, 0.0), (0.0, 1.0)], None, r"impulses\[1\] \(entity \d+\) must be finite"),
        ([(1.0, 0.0)] * 3, [(0.0, 0.0), (0.0, 0.0), (math.inf, 0.0)], r"points\[2\]"),
        ([(1.0, 0.0)] * 2, None, r"shape \(3, 2\)"),
        ([(1e308, 0.0)] * 3, None, r"would not be finite"),
        ("abc", None, r"impulses"),
    ],
)
def test_a_bad_row_raises_and_applies_nothing(impulses: object, points: object, message: str) -> None:
    sim, es = _scene()
    try:
        before = _velocities(sim, es)
        with pytest.raises(ValidationError, match=message):
            sim.physics.apply_linear_impulses(es, impulses, points)
        assert _velocities(sim, es) == before
    finally:
        sim.close()


def test_bad_entities_are_refused_before_any_change() -> None:
    sim, es = _scene()
    try:
        before = _velocities(sim, es)
        with pytest.raises(EntityNotFoundError):
            sim.physics.apply_linear_impulses([es[0], 999_999], [(1.0, 0.0)] * 2)
        with pytest.raises(ValidationError, match="int ids"):
            sim.physics.apply_linear_impulses([1.5, 2.5], [(1.0, 0.0)] * 2)
        assert _velocities(sim, es) == before
    finally:
        sim.close()


def test_wake_false_leaves_a_sleeping_body_asleep() -> None:
    sim = Sim()
    try:
        sim.ground()
        box = sim.dynamic(Box(0.5, 0.5), 0.0, 0.5, density=1.0)
        sim.step(120)
        assert not sim.rb(box).awake
        sim.physics.apply_linear_impulses([box], [(5.0, 0.0)], wake=False)
        assert not sim.rb(box).awake and sim.rb(box).velocity == (0.0, 0.0)
        sim.physics.apply_linear_impulses([box], [(5.0, 0.0)])
        assert sim.rb(box).awake and sim.rb(box).velocity[0] > 0.0
    finally:
        sim.close()


def test_body_types_that_impulses_do_not_move() -> None:
    sim, es = _scene()
    try:
        kin = sim.spawn(Transform(5.0, 5.0), RigidBody(type=BodyType.KINEMATIC),
                        Collider(Box(0.5, 0.5)))
        sim.step()
        sim.physics.apply_linear_impulses([kin, es[0]], [(9.0, 0.0), (1.0, 0.0)])
        assert sim.rb(kin).velocity == (0.0, 0.0)
        assert sim.rb(es[0]).velocity[0] > 0.0
    finally:
        sim.close()



def test_distinct_awake_bodies_take_the_numpy_path_and_equal_the_calls_one_by_one(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    """One row per body, all awake and dynamic (a batch of engines): pushed in numpy,
    bit for bit what the single calls give (turned bodies, a fixed-rotation body,
    with and without points)."""
    from kge.physics.resource import Physics

    taken: list[bool] = []
    real = Physics._push_distinct

    def spy(self: Physics, *args: object) -> bool:
        taken.append(real(self, *args))  # type: ignore[arg-type]
        return taken[-1]

    monkeypatch.setattr(Physics, "_push_distinct", spy)

    def scene() -> tuple[Sim, list[int]]:
        sim, es = _scene()
        es.append(sim.spawn(Transform(4.0, 2.0, 1.1),
                            RigidBody(type=BodyType.DYNAMIC, fixed_rotation=True),
                            Collider(Box(0.3, 0.3), density=1.0)))
        sim.step(3)  # turned and moving
        return sim, es

    rows = [(2, (0.5, -1.0), (-1.5, 4.1)), (0, (1.0, 2.0), (0.3, 2.1)),
            (3, (0.2, 0.1), (4.4, 2.2)), (1, (-0.5, 0.0), (2.0, 3.2))]
    for with_points in (True, False):
        one, es1 = scene()
        bulk, es2 = scene()
        try:
            for k, j, p in rows:
                one.physics.apply_linear_impulse(es1[k], j, p if with_points else None)
            taken.clear()
            bulk.physics.apply_linear_impulses(
                [es2[k] for k, _, _ in rows], [j for _, j, _ in rows],
                [p for _, _, p in rows] if with_points else None)
            assert taken == [True]
            assert _velocities(bulk, es2) == _velocities(one, es1)
            assert bulk.rb(es2[3]).angular_velocity == one.rb(es1[3]).angular_velocity
            for s in (one, bulk):
                s.step(5)
            assert [(bulk.t(e).x, bulk.t(e).angle) for e in es2] == [
                (one.t(e).x, one.t(e).angle) for e in es1]
        finally:
            one.close()
            bulk.close()


def _spy_ccd_reads(monkeypatch: pytest.MonkeyPatch) -> list[object]:
    """What each step's continuous collision is handed as its read, and a fresh read."""
    from kge.physics.ccd import ContinuousCollision
    from kge.physics.cp.bulk import BodyReader
    from kge.physics.sync import FIELDS

    seen: list[object] = []
    real = ContinuousCollision.before_step

    def spy(self: ContinuousCollision, dt: float, n: int = 1,
            read: tuple[np.ndarray, np.ndarray] | None = None) -> int:
        if read is None:
            seen.append(None)
        else:
            ids, rows = read
            now_ids, now_rows = BodyReader(FIELDS).read(self.space)
            seen.append((np.sort(ids).tolist() == np.sort(now_ids).tolist(),
                         rows[np.argsort(ids)].tobytes() == now_rows[np.argsort(now_ids)].tobytes()))
        return real(self, dt, n, read)

    monkeypatch.setattr(ContinuousCollision, "before_step", spy)
    return seen


def test_bulk_impulses_hand_their_read_to_the_step_while_it_is_current(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    """The bulk impulses keep their bulk read current (the velocities they wrote patched
    in), so the step's continuous collision and joints use it instead of reading again;
    any other change between the impulses and the step drops it."""
    seen = _spy_ccd_reads(monkeypatch)
    sim, es = _scene()
    try:
        pushes = [(1.0, 2.0), (-0.5, 0.3), (0.2, 0.1)]
        points = [(0.3, 2.1), (2.0, 3.2), (-2.1, 4.5)]
        sim.physics.apply_linear_impulses(es, pushes, points)
        sim.step()
        assert seen[-1] == (True, True)  # handed over, and equal to a read at that moment
        for change in ("component", "force", "single impulse", "query after a write"):
            sim.physics.apply_linear_impulses(es, pushes, points)
            if change == "component":
                sim.rb(es[1]).velocity = (4.0, 0.0)
            elif change == "force":
                sim.physics.apply_force(es[0], (1.0, 0.0))
            elif change == "single impulse":
                sim.physics.apply_linear_impulse(es[2], (0.0, 1.0))
            else:
                sim.t(es[0]).x += 0.5
                sim.physics.query_point((0.0, 0.0))  # syncs the teleport before the step
            sim.step()
            assert seen[-1] is None, change
    finally:
        sim.close()
