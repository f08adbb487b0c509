"""Touch points and the gestures recognised from them: tap, double tap, drag, pinch, rotate.

:class:`~kge.input.Input` owns one :class:`TouchState`; a window (or a test) feeds it
with ``Input.touch_down / touch_move / touch_up`` in screen pixels, and the Input
converts each point to world metres in its one place (``Input.screen_to_world``).

Gestures follow the usual mobile rules (the thresholds are attributes):

* **tap**: one finger down and up within :data:`TAP_TIME` seconds, never moving
  more than :data:`TAP_SLOP` pixels; a tap within :data:`DOUBLE_TAP_WINDOW` seconds
  and :data:`DOUBLE_TAP_SLOP` pixels of the previous one is a **double tap**
  (``TapGesture.taps`` counts on: 2, 3...).
* **drag**: the fingers' centre moves more than :data:`TAP_SLOP` pixels; one finger
  drags, two pan. A change in the number of fingers ends the drag (a new one may
  begin), so the centre never jumps.
* **pinch**: two fingers move apart or together by more than :data:`PINCH_SLOP`
  pixels; ``scale`` is their distance over the distance when the second finger came
  down.
* **rotate**: two fingers turn by more than :data:`ROTATE_SLOP` radians;
  ``angle`` is counter-clockwise, like every angle in kge, and counts whole turns
  (each move between two events must turn less than half a turn).

Each gesture is a button-like edge (``Input.gesture_pressed("pinch")``: it began;
``gesture_held``: it goes on; ``gesture_released``: it ended; a tap is pressed and
released at once) and an event (:class:`TapGesture`, :class:`DragGesture`, :class:`PinchGesture`,
:class:`RotateGesture`, and :class:`TouchPoint` for every touch phase) emitted into the top
scene's world. The clock that times taps is real time, advanced by the App each frame
(:meth:`TouchState.advance` in tests without an App).

>>> from kge.input import Input
>>> inp = Input()
>>> inp.touch_down(0, (100, 100)); inp.touch_down(1, (200, 100))
>>> inp.touch_move(1, (300, 100))                 # twice as far apart
>>> inp.gesture_pressed("pinch"), inp.pinch_scale()
(True, 2.0)
"""

from __future__ import annotations

import math
from collections.abc import Callable, Hashable
from dataclasses import dataclass
from typing import Protocol

from kge.errors import ValidationError

Vec2 = tuple[float, float]

#: the gesture names (``Input.gesture_pressed(name)``, bindings ``"touch:NAME"``)
GESTURES: tuple[str, ...] = ("tap", "double_tap", "drag", "pinch", "rotate")
#: phases of a touch point and of the continuous gestures
PHASES: tuple[str, ...] = ("began", "moved", "ended")
#: a touch held longer than this (seconds) is not a tap
TAP_TIME = 0.3
#: a finger moving further than this (pixels) is not a tap; a centre moving further drags
TAP_SLOP = 10.0
#: a tap at most this many seconds after the previous tap, ...
DOUBLE_TAP_WINDOW = 0.3
#: ... and at most this many pixels from it, is a double tap
DOUBLE_TAP_SLOP = 40.0
#: two fingers' distance must change by this many pixels before a pinch begins
PINCH_SLOP = 10.0
#: two fingers must turn by this many radians before a rotation begins
ROTATE_SLOP = 0.15
#: the touch id the mouse's left button becomes (``Input.emulate_touch_from_mouse``)
MOUSE_TOUCH_ID = 0


@dataclass(slots=True, frozen=True)
class TouchPoint:
    """One finger: its ``id``, ``phase`` ("began", "moved", "ended"), position in screen
    pixels (origin bottom-left) and world metres, and where it began (screen pixels).
    Both the state ``Input.touches()`` lists and the event each phase emits."""

    id: int
    phase: str
    screen: Vec2
    world: Vec2
    start: Vec2

    def down(self) -> bool:
        """Still touching (began or moved)?"""
        return self.phase != "ended"


@dataclass(slots=True, frozen=True)
class TapGesture:
    """A tap ended here; ``taps`` is 2 for a double tap, 3 for a triple tap..."""

    screen: Vec2
    world: Vec2
    taps: int = 1


@dataclass(slots=True, frozen=True)
class DragGesture:
    """The fingers' centre moved: ``delta`` since the last DragGesture event (pixels and metres);
    ``fingers`` is 1 for a drag, 2 for a two-finger pan."""

    phase: str
    screen: Vec2
    world: Vec2
    delta: Vec2
    delta_world: Vec2
    fingers: int = 1


@dataclass(slots=True, frozen=True)
class PinchGesture:
    """Two fingers spread (``scale`` > 1) or closed (< 1) since they came down;
    ``delta`` is the factor since the last PinchGesture event (``zoom *= delta``)."""

    phase: str
    center: Vec2
    center_world: Vec2
    scale: float
    delta: float


@dataclass(slots=True, frozen=True)
class RotateGesture:
    """Two fingers turned ``angle`` radians counter-clockwise since they came down;
    ``delta`` since the last RotateGesture event."""

    phase: str
    center: Vec2
    center_world: Vec2
    angle: float
    delta: float


