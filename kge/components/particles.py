"""``ParticleEmitter``: how an entity sprays particles (pure data).

The particles themselves are not entities: the particle system keeps each
emitter's particles in numpy arrays (see :mod:`kge.particles`) and draws them
with one vertex list per emitter. This component only says *how* to make and
move them, in metres, seconds and radians:

* **when**: ``rate`` per second and/or ``rate_per_meter`` travelled while
  ``emitting``; ``burst`` particles at once when the emitter starts; a
  ``duration`` after which emission stops; ``one_shot`` despawns the entity
  once it has stopped emitting and its last particle died; ``prewarm`` seconds
  simulated at spawn (a fire that is already burning).
* **where**: ``shape``, one of :class:`EmitPoint`, :class:`EmitCircle`,
  :class:`EmitBox`, :class:`EmitLine` or :class:`EmitCollider` (the entity's own
  collider), in the entity frame, shifted by ``offset``.
* **how they move**: ``lifetime`` and ``speed`` ranges, ``direction`` (rad, in the
  entity frame) with a ``spread`` cone (full angle, 0..2pi), ``inherit_velocity``
  (share of the body's velocity), ``acceleration`` (gravity, m/s^2), linear
  ``drag`` (1/s), ``spin`` range (rad/s); around the emitter's origin (the entity
  plus ``offset``): ``radial_acceleration`` (m/s^2, + outward: a burst that slows,
  - inward: a vortex), ``tangential_acceleration`` (m/s^2, + counter-clockwise: a
  swirl) and ``orbit`` (rad/s, carries particles round it); and ``collide`` with
  static colliders
  (:class:`ParticleCollision`: ``NONE``, ``BOUNCE`` with ``bounciness``, or ``DIE``).
* **how they look**: ``size`` (metres), ``color`` (RGB 0-255) and ``opacity``
  (0-255, as ``Sprite.opacity``) over life, each a single value or a sequence of
  evenly spaced keys interpolated linearly from birth to death; ``texture`` (None:
  a generated soft dot; else an asset name or image) or ``flat`` squares; ``blend``
  (:class:`~kge.components.blend.Blend`, as for sprites); ``space``
  (:class:`ParticleSpace`: ``WORLD``, particles stay where they were born, or
  ``LOCAL``, they move with the entity); ``layer`` / ``order`` as sprites.
* ``max_particles`` caps the live count: further particles are dropped, the
  arrays never grow past it. ``seed`` makes the emitter deterministic (the same
  seed gives the same particles); None derives one from the entity id.

>>> e = ParticleEmitter(rate=50.0, lifetime=(0.5, 1.0), color=((255, 255, 0), (255, 0, 0)))
>>> e.size, e.spread
((0.1,), 0.0)
>>> ParticleEmitter(rate=float("nan"))
Traceback (most recent call last):
...
kge.errors.ValidationError: ParticleEmitter.rate must be finite, got nan
>>> ParticleEmitter(spread=7.0)
Traceback (most recent call last):
...
kge.errors.ValidationError: ParticleEmitter.spread must be in [0.0, 6.283185307179586], got 7.0
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from enum import StrEnum
from typing import Any, ClassVar, cast

from kge.components.blend import Blend
from kge.components.color import RGB, rgb
from kge.components.tracked import Check, Tracked
from kge.deprecation import renamed_fields
from kge.errors import ComponentTypeError, ValidationError
from kge.validate import (
    Vec2,
    boolean,
    choice,
    entity_id,
    finite,
    in_range,
    integer,
    non_negative,
    point,
    positive,
    vec2,
)

TAU = 2.0 * math.pi
#: the largest magnitude of speeds (m/s), accelerations (m/s^2), spins (rad/s), drag
#: (1/s), lifetimes (s) and sizes (m): particles are float32, and larger values would
#: overflow them to infinity within a few frames
LIMIT = 1e6
#: the largest ``max_particles`` an emitter may ask for (arrays are allocated up to it)
MAX_PARTICLES = 1_000_000


class ParticleSpace(StrEnum):
    """Where particles live once born."""

    WORLD = "world"  #: they stay where they were born (smoke trails)
    LOCAL = "local"  #: they move with the emitter's entity (a jet flame)


class ParticleCollision(StrEnum):
    """What particles do when they reach a static collider."""

    NONE = "none"  #: pass through
    BOUNCE = "bounce"  #: bounce, keeping ``bounciness`` of their speed
    DIE = "die"  #: vanish


BLENDS = tuple(Blend)
SPACES = tuple(ParticleSpace)
COLLIDE = tuple(ParticleCollision)


# -- emission shapes (immutable values) --------------------------------------------------


@dataclass(slots=True, frozen=True)
class EmitPoint:
    """Every particle starts at the emitter's origin."""


