"""``fwSettings``: the testbed's settings, with the names and defaults of pybox2d's testbed.

Examples read them in ``Step(settings)`` (``settings.hz``, ``settings.pause``) and
some change them (liquid.py turns sub-stepping off), so one :class:`Settings`
object is shared by the framework and the running example; :func:`reset` puts
the defaults back before a run. :func:`parse` reads pybox2d's command-line
options (``--hz 30``, ``--no-drawStats``, ``--drawAABBs``...) into it.

>>> reset()
>>> fwSettings.hz, fwSettings.velocityIterations, fwSettings.positionIterations
(60.0, 8, 3)
>>> parse(["--hz", "30", "--drawAABBs", "--no-drawStats", "car"])
['car']
>>> fwSettings.hz, fwSettings.drawAABBs, fwSettings.drawStats
(30.0, True, False)
>>> reset(); fwSettings.hz
60.0
"""

from __future__ import annotations

import argparse
from dataclasses import dataclass, fields


@dataclass
class Settings:
    """What the testbed runs with (pybox2d's names: programs read these attributes)."""

    backend: str = "kge"
    # physics
    hz: float = 60.0
    velocityIterations: int = 8
    positionIterations: int = 3
    enableWarmStarting: bool = True
    enableContinuous: bool = True
    enableSubStepping: bool = False
    # drawing
    drawStats: bool = True
    drawShapes: bool = True
    drawJoints: bool = True
    drawCoreShapes: bool = False
    drawAABBs: bool = False
    drawOBBs: bool = False
    drawPairs: bool = False
    drawContactPoints: bool = False
    maxContactPoints: int = 100
    drawContactNormals: bool = False
    drawFPS: bool = True
    drawMenu: bool = True
    drawCOMs: bool = False
    pointSize: float = 2.5
    # control
    pause: bool = False
    singleStep: bool = False
    onlyInit: bool = False


fwSettings = Settings()


def reset() -> None:
    """Put every setting back to its default."""
    for f in fields(Settings):
        setattr(fwSettings, f.name, f.default)


def options(parser: argparse.ArgumentParser | argparse._ArgumentGroup) -> None:
    """Add pybox2d's testbed options to ``parser``: ``--<name> VALUE`` for numbers and
    text, ``--<name>`` to turn a default-off flag on, ``--no-<name>`` to turn one off."""
    for f in fields(Settings):
        if f.type == "bool":
            if f.default:
                parser.add_argument(f"--no-{f.name}", dest=f.name, action="store_false",
                                    default=argparse.SUPPRESS, help=f"turn {f.name} off")
            else:
                parser.add_argument(f"--{f.name}", dest=f.name, action="store_true",
                                    default=argparse.SUPPRESS, help=f"turn {f.name} on")
        else:
            kind = {"float": float, "int": int}.get(str(f.type), str)
            parser.add_argument(f"--{f.name}", dest=f.name, type=kind,
                                default=argparse.SUPPRESS, help=f"(default {f.default})")


def apply(values: argparse.Namespace) -> None:
    """Copy the parsed testbed options onto :data:`fwSettings`."""
    for f in fields(Settings):
        if hasattr(values, f.name):
            setattr(fwSettings, f.name, getattr(values, f.name))


def parse(argv: list[str]) -> list[str]:
    """Apply the testbed options in ``argv``; return what was not one of them."""
    parser = argparse.ArgumentParser(add_help=False)
    options(parser)
    values, rest = parser.parse_known_args(argv)
    apply(values)
    return rest
