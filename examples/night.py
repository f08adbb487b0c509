"""A night street: lights with shadows cast by colliders, particles, unlit fireflies.

A street lamp (a point light with ``shadows=True``) lights the road; the
houses and the car are colliders, so they throw shadows with no extra
authoring; the car (a ``ShadowCaster`` body) drives back and forth with a spot
headlight and an exhaust trail; rain falls and dies on the road and roofs
(particle collision with static colliders); fireflies glow on a layer above
``Lighting.unlit_layer``, so the night does not darken them.

Run: ``python examples/night.py`` (a window; headless machines save
``out/night.png`` after a few seconds of game time).
"""

from __future__ import annotations

import math

import kge
from kge import (
    App,
    Behaviour,
    Blend,
    Box,
    Camera,
    Collider,
    EmitBox,
    Light,
    Lighting,
    Name,
    ParticleCollision,
    ParticleEmitter,
    RigidBody,
    Script,
    ShadowCaster,
    Transform,
    World,
    draw,
)
from kge.components.rigidbody import BodyType

SIZE = (960, 540)
ROAD = (60, 60, 70)
HOUSE = (150, 120, 100)


class Drive(Script):
    """Drives the car between x = -8 and x = 8, turning its headlight round at each end."""

    def __init__(self, speed: float = 3.0) -> None:
        self.speed = speed

    def on_fixed_update(self, dt: float) -> None:
        t, rb = self.transform, self.get(RigidBody)
        if (t.x > 8.0 and self.speed > 0) or (t.x < -8.0 and self.speed < 0):
            self.speed = -self.speed
        rb.velocity = (self.speed, 0.0)
        self.get(Light).direction = 0.0 if self.speed > 0 else math.pi
        exhaust = self.get(ParticleEmitter)
        exhaust.offset = (-1.1 if self.speed > 0 else 1.1, -0.2)
        exhaust.direction = math.pi if self.speed > 0 else 0.0


def night(world: World) -> None:
    world.insert_resource(Camera(center=(0.0, 4.0), pixels_per_meter=40))
    world.insert_resource(Lighting(ambient=(25, 28, 45)))
    world.spawn(Transform(0.0, 6.0), draw.Rect(30.0, 12.0, color=(70, 80, 110), layer=0))  # sky
    world.spawn(Transform(0.0, -2.0), draw.Rect(30.0, 4.0, color=(35, 45, 35), layer=0))
    world.spawn(Transform(0.0, -0.5), Collider(Box(15.0, 0.5)),
                draw.Rect(30.0, 1.0, color=ROAD, layer=1), Name("road"))  # fmt: skip
    for x, w, h in ((-9.0, 2.5, 3.0), (-4.5, 1.8, 4.5), (5.0, 2.2, 3.5), (10.0, 1.6, 5.0)):
        world.spawn(Transform(x, h / 2), Collider(Box(w / 2, h / 2)), Name("house"),
                    draw.Rect(w, h, color=HOUSE, layer=1))  # fmt: skip
    world.spawn(Transform(0.0, 2.6), draw.Rect(0.15, 5.2, color=(40, 40, 40), layer=2))
    world.spawn(Transform(0.0, 5.3), Name("lamp"), draw.Circle(0.25, color=(255, 240, 190),
                layer=100), Light(radius=11.0, color=(255, 210, 140), intensity=1.3,
                                  falloff=1.3, shadows=True))  # fmt: skip
    world.spawn(Transform(-6.0, 0.45), Name("car"),
                RigidBody(type=BodyType.KINEMATIC), Collider(Box(1.0, 0.4)), ShadowCaster(),
                draw.Rect(2.0, 0.8, color=(170, 40, 40), layer=2),
                Light(radius=9.0, cone=0.8, softness=0.4, offset=(1.0, 0.1),
                      color=(255, 255, 220), shadows=True),
                ParticleEmitter(rate=40.0, lifetime=(0.6, 1.0), speed=(0.2, 0.5), spread=0.8,
                                acceleration=(0.0, 0.5), size=(0.1, 0.5), opacity=(128, 0),
                                color=((160, 160, 160), (80, 80, 80)), layer=3, seed=2),
                Behaviour(Drive()))  # fmt: skip
    world.spawn(Transform(0.0, 10.0), Name("rain"), ParticleEmitter(
        rate=400.0, shape=EmitBox(30.0, 0.1), direction=-math.pi / 2 - 0.15, speed=(9.0, 11.0),
        lifetime=2.0, size=0.06, color=(170, 190, 230), opacity=153, flat=True,
        collide=ParticleCollision.DIE,
        max_particles=2000, layer=3, seed=4,
    ))  # fmt: skip
    world.spawn(Transform(-2.0, 3.0), Name("fireflies"), ParticleEmitter(
        rate=6.0, shape=EmitBox(8.0, 3.0), spread=2 * math.pi, speed=(0.05, 0.3),
        lifetime=(2.0, 4.0), size=0.12, color=((200, 255, 120), (120, 220, 60)),
        opacity=(0, 255, 0), blend=Blend.ADDITIVE, layer=101, prewarm=3.0, seed=6,
    ))  # fmt: skip


def main(seconds: float = 3.0) -> App:
    app = App(night, title="kge: night street", size=SIZE, background=(0, 0, 0))
    if app.headless:
        app.step(int(seconds * 60))
        app.screenshot("out/night.png")
        print(f"kge {kge.__version__} night scene: {seconds:g} s of game time, out/night.png")
    else:
        app.run()
    return app


if __name__ == "__main__":
    main()
