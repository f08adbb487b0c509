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
* ``phase="after"`` passes run after every camera and the screen-space text:
  overlays drawn in screen pixels (UI), with the screen's projection set (design
  pixels with a ``Resolution``).

Within a phase, passes are ordered by name, as systems are (:mod:`kge.schedule`): a
pass names itself (``name=``) and may say ``before=`` / ``after=`` other passes' names;
two passes nothing orders *tie* and run in the order they were added, reported by
:meth:`RenderPasses.ties`. The built-in order is ``animation`` -> ``tilemap`` ->
``particles`` before the batch, ``lighting`` per view, ``ui`` after it.

A pass receives a :class:`Frame` and imports pyglet's GL only when it runs, so a
headless App that never renders never loads it.

>>> from kge.world import World
>>> passes = passes_for(World())
>>> calls = []
>>> _ = passes.add(lambda frame: calls.append("ui"), phase="after", name="ui")
>>> _ = passes.add(lambda frame: calls.append("fog"), phase="after", name="fog",
...                before=["ui"])
>>> for p in passes.after(): p(None)
>>> calls
['fog', 'ui']
"""

from __future__ import annotations

from collections.abc import Callable, Iterable
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any, Literal

from kge import deprecation
from kge.schedule import order_items

if TYPE_CHECKING:
    import numpy as np

    from kge.components.camera import Camera
    from kge.world import World

Pass = Callable[["Frame"], None]
Phase = Literal["before", "view", "after"]
PHASES: tuple[Phase, ...] = ("before", "view", "after")


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


@dataclass(slots=True)
class _Entry:
    phase: Phase
    name: str
    before: tuple[str, ...]
    after: tuple[str, ...]
    legacy: int | None  #: a deprecated integer ``order``
    fn: Pass


#: the integers the built-in passes had before names, to place a deprecated ``order``
_LEGACY = {"animation": -100, "tilemap": -100, "particles": 100, "lighting": 200, "ui": 1000}


class RenderPasses:
    """The passes of one world (a resource; see the module docstring)."""

    def __init__(self) -> None:
        self._entries: list[_Entry] = []
        self._sorted: dict[Phase, list[_Entry]] = {p: [] for p in PHASES}
        self._ties: dict[Phase, list[tuple[str, str]]] = {p: [] for p in PHASES}

    def add(
        self,
        fn: Pass,
        *,
        phase: Phase = "before",
        name: str | None = None,
        before: Iterable[str] = (),
        after: Iterable[str] = (),
        order: int | None = None,
    ) -> Pass:
        """Register ``fn`` in ``phase``, placed by ``before`` / ``after`` (pass names).

        ``order`` (an integer, lower first) is deprecated: name the pass instead.
        """
        if phase not in PHASES:
            raise ValueError(
                f"RenderPasses.add: phase must be 'before', 'view' or 'after', got {phase!r}"
            )
        label = name if name is not None else getattr(fn, "__qualname__", repr(fn))
        if order is not None:
            deprecation.warn(
                f"RenderPasses.add(order={order}): name the pass (name=) and place it "
                "with before= / after= other passes' names"
            )
        entry = _Entry(phase, str(label), tuple(before), tuple(after),
                       None if order is None else int(order), fn)  # fmt: skip
        entries = [*self._entries, entry]
        self._sorted[phase], self._ties[phase] = _sort(phase, entries)
        self._entries = entries
        return fn

    def remove(self, fn: Pass) -> None:
        self._entries = [e for e in self._entries if e.fn is not fn]
        for phase in PHASES:
            self._sorted[phase], self._ties[phase] = _sort(phase, self._entries)

    def before(self) -> list[Pass]:
        return [e.fn for e in self._sorted["before"]]

    def view(self) -> list[Pass]:
        return [e.fn for e in self._sorted["view"]]

    def after(self) -> list[Pass]:
        return [e.fn for e in self._sorted["after"]]

    def names(self, phase: Phase) -> list[str]:
        """The passes of ``phase`` by name, in the order they run."""
        return [e.name for e in self._sorted[phase]]

    def ties(self) -> list[tuple[Phase, str, str]]:
        """Pairs of passes that run one after the other with nothing ordering them."""
        return [(phase, a, b) for phase in PHASES for a, b in self._ties[phase]]


def _sort(phase: Phase, entries: list[_Entry]) -> tuple[list[_Entry], list[tuple[str, str]]]:
    mine = [e for e in entries if e.phase == phase]
    index: dict[str, list[int]] = {}
    for i, e in enumerate(mine):
        index.setdefault(e.name, []).append(i)
    edges = []
    for i, e in enumerate(mine):
        edges += [(j, i) for name in e.after for j in index.get(name, ())]
        edges += [(i, j) for name in e.before for j in index.get(name, ())]
        if e.legacy is not None:  # a deprecated integer: against the others' numbers
            for j, other in enumerate(mine):
                theirs = other.legacy if other.legacy is not None else _LEGACY.get(other.name)
                if j != i and theirs is not None:  # equal numbers: the one added first
                    first = theirs < e.legacy or (theirs == e.legacy and j < i)
                    edges.append((j, i) if first else (i, j))
    order, ties = order_items([e.name for e in mine], edges, f"{phase} render pass")
    return [mine[i] for i in order], [(mine[a].name, mine[b].name) for a, b in ties]


def passes_for(world: World) -> RenderPasses:
    """The world's :class:`RenderPasses`, created on first use."""
    found = world.try_resource(RenderPasses)
    if found is None:
        found = world.insert_resource(RenderPasses())
    return found
