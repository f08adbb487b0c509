"""Collision filtering (box2d-reference: filtering; DESIGN.md filtering rules)."""

from __future__ import annotations

import random

import pytest

from kge.components.collider import Collider
from kge.components.filter import Filter
from kge.components.rigidbody import RigidBody
from kge.components.shapes import Box
from kge.components.transform import Transform

from .conftest import Sim

REST_Y = 0.765  # on the platform: 0.25 + 0.5 + Box2D's 0.015 skin gap


def _drop(fp: Filter, fb: Filter, steps: int = 90) -> float:
    s = Sim()
    s.spawn(Transform(0.0, 0.0), Collider(Box(2.0, 0.25), filter=fp))
    box = s.dynamic(Box(0.5, 0.5), 0.0, 1.5, filter=fb)
    s.step(steps)
    y = s.t(box).y
    s.close()
    return y


CASES = [
    (Filter(), Filter(), True),
    (Filter(category_bits=2, mask_bits=0, group_index=3),
     Filter(category_bits=4, mask_bits=0, group_index=3), True),
    (Filter(group_index=-3), Filter(group_index=-3), False),
    (Filter(category_bits=2, mask_bits=4, group_index=-1),
     Filter(category_bits=4, mask_bits=2, group_index=-2), True),
    (Filter(category_bits=2, mask_bits=1, group_index=-1),
     Filter(category_bits=4, mask_bits=2, group_index=-2), False),
    (Filter(category_bits=2, mask_bits=1, group_index=2),
     Filter(category_bits=4, mask_bits=2, group_index=3), False),
    (Filter(category_bits=2, mask_bits=4, group_index=2),
     Filter(category_bits=4, mask_bits=2, group_index=3), True),
    (Filter(category_bits=1, mask_bits=0xFFFF), Filter(category_bits=2, mask_bits=0xFFFE), False),
    (Filter(category_bits=0x10000, mask_bits=0x10000),
     Filter(category_bits=0x10000, mask_bits=0x10000), True),  # 32-bit categories
    (Filter(group_index=5), Filter(group_index=0, mask_bits=0), False),
]


@pytest.mark.parametrize("fp,fb,collides", CASES)
def test_filter_cases_follow_box2d_rule(fp: Filter, fb: Filter, collides: bool) -> None:
    assert fp.collides_with(fb) == collides
    y = _drop(fp, fb)
    if collides:
        assert y == pytest.approx(REST_Y, abs=0.01)
    else:
        assert y < -1.0


def test_rule_matches_formula_on_random_pairs() -> None:
    rng = random.Random(7)
    for _ in range(300):
        a = Filter(rng.randrange(0, 8), rng.randrange(0, 8), rng.choice([-2, -1, 0, 0, 1, 2]))
        b = Filter(rng.randrange(0, 8), rng.randrange(0, 8), rng.choice([-2, -1, 0, 0, 1, 2]))
        if a.group_index == b.group_index != 0:
            expected = a.group_index > 0
        else:
            expected = bool(a.category_bits & b.mask_bits) and bool(b.category_bits & a.mask_bits)
        assert a.collides_with(b) == expected


def test_refilter_takes_effect_next_step_and_ends_contacts(sim: Sim) -> None:
    sim.spawn(Transform(0.0, 0.0), Collider(Box(2.0, 0.25)))
    box = sim.dynamic(Box(0.5, 0.5), 0.0, 1.5)
    sim.step(120)
    assert sim.t(box).y == pytest.approx(REST_Y, abs=0.01)
    assert not sim.rb(box).awake  # asleep on the platform
    ends = []
    sim.world.get(box, Collider).filter = Filter(mask_bits=0)
    sim.step()
    ends += sim.events.contact_end
    sim.step(30)
    assert len(ends) == 1
    assert sim.t(box).y < 0.0  # woke up and fell through


def test_same_body_colliders_never_touch(sim: Sim) -> None:
    body = sim.spawn(Transform(0.0, 5.0), RigidBody())
    sim.spawn(Collider(Box(0.5, 0.5), body=body))
    sim.spawn(Collider(Box(0.5, 0.5, center=(0.2, 0.0)), body=body))
    sim.step(10)
    assert sim.events.contact_begin == []
    assert sim.system.sim.recorder.active == {}


def test_contact_filter_callback(sim: Sim) -> None:
    ground = sim.ground()
    box = sim.dynamic(Box(0.5, 0.5), 0.0, 1.0)
    other = sim.dynamic(Box(0.5, 0.5), 3.0, 1.0)
    asked = []

    def should_collide(a: int, b: int) -> bool:
        asked.append((a, b))
        return box not in (a, b)

    sim.physics.contact_filter = should_collide
    sim.step(120)
    assert sim.t(box).y < -5.0  # fell through the ground
    assert sim.t(other).y == pytest.approx(0.515, abs=0.01)
    assert (ground, box) in asked or (box, ground) in asked
