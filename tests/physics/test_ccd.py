"""Continuous collision and speed caps (box2d-reference.md rows ccd and max_translation).

The spaces are built the way kge's physics system builds them (PhysicsSettings
defaults: 4 substeps of 1/240 s, 10 iterations, slop 0.005, 0.01 m skin on
polygons and edges) and stepped through ContinuousCollision's per-step hooks.
"""

from __future__ import annotations

import itertools
import math
import pickle
import random

import pymunk
import pytest

from kge.components.filter import Filter
from kge.errors import ComponentTypeError, ValidationError
from kge.physics.ccd import ContinuousCollision
from kge.physics.filtering import to_pymunk
from kge.physics.shape_table import ShapeTable
from kge.physics.speed_cap import clamp_velocity

DT = 1 / 60
SKIN = 0.01
WALL_X = 11.11
PHASES = range(8)


def tag(
    space: pymunk.Space, shape: pymunk.Shape, entity: int, flt: Filter | None = None
) -> pymunk.Shape:
    """Register ``shape`` in the space's shape table as the physics system does."""
    flt = flt or Filter()
    ShapeTable.of(space).add(shape, entity, entity, filter=flt)
    shape.filter = to_pymunk(flt)  # as the physics system does
    return shape


class Sim:
    """One pymunk space with kge's default settings and a ContinuousCollision."""

    def __init__(self, gravity: tuple[float, float] = (0.0, 0.0), use_ccd: bool = True) -> None:
        self.space = pymunk.Space()
        self.space.gravity = gravity
        self.space.collision_slop = 0.005
        self.space.iterations = 10
        self.ccd = ContinuousCollision(self.space)
        self.use_ccd = use_ccd
        self.entities = 0

    def _next(self) -> int:
        self.entities += 1
        return self.entities

    def box(
        self,
        kind: int,
        pos: tuple[float, float],
        half: tuple[float, float],
        *,
        angle: float = 0.0,
        bullet: bool = False,
        flt: Filter | None = None,
        sensor: bool = False,
    ) -> pymunk.Body:
        body = self.space.static_body if kind == pymunk.Body.STATIC else pymunk.Body(body_type=kind)
        hw, hh = half
        verts = [(-hw, -hh), (hw, -hh), (hw, hh), (-hw, hh)]
        if kind == pymunk.Body.STATIC:
            c, s = math.cos(angle), math.sin(angle)
            verts = [(pos[0] + c * x - s * y, pos[1] + s * x + c * y) for x, y in verts]
        shape = tag(self.space, pymunk.Poly(body, verts, radius=SKIN), self._next(), flt)
        shape.sensor = sensor
        if kind == pymunk.Body.STATIC:
            self.space.add(shape)
            return body
        body.position, body.angle = pos, angle
        if kind == pymunk.Body.DYNAMIC:
            shape.density = 1.0
        self.space.add(body, shape)
        self.ccd.track(body, bullet=bullet)
        return body

    def ball(self, pos: tuple[float, float], radius: float, *, bullet: bool = False) -> pymunk.Body:
        body = pymunk.Body()
        shape = tag(self.space, pymunk.Circle(body, radius), self._next())
        shape.density = 1.0
        body.position = pos
        self.space.add(body, shape)
        self.ccd.track(body, bullet=bullet)
        return body

    def step(self, n: int = 1, dt: float = DT, substeps: int = 4) -> None:
        for _ in range(n):
            if self.use_ccd:
                self.ccd.before_step(dt, substeps)
            for _ in range(substeps):
                self.space.step(dt / substeps)
            if self.use_ccd:
                self.ccd.after_step(dt)


def shoot(speed: float, phase: int, wall: int, *, bullet: bool = False, use_ccd: bool = True):
    """The reference ccd scenario: circle r=0.05 at ``speed`` towards a wall half (0.05, 2)."""
    sim = Sim(use_ccd=use_ccd)
    wall_body = sim.box(wall, (WALL_X, 0.0), (0.05, 2.0))
    per_step = min(speed, 120.0) * DT
    ball = sim.ball((phase * per_step / 8, 0.0), 0.05, bullet=bullet)
    ball.velocity = (speed, 0.0)
    sim.step(int((WALL_X + 0.5) / min(speed, 120.0) / DT) + 30)
    wall_x = WALL_X if wall == pymunk.Body.STATIC else wall_body.position.x
    return ball, wall_x


