"""Which Transforms the blend reads, and how every other change reaches the pose table.

The blend reads only Transforms that user code wrote since the last step or
frame (marked through the Transform's binding, which physics shares). Steps
are read in full by ``record``, physics' history is checked by ``adopt``, and
replaced Transforms come through ``set_transform``. These tests break if any
of those paths stops reaching the table.
"""

from __future__ import annotations

import numpy as np

from kge import Transform
from kge.components.camera import Camera
from kge.components.collider import Collider
from kge.components.rigidbody import RigidBody
from kge.components.shapes import Box
from kge.components.sprite import Sprite
from kge.components.tracked import bind, raw_set, unbind
from kge.render.images import solid
from kge.render.poses import PoseTable
from kge.schedule import Stage, System, SystemSet
from kge.systems.render import RenderSystem

from .conftest import SIZE, bbox, mask, pixels

RED = (255, 0, 0)
PPM = 20  # pixels per metre in every scene here


def _sprite() -> Sprite:
    return Sprite(solid(2, 2, RED), size=(1, 1))


def _center_x(app) -> float:
    """Where the red sprite is drawn, in metres right of the window centre."""
    x0, x1, _, _ = bbox(mask(pixels(app), RED))
    return ((x0 + x1 + 1) / 2 - SIZE[0] / 2) / PPM


def _close(app, x: float) -> bool:
    """The red sprite is drawn at ``x`` metres, within a pixel."""
    return abs(_center_x(app) - x) <= 1 / PPM


def _view(app):
    system = app.world.get_system(RenderSystem)
    assert system is not None
    return system.view


def _half_step(app) -> None:
    app.timestep.accumulator = 0.5 * app.fixed_dt


# -- bindings shared by several systems -------------------------------------------------
def test_a_transform_bound_by_two_systems_marks_both_in_either_order():
    for order in ((0, 1), (1, 0)):
        t = Transform()
        sets: list[set[int]] = [set(), set()]  # physics' and the renderer's
        for i in order:
            bind(t, 5, sets[i])
        t.x = 1.0
        assert sets == [{5}, {5}]
        bind(t, 5, sets[0])  # binding the same set again adds nothing
        assert t._binding is not None and len(t._binding.sets) == 2
        unbind(t, sets[1])
        for s in sets:
            s.clear()
        t.y = 2.0
        assert sets == [{5}, set()]
        unbind(t)
        sets[0].clear()
        t.angle = 0.5
        assert sets == [set(), set()]


def test_binding_a_component_to_another_entity_replaces_the_old_binding():
    t = Transform()
    old: set[int] = set()
    new: set[int] = set()
    bind(t, 1, old)
    bind(t, 2, new)
    t.x = 1.0
    assert old == set()
    assert new == {2}


# -- the table on its own -----------------------------------------------------------------
def test_a_user_write_between_steps_is_read_by_the_next_blend_only():
    table = PoseTable()
    t = Transform(0.0, 0.0)
    row = table.acquire(1, t)
    t.x = 1.0
    table.record()  # a step: 0 -> 1
    assert table.written == set()  # the step read every Transform
    t.x = 5.0  # an on_update script
    assert table.written == {1}
    np.testing.assert_allclose(table.blend(0.5)[row], (5.0, 0.0, 0.0))  # drawn at once
    assert table.written == set()
    np.testing.assert_allclose(table.last_live[row], (5.0, 0.0, 0.0))


def test_record_reads_only_written_rows_and_physics_comes_through_adopt():
    """A step reads no Transform nobody wrote: moves written without a mark (physics'
    sync-out) are drawn from physics' own history, handed over by ``adopt``."""
    table = PoseTable()
    t = Transform(0.0, 0.0)
    row = table.acquire(1, t)
    raw_set(t, "x", 1.0)  # physics' sync-out inside the step
    table.record()
    np.testing.assert_allclose(table.blend(0.5)[row], (0.0, 0.0, 0.0))  # not read
    table.adopt(np.array([1]), np.array([[0.0, 0.0, 0.0]]), np.array([[1.0, 0.0, 0.0]]))
    np.testing.assert_allclose(table.blend(0.5)[row], (0.5, 0.0, 0.0))
    raw_set(t, "x", 1.5)
    table.record()
    table.adopt(np.array([1]), np.array([[1.0, 0.0, 0.0]]), np.array([[1.5, 0.0, 0.0]]))
    np.testing.assert_allclose(table.blend(0.5)[row], (1.25, 0.0, 0.0))


