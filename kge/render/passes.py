"""Render passes: how a plugin draws with the world's cameras, before or after the batch.

Every world that draws has one pyglet batch (sprites, shapes, text, debug draw) and
one or more cameras. A game-layer plugin that draws something of its own (particles, a
light map, UI, tile chunks) registers a *pass* in the world's :class:`RenderPasses`
resource, from its ``build(world)``, without touching GL:

* ``phase="before"`` passes run once the frame's camera and blended poses are known
  and before the batch is drawn: upload vertex data in bulk into vertex lists that
  live in ``frame.batch`` (in ``frame.groups.get(layer, WORLD)`` so they sort with
  sprites of the same layer); with several cameras, ``frame.view`` covers all views;
* ``phase="view"`` passes run once per camera, just before that camera draws the
  batch, with that camera's ``frame`` (the light map is rendered here);
* ``phase="after"`` passes run after every camera and the screen-space text, in
  ``order``: overlays drawn in screen pixels (UI), with the screen's projection set
  (design pixels with a ``Resolution``).

A pass receives a :class:`Frame` and imports pyglet's GL only when it runs, so a
headless App that never renders never loads it.

>>> from kge.world import World
>>> passes = passes_for(World())
>>> calls = []
>>> _ = passes.add(lambda frame: calls.append("ui"), phase="after", order=1000)
>>> _ = passes.add(lambda frame: calls.append("lights"), phase="after", order=100)
>>> for p in passes.after(): p(None)
>>> calls
['lights', 'ui']
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any, Literal

if TYPE_CHECKING:
    import numpy as np

    from kge.components.camera import Camera
    from kge.world import World

Pass = Callable[["Frame"], None]
Phase = Literal["before", "view", "after"]


@dataclass(slots=True)
class Frame:
    """What a pass knows of the frame being drawn (pixels only here, in rendering)."""

    alpha: float  #: interpolation between the last two fixed steps
    camera: Camera
    center: tuple[float, float]  #: the camera centre drawn this frame (metres)
    scale: float  #: window pixels per metre (pixels_per_meter * zoom)
    viewport: tuple[int, int]  #: the camera's viewport size in screen (design) pixels
    view: tuple[float, float, float, float]  #: visible world rect (left, bottom, right, top)
    world_matrix: Any  #: pyglet Mat4: world metres -> window pixels (the WORLD groups' view)
    time: float  #: game time of the last fixed step (seconds)
    batch: Any  #: the world's pyglet Batch (drawn between the two phases)
    groups: Any  #: :class:`kge.render.groups.Groups`: ``groups.get(layer, space, order)``
    poses: np.ndarray  #: blended (x, y, angle) rows of drawn entities
    rows: dict[int, int]  #: entity -> row of ``poses``
    #: the camera's viewport in the framebuffer drawn into: (x, y, width, height) pixels
    rect: tuple[int, int, int, int] = (0, 0, 0, 0)
    #: framebuffer pixels per screen (design) pixel
    pixel_scale: float = 1.0
    #: the camera's rotation, radians counter-clockwise
    rotation: float = 0.0

    def pose(self, entity: int) -> tuple[float, float, float] | None:
        """The blended pose of a drawn entity this frame, or None."""
        row = self.rows.get(entity)
        if row is None:
            return None
        x, y, a = self.poses[row, :3]
        return (float(x), float(y), float(a))

    def world_to_screen(self, point: tuple[float, float]) -> tuple[float, float]:
        """World metres to viewport pixels with this frame's camera."""
        m = self.world_matrix
        x, y = point
        return (m[0] * x + m[4] * y + m[12], m[1] * x + m[5] * y + m[13])


class RenderPasses:
    """The passes of one world (a resource; see the module docstring)."""

    def __init__(self) -> None:
        self._passes: list[tuple[Phase, int, int, Pass]] = []
        self._serial = 0

    def add(self, fn: Pass, *, phase: Phase = "before", order: int = 0) -> Pass:
        """Register ``fn``; within a phase lower ``order`` runs first (ties: added first)."""
        if phase not in ("before", "view", "after"):
            raise ValueError(
                f"RenderPasses.add: phase must be 'before', 'view' or 'after', got {phase!r}"
            )
        self._serial += 1
        self._passes.append((phase, int(order), self._serial, fn))
        self._passes.sort(key=lambda p: (p[1], p[2]))
        return fn

    def remove(self, fn: Pass) -> None:
        self._passes = [p for p in self._passes if p[3] is not fn]

    def before(self) -> list[Pass]:
        return [p[3] for p in self._passes if p[0] == "before"]

    def view(self) -> list[Pass]:
        return [p[3] for p in self._passes if p[0] == "view"]

    def after(self) -> list[Pass]:
        return [p[3] for p in self._passes if p[0] == "after"]


def passes_for(world: World) -> RenderPasses:
    """The world's :class:`RenderPasses`, created on first use."""
    found = world.try_resource(RenderPasses)
    if found is None:
        found = world.insert_resource(RenderPasses())
    return found