# ------------------------------------------------------------------------------ ccd row


@pytest.mark.parametrize(
    "wall", [pymunk.Body.STATIC, pymunk.Body.KINEMATIC], ids=["static", "kinematic"]
)
@pytest.mark.parametrize("speed", [10.0, 30.0, 200.0, 500.0])
def test_static_and_kinematic_walls_never_tunnel(wall: int, speed: float) -> None:
    for phase in PHASES:
        ball, wall_x = shoot(speed, phase, wall)
        assert ball.position.x < wall_x, f"tunnelled at phase {phase}"
        # stopped at the face: Box2D leaves the centre at 11.005 (wall face 11.06 - skin - r)
        assert ball.position.x == pytest.approx(11.005, abs=0.02)
        assert abs(ball.velocity.x) < 1e-6


@pytest.mark.parametrize("speed", [10.0, 30.0, 200.0, 500.0])
def test_bullets_never_tunnel_through_a_dynamic_plank(speed: float) -> None:
    for phase in PHASES:
        ball, plank_x = shoot(speed, phase, pymunk.Body.DYNAMIC, bullet=True)
        assert ball.position.x < plank_x, f"tunnelled at phase {phase}"
        assert plank_x > WALL_X  # the plank was hit and pushed


@pytest.mark.parametrize("bullet", [True, False])
def test_a_fast_plank_hits_a_resting_bullet(bullet: bool) -> None:
    # Box2D sweeps every pair that contains a bullet, whichever body is the fast one
    hit = 0
    for phase in PHASES:
        sim = Sim()
        plank = sim.box(pymunk.Body.DYNAMIC, (-phase * 0.25, 0.0), (0.05, 1.0))
        plank.velocity = (120.0, 0.0)
        ball = sim.ball((5.0, 0.0), 0.05, bullet=bullet)
        sim.step(10)
        hit += ball.position.x > plank.position.x and ball.velocity.x > 100.0
    if bullet:
        assert hit == 8
    else:
        assert hit < 8  # two non-bullets may tunnel, as in Box2D


def test_non_bullets_may_tunnel_through_dynamic_bodies() -> None:
    # Box2D: 8/8 at 500 m/s; kge only pays for sweeps against dynamic bodies on bullets
    tunnelled = sum(
        ball.position.x > plank_x
        for ball, plank_x in (shoot(500.0, p, pymunk.Body.DYNAMIC) for p in PHASES)
    )
    assert tunnelled >= 1


def test_without_ccd_the_wall_is_tunnelled() -> None:
    # control: the scenario really needs CCD (Box2D continuousPhysics=False: 8/8 tunnel)
    tunnelled = sum(
        ball.position.x > WALL_X
        for ball, _ in (shoot(500.0, p, pymunk.Body.STATIC, use_ccd=False) for p in PHASES)
    )
    assert tunnelled == 8


@pytest.mark.parametrize("speed", [20.0, 60.0, 100.0, 500.0])
def test_fast_kinematic_paddle_never_passes_over_a_resting_body(speed: float) -> None:
    # Box2D sweeps both bodies of a kinematic-dynamic pair; the ball is at rest here
    for phase in PHASES:
        sim = Sim()
        paddle = pymunk.Body(body_type=pymunk.Body.KINEMATIC)  # untracked, as kge leaves it
        verts = [(-0.05, -1.0), (0.05, -1.0), (0.05, 1.0), (-0.05, 1.0)]
        sim.space.add(paddle, tag(sim.space, pymunk.Poly(paddle, verts, radius=SKIN), 99))
        paddle.position = (-phase * min(speed, 120.0) * DT / 8, 0.0)
        paddle.velocity = (speed, 0.0)
        ball = sim.ball((3.0, 0.0), 0.05)
        sim.step(int(4.0 / min(speed, 120.0) / DT) + 3)
        assert ball.position.x > paddle.position.x + 0.05, f"passed over at phase {phase}"
        assert ball.velocity.x == pytest.approx(min(speed, 120.0), rel=0.02)