GestureEvent = TapGesture | DragGesture | PinchGesture | RotateGesture
TouchEventAny = TouchPoint | GestureEvent


class EdgeSink(Protocol):
    """Where gesture edges go (the Input's edge book, so fixed steps see them once)."""

    def down(self, code: Hashable) -> bool: ...

    def up(self, code: Hashable) -> bool: ...


class _Finger:
    __slots__ = ("began_at", "id", "phase", "screen", "start", "world")

    def __init__(self, id: int, screen: Vec2, world: Vec2, now: float) -> None:
        self.id, self.screen, self.world, self.start = id, screen, world, screen
        self.began_at = now
        self.phase = "began"  #: "began" in the frame it came down, "moved" in later ones

    def point(self, phase: str) -> TouchPoint:
        return TouchPoint(self.id, phase, self.screen, self.world, self.start)


class _Two:
    """The two-finger gesture in progress: distances and the angle turned so far."""

    __slots__ = ("angle", "dist", "dist0", "pinching", "rotating", "turned", "turned_sent")

    def __init__(self, dist: float, angle: float) -> None:
        self.dist0 = self.dist = dist
        self.angle = angle  #: the fingers' direction at the last move
        self.turned = 0.0  #: radians turned since they came down (not wrapped: 3/2 pi is)
        self.turned_sent = 0.0  #: ``turned`` at the last RotateGesture event
        self.pinching = self.rotating = False


def _wrap(angle: float) -> float:
    return (angle + math.pi) % math.tau - math.pi