def test_a_written_body_whose_transform_disagrees_with_physics_is_drawn_at_its_transform():
    table = PoseTable()
    t = Transform(0.0, 0.0)
    row = table.acquire(1, t)
    t.x = 7.0  # a teleport after physics synced (a contact handler)
    table.record()
    table.adopt(np.array([1]), np.array([[0.0, 0.0, 0.0]]), np.array([[0.1, 0.0, 0.0]]))
    np.testing.assert_allclose(table.blend(0.5)[row], (7.0, 0.0, 0.0))



def test_a_replaced_transform_is_read_and_the_old_one_forgotten():
    table = PoseTable()
    old, new = Transform(1.0, 0.0), Transform(3.0, 0.0)
    row = table.acquire(1, old)
    table.set_transform(1, new)
    assert old._binding is None
    np.testing.assert_allclose(table.blend(0.5)[row], (3.0, 0.0, 0.0))
    old.x = 9.0
    assert table.written == set()
    new.x = 4.0
    np.testing.assert_allclose(table.blend(0.5)[row], (4.0, 0.0, 0.0))
    table.set_transform(1, None)  # Transform removed: drawn at the origin, nothing bound
    assert new._binding is None
    np.testing.assert_allclose(table.blend(0.5)[row], (0.0, 0.0, 0.0))


def test_a_released_row_unbinds_its_transform_and_is_reused():
    table = PoseTable()
    a, b = Transform(1.0, 0.0), Transform(2.0, 0.0)
    row = table.acquire(10, a)
    a.x = 1.5
    table.release(10)
    assert a._binding is None
    assert table.written == set()
    assert table.acquire(11, b) == row
    b.y = 3.0
    assert table.written == {11}
    np.testing.assert_allclose(table.blend(0.5)[row], (2.0, 3.0, 0.0))


def _table_at(x: float) -> tuple[PoseTable, Transform, int]:
    table = PoseTable()
    t = Transform(0.0, 0.0)
    return table, t, table.acquire(1, t)


def test_adopt_takes_the_physics_history_of_a_transform_physics_wrote():
    table, t, row = _table_at(0.0)
    raw_set(t, "x", 0.5)  # physics' sync-out
    table.record()
    table.adopt(np.array([1]), np.array([[0.25, 0.0, 0.0]]), np.array([[0.5, 0.0, 0.0]]))
    np.testing.assert_allclose(table.blend(0.5)[row], (0.375, 0.0, 0.0))


def test_adopt_snaps_a_transform_written_after_physics_synced():
    table, t, row = _table_at(0.0)
    raw_set(t, "x", 0.5)  # physics' sync-out ...
    t.x = -1.0  # ... then a contact handler teleports it; physics has not seen that
    table.record()
    table.adopt(np.array([1]), np.array([[0.25, 0.0, 0.0]]), np.array([[0.5, 0.0, 0.0]]))
    np.testing.assert_allclose(table.blend(0.5)[row], (-1.0, 0.0, 0.0))


def test_adopt_without_a_record_still_checks_the_transform():
    table, t, row = _table_at(0.0)
    raw_set(t, "x", 0.5)  # table.cur is stale (0), the Transform agrees with physics
    table.adopt(np.array([1]), np.array([[0.25, 0.0, 0.0]]), np.array([[0.5, 0.0, 0.0]]))
    np.testing.assert_allclose(table.blend(0.5)[row], (0.375, 0.0, 0.0))


# -- in an App ----------------------------------------------------------------------------
class _TeleportAfterPhysics(System):
    """Writes ``x`` into a Transform after the physics step (like a contact handler)."""

    stage = Stage.FIXED
    in_set = SystemSet.PHYSICS_EVENTS  # like a contact handler: after the step

    def __init__(self) -> None:
        self.target: tuple[int, float] | None = None

    def process(self, dt: float) -> None:
        if self.target is not None:
            entity, x = self.target
            self.world.get(entity, Transform).x = x
            self.target = None


def _sliding_app(make_app, **camera):
    """A red sprite on a body sliding at 30 m/s (0.5 m per step), and the teleporter."""
    state = {}

    def scene(world):
        world.insert_resource(Camera(pixels_per_meter=PPM, **camera))
        state["entity"] = e = world.spawn(
            Transform(0.0, 0.0),
            _sprite(),
            RigidBody(velocity=(30.0, 0.0), gravity_scale=0.0),
            Collider(Box(0.5, 0.5)),
        )
        if camera:
            world.resource(Camera).follow = e
        state["teleport"] = world.add_system(_TeleportAfterPhysics())

    app = make_app(scene)
    app.render()
    return app, state["entity"], state["teleport"]


