"""Animator transitions on conditions beyond a truthy parameter: not, comparisons, and."""

from __future__ import annotations

from typing import Any

import pytest

from kge import Animator, Clip, Transition, ValidationError, World
from kge.components.conditions import met
from kge.schedule import Stage
from kge.systems.animation import AnimationPlugin


def test_conditions_read_the_parameters() -> None:
    params: dict[str, Any] = {"speed": 2, "grounded": True, "state": "jump"}
    assert met("speed > 1.5", params) and not met("speed >= 2.5", params)
    assert met("speed == 2", params) and met("speed != 3", params)
    assert met("grounded and state == jump", params)
    assert not met("not grounded", params) and met("not hurt", params)
    assert not met("hurt > 0", params)  # unset: a comparison is false, never an error
    assert not met("state > 1", params)  # a word is not a number
    assert met("grounded == true", params)


@pytest.mark.parametrize("bad", ["speed >> 2", "", "speed >", "2 < speed", "a or b",
                                 "speed > inf", "not"])
def test_a_malformed_condition_is_refused_when_the_transition_is_made(bad: str) -> None:
    with pytest.raises(ValidationError, match="Transition.when"):
        Transition("idle", "run", when=bad)


def test_the_animator_follows_comparisons(sheet: Any) -> None:
    idle = Clip.grid(sheet, (4, 1), frames=[0])
    walk = Clip.grid(sheet, (4, 1), frames=[1])
    run = Clip.grid(sheet, (4, 1), frames=[2])
    trs = (
        Transition("*", "run", when="speed >= 4 and grounded"),
        Transition("idle", "walk", when="speed > 0.1 and speed < 4"),
        Transition("*", "idle", when="speed <= 0.1"),
    )
    w = World()
    w.add_plugins(AnimationPlugin())
    anim = w.get(w.spawn(Animator({"idle": idle, "walk": walk, "run": run}, transitions=trs,
                                  params={"speed": 0.0, "grounded": True})), Animator)
    seen = []
    for speed in (0.0, 1.0, 5.0, 0.05):
        anim.set("speed", speed)
        w.schedule.run(Stage.UPDATE, 0.05)
        seen.append(anim.current)
    assert seen == ["idle", "walk", "run", "idle"]
    anim.set("grounded", False)
    anim.set("speed", 5.0)
    w.schedule.run(Stage.UPDATE, 0.05)
    assert anim.current == "idle"  # "idle" -> "walk" needs speed < 4; "run" needs grounded