@pytest.mark.parametrize("wall_speed", [-10.0, -50.0, -120.0, 30.0])
def test_head_on_kinematic_wall_never_tunnels(wall_speed: float) -> None:
    for phase in PHASES:
        sim = Sim()
        wall = sim.box(pymunk.Body.KINEMATIC, (WALL_X + phase * 0.1, 0.0), (0.05, 2.0))
        wall.velocity = (wall_speed, 0.0)
        ball = sim.ball((0.0, 0.0), 0.05)
        ball.velocity = (120.0, 0.0)
        sim.step(15)
        gap = wall.position.x - ball.position.x
        assert gap == pytest.approx(0.05 + SKIN + 0.05 - 0.005, abs=0.02), f"phase {phase}"


def test_fast_fall_onto_a_thin_edge_lands_and_rests() -> None:
    sim = Sim(gravity=(0.0, -10.0))
    ground = tag(sim.space, pymunk.Segment(sim.space.static_body, (-5, 0), (5, 0), SKIN), 99)
    sim.space.add(ground)
    ball = sim.ball((0.0, 5.0), 0.1)
    box = sim.box(pymunk.Body.DYNAMIC, (2.0, 5.0), (0.1, 0.1))
    ball.velocity = box.velocity = (0.0, -150.0)
    sim.step(90)
    assert ball.position.y == pytest.approx(0.1 + SKIN - 0.005, abs=0.01)
    assert box.position.y == pytest.approx(0.1 + 2 * SKIN - 0.005, abs=0.01)
    assert abs(ball.velocity.y) < 0.05 and abs(box.velocity.y) < 0.05


@pytest.mark.parametrize("angle", [0.0, math.pi / 4, 1.0])
def test_rotated_and_spinning_polygons_do_not_tunnel(angle: float) -> None:
    sim = Sim()
    sim.box(pymunk.Body.STATIC, (WALL_X, 0.0), (0.05, 2.0))
    plank = sim.box(pymunk.Body.DYNAMIC, (0.0, 0.0), (0.3, 0.03), angle=angle)
    plank.velocity = (300.0, 0.0)
    plank.angular_velocity = 60.0
    sim.step(60)
    assert plank.position.x < WALL_X
    for v in next(iter(plank.shapes)).get_vertices():
        assert plank.local_to_world(v).x < WALL_X


# ------------------------------------------------------------------------------ filtering


def test_sweep_respects_filters_sensors_and_joints() -> None:
    sim = Sim()
    sim.box(
        pymunk.Body.STATIC, (3.0, 0.0), (0.05, 2.0), flt=Filter(category_bits=0x2, mask_bits=0x1)
    )
    sim.box(pymunk.Body.STATIC, (5.0, 0.0), (0.05, 2.0), sensor=True)
    sim.box(pymunk.Body.STATIC, (7.0, 0.0), (0.05, 2.0), flt=Filter(group_index=-3))
    ghost = pymunk.Body()
    shape = tag(
        sim.space, pymunk.Circle(ghost, 0.05), 50, Filter(category_bits=0x4, group_index=-3)
    )
    shape.density = 1.0
    sim.space.add(ghost, shape)
    sim.ccd.track(ghost)
    ghost.velocity = (100.0, 0.0)
    sim.step(10)
    assert ghost.position.x > 8.0  # passed the rejecting wall, the sensor and its own group

    # joints without collide_bodies: a bullet never stops at the body it is jointed to
    sim = Sim()
    anchor = sim.box(pymunk.Body.KINEMATIC, (WALL_X, 0.0), (0.05, 2.0))
    bullet = sim.ball((0.0, 0.0), 0.05, bullet=True)
    joint = pymunk.SlideJoint(anchor, bullet, (0, 0), (0, 0), 0, 100)
    joint.collide_bodies = False
    sim.space.add(joint)
    bullet.velocity = (100.0, 0.0)
    sim.step(12)
    assert bullet.position.x > WALL_X


def test_one_way_platform_lets_fast_bodies_through_from_below() -> None:
    sim = Sim(gravity=(0.0, -10.0))
    platform = tag(
        sim.space,
        pymunk.Poly(
            sim.space.static_body, [(-3, 9.5), (3, 9.5), (3, 10.5), (-3, 10.5)], radius=SKIN
        ),
        77,
    )
    ShapeTable.of(sim.space).set_oneway(platform, ((0.0, 1.0), 0.5))
    sim.space.add(platform)

    def one_way(arb: pymunk.Arbiter, space: pymunk.Space, data: object) -> None:
        # the physics system's rule: accept only contacts arriving from the solid side
        a, b = arb.shapes
        if platform in (a, b):
            normal = arb.normal if a is platform else -arb.normal  # platform -> other
            if normal.dot((0.0, 1.0)) < 0.5:
                arb.process_collision = False

    sim.space.on_collision(None, None, begin=one_way)
    up = sim.ball((0.0, 5.0), 0.05)
    up.velocity = (0.0, 110.0)
    sim.step(5)
    assert sim.ccd.stats()[1] == 0  # no impact found
    assert up.position.y > 10.5  # went through the open side
    down = sim.ball((1.0, 20.0), 0.05)
    down.velocity = (0.0, -110.0)
    sim.step(20)
    assert down.position.y > 10.5  # sweep stops it on the solid side


