"""The night example: lit by its lamp, shadows from the houses, rain stops at the road."""

import night  # examples/night.py
import numpy as np

from kge import App, Light, Lighting, ParticleEmitter
from kge.particles import Particles
from kge.render.setup import frame_pixels
from kge.testbed.samples.build import named


def test_the_night_street_renders_lit_with_rain_and_fireflies() -> None:
    app = App(night.night, headless=True, size=(480, 270), background=(0, 0, 0))
    app.step(120)
    world = app.world
    particles = world.resource(Particles)
    rain = particles.positions(named(world, "rain")[0])
    assert len(rain) > 300
    over_road = rain[np.abs(rain[:, 0]) < 14.5]
    assert over_road[:, 1].min() > -0.2, "rain dies on the road instead of falling through it"
    flies = named(world, "fireflies")[0]
    assert world.get(flies, ParticleEmitter).layer >= world.resource(Lighting).unlit_layer
    assert particles.count(flies) > 5
    assert all(world.get(e, Light).shadows for e in named(world, "lamp"))
    app.render()
    px = frame_pixels(app)[..., :3].astype(int)

    def at(p: tuple[float, float]) -> int:
        x, y = app.world_to_screen(p)
        return int(px[int(y), int(x)].sum())

    assert at((1.0, 5.0)) > at((5.5, 7.2)) + 60, "the lamp lights the sky around it"
    app.close()


def test_main_saves_a_screenshot(tmp_path, monkeypatch) -> None:
    monkeypatch.chdir(tmp_path)
    app = night.main(seconds=0.5)
    assert (tmp_path / "out" / "night.png").read_bytes()[:4] == b"\x89PNG"
    app.close()
