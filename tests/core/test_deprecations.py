"""Choices that were strings are enums now (StrEnum: each member equals its old string).
The strings still work for one release, with a DeprecationWarning naming the member;
an unknown string is still refused at the call."""

from __future__ import annotations

import warnings
from pathlib import Path

import pytest

from kge import (
    App,
    Blend,
    Box,
    Circle,
    Clip,
    Collider,
    Loop,
    ParticleCollision,
    ParticleEmitter,
    ParticleSpace,
    Physics,
    RayMode,
    RigidBody,
    Transform,
    ValidationError,
    World,
)


def test_particle_choices_take_enums_and_still_the_strings() -> None:
    with warnings.catch_warnings():
        warnings.simplefilter("error", DeprecationWarning)  # the enums never warn
        em = ParticleEmitter(blend=Blend.ADDITIVE, space=ParticleSpace.LOCAL,
                             collide=ParticleCollision.DIE)  # fmt: skip
    with pytest.warns(DeprecationWarning, match=r"blend='additive' is now Blend.ADDITIVE"):
        old = ParticleEmitter(blend="additive", space="local", collide="die")  # type: ignore[arg-type]
    assert old == em and old.blend is Blend.ADDITIVE and old.blend == "additive"
    with pytest.warns(DeprecationWarning, match="ParticleCollision.BOUNCE"):
        em.collide = "bounce"  # type: ignore[assignment]
    assert em.collide is ParticleCollision.BOUNCE
    with pytest.raises(ValidationError, match=r"blend must be one of Blend.ALPHA, Blend.ADDITIVE"):
        ParticleEmitter(blend="sideways")  # type: ignore[arg-type]


def test_clip_loop_takes_an_enum_and_still_the_strings() -> None:
    clip = Clip.grid("hero.png", (4, 1), frames=[0, 1], fps=10, loop=Loop.ONCE)
    with pytest.warns(DeprecationWarning, match=r"loop='hold' is now Loop.HOLD"):
        held = Clip.grid("hero.png", (4, 1), frames=[0, 1], fps=10, loop="hold")
    assert clip.loop is Loop.ONCE and held.loop is Loop.HOLD
    with pytest.raises(ValidationError, match="loop must be one of Loop.LOOP"):
        Clip.grid("hero.png", (4, 1), loop="forever")


def _ball(world: World) -> None:
    world.spawn(Transform(0, -1), Collider(Box(5, 1)))
    world.spawn(Transform(0, 3), RigidBody(), Collider(Circle(0.5)))


def test_raycast_modes_are_an_enum_with_typed_results() -> None:
    physics = App(_ball, headless=True).world.resource(Physics)
    every = physics.raycast((0, 10), (0, -10), mode=RayMode.ALL)
    assert [h.collider for h in every] == [2, 1]
    nearest = physics.raycast((0, 10), (0, -10))
    assert nearest is not None and nearest.collider == 2
    assert physics.raycast((20, 10), (20, -10), mode=RayMode.ANY) is None
    with pytest.warns(DeprecationWarning, match=r"mode='all' is now RayMode.ALL"):
        assert physics.raycast((0, 10), (0, -10), mode="all") == every
    with pytest.raises(ValidationError, match="mode must be one of RayMode.CLOSEST"):
        physics.raycast((0, 10), (0, -10), mode="nearest")


def test_enum_choices_round_trip_through_scene_files(tmp_path: Path) -> None:
    """Scene files write an enum by its member's name; a file from before the enum (the
    plain string value) still loads, as the member."""
    from kge import load_scene, save_scene

    def fresh() -> World:
        return App(lambda world: None, headless=True).world

    world = fresh()
    world.spawn(Transform(), ParticleEmitter(blend=Blend.ADDITIVE, collide=ParticleCollision.DIE))
    path = save_scene(world, tmp_path / "fx.scene.toml")
    text = path.read_text()
    assert 'blend = "ADDITIVE"' in text and 'collide = "DIE"' in text
    with warnings.catch_warnings():
        warnings.simplefilter("error", DeprecationWarning)
        for source in (text, text.replace('"ADDITIVE"', '"additive"')):
            target = fresh()
            path.write_text(source)
            (entity,) = load_scene(target, path)
            emitter = target.get(entity, ParticleEmitter)
            assert emitter.blend is Blend.ADDITIVE and emitter.collide is ParticleCollision.DIE
