"""``Camera``: which part of the world a view shows, where, how big and turned how.

World units are metres with y up; the screen is pixels with the origin at the
window's bottom-left (pyglet's convention; with a ``Resolution`` resource, design
pixels). A camera maps one to the other:

    screen = R(-rotation) (world - center) * pixels_per_meter * zoom + viewport centre

so ``center`` is the world point at the middle of the camera's viewport and a
positive ``rotation`` turns the camera counter-clockwise (the world turns the other
way on screen). ``zoom`` is
clamped to [0.1, 10] (a zoom of 0 would divide by zero in ``screen_to_world``).
The maths here is pure, so mouse picking and tests need no window.

Put a Camera on an entity (the lowest entity id with one is the active camera)
or insert one as a resource; without either the renderer uses a default one,
inserted as a resource so ``world.resource(Camera)`` can change it.

Several cameras: every enabled Camera entity draws, in ``order``. ``viewport`` is
its rectangle in the window as fractions ``(x, y, w, h)`` from the bottom-left (split
screen: two halves; a minimap: a corner), ``layers`` the layers it draws (None: all),
``background`` the colour it clears its viewport to first (None: it draws over what
is there), ``target="name"`` draws into a texture a Sprite shows with
``RenderTexture("name")`` instead of the window, and ``post`` is its post-processing
stack (:mod:`kge.components.post`). Screen-space text and UI are drawn once, over
all cameras. The mouse maps through the camera whose viewport is under it.

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
>>> turned = Camera(rotation=math.pi / 2, pixels_per_meter=10)
>>> [round(v, 6) for v in turned.world_to_screen((1.0, 0.0), (100, 100))]
[50.0, 40.0]
>>> Camera(viewport=(0.5, 0.0, 0.6, 1.0))
Traceback (most recent call last):
...
kge.errors.ValidationError: Camera.viewport (0.5, 0.0, 0.6, 1.0) must lie inside the window: ...
"""

from __future__ import annotations

import math
from collections.abc import Collection
from dataclasses import dataclass
from typing import Any, ClassVar

from kge.components.color import RGBA, Color, rgba
from kge.components.material import Material
from kge.components.post import PostEffect
from kge.components.tracked import Check, Tracked
from kge.errors import ComponentTypeError, ValidationError
from kge.validate import (
    Vec2,
    at_most,
    boolean,
    entity_id,
    finite,
    integer,
    non_negative,
    positive,
    vec2,
)

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
Viewport = tuple[float, float, float, float]
FULL: Viewport = (0.0, 0.0, 1.0, 1.0)
#: the largest texture a camera may draw into, pixels per side
MAX_TARGET = 8192


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


def _viewport(value: Any, owner: str, field: str) -> Viewport:
    if not isinstance(value, (tuple, list)) or len(value) != 4:
        raise ComponentTypeError(f"{owner}.{field} must be (x, y, w, h) fractions, got {value!r}")
    x, y, w, h = (finite(v, owner, f"{field}[{i}]") for i, v in enumerate(value))
    eps = 1e-9
    if x < 0 or y < 0 or w <= 0 or h <= 0 or x + w > 1 + eps or y + h > 1 + eps:
        raise ValidationError(
            f"{owner}.{field} {tuple(value)!r} must lie inside the window: (x, y, w, h) fractions "
            "with w, h > 0 and x + w <= 1, y + h <= 1"
        )
    return (x, y, w, h)


def _layers(value: Any, owner: str, field: str) -> tuple[int, ...] | None:
    if value is None:
        return None
    if isinstance(value, (str, bytes)) or not hasattr(value, "__iter__"):
        raise ComponentTypeError(f"{owner}.{field} must be None or layer numbers, got {value!r}")
    return tuple(sorted({integer(v, owner, f"{field}[]") for v in value}))


def _target(value: Any, owner: str, field: str) -> str | None:
    if value is None:
        return None
    if not isinstance(value, str) or not value:
        raise ComponentTypeError(f"{owner}.{field} must be None or a texture name, got {value!r}")
    return value


def _target_size(value: Any, owner: str, field: str) -> tuple[int, int] | None:
    if value is None:
        return None
    if not isinstance(value, (tuple, list)) or len(value) != 2:
        raise ComponentTypeError(f"{owner}.{field} must be None or (width, height) pixels")
    w, h = (integer(v, owner, f"{field}[{i}]") for i, v in enumerate(value))
    if not (1 <= w <= MAX_TARGET and 1 <= h <= MAX_TARGET):
        raise ValidationError(
            f"{owner}.{field} must be 1..{MAX_TARGET} pixels a side, got {value!r}"
        )
    return (w, h)


def _background(value: Any, owner: str, field: str) -> RGBA | None:
    return None if value is None else rgba(value, owner, field)


def _post(value: Any, owner: str, field: str) -> tuple[Any, ...]:
    if isinstance(value, (PostEffect, Material)):
        value = (value,)
    if not isinstance(value, (tuple, list)):
        raise ComponentTypeError(f"{owner}.{field} must be a tuple of post effects, got {value!r}")
    for i, effect in enumerate(value):
        if not isinstance(effect, (PostEffect, Material)):
            raise ComponentTypeError(
                f"{owner}.{field}[{i}] must be a post effect (Bloom, ColorGrade, Vignette, CRT) "
                f"or a Material, got {effect!r}"
            )
    return tuple(value)


