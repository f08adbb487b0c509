"""``Physics.states``: many bodies' end-of-step states in one call, equal to their components."""

from __future__ import annotations

import numpy as np
import pytest

from kge.components.collider import Collider
from kge.components.rigidbody import BodyType, RigidBody
from kge.components.shapes import Box, Circle
from kge.components.transform import Transform
from kge.errors import EntityNotFoundError, ValidationError

from .conftest import Sim


def _components(sim: Sim, es: list[int]) -> tuple[np.ndarray, np.ndarray]:
    rows = [(sim.t(e).x, sim.t(e).y, sim.t(e).angle, *sim.rb(e).velocity,
             sim.rb(e).angular_velocity) for e in es]
    return np.array(rows), np.array([sim.rb(e).awake for e in es])


def test_states_equal_the_components_every_step_through_sleep_spawns_and_despawns() -> None:
    sim = Sim()
    try:
        sim.ground()
        es = [sim.dynamic(Box(0.4, 0.3), x, 1.0 + x, 0.2 * x, density=1.0)
              for x in (-2.0, 0.0, 2.0)]
        es.append(sim.dynamic(Circle(0.3), 4.0, 3.0, density=2.0))
        seen_asleep = False
        for k in range(260):
            if k == 40:  # a body spawned between steps reads its pose at spawn
                es.append(sim.dynamic(Circle(0.2), -4.0, 2.0, 0.5, density=1.0))
                states, awake = sim.physics.states(es)
                assert states[-1].tolist() == [-4.0, 2.0, 0.5, 0.0, 0.0, 0.0]
            if k == 80:  # a despawn rebuilds the table: the slots are looked up again
                sim.world.despawn(es.pop(1))
                sim.world.flush()
            sim.step()
            states, awake = sim.physics.states(es)
            want, want_awake = _components(sim, es)
            assert states.tobytes() == want.tobytes()  # bit for bit, zeros of sleepers too
            assert awake.tolist() == want_awake.tolist()
            seen_asleep |= not awake.all()
        assert seen_asleep  # the run covered sleeping bodies (their rows read zero speed)
        assert sim.physics.states(es[::-1])[0].tolist() == sim.physics.states(es)[0][::-1].tolist()
    finally:
        sim.close()


def test_kinematic_bodies_and_fresh_arrays() -> None:
    sim = Sim()
    try:
        kin = sim.spawn(Transform(1.0, 2.0), RigidBody(type=BodyType.KINEMATIC, velocity=(3.0, 0.0)),
                        Collider(Box(0.5, 0.5)))
        sim.step()
        states, awake = sim.physics.states([kin])
        assert states[0, 3] == 3.0 and states[0, 0] == pytest.approx(1.05) and awake.tolist() == [True]
        states[0, 0] = 99.0  # a copy: the table is not changed through it
        assert sim.physics.states([kin])[0][0, 0] == pytest.approx(1.05)
    finally:
        sim.close()


def test_bad_entities_raise_naming_them() -> None:
    sim = Sim()
    try:
        ground = sim.ground()
        box = sim.dynamic(Box(0.5, 0.5), 0.0, 2.0, density=1.0)
        bare = sim.spawn(Transform())
        sim.step()
        with pytest.raises(EntityNotFoundError, match="999999"):
            sim.physics.states([box, 999_999])
        with pytest.raises(ValidationError, match=f"entity {ground} has a static body"):
            sim.physics.states([ground])
        with pytest.raises(ValidationError, match=f"entity {bare} has no body"):
            sim.physics.states([bare])
        with pytest.raises(ValidationError, match="int ids"):
            sim.physics.states([1.5])
        with pytest.raises(ValidationError, match="int ids"):
            sim.physics.states([[box]])
        assert sim.physics.states([])[0].shape == (0, 6)
    finally:
        sim.close()
