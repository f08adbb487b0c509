"""``Camera``: which part of the world the window shows, and how big.

World units are metres with y up; the screen is pixels with the origin at the
window's bottom-left (pyglet's convention). A camera maps one to the other:

    screen = (world - center) * pixels_per_meter * zoom + viewport / 2

so ``center`` is the world point at the middle of the window. ``zoom`` is
clamped to [0.1, 10] (a zoom of 0 would divide by zero in ``screen_to_world``).
The maths here is pure, so mouse picking and tests need no window.

Put a Camera on an entity (the lowest entity id with one is the active camera)
or insert one as a resource; without either the renderer uses a default one,
inserted as a resource so ``world.resource(Camera)`` can change it.

``follow=e`` keeps entity ``e`` in view: each frame the centre moves towards
the target's position, all the way when ``smoothing`` is 0, otherwise with that
time constant in seconds (``1 - exp(-dt / smoothing)`` of the way per frame, so
it behaves the same at any frame rate). ``bounds=(min_x, min_y, max_x, max_y)``
keeps the visible area inside the level. ``dead_zone=(w, h)`` (metres) lets the
target move inside a box around the centre without moving the camera (it moves
once the target leaves the box, by just enough); ``look_ahead`` (seconds) aims
ahead of a moving target by its velocity times that time.

>>> cam = Camera(center=(2.0, 1.0), pixels_per_meter=50, zoom=2)
>>> cam.world_to_screen((3.0, 1.0), (800, 600))
(500.0, 300.0)
>>> cam.screen_to_world((500.0, 300.0), (800, 600))
(3.0, 1.0)
>>> cam.zoom = 50; cam.zoom
10.0
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any, ClassVar

from kge.components.tracked import Check, Tracked
from kge.errors import ComponentTypeError, ValidationError
from kge.validate import Vec2, at_most, entity_id, finite, non_negative, positive, vec2

MIN_ZOOM = 0.1
MAX_ZOOM = 10.0
#: how far from the origin a camera may look, metres: a hundred times kge's world bound
#: (room for a shake or a look-ahead past it), far inside float32 screen maths
MAX_VIEW = 1e9
#: the range of ``pixels_per_meter``
MIN_PPM, MAX_PPM = 1e-3, 1e6
#: the longest ``look_ahead`` and ``smoothing``, seconds
MAX_SECONDS = 1e6

Bounds = tuple[float, float, float, float]


def _zoom(value: Any, owner: str, field: str) -> float:
    z = positive(value, owner, field)
    return min(max(z, MIN_ZOOM), MAX_ZOOM)


def _entity(value: Any, owner: str, field: str) -> int | None:
    if value is None:
        return None
    if isinstance(value, bool) or not isinstance(value, int):
        raise ComponentTypeError(f"{owner}.{field} must be an entity id or None, got {value!r}")
    return entity_id(value, owner, field)


def _view(value: float, owner: str, field: str) -> float:
    if not -MAX_VIEW <= value <= MAX_VIEW:
        raise ValidationError(
            f"{owner}.{field} must lie within {MAX_VIEW:g} m of the origin, got {value!r}"
        )
    return value


def _center(value: Any, owner: str, field: str) -> Vec2:
    x, y = vec2(value, owner, field)
    return (_view(x, owner, f"{field}[0]"), _view(y, owner, f"{field}[1]"))


def _ppm(value: Any, owner: str, field: str) -> float:
    v = positive(value, owner, field)
    if not MIN_PPM <= v <= MAX_PPM:
        raise ValidationError(f"{owner}.{field} must be in [{MIN_PPM:g}, {MAX_PPM:g}], got {v!r}")
    return v


def _seconds(value: Any, owner: str, field: str) -> float:
    return at_most(non_negative(value, owner, field), MAX_SECONDS, owner, field, "s")


def _dead_zone(value: Any, owner: str, field: str) -> Vec2:
    w, h = vec2(value, owner, field)
    non_negative(w, owner, f"{field}[0]")
    non_negative(h, owner, f"{field}[1]")
    return (_view(w, owner, f"{field}[0]"), _view(h, owner, f"{field}[1]"))


def _bounds(value: Any, owner: str, field: str) -> Bounds | None:
    if value is None:
        return None
    if not isinstance(value, (tuple, list)) or len(value) != 4:
        raise ComponentTypeError(f"{owner}.{field} must be (min_x, min_y, max_x, max_y)")
    x0, y0, x1, y1 = (
        _view(finite(v, owner, f"{field}[{i}]"), owner, f"{field}[{i}]")
        for i, v in enumerate(value)
    )
    if x1 <= x0 or y1 <= y0:
        raise ValidationError(f"{owner}.{field} must have min < max, got {value!r}")
    return (x0, y0, x1, y1)


@dataclass(slots=True)
class Camera(Tracked):
    """View of the world: centre (m), scale (px/m) and zoom. See the module docstring."""

    #: the followed entity must exist and have a Transform (checked by the render plugin)
    _world_fields: ClassVar[frozenset[str]] = frozenset({"follow"})

    _checks: ClassVar[dict[str, Check]] = {
        "center": _center,
        "pixels_per_meter": _ppm,
        "zoom": _zoom,
        "follow": _entity,
        "smoothing": _seconds,
        "bounds": _bounds,
        "dead_zone": _dead_zone,
        "look_ahead": _seconds,
    }

    center: Vec2 = (0.0, 0.0)
    pixels_per_meter: float = 64.0
    zoom: float = 1.0
    follow: int | None = None
    smoothing: float = 0.0
    bounds: Bounds | None = None
    dead_zone: Vec2 = (0.0, 0.0)
    look_ahead: float = 0.0

    @property
    def scale(self) -> float:
        """Pixels per metre on screen (``pixels_per_meter * zoom``)."""
        return self.pixels_per_meter * self.zoom

    def world_to_screen(self, point: Vec2, viewport: tuple[float, float]) -> Vec2:
        """World metres -> window pixels (origin bottom-left)."""
        k = self.scale
        return (
            (point[0] - self.center[0]) * k + viewport[0] / 2,
            (point[1] - self.center[1]) * k + viewport[1] / 2,
        )

    def screen_to_world(self, point: Vec2, viewport: tuple[float, float]) -> Vec2:
        """Window pixels (origin bottom-left) -> world metres."""
        k = self.scale
        return (
            (point[0] - viewport[0] / 2) / k + self.center[0],
            (point[1] - viewport[1] / 2) / k + self.center[1],
        )

    def view_rect(self, viewport: tuple[float, float]) -> Bounds:
        """The visible world rectangle ``(min_x, min_y, max_x, max_y)``."""
        hw, hh = viewport[0] / (2 * self.scale), viewport[1] / (2 * self.scale)
        cx, cy = self.center
        return (cx - hw, cy - hh, cx + hw, cy + hh)

    def clamped(self, center: Vec2, viewport: tuple[float, float] | None) -> Vec2:
        """``center`` moved so the view stays inside ``bounds`` (unchanged without bounds).

        A view larger than the bounds is centred on them.
        """
        if self.bounds is None:
            return center
        x0, y0, x1, y1 = self.bounds
        hw = hh = 0.0
        if viewport is not None:
            hw, hh = viewport[0] / (2 * self.scale), viewport[1] / (2 * self.scale)

        def clamp(c: float, lo: float, hi: float, half: float) -> float:
            if hi - lo <= 2 * half:
                return (lo + hi) / 2
            return min(max(c, lo + half), hi - half)

        return (clamp(center[0], x0, x1, hw), clamp(center[1], y0, y1, hh))

    def track(
        self,
        target: Vec2,
        dt: float,
        viewport: tuple[float, float] | None = None,
        velocity: Vec2 = (0.0, 0.0),
    ) -> None:
        """Move the centre towards ``target`` for a frame of ``dt`` seconds (follow logic).

        >>> cam = Camera(smoothing=0.5)
        >>> cam.track((10.0, 0.0), dt=0.5); round(cam.center[0], 3)
        6.321
        >>> cam = Camera(dead_zone=(4.0, 2.0))
        >>> cam.track((1.5, 0.5), dt=0.1); cam.center
        (0.0, 0.0)
        >>> cam.track((3.0, 0.0), dt=0.1); cam.center
        (1.0, 0.0)
        """
        aim = (
            clamp_view(target[0] + velocity[0] * self.look_ahead),
            clamp_view(target[1] + velocity[1] * self.look_ahead),
        )  # a body's velocity is only bounded by float64: the aim stays in view range
        hw, hh = self.dead_zone[0] / 2, self.dead_zone[1] / 2
        if hw > 0 or hh > 0:
            cx0, cy0 = self.center

            def edge(a: float, c: float, half: float) -> float:
                return a - half if a > c + half else a + half if a < c - half else c

            target = (edge(aim[0], cx0, hw), edge(aim[1], cy0, hh))
        else:
            target = aim
        if self.smoothing <= 0 or dt <= 0:
            k = 1.0 if self.smoothing <= 0 else 0.0
        else:
            k = 1.0 - math.exp(-dt / self.smoothing)
        cx, cy = self.center
        new = (cx + (target[0] - cx) * k, cy + (target[1] - cy) * k)
        self.center = self.clamped(new, viewport)


def clamp_view(value: float) -> float:
    """``value`` (finite or infinite, not NaN) within +-:data:`MAX_VIEW`."""
    return min(max(value, -MAX_VIEW), MAX_VIEW)


def active_camera(world: Any) -> Camera | None:
    """The camera a world is seen through: the lowest entity id with a Camera, else the
    Camera resource, else None (the App then uses a default camera)."""
    cams = world.query(Camera)
    if cams:
        cam: Camera = min(cams, key=lambda item: item[0])[1][0]
        return cam
    found: Camera | None = world.try_resource(Camera)
    return found
