"""A collider's new edge or chain of the same segments reuses its pymunk segments.

``Simulation._reshape`` must be indistinguishable from the rebuild it replaces
(the old segments out, new ones in): every scenario here runs twice, once as
is and once with the in-place path switched off, and the two runs must agree
bit for bit (poses, velocities, sleep, events, queries).
"""

from __future__ import annotations

import math
from collections.abc import Iterator
from typing import Any

import pymunk
import pytest

from kge.components.collider import Collider
from kge.components.filter import Filter
from kge.components.platform import OneWayPlatform
from kge.components.rigidbody import BodyType, RigidBody
from kge.components.shapes import Box, Chain, Circle, Edge
from kge.components.transform import Transform
from kge.physics.simulation import Simulation
from tests.physics.conftest import Sim

HILLS = [(-10.0, 0.0), (-5.0, 0.5), (0.0, 0.0), (5.0, 0.5), (10.0, 0.0)]
#: as many vertices, 3 m lower (nothing resting on HILLS touches it)
LOW = [(x, y - 3.0) for x, y in HILLS]
#: as many vertices, 1 m higher: boxes resting on HILLS now overlap it
HIGH = [(x, y + 1.0) for x, y in HILLS]


@pytest.fixture(params=["in place", "rebuilt"])
def mode(request: pytest.FixtureRequest, monkeypatch: pytest.MonkeyPatch) -> Iterator[str]:
    if request.param == "rebuilt":
        monkeypatch.setattr(Simulation, "_reshape", lambda self, crec, col: False)
    yield request.param


def _sim(loop: bool = False) -> tuple[Sim, int]:
    sim = Sim()
    ground = sim.spawn(Transform(0.0, 0.0), Collider(Chain(HILLS, loop=loop), friction=0.6))
    return sim, ground


def _segments(sim: Sim, e: int) -> list[pymunk.Shape]:
    return list(sim.system.sim.colliders[e].shapes)


def _row(sim: Sim, s: pymunk.Shape) -> tuple[Any, ...]:
    """The shape's row of kge's shape table (collider, body, child, rank, material...)."""
    t = sim.system.sim.shapes
    i = t.slot(s)
    assert i is not None
    hit = float(t.hit[i])
    return (int(t.collider[i]), t.body_entity(i), int(t.child[i]), int(t.rank[i]),
            float(t.friction[i]), float(t.restitution[i]), None if math.isnan(hit) else hit,
            t.flags[i], t.filters[i], t.oneway[i])


def _state(sim: Sim, bodies: list[int]) -> list[Any]:
    out: list[Any] = []
    for b in bodies:
        t, rb = sim.t(b), sim.world.get(b, RigidBody)
        out.append((t.x, t.y, t.angle, rb.velocity, rb.angular_velocity, rb.awake))
    return out


def _events(sim: Sim) -> list[Any]:
    ev = sim.events
    return [list(ev.contact_begin), list(ev.contact_end)]


def _boxes_on_hills(sim: Sim, n: int = 3) -> list[int]:
    return [sim.dynamic(Box(0.25, 0.25), x=-6.0 + 4.0 * i, y=2.0, density=1.0, friction=0.6)
            for i in range(n)]


def _run(outline: list[tuple[float, float]], settle: int = 150, after: int = 60,
         **spawn: Any) -> tuple[list[Any], bool]:
    """Boxes settle (and fall asleep) on HILLS, the outline becomes ``outline``:
    everything seen every step after, and whether the segments were reused."""
    sim, ground = _sim()
    boxes = _boxes_on_hills(sim)
    sim.step(settle)
    before = _segments(sim, ground)
    seen: list[Any] = [_state(sim, boxes)]
    sim.world.get(ground, Collider).shape = Chain(outline)
    for _ in range(after):
        sim.step()
        seen.append((_state(sim, boxes), _events(sim)))
    reused = [id(s) for s in _segments(sim, ground)] == [id(s) for s in before]
    return seen, reused


