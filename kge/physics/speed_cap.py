"""Box2D's speed limits: no body moves more than 2 m or turns more than π/2 per step.

Box2D clamps every body's velocity while it integrates positions
(``b2_maxTranslation``, ``b2_maxRotation``; :class:`PhysicsSettings`
``max_translation`` and ``max_rotation`` here). The limit is far above anything
a game asks for (120 m/s at 60 Hz) and exists for the day a solver diverges: a
tangle of stiff joints pulling against each other can multiply a velocity by
ten in one pymunk step, and without a limit the body is kilometres away within
a few steps and ``inf`` soon after.

pymunk has no such limit, so kge applies it in two places:

* **before every substep** but the first (:meth:`SpeedCap.before_substep`):
  one bulk read of every body's velocities, and a write only to the bodies
  over the limit (before the first, sync-in has capped the velocities users
  wrote and continuous collision those that impulses made);
* **after the step**, in sync-out, on the rows it reads anyway (:func:`clamp`).

Chipmunk moves each body with the velocity the previous substep ended with
(positions first, then velocities and the solver), so capping before every
substep caps every move: no body's velocity carries it further than
``max_translation`` or turns it more than ``max_rotation`` in one step, as in
Box2D, whatever the solver does to that velocity meanwhile (position
corrections of contacts and joints come on top, as Box2D's position pass
does). The limit is a speed (``max_translation / dt``), the same for every
substep.
"""

from __future__ import annotations

import math
from collections.abc import Sequence

import numpy as np
import pymunk
import pymunk.batch as pb

from kge.physics.cp import body_handle
from kge.physics.cp import lib as _lib
from kge.physics.cp.bulk import BodyReader

_VELOCITIES = pb.BodyFields.VELOCITY | pb.BodyFields.ANGULAR_VELOCITY
_SQRT_HALF = math.sqrt(0.5)
_MAX = np.maximum.reduce
_ABS = np.absolute


def clamp(v: np.ndarray, vmax: float, wmax: float) -> np.ndarray:
    """Clamp rows ``(vx, vy, w)`` of ``v`` in place; returns the indices of the rows changed.

    The linear velocity keeps its direction (scaled to ``vmax``); the angular
    one keeps its sign.

    >>> v = np.array([[3.0, 4.0, 0.1], [0.5, 0.0, -9.0], [1.0, 1.0, 1.0]])
    >>> clamp(v, 2.5, 2.0).tolist()
    [0, 1]
    >>> v.tolist()
    [[1.5, 2.0, 0.1], [0.5, 0.0, -2.0], [1.0, 1.0, 1.0]]
    """
    with np.errstate(over="ignore"):  # a square beyond float64 is inf: over the limit
        speed2 = v[:, 0] * v[:, 0] + v[:, 1] * v[:, 1]
    fast = speed2 > vmax * vmax
    spin = np.abs(v[:, 2]) > wmax
    over = np.flatnonzero(fast | spin)
    if len(over):
        k = np.flatnonzero(fast)
        scale = vmax / np.hypot(v[k, 0], v[k, 1])  # overflow-safe where the square was not
        v[k, 0] *= scale
        v[k, 1] *= scale
        np.clip(v[:, 2], -wmax, wmax, out=v[:, 2])
    return over


def clamp_one(
    vx: float, vy: float, w: float, vmax: float, wmax: float
) -> tuple[tuple[float, float] | None, float | None]:
    """One body's capped velocity and spin, each None when already within its limit.

    >>> clamp_one(300.0, 400.0, -1.0, 100.0, 2.0)
    ((60.0, 80.0), None)
    """
    speed = math.hypot(vx, vy)  # overflow-safe; so is the scale (vx * vmax overflows at 1e307)
    if speed > vmax:
        scale = vmax / speed
        nv: tuple[float, float] | None = (vx * scale, vy * scale)
    else:
        nv = None
    nw = math.copysign(wmax, w) if abs(w) > wmax else None
    return nv, nw


def clamp_velocity(
    body: pymunk.Body,
    step_dt: float,
    max_translation: float = 2.0,
    max_rotation: float = 0.5 * math.pi,
) -> bool:
    """Clamp one body to Box2D's per-step caps; True if its velocity changed.

    ``step_dt`` is the fixed step (not a substep): the caps are per step.

    >>> b = pymunk.Body(1, 1)
    >>> b.velocity, b.angular_velocity = (500, 0), 200
    >>> clamp_velocity(b, 1 / 60), b.velocity.x, round(b.angular_velocity, 3)
    (True, 120.0, 94.248)
    """
    vx, vy = body.velocity
    nv, nw = clamp_one(
        vx, vy, body.angular_velocity, max_translation / step_dt, max_rotation / step_dt
    )
    if nv is not None:
        body.velocity = nv
    if nw is not None:
        body.angular_velocity = nw
    return nv is not None or nw is not None