# ------------------------------------------------------------------------------ caps


@pytest.mark.parametrize("v0", [100.0, 119.0, 121.0, 200.0, 500.0])
def test_max_translation_clamps_and_keeps_velocity(v0: float) -> None:
    sim = Sim()
    ball = sim.ball((0.0, 0.0), 0.1)
    ball.velocity = (v0, 0.0)
    sim.step()
    expected = min(v0, 120.0)
    assert ball.position.x == pytest.approx(expected * DT, abs=1e-3)  # 2.000 m for v0 >= 121
    assert ball.velocity.x == pytest.approx(expected, abs=1e-3)
    sim.step(10)
    assert ball.velocity.x == pytest.approx(expected, abs=1e-3)


def test_max_rotation_and_other_step_sizes() -> None:
    sim = Sim()
    slow, fast = sim.ball((0.0, 0.0), 0.1), sim.ball((5.0, 0.0), 0.1)
    slow.angular_velocity, fast.angular_velocity = 50.0, -200.0
    sim.step(3)
    assert slow.angular_velocity == pytest.approx(50.0, abs=1e-9)
    assert fast.angular_velocity == pytest.approx(-94.248, abs=1e-3)
    ball = sim.ball((0.0, 5.0), 0.1)
    ball.velocity = (0.0, 500.0)
    sim.step(dt=1 / 120, substeps=2)
    assert ball.velocity.y == pytest.approx(240.0, abs=1e-3)  # the cap is 2 m per step


def test_free_fall_saturates_at_120() -> None:
    sim = Sim(gravity=(0.0, -10.0))
    ball = sim.ball((0.0, 0.0), 0.5)
    saturated = None
    for n in range(1, 901):
        sim.step()
        if saturated is None and ball.velocity.y <= -120.0 + 1e-6:
            saturated = n
    assert saturated is not None and abs(saturated - 720) <= 2
    assert ball.velocity.y == pytest.approx(-120.0, abs=1e-3)


def test_clamp_velocity_function() -> None:
    body = pymunk.Body(1, 1)
    body.velocity, body.angular_velocity = (300.0, 400.0), 1.0
    assert clamp_velocity(body, DT)
    assert body.velocity.length == pytest.approx(120.0)
    assert body.velocity.x / body.velocity.y == pytest.approx(0.75)  # direction kept
    assert not clamp_velocity(body, DT)


# ------------------------------------------------------------------------------ cost & safety


def test_only_fast_bodies_are_armed_and_sliding_is_not_disturbed() -> None:
    sim = Sim(gravity=(0.0, -10.0))
    pts = [(x - 10.0, 0.0) for x in range(120)]
    for i, (a, b) in enumerate(itertools.pairwise(pts)):
        seg = tag(sim.space, pymunk.Segment(sim.space.static_body, a, b, SKIN), 200 + i)
        seg.set_neighbors(pts[i - 1] if i else a, pts[i + 2] if i + 2 < len(pts) else b)
        seg.friction = 0.0
        sim.space.add(seg)
    slow = sim.ball((-5.0, 0.105), 0.1)
    fast = sim.box(pymunk.Body.DYNAMIC, (0.0, 0.115), (0.1, 0.1))
    for body in (slow, fast):
        for s in body.shapes:
            s.friction = 0.0
    fast.velocity = (40.0, 0.0)
    sim.step(60)
    assert not sim.ccd.is_armed(slow) and slow.position_func == pymunk.Body.update_position
    assert sim.ccd.is_armed(fast) and sim.ccd.armed_count == 1
    sweeps, impacts = sim.ccd.stats()
    assert sweeps > 0 and impacts == 0  # seams between segments are never "hit"
    assert fast.velocity.x == pytest.approx(40.0, abs=0.01)
    assert abs(fast.angle) < 1e-3 and fast.position.y == pytest.approx(0.115, abs=0.005)
    fast.velocity = (0.0, 0.0)
    sim.step()
    assert not sim.ccd.is_armed(fast) and fast.position_func == pymunk.Body.update_position
    fast.velocity = (40.0, 0.0)
    sim.step()
    sim.ccd.untrack(fast)
    assert fast.position_func == pymunk.Body.update_position