def test_a_body_moved_between_steps_is_drawn_at_once_and_teleported_by_physics(make_app):
    app, e, _ = _sliding_app(make_app)
    app.step(1)
    app.world.get(e, Transform).x = -2.0  # marks physics' set and the renderer's
    _half_step(app)
    assert _close(app, -2.0)
    app.step(1)  # physics teleported the body: -2.0 -> -1.5
    _half_step(app)
    assert _close(app, -1.75)


def test_a_teleport_after_the_physics_step_is_drawn_where_it_is(make_app):
    app, e, teleport = _sliding_app(make_app)
    app.step(1)  # x = 0.5
    teleport.target = (e, -1.0)  # physics moves it to 1.0, then this writes -1.0
    app.step(1)
    _half_step(app)
    assert _close(app, -1.0)  # physics' history (0.5 -> 1.0) does not apply


def test_camera_follow_centres_the_drawn_pose(make_app):
    app, _, _ = _sliding_app(make_app, smoothing=0.0)
    app.step(2)  # previous 0.5, current 1.0; the camera follows the Transform (1.0)
    _half_step(app)
    assert _close(app, 0.0)  # drawn at 0.75, and the view centred on what is drawn


def _still_app(make_app, x: float = 0.0):
    state = {}

    def scene(world):
        world.insert_resource(Camera(pixels_per_meter=PPM))
        state["entity"] = world.spawn(Transform(x, 0.0), _sprite())

    app = make_app(scene)
    app.render()
    app.step(1)
    return app, state["entity"]


def test_a_replaced_transform_component_is_drawn_and_tracked(make_app):
    app, e = _still_app(make_app)
    old = app.world.get(e, Transform)
    app.world.add(e, Transform(2.0, 0.0))
    assert _close(app, 2.0)
    app.world.get(e, Transform).x = -1.0
    assert _close(app, -1.0)
    old.x = 3.0  # no longer the entity's
    assert _close(app, -1.0)


def test_a_despawned_row_is_reused_and_tracked_for_the_new_entity(make_app):
    app, a = _still_app(make_app, x=-2.0)
    row = _view(app).poses.row_of[a]
    app.world.despawn(a)
    app.world.flush()
    b = app.world.spawn(Transform(1.5, 0.0), _sprite())
    assert _close(app, 1.5)
    assert _view(app).poses.row_of[b] == row
    app.world.get(b, Transform).x = -0.5
    assert _close(app, -0.5)


def test_a_new_scene_tracks_its_own_transforms(make_app):
    app, a = _still_app(make_app, x=-2.0)
    old_view, old_t = _view(app), app.world.get(a, Transform)

    def second(world):
        world.insert_resource(Camera(pixels_per_meter=PPM))
        world.spawn(Transform(1.0, 0.0), _sprite())

    app.replace_scene(second)
    assert _close(app, 1.0)
    assert old_view.poses.row_of == {}  # the closed view released every row
    ((_, (t,)),) = app.world.query(Transform)
    t.x = -1.0
    old_t.x = 4.0
    assert _close(app, -1.0)


def test_rows_are_found_by_entity_without_a_table_as_large_as_the_largest_id():
    """Entity ids are never reused: a long game reaches large ids with few live rows."""
    table = PoseTable()
    big = 10**12  # a table indexed by id would need terabytes
    t = Transform(0.0, 0.0)
    row = table.acquire(big, t)
    table.acquire(3, Transform(5.0, 5.0))
    table.record()
    table.adopt(np.array([big, 7]), np.array([[0.0, 0.0, 0.0]] * 2), np.array([[2.0, 0.0, 0.0]] * 2))
    np.testing.assert_allclose(table.blend(1.0)[row], (2.0, 0.0, 0.0))
    table.release(big)
    table.adopt(np.array([big]), np.array([[0.0, 0.0, 0.0]]), np.array([[9.0, 0.0, 0.0]]))
    assert len(table) == 2 and big not in table.row_of


def test_the_table_shrinks_back_once_its_entities_are_gone() -> None:
    table = PoseTable()
    transforms = {e: Transform(float(e), 0.0) for e in range(1, 501)}
    alive: list[int] = []
    for e, t in transforms.items():  # churn: 500 entities, 40 alive at once
        table.acquire(e, t)
        alive.append(e)
        if len(alive) > 40:
            table.release(alive.pop(0))
        table.record()
        assert len(table) <= 2 * 40 + 2
    for e in alive[:-1]:
        table.release(e)
    last = alive[-1]
    table.record()
    row = table.row_of[last]
    assert tuple(table.cur[row]) == (float(last), 0.0, 0.0)  # the live row kept its pose
    table.release(last)
    assert len(table) == 0 and table._free == [] and len(table.cur) == 64
    e = table.acquire(7, Transform(3.0, 4.0))
    assert e == 0 and tuple(table.cur[0]) == (3.0, 4.0, 0.0)
