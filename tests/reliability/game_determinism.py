"""A game-layer scene whose whole state is hashed: the cross-process determinism check.

Physics bodies fall and collide; an emitter with a seed sprays particles that inherit
its body's velocity; tweens (a yoyo on a sprite's x, a sequence on its opacity, the
camera's zoom) run; an animator plays and changes clips through its parameters; UI
widgets are written every few frames. :func:`game_hash` hashes every pose, every
live particle's fields, every tweened value, the animators' clip and frame and the
UI widgets' state after ``frames`` frames. Run as a script it prints the hash, so a
test can compare processes with other hash seeds::

    python -m tests.reliability.game_determinism 120
"""

from __future__ import annotations

import hashlib
import shutil
import struct
import sys
from typing import Any

import kge
from kge import (
    Animator,
    Box,
    Camera,
    Circle,
    Clip,
    Collider,
    ParticleEmitter,
    RigidBody,
    Slider,
    Sprite,
    TextInput,
    Transform,
    Tween,
    Tweens,
    TweenSequence,
    UINode,
)  # fmt: skip
from kge.assets import Assets
from kge.components.animation import Transition

from .game_catalogue import _assets_dir


def _scene(root: Any) -> Any:
    def setup(world: kge.World) -> None:
        world.insert_resource(Assets(root, anchor=root))
        world.spawn(Transform(0.0, -1.0), Collider(Box(20.0, 0.5)))
        for i in range(12):
            world.spawn(
                Transform(-3.0 + 0.55 * i, 2.0 + 0.9 * (i % 4), 0.1 * i), RigidBody(),
                Collider(Circle(0.25) if i % 2 else Box(0.25, 0.2)),
            )  # fmt: skip
        runner = world.spawn(
            Transform(0.0, 4.0), RigidBody(velocity=(1.5, 0.0)), Collider(Circle(0.3)),
            ParticleEmitter(rate=120.0, speed=(1.0, 3.0), spread=1.0, lifetime=(0.3, 0.9),
                            inherit_velocity=0.5, drag=0.3, acceleration=(0.0, -4.0), seed=7),
        )  # fmt: skip
        clips = {
            "idle": Clip.grid("sheet.png", (4, 2), frames=[0, 1, 2, 3], fps=8),
            "run": Clip.grid("sheet.png", (4, 2), frames=[4, 5, 6, 7], fps=12, loop="ping_pong"),
        }
        hero = world.spawn(
            Transform(1.0, 0.0), Sprite("sheet.png"),
            Animator(clips, transitions=(Transition("idle", "run", when="fast"),)),
        )  # fmt: skip
        world.spawn(Camera())
        tweens = world.resource(Tweens)
        tweens.to(hero, Transform, "x", 4.0, 0.7, ease="sine_in_out", repeat=-1, yoyo=True)
        tweens.start(hero, TweenSequence(
            Tween(Sprite, "opacity", 40, 0.4), Tween(Sprite, "opacity", 255, 0.3), repeat=-1))
        tweens.zoom_to(2.0, 1.5)
        panel = world.spawn(UINode(width=300, height=200, layout="column"))
        world.spawn(UINode(parent=panel), Slider(0.0, 10.0, 2.0, step=0.5))
        world.spawn(UINode(parent=panel), TextInput("abc", max_length=32))
        del runner

    return setup


def _pack(values: Any) -> bytes:
    return struct.pack(f"<{len(values)}d", *values)


def game_hash(frames: int) -> str:
    """The hash of the scene's game-layer state after ``frames`` frames."""
    root = _assets_dir()
    app = kge.App(_scene(root), headless=True)
    try:
        world = app.world
        for frame in range(frames):
            app.step()
            if frame % 10 == 9:
                for _, (slider,) in world.query(Slider):
                    slider.value = (slider.value + 1.5) % 10.0
                for _, (field,) in world.query(TextInput):
                    field.text = field.text[-20:] + str(frame % 7)
                for _, (anim,) in world.query(Animator):
                    anim.params = {"fast": frame % 20 == 9}
        return _digest(world)
    finally:
        app.close()
        shutil.rmtree(root, ignore_errors=True)


def _digest(world: kge.World) -> str:
    h = hashlib.sha256()
    for e in sorted(world.entities()):
        t = world.try_get(e, Transform)
        if t is not None:
            h.update(_pack((e, t.x, t.y, t.angle)))
        sprite = world.try_get(e, Sprite)
        if sprite is not None:
            h.update(_pack((sprite.opacity,)))
        cam = world.try_get(e, Camera)
        if cam is not None:
            h.update(_pack((*cam.center, cam.zoom)))
        for widget in (world.try_get(e, Slider), world.try_get(e, TextInput)):
            if widget is not None:
                h.update(repr(widget).encode())
        if world.try_get(e, Animator) is not None:
            anims = world.resource(kge.Animations)
            h.update(f"{anims.clip(e)}:{anims.frame(e)}".encode())
    for e, st in sorted(world.resource(kge.Particles).states.items()):
        h.update(struct.pack("<q", e))
        h.update(st.pool.data[:, : st.pool.count].tobytes())
    return h.hexdigest()


if __name__ == "__main__":
    sys.stdout.write(game_hash(int(sys.argv[1])) + "\n")
