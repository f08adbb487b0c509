"""Edges and chains (box2d-reference: edges_chains, chain two-sided, slope to flat)."""

from __future__ import annotations

import pytest

from kge.components.collider import Collider
from kge.components.rigidbody import RigidBody
from kge.components.shapes import Box, Chain, Circle, Edge
from kge.components.transform import Transform
from kge.errors import ValidationError

from .conftest import Sim


def _floor(sim: Sim, kind: str) -> None:
    if kind == "edge":
        sim.spawn(Transform(), Collider(Edge((-40.0, 0.0), (40.0, 0.0))))
    elif kind == "chain":
        sim.spawn(Transform(), Collider(Chain([(-40.0 + i, 0.0) for i in range(81)])))
    elif kind == "loop":
        sim.spawn(Transform(), Collider(Chain([(-40, 0), (40, 0), (40, -1), (-40, -1)],
                                              loop=True)))


@pytest.mark.parametrize("kind", ["edge", "chain", "loop"])
def test_box_slides_without_bumps(sim: Sim, kind: str) -> None:
    _floor(sim, kind)
    box = sim.dynamic(Box(0.5, 0.5), -20.0, 0.515, friction=0.0,
                      body=RigidBody(velocity=(5.0, 0.0)))
    worst_vy = worst_w = 0.0
    for _ in range(240):
        sim.step()
        worst_vy = max(worst_vy, abs(sim.rb(box).velocity[1]))
        worst_w = max(worst_w, abs(sim.rb(box).angular_velocity))
    assert sim.rb(box).velocity[0] == pytest.approx(5.0, abs=0.01)
    # Box2D: < 1e-6. Chipmunk's segment neighbours leave a rare jolt of ~0.025 m/s when a
    # box corner crosses a chain vertex exactly; no speed is lost (vx above).
    assert worst_vy < 0.05 and worst_w < 0.1


@pytest.mark.parametrize("kind", ["edge", "chain"])
def test_circle_rolls_without_resistance(sim: Sim, kind: str) -> None:
    _floor(sim, kind)
    ball = sim.dynamic(Circle(0.5), -20.0, 0.505, friction=0.6,
                       body=RigidBody(velocity=(5.0, 0.0), angular_velocity=-10.0))
    sim.step(240)
    vx = sim.rb(ball).velocity[0]
    assert vx == pytest.approx(5.0, abs=0.05)
    assert sim.rb(ball).angular_velocity * 0.5 == pytest.approx(-vx, rel=0.01)


def test_box_landing_on_chain_keeps_speed(sim: Sim) -> None:
    _floor(sim, "chain")
    box = sim.dynamic(Box(0.5, 0.5), -20.0, 0.985, friction=0.0,
                      body=RigidBody(velocity=(10.0, 0.0)))
    sim.step(120)
    assert sim.rb(box).velocity[0] > 10.0 * 0.995


def test_chain_is_two_sided(sim: Sim) -> None:
    sim.spawn(Transform(), Collider(Chain([(-5.0, 5.0), (0.0, 5.0), (5.0, 5.0)])))
    ball = sim.dynamic(Circle(0.5), 0.0, 0.0, body=RigidBody(velocity=(0.0, 10.0)))
    top = 0.0
    for _ in range(120):
        sim.step()
        top = max(top, sim.t(ball).y)
    assert top < 4.5


def test_chain_slope_to_flat(sim: Sim) -> None:
    sim.spawn(Transform(), Collider(Chain([(-20.0, 10.0), (-10.0, 0.0), (30.0, 0.0)])))
    # a ball resting on the top of the slope (offset along the slope normal)
    n = (0.5**0.5, 0.5**0.5)
    ball = sim.dynamic(Circle(0.5), -19.0 + 0.515 * n[0], 9.0 + 0.515 * n[1], friction=0.6)
    sim.step(300)
    assert sim.rb(ball).velocity[0] == pytest.approx(8.67, rel=0.03)


@pytest.mark.parametrize("ghosts", [True, False])
def test_lone_edges_with_ghost_vertices_join_smoothly(sim: Sim, ghosts: bool) -> None:
    """A row of separate Edge colliders naming their neighbours (Box2D's ghost vertices
    vertex0 / vertex3) is as smooth as a chain; without them a fast box catches on a join."""
    xs = [-20.0 + 0.5 * i for i in range(81)]
    for i in range(len(xs) - 1):
        v0 = (xs[i - 1], 0.0) if ghosts and i > 0 else None
        v3 = (xs[i + 2], 0.0) if ghosts and i + 2 < len(xs) else None
        sim.spawn(Transform(), Collider(Edge((xs[i], 0.0), (xs[i + 1], 0.0), vertex0=v0,
                                             vertex3=v3)))
    box = sim.dynamic(Box(0.25, 0.25), -18.0, 0.26, friction=0.0,
                      body=RigidBody(velocity=(20.0, 0.0)))
    worst_vy = 0.0
    for _ in range(90):
        sim.step()
        worst_vy = max(worst_vy, sim.rb(box).velocity[1])
    if ghosts:
        assert worst_vy < 0.05 and sim.rb(box).velocity[0] == pytest.approx(20.0, abs=0.01)
    else:  # the internal-edge bump the ghosts remove (kge before ghosts: 5.5 m/s up)
        assert worst_vy > 1.0


def test_edge_ghost_vertices_are_checked() -> None:
    edge = Edge((0, 0), (1, 0), vertex3=(2, 1))
    assert edge.vertex0 is None and edge.vertex3 == (2.0, 1.0)
    with pytest.raises(ValidationError):
        Edge((0, 0), (1, 0), vertex0=(float("nan"), 0.0))
