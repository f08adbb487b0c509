"""Shadow geometry with numpy: which edges cast, how far, and which colliders occlude."""

from __future__ import annotations

import math

import numpy as np
import pytest

from kge import Collider, RigidBody, Transform, World
from kge.components.lights import Light, Lighting, ShadowCaster
from kge.components.shapes import Box, Chain, Circle, Edge
from kge.errors import ComponentTypeError, ValidationError
from kge.lighting import Occluders, shadow_quads
from kge.lighting.occluders import shape_outline
from kge.systems.lighting import LightingPlugin


def _inside(quad: np.ndarray, p: tuple[float, float]) -> bool:
    """Point in a convex quad (either winding)."""
    signs = []
    for a, b in zip(quad, np.roll(quad, -1, axis=0), strict=True):
        signs.append((b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0]))
    return all(s >= 0 for s in signs) or all(s <= 0 for s in signs)


def _shadowed(quads: np.ndarray, p: tuple[float, float]) -> bool:
    return any(_inside(q, p) for q in quads)


def test_a_box_shadows_what_is_behind_it_and_not_what_is_beside_it() -> None:
    edges, closed = shape_outline(Box(0.5, 0.5, center=(2.0, 0.0)))
    quads, _ = shadow_quads(np.array([[0.0, 0.0]]), np.array([10.0]), edges, np.full(4, closed))
    assert len(quads) == 3, "only the edges facing away from the light (not the near one)"
    assert _shadowed(quads, (4.0, 0.0)) and _shadowed(quads, (9.0, 0.3))
    assert not _shadowed(quads, (1.0, 0.0)), "in front of the box is lit"
    assert not _shadowed(quads, (4.0, 3.0)), "beside the shadow is lit"
    assert np.hypot(*quads[:, 2].T).min() > 10.0, "shadows reach past the light's radius"


def test_open_edges_cast_from_both_sides_and_far_edges_are_skipped() -> None:
    edges, closed = shape_outline(Edge((1.0, -1.0), (1.0, 1.0)))
    assert not closed
    lights = np.array([[0.0, 0.0], [2.0, 0.0], [50.0, 0.0]])
    quads, owner = shadow_quads(lights, np.array([5.0, 5.0, 5.0]), edges, np.zeros(1, bool))
    assert owner.tolist() == [0, 1]  # the light 49 m away casts nothing
    assert _shadowed(quads[owner == 0], (3.0, 0.0))
    assert _shadowed(quads[owner == 1], (-1.0, 0.0))


def test_many_lights_at_once_match_one_at_a_time() -> None:
    rng = np.random.default_rng(4)
    a = rng.uniform(-10, 10, (300, 2))
    edges = np.stack([a, a + rng.uniform(-1, 1, (300, 2))], axis=1)
    closed = rng.random(300) < 0.5
    lights = rng.uniform(-10, 10, (16, 2))
    radii = rng.uniform(3, 8, 16)
    quads, owner = shadow_quads(lights, radii, edges, closed)
    assert np.all(np.diff(owner) >= 0), "grouped by light"
    for i in (0, 7, 15):
        one, _ = shadow_quads(lights[i : i + 1], radii[i : i + 1], edges, closed)
        np.testing.assert_allclose(quads[owner == i], one)


def test_circle_and_chain_outlines() -> None:
    edges, closed = shape_outline(Circle(1.0, center=(3.0, 0.0)))
    assert closed and len(edges) == 16
    assert np.allclose(np.hypot(edges[:, 0, 0] - 3.0, edges[:, 0, 1]), 1.0)
    edges, closed = shape_outline(Chain([(0, 0), (1, 0), (1, 1)]))
    assert not closed and len(edges) == 2


def test_occluders_static_by_default_casters_follow_their_body() -> None:
    w = World()
    w.add_plugins(LightingPlugin())
    occ = w.resource(Occluders)
    w.spawn(Transform(0.0, -1.0), Collider(Box(5.0, 0.5)))
    w.spawn(Transform(0.0, 5.0), RigidBody(), Collider(Circle(0.5)))  # dynamic, not a caster
    edges, closed = occ.edges(w, static=True)
    assert len(edges) == 4 and closed.all()
    assert edges[:, :, 1].max() == pytest.approx(-0.5)
    crate = w.spawn(Transform(3.0, 3.0), RigidBody(), Collider(Box(0.5, 0.5)), ShadowCaster())
    edges, _ = occ.edges(w, static=True)
    assert len(edges) == 8
    w.get(crate, Transform).x = 10.0
    edges, _ = occ.edges(w, static=True)
    assert edges[:, :, 0].max() == pytest.approx(10.5), "the caster's shadow moves with it"
    assert len(occ.edges(w, static=False)[0]) == 4  # static shadows switched off
    w.spawn(Transform(-3.0, 0.0), Collider(Box(0.5, 0.5)))
    assert occ.dirty, "a new collider refreshes the static cache"
    assert len(occ.edges(w, static=True)[0]) == 12


@pytest.mark.parametrize(
    ("kwargs", "message"),
    [
        ({"radius": 0.0}, "Light.radius must be > 0"),
        ({"radius": -2.0}, "Light.radius must be > 0"),
        ({"radius": math.nan}, "Light.radius must be finite"),
        ({"intensity": math.nan}, "Light.intensity must be finite"),
        ({"intensity": -1.0}, "Light.intensity must be in"),
        ({"cone": 7.0}, "Light.cone must be in"),
        ({"cone": -0.1}, "Light.cone must be in"),
        ({"color": (256, 0, 0)}, r"Light.color\[0\] must be an int in 0..255"),
        ({"softness": 1.5}, "Light.softness must be in"),
        ({"falloff": -1.0}, "Light.falloff must be in"),
        ({"offset": (0.0, math.inf)}, r"Light.offset\[1\] must be finite"),
        ({"shadow_softness": -0.5}, "Light.shadow_softness must be >= 0"),
        ({"shadow_softness": math.nan}, "Light.shadow_softness must be finite"),
    ],
)
def test_bad_lights_are_refused_at_construction_and_writes(kwargs, message) -> None:
    with pytest.raises(ValidationError, match=message):
        Light(**kwargs)
    light = Light()
    ((field, value),) = kwargs.items()
    before = getattr(light, field)
    with pytest.raises(ValidationError):
        setattr(light, field, value)
    assert getattr(light, field) == before


def test_bad_lighting_settings() -> None:
    with pytest.raises(ValidationError, match=r"Lighting.ambient\[2\] must be an int in 0..255"):
        Lighting(ambient=(0, 0, -1))
    with pytest.raises(ComponentTypeError, match="Lighting.enabled must be True or False"):
        Lighting(enabled=1)  # type: ignore[arg-type]
    w = World()
    w.add_plugins(LightingPlugin())
    e = w.spawn(Transform(), Light())
    with pytest.raises(ValidationError, match="Light.radius"):
        w.get(e, Light).radius = 0.0
    assert w.get(e, Light).radius == 5.0


def test_snapshots_keep_the_lighting_settings() -> None:
    w = World()
    w.add_plugins(LightingPlugin())
    w.insert_resource(Lighting(ambient=(10, 20, 30), unlit_layer=7))
    w.spawn(Transform(1.0, 2.0), Light(radius=3.0, cone=1.0, shadows=True))
    copy = World.restore(w.snapshot())
    assert copy.resource(Lighting).ambient == (10, 20, 30)
    assert copy.resource(Lighting).unlit_layer == 7
    (light,) = [lt for _, (lt,) in copy.query(Light)]
    assert (light.radius, light.cone, light.shadows) == (3.0, 1.0, True)
