"""Bad input to kge.collision gets a clear kge error at the call, never a NaN answer."""

from __future__ import annotations

import math

import pytest

from kge.collision import (
    Sweep,
    aabb,
    collide,
    distance,
    mass_data,
    ray_cast,
    test_point,
    time_of_impact,
)
from kge.components.shapes import Box, Chain, Circle
from kge.components.transform import Transform
from kge.errors import ComponentTypeError, KgeError, ValidationError

NAN = float("nan")
BOX = Box(0.5, 0.5)
STILL = Sweep.between((0.0, 0.0, 0.0), (0.0, 0.0, 0.0))


@pytest.mark.parametrize("call", [
    lambda p: test_point(BOX, p, (0.0, 0.0)),
    lambda p: ray_cast(BOX, p, (-2.0, 0.0), (2.0, 0.0)),
    lambda p: aabb(BOX, p),
    lambda p: mass_data(BOX, p),
    lambda p: distance(BOX, p, BOX, (3.0, 0.0, 0.0)),
    lambda p: collide(BOX, (0.0, 0.0, 0.0), BOX, p),
    lambda p: Sweep.between(p, (0.0, 0.0, 0.0)),
], ids=["test_point", "ray_cast", "aabb", "mass_data", "distance", "collide", "sweep"])
def test_non_finite_poses_are_refused(call) -> None:
    for bad, match in [((NAN, 0.0, 0.0), r"\.x must be finite"),
                       ((0.0, math.inf, 0.0), r"\.y must be finite"),
                       ((0.0, 0.0, NAN), r"\.angle must be finite"),
                       ((1e300, 0.0, 0.0), r"\.x must be within 1e\+12 m"),
                       ((0.0, 0.0), "triple")]:
        with pytest.raises(ValidationError, match=match):
            call(bad)
    with pytest.raises(ComponentTypeError, match="must be a Pose"):
        call("origin")
    with pytest.raises(ComponentTypeError, match="must be a number"):
        call(("0", 0.0, 0.0))


def test_far_points_are_refused_rather_than_overflowing() -> None:
    with pytest.raises(ValidationError, match=r"p1\[0\] must be within"):
        ray_cast(BOX, (0, 0, 0), (-1.7e308, 0.0), (1.7e308, 0.0))
    with pytest.raises(ValidationError, match=r"Sweep.c\[1\] must be within"):
        Sweep((0.0, 0.0), (0.0, 0.0), (0.0, 1e13), 0.0, 0.0)
    # the limit itself is fine and answers stay finite
    out = distance(BOX, (1e12, 0, 0), BOX, (-1e12, 0, 0))
    assert math.isfinite(out.distance) and out.distance > 1.9e12


def test_the_argument_is_named_in_the_message() -> None:
    with pytest.raises(ValidationError, match=r"pose_b\.x must be finite"):
        distance(BOX, (0.0, 0.0, 0.0), BOX, (NAN, 0.0, 0.0))
    with pytest.raises(ValidationError, match=r"pose_a\.angle must be finite"):
        collide(BOX, (0.0, 0.0, NAN), BOX, (0.0, 0.0, 0.0))


def test_non_shapes_are_refused() -> None:
    for bad in (None, "box", (0.5, 0.5), Box):
        with pytest.raises(ComponentTypeError, match="shape_a must be a kge shape"):
            distance(bad, (0, 0, 0), BOX, (0, 0, 0))
        with pytest.raises(ComponentTypeError, match="must be a kge shape"):
            test_point(bad, (0, 0, 0), (0, 0))
    with pytest.raises(ComponentTypeError, match="shape_b must be a kge shape"):
        collide(BOX, (0, 0, 0), object(), (0, 0, 0))


def test_children_out_of_range_are_refused() -> None:
    chain = Chain([(0, 0), (1, 0), (2, 1)])
    assert aabb(chain, (0, 0, 0), child=1).upper == pytest.approx((2.0, 1.0))
    with pytest.raises(ValidationError, match=r"child must be in \[0, 1\] for Chain, got 2"):
        aabb(chain, (0, 0, 0), child=2)
    with pytest.raises(ValidationError, match=r"child must be in \[0, 0\] for Circle"):
        distance(Circle(1.0), (0, 0, 0), BOX, (0, 0, 0), child_a=1)
    with pytest.raises(ComponentTypeError, match="must be an int"):
        aabb(chain, (0, 0, 0), child=0.5)


def test_bad_points_rays_densities_and_sweeps_are_refused() -> None:
    with pytest.raises(ValidationError, match=r"p\[0\] must be finite"):
        test_point(BOX, (0, 0, 0), (NAN, 0.0))
    with pytest.raises(ValidationError, match="zero-length"):
        ray_cast(BOX, (0, 0, 0), (1.0, 1.0), (1.0, 1.0))
    with pytest.raises(ValidationError, match="max_fraction must be >= 0"):
        ray_cast(BOX, (0, 0, 0), (-2.0, 0.0), (2.0, 0.0), max_fraction=-1.0)
    with pytest.raises(ValidationError, match="density must be >= 0"):
        mass_data(BOX, (0, 0, 0), density=-1.0)
    with pytest.raises(ValidationError, match="Sweep.a0 must be finite"):
        Sweep((0.0, 0.0), (0.0, 0.0), (1.0, 0.0), NAN, 0.0)
    with pytest.raises(ValidationError, match="sweep_b must be a kge.collision.Sweep"):
        time_of_impact(BOX, STILL, BOX, (0.0, 0.0, 0.0))
    with pytest.raises(ValidationError, match=r"t_max must be in \[0, 1\]"):
        time_of_impact(BOX, STILL, BOX, STILL, 2.0)
    with pytest.raises(ComponentTypeError, match="use_radii must be True or False"):
        distance(BOX, (0, 0, 0), BOX, (3, 0, 0), use_radii=1)


def test_every_refusal_is_a_kge_error() -> None:
    with pytest.raises(KgeError):
        distance(BOX, (NAN, 0, 0), BOX, (0, 0, 0))
    with pytest.raises(KgeError):
        distance(42, (0, 0, 0), BOX, (0, 0, 0))


def test_poses_may_be_transforms_or_numpy_values() -> None:
    import numpy as np

    t = Transform(1.0, 2.0, 0.5)
    assert aabb(BOX, t) == aabb(BOX, (1.0, 2.0, 0.5))
    assert aabb(BOX, np.array([1.0, 2.0, 0.5])) == aabb(BOX, (1.0, 2.0, 0.5))
