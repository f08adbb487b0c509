"""``CharacterBody``: a character that collides and slides (Godot's ``CharacterBody2D``).

A character is an entity with a :class:`~kge.components.transform.Transform` and a
``CharacterBody``. Each fixed step the character system (``kge.systems.character``)
moves it by ``velocity`` with shape casts against the world's colliders: it stops at
what it hits, slides along it, stands on floors, stays on them going down slopes and
steps, steps up small ledges, rides moving and rotating platforms, passes up through
one-way platforms and pushes dynamic bodies. The entity gets a kinematic
:class:`~kge.components.rigidbody.RigidBody` and a :class:`~kge.components.collider.
Collider` of its shape (unless it brings its own), so dynamic bodies, sensors and ray
casts meet it like any body.

Set ``velocity`` (and, in a platformer, hold ``jump``) in ``on_fixed_update``; read
``on_floor``, ``on_wall``, ``on_ceiling``, their normals and the landing fields after
the step. Everything is in metres, seconds and radians; ``up`` says where floors face.

>>> body = CharacterBody(Capsule(0.3, 0.9), jump_speed=7.0)
>>> body.on_floor, body.velocity
(False, (0.0, 0.0))
>>> CharacterBody(Capsule(0.3, 0.9), max_floor_angle=2.0)
Traceback (most recent call last):
...
kge.errors.ValidationError: CharacterBody.max_floor_angle must be in [0, pi/2] radians ...
>>> CharacterBody(Box(0.4, 0.4), step_height=1.0)
Traceback (most recent call last):
...
kge.errors.ValidationError: CharacterBody.step_height (1.0 m) must be less than the shape's ...
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from enum import Enum
from typing import Any, ClassVar

from kge.components.shapes import LINEAR_SLOP, Box, Circle
from kge.components.tracked import Check, Tracked
from kge.errors import ComponentTypeError, ValidationError
from kge.validate import (
    FAST,
    Vec2,
    at_most,
    boolean,
    finite,
    in_range,
    integer,
    non_negative,
    vec2,
)

#: Largest character shape accepted, metres (half extent): a character is a moving body,
#: and Box2D tunes moving bodies for 0.1 to 10 m.
MAX_CHARACTER_SIZE = 50.0
#: Smallest character half extent, metres (Box2D's linear slop).
MIN_CHARACTER_SIZE = LINEAR_SLOP
#: Fastest velocity accepted, m/s per axis. A step's move is also capped at
#: ``PhysicsSettings.max_translation`` (2 m per step: 120 m/s at 60 Hz), as for every body.
MAX_SPEED = 1000.0
#: Longest snap to the floor accepted, metres.
MAX_SNAP = 10.0
#: Longest coyote time or jump buffer accepted, seconds.
MAX_GRACE = 10.0
#: Most slide iterations per step.
MAX_SLIDES = 16


class CharacterMode(Enum):
    """How a character treats the surfaces it meets."""

    #: gravity, floors, walls and ceilings, jumps, snapping and steps
    PLATFORMER = "platformer"
    #: no gravity and no floor: every surface is a wall to slide along (a top-down game)
    TOP_DOWN = "top_down"


@dataclass(slots=True, frozen=True)
class Capsule:
    """An upright capsule: two half discs of ``radius`` joined by a rectangle.

    ``half_height`` is half the whole height (as :class:`~kge.components.shapes.Box`
    takes half extents), so ``Capsule(0.3, 0.9)`` is 0.6 m wide and 1.8 m tall;
    ``half_height == radius`` is a circle.

    >>> Capsule(0.25, 0.75).segment
    ((0.0, -0.5), (0.0, 0.5))
    """

    radius: float
    half_height: float

    def __post_init__(self) -> None:
        r = _size(self.radius, "Capsule", "radius")
        h = _size(self.half_height, "Capsule", "half_height")
        if h < r:
            raise ValidationError(
                f"Capsule.half_height must be >= radius ({r!r} m): it is half the whole "
                f"height, got {h!r}"
            )
        object.__setattr__(self, "radius", r)
        object.__setattr__(self, "half_height", h)

    @property
    def segment(self) -> tuple[Vec2, Vec2]:
        """The core segment (the capsule is every point within ``radius`` of it)."""
        a = self.half_height - self.radius
        return ((0.0, -a), (0.0, a))


CharacterShape = Capsule | Box | Circle
SHAPES = (Capsule, Box, Circle)


def _size(value: Any, owner: str, name: str) -> float:
    v = finite(value, owner, name)
    if not MIN_CHARACTER_SIZE <= v <= MAX_CHARACTER_SIZE:
        raise ValidationError(
            f"{owner}.{name} must be in [{MIN_CHARACTER_SIZE}, {MAX_CHARACTER_SIZE}] m "
            f"(a character's size), got {v!r}"
        )
    return v


def _shape(value: Any, owner: str, name: str) -> CharacterShape:
    if not isinstance(value, SHAPES):
        raise ComponentTypeError(
            f"{owner}.{name} must be a Capsule, Box or Circle (the character's shape), "
            f"got {type(value).__name__} {value!r}"
        )
    if isinstance(value, Box):
        for field_name in ("half_width", "half_height"):
            _size(getattr(value, field_name), owner, f"{name}.{field_name}")
        _offset(value.center, owner, f"{name}.center")
    elif isinstance(value, Circle):
        _size(value.radius, owner, f"{name}.radius")
        _offset(value.center, owner, f"{name}.center")
    return value


def _offset(value: Vec2, owner: str, name: str) -> None:
    if max(abs(value[0]), abs(value[1])) > MAX_CHARACTER_SIZE:
        raise ValidationError(
            f"{owner}.{name} must lie within {MAX_CHARACTER_SIZE} m of the entity, got {value!r}"
        )


def _velocity(value: Any, owner: str, name: str) -> Vec2:
    x, y = vec2(value, owner, name)
    if abs(x) > MAX_SPEED or abs(y) > MAX_SPEED:
        raise ValidationError(
            f"{owner}.{name} must be at most {MAX_SPEED:g} m/s along each axis, got {(x, y)!r}"
        )
    return (x, y)


def _up(value: Any, owner: str, name: str) -> Vec2:
    x, y = vec2(value, owner, name)
    n = math.hypot(x, y)
    if not n > 1e-9:
        raise ValidationError(f"{owner}.{name} must be a non-zero direction, got {value!r}")
    return (x / n, y / n)


def _mode(value: Any, owner: str, name: str) -> CharacterMode:
    if isinstance(value, CharacterMode):
        return value
    if isinstance(value, str):
        try:
            return CharacterMode(value.lower().replace("-", "_"))
        except ValueError:
            pass
    raise ComponentTypeError(
        f"{owner}.{name} must be a CharacterMode (PLATFORMER or TOP_DOWN), got {value!r}"
    )


def _floor_angle(value: Any, owner: str, name: str) -> float:
    v = finite(value, owner, name)
    if not 0.0 <= v <= 0.5 * math.pi:
        raise ValidationError(
            f"{owner}.{name} must be in [0, pi/2] radians (0 to 90 degrees), got {v!r}"
        )
    return v


def _bounded(limit: float, unit: str) -> Check:
    """A check of a value in [0, ``limit``] ``unit``."""

    def check(value: Any, owner: str, name: str) -> float:
        return at_most(non_negative(value, owner, name), limit, owner, name, unit)

    return check


def _positive_or_inf(value: Any, owner: str, name: str) -> float:
    v = finite(value, owner, name) if value != math.inf else math.inf
    if not v > 0.0:
        raise ValidationError(f"{owner}.{name} must be > 0 (math.inf: unlimited), got {v!r}")
    return v


def _non_negative_or_inf(value: Any, owner: str, name: str) -> float:
    return math.inf if value == math.inf else non_negative(value, owner, name)


def _slides(value: Any, owner: str, name: str) -> int:
    v = integer(value, owner, name)
    if not 1 <= v <= MAX_SLIDES:
        raise ValidationError(f"{owner}.{name} must be in [1, {MAX_SLIDES}], got {v!r}")
    return v


def _speed_pair(v: Any) -> bool:
    if type(v) is not tuple or len(v) != 2:
        return False
    x, y = v
    return type(x) is float and type(y) is float and -MAX_SPEED <= x <= MAX_SPEED and (
        -MAX_SPEED <= y <= MAX_SPEED
    )


# values the checks would return unchanged pass without a call (written every step)
FAST[_velocity] = _speed_pair
FAST[_mode] = lambda v: type(v) is CharacterMode


def height_along(shape: CharacterShape, up: Vec2) -> float:
    """The extent of ``shape`` along the unit direction ``up`` (its height, for steps)."""
    ux, uy = up
    if isinstance(shape, Circle):
        return 2.0 * shape.radius
    if isinstance(shape, Capsule):
        return 2.0 * (shape.half_height - shape.radius) * abs(uy) + 2.0 * shape.radius
    dots = [x * ux + y * uy for x, y in shape.vertices()]
    return max(dots) - min(dots)


#: fields whose values are checked against each other (the step must fit under the body)
_CROSS = frozenset({"shape", "up", "step_height"})


@dataclass(slots=True)
class CharacterBody(Tracked):
    """A kinematic character moved by collide-and-slide (see the module docstring).

    Settings: ``shape`` (a :class:`Capsule`, ``Box`` or ``Circle`` in the entity's
    frame; it does not rotate), ``mode``, ``up`` (unit, the direction floors face),
    ``max_floor_angle`` (steeper surfaces are walls; 0 to pi/2), ``snap_length``
    (how far below its feet a character that was standing looks for the floor, to
    stay on it down slopes and steps), ``step_height`` (ledges up to this height are
    stepped onto; less than the shape's height), ``gravity_scale`` (times
    ``PhysicsSettings.gravity``), ``max_slides`` (slide iterations per step),
    ``push_force`` (N, the most force it pushes dynamic bodies with; ``math.inf``
    pushes like an infinitely heavy body, 0 not at all) and ``mass`` (kg, how hard
    dynamic bodies push it; ``math.inf``: never).

    Platformer helpers: ``jump_speed`` (m/s; 0 turns jumping off), ``jump`` (hold it
    while the jump button is held: pressing starts a jump, releasing early cuts it to
    ``jump_cut`` times its speed, for variable jump height), ``coyote_time`` (a jump
    pressed this long after walking off a ledge still jumps), ``jump_buffer`` (a jump
    pressed this long before landing jumps on landing), ``hard_landing_speed`` (m/s:
    landing faster sets ``hard_landing``) and ``drop_through`` (set it to fall through
    the one-way platform under the feet).

    Read back after each step (written by the character system): ``on_floor``,
    ``on_wall``, ``on_ceiling`` and ``floor_normal``, ``wall_normal``,
    ``ceiling_normal`` (unit, pointing away from the surface; (0, 0) when not
    touching), ``floor_collider`` and ``wall_collider`` (the collider entity stood on
    or blocked by, or None: a crate it is pushing is a wall too),
    ``floor_velocity`` (the floor's velocity under the feet: a moving platform's),
    ``jumped`` and ``landed`` (this step), ``landing_speed`` (m/s into the floor when
    it landed) and ``hard_landing``. ``velocity`` comes back as it was after sliding
    (pushing into a wall leaves none of that speed).
    """

    _checks: ClassVar[dict[str, Check]] = {
        "shape": _shape,
        "velocity": _velocity,
        "mode": _mode,
        "up": _up,
        "max_floor_angle": _floor_angle,
        "snap_length": _bounded(MAX_SNAP, "m"),
        "step_height": _bounded(2.0 * MAX_CHARACTER_SIZE, "m"),
        "gravity_scale": finite,
        "max_slides": _slides,
        "push_force": _non_negative_or_inf,
        "mass": _positive_or_inf,
        "jump_speed": _bounded(MAX_SPEED, "m/s"),
        "jump": boolean,
        "jump_cut": lambda v, o, n: in_range(v, 0.0, 1.0, o, n),
        "coyote_time": _bounded(MAX_GRACE, "s"),
        "jump_buffer": _bounded(MAX_GRACE, "s"),
        "hard_landing_speed": _positive_or_inf,
        "drop_through": boolean,
        "on_floor": boolean,
        "on_wall": boolean,
        "on_ceiling": boolean,
        "floor_normal": vec2,
        "wall_normal": vec2,
        "ceiling_normal": vec2,
        "floor_velocity": vec2,
        "jumped": boolean,
        "landed": boolean,
        "hard_landing": boolean,
        "landing_speed": non_negative,
    }

    shape: CharacterShape
    velocity: Vec2 = (0.0, 0.0)
    mode: CharacterMode = CharacterMode.PLATFORMER
    up: Vec2 = (0.0, 1.0)
    max_floor_angle: float = math.radians(45.0)
    snap_length: float = 0.2
    step_height: float = 0.0
    gravity_scale: float = 1.0
    max_slides: int = 4
    push_force: float = 500.0
    mass: float = 80.0
    jump_speed: float = 0.0
    jump: bool = False
    jump_cut: float = 0.5
    coyote_time: float = 0.1
    jump_buffer: float = 0.1
    hard_landing_speed: float = math.inf
    drop_through: bool = False
    # read back, written by the character system after each step
    on_floor: bool = field(default=False, init=False)
    on_wall: bool = field(default=False, init=False)
    on_ceiling: bool = field(default=False, init=False)
    floor_normal: Vec2 = field(default=(0.0, 0.0), init=False)
    wall_normal: Vec2 = field(default=(0.0, 0.0), init=False)
    ceiling_normal: Vec2 = field(default=(0.0, 0.0), init=False)
    floor_collider: int | None = field(default=None, init=False)
    wall_collider: int | None = field(default=None, init=False)
    floor_velocity: Vec2 = field(default=(0.0, 0.0), init=False)
    jumped: bool = field(default=False, init=False)
    landed: bool = field(default=False, init=False)
    hard_landing: bool = field(default=False, init=False)
    landing_speed: float = field(default=0.0, init=False)

    def __post_init__(self) -> None:
        self._check_step(self.shape, self.up, self.step_height)

    def __setattr__(self, name: str, value: Any) -> None:
        if name in _CROSS and _initialised(self):
            owner = self._owner()
            v = self._checks[name](value, owner, name)
            shape, up, step = self.shape, self.up, self.step_height
            if name == "shape":
                shape = v
            elif name == "up":
                up = v
            else:
                step = v
            self._check_step(shape, up, step)
            value = v
        Tracked.__setattr__(self, name, value)

    def _check_step(self, shape: CharacterShape, up: Vec2, step: float) -> None:
        height = height_along(shape, up)
        if step >= height - 1e-9:
            raise ValidationError(
                f"{self._owner()}.step_height ({step!r} m) must be less than the shape's "
                f"height along up ({round(height, 9)!r} m)"
            )

    @property
    def is_platformer(self) -> bool:
        return self.mode is CharacterMode.PLATFORMER


def _initialised(body: CharacterBody) -> bool:
    """False inside ``__init__``, before the last cross-checked field is set."""
    try:
        object.__getattribute__(body, "step_height")
    except AttributeError:
        return False
    return True