def test_same_scene_twice_is_bit_identical() -> None:
    def run() -> list[tuple[float, float, float]]:
        sim = Sim(gravity=(0.0, -10.0))
        sim.box(pymunk.Body.STATIC, (0.0, -1.0), (20.0, 0.05))
        sim.box(pymunk.Body.STATIC, (6.0, 1.0), (0.05, 2.0))
        bodies = [sim.ball((i * 0.3, 2.0), 0.05, bullet=i % 2 == 0) for i in range(6)]
        bodies.append(sim.box(pymunk.Body.DYNAMIC, (0.0, 3.0), (0.2, 0.1), angle=0.3))
        for i, b in enumerate(bodies):
            b.velocity = (80.0 + 10 * i, -20.0)
        sim.step(60)
        return [(b.position.x, b.position.y, b.angle) for b in bodies]

    assert run() == run()


def test_bad_input() -> None:
    with pytest.raises(ComponentTypeError, match="pymunk.Space"):
        ContinuousCollision(object())  # type: ignore[arg-type]
    sim = Sim()
    ball = sim.ball((0.0, 0.0), 0.1)
    with pytest.raises(ValidationError, match="step_dt"):
        sim.ccd.before_step(0.0)
    with pytest.raises(ValidationError, match="step_dt"):
        sim.ccd.after_step(math.nan)
    with pytest.raises(ComponentTypeError, match="bullet"):
        sim.ccd.track(ball, bullet=1)  # type: ignore[arg-type]
    with pytest.raises(ComponentTypeError, match="Body"):
        sim.ccd.track("ball")  # type: ignore[arg-type]
    with pytest.raises(ValidationError, match="threshold"):
        ContinuousCollision(sim.space, threshold=-1.0)


def test_space_with_armed_bodies_can_be_copied_and_pickled() -> None:
    sim = Sim()
    sim.box(pymunk.Body.STATIC, (1.0, 0.0), (0.05, 2.0))
    ball = sim.ball((0.0, 0.0), 0.05)
    ball.velocity = (100.0, 0.0)
    sim.ccd.before_step(DT)
    assert sim.ccd.is_armed(ball)
    for clone in (sim.space.copy(), pickle.loads(pickle.dumps(sim.space))):
        (copied,) = [b for b in clone.bodies if b.body_type == pymunk.Body.DYNAMIC]
        assert copied.position_func == pymunk.Body.update_position  # plain integrator
    sim.step(5)
    assert ball.position.x < 1.0  # the live space still sweeps


def test_bad_substeps() -> None:
    sim = Sim()
    with pytest.raises(ValidationError, match="substeps"):
        sim.ccd.before_step(DT, 0)
    with pytest.raises(ComponentTypeError, match="substeps"):
        sim.ccd.before_step(DT, 2.5)  # type: ignore[arg-type]


def test_pair_filter_is_honoured() -> None:
    # the world's custom contact filter rejects the pair, so the sweep must not stop it
    calls: list[tuple[int, int]] = []

    def reject(a: pymunk.Shape, b: pymunk.Shape) -> bool:
        table = ShapeTable.of(sim.space)
        ca, cb = table.collider_of(a), table.collider_of(b)
        assert ca is not None and cb is not None
        calls.append((ca, cb))
        return False

    sim = Sim()
    sim.box(pymunk.Body.STATIC, (WALL_X, 0.0), (0.05, 2.0))
    sim.ccd.pair_filter = reject
    ball = sim.ball((0.0, 0.0), 0.05)
    ball.velocity = (100.0, 0.0)
    sim.step(10)
    assert calls and ball.position.x > WALL_X


