"""Cross-fade sample: walkers blend between a walk cycle and a still pose, cut vs faded."""

from __future__ import annotations

from typing import Any

from kge.components import Behaviour, Name, Script, Transform
from kge.components.animation import Animator, Clip, Transition
from kge.components.drawables import Line
from kge.components.sprite import Sprite
from kge.systems.animation import Animations
from kge.testbed.art import as_image, walk_sheet
from kge.testbed.registry import sample
from kge.testbed.samples.build import named
from kge.world import World

#: each walker's cross-fade (seconds), top to bottom: a cut, then slower and slower blends
FADES = (0.0, 0.15, 0.4)
PERIOD = 1.0


class _Toggle(Script):
    """Every PERIOD seconds flips each walker's ``moving`` parameter; counts fades seen."""

    def __init__(self) -> None:
        self.clock = 0.0
        self.moving = False
        self.fading_frames = 0

    def on_update(self, dt: float) -> None:
        self.clock += dt
        if self.clock >= PERIOD:
            self.clock -= PERIOD
            self.moving = not self.moving
        anims = self.world.resource(Animations)
        for e in named(self.world, "walker"):
            self.world.get(e, Animator).set("moving", self.moving)
            if anims.crossfade(e) is not None:
                self.fading_frames += 1


@sample("Animation", "Cross-fade",
        help="Three walkers start and stop walking every second: the top one cuts between "
             "its clips, the others cross-fade over 0.15 s and 0.4 s (Transition fade=).")
def crossfade(world: World) -> None:
    sheet = as_image(walk_sheet())
    walk = Clip.grid(sheet, (8, 1), fps=12)
    still = Clip.grid(sheet, (8, 1), frames=[2])
    for i, fade in enumerate(FADES):
        y = 2.0 - 1.5 * i
        trs = (Transition("still", "walk", when="moving", fade=fade),
               Transition("walk", "still", when="not moving", fade=fade))
        world.spawn(Transform(0.0, y), Sprite(sheet, size=(1.2, 1.2)),
                    Animator({"still": still, "walk": walk}, transitions=trs), Name("walker"))
        world.spawn(Transform(0.0, y - 0.6), Line((-1.0, 0.0), (1.0, 0.0), color=(90, 90, 110)))
    world.spawn(Behaviour(_Toggle()), Name("toggle"))


@crossfade.claim
def _fades_happen(app: Any) -> None:
    toggle = app.world.get(named(app.world, "toggle")[0], Behaviour).script
    assert toggle.fading_frames > 0, "no walker cross-faded"
