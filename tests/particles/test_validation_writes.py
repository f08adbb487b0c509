"""A ParticleEmitter's texture is checked at every write, as at spawn."""

import pytest

from kge import App, ParticleEmitter, Transform, ValidationError


def test_a_missing_texture_written_later_is_refused_and_the_emitter_keeps_its_own() -> None:
    app = App(lambda world: None, headless=True)
    e = app.world.spawn(Transform(), ParticleEmitter(rate=10.0))
    em = app.world.get(e, ParticleEmitter)
    with pytest.raises(ValidationError, match=f"entity {e}, ParticleEmitter.texture"):
        em.texture = "no-such-spark.png"
    assert em.texture is None
