"""Many linear impulses in one call: ``Physics.apply_linear_impulses``.

A controller that pushes many bodies every step (the thrusters of 64
vehicles sharing one world) paid ``apply_linear_impulse``'s per-call checks and
lookups once per body. Here the rows are checked together with numpy (shape,
finiteness), each entity is looked up once, and the new velocities are computed
for every row before any body changes, so a bad row leaves the world as it was.

Rows are applied in order, exactly as the same calls one by one would: an
entity listed twice gets both pushes, the second from the velocity the first
left. Impulses change velocities at once (N s); a row without a point pushes at
the body's centre of mass.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import Any

import numpy as np

from kge.errors import ValidationError
from kge.physics.cp import body_handle
from kge.physics.cp import lib as _lib
from kge.physics.cp.bulk import BodyReader
from kge.physics.sync import FIELDS

_get_position = _lib.cpBodyGetPosition
_get_angle = _lib.cpBodyGetAngle
_get_cog = _lib.cpBodyGetCenterOfGravity
_get_velocity = _lib.cpBodyGetVelocity
_get_angular_velocity = _lib.cpBodyGetAngularVelocity
_get_mass = _lib.cpBodyGetMass
_get_moment = _lib.cpBodyGetMoment

#: (record, its new [vx, vy, w]), keyed by ``id(record)``
Velocities = dict[int, tuple[Any, list[float]]]


def checked_rows(
    owner: str, entities: Any, impulses: Any, points: Any
) -> tuple[list[int], np.ndarray, np.ndarray | None]:
    """The rows as (entity ids, (n, 2) impulses, (n, 2) points or None), or a clear error."""
    ents = np.asarray(entities)
    if ents.ndim != 1 or (len(ents) and ents.dtype.kind not in "iu"):
        raise ValidationError(
            f"{owner}: entities must be a 1-D sequence of int ids, got {entities!r}"
        )
    n = len(ents)
    jj = _rows(owner, "impulses", impulses, n)
    pp = None if points is None else _rows(owner, "points", points, n)
    for name, arr in (("impulses", jj), ("points", pp)):
        if arr is not None and not np.isfinite(arr).all():
            k = int(np.flatnonzero(~np.isfinite(arr).all(axis=1))[0])
            raise ValidationError(
                f"{owner}: {name}[{k}] (entity {int(ents[k])}) must be finite, "
                f"got {tuple(arr[k].tolist())!r}"
            )
    return ents.tolist(), jj, pp


def _rows(owner: str, name: str, value: Any, n: int) -> np.ndarray:
    try:
        arr = np.asarray(value, dtype=np.float64)
    except (TypeError, ValueError):
        raise ValidationError(f"{owner}: {name} must be numbers, got {value!r}") from None
    if arr.shape != (n, 2):
        raise ValidationError(
            f"{owner}: {name} must have shape ({n}, 2), one (x, y) row per entity, "
            f"got shape {arr.shape}"
        )
    return arr


def velocity_of(cb: Any) -> list[float]:
    """``[vx, vy, w]`` of the Chipmunk body ``cb``."""
    v = _get_velocity(cb)
    return [v.x, v.y, _get_angular_velocity(cb)]


def centre(x: float, y: float, angle: float, cog: Sequence[float]) -> tuple[float, float]:
    """The world centre of mass of a body at ``(x, y, angle)`` with local centre ``cog``.

    Chipmunk's own arithmetic (``cpBodyLocalToWorld`` through the body transform that
    ``SetTransform`` builds from the angle's libm cosine and sine), operation for
    operation, so the bulk form (:func:`distinct_velocities`, numpy over rows, which
    never fuses a multiply and an add) gives the same floats on every platform.
    """
    ca, sa = math.cos(angle), math.sin(angle)
    return ca * cog[0] + (-sa) * cog[1] + x, sa * cog[0] + ca * cog[1] + y


def push(cb: Any, v: list[float], jx: float, jy: float, at: Sequence[float] | None) -> None:
    """Add the impulse ``(jx, jy)`` at world point ``at`` (None: the centre of mass) to
    ``v = [vx, vy, w]`` of the Chipmunk body ``cb``; a body that cannot turn keeps ``w``."""
    m, i = _get_mass(cb), _get_moment(cb)
    v[0] += jx / m
    v[1] += jy / m
    if math.isfinite(i):
        p, g = _get_position(cb), _get_cog(cb)
        cx, cy = centre(p.x, p.y, _get_angle(cb), (g.x, g.y))
        px, py = (cx, cy) if at is None else at
        v[2] += ((px - cx) * jy - (py - cy) * jx) / i


def new_velocities(
    owner: str, records: Sequence[Any], entities: Sequence[int],
    impulses: np.ndarray, points: np.ndarray | None,
) -> Velocities:
    """Each pushed body's velocity after its rows, in row order; nothing is written yet.

    ``records`` are the rows' body records (anything with a ``body``); the result maps
    each record's ``id`` to ``(record, [vx, vy, w])``, in the order of first appearance.
    """
    out: Velocities = {}
    rows = impulses.tolist()
    at = None if points is None else points.tolist()
    for k, rec in enumerate(records):
        cb = body_handle(rec.body)
        key = id(rec)
        pushed = out.get(key)
        if pushed is None:
            pushed = out[key] = (rec, velocity_of(cb))
        v = pushed[1]
        jx, jy = rows[k]
        push(cb, v, jx, jy, None if at is None else at[k])
        if not (math.isfinite(v[0]) and math.isfinite(v[1]) and math.isfinite(v[2])):
            raise ValidationError(
                f"{owner}: the velocity of entity {entities[k]} after impulses[{k}] would not "
                f"be finite ({tuple(v)!r}); the input is too large"
            )
    return out


def distinct_velocities(
    state: np.ndarray, masses: Sequence[Any], impulses: np.ndarray, points: np.ndarray | None
) -> np.ndarray:
    """:func:`new_velocities` for rows of distinct bodies, in numpy: (n, 3) rows
    ``(vx, vy, w)``; nothing is written. The caller checks the result is finite.

    ``state`` holds each row's body as read in bulk, ``(x, y, angle, vx, vy, w)``;
    ``masses`` its :class:`~kge.physics.mass.MassData` (what the physics gave
    Chipmunk). The arithmetic is :func:`push`'s, element by element in the same
    order, so the floats are the same as the row-by-row path's.
    """
    out = state[:, 3:6].copy()
    md = np.array([(m.mass, m.inertia, *m.center) for m in masses]).reshape(-1, 4)
    mass, moment = md[:, 0], md[:, 1]
    jx, jy = impulses[:, 0], impulses[:, 1]
    with np.errstate(all="ignore"):  # too large a push: the caller reports the row
        out[:, 0] += jx / mass
        out[:, 1] += jy / mass
        turns = np.isfinite(moment)
        if not turns.any():
            return out
        angles = state[:, 2].tolist()
        ca = np.array([math.cos(a) for a in angles])
        sa = np.array([math.sin(a) for a in angles])
        gx, gy = md[:, 2], md[:, 3]
        cx = ca * gx + (-sa) * gy + state[:, 0]
        cy = sa * gx + ca * gy + state[:, 1]
        px, py = (cx, cy) if points is None else (points[:, 0], points[:, 1])
        spin = ((px - cx) * jy - (py - cy) * jx) / moment
    if turns.all():
        out[:, 2] += spin
    else:  # (a body that cannot turn keeps its angular velocity, even a -0.0)
        out[turns, 2] += spin[turns]
    return out


class RowReader:
    """Rows ``(x, y, angle, vx, vy, w)`` of chosen bodies, from one bulk read of the space.

    Chipmunk's getters cost about 0.15 µs a call through cffi, and a pushed body needs
    six of them; one ``pymunk.batch`` read of every body costs a few µs whatever the
    number of rows wanted. The read's body order is kept from call to call unless
    bodies come, go or fall asleep, so its sorting is reused while it holds.
    """

    def __init__(self) -> None:
        self._reader = BodyReader(FIELDS)
        self._key = b""
        self._order = np.empty(0, dtype=np.intp)
        self._sorted = np.empty(0, dtype=np.int64)
        self._last: tuple[np.ndarray, np.ndarray] = (self._sorted, np.empty((0, 6)))
        self._at = np.empty(0, dtype=np.intp)

    def rows(self, space: Any, body_ids: np.ndarray) -> np.ndarray | None:
        """The current rows of the bodies ``body_ids`` (pymunk ids), or None if one of
        them is not in the space. :meth:`patch` may then write their new velocities."""
        ids, rows = self._reader.read(space)
        self._last = (ids, rows)
        key = ids.tobytes()
        if key != self._key:
            self._order = np.argsort(ids, kind="stable")
            self._sorted = ids[self._order]
            self._key = key
        if len(self._sorted) == 0:
            return None
        at = np.minimum(np.searchsorted(self._sorted, body_ids), len(self._sorted) - 1)
        if not np.array_equal(self._sorted[at], body_ids):
            return None
        self._at = self._order[at]
        return rows[self._at]

    def patch(self, velocities: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Write the velocities just given to the bodies of the last :meth:`rows` into
        that read, and return it, ``(ids, rows)`` of every body: the space as it is now
        (views of the buffer, valid until the next read)."""
        ids, rows = self._last
        rows[self._at, 3:6] = velocities
        return ids, rows