def _int(value: Any, owner: str, field: str) -> int:
    return integer(value, owner, field)


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
        "rotation": finite,
        "viewport": _viewport,
        "layers": _layers,
        "order": _int,
        "target": _target,
        "target_size": _target_size,
        "background": _background,
        "post": _post,
        "enabled": boolean,
    }

    center: Vec2 = (0.0, 0.0)
    pixels_per_meter: float = 64.0
    zoom: float = 1.0
    follow: int | None = None
    smoothing: float = 0.0
    bounds: Bounds | None = None
    dead_zone: Vec2 = (0.0, 0.0)
    look_ahead: float = 0.0
    #: radians counter-clockwise the camera is turned (the world turns the other way)
    rotation: float = 0.0
    #: (x, y, w, h) of the window, as fractions from the bottom-left
    viewport: Viewport = FULL
    #: the layers this camera draws (None: every layer); any ints, kept as a sorted tuple
    layers: Collection[int] | None = None
    #: cameras draw in ascending order (ties: entity id)
    order: int = 0
    #: draw into the texture of this name (``RenderTexture(name)``) instead of the window
    target: str | None = None
    #: that texture's size in pixels (None: the viewport's size in the window)
    target_size: tuple[int, int] | None = None
    #: RGB(A) the viewport is cleared to before drawing (None: draw over what is there)
    background: Color | None = None
    #: post-processing passes, in order (:mod:`kge.components.post`)
    post: tuple[Any, ...] = ()
    enabled: bool = True

    @property
    def scale(self) -> float:
        """Pixels per metre on screen (``pixels_per_meter * zoom``)."""
        return self.pixels_per_meter * self.zoom

    def rect(self, canvas: tuple[float, float]) -> Bounds:
        """The camera's viewport in canvas pixels: (x, y, width, height)."""
        if self.target is not None:
            w, h = self.target_size or (canvas[0] * self.viewport[2], canvas[1] * self.viewport[3])
            return (0.0, 0.0, float(w), float(h))
        x, y, w, h = self.viewport
        return (x * canvas[0], y * canvas[1], w * canvas[0], h * canvas[1])

    def world_to_screen(self, point: Vec2, viewport: tuple[float, float]) -> Vec2:
        """World metres -> window pixels (origin bottom-left); ``viewport`` is the
        window's (or design resolution's) size."""
        x, y, w, h = self.rect(viewport)
        k = self.scale
        dx, dy = (point[0] - self.center[0]) * k, (point[1] - self.center[1]) * k
        if self.rotation:
            c, s = math.cos(self.rotation), math.sin(self.rotation)
            dx, dy = c * dx + s * dy, -s * dx + c * dy
        return (x + w / 2 + dx, y + h / 2 + dy)

    def screen_to_world(self, point: Vec2, viewport: tuple[float, float]) -> Vec2:
        """Window pixels (origin bottom-left) -> world metres."""
        x, y, w, h = self.rect(viewport)
        k = self.scale
        dx, dy = (point[0] - x - w / 2) / k, (point[1] - y - h / 2) / k
        if self.rotation:
            c, s = math.cos(self.rotation), math.sin(self.rotation)
            dx, dy = c * dx - s * dy, s * dx + c * dy
        return (dx + self.center[0], dy + self.center[1])

    def half_extents(self, viewport: tuple[float, float]) -> Vec2:
        """Half the width and height of the world area seen, axis-aligned (metres)."""
        _, _, w, h = self.rect(viewport)
        hw, hh = w / (2 * self.scale), h / (2 * self.scale)
        if self.rotation:
            c, s = abs(math.cos(self.rotation)), abs(math.sin(self.rotation))
            hw, hh = c * hw + s * hh, s * hw + c * hh
        return (hw, hh)

    def view_rect(self, viewport: tuple[float, float]) -> Bounds:
        """The visible world rectangle ``(min_x, min_y, max_x, max_y)`` (its bounding box
        when the camera is turned)."""
        hw, hh = self.half_extents(viewport)
        cx, cy = self.center
        return (cx - hw, cy - hh, cx + hw, cy + hh)

    def contains(self, point: Vec2, canvas: tuple[float, float]) -> bool:
        """Whether canvas pixel ``point`` is inside this camera's viewport in the window."""
        if self.target is not None:
            return False
        x, y, w, h = self.rect(canvas)
        return x <= point[0] < x + w and y <= point[1] < y + h

    def clamped(self, center: Vec2, viewport: tuple[float, float] | None) -> Vec2:
        """``center`` moved so the view stays inside ``bounds`` (unchanged without bounds).

        A view larger than the bounds is centred on them.
        """
        if self.bounds is None:
            return center
        x0, y0, x1, y1 = self.bounds
        hw = hh = 0.0
        if viewport is not None:
            hw, hh = self.half_extents(viewport)

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


def cameras(world: Any) -> list[tuple[int, Camera]]:
    """The enabled cameras that draw, in drawing order: texture targets first, then by
    ``order`` and entity id; the Camera resource (entity -1) when no entity has one."""
    found = [(e, c) for e, (c,) in world.query(Camera) if c.enabled]
    if not found and not world.query(Camera):
        res = world.try_resource(Camera)
        if res is not None:
            found = [(-1, res)]
    return sorted(found, key=lambda ec: (ec[1].target is None, ec[1].order, ec[0]))


def camera_at(world: Any, point: Vec2, canvas: tuple[float, float]) -> Camera | None:
    """The camera whose viewport is under canvas pixel ``point``: the one drawn last
    there; else the active camera."""
    under = [c for _, c in cameras(world) if c.contains(point, canvas)]
    return under[-1] if under else active_camera(world)


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