class SpeedCap:
    """The before-substep limit of one space (keeps its read buffers)."""

    #: below this many floats (a few dozen bodies), Python's max/min beat numpy's
    SMALL = 192

    def __init__(self) -> None:
        self._velocities = BodyReader(_VELOCITIES)
        self._ids = BodyReader(pb.BodyFields.BODY_ID)
        self._abs = np.empty(0)  # |v| of the last read, reused while the count stays

    def before_substep(
        self,
        space: pymunk.Space,
        known: tuple[np.ndarray, Sequence[pymunk.Body]],
        vmax: float,
        wmax: float,
    ) -> int:
        """Clamp every body of ``space``; returns how many were over the limit.

        ``known`` is (sorted pymunk ids, their bodies): the pose table's, which
        sync-in has brought up to date before the substeps. Only the bodies over
        the limit are written, through Chipmunk's setters: a bulk write would
        touch every body and reset each one's time towards sleep. A body missing
        from ``known`` (none in practice) would be left to sync-out's limit.

        Runs every substep, so the common case is kept to a bulk read of the
        velocities alone (ids are read only when a body is over) and one
        ``max``/``min`` over all of them: in plain Python for a few bodies, in
        numpy for many (on the reader's standing view of its buffer and a reused
        ``|v|`` array: no numpy object is made while nothing is over).
        """
        bound = min(vmax * _SQRT_HALF, wmax)
        reader = self._velocities
        count = reader.fill(space)
        if count < self.SMALL:
            if not count:
                return 0
            flat = reader.memory()
            if max(flat) <= bound and min(flat) >= -bound:
                return 0
            v = np.array(flat).reshape(-1, 3)
        else:
            view = reader.flat()
            scratch = self._abs
            if len(scratch) != count:
                scratch = self._abs = np.empty(count)
            # maybe_over's test on the flat view (a NaN is not over, as there)
            if not float(_MAX(_ABS(view, out=scratch))) > bound:
                return 0
            v = view.reshape(-1, 3)  # a view of the buffer
        capped = v.copy()  # ``v`` views the buffer
        over = clamp(capped, vmax, wmax)
        if len(over) == 0:
            return 0
        ids, _ = self._ids.read(space)  # same order: no step between
        ids = ids[over]
        known_ids, bodies = known
        at = np.searchsorted(known_ids, ids)
        n = 0
        for i, k, pid in zip(over.tolist(), at.tolist(), ids.tolist(), strict=True):
            if k >= len(known_ids) or known_ids[k] != pid:
                continue
            cp = body_handle(bodies[k])
            vx, vy, w = capped[i].tolist()
            _lib.cpBodySetVelocity(cp, (vx, vy))
            _lib.cpBodySetAngularVelocity(cp, w)
            n += 1
        return n


def maybe_over(v: np.ndarray, vmax: float, wmax: float) -> bool:
    """A conservative test, 6x faster than the exact one: could any row be over a limit?

    No component beyond ``vmax / sqrt(2)`` means no speed beyond ``vmax``; one
    bound for all three columns keeps it to one ``max`` of ``|v|``.

    >>> maybe_over(np.array([[80.0, -80.0, 80.0]]), 120.0, 94.0)
    False
    >>> maybe_over(np.array([[90.0, 0.0, 0.0]]), 120.0, 94.0)
    True
    """
    return largest(v) > screen(vmax, wmax)


def screen(vmax: float, wmax: float) -> float:
    """:func:`maybe_over`'s bound: no ``|component|`` above it means no row over a limit."""
    return min(vmax * _SQRT_HALF, wmax)


def largest(v: np.ndarray) -> float:
    """The largest ``|component|`` of ``v`` (0 when empty; NaN if any is NaN).

    The ufuncs themselves: ndarray.max/min add a Python wrapper each, a third of the
    cost for a few bodies; one ``|v|`` pass is also faster than a max and a min for many.

    >>> largest(np.array([[1.0, -3.0], [2.0, 0.5]]))
    3.0
    """
    return float(_MAX(_ABS(v), axis=None)) if v.size else 0.0
