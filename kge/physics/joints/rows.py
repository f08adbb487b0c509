"""Velocity steps of the custom joint parts (motors, limits, pulley, gear, rope, weld).

A scalar velocity constraint is a list of Jacobian rows ``(body, jx, jy, jw)``:
its rate is ``sum(jx·vx + jy·vy + jw·w)`` over the bodies (v at the centre of
gravity). :class:`VelocityStep` solves one such constraint once per substep,
from a carrier constraint's ``pre_solve``; :func:`fold` makes an angular or
axial row see through the pivot or groove that pymunk solves alongside it.
"""

from __future__ import annotations

import math
from collections.abc import Iterable

import pymunk

from kge.physics.joints.mechanics import cog_world, cross, inv_mass

#: one Jacobian row: (body, jx, jy, jw)
Row = tuple[pymunk.Body, float, float, float]
#: Box2D's Baumgarte factor, used by the custom position corrections
BAUMGARTE = 0.2
#: the fastest a motor drives its joint (m/s or rad/s): far beyond any body's speed
#: cap (PhysicsSettings allows at most 1e3 m or rad per step, 6e4 per second at 60 Hz),
#: so it changes no reachable speed, and it keeps a motor asked for 1e308 with 1e308
#: of force from products that overflow to inf and turn the bodies' poses into NaN
MOTOR_SPEED_BOUND = 1e6


def motor_speed(speed: float) -> float:
    """``speed`` within ``±MOTOR_SPEED_BOUND``.

    >>> motor_speed(1e308), motor_speed(-3.0)
    (1000000.0, -3.0)
    """
    return min(max(speed, -MOTOR_SPEED_BOUND), MOTOR_SPEED_BOUND)


def correction(error: float, max_correction: float, factor: float = BAUMGARTE) -> float:
    """The part of a position ``error`` a velocity step may remove in one (sub)step.

    Box2D's position solver clamps every correction (``b2_maxLinearCorrection``
    0.2 m, ``b2_maxAngularCorrection`` 8°) and never turns it into velocity. Here
    the correction is a velocity bias (``-correction / h``), which the body keeps:
    unclamped, a joint whose error is metres (a limit far past its bound, a body
    teleported away from its gear partner) would throw its bodies at hundreds of
    metres per second. Clamped, the push is bounded whatever the error.
    """
    return factor * max(-max_correction, min(max_correction, error))


def line_rows(
    a: pymunk.Body, b: pymunk.Body, pa: pymunk.Vec2d, pb: pymunk.Vec2d
) -> tuple[list[Row], float]:
    """Jacobian of the distance between world points ``pa`` (on a) and ``pb`` (on b)."""
    d = pb - pa
    n = abs(d)
    u = d / n if n > 1e-9 else pymunk.Vec2d(1.0, 0.0)
    ra, rb = pa - cog_world(a), pb - cog_world(b)
    return [
        (b, u.x, u.y, cross(rb.x, rb.y, u.x, u.y)),
        (a, -u.x, -u.y, -cross(ra.x, ra.y, u.x, u.y)),
    ], float(n)


def _dot(r1: list[Row], r2: list[Row]) -> float:
    """<J1, J2> weighted by the inverse mass matrix."""
    total = 0.0
    for b1, x1, y1, w1 in r1:
        for b2, x2, y2, w2 in r2:
            if b1 is b2:
                im, ii = inv_mass(b1)
                total += im * (x1 * x2 + y1 * y2) + ii * w1 * w2
    return total


def fold(main: list[Row], keep: list[list[Row]]) -> list[Row]:
    """``main``'s Jacobian with the constraints ``keep`` (solved by pymunk) folded in.

    An impulse along ``main`` alone disturbs the ``keep`` constraints, which then
    undo most of it: a motor torque on a pendulum bob spins the bob about its own
    centre and the pivot fights back, so pymunk's separate ``SimpleMotor`` or
    ``RotaryLimitJoint`` converge badly (a brake slips, a limit throws the bob
    back). Box2D solves such joints as one block. Folding is the same thing for
    one row: pair each unit impulse along ``main`` with ``p = -K⁻¹·k`` along the
    ``keep`` rows (K their mass matrix, k their coupling with ``main``), which
    leaves their rates untouched. The folded rows then measure the rate ``main``
    will have once pymunk has solved ``keep``, and their effective mass is the
    Schur complement (for a pendulum: the inertia about the pivot).
    """
    n = len(keep)
    if n == 0:
        return main
    k = [[_dot(keep[i], keep[j]) for j in range(n)] for i in range(n)]
    c = [_dot(keep[i], main) for i in range(n)]
    if n == 1:
        p = [-c[0] / k[0][0]] if abs(k[0][0]) > 1e-12 else [0.0]
    else:  # n == 2
        det = k[0][0] * k[1][1] - k[0][1] * k[1][0]
        if abs(det) <= DEGENERATE * k[0][0] * k[1][1]:
            return main  # the kept rows are (nearly) dependent: nothing sound to fold
        p = [
            -(k[1][1] * c[0] - k[0][1] * c[1]) / det,
            -(-k[1][0] * c[0] + k[0][0] * c[1]) / det,
        ]
    out = list(main)
    for coef, rows in zip(p, keep, strict=True):
        out += [(body, coef * x, coef * y, coef * w) for body, x, y, w in rows]
    return out


def point_rows(
    a: pymunk.Body, b: pymunk.Body, pa: pymunk.Vec2d, pb: pymunk.Vec2d
) -> list[list[Row]]:
    """The x and y rows of a pivot between world points ``pa`` (on a) and ``pb`` (on b)."""
    ra, rb = pa - cog_world(a), pb - cog_world(b)
    return [
        [(b, 1.0, 0.0, -rb.y), (a, -1.0, 0.0, ra.y)],
        [(b, 0.0, 1.0, rb.x), (a, 0.0, -1.0, -ra.x)],
    ]