def test_a_chain_of_as_many_vertices_reuses_its_segments() -> None:
    sim, ground = _sim()
    sim.step()
    before = _segments(sim, ground)
    sim.world.get(ground, Collider).shape = Chain(LOW)
    sim.step()
    after = _segments(sim, ground)
    assert [id(s) for s in after] == [id(s) for s in before]
    space = sim.system.sim.space
    for i, s in enumerate(after):
        fresh = pymunk.Segment(None, LOW[i], LOW[i + 1], s.radius)
        assert (s.a, s.b, s.normal) == (fresh.a, fresh.b, fresh.normal)
        row = _row(sim, s)
        assert s.space is space and row[2] == i and row[0] == ground
        assert s.bb == pymunk.BB(*_box(LOW[i], LOW[i + 1], s.radius))


def _box(a: tuple[float, float], b: tuple[float, float], r: float) -> tuple[float, ...]:
    return (min(a[0], b[0]) - r, min(a[1], b[1]) - r, max(a[0], b[0]) + r, max(a[1], b[1]) + r)


@pytest.mark.parametrize(
    "new",
    [
        Chain(HILLS[:-1]),  # one vertex fewer
        Chain([*HILLS, (15.0, 1.0)]),  # one more
        Chain(HILLS, loop=True),  # a loop: one segment more
        Edge((-10.0, 0.0), (10.0, 0.0)),
        Box(1.0, 1.0),
    ],
    ids=["fewer", "more", "loop", "edge", "box"],
)
def test_another_topology_is_rebuilt(new: Any) -> None:
    sim, ground = _sim()
    sim.step()
    before = {id(s) for s in _segments(sim, ground)}
    col = sim.world.get(ground, Collider)
    col.shape = new
    sim.step()
    after = _segments(sim, ground)
    assert not before & {id(s) for s in after}
    assert sim.physics.raycast((0.3, 5.0), (0.3, -5.0)) is not None  # the new shape is there


def test_an_edge_reuses_its_segment_and_a_body_change_rebuilds() -> None:
    sim = Sim()
    e = sim.spawn(Transform(), Collider(Edge((-1.0, 0.0), (1.0, 0.0))))
    sim.step()
    (seg,) = _segments(sim, e)
    col = sim.world.get(e, Collider)
    col.shape = Edge((-2.0, 1.0), (2.0, 3.0))
    sim.step()
    assert _segments(sim, e) == [seg]
    assert (seg.a, seg.b) == ((-2.0, 1.0), (2.0, 3.0))
    hit = sim.physics.raycast((0.0, 5.0), (0.0, -5.0))
    assert hit is not None and hit.point == pytest.approx((0.0, 2.0), abs=0.02)
    # moved onto another body: rebuilt (the implicit static body goes)
    body = sim.spawn(Transform(), RigidBody(BodyType.KINEMATIC))
    col.body = body
    col.shape = Edge((-3.0, 0.0), (3.0, 0.0))
    sim.step()
    (other,) = _segments(sim, e)
    assert other is not seg and other.body is sim.system.sim.bodies[body].body


def test_the_reshaped_segments_are_what_a_rebuild_makes() -> None:
    """Every Chipmunk and kge field of a reused segment equals a freshly built one's,
    material, filter, sensor flag, hooks and one-way platform included."""
    def built(reuse: bool) -> list[tuple[Any, ...]]:
        sim, ground = _sim()
        sim.step()
        col = sim.world.get(ground, Collider)
        col.shape = Chain([(1e-120, 0.0), *HIGH[1:]])  # a tiny coordinate: flushed to 0
        col.friction, col.restitution, col.sensor = 0.3, 0.2, True
        col.filter = Filter(category_bits=0x4, mask_bits=0x3, group_index=-2)
        col.contact_hooks = True
        sim.world.add(ground, OneWayPlatform())
        if not reuse:
            sim.system.sim._reshape = lambda crec, col: False  # type: ignore[method-assign]
        sim.step()
        return [
            (s.a, s.b, s.normal, s.radius, s.friction, s.elasticity, s.filter, s.sensor,
             s.collision_type, s.bb, s.surface_velocity, s.mass, s.center_of_gravity,
             _row(sim, s))
            for s in _segments(sim, ground)
        ]

    reused, fresh = built(True), built(False)
    assert reused == fresh
    assert reused[0][0] == (0.0, 0.0) and reused[0][7] is True


