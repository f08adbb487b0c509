"""Timeline sample: a keyframed door and lamp with a call track and a sound track."""

from __future__ import annotations

from typing import Any

from kge.components import Behaviour, Name, Script, Transform
from kge.components.drawables import Circle, Line
from kge.components.sprite import Sprite
from kge.components.timeline import Calls, Keys, Sounds, Timeline, TimelinePlayer
from kge.keys import Key
from kge.render.images import solid
from kge.sound import tone
from kge.testbed.registry import sample
from kge.testbed.samples.build import named
from kge.world import World


class _Door(Script):
    """Counts the chimes its timeline calls; Space plays the cycle backwards and on."""

    def __init__(self) -> None:
        self.chimes = 0

    def chime(self, times: int) -> None:
        self.chimes += times

    def on_update(self, dt: float) -> None:
        from kge.input import Input

        inp = self.world.try_resource(Input)
        if inp is not None and inp.pressed(Key.SPACE):
            player = self.world.get(self.entity, TimelinePlayer)
            player.speed = -player.speed


def cycle() -> Timeline:
    """Door rises (cubic), holds, falls (linear); the lamp turns green while open."""
    return Timeline([
        Keys(Transform, "y", [(0.0, 0.0), (0.8, 2.0), (2.0, 2.0), (2.6, 0.0)], interp="cubic"),
        Keys(Sprite, "tint", [(0.0, (200, 60, 60)), (0.8, (60, 200, 90)),
                              (2.0, (60, 200, 90)), (2.6, (200, 60, 60))]),
        Calls([(0.8, "chime", 1), (2.6, "chime", 2)]),
        Sounds([(0.0, tone(330.0, 0.08)), (2.6, tone(220.0, 0.1))], volume=0.4),
    ], length=3.0, loop=True)


@sample("Animation", "Timeline",
        help="A door keyframed as a timeline (Godot's AnimationPlayer): a cubic lift, a tint "
             "track, a call track (chimes) and a sound track, looping. Space reverses it.")
def timeline(world: World) -> None:
    world.spawn(Transform(0.0, -0.6), Line((-2.0, 0.0), (2.0, 0.0), color=(90, 90, 110)))
    world.spawn(Transform(-1.2, 2.0), Circle(0.2, color=(240, 220, 120)))
    world.spawn(Transform(0.0, 0.0), Sprite(solid(8, 8), size=(1.2, 1.2)),
                TimelinePlayer({"cycle": cycle()}), Behaviour(_Door()), Name("door"))


@timeline.claim
def _chimes_on_time(app: Any) -> None:
    # 300 steps of 1/60 s = 5 s: one full 3 s cycle (1 + 2 chimes) and the 0.8 s chime
    door = app.world.get(named(app.world, "door")[0], Behaviour).script
    assert door.chimes == 4, f"{door.chimes} chimes in 5 s, expected 4"