def spin_rows(a: pymunk.Body, b: pymunk.Body, scale: float = 1.0) -> list[Row]:
    """Relative spin ``w_b - w_a``."""
    return [(b, 0.0, 0.0, scale), (a, 0.0, 0.0, -scale)]


def hinge_rows(a: pymunk.Body, b: pymunk.Body, pa: pymunk.Vec2d, pb: pymunk.Vec2d) -> list[Row]:
    """Relative spin of two bodies pinned at ``pa`` / ``pb``, the pivot folded in."""
    return fold(spin_rows(a, b), point_rows(a, b, pa, pb))


#: a constraint whose effective mass is below this fraction of its rows' own is
#: treated as degenerate (no impulse), like Box2D's ``k == 0`` guard
DEGENERATE = 1e-9

#: passes over a joint's motor and limit per substep when both are on, so a motor
#: pushing into its limit ends at its full force as in Box2D's iterations
MOTOR_LIMIT_PASSES = 4


def motor_and_limits(
    space: pymunk.Space,
    rows: list[Row],
    value: float,
    h: float,
    motor: tuple[float, float] | None,
    lower: float | None,
    upper: float | None,
    max_correction: float,
) -> tuple[float, float]:
    """Motor ``(speed, max force or torque)`` and limits on a joint coordinate.

    The limits are speculative, like Box2D's rope and contacts: while inside the
    range the approach speed is capped so the coordinate reaches the bound
    exactly at the next step; past it, Baumgarte pushes back on at most
    ``max_correction`` of the overshoot (see :func:`correction`). Impulses are
    accumulated and clamped over a few passes as in a sequential-impulse solver.
    Returns the (motor, limit) impulses.
    """
    m_acc = lo_acc = hi_acc = 0.0
    cap = motor[1] * h if motor is not None else 0.0
    limited = lower is not None or upper is not None
    passes = MOTOR_LIMIT_PASSES if motor is not None and limited else 1
    for _ in range(passes):
        if motor is not None:
            target = motor_speed(motor[0])
            m_acc += VelocityStep.solve(space, rows, target, h, -cap - m_acc, cap - m_acc)
        if lower is not None:
            c = value - lower
            target = -c / h if c >= 0 else -correction(c, max_correction) / h
            lo_acc += VelocityStep.solve(space, rows, target, h, lo=-lo_acc)
        if upper is not None:
            c = upper - value
            target = c / h if c >= 0 else correction(c, max_correction) / h
            hi_acc += VelocityStep.solve(space, rows, target, h, hi=-hi_acc)
    return m_acc, lo_acc + hi_acc


#: one body's summed Jacobian row with its inverse mass and inertia: (body, jx, jy, jw, 1/m, 1/I)
Merged = tuple[pymunk.Body, float, float, float, float, float]


def merge(rows: Iterable[Row]) -> tuple[list[Merged], float]:
    """The rows summed per body, and the constraint's inverse effective mass ``k``.

    ``k`` is 0 when the constraint is degenerate. Box2D skips a row whose
    effective mass is zero; rows that cancel (a gear of two joints on the same
    bodies with ratio -1) leave rounding noise instead of an exact 0, and 1/noise
    would be an enormous impulse, so ``k`` below ``DEGENERATE`` times the rows'
    own (taken one by one) counts as zero too.
    """
    acc: dict[pymunk.Body, list[float]] = {}
    for body, jx, jy, jw in rows:
        a = acc.setdefault(body, [0.0, 0.0, 0.0, 0.0, 0.0])
        a[0] += jx
        a[1] += jy
        a[2] += jw
        a[3] += jx * jx + jy * jy
        a[4] += jw * jw
    merged: list[Merged] = []
    k = scale = 0.0
    for body, (jx, jy, jw, lin2, ang2) in acc.items():
        im, ii = inv_mass(body)
        k += im * (jx * jx + jy * jy) + ii * jw * jw
        scale += im * lin2 + ii * ang2
        merged.append((body, jx, jy, jw, im, ii))
    return merged, (k if k > DEGENERATE * scale else 0.0)


class VelocityStep:
    """A scalar velocity constraint solved once per substep: rate -> target.

    ``rows`` gives the Jacobian; ``solve`` predicts this substep's gravity
    (pre_solve runs before velocities are integrated), computes the impulse that
    brings the rate to ``target - bias``, clamps it, and applies it.
    """

    @staticmethod
    def solve(
        space: pymunk.Space,
        rows: Iterable[Row],
        target: float,
        h: float,
        lo: float = -math.inf,
        hi: float = math.inf,
    ) -> float:
        merged, k = merge(rows)
        if k == 0.0:
            return 0.0
        gx, gy = space.gravity
        rate = 0.0
        for body, jx, jy, jw, im, _ in merged:
            vx, vy = body.velocity
            if im:  # a dynamic body: this substep's gravity is still to come
                vx += gx * h
                vy += gy * h
            rate += jx * vx + jy * vy + jw * body.angular_velocity
        impulse = min(max((target - rate) / k, lo), hi)
        if impulse != 0.0:
            for body, jx, jy, jw, im, ii in merged:
                if im or ii:
                    vx, vy = body.velocity
                    body.velocity = (vx + im * impulse * jx, vy + im * impulse * jy)
                    body.angular_velocity = body.angular_velocity + ii * impulse * jw
        return impulse
