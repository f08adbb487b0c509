"""``DebugDraw``: what the physics debug view shows, switchable while the game runs.

Insert it as a resource (``world.insert_resource(DebugDraw())``) or toggle the
one the renderer creates: ``world.resource(DebugDraw).enabled = True``. In a
window, F1 toggles ``enabled``, F2 the stats overlay and F4 the per-system timings
in it (the debug plugin's key).

Colours follow the Box2D testbed, so a Box2D user reads the picture at once:
bodies are coloured by state (static green, kinematic blue, asleep grey,
disabled olive, awake pink), joints cyan, AABBs magenta, new contact points
green and their normals yellow.

>>> d = DebugDraw(aabbs=True)
>>> d.enabled, d.color_for(static=False, kinematic=False, awake=False, enabled=True)
(True, (153, 153, 153, 255))
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import ClassVar

from kge.components.color import RGBA, rgba
from kge.components.tracked import Check, Tracked
from kge.validate import boolean, positive


@dataclass(slots=True)
class DebugDraw(Tracked):
    """Physics debug-draw switches and colours (RGBA 0-255)."""

    _checks: ClassVar[dict[str, Check]] = {
        "enabled": boolean,
        "shapes": boolean,
        "joints": boolean,
        "aabbs": boolean,
        "centers_of_mass": boolean,
        "contacts": boolean,
        "contact_normals": boolean,
        "stats": boolean,
        "timings": boolean,
        "contact_seconds": positive,
        "static_color": rgba,
        "kinematic_color": rgba,
        "asleep_color": rgba,
        "disabled_color": rgba,
        "awake_color": rgba,
        "joint_color": rgba,
        "aabb_color": rgba,
        "contact_color": rgba,
        "normal_color": rgba,
    }

    enabled: bool = True
    shapes: bool = True
    joints: bool = True
    aabbs: bool = False
    centers_of_mass: bool = False
    contacts: bool = True
    contact_normals: bool = True
    stats: bool = False
    #: per-system timings in the stats overlay (F4; turns the schedule's timings on)
    timings: bool = False
    #: how long a contact point stays drawn after its begin event (events last one step)
    contact_seconds: float = 0.25
    static_color: RGBA = (127, 230, 127, 255)
    kinematic_color: RGBA = (127, 127, 230, 255)
    asleep_color: RGBA = (153, 153, 153, 255)
    disabled_color: RGBA = (127, 127, 76, 255)
    awake_color: RGBA = (230, 178, 178, 255)
    joint_color: RGBA = (127, 204, 204, 255)
    aabb_color: RGBA = (230, 76, 230, 255)
    contact_color: RGBA = (76, 242, 76, 255)
    normal_color: RGBA = (230, 230, 76, 255)

    def color_for(self, *, static: bool, kinematic: bool, awake: bool, enabled: bool) -> RGBA:
        """The outline colour of a body in this state (Box2D's order of precedence)."""
        if not enabled:
            return self.disabled_color
        if static:
            return self.static_color
        if kinematic:
            return self.kinematic_color
        if not awake:
            return self.asleep_color
        return self.awake_color
