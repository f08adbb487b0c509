"""Scripted key presses, for both testbed backends.

A :class:`Press` is a key going down at a frame and up ``hold`` frames later;
:func:`parse_presses` reads the command line's ``--keys 120:b,300:w/60`` (press
b at frame 120; hold w from frame 300 for 60 frames).

>>> parse_presses("120:b,300:w/60")
[Press(frame=120, key='b', hold=1), Press(frame=300, key='w', hold=60)]
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

from kge.box2d.testbed.keys import key_code

if TYPE_CHECKING:
    from kge.box2d.testbed.framework import Framework


@dataclass(frozen=True, slots=True)
class Press:
    """Key ``key`` (a ``Keys.K_<key>`` name) down at ``frame``, up ``hold`` frames later."""

    frame: int
    key: str
    hold: int = 1

    @property
    def code(self) -> int:
        return key_code(self.key)

    def downs_at(self, frame: int) -> bool:
        return frame == self.frame

    def ups_at(self, frame: int) -> bool:
        return frame == self.frame + self.hold


def parse_presses(text: str) -> list[Press]:
    """``FRAME:KEY[/HOLD],...`` into presses (each key name checked)."""
    out = []
    for item in filter(None, (part.strip() for part in text.split(","))):
        frame, _, rest = item.partition(":")
        key, _, hold = rest.partition("/")
        if not frame.isdigit() or not key or (hold and not hold.isdigit()):
            raise ValueError(f"a key press is FRAME:KEY or FRAME:KEY/HOLD, got {item!r}")
        press = Press(int(frame), key, int(hold) if hold else 1)
        press.code  # noqa: B018 - an unknown key name fails here, not mid-run
        out.append(press)
    return out


def press_scripted(test: Framework, presses: list[Press], frame: int) -> None:
    """Before ``frame``: release the presses that end there, then press those that start."""
    for press in presses:
        if press.ups_at(frame):
            test.KeyUp(press.code)
    for press in presses:
        if press.downs_at(frame):
            test.KeyDown(press.code)