def test_reshape_wakes_sleepers_and_ends_contacts_as_a_rebuild(mode: str) -> None:
    seen, reused = _run(LOW)
    assert reused == (mode == "in place")
    boxes_before, (boxes_after, (begins, ends)) = seen[0], seen[1]
    assert all(not awake for *_, awake in boxes_before)  # they slept on the old outline
    assert all(awake for *_, awake in boxes_after)  # woken when it went
    assert len(ends) == 3 and not begins  # each box's contact ended, with its event
    assert seen[-1][0][0][1] < -2.0  # and they fell onto the low outline


def test_reshape_matches_a_rebuild_bit_for_bit(monkeypatch: pytest.MonkeyPatch) -> None:
    for outline in (LOW, HIGH, [(x, y + 0.05) for x, y in HILLS]):
        in_place, reused = _run(outline, after=90)
        assert reused
        with monkeypatch.context() as m:
            m.setattr(Simulation, "_reshape", lambda self, crec, col: False)
            rebuilt, again = _run(outline, after=90)
        assert not again
        assert in_place == rebuilt


def test_a_sleeper_under_the_new_outline_behaves_as_after_a_rebuild(mode: str) -> None:
    """A box asleep on the old ground that the new outline overlaps: neither Chipmunk
    nor Box2D wakes a sleeping body for new static geometry, and neither does a
    reshape (the bit-for-bit test checks it is the same as a rebuild)."""
    sim, ground = _sim()
    sim.spawn(Transform(0.0, -6.0), Collider(Box(20.0, 0.5)))
    box = sim.dynamic(Box(0.25, 0.25), x=0.0, y=-5.2, density=1.0)
    sim.step(150)
    assert not sim.world.get(box, RigidBody).awake
    pose = (sim.t(box).x, sim.t(box).y, sim.t(box).angle)
    sim.world.get(ground, Collider).shape = Chain([(x, y - 5.3) for x, y in HILLS])
    sim.step(5)
    assert not sim.world.get(box, RigidBody).awake
    assert (sim.t(box).x, sim.t(box).y, sim.t(box).angle) == pose
    # the new outline cuts through the sleeping box, which stays put
    assert {h.collider for h in sim.physics.query_aabb((-0.1, -5.4), (0.1, -5.2))} == {
        ground, box}


def test_queries_and_rays_see_the_new_outline_at_once(mode: str) -> None:
    sim, ground = _sim()
    sim.step()
    sim.world.get(ground, Collider).shape = Chain(HIGH)
    hit = sim.physics.raycast((0.0, 5.0), (0.0, -5.0))  # before any step
    assert hit is not None and hit.collider == ground
    assert hit.point[1] == pytest.approx(1.0, abs=0.02)
    # the old outline's boxes are gone from the index, the new ones are in it
    assert sim.physics.query_aabb((-0.2, -0.2), (0.2, 0.2)) == []
    assert [h.collider for h in sim.physics.query_aabb((4.9, 1.4), (5.1, 1.6))] == [ground]
    sim.step()
    again = sim.physics.raycast((-2.5, 5.0), (-2.5, -5.0))
    assert again is not None and again.point[1] == pytest.approx(1.25, abs=0.02)


RIM = [(-1.0, 0.0), (0.0, -1.0), (1.0, 0.0)]
WIDE_RIM = [(-2.0, 0.0), (0.0, -2.0), (2.0, 0.0)]


def _rimmed_bullet(rim: list[tuple[float, float]]) -> tuple[Sim, int, int]:
    sim = Sim()
    body = sim.spawn(Transform(0.0, 5.0), RigidBody(BodyType.DYNAMIC, bullet=True))
    sim.spawn(Transform(), Collider(Circle(0.5), density=2.0, body=body))
    e = sim.spawn(Transform(), Collider(Chain(rim), body=body))
    sim.step()
    return sim, body, e


def _sweep(sim: Sim, body: int) -> tuple[float, float, float]:
    """What continuous collision knows of the body's shapes (kge.physics.ccd.sweep)."""
    pb = sim.system.sim.bodies[body].body
    info = sim.system.sim.ccd._tracked[pb.id]
    return info.core, info.reach, info.extent


def test_a_reshaped_chain_on_a_dynamic_body_keeps_its_mass_and_continuous_collision(
    mode: str,
) -> None:
    sim, body, rim = _rimmed_bullet(RIM)
    mass = sim.physics.mass_data(body)
    narrow = _sweep(sim, body)
    sim.world.get(rim, Collider).shape = Chain(WIDE_RIM)
    sim.step()
    assert sim.physics.mass_data(body) == mass
    # continuous collision re-read the body's shapes: as if built with the wide rim
    wide, _, _ = _rimmed_bullet(WIDE_RIM)
    assert _sweep(sim, body) == _sweep(wide, body) != narrow
    pb = sim.system.sim.bodies[body].body
    assert {s for s in pb.shapes if s.space is not None} >= set(_segments(sim, rim))


