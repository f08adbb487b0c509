"""The live inspector over a running game: list, read, write through validation, pick."""

from __future__ import annotations

import pytest

from kge import (
    App,
    Box,
    Circle,
    Collider,
    EntityNotFoundError,
    Key,
    Mouse,
    Name,
    RigidBody,
    Sprite,
    Transform,
    ValidationError,
    World,
)
from kge.components.particles import Blend, ParticleEmitter
from kge.debug import Gizmos, Inspector
from kge.debug.plugin import DebugOverlay
from kge.render.images import solid

from ..render.conftest import mask, pixels


def level(world: World) -> None:
    world.spawn(Transform(0, -1), Collider(Box(5, 1)), Name("ground"))
    world.spawn(Transform(2, 3), RigidBody(), Collider(Circle(0.5)), Name("ball"))
    world.spawn(Transform(-2, 0), ParticleEmitter(rate=10.0), Name("smoke"))


def test_rows_show_fields_as_the_editor_does() -> None:
    app = App(level, headless=True)
    ins = Inspector(app.world)
    assert ins.entities() == [(1, "ground"), (2, "ball"), (3, "smoke")]
    assert ins.entities("emitter") == [(3, "smoke")]  # searches component names too
    rows = {(r.component, r.field): r for r in ins.rows(2)}
    assert rows[("Transform", "x")].text == "2" and rows[("Transform", "x")].widget == "number"
    assert rows[("Transform", "angle")].widget == "angle"
    assert rows[("RigidBody", "type")].widget == "choice"
    assert "DYNAMIC" in rows[("RigidBody", "type")].choices
    assert rows[("Collider", "shape")].text.startswith("{ type = \"Circle\"")
    assert rows[("RigidBody", "mass")].text == "none"


def test_writes_go_through_validation_and_the_running_game_follows() -> None:
    app = App(level, headless=True)
    ins = Inspector(app.world)
    ins.set(3, "ParticleEmitter", "blend", "ADDITIVE")
    assert app.world.get(3, ParticleEmitter).blend is Blend.ADDITIVE
    ins.set(2, "RigidBody", "velocity", "3, 0")
    app.step(10)
    assert app.world.get(2, Transform).x > 2.3  # the body took the new velocity
    ins.set(2, "Collider", "shape", '{ type = "Box", half_width = 0.25, half_height = 0.25 }')
    assert isinstance(app.world.get(2, Collider).shape, Box)
    with pytest.raises(ValidationError, match=r"entity 3, ParticleEmitter.rate"):
        ins.set(3, "ParticleEmitter", "rate", "-5")
    assert app.world.get(3, ParticleEmitter).rate == 10.0
    with pytest.raises(ValidationError, match="not one of"):
        ins.set(3, "ParticleEmitter", "blend", "GLOW")
    with pytest.raises(ValidationError, match="no field 'speedy'"):
        ins.set(2, "Transform", "speedy", "1")
    with pytest.raises(ValidationError, match="has no Sprite component"):
        ins.set(2, "Sprite", "opacity", "1")
    with pytest.raises(EntityNotFoundError):
        ins.rows(99)
    ins.set(2, "RigidBody", "mass", "2.5")
    assert app.world.get(2, RigidBody).mass == 2.5
    ins.set(2, "RigidBody", "mass", "none")
    assert app.world.get(2, RigidBody).mass is None


def test_pick_finds_a_collider_then_the_nearest_transform() -> None:
    app = App(level, headless=True)
    ins = Inspector(app.world)
    app.step(1)
    assert ins.pick((2.1, 2.9)) == 2  # inside the ball's circle
    assert ins.pick((-2.2, 0.1)) == 3  # no collider: the emitter's Transform, 0.22 m away
    assert ins.pick((20.0, 20.0)) is None and ins.selected == 3
    assert ins.step(1) == 1 and ins.step(-1) == 3


def test_f3_opens_the_panel_and_a_click_picks(make_app) -> None:
    app = make_app(level)
    app.step(1)
    app.input.press(Key.F3)
    app.step(1)
    app.input.release(Key.F3)
    assert app.world.resource(DebugOverlay).inspector
    app.input.click(Mouse.LEFT, at=app.world_to_screen((2.0, 3.0)))
    app.step(1)
    ins = app.world.resource(Inspector)
    assert ins.selected == 2
    assert len(app.world.resource(Gizmos)) == 2  # the selection's cross
    px = pixels(app)
    w = px.shape[1]
    panel = mask(px, (12, 14, 20), tol=4)
    assert panel[:, int(w * 0.8)].mean() > 0.5 and not panel[:, int(w * 0.3)].any()
    app.input.press(Key.PAGEDOWN)
    app.step(1)
    assert ins.selected == 3


def test_the_sprite_image_field_shows_and_refuses_bad_text() -> None:
    def scene(world: World) -> None:
        world.spawn(Transform(), Sprite(solid(2, 2, (255, 0, 0))))

    app = App(scene, headless=True)
    ins = Inspector(app.world)
    rows = {r.field: r for r in ins.rows(1)}
    assert rows["opacity"].text == "255"
    ins.set(1, "Sprite", "opacity", "128")
    assert app.world.get(1, Sprite).opacity == 128
    with pytest.raises(ValidationError):
        ins.set(1, "Sprite", "opacity", "999")
    assert app.world.get(1, Sprite).opacity == 128
