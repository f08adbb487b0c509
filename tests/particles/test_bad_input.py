"""Bad emitter settings fail at the call that made them and leave the world unchanged."""

from __future__ import annotations

import math

import pytest

from kge import App, Transform, World
from kge.components.particles import (
    BurstOnHit,
    EmitCircle,
    ParticleBurst,
    ParticleCollision,
    ParticleEmitter,
    ParticleSpace,
)
from kge.errors import ComponentTypeError, EntityNotFoundError, ValidationError
from kge.particles import Particles
from kge.systems.particles import ParticlesPlugin

NAN = float("nan")


@pytest.mark.parametrize(
    ("field", "value", "message"),
    [
        ("rate", NAN, "rate must be finite"),
        ("rate", -1.0, "rate must be >= 0"),
        ("rate_per_meter", math.inf, "rate_per_meter must be finite"),
        ("lifetime", -1.0, "lifetime must be > 0"),
        ("lifetime", (2.0, 1.0), "low <= high"),
        ("lifetime", (NAN, 1.0), "lifetime[0] must be finite"),
        ("size", -0.5, "size must be >= 0"),
        ("size", (0.1, NAN), "size[1] must be finite"),
        ("color", (300, 0, 0), "color[0] must be an int in 0..255"),
        ("color", ((255, 0, 0), (0, -1, 0)), "color[1][1] must be an int in 0..255"),
        ("opacity", 256, "opacity must be in [0.0, 255.0]"),
        ("spread", 7.0, "spread must be in"),
        ("spread", -0.1, "spread must be in"),
        ("speed", (-1.0, 1.0), "speed must be >= 0"),
        ("max_particles", 0, "max_particles must be in 1..1000000"),
        ("max_particles", 10**9, "max_particles must be in 1..1000000"),
        ("blend", "overlay", "blend must be one of"),
        ("space", "screen", "space must be one of"),
        ("collide", "stick", "collide must be one of"),
        ("bounciness", 2.0, "bounciness must be in"),
        ("prewarm", -1.0, "prewarm must be in"),
        ("duration", 0.0, "duration must be > 0"),
        ("burst", -3, "burst must be in"),
        ("seed", -1, "seed must be >= 0"),
        ("acceleration", (0.0, NAN), "acceleration[1] must be finite"),
        ("texture", "", "texture must not be an empty string"),
        ("speed", (0.0, 1e30), "speed must be within"),
        ("acceleration", (0.0, -1e300), "acceleration[1] must be within"),
        ("size", 1e9, "size must be within"),
        ("lifetime", 1e12, "lifetime must be within"),
        ("drag", 1e300, "drag must be within"),
        ("inherit_velocity", 1e6, "inherit_velocity must be in"),
    ],
)
def test_bad_values_are_refused_at_construction_and_at_writes(field, value, message) -> None:
    with pytest.raises(ValidationError, match=message.replace("[", r"\[").replace("]", r"\]")
                       .replace("(", r"\(").replace(")", r"\)")):  # fmt: skip
        ParticleEmitter(**{field: value})
    em = ParticleEmitter()
    before = getattr(em, field)
    with pytest.raises(ValidationError):
        setattr(em, field, value)
    assert getattr(em, field) == before


def test_wrong_types() -> None:
    with pytest.raises(ComponentTypeError, match="ParticleEmitter.shape must be one of"):
        ParticleEmitter(shape="circle")  # type: ignore[arg-type]
    with pytest.raises(ComponentTypeError, match="ParticleEmitter.rate must be a number"):
        ParticleEmitter(rate="10")  # type: ignore[arg-type]
    with pytest.raises(ValidationError, match="EmitCircle.radius must be > 0"):
        EmitCircle(0.0)
    with pytest.raises(ValidationError, match="ParticleBurst.count must be in"):
        ParticleBurst(1, -5)


def test_unknown_texture_is_refused_at_spawn_and_the_world_is_unchanged() -> None:
    w = World()
    w.add_plugins(ParticlesPlugin())
    with pytest.raises(
        ValidationError, match=r"ParticleEmitter.texture: unknown texture 'nope.png'"
    ):
        w.spawn(Transform(), ParticleEmitter(texture="nope.png"))
    assert len(w) == 0
    e = w.spawn(Transform())
    with pytest.raises(ValidationError, match=f"entity {e}, ParticleEmitter.texture"):
        w.add(e, ParticleEmitter(texture="nope.png"))
    assert not w.has(e, ParticleEmitter)


def test_local_space_collision_is_refused() -> None:
    w = World()
    w.add_plugins(ParticlesPlugin())
    with pytest.raises(ValidationError, match=r"collide = ParticleCollision.BOUNCE needs space=ParticleSpace.WORLD"):
        w.spawn(Transform(), ParticleEmitter(space=ParticleSpace.LOCAL, collide=ParticleCollision.BOUNCE))
    assert len(w) == 0


def test_code_api_names_the_missing_emitter() -> None:
    app = App(lambda w: w.spawn(Transform()), headless=True)
    p = app.world.resource(Particles)
    with pytest.raises(
        EntityNotFoundError, match="Particles.burst: entity 1 has no ParticleEmitter"
    ):
        p.burst(1, 3)
    with pytest.raises(EntityNotFoundError, match="Particles.stop: entity 99"):
        p.stop(99)


def test_burst_on_hit_needs_an_entity() -> None:
    with pytest.raises(ValidationError, match="BurstOnHit.emitter"):
        BurstOnHit(emitter=-1)