class TouchState:
    """The fingers down now and the gesture recogniser (see the module docstring)."""

    def __init__(self, edges: EdgeSink, to_world: Callable[[Vec2], Vec2]) -> None:
        self._edges = edges
        self._to_world = to_world
        self.now = 0.0
        self.fingers: dict[int, _Finger] = {}  #: in the order they came down
        self.ended: list[TouchPoint] = []  #: fingers lifted this frame
        self.events: list[TouchEventAny] = []  #: this frame's touch and gesture events
        self.tap_time, self.tap_slop = TAP_TIME, TAP_SLOP
        self.double_tap_window, self.double_tap_slop = DOUBLE_TAP_WINDOW, DOUBLE_TAP_SLOP
        self.pinch_slop, self.rotate_slop = PINCH_SLOP, ROTATE_SLOP
        # this frame's sums of the continuous gestures
        self.drag_delta: Vec2 = (0.0, 0.0)
        self.drag_delta_world: Vec2 = (0.0, 0.0)
        self.pinch = 1.0
        self.rotation = 0.0
        self._tap_ok = False  #: the finger now down may still be a tap
        self._last_tap: tuple[float, Vec2, int] = (-math.inf, (0.0, 0.0), 0)
        self._drag_from: Vec2 | None = None  #: the centre a drag is measured from
        self._dragging = False
        self._two: _Two | None = None

    # -- feeding -----------------------------------------------------------------------
    def down(self, id: int, screen: Vec2) -> None:
        if id in self.fingers:
            raise ValidationError(f"Input.touch_down: touch {id} is already down")
        self._end_continuous()
        self._tap_ok = not self.fingers
        finger = self.fingers[id] = _Finger(id, screen, self._to_world(screen), self.now)
        self.events.append(finger.point("began"))
        self._regroup()

    def move(self, id: int, screen: Vec2, call: str = "touch_move") -> None:
        finger = self._finger(id, call)
        if screen == finger.screen:
            return
        finger.screen, finger.world = screen, self._to_world(screen)
        self.events.append(finger.point("moved"))
        if finger.phase != "began":
            finger.phase = "moved"
        if math.dist(screen, finger.start) > self.tap_slop:
            self._tap_ok = False
        self._track()

    def up(self, id: int, screen: Vec2 | None) -> None:
        finger = self._finger(id, "touch_up")
        if screen is not None:
            self.move(id, screen, "touch_up")
        self._end_continuous()
        lifted = finger.point("ended")
        del self.fingers[id]
        self.ended.append(lifted)
        self.events.append(lifted)
        if not self.fingers and self._tap_ok and self.now - finger.began_at <= self.tap_time:
            self._tap(lifted)
        self._regroup()

    def advance(self, dt: float) -> None:
        """Advance the tap clock by ``dt`` real seconds (the App does, every frame)."""
        if math.isfinite(dt) and dt > 0:
            self.now += dt

    # -- recognising -------------------------------------------------------------------
    def _finger(self, id: int, call: str) -> _Finger:
        finger = self.fingers.get(id)
        if finger is None:
            down = ", ".join(map(str, self.fingers)) or "none"
            raise ValidationError(f"Input.{call}: touch {id} is not down (down: {down})")
        return finger

    def _pair(self) -> list[_Finger]:
        """The fingers gestures follow: the first two down."""
        return list(self.fingers.values())[:2]

    def _centre(self) -> Vec2:
        pair = self._pair()
        return (
            sum(f.screen[0] for f in pair) / len(pair),
            sum(f.screen[1] for f in pair) / len(pair),
        )

    def _regroup(self) -> None:
        """The fingers changed: measure drags and two-finger gestures afresh."""
        self._drag_from = self._centre() if self.fingers else None
        pair = self._pair()
        self._two = _Two(*self._spread(pair)) if len(pair) == 2 else None

    @staticmethod
    def _spread(pair: list[_Finger]) -> tuple[float, float]:
        (ax, ay), (bx, by) = pair[0].screen, pair[1].screen
        return max(math.hypot(bx - ax, by - ay), 1.0), math.atan2(by - ay, bx - ax)

    def _track(self) -> None:
        centre = self._centre()
        if self._drag_from is not None and (
            self._dragging or math.dist(centre, self._drag_from) > self.tap_slop
        ):
            self._drag("moved" if self._dragging else "began", centre)
        two = self._two
        if two is None:
            return
        dist, angle = self._spread(self._pair())
        world = self._to_world(centre)
        phase = self._phase("pinch", two.pinching, abs(dist - two.dist0) > self.pinch_slop,
                            dist != two.dist)  # fmt: skip
        if phase:
            delta, two.dist, two.pinching = dist / two.dist, dist, True
            self.pinch *= delta
            self.events.append(PinchGesture(phase, centre, world, dist / two.dist0, delta))
        two.turned += _wrap(angle - two.angle)  # each move turns less than half a turn
        two.angle = angle
        phase = self._phase("rotate", two.rotating, abs(two.turned) > self.rotate_slop,
                            two.turned != two.turned_sent)  # fmt: skip
        if phase:
            delta_a, two.turned_sent, two.rotating = two.turned - two.turned_sent, two.turned, True
            self.rotation += delta_a
            self.events.append(RotateGesture(phase, centre, world, two.turned, delta_a))

    def _phase(self, name: str, active: bool, past_slop: bool, changed: bool) -> str:
        """ "began" when a gesture crosses its threshold, "moved" while it changes, else ""."""
        if not active and past_slop:
            self._edges.down(name)
            return "began"
        return "moved" if active and changed else ""

    def _drag(self, phase: str, centre: Vec2) -> None:
        assert self._drag_from is not None
        if phase == "began":
            self._dragging = True
            self._edges.down("drag")
        dx, dy = centre[0] - self._drag_from[0], centre[1] - self._drag_from[1]
        w0, w1 = self._to_world(self._drag_from), self._to_world(centre)
        dw = (w1[0] - w0[0], w1[1] - w0[1])
        self._drag_from = centre
        self.drag_delta = (self.drag_delta[0] + dx, self.drag_delta[1] + dy)
        self.drag_delta_world = (self.drag_delta_world[0] + dw[0], self.drag_delta_world[1] + dw[1])
        self.events.append(DragGesture(phase, centre, w1, (dx, dy), dw, len(self._pair())))

    def _end_continuous(self) -> None:
        """The number of fingers changes: a drag, pinch or rotation in progress ends."""
        if self._dragging:
            centre = self._centre()
            self.events.append(
                DragGesture("ended", centre, self._to_world(centre), (0.0, 0.0), (0.0, 0.0),
                     len(self._pair()))
            )  # fmt: skip
            self._dragging = False
            self._edges.up("drag")
        two = self._two
        if two is None:
            return
        centre = self._centre()
        world = self._to_world(centre)
        if two.pinching:
            self.events.append(PinchGesture("ended", centre, world, two.dist / two.dist0, 1.0))
            self._edges.up("pinch")
        if two.rotating:
            self.events.append(RotateGesture("ended", centre, world, two.turned_sent, 0.0))
            self._edges.up("rotate")
        self._two = None

    def _tap(self, lifted: TouchPoint) -> None:
        at, (last, where, taps) = lifted.screen, self._last_tap
        near = math.dist(at, where) <= self.double_tap_slop
        taps = taps + 1 if self.now - last <= self.double_tap_window and near else 1
        self._last_tap = (self.now, at, taps)
        self.events.append(TapGesture(at, lifted.world, taps))
        names = ("tap", "double_tap") if taps == 2 else ("tap",)
        for name in names:
            self._edges.down(name)
            self._edges.up(name)

    # -- the frame ---------------------------------------------------------------------
    def end_frame(self) -> None:
        for finger in self.fingers.values():
            finger.phase = "moved"
        self.ended.clear()
        self.events.clear()
        self.drag_delta = self.drag_delta_world = (0.0, 0.0)
        self.pinch, self.rotation = 1.0, 0.0

    def reset(self) -> None:
        """Lift every finger silently and forget taps (focus lost, scene changed)."""
        self.fingers.clear()
        self._two, self._drag_from, self._dragging, self._tap_ok = None, None, False, False
        self._last_tap = (-math.inf, (0.0, 0.0), 0)
        self.end_frame()

    def deliver(self, emit: Callable[[object], None]) -> None:
        """Emit this frame's touch and gesture events (into the top scene's world)."""
        for ev in self.events:
            emit(ev)
