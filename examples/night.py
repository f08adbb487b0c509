"""A night street with a slingshot: soft shadows, normal-mapped crates, rain, fireflies.

A street lamp (a point light with ``shadows=True``) lights the road; the
houses and the car are colliders, so they throw shadows with no extra
authoring; the car (a ``ShadowCaster`` body) drives back and forth with a spot
headlight and an exhaust trail; rain falls and dies on the road and roofs
(particle collision with static colliders); fireflies glow on a layer above
``Lighting.unlit_layer``, so the night does not darken them. A stack of painted
crates on a roof has normal maps: the lamp lights the edges of their planks and
frames that face it. Moonlight (a directional light) casts long parallel shadows.
Drag from the slingshot at the left with the mouse and let go to throw a stone at
the crates.

Run: ``python examples/night.py`` (a window; headless machines take a shot, then
save ``out/night.png`` after a few seconds of game time).
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
    Circle,
    Collider,
    DirectionalLight,
    EmitBox,
    Input,
    Light,
    Lighting,
    Mouse,
    Name,
    ParticleCollision,
    ParticleEmitter,
    RigidBody,
    Script,
    ShadowCaster,
    Sprite,
    TextureFilter,
    Transform,
    World,
    draw,
    from_array,
)
from kge.components.rigidbody import BodyType
from kge.testbed import paint

SIZE = (960, 540)
ROAD = (60, 60, 70)
HOUSE = (150, 120, 100)
SLING = (-9.0, 4.1)  # on the roof of the first house
CRATE = from_array(paint.crate(64))
CRATE_NORMALS = from_array(paint.crate_normals(64))


class Slingshot(Script):
    """Drag from the sling and let go: a stone flies the other way, faster the further
    it was pulled (up to 3 m)."""

    def on_update(self, dt: float) -> None:
        inp = self.world.resource(Input)
        mx, my = inp.mouse_world
        if inp.mouse_pressed(Mouse.LEFT) and math.hypot(mx - SLING[0], my - SLING[1]) < 1.5:
            self.pulling = True
        if getattr(self, "pulling", False) and inp.mouse_released(Mouse.LEFT):
            self.pulling = False
            self.fire((mx - SLING[0], my - SLING[1]))

    def fire(self, pull: tuple[float, float]) -> int:
        """Throw a stone against ``pull`` (metres from the sling); returns its entity."""
        length = min(math.hypot(*pull), 3.0)
        angle = math.atan2(-pull[1], -pull[0])
        speed = 6.0 * length
        return self.world.spawn(
            Transform(*SLING), Name("stone"), RigidBody(bullet=True,
            velocity=(speed * math.cos(angle), speed * math.sin(angle))),
            Collider(Circle(0.18), density=8.0, restitution=0.2), ShadowCaster(),
            draw.Circle(0.18, color=(170, 170, 180), layer=2))  # fmt: skip


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
    world.insert_resource(Lighting(ambient=(25, 28, 45), resolution=0.75))
    world.spawn(Transform(0.0, 6.0), draw.Rect(30.0, 12.0, color=(70, 80, 110), layer=0))  # sky
    world.spawn(Transform(0.0, -2.0), draw.Rect(30.0, 4.0, color=(35, 45, 35), layer=0))
    world.spawn(Transform(0.0, -0.5), Collider(Box(15.0, 0.5)),
                draw.Rect(30.0, 1.0, color=ROAD, layer=1), Name("road"))  # fmt: skip
    for x, w, h in ((-9.0, 2.5, 3.0), (-4.5, 1.8, 4.5), (5.0, 2.2, 3.5), (10.0, 1.6, 5.0)):
        world.spawn(Transform(x, h / 2), Collider(Box(w / 2, h / 2)), Name("house"),
                    draw.Rect(w, h, color=HOUSE, layer=1))  # fmt: skip
    world.spawn(Transform(0.0, 2.6), draw.Rect(0.15, 5.2, color=(40, 40, 40), layer=2))
    for x, y in ((4.3, 3.9), (5.1, 3.9), (5.9, 3.9), (4.7, 4.7), (5.5, 4.7),
                 (5.1, 5.5)):  # a pyramid of crates on the roof at x = 5
        world.spawn(Transform(x, y), Name("crate"), RigidBody(), ShadowCaster(),
                    Collider(Box(0.4, 0.4), friction=0.7),
                    Sprite(CRATE, size=(0.8, 0.8), filter=TextureFilter.LINEAR,
                           normal_map=CRATE_NORMALS, layer=2))  # fmt: skip
    fork = [(-0.05, -1.1), (0.05, -1.1), (0.05, -0.35), (0.35, 0.4), (0.25, 0.45), (0.0, -0.15),
            (-0.25, 0.45), (-0.35, 0.4), (-0.05, -0.35)]  # a Y, counter-clockwise
    world.spawn(Transform(*SLING), Name("slingshot"), Behaviour(Slingshot()),
                draw.Polygon(fork, color=(110, 80, 50), layer=2))
    world.spawn(Transform(0.0, 5.3), Name("lamp"), draw.Circle(0.25, color=(255, 240, 190),
                layer=100), Light(radius=11.0, color=(255, 210, 140), intensity=1.3,
                                  falloff=1.3, shadows=True, shadow_softness=0.15,
                                  glow=0.35))  # fmt: skip
    world.spawn(Name("moon"), DirectionalLight(color=(70, 90, 150), intensity=0.6, angle=-2.0,
                                               shadows=True, shadow_softness=0.03))
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
        sling = next(e for e, (n,) in app.world.query(Name) if n.value == "slingshot")
        app.world.get(sling, Behaviour).script.fire((-2.4, -1.0))  # at the crates
        app.step(int(seconds * 60))
        app.screenshot("out/night.png")
        print(f"kge {kge.__version__} night scene: {seconds:g} s of game time, out/night.png")
    else:
        app.run()
    return app


if __name__ == "__main__":
    main()
