"""2D lights: ``Light`` (point or spot), ``ShadowCaster`` and the ``Lighting`` resource.

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
  size of the light's bulb) gives the shadows soft edges (0: hard).
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


def _unit(value: Any, owner: str, field: str) -> float:
    return in_range(value, 0.0, 1.0, owner, field)


@dataclass(slots=True)
class Light(Tracked):
    """A point or spot light at the entity. See the module docstring."""

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

    @property
    def is_spot(self) -> bool:
        return self.cone < TAU


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
    colliders block shadowed lights.
    """

    _checks: ClassVar[dict[str, Check]] = {
        "ambient": rgb,
        "enabled": boolean,
        "unlit_layer": _layer,
        "static_shadows": boolean,
    }

    ambient: RGB = (40, 40, 60)
    enabled: bool = True
    unlit_layer: int = 100
    static_shadows: bool = True
