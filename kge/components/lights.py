"""2D lights: ``Light`` (point or spot), ``DirectionalLight``, ``ShadowCaster`` and ``Lighting``.

A scene with a :class:`Lighting` resource is drawn lit: every layer below
``Lighting.unlit_layer`` is multiplied by a *light map*, the ``ambient`` colour
plus the light of every :class:`Light` (added up, clamped to white). Layers
from ``unlit_layer`` up are drawn after the multiply, unlit: UI, emissive
sprites, glowing particles.

* ``Light``: at the entity's pose (plus ``offset``), ``color`` (RGB 0-255) times
  ``intensity``, reaching ``radius`` metres with ``falloff`` (the exponent of
  ``(1 - d / radius)``: 0 a hard disc, 1 linear, 2 a soft glow). A ``cone`` below
  2 pi makes a spot light pointing along the entity's angle plus ``direction``;
  ``softness`` (0..1) is the share of the cone's half-angle that fades out at its
  edges. ``shadows=True``: colliders block it; ``shadow_softness`` (metres, the
  size of the light's bulb) gives the shadows soft edges (0: hard, still
  anti-aliased); ``shadow_color`` is light it still casts into its shadows (coloured
  shade). ``texture`` is a *cookie*: an image the light is multiplied by, stretched
  over its radius and turned with it (a window frame, a flashlight's ring).
  ``glow`` draws a halo of the light's colour over the scene (a lamp that looks
  bright even against black). ``height`` (metres above the scene) sets the angle it
  lights normal-mapped sprites at.
* ``DirectionalLight``: sunlight or moonlight over the whole view, travelling along
  ``angle``; its shadows are parallel, ``shadow_softness`` (radians) their spread.
* Shadows are cast by static colliders (``Lighting.static_shadows``, on by
  default) and by any entity carrying :class:`ShadowCaster` (moving bodies: their
  shadows move with them). No extra authoring: the colliders' shapes are the
  occluders.

>>> Light(radius=4.0, color=(255, 200, 120)).cone == TAU
True
>>> Light(radius=0.0)
Traceback (most recent call last):
...
kge.errors.ValidationError: Light.radius must be > 0, got 0.0
>>> Light(cone=7.0)
Traceback (most recent call last):
...
kge.errors.ValidationError: Light.cone must be in [0.0, 6.283185307179586], got 7.0
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any, ClassVar

from kge.components.color import RGB, rgb
from kge.components.tracked import Check, Tracked
from kge.errors import ValidationError
from kge.validate import Vec2, boolean, finite, in_range, integer, non_negative, point

TAU = 2.0 * math.pi
#: the brightest a light may be (intensity multiplies its colour)
MAX_INTENSITY = 100.0
#: the largest light radius, metres
MAX_RADIUS = 1e5


def _radius(value: Any, owner: str, field: str) -> float:
    v = finite(value, owner, field)
    if v <= 0:
        raise ValidationError(f"{owner}.{field} must be > 0, got {v!r}")
    if v > MAX_RADIUS:
        raise ValidationError(f"{owner}.{field} must be <= {MAX_RADIUS:g} m, got {v!r}")
    return v


def _intensity(value: Any, owner: str, field: str) -> float:
    return in_range(value, 0.0, MAX_INTENSITY, owner, field)


def _falloff(value: Any, owner: str, field: str) -> float:
    return in_range(value, 0.0, 16.0, owner, field)


def _softness_size(value: Any, owner: str, field: str) -> float:
    v = non_negative(value, owner, field)
    if v > MAX_RADIUS:
        raise ValidationError(f"{owner}.{field} must be <= {MAX_RADIUS:g} m, got {v!r}")
    return v


def _cone(value: Any, owner: str, field: str) -> float:
    return in_range(value, 0.0, TAU, owner, field)


def _cookie(value: Any, owner: str, field: str) -> Any:
    if value is None:
        return None
    if isinstance(value, (int, float, bool, bytes, tuple, list)):
        raise ValidationError(f"{owner}.{field} must be None, an asset name or an image")
    return value


def _glow(value: Any, owner: str, field: str) -> float:
    return in_range(value, 0.0, 10.0, owner, field)


def _height(value: Any, owner: str, field: str) -> float:
    return in_range(value, 0.01, MAX_RADIUS, owner, field)


def _spread(value: Any, owner: str, field: str) -> float:
    return in_range(value, 0.0, 0.5, owner, field)


def _resolution(value: Any, owner: str, field: str) -> float:
    return in_range(value, 0.1, 1.0, owner, field)


def _unit(value: Any, owner: str, field: str) -> float:
    return in_range(value, 0.0, 1.0, owner, field)


@dataclass(slots=True)
class Light(Tracked):
    """A point or spot light at the entity. See the module docstring."""

    #: a cookie image named by file is looked up by the lighting plugin (spawn and write)
    _world_fields: ClassVar[frozenset[str]] = frozenset({"texture"})

    _checks: ClassVar[dict[str, Check]] = {
        "color": rgb,
        "intensity": _intensity,
        "radius": _radius,
        "falloff": _falloff,
        "cone": _cone,
        "direction": finite,
        "softness": _unit,
        "shadows": boolean,
        "shadow_softness": _softness_size,
        "offset": point,
        "enabled": boolean,
        "shadow_color": rgb,
        "texture": _cookie,
        "glow": _glow,
        "height": _height,
    }

    color: RGB = (255, 255, 255)
    intensity: float = 1.0
    radius: float = 5.0
    falloff: float = 1.5
    cone: float = TAU
    direction: float = 0.0
    softness: float = 0.2
    shadows: bool = False
    shadow_softness: float = 0.0
    offset: Vec2 = (0.0, 0.0)
    enabled: bool = True
    #: colour the light still casts into its own shadows (black: none)
    shadow_color: RGB = (0, 0, 0)
    #: an image multiplying the light, over its radius, turned with it (None: none)
    texture: Any = None
    #: strength of a halo of the light's colour drawn over the scene (0: none)
    glow: float = 0.0
    #: metres above the scene, for normal-mapped sprites
    height: float = 1.0

    @property
    def is_spot(self) -> bool:
        return self.cone < TAU


@dataclass(slots=True)
class DirectionalLight(Tracked):
    """Light over the whole view from far away (sun, moon), travelling along ``angle``
    (radians counter-clockwise; -pi/2 shines straight down). See the module docstring."""

    _checks: ClassVar[dict[str, Check]] = {
        "color": rgb,
        "intensity": _intensity,
        "angle": finite,
        "shadows": boolean,
        "shadow_softness": _spread,
        "shadow_color": rgb,
        "height": _height,
        "enabled": boolean,
    }

    color: RGB = (255, 255, 255)
    intensity: float = 1.0
    angle: float = -math.pi / 2
    shadows: bool = False
    #: half the angle the light comes from, radians (0: razor-sharp shadows)
    shadow_softness: float = 0.0
    shadow_color: RGB = (0, 0, 0)
    #: how steeply it falls on normal-mapped sprites (metres up per metre across)
    height: float = 1.0
    enabled: bool = True


@dataclass(slots=True)
class ShadowCaster(Tracked):
    """Marks an entity whose colliders block shadowed lights (dynamic ones included).

    On a body entity it covers every collider of that body; on a collider entity,
    that collider.
    """

    _checks: ClassVar[dict[str, Check]] = {"enabled": boolean}

    enabled: bool = True


def _layer(value: Any, owner: str, field: str) -> int:
    return integer(value, owner, field)


@dataclass(slots=True)
class Lighting(Tracked):
    """The world's lighting settings (a resource): ambient colour, on/off, unlit layers.

    ``ambient`` is what an unlit corner looks like ((0, 0, 0): black night;
    (255, 255, 255): lights change nothing). ``unlit_layer``: layers at or above
    it are drawn after the light map, unlit. ``static_shadows``: static
    colliders block shadowed lights. ``resolution``: the light map's pixels per
    view pixel (0.1..1; 1 for crisp normal-mapped detail).
    """

    _checks: ClassVar[dict[str, Check]] = {
        "ambient": rgb,
        "enabled": boolean,
        "unlit_layer": _layer,
        "static_shadows": boolean,
        "resolution": _resolution,
    }

    ambient: RGB = (40, 40, 60)
    enabled: bool = True
    unlit_layer: int = 100
    static_shadows: bool = True
    #: the light map's size as a share of the view's pixels (it is smooth: half is plenty)
    resolution: float = 0.5
