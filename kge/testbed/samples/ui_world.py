"""UI in the world: health bars and name tags that follow falling crates, losing health
when the crates land hard."""

from __future__ import annotations

from typing import Any

from kge.components import Behaviour, Name, Script, Transform
from kge.components.drawables import Rect
from kge.components.ui import Label, ProgressBar, UINode
from kge.physics.events import ContactBegin
from kge.testbed.registry import sample
from kge.testbed.samples.build import box, static_box
from kge.world import World


class _Damage(Script):
    """A crate's health drops by 10 on every contact it begins."""

    def __init__(self, bars: dict[int, int]) -> None:
        self.bars = bars

    def on_fixed_update(self, dt: float) -> None:
        for ev in self.world.events(ContactBegin):
            for body in (ev.body_a, ev.body_b):
                bar = self.bars.get(body) if body is not None else None
                if bar is not None and self.world.exists(bar):
                    self.world.get(bar, ProgressBar).value -= 10


@sample("UI", "World-space UI",
        help="Health bars and name tags follow the crates (UINode.follow); hits cost health.")
def world_space_ui(world: World) -> None:
    ground = static_box(world, 0.0, -1.0, 14.0, 1.0, name="ground")
    world.add(ground, Rect(28.0, 2.0, color=(90, 96, 110, 255)))
    bars: dict[int, int] = {}
    for i in range(6):
        crate = box(world, -5.0 + 2.0 * i, 3.0 + 1.2 * i, 0.5, 0.5, density=1.0, name="crate")
        world.add(crate, Rect(1.0, 1.0, color=(230, 160, 60, 255)))
        bars[crate] = world.spawn(
            UINode(follow=crate, follow_offset=(0.0, 0.75), anchor="bottom", width=48, height=7),
            ProgressBar(100, max=100, color=(90, 220, 110, 255)),
        )
        world.spawn(UINode(follow=crate, follow_offset=(0.0, 0.75), anchor="bottom",
                           offset=(0, 9)), Label(f"Crate {i + 1}", size=11))  # fmt: skip
    world.spawn(Behaviour(_Damage(bars)), Name("referee"))


@world_space_ui.claim
def _bars_follow_their_crates_and_lose_health_on_landing(app: Any) -> None:
    from kge.ui.current import current_layout

    world = app.world
    lay = current_layout(world)
    for e, (node, bar) in world.query(UINode, ProgressBar):
        assert node.follow is not None
        t = world.get(node.follow, Transform)
        x, y = app.world_to_screen((t.x, t.y + 0.75))
        b = lay.boxes[e]
        assert abs(b.center[0] - x) < 1e-6 and abs(b.y - y) < 1e-6
        assert bar.value < 100  # every crate has landed on something by now