@dataclass(slots=True, frozen=True)
class EmitCircle:
    """Uniformly inside a disc of ``radius`` (or on its rim with ``edge=True``)."""

    radius: float
    edge: bool = False

    def __post_init__(self) -> None:
        _extent(self.radius, "EmitCircle", "radius")
        boolean(self.edge, "EmitCircle", "edge")


@dataclass(slots=True, frozen=True)
class EmitBox:
    """Uniformly inside a ``width`` x ``height`` rectangle centred on the origin."""

    width: float
    height: float

    def __post_init__(self) -> None:
        _extent(self.width, "EmitBox", "width")
        _extent(self.height, "EmitBox", "height")


@dataclass(slots=True, frozen=True)
class EmitLine:
    """Uniformly along the segment ``start`` - ``end`` (entity frame)."""

    start: Vec2
    end: Vec2

    def __post_init__(self) -> None:
        object.__setattr__(self, "start", _vector(self.start, "EmitLine", "start"))
        object.__setattr__(self, "end", _vector(self.end, "EmitLine", "end"))


@dataclass(slots=True, frozen=True)
class EmitCollider:
    """Inside the entity's own collider shape (circle, box, polygon; along edges/chains)."""


#: what a range field accepts: one number or (low, high); it always holds the pair
Range = tuple[float, float] | float

EmitShape = EmitPoint | EmitCircle | EmitBox | EmitLine | EmitCollider
EMIT_SHAPES: tuple[type, ...] = (EmitPoint, EmitCircle, EmitBox, EmitLine, EmitCollider)


# -- field checks ------------------------------------------------------------------------


def span(value: Range) -> tuple[float, float]:
    """A range field as its (low, high) pair (fields hold the pair once validated)."""
    return (value, value) if isinstance(value, (int, float)) else value


def _limited(v: float, owner: str, field: str) -> float:
    if abs(v) > LIMIT:
        raise ValidationError(f"{owner}.{field} must be within +-{LIMIT:g}, got {v!r}")
    return v


def _extent(value: Any, owner: str, field: str) -> float:
    """A size of an emission shape: metres in (0, LIMIT]."""
    return _limited(positive(value, owner, field), owner, field)


def _range(value: Any, owner: str, field: str) -> Vec2:
    """A (low, high) pair of finite numbers, or one number meaning (v, v)."""
    if isinstance(value, (int, float)) and not isinstance(value, bool):
        v = _limited(finite(value, owner, field), owner, field)
        return (v, v)
    lo, hi = vec2(value, owner, field)
    _limited(lo, owner, field)
    _limited(hi, owner, field)
    if lo > hi:
        raise ValidationError(
            f"{owner}.{field} must be (low, high) with low <= high, got {value!r}"
        )
    return (lo, hi)


def _non_negative_range(value: Any, owner: str, field: str) -> Vec2:
    lo, hi = _range(value, owner, field)
    if lo < 0:
        raise ValidationError(f"{owner}.{field} must be >= 0, got {value!r}")
    return (lo, hi)


def _lifetime(value: Any, owner: str, field: str) -> Vec2:
    lo, hi = _range(value, owner, field)
    if lo <= 0:
        raise ValidationError(f"{owner}.{field} must be > 0 seconds, got {value!r}")
    return (lo, hi)


def _keys(value: Any, owner: str, field: str) -> list[Any]:
    if isinstance(value, (str, bytes)) or not isinstance(value, Sequence):
        raise ComponentTypeError(f"{owner}.{field} must be a value or a sequence of keys")
    if not 1 <= len(value) <= 64:
        raise ValidationError(f"{owner}.{field} needs 1..64 keys, got {len(value)}")
    return list(value)


def _size(value: Any, owner: str, field: str) -> float:
    return _limited(non_negative(value, owner, field), owner, field)


def _sizes(value: Any, owner: str, field: str) -> tuple[float, ...]:
    """Size over life: one size or evenly spaced keys, metres >= 0."""
    if isinstance(value, (int, float)) and not isinstance(value, bool):
        return (_size(value, owner, field),)
    return tuple(_size(v, owner, f"{field}[{i}]") for i, v in enumerate(_keys(value, owner, field)))


def _opacities(value: Any, owner: str, field: str) -> tuple[float, ...]:
    """Opacity over life: one value or evenly spaced keys in 0..255 (as Sprite.opacity)."""
    if isinstance(value, (int, float)) and not isinstance(value, bool):
        return (in_range(value, 0.0, 255.0, owner, field),)
    return tuple(
        in_range(v, 0.0, 255.0, owner, f"{field}[{i}]")
        for i, v in enumerate(_keys(value, owner, field))
    )