@pytest.mark.parametrize("speed", [30.0, 100.0, 500.0])
def test_a_rejected_contact_never_traps_a_body_at_the_face(speed: float) -> None:
    # a contact the world rejects (here in pymunk, without telling the sweep through
    # pair_filter) costs the body one substep at the face, then it passes on
    for phase in PHASES:
        sim = Sim()
        sim.box(pymunk.Body.STATIC, (WALL_X, 0.0), (0.05, 2.0))

        def reject(arb: pymunk.Arbiter, space: pymunk.Space, data: object) -> None:
            arb.process_collision = False

        sim.space.on_collision(None, None, begin=reject)
        ball = sim.ball((phase * 0.03, 0.0), 0.05)
        ball.velocity = (speed, 0.0)
        sim.step(int(12.0 / min(speed, 120.0) / DT) + 10)
        assert ball.position.x > WALL_X + 1.0
        assert ball.velocity.x == pytest.approx(min(speed, 120.0))  # never stopped


def _arena(seed: int, use_ccd: bool, n: int = 40, steps: int = 240) -> int:
    """Fast, spinning, colliding circles and thin boxes (a third of them bullets) in a
    10 m box of thin static edges; returns how many end up outside."""
    rng = random.Random(seed)
    sim = Sim(gravity=(0.0, -10.0), use_ccd=use_ccd)
    corners = [(-5.0, -5.0), (5.0, -5.0), (5.0, 5.0), (-5.0, 5.0)]
    for i in range(4):
        edge = tag(
            sim.space,
            pymunk.Segment(sim.space.static_body, corners[i], corners[(i + 1) % 4], SKIN), 900 + i
        )
        edge.elasticity = 1.0
        sim.space.add(edge)
    bodies = []
    for k in range(n):
        pos = (rng.uniform(-4, 4), rng.uniform(-4, 4))
        if k % 2:
            body = sim.ball(pos, rng.uniform(0.03, 0.2), bullet=k % 3 == 0)
        else:
            half = (rng.uniform(0.03, 0.3), rng.uniform(0.02, 0.1))
            body = sim.box(
                pymunk.Body.DYNAMIC, pos, half, angle=rng.uniform(0, 3), bullet=k % 3 == 0
            )
        for s in body.shapes:
            s.elasticity = 0.9
        heading, speed = rng.uniform(0, 2 * math.pi), rng.uniform(20, 400)
        body.velocity = (speed * math.cos(heading), speed * math.sin(heading))
        body.angular_velocity = rng.uniform(-150, 150)
        bodies.append(body)
    sim.step(steps)
    return sum(max(abs(b.position.x), abs(b.position.y)) > 5.0 for b in bodies)


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_nothing_escapes_a_box_of_thin_edges(seed: int) -> None:
    assert _arena(seed, use_ccd=True) == 0


def test_the_arena_needs_ccd() -> None:
    assert _arena(0, use_ccd=False) > 20  # control: pymunk alone loses most of them


# ------------------------------------------------------------------------------ obstacle index


def _own_static_wall(sim: Sim, x: float, y: float = 0.0) -> tuple[pymunk.Body, pymunk.Shape]:
    """A thin wall on its own static body (as kge makes one per static entity)."""
    body = pymunk.Body(body_type=pymunk.Body.STATIC)
    body.position = (x, y)
    wall = tag(sim.space, pymunk.Poly.create_box(body, (0.1, 4.0), radius=SKIN), sim._next())
    sim.space.add(body, wall)
    return body, wall


@pytest.mark.parametrize("event", ["added", "moved", "reindexed-late", "retyped"])
def test_walls_that_appear_mid_flight_are_never_tunnelled(event: str) -> None:
    # The index of static and kinematic shapes must see every way a wall can appear
    # after the ball was launched: a new shape, a static body moved (and reindexed,
    # now or one step later), a dynamic body turned static in place.
    sim = Sim()
    ball = sim.ball((0.0, 0.0), 0.05)
    ball.velocity = (500.0, 0.0)  # capped to 120 m/s: 2 m per step
    sim.step(1)
    if event == "added":
        _own_static_wall(sim, WALL_X)
    elif event in ("moved", "reindexed-late"):
        body, _ = _own_static_wall(sim, WALL_X, 50.0)  # out of the way
        sim.step(1)
        body.position = (WALL_X, 0.0)
        if event == "reindexed-late":
            sim.step(1)
        sim.space.reindex_shapes_for_body(body)
    else:
        plank = sim.box(pymunk.Body.DYNAMIC, (WALL_X, 0.0), (0.05, 2.0))
        sim.step(1)
        plank.body_type = pymunk.Body.STATIC
        sim.ccd.untrack(plank)  # what the physics system does after a type change
        sim.space.reindex_shapes_for_body(plank)
    sim.step(20)
    assert ball.position.x < WALL_X


