"""Many linear impulses in one call: ``Physics.apply_linear_impulses``.

A controller that pushes many bodies every step (the engines of 64 Gymnasium
landers sharing one world) paid ``apply_linear_impulse``'s per-call checks and
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
from pymunk._chipmunk import lib as _lib

from kge.errors import ValidationError

_local_to_world = _lib.cpBodyLocalToWorld
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


def push(cb: Any, v: list[float], jx: float, jy: float, at: Sequence[float] | None) -> None:
    """Add the impulse ``(jx, jy)`` at world point ``at`` (None: the centre of mass) to
    ``v = [vx, vy, w]`` of the Chipmunk body ``cb``; a body that cannot turn keeps ``w``."""
    m, i = _get_mass(cb), _get_moment(cb)
    v[0] += jx / m
    v[1] += jy / m
    if math.isfinite(i):
        c = _local_to_world(cb, _get_cog(cb))
        px, py = (c.x, c.y) if at is None else at
        v[2] += ((px - c.x) * jy - (py - c.y) * jx) / i


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
        cb = rec.body._body
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
    cbs: Sequence[Any], impulses: np.ndarray, points: np.ndarray | None
) -> np.ndarray:
    """:func:`new_velocities` for rows of distinct bodies, in numpy: (n, 3) rows
    ``(vx, vy, w)`` (Chipmunk bodies ``cbs``, one per row); nothing is written.

    The same arithmetic as :func:`push` element by element (the same operations in
    the same order, so the same floats), with each body's state read through one
    list of Chipmunk getter calls per quantity instead of a Python frame per row.
    The caller checks the result is finite.
    """
    n = len(cbs)
    vel = [_get_velocity(cb) for cb in cbs]
    out = np.empty((n, 3))
    out[:, 0] = [v.x for v in vel]
    out[:, 1] = [v.y for v in vel]
    out[:, 2] = [_get_angular_velocity(cb) for cb in cbs]
    mass = np.array([_get_mass(cb) for cb in cbs])
    moment = np.array([_get_moment(cb) for cb in cbs])
    jx, jy = impulses[:, 0], impulses[:, 1]
    out[:, 0] += jx / mass
    out[:, 1] += jy / mass
    turns = np.isfinite(moment)
    if points is not None and turns.any():
        centre = [_local_to_world(cb, _get_cog(cb)) for cb in cbs]
        cx = np.array([c.x for c in centre])
        cy = np.array([c.y for c in centre])
        with np.errstate(all="ignore"):  # rows that do not turn are not used
            spin = ((points[:, 0] - cx) * jy - (points[:, 1] - cy) * jx) / moment
        out[turns, 2] += spin[turns]
    elif turns.any():  # at the centre of mass: no lever, but add the signed zero push() adds
        with np.errstate(all="ignore"):
            spin = (0.0 * jy - 0.0 * jx) / moment
        out[turns, 2] += spin[turns]
    return out
