"""Animation samples: a walk cycle from a sheet, a GIF, the easing gallery, camera shake."""

from __future__ import annotations

import hashlib
import math
import tempfile
from pathlib import Path
from typing import Any

from kge.animation.gif import gif_clip
from kge.animation.tweens import Tweens
from kge.components import Behaviour, Name, Script, Transform
from kge.components.animation import Animator, Clip
from kge.components.collider import Collider
from kge.components.drawables import Circle, Line
from kge.components.rigidbody import RigidBody
from kge.components.shapes import Box
from kge.components.sprite import Sprite
from kge.components.tween import EASING_NAMES, Tween, TweenSequence
from kge.keys import Key
from kge.systems.animation import shake
from kge.testbed.art import as_image, coin_delays, coin_gif, walk_sheet
from kge.testbed.registry import sample
from kge.testbed.samples.build import named, static_box
from kge.world import World


class _Counter(Script):
    """Counts this entity's footsteps (``on_animation_event``)."""

    def __init__(self) -> None:
        self.steps = 0

    def on_animation_event(self, event: Any) -> None:
        if event.name == "step":
            self.steps += 1


@sample("Animation", "Walk Cycle",
        help="A walk cycle cut from a sprite sheet, walking to and fro (a tween) "
             "with footstep events on frames 0 and 4.")
def walk_cycle(world: World, walkers: int = 3) -> None:
    sheet = as_image(walk_sheet())
    walk = Clip.grid(sheet, (8, 1), fps=12, events={0: "step", 4: "step"})
    back = Clip.grid(sheet, (8, 1), fps=12, flip_x=True, events={0: "step", 4: "step"})
    tweens = world.resource(Tweens)
    for i in range(walkers):
        y = 0.5 + 1.2 * i
        e = world.spawn(
            Transform(-3.0, y),
            Sprite(sheet, size=(1.0, 1.0)),
            Animator({"walk": walk, "back": back}, speed=1.0 + 0.25 * i),
            Behaviour(_Counter()),
            Name("walker"),
        )
        tweens.start(e, TweenSequence(Tween(Transform, "x", 3.0, 3.0 - 0.5 * i),
                                 Tween(Transform, "x", -3.0, 3.0 - 0.5 * i), repeat=-1))
        world.spawn(Transform(0.0, y - 0.5), Line((-3.5, 0.0), (3.5, 0.0), color=(90, 90, 110)))
    world.spawn(Behaviour(_TurnAround()))


class _TurnAround(Script):
    """Plays the mirrored clip while a walker moves left."""

    def __init__(self) -> None:
        self.last: dict[int, float] = {}

    def on_update(self, dt: float) -> None:
        for e in named(self.world, "walker"):
            x = self.world.get(e, Transform).x
            prev = self.last.get(e, x)
            anim = self.world.get(e, Animator)
            if x < prev:
                anim.play("back", restart=False)
            elif x > prev:
                anim.play("walk", restart=False)
            self.last[e] = x


@walk_cycle.claim
def _footsteps_on_time(app: Any) -> None:
    # 300 steps = 5 s at 12 fps x speed, two steps per 8 frames, one more at each start
    # (turning around restarts the clip on its frame 0)
    for i, e in enumerate(named(app.world, "walker")):
        steps = app.world.get(e, Behaviour).script.steps
        speed = app.world.get(e, Animator).speed
        turns = math.ceil(5.0 / (3.0 - 0.5 * i)) - 1
        expected = 5.0 * 12 * speed / 4 + 1 + turns
        assert abs(steps - expected) <= 1.5, f"walker {e}: {steps} footsteps, expected ~{expected}"


def _coin_file() -> str:
    """The sample's GIF, written once to the temp folder (named by its content)."""
    data = coin_gif()
    path = Path(tempfile.gettempdir()) / f"kge-coin-{hashlib.sha1(data).hexdigest()[:12]}.gif"
    if not path.exists():
        path.write_bytes(data)
    return str(path)


@sample("Animation", "GIF", help="Spinning coins played from an animated GIF with the file's "
        "own frame delays; each coin at its own speed.")
def gif(world: World, coins: int = 5) -> None:
    path = _coin_file()
    clip = gif_clip(path)
    for i in range(coins):
        world.spawn(
            Transform(-2.4 + 1.2 * i, 0.0),
            Sprite(path, size=(0.8, 0.8)),
            Animator({"spin": clip}, speed=0.5 + 0.25 * i),
            Name("coin"),
        )


@gif.claim
def _gif_timing(app: Any) -> None:
    clip = app.world.get(named(app.world, "coin")[0], Animator).clips["spin"]
    assert [round(d * 1000) for d in clip.durations] == coin_delays()


@sample("Animation", "Easing Gallery",
        help="Every easing (31 curves) moving a dot from left to right and back, in rows.")
def easing_gallery(world: World) -> None:
    tweens = world.resource(Tweens)
    cols = 4
    for k, name in enumerate(EASING_NAMES):
        col, row = k % cols, k // cols
        x0 = -9.0 + col * 4.8
        y = 5.0 - row * 1.3
        world.spawn(Transform(x0, y), Line((0.0, 0.0), (4.0, 0.0), color=(70, 70, 90)))
        dot = world.spawn(Transform(x0, y), Circle(0.18, color=(255, 200, 80)), Name(name))
        tweens.to(dot, Transform, "x", x0 + 4.0, 1.5, ease=name, repeat=-1, yoyo=True)


@easing_gallery.claim
def _dots_stay_on_their_rails(app: Any) -> None:
    for name in EASING_NAMES:
        e = named(app.world, name)[0]
        x = app.world.get(e, Transform).x
        col = EASING_NAMES.index(name) % 4
        lo = -9.0 + col * 4.8
        overshoot = 4.0 if name.startswith(("back", "elastic")) else 0.0
        assert lo - overshoot <= x <= lo + 4.0 + overshoot, f"{name} at {x}"


class _Lander(Script):
    """Shakes the camera when this box lands hard (``on_hit``, above its hit threshold)."""

    def __init__(self) -> None:
        self.hits = 0

    def on_hit(self, event: Any) -> None:
        shake(self.world, min(0.6, 0.06 * event.approach_speed))
        self.hits += 1


class _SpaceShakes(Script):
    def on_key_down(self, key: int) -> None:
        if key == Key.SPACE:
            shake(self.world, 0.5)


@sample("Animation", "Camera Shake",
        help="Boxes drop onto the ground; every hard landing adds trauma to a camera shake "
             "that decays smoothly. Space: shake.", keys={"Space": "shake"})
def camera_shake(world: World, boxes: int = 6) -> None:
    static_box(world, 0.0, -0.5, 12.0, 0.5, name="ground")
    for i in range(boxes):
        world.spawn(Transform(-5.0 + 2.0 * i, 4.0 + 3.0 * i), RigidBody(),
                    Collider(Box(0.5, 0.5), density=1.0, hit_threshold=3.0),
                    Behaviour(_Lander()), Name("box"))
    world.spawn(Behaviour(_SpaceShakes()))


@camera_shake.claim
def _shaken_then_still(app: Any) -> None:
    from kge.components.shake import CameraShake

    hits = sum(app.world.get(e, Behaviour).script.hits for e in named(app.world, "box"))
    assert hits >= 1, "no landing was hard enough to shake"
    s = app.world.try_resource(CameraShake)
    assert s is not None and s.trauma < 0.05, "the shake should have decayed by now"