def _alpha_to_opacity(alpha: Any) -> Any:
    """The deprecated ``alpha`` (0..1) as an ``opacity`` (0..255), checked as alpha was."""
    keys = _keys_of(alpha)
    for i, a in enumerate(keys):
        in_range(a, 0.0, 1.0, "ParticleEmitter", f"alpha[{i}]" if len(keys) > 1 else "alpha")
    return tuple(float(a) * 255.0 for a in keys)


def _opacity_to_alpha(opacity: tuple[float, ...]) -> tuple[float, ...]:
    return tuple(o / 255.0 for o in opacity)


def _keys_of(value: Any) -> tuple[Any, ...]:
    if isinstance(value, (int, float)) and not isinstance(value, bool):
        return (value,)
    return tuple(_keys(value, "ParticleEmitter", "alpha"))


def _colors(value: Any, owner: str, field: str) -> tuple[RGB, ...]:
    """Colour over life: one RGB or evenly spaced RGB keys (ints 0-255)."""
    if (
        isinstance(value, Sequence)
        and not isinstance(value, (str, bytes))
        and len(value) == 3
        and all(isinstance(c, int) for c in value)
    ):
        return (rgb(value, owner, field),)
    return tuple(rgb(v, owner, f"{field}[{i}]") for i, v in enumerate(_keys(value, owner, field)))


def _shape(value: Any, owner: str, field: str) -> EmitShape:
    if not isinstance(value, EMIT_SHAPES):
        names = ", ".join(t.__name__ for t in EMIT_SHAPES)
        raise ComponentTypeError(f"{owner}.{field} must be one of {names}, got {value!r}")
    return cast(EmitShape, value)


def _max_particles(value: Any, owner: str, field: str) -> int:
    n = integer(value, owner, field)
    if not 1 <= n <= MAX_PARTICLES:
        raise ValidationError(f"{owner}.{field} must be in 1..{MAX_PARTICLES}, got {n}")
    return n


def _count(value: Any, owner: str, field: str) -> int:
    n = integer(value, owner, field)
    if not 0 <= n <= MAX_PARTICLES:
        raise ValidationError(f"{owner}.{field} must be in 0..{MAX_PARTICLES}, got {n}")
    return n


def _texture(value: Any, owner: str, field: str) -> Any:
    if value is None:
        return None
    if isinstance(value, (int, float, bool, bytes)):
        raise ComponentTypeError(
            f"{owner}.{field} must be None (soft dot), an asset name or an image, got {value!r}"
        )
    if isinstance(value, str) and not value:
        raise ValidationError(f"{owner}.{field} must not be an empty string")
    return value


def _optional_duration(value: Any, owner: str, field: str) -> float | None:
    return None if value is None else positive(value, owner, field)


def _seed(value: Any, owner: str, field: str) -> int | None:
    if value is None:
        return None
    n = integer(value, owner, field)
    if n < 0:
        raise ValidationError(f"{owner}.{field} must be >= 0, got {n}")
    return n


def _spread(value: Any, owner: str, field: str) -> float:
    return in_range(value, 0.0, TAU, owner, field)


def _unit(value: Any, owner: str, field: str) -> float:
    return in_range(value, 0.0, 1.0, owner, field)


def _prewarm(value: Any, owner: str, field: str) -> float:
    return in_range(value, 0.0, 60.0, owner, field)


def _int(value: Any, owner: str, field: str) -> int:
    return integer(value, owner, field)


def _vector(value: Any, owner: str, field: str) -> Vec2:
    x, y = vec2(value, owner, field)
    return (_limited(x, owner, f"{field}[0]"), _limited(y, owner, f"{field}[1]"))


def _limited_float(value: Any, owner: str, field: str) -> float:
    return _limited(finite(value, owner, field), owner, field)


def _drag(value: Any, owner: str, field: str) -> float:
    return _limited(non_negative(value, owner, field), owner, field)


def _inherit(value: Any, owner: str, field: str) -> float:
    return in_range(value, -100.0, 100.0, owner, field)


def _rate(value: Any, owner: str, field: str) -> float:
    v = non_negative(value, owner, field)
    if v > 1e7:
        raise ValidationError(f"{owner}.{field} must be <= 1e7 particles per unit, got {v!r}")
    return v


