"""Broad phase and solver threads: ``PhysicsSettings.spatial_hash`` and ``threads``.

Both are speed settings for large scenes (docs/benchmarks.md has the measured
wins). The spatial hash is deterministic; the threaded solver is not, which is
why it is off by default and documented as such. Both are chosen before the
first step, and a later change is refused with the settings left as they were.
"""

from __future__ import annotations

import math

import pymunk
import pytest

import kge
from kge.components.collider import Collider
from kge.components.rigidbody import RigidBody
from kge.components.shapes import Box
from kge.components.transform import Transform
from kge.errors import KgeError, ValidationError
from kge.physics.settings import PhysicsSettings
from kge.systems.physics import PhysicsSystem
from kge.world import World


def _pile(world: World, **settings: object) -> None:
    world.insert_resource(PhysicsSettings(**settings))  # type: ignore[arg-type]
    world.spawn(Transform(0.0, 0.0), Collider(Box(20.0, 1.0)))
    for i in range(40):
        world.spawn(
            Transform(float(i % 8) - 4.0, 2.0 + 1.2 * (i // 8)),
            RigidBody(),
            Collider(Box(0.5, 0.5), density=1.0),
        )


def _run(steps: int = 150, **settings: object) -> tuple[kge.App, list[tuple[float, float, float]]]:
    app = kge.App(lambda w: _pile(w, **settings), headless=True)
    app.step(steps)
    poses = [(t.x, t.y, t.angle) for _, (t, _rb) in app.world.query(Transform, RigidBody)]
    return app, poses


def _space(app: kge.App) -> pymunk.Space:
    system = app.world.get_system(PhysicsSystem)
    assert system is not None
    return system.sim.space


def _settled(poses: list[tuple[float, float, float]]) -> None:
    """Forty boxes dropped on the ground rest on it in five layers, none lost."""
    assert len(poses) == 40
    ys = sorted(p[1] for p in poses)
    assert ys[0] == pytest.approx(1.5, abs=0.03)  # on the ground's top (y = 1), half a box up
    assert all(1.4 < y < 8.0 for y in ys)
    assert all(abs(x) < 6.0 and math.isfinite(a) for x, _, a in poses)


def test_spatial_hash_settles_the_pile_and_replays_bit_for_bit() -> None:
    app, first = _run(spatial_hash=1.0)
    space = _space(app)
    # Chipmunk's hash answers queries too: a ray down the middle hits the pile's top
    hit = app.world.resource(kge.Physics).raycast((0.25, 20.0), (0.25, -5.0))
    assert hit is not None and 1.0 < hit.point[1] < 7.0
    _settled(first)
    _, second = _run(spatial_hash=1.0)
    assert first == second  # deterministic, like the tree
    assert space is _space(app)


def test_threads_two_solves_on_pymunks_threaded_space() -> None:
    app, poses = _run(threads=2)
    space = _space(app)
    assert space.threaded is True and space.threads == 2
    _settled(poses)
    serial, _ = _run()
    assert _space(serial).threaded is False  # the default stays serial


def test_default_serial_space_replays_bit_for_bit() -> None:
    _, a = _run(60)
    _, b = _run(60)
    assert a == b


def test_threads_change_after_the_first_step_is_refused_and_undone() -> None:
    app, _ = _run(5)
    settings = app.world.resource(PhysicsSettings)
    settings.threads = 2
    with pytest.raises(ValidationError, match=r"PhysicsSettings\.threads.*before the first step"):
        app.step()
    assert settings.threads == 1  # left as the space is
    app.step()  # and the world steps on as before


def test_spatial_hash_cannot_go_back_to_the_tree() -> None:
    app, _ = _run(5, spatial_hash=1.0)
    settings = app.world.resource(PhysicsSettings)
    settings.spatial_hash = 2.0  # another cell size is fine at any time
    app.step()
    settings.spatial_hash = None
    with pytest.raises(ValidationError, match=r"spatial_hash.*cannot go back"):
        app.step()
    assert settings.spatial_hash == 2.0
    app.step()


@pytest.mark.parametrize(
    ("field", "value"),
    [("threads", 3), ("threads", 0), ("threads", 1.5), ("spatial_hash", -1.0),
     ("spatial_hash", math.nan), ("spatial_hash", 0.0), ("spatial_hash", "1")],
)
def test_bad_values_are_refused_at_the_write(field: str, value: object) -> None:
    s = PhysicsSettings()
    with pytest.raises(KgeError, match=f"PhysicsSettings.{field}"):
        setattr(s, field, value)
    assert getattr(s, field) == {"threads": 1, "spatial_hash": None}[field]
