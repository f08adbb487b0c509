"""Revolute joints in bulk: the position pass and the read-back, as columns.

A chain of 200 links or a 30 x 30 grid has hundreds of revolute joints, and
doing their after-step work one joint at a time (Box2D's position pass through
pymunk's per-body properties, then angle, speed and reaction per joint) cost
about 25 µs per joint per step, twenty times pymunk's own step. This module does
the same work over all of them at once:

* poses and velocities come from one ``pymunk.batch.get_space_bodies`` call
  (rows mapped to our bodies by id, as in :mod:`kge.physics.sync`);
* the position pass is Box2D's point projection
  (:func:`~kge.physics.joints.positions.project_point`) as numpy columns. It stays
  a Gauss-Seidel sweep: the joints are split into *colours* in which no dynamic
  body appears twice, so each colour is one vectorised update and later colours
  see the earlier ones' corrections, as a sequential pass does. A chain needs 2
  colours, a grid 4. The order differs from the per-joint pass (entity order),
  so results agree to rounding for one joint and drift apart only as chaos
  allows; a chain's largest anchor gap is about twice the sequential pass's
  (3.7 mm instead of 1.8 mm for the benchmark's 40-link chains; Box2D: 11 mm);
* only bodies that moved are written back to pymunk (angle, then origin);
* angle, speed and reaction force are computed as columns and written into the
  components through the slots' own setters (C loops); the torques of a joint
  with no motor and no limit are zero and are written once. The angle is read
  after the whole pass, so it matches the final poses exactly.

Hinges with a motor or a limit join the batch when pymunk solves those in its
iterations (``PhysicsSettings.iterated_hinges``, the Box2D-style setting; 128
motorised, limited legs in one world took a fifth of a step on the
per-joint path). Their position pass is the per-joint one's: within each colour,
the limits first (Box2D's angular projection back to within b2_angularSlop, at
most 8° per step), then the points; gaps under ``ITERATED_PIVOT_TOLERANCE`` are
left alone in such worlds, so a leg held on its limit does not wake. Their motor
and limit torques are read from pymunk's constraints as columns. With the other
setting the motor and limit rows run in Python every substep, which dwarfs the
after-step work, and those joints stay on the per-joint path (see
``JointBridge._batchable``).

Mass data is reloaded when a body's ``BodyRecord.mass`` object changes (the
physics system replaces it whenever it recomputes a mass) and the body types
after every membership refresh (which every type change triggers).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import numpy as np
import pymunk
import pymunk.batch as pb

from kge.components.tracked import raw_set
from kge.physics.cp import body_handle, constraint_handle, lib
from kge.physics.cp.bulk import BodyReader
from kge.physics.joints.base import JOLT
from kge.physics.joints.mechanics import inv_mass, is_dynamic
from kge.physics.joints.positions import (
    ANGULAR_SLOP,
    MAX_ANGULAR_CORRECTION,
    MAX_CORRECTION,
)
from kge.physics.sync import FIELDS  # the same columns sync-out reads
from kge.physics.writeback import set_all, slot_setter

if TYPE_CHECKING:
    from kge.physics.joints.revolute import Revolute


#: Gauss-Seidel sweeps of the position pass per step. One, like the per-joint
#: pass. Two halve a chain's anchor gap (the colour order propagates a correction
#: one joint per colour, where a sequential pass carries it down the whole
#: chain), but the pinned testbed bridge then rings about five times longer.
SWEEPS = 1

_set_angle = lib.cpBodySetAngle
_set_position = lib.cpBodySetPosition
_get_position = lib.cpBodyGetPosition
_get_mass = lib.cpBodyGetMass
_get_cog = lib.cpBodyGetCenterOfGravity
_get_impulse = lib.cpConstraintGetImpulse


def colour(pairs: list[tuple[int, int]], movable: list[bool]) -> list[int]:
    """Greedy colouring: no movable slot appears twice within one colour.

    Each joint takes the lowest colour neither of its movable bodies has yet (a
    bit mask per body: the lowest clear bit of the two masks' union).

    >>> colour([(1, 2), (2, 3), (3, 4), (0, 1)], [False, True, True, True, True])
    [0, 1, 0, 1]
    """
    masks = [0] * len(movable)
    out = []
    for a, b in pairs:
        taken = (masks[a] if movable[a] else 0) | (masks[b] if movable[b] else 0)
        c = (~taken & (taken + 1)).bit_length() - 1
        bit = 1 << c
        if movable[a]:
            masks[a] |= bit
        if movable[b]:
            masks[b] |= bit
        out.append(c)
    return out


@dataclass(slots=True)
class _Colour:
    """One colour's joints, their two ends stacked: row k of the first half is joint
    k's body A, of the second half its body B, so one numpy call serves both ends."""

    idx: np.ndarray  # the joints (indices into PivotBatch.handles)
    n: int
    ab: np.ndarray  # body slots, the A ends then the B ends (2n)
    arm: np.ndarray  # anchors from the centres of gravity, in the bodies' frames
    cog: np.ndarray  # local centres of gravity
    inv_i: np.ndarray  # inverse inertias
    msum: np.ndarray  # im[a] + im[b] (n)
    step_m: np.ndarray  # -im[a], then +im[b]: how far the position impulse moves each end
    step_i: np.ndarray  # -ii[a], then +ii[b]: how far it turns each end
    movable: np.ndarray  # the ends that can move (bool)
    all_movable: bool
    #: the limited joints' columns (see PivotBatch._limits), or None
    limit: tuple[Any, ...] | None


class PivotBatch:
    """The revolute joints of one space that need no Python between substeps, together.

    Poses are complex numbers here (origin ``x + iy``, rotation ``e^{iθ}``), which
    turns each rotate-and-add of the position pass into one numpy operation.
    """

    def __init__(self, space: pymunk.Space, bodies: dict[int, Any]) -> None:
        self.space = space
        #: body entity -> BodyRecord (the physics system's map)
        self.records = bodies
        self._buffer = pb.Buffer()
        #: the read-back of a position pass that moved most bodies (see :meth:`project`)
        self._reader = BodyReader(FIELDS)
        self._clear()

    def _clear(self) -> None:
        self.handles: list[Revolute] = []
        self.bodies: list[pymunk.Body] = []
        self.masses: list[Any] = []
        self.recs: list[Any] = []
        self.ids = np.empty(0, dtype=np.int64)
        self._mapping: tuple[np.ndarray, np.ndarray] | None = None
        #: the largest anchor gap the last position pass found, m
        self.v0: np.ndarray | None = None
        self._mass_epoch = -1
        self.tolerance = 1e-9
        #: the last read of the whole space, with the position pass's moves patched in
        #: (sync-out reuses it: Simulation.out_read)
        self.raw: tuple[np.ndarray, np.ndarray] | None = None
        self.torqued: list[int] = []
        self.breakable: list[int] = []

    # -- structure ------------------------------------------------------------------
    def rebuild(self, handles: list[Revolute], tolerance: float = 0.0) -> None:
        """Take ``handles`` (live revolute joints whose bodies are in the space).

        ``tolerance``: pivot gaps below it are not projected (m; see
        ``ITERATED_PIVOT_TOLERANCE``).
        """
        self._clear()
        self.tolerance = max(tolerance, 1e-9)
        static = self.space.static_body
        slot: dict[pymunk.Body, int] = {static: 0}
        bodies = [static]
        recs: list[Any] = [None]
        pairs = []
        for h in handles:
            ends = []
            for body, ent in ((h.a, h.body_a), (h.b, h.body_b)):
                s = slot.get(body)
                if s is None:
                    s = slot[body] = len(bodies)
                    bodies.append(body)
                    recs.append(self.records.get(ent))
                ends.append(s)
            pairs.append((ends[0], ends[1]))
        self.handles = list(handles)
        self.components = comps = [h.component for h in handles]
        sets = [h.settings for h in handles]
        #: joints with a motor or a limit (pymunk's SimpleMotor / RotaryLimitJoint)
        self.motors = [k for k, j in enumerate(sets) if j.enable_motor]
        self.limits = [k for k, j in enumerate(sets) if j.enable_limit]
        self.torqued = sorted({*self.motors, *self.limits})
        self._motor_cs = [constraint_handle(handles[k].motor) for k in self.motors]  # type: ignore[arg-type]
        self._limit_cs = [constraint_handle(handles[k].limit) for k in self.limits]  # type: ignore[arg-type]
        where = {k: i for i, k in enumerate(self.torqued)}
        self._motor_rows = np.array([where[k] for k in self.motors], dtype=np.intp)
        self._limit_rows = np.array([where[k] for k in self.limits], dtype=np.intp)
        self._torqued_comps = [comps[k] for k in self.torqued]
        # the torques of a joint with no motor and no limit are zero: written once here
        plain = np.ones(len(handles), dtype=bool)
        plain[self.torqued] = False
        for k in np.flatnonzero(plain).tolist():
            raw_set(comps[k], "motor_torque", 0.0)
            raw_set(comps[k], "reaction_torque", 0.0)
            handles[k]._torque = 0.0
        #: the limits, widened by b2_angularSlop (the position pass leaves that much)
        limited = np.zeros(len(handles), dtype=bool)
        limited[self.limits] = True
        self.limited = limited
        self.lower = np.array([j.lower_angle - ANGULAR_SLOP if j.enable_limit else 0.0
                               for j in sets])
        self.upper = np.array([j.upper_angle + ANGULAR_SLOP if j.enable_limit else 0.0
                               for j in sets])
        #: joints with a break limit: their reaction size is kept for the break check
        self.breakable = [
            k for k, j in enumerate(comps)
            if j.break_force is not None or j.break_torque is not None
        ]
        # each field's setter: the slot's own (a C call) when all are one class
        kinds = {type(j) for j in comps}
        kind = kinds.pop() if len(kinds) == 1 else object  # object: raw_set each
        self._setters = {f: slot_setter(kind, f) for f in (
            "angle", "speed", "reaction_force", "motor_torque", "reaction_torque")}
        self.pivots = [constraint_handle(h.pivot) for h in handles]  # type: ignore[arg-type]
        self.bodies = bodies
        self.cbodies = [body_handle(b) for b in bodies]
        self.recs = recs
        self.ids = np.array([b.id for b in bodies[1:]], dtype=np.int64)
        self.ia = np.array([p[0] for p in pairs], dtype=np.intp)
        self.ib = np.array([p[1] for p in pairs], dtype=np.intp)
        dyn = np.array([is_dynamic(b) for b in bodies], dtype=bool)
        # the body whose momentum balance gives a reaction's direction: B, else A
        dyn_b = dyn[self.ib]
        self.sel = np.where(dyn_b, self.ib, self.ia)
        self.sign = np.where(dyn_b, 1.0, -1.0) * dyn[self.sel]
        self.refresh_anchors()
        self.refresh_mass()

    def refresh_anchors(self) -> None:
        """Local anchors and reference angles (changed only by ``apply``)."""
        hs = self.handles
        self.la = np.array([complex(*h.la) for h in hs], dtype=complex)
        self.lb = np.array([complex(*h.lb) for h in hs], dtype=complex)
        self.ref = np.array([h.ref for h in hs], dtype=float)

    def refresh_mass(self) -> None:
        n = len(self.bodies)
        im, ii, mass = np.zeros(n), np.zeros(n), np.zeros(n)
        cog = np.zeros(n, dtype=complex)
        for k, body in enumerate(self.bodies):
            im[k], ii[k] = inv_mass(body)
            if k:
                cb = body_handle(body)  # Chipmunk's getters: no Vec2d per read
                mass[k] = _get_mass(cb)
                c = _get_cog(cb)
                cog[k] = complex(c.x, c.y)
        self.im, self.ii, self.mass, self.cog = im, ii, mass, cog
        self.masses = [None if r is None else r.mass for r in self.recs]
        movable = (im != 0.0) | (ii != 0.0)
        colours = colour(list(zip(self.ia.tolist(), self.ib.tolist(), strict=True)),
                         movable.tolist())
        col = np.array(colours, dtype=np.intp)
        self.passes = [
            self._colour(np.flatnonzero(col == ci), movable)
            for ci in range(max(colours, default=-1) + 1)
        ]

    def _colour(self, idx: np.ndarray, movable: np.ndarray) -> _Colour:
        """The constant columns of one colour's joints, both ends stacked."""
        im, ii, cog = self.im, self.ii, self.cog
        a, b = self.ia[idx], self.ib[idx]
        ab = np.concatenate((a, b))
        lim = np.flatnonzero(self.limited[idx])
        lim = lim[ii[a[lim]] + ii[b[lim]] > 0.0]  # neither body can turn: nothing to do
        la_, lb_ = a[lim], b[lim]
        turning = ii[la_] + ii[lb_]
        ref = self.ref[idx[lim]]
        limit = (
            None if not len(lim)
            else (la_, lb_, self.lower[idx[lim]] + ref, self.upper[idx[lim]] + ref,
                  ii[la_] / turning, ii[lb_] / turning, cog[la_], cog[lb_])
        )
        ends = movable[ab]
        return _Colour(
            idx=idx, n=len(idx), ab=ab,
            arm=np.concatenate((self.la[idx], self.lb[idx])) - cog[ab],
            cog=cog[ab], inv_i=ii[ab], msum=im[a] + im[b],
            step_m=np.concatenate((-im[a], im[b])), step_i=np.concatenate((-ii[a], ii[b])),
            movable=ends, all_movable=bool(ends.all()), limit=limit,
        )

    def mass_changed(self, epoch: int) -> bool:
        """Whether a body's mass data was replaced since the last check.

        ``epoch`` counts the physics system's mass updates (any body's): the
        per-body comparison runs only when it moved, not every step.
        """
        if epoch == self._mass_epoch:
            return False
        self._mass_epoch = epoch
        return [None if r is None else r.mass for r in self.recs] != self.masses

    # -- reading ----------------------------------------------------------------------
    def read(self, raw: tuple[np.ndarray, np.ndarray] | None = None) -> np.ndarray | None:
        """(x, y, angle, vx, vy, w) of every slot (slot 0: the static body), or None
        when a body is no longer in the space.

        ``raw``: the (ids, rows) of a bulk read of the whole space that is still
        current (sync-out's, when nothing touched a body since), instead of a new one.
        """
        if raw is None:
            buf = self._buffer
            buf.clear()
            pb.get_space_bodies(self.space, FIELDS, buf)
            ids = np.frombuffer(buf.int_buf(), dtype=np.int64)
            rows = np.frombuffer(buf.float_buf(), dtype=np.float64).reshape(-1, 6)
        else:
            ids, rows = raw
        self.raw = (ids, rows)
        m = self._mapping
        if m is None or not np.array_equal(ids, m[0]):
            if len(ids) == 0:
                return None
            order = np.argsort(ids, kind="stable")
            pos = np.searchsorted(ids[order], self.ids)
            pos[pos >= len(ids)] = 0
            found = order[pos]
            if not np.array_equal(ids[found], self.ids):
                self._mapping = None
                return None
            m = self._mapping = (ids.copy(), found)
        out = np.empty((len(self.bodies), 6))
        out[1:] = rows[m[1]]
        s = self.space.static_body
        p = s.position
        out[0] = (p.x, p.y, s.angle, 0.0, 0.0, 0.0)
        return out

    def before_step(self, raw: tuple[np.ndarray, np.ndarray] | None = None) -> bool:
        """Remember the velocities (for the reactions' direction); False if stale."""
        state = self.read(raw)
        if state is None:
            return False
        self.v0 = state[:, 3:]
        return True

    # -- position pass ------------------------------------------------------------------
    def project(self, state: np.ndarray) -> list[int]:
        """Box2D's point projection over every joint, colour by colour.

        Updates ``state``'s poses and writes the bodies that moved to pymunk.
        Returns the joints (indices into ``handles``) found far apart (see ``JOLT``).
        """
        pos = state[:, 0] + 1j * state[:, 1]
        t = state[:, 2].copy()
        moved = np.zeros(len(self.bodies), dtype=bool)
        jolted: list[int] = []
        tol = self.tolerance
        for col in self.passes * SWEEPS:
            if col.limit is not None:
                self._limits(col.limit, pos, t, moved)
            n, ab = col.n, col.ab
            tt = t[ab]  # ends A then B: one call serves both
            e = np.exp(1j * tt)
            r = e * col.arm  # lever arms from the centres of gravity
            g = pos[ab] + e * col.cog  # centres of gravity
            w = g + r  # the anchors in the world
            c = w[n:] - w[:n]
            gap = np.abs(c)
            # the guards below cost a dozen numpy calls per colour; a settled or
            # everyday step needs none of them (largest gap under the clamp, none zero)
            top = gap.max()
            if top > JOLT * MAX_CORRECTION:
                jolted += col.idx[gap > JOLT * MAX_CORRECTION].tolist()
            if top > MAX_CORRECTION:
                c = np.where(gap > MAX_CORRECTION,
                             c * (MAX_CORRECTION / np.maximum(gap, 1e-300)), c)
            rx, ry = r.real, r.imag
            wx, wy = col.inv_i * rx, col.inv_i * ry
            k_yy, k_xx, k_xy = wy * ry, wx * rx, wx * ry
            k11 = col.msum + k_yy[:n] + k_yy[n:]
            k12 = -(k_xy[:n] + k_xy[n:])
            k22 = col.msum + k_xx[:n] + k_xx[n:]
            det = k11 * k22 - k12 * k12
            cx, cy = c.real, c.imag
            p = (k12 * cy - k22 * cx) + 1j * (k12 * cx - k11 * cy)
            act = col.movable
            if gap.min() >= tol and np.abs(det).min() >= 1e-12:
                p = p / det
                every = col.all_movable
            else:  # joints within the tolerance (or degenerate) move nothing
                ok = (gap >= tol) & (np.abs(det) >= 1e-12)
                if not ok.any():
                    continue
                p = np.where(ok, p / np.where(ok, det, 1.0), 0.0)
                act = act & np.concatenate((ok, ok))
                every = False
            pp = np.concatenate((p, p))  # P at B's anchor, -P at A's (in step_m, step_i)
            new_t = tt + col.step_i * (rx * pp.imag - ry * pp.real)
            new_pos = g + col.step_m * pp - np.exp(1j * new_t) * col.cog
            if every:  # no body appears twice among a colour's movable ends
                t[ab], pos[ab] = new_t, new_pos
                moved[ab] = True
            else:
                s = ab[act]
                t[s], pos[s] = new_t[act], new_pos[act]
                moved[s] = True
        idx = np.flatnonzero(moved)
        if not len(idx):
            return jolted
        state[:, 0], state[:, 1], state[:, 2] = pos.real, pos.imag, t
        angles = t[idx]
        moved_bodies = list(map(self.cbodies.__getitem__, idx.tolist()))
        # each body's angle before its origin (Chipmunk turns a body about its centre
        # of gravity); bodies are independent, so every angle, then every origin: two
        # C loops instead of a Python frame per body
        set_all(_set_angle, moved_bodies, angles.tolist())
        set_all(_set_position, moved_bodies, zip(pos.real[idx].tolist(),
                                                 pos.imag[idx].tolist(), strict=True))
        # Chipmunk's origin is (x, y) to the last bit, or not: read it back. When most
        # of the space moved, one bulk read of every body beats a getter per body
        raw = self.raw
        if raw is not None and self._mapping is not None and 4 * len(idx) >= len(raw[0]):
            ids, rows = self._reader.read(self.space)
            if np.array_equal(ids, raw[0]):  # the rows the mapping was made for
                self.raw = (ids.copy(), rows.copy())  # (the reader's buffer is reused)
                return jolted
        got = list(map(_get_position, moved_bodies))
        self._patch(idx, [p.x for p in got], [p.y for p in got], angles)
        return jolted

    def _patch(self, idx: np.ndarray, xs: list[float], ys: list[float],
               angles: np.ndarray) -> None:
        """Put the moved bodies' poses into :attr:`raw` (a copy: the buffer is reused)."""
        if self.raw is None or self._mapping is None:
            return
        ids, rows = self.raw
        rows = rows.copy()
        at = self._mapping[1][idx - 1]  # slot k >= 1 is row found[k - 1]
        rows[at, 0] = xs
        rows[at, 1] = ys
        rows[at, 2] = angles
        self.raw = (ids, rows)

    @staticmethod
    def _limits(limit: tuple[Any, ...], pos: np.ndarray, t: np.ndarray,
                moved: np.ndarray) -> None:
        """Box2D's angular limit projection for one colour's limited joints: each
        hinge angle outside its (slop-widened) range turns both bodies about their
        centres of gravity, shared by inverse inertia, by at most 8° per step."""
        a, b, lower, upper, fa, fb, ca, cb = limit  # bounds on θb - θa (reference added)
        turn = t[b] - t[a]
        below, above = turn < lower, turn > upper
        if not (below.any() or above.any()):
            return  # the everyday case: every hinge within its limits
        out = np.flatnonzero(below | above)
        turn = turn[out]
        error = np.where(below[out], turn - lower[out], turn - upper[out])
        error = np.minimum(np.maximum(error, -MAX_ANGULAR_CORRECTION), MAX_ANGULAR_CORRECTION)
        # both ends at once (no movable body appears twice in a colour): A turns by
        # +fa*error, B by -fb*error, each about its centre of gravity
        s = np.concatenate((a[out], b[out]))
        turn = np.concatenate((fa[out] * error, -fb[out] * error))
        cog = np.concatenate((ca[out], cb[out]))
        live = turn != 0.0  # a body that cannot turn stays put
        if not live.all():
            s, turn, cog = s[live], turn[live], cog[live]
        g = pos[s] + np.exp(1j * t[s]) * cog
        t[s] = t[s] + turn
        pos[s] = g - np.exp(1j * t[s]) * cog
        moved[s] = True

    # -- read-back ------------------------------------------------------------------------
    def read_back(self, state: np.ndarray, dt: float, step_time: float, gravity: Any) -> None:
        """Write angle, speed, reactions and torques into every joint's component.

        The torques of joints with no motor and no limit are zero (written at
        ``rebuild``); the others' are pymunk's last substep impulses over its time.
        """
        t, w = state[:, 2], state[:, 5]
        ia, ib = self.ia, self.ib
        n = len(ia)
        # body B's momentum balance over the step (A's, negated, when B cannot move)
        sel = self.sel
        v0 = self.v0
        if v0 is None or dt <= 0:
            bx = by = np.zeros(n)
        else:
            m = self.mass[sel] * self.sign
            bx = m * (state[sel, 3] - v0[sel, 0] - gravity[0] * dt)
            by = m * (state[sel, 4] - v0[sel, 1] - gravity[1] * dt)
        norm = np.hypot(bx, by)
        big = norm > 1e-12
        force = np.fromiter(map(_get_impulse, self.pivots), dtype=float, count=n)
        force *= 1.0 / step_time
        f = np.where(big, force / np.where(big, norm, 1.0), 0.0)
        comps = self.components
        angle = (t[ib] - t[ia] - self.ref).tolist()
        speed = (w[ib] - w[ia]).tolist()
        reaction = zip((f * bx).tolist(), (f * by).tolist(), strict=True)
        self._write(comps, "angle", angle)
        self._write(comps, "speed", speed)
        self._write(comps, "reaction_force", reaction)
        torque = self._torques(step_time) if self.torqued else None
        if self.breakable:
            hs = self.handles
            for k in self.breakable:
                hs[k]._force = float(force[k])
            if torque is not None:
                where = dict(zip(self.torqued, np.abs(torque).tolist(), strict=True))
                for k in self.breakable:
                    hs[k]._torque = where.get(k, 0.0)

    def _torques(self, step_time: float) -> np.ndarray:
        """Write the motor and limit torques (Box2D's sign: on body B) of the joints
        that have them; returns the limit torques (the break check's)."""
        n = len(self.torqued)
        motor, limit = np.zeros(n), np.zeros(n)
        scale = -1.0 / step_time
        if self._motor_cs:
            motor[self._motor_rows] = np.fromiter(
                map(_get_impulse, self._motor_cs), dtype=float, count=len(self._motor_cs))
            motor *= scale
        if self._limit_cs:
            limit[self._limit_rows] = np.fromiter(
                map(_get_impulse, self._limit_cs), dtype=float, count=len(self._limit_cs))
            limit *= scale
        self._write(self._torqued_comps, "motor_torque", motor.tolist())
        self._write(self._torqued_comps, "reaction_torque", limit.tolist())
        return limit

    def _write(self, comps: list[Any], field: str, values: Any) -> None:
        """Set ``field`` of each component (no validation, no dirty mark), in a C loop."""
        set_all(self._setters[field], comps, values)