@renamed_fields(
    rate_per_metre=("rate_per_meter", None, None),  # one spelling: pixels_per_meter
    alpha=("opacity", _alpha_to_opacity, _opacity_to_alpha),  # 0-255 as Sprite.opacity
)
@dataclass(slots=True)
class ParticleEmitter(Tracked):
    """Sprays particles from the entity. See the module docstring."""

    #: a texture name is looked up in the world's asset store at every write
    _world_fields: ClassVar[frozenset[str]] = frozenset({"texture"})

    _checks: ClassVar[dict[str, Check]] = {
        "rate": _rate,
        "rate_per_meter": _rate,
        "burst": _count,
        "emitting": boolean,
        "duration": _optional_duration,
        "one_shot": boolean,
        "prewarm": _prewarm,
        "shape": _shape,
        "offset": _vector,
        "lifetime": _lifetime,
        "speed": _non_negative_range,
        "direction": finite,
        "spread": _spread,
        "inherit_velocity": _inherit,
        "acceleration": _vector,
        "drag": _drag,
        "radial_acceleration": _limited_float,
        "tangential_acceleration": _limited_float,
        "orbit": _limited_float,
        "spin": _range,
        "size": _sizes,
        "color": _colors,
        "opacity": _opacities,
        "texture": _texture,
        "flat": boolean,
        "blend": choice(Blend),
        "space": choice(ParticleSpace),
        "collide": choice(ParticleCollision),
        "bounciness": _unit,
        "max_particles": _max_particles,
        "seed": _seed,
        "layer": _int,
        "order": _int,
        "visible": boolean,
    }

    rate: float = 0.0
    rate_per_meter: float = 0.0
    burst: int = 0
    emitting: bool = True
    duration: float | None = None
    one_shot: bool = False
    prewarm: float = 0.0
    shape: EmitShape = EmitPoint()
    offset: Vec2 = (0.0, 0.0)
    lifetime: Range = (1.0, 1.0)
    speed: Range = (1.0, 1.0)
    direction: float = math.pi / 2
    spread: float = 0.0
    inherit_velocity: float = 0.0
    acceleration: Vec2 = (0.0, 0.0)
    drag: float = 0.0
    spin: Range = (0.0, 0.0)
    size: Sequence[float] | float = (0.1,)
    color: Sequence[Any] = ((255, 255, 255),)
    opacity: Sequence[float] | float = (255.0,)
    texture: Any = None
    flat: bool = False
    blend: Blend = Blend.ALPHA
    space: ParticleSpace = ParticleSpace.WORLD
    collide: ParticleCollision = ParticleCollision.NONE
    bounciness: float = 0.5
    max_particles: int = 2000
    seed: int | None = None
    layer: int = 0
    order: int = 0
    visible: bool = True
    radial_acceleration: float = 0.0  #: m/s^2 away from the origin (< 0: towards it)
    tangential_acceleration: float = 0.0  #: m/s^2 counter-clockwise round the origin
    orbit: float = 0.0  #: rad/s: particles are carried round the origin


@dataclass(slots=True, frozen=True)
class ParticleBurst:
    """An event: burst ``count`` particles from ``emitter`` (``world.emit(ParticleBurst(...))``).

    ``position`` (world metres) and ``direction`` (radians) override the
    emitter's own origin and direction for this burst only: sparks at a contact
    point along its normal.
    """

    emitter: int
    count: int
    position: Vec2 | None = None
    direction: float | None = None

    def __post_init__(self) -> None:
        entity_id(self.emitter, "ParticleBurst", "emitter")
        _count(self.count, "ParticleBurst", "count")
        if self.position is not None:
            object.__setattr__(self, "position", point(self.position, "ParticleBurst", "position"))
        if self.direction is not None:
            object.__setattr__(
                self, "direction", finite(self.direction, "ParticleBurst", "direction")
            )


@renamed_fields(min_speed=("hit_threshold", None, None))  # one name for one speed
@dataclass(slots=True)
class BurstOnHit(Tracked):
    """On a collider entity: each physics ``Hit`` (or contact begin) bursts an emitter.

    ``count`` particles leave the contact point along the contact normal, pointing
    away from this collider. ``contacts=True`` also reacts to every
    ``ContactBegin``. Either way only impacts at ``hit_threshold`` (m/s, the
    approach speed) or faster burst (``min_speed`` before kge 2.0.0a2).
    """

    #: the emitter must exist and hold a ParticleEmitter (checked by the particles plugin)
    _world_fields: ClassVar[frozenset[str]] = frozenset({"emitter"})

    _checks: ClassVar[dict[str, Check]] = {
        "emitter": entity_id,
        "count": _count,
        "contacts": boolean,
        "hit_threshold": non_negative,
    }

    emitter: int
    count: int = 12
    contacts: bool = False
    hit_threshold: float = 0.0


@dataclass(slots=True)
class ParticleAttractor(Tracked):
    """On an entity with a Transform: pulls the particles of every world-space emitter
    within ``radius`` metres towards it (``strength`` m/s^2 at its centre, falling
    linearly to 0 at ``radius``; a negative strength pushes them away). Emitters in
    local space are not affected.
    """

    _checks: ClassVar[dict[str, Check]] = {
        "strength": _limited_float,
        "radius": positive,
        "enabled": boolean,
    }

    strength: float = 10.0
    radius: float = 5.0
    enabled: bool = True