def test_a_removed_wall_stops_nothing_and_arms_nothing() -> None:
    sim = Sim()
    body, wall = _own_static_wall(sim, WALL_X)
    ball = sim.ball((WALL_X - 1.0, 0.0), 0.05)
    ball.velocity = (60.0, 0.0)  # 1 m per step: the wall is within reach
    sim.ccd.before_step(DT, 4)
    assert sim.ccd.is_armed(ball)
    sim.space.remove(wall, body)
    sim.ccd.before_step(DT, 4)
    assert not sim.ccd.is_armed(ball)  # a non-bullet in open air
    sim.step(20)
    assert ball.position.x > WALL_X + 5.0 and ball.velocity.x == pytest.approx(60.0)


def _spinning_cluster(sim: Sim, n: int, *, bullets: bool = False) -> list[pymunk.Body]:
    rng = random.Random(7)
    bodies = []
    for k in range(n):
        body = sim.box(
            pymunk.Body.DYNAMIC,
            (rng.uniform(-3, 3), rng.uniform(-3, 3)),
            (0.3, 0.05),
            bullet=bullets and k % 10 == 0,
        )
        body.velocity = (rng.uniform(-30, 30), rng.uniform(-30, 30))
        body.angular_velocity = rng.uniform(-40, 40)
        bodies.append(body)
    return bodies


def test_fast_bodies_far_from_static_geometry_cost_no_shape_walks(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    # A non-bullet can only be stopped by static or kinematic shapes: a swarm of fast
    # thin bodies (a swinging chain) with the only wall 50 m away must be screened in
    # bulk, never by testing the dynamic shapes around each of them.
    from kge.physics.ccd import sweep as ccd_module

    tested: list[pymunk.Shape] = []
    original = ccd_module.Tracked._is_obstacle

    def counting(
        self: ccd_module.Tracked, shape: pymunk.Shape, joint_free: ccd_module.JointFree
    ) -> bool:
        tested.append(shape)
        return original(self, shape, joint_free)

    monkeypatch.setattr(ccd_module.Tracked, "_is_obstacle", counting)
    sim = Sim()
    _own_static_wall(sim, 50.0)
    _spinning_cluster(sim, 150)
    for _ in range(5):
        assert sim.ccd.before_step(DT, 4) == 0
        for _ in range(4):
            sim.space.step(DT / 4)
    assert tested == []
    # the same swarm around a wall: armed, and only the wall was ever examined
    sim = Sim()
    _, wall = _own_static_wall(sim, 0.0)
    _spinning_cluster(sim, 150)
    assert sim.ccd.before_step(DT, 4) > 0
    assert tested and all(s is wall for s in tested)


def test_a_fast_body_arms_the_neighbour_it_may_launch_into_a_wall() -> None:
    # Box2D's impacts use post-solve velocities: a resting body that a fast one is about
    # to strike is armed when a wall is within the speed cap of it - and only then.
    for wall in (True, False):
        sim = Sim()
        if wall:
            _own_static_wall(sim, 3.5)
        fast = sim.ball((0.0, 0.0), 0.1)
        resting = sim.ball((1.0, 0.0), 0.1)
        fast.velocity = (100.0, 0.0)  # 1.67 m this step
        sim.ccd.before_step(DT, 4)
        assert sim.ccd.is_armed(resting) == wall
        assert not sim.ccd.is_armed(fast)  # the wall is 3.3 m away: out of its own reach


def test_the_obstacle_index_reuses_rows_of_removed_shapes() -> None:
    """Kinematic bodies spawned and removed for ever must not grow the index for ever."""
    sim = Sim()
    sim.box(pymunk.Body.STATIC, (0.0, -1.0), (10.0, 1.0))  # a wall that always stays
    ball = sim.ball((0.0, 5.0), 0.1)
    ball.velocity = (0.0, -30.0)  # a fast body: the index is consulted every step
    for k in range(300):
        body = sim.box(pymunk.Body.KINEMATIC, (3.0 + k % 5, 2.0), (0.2, 0.2))
        sim.step()
        sim.space.remove(body, *body.shapes)
        sim.ccd.untrack(body)
        sim.step()
    obstacles = sim.ccd._obstacles
    assert obstacles.live == 1  # the wall
    assert len(obstacles.shapes) <= 4, len(obstacles.shapes)