def test_a_disabled_body_reshapes_out_of_the_space_and_comes_back(mode: str) -> None:
    sim = Sim()
    body = sim.spawn(Transform(), RigidBody(BodyType.STATIC, enabled=False))
    e = sim.spawn(Transform(), Collider(Chain(HILLS), body=body))
    sim.step()
    sim.world.get(e, Collider).shape = Chain(HIGH)
    sim.step()
    assert all(s.space is None for s in _segments(sim, e))
    assert sim.physics.raycast((0.0, 5.0), (0.0, -5.0)) is None
    sim.world.get(body, RigidBody).enabled = True
    sim.step()
    hit = sim.physics.raycast((0.0, 5.0), (0.0, -5.0))
    assert hit is not None and hit.point[1] == pytest.approx(1.0, abs=0.02)


def test_what_touches_the_bodys_other_colliders_wakes_as_after_a_rebuild(mode: str) -> None:
    """kge wakes everything touching a body whose collider is rebuilt (bodies.take_out):
    a box asleep on the same static body's other collider wakes too."""
    sim = Sim()
    ground = sim.spawn(Transform(), RigidBody(BodyType.STATIC))
    sim.spawn(Transform(), Collider(Box(2.0, 0.5), body=ground))  # a platform at x = 0
    rim = sim.spawn(Transform(), Collider(Chain([(20.0, 0.0), (25.0, 1.0), (30.0, 0.0)]),
                                          body=ground))
    box = sim.dynamic(Box(0.25, 0.25), x=0.0, y=0.8, density=1.0)
    sim.step(150)
    assert not sim.world.get(box, RigidBody).awake
    sim.world.get(rim, Collider).shape = Chain([(20.0, 1.0), (25.0, 2.0), (30.0, 1.0)])
    sim.step()
    assert sim.world.get(box, RigidBody).awake


def _two_grounds(reshape: bool) -> list[Any]:
    """Two outlines re-laid in the same step (their segments go back in one batch, in
    entity order, as a rebuild adds them), boxes on both."""
    sim = Sim()
    grounds = [sim.spawn(Transform(dx, 0.0), Collider(Chain(HILLS), friction=0.6))
               for dx in (0.0, 21.0)]
    boxes = [sim.dynamic(Box(0.25, 0.25), x=dx - 6.0 + 3.0 * i, y=2.0, density=1.0)
             for dx in (0.0, 21.0) for i in range(5)]
    if not reshape:
        sim.system.sim._reshape = lambda crec, col: False  # type: ignore[method-assign]
    sim.step(40)  # some still bounce, some rest
    seen: list[Any] = []
    for k, outline in enumerate((HIGH, LOW, HILLS)):
        for g in grounds if k != 1 else reversed(grounds):
            sim.world.get(g, Collider).shape = Chain(outline)
        for _ in range(30):
            sim.step()
            seen.append((_state(sim, boxes), _events(sim)))
    return seen


def test_outlines_re_laid_together_match_a_rebuild_bit_for_bit() -> None:
    assert _two_grounds(True) == _two_grounds(False)


def test_continuous_collision_sees_an_outline_moved_far_away(mode: str) -> None:
    """A fast small box fired at where the outline went (100 m off) stops on it: the
    obstacle index that screens fast bodies re-read the reused segments' boxes."""
    sim, ground = _sim()
    sim.step()
    sim.world.get(ground, Collider).shape = Chain([(x + 100.0, y) for x, y in HILLS])
    box = sim.dynamic(Box(0.05, 0.05), x=100.0, y=3.0, density=1.0,
                      body=RigidBody(BodyType.DYNAMIC, velocity=(0.0, -110.0)))
    lowest = math.inf
    for _ in range(30):
        sim.step()
        lowest = min(lowest, sim.t(box).y)
    assert lowest > -0.1  # it never went through (the outline is at y = 0 there)
    assert abs(sim.t(box).x - 100.0) < 1.0
