"""Physics debug view: shapes by body state, joints, contacts, retained meshes."""

from __future__ import annotations

import numpy as np
import pytest

from kge import Transform
from kge.components.camera import Camera
from kge.components.collider import Collider
from kge.components.debug import DebugDraw
from kge.components.joints import RevoluteJoint
from kge.components.rigidbody import BodyType, RigidBody
from kge.components.shapes import Box, Circle
from kge.systems.render import RenderSystem

from .conftest import SIZE, mask, pixels

PPM = 40
D = DebugDraw()


def near(m: np.ndarray, world: tuple[float, float], r: int = 2) -> bool:
    """Any pixel of mask ``m`` within ``r`` px of a world point (camera at the origin)."""
    x = round(SIZE[0] / 2 + world[0] * PPM)
    y = round(SIZE[1] / 2 + world[1] * PPM)
    return bool(m[max(0, y - r) : y + r + 1, max(0, x - r) : x + r + 1].any())


def scene(world):
    world.insert_resource(Camera(pixels_per_meter=PPM))
    world.insert_resource(DebugDraw(contact_seconds=10.0))
    world.spawn(Transform(0.0, -1.6), Collider(Box(2.4, 0.2)))  # implicit static ground
    world.spawn(Transform(0.0, -1.15), RigidBody(), Collider(Box(0.3, 0.3)))  # overlaps: contact
    world.spawn(Transform(-1.5, 0.8), RigidBody(), Collider(Circle(0.4)))
    ball = world.spawn(Transform(1.5, 0.3), RigidBody(), Collider(Circle(0.3)))
    world.spawn(RevoluteJoint(None, ball, anchor=(1.5, 1.5)))


def test_debug_draw_shows_shapes_joint_and_contact_in_their_colours(make_app):
    app = make_app(scene)
    app.render()
    app.step(1)
    px = pixels(app)
    static, awake = mask(px, D.static_color[:3], 12), mask(px, D.awake_color[:3], 12)
    joint, contact = mask(px, D.joint_color[:3], 12), mask(px, D.contact_color[:3], 12)
    assert near(static, (2.4, -1.6))  # right edge of the ground box
    assert near(awake, (-1.5, 1.2)) and near(awake, (-1.1, 0.8))  # the circle's rim
    assert not near(awake, (-1.5, 0.5), r=1)  # outline only
    assert near(joint, (1.5, 1.0)) and near(joint, (0.75, 0.75))  # anchor lines (Box2D layout)
    assert contact.sum() >= 8 and near(contact, (0.3, -1.4), r=4)
    assert near(mask(px, D.normal_color[:3], 12), (0.3, -1.25), r=3)  # normal points up


def test_outlines_are_retained_and_recoloured_by_state(make_app):
    app = make_app(scene)
    app.render()
    view = app.world.get_system(RenderSystem).view
    lists = dict(view.debug.meshes.lists)
    shapes = {k: v for k, v in lists.items() if k[0] == "shape"}
    assert len(shapes) == 4
    app.step(3)
    app.render()
    for k, vl in shapes.items():
        assert view.debug.meshes.lists[k] is vl  # moved, not rebuilt
    for _e, (rb,) in app.world.query(RigidBody):
        rb.enabled = False
    px = pixels(app)
    assert near(mask(px, D.disabled_color[:3], 12), (-1.1, 0.8), r=4)
    for _e, (rb,) in app.world.query(RigidBody):
        rb.enabled = True
        rb.type = BodyType.KINEMATIC
    px = pixels(app)
    assert near(mask(px, D.kinematic_color[:3], 12), (-1.1, 0.8), r=4)


def test_debug_draw_toggles_at_run_time(make_app):
    app = make_app(scene)
    app.render()
    app.world.resource(DebugDraw).enabled = False
    px = pixels(app)
    assert not mask(px, D.static_color[:3], 12).any()
    app.world.resource(DebugDraw).enabled = True
    app.world.resource(DebugDraw).aabbs = True
    app.world.resource(DebugDraw).centers_of_mass = True
    px = pixels(app)
    aabb = mask(px, D.aabb_color[:3], 12)
    assert near(aabb, (-1.1, 1.2), r=2) and not near(aabb, (0.0, 0.0), r=8)  # circle AABB corner
    assert near(mask(px, (230, 76, 76), 12), (1.7, 0.3), r=2)  # centre-of-mass x axis, red


def test_stats_overlay_counts_bodies(make_app):
    app = make_app(scene)
    app.world.resource(DebugDraw).stats = True
    app.render()
    app.step(2)
    app.render()
    view = app.world.get_system(RenderSystem).view
    values = view.stat_values()
    assert values["bodies"] == 3 and values["contacts"] >= 1
    assert "bodies 3" in view.stats.text


def joints_scene(world):
    from kge.components.joints import DistanceJoint, MouseJoint, PulleyJoint
    from kge.components.shapes import Chain, Edge

    world.insert_resource(Camera(pixels_per_meter=PPM))
    world.insert_resource(DebugDraw())
    world.spawn(Transform(0.0, -1.8), Collider(Edge((-2.0, 0.0), (2.0, 0.0))))
    world.spawn(Transform(), Collider(Chain(((-2.3, -1.0), (-2.3, 1.5), (-1.8, 1.9)))))
    a = world.spawn(Transform(-1.2, 0.0), RigidBody(), Collider(Circle(0.2)))
    b = world.spawn(Transform(-0.2, 0.0), RigidBody(), Collider(Circle(0.2)))
    world.spawn(DistanceJoint(a, b, anchor_a=(-1.2, 0.0), anchor_b=(-0.2, 0.0)))
    c = world.spawn(Transform(1.0, -1.0), RigidBody(), Collider(Circle(0.2)))
    world.spawn(MouseJoint(None, c, target=(1.0, -1.0), max_force=10.0))
    d = world.spawn(Transform(0.6, 0.8), RigidBody(), Collider(Circle(0.15)))
    e = world.spawn(Transform(2.0, 0.8), RigidBody(), Collider(Circle(0.15)))
    world.spawn(
        PulleyJoint(
            d,
            e,
            ground_anchor_a=(0.6, 1.8),
            ground_anchor_b=(2.0, 1.8),
            anchor_a=(0.6, 0.8),
            anchor_b=(2.0, 0.8),
        )
    )


def test_joint_layouts_and_edge_chain_outlines(make_app):
    app = make_app(joints_scene)
    app.render()
    from kge.components.joints import MouseJoint

    ((_, (mouse,)),) = app.world.query(MouseJoint)
    mouse.target = (1.0, -0.2)  # drag: the anchor stays where the target was at creation
    for steps in (0, 1):  # before physics resolves the anchors, and after
        app.step(steps)
        px = pixels(app)
        joint = mask(px, D.joint_color[:3], 12)
        static = mask(px, D.static_color[:3], 12)
        assert near(joint, (-0.7, 0.0))  # distance joint: anchor to anchor
        assert near(joint, (1.0, -0.6))  # mouse joint: target to body anchor
        assert near(joint, (0.6, 1.3)) and near(joint, (1.3, 1.8)) and near(joint, (2.0, 1.3))
        assert (
            near(static, (1.5, -1.8)) and near(static, (-2.3, 0.5)) and near(static, (-2.05, 1.7))
        )


def test_shapes_are_filled_translucently_under_their_outlines(make_app):
    """Box2D v3's samples' look: a translucent fill in the body-state colour, outlined."""

    def one_box(world):
        world.insert_resource(Camera(pixels_per_meter=PPM))
        world.insert_resource(DebugDraw(contacts=False))
        world.spawn(Transform(0.0, 0.0), Collider(Box(1.0, 1.0)))  # static: 80 x 80 px
        world.spawn(Transform(0.0, 1.6), Collider(Circle(0.4)))  # a circle is filled too

    app = make_app(one_box)
    px = pixels(app)
    cx, cy = SIZE[0] // 2, SIZE[1] // 2
    inside = px[cy - 10 : cy + 10, cx - 10 : cx + 10, :3].astype(int)
    outline = np.array(D.static_color[:3])
    assert np.ptp(inside.reshape(-1, 3), axis=0).max() == 0  # one even fill
    fill = inside[0, 0]
    # translucent: well above the black background, well below the outline, same hue
    assert np.all(fill < 0.6 * outline) and fill.max() > 0.15 * outline.max(), fill
    assert int(np.argmax(fill)) == int(np.argmax(outline))
    assert mask(px, D.static_color[:3], 12)[cy - 40 : cy + 41, cx - 41 : cx - 38].any()  # outline
    assert np.all(np.abs(px[cy + 64, cx, :3].astype(int) - fill) <= 2)  # the circle too


def _bouncing_balls(world, debug: DebugDraw | None) -> None:
    if debug is not None:
        world.insert_resource(debug)
    world.spawn(Transform(0, -3), Collider(Box(10, 0.5)))
    for i in range(30):
        world.spawn(Transform(-7.5 + 0.5 * i, 1 + (i % 5)), RigidBody(),
                    Collider(Circle(0.2), restitution=0.9))


@pytest.mark.parametrize("debug", [None, DebugDraw(enabled=False), DebugDraw(contacts=False)])
def test_contact_markers_are_not_kept_while_they_are_not_drawn(make_app, debug) -> None:
    from kge.physics.events import ContactBegin

    app = make_app(lambda world: _bouncing_balls(world, debug))
    app.render()  # the renderer now records every fixed step
    begins = 0
    for _ in range(600):
        app.step()
        begins += len(app.world.events(ContactBegin))
    assert begins > 100
    assert len(app.world.get_system(RenderSystem).view.debug._contacts) == 0


def test_contact_markers_linger_only_contact_seconds(make_app) -> None:
    app = make_app(lambda world: _bouncing_balls(world, DebugDraw(contact_seconds=0.25)))
    app.render()
    kept = []
    for _ in range(600):
        app.step()
        kept.append(len(app.world.get_system(RenderSystem).view.debug._contacts))
    # a quarter second of begins at most (30 balls bouncing: a few a step), never all of them
    assert 0 < max(kept) < 150
