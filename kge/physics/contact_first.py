"""Velocities set between steps meet the contacts before they move anything.

Box2D steps in the order *solve velocities, then integrate positions*: a velocity
written with ``SetLinearVelocity`` (or changed by an impulse) between two steps
first goes through the contact solver, which takes out whatever part of it
drives the body into what it touches (and applies the friction that pressing
allows, and hands momentum to what the body pushes), and only then moves the
body. Chipmunk steps the other way round (``cpSpaceStep``: integrate positions,
find contacts, solve): the first substep after a write moved the body by
``v * h`` into the wall before any contact saw the velocity, and the contact's
bias pushed back only part of that, so a character walking into a wall settled
0.22 m deep at 6 m/s and went through a 3 m wall with one substep. Letting
Chipmunk's solver absorb the write inside the first substep instead is not
enough either: the impulse it takes (the whole written momentum, every step)
warm-starts the following substeps, which must undo it, and a crate squeezed
between a fast character and a wall was kicked loose within a few steps.

So the velocities set from outside get Box2D's order back here, before the
first substep. A body whose velocity was written or changed by an impulse since
the last step is *pushed* (the simulation marks it). The pushed bodies and the
dynamic bodies they touch (an island grown through contacts, up to
:data:`MAX_BODIES`) are solved against the contacts Chipmunk's solver used in
the last substep (the arbiters threaded on them, with their current
separations): sequential impulses with Chipmunk's own rules (no overlap may
grow, a gap may close; friction up to ``friction * normal impulse``; surface
velocities), the bodies' masses and inertia, static and kinematic bodies
immovable. The island's velocities leave with what the contacts allow, and the
step then runs as usual: its solver finds the contacts already satisfied, so
no large impulse is cached for the next substeps.

Bodies that nothing pushed cost nothing; a pushed body that touches nothing
costs a look at its (empty) contact list (and many pushed bodies one bulk read of
the space's contacts). The work is bounded: an island stops growing at
:data:`MAX_BODIES` and the passes at :data:`BUDGET` point solves, so pushing into a
large pile leaves its far side to the step's own solver, as before.
"""

from __future__ import annotations

import math
from typing import Any

import pymunk

from kge.physics.cp import arbiter_handle, body_handle
from kge.physics.cp import ffi as _ffi
from kge.physics.cp import lib as _lib
from kge.physics.cp.bulk import ArbiterBodies

_DYNAMIC = _lib.CP_BODY_TYPE_DYNAMIC
_from_handle = _ffi.from_handle
#: most dynamic bodies solved together around the pushed ones (the rest of a
#: pile is left to the step's own solver)
MAX_BODIES = 8
#: most passes over the island's contact points (fewer when nothing changes): a
#: character pressing a crate into a wall needs about 30 to settle the chain
PASSES = 40
#: most point solves per step (passes x points): pushing into a pile costs at most
#: about a millisecond; what remains is left to the step's solver
BUDGET = 320
#: an impulse below this (N s per kg of effective mass) counts as no change
_QUIET = 1e-9
#: above this many pushed bodies, a bulk read of the contacts screens them first
FEW = 8


class _Body:
    """One body of the island: its velocity and inverse mass as the solve goes."""

    __slots__ = ("cp", "cx", "cy", "ii", "im", "vx", "vx0", "vy", "vy0", "w", "w0")

    def __init__(self, cp: Any, dynamic: bool) -> None:
        self.cp = cp
        v = _lib.cpBodyGetVelocity(cp)
        self.vx = self.vx0 = v.x
        self.vy = self.vy0 = v.y
        self.w = self.w0 = _lib.cpBodyGetAngularVelocity(cp)
        c = _lib.cpBodyLocalToWorld(cp, _lib.cpBodyGetCenterOfGravity(cp))
        self.cx, self.cy = c.x, c.y
        if dynamic:
            self.im = 1.0 / _lib.cpBodyGetMass(cp)
            moment = _lib.cpBodyGetMoment(cp)
            self.ii = 0.0 if math.isinf(moment) else 1.0 / moment
        else:
            self.im = self.ii = 0.0


class _Point:
    """One contact point: Chipmunk's normal and friction rows."""

    __slots__ = (
        "a", "b", "jn", "jt", "least", "n_mass", "nx", "ny", "r1n", "r1t", "r1x", "r1y",
        "r2n", "r2t", "r2x", "r2y", "svx", "svy", "t_mass", "u",
    )

    def __init__(self, a: _Body, b: _Body, nx: float, ny: float, px: float, py: float,
                 gap: float, u: float, sv: tuple[float, float], inv_h: float) -> None:
        self.a, self.b = a, b
        self.nx, self.ny = nx, ny
        self.r1x, self.r1y = px - a.cx, py - a.cy
        self.r2x, self.r2y = px - b.cx, py - b.cy
        # cross products with the normal and the tangent t = (-ny, nx)
        self.r1n = self.r1x * ny - self.r1y * nx
        self.r2n = self.r2x * ny - self.r2y * nx
        self.r1t = self.r1x * nx + self.r1y * ny
        self.r2t = self.r2x * nx + self.r2y * ny
        kn = a.im + b.im + a.ii * self.r1n * self.r1n + b.ii * self.r2n * self.r2n
        kt = a.im + b.im + a.ii * self.r1t * self.r1t + b.ii * self.r2t * self.r2t
        self.n_mass = 1.0 / kn if kn > 0.0 else 0.0
        self.t_mass = 1.0 / kt if kt > 0.0 else 0.0
        # the least normal speed allowed: a gap may close within the substep
        self.least = -gap * inv_h if gap > 0.0 else 0.0
        self.u = u
        self.svx, self.svy = sv
        self.jn = self.jt = 0.0

    def solve(self) -> bool:
        a, b = self.a, self.b
        nx, ny = self.nx, self.ny
        # relative velocity of b's point over a's (plus the surface velocity)
        rvx = (b.vx - b.w * self.r2y) - (a.vx - a.w * self.r1y) + self.svx
        rvy = (b.vy + b.w * self.r2x) - (a.vy + a.w * self.r1x) + self.svy
        vn = rvx * nx + rvy * ny
        vt = -rvx * ny + rvy * nx
        jn_old = self.jn
        jn = max(jn_old + (self.least - vn) * self.n_mass, 0.0)
        self.jn = jn
        dn = jn - jn_old
        limit = self.u * jn
        jt_old = self.jt
        jt = min(max(jt_old - vt * self.t_mass, -limit), limit)
        self.jt = jt
        dt = jt - jt_old
        if abs(dn) < _QUIET and abs(dt) < _QUIET:
            return False
        # impulse dn along n plus dt along t = (-ny, nx), on b; minus on a
        jx = nx * dn - ny * dt
        jy = ny * dn + nx * dt
        rn_a = self.r1n * dn + self.r1t * dt  # r1 x j
        rn_b = self.r2n * dn + self.r2t * dt
        a.vx -= jx * a.im
        a.vy -= jy * a.im
        a.w -= rn_a * a.ii
        b.vx += jx * b.im
        b.vy += jy * b.im
        b.w += rn_b * b.ii
        return True


class ContactFirst:
    """Pushed bodies of one space, solved against their contacts before a step."""

    def __init__(self) -> None:
        #: entity -> body pushed since the last step
        self.pushed: dict[int, pymunk.Body] = {}
        #: the Chipmunk bodies pushed before the current step: their new contacts get a
        #: time of impact against dynamic bodies too (kge.physics.impact)
        self.current: set[Any] = set()
        self._pair = (_ffi.new("cpBody *[1]"), _ffi.new("cpBody *[1]"))
        self._arbiters = ArbiterBodies()

    def push(self, entity: int, body: pymunk.Body) -> None:
        """``body`` got a velocity from outside the solver (a write, an impulse)."""
        self.pushed[entity] = body

    def end_step(self) -> None:
        """The step is over: no body counts as pushed any more."""
        if self.current:
            self.current.clear()

    def solve(self, space: pymunk.Space, h: float, iterations: int = PASSES) -> bool:
        """Solve the pushed bodies' islands against their contacts (``h``: the substep).

        Returns True when a velocity changed (bulk reads taken before are stale).
        """
        pushed, self.pushed = self.pushed, {}
        current = self.current
        current.clear()
        seeds = []
        for e in sorted(pushed):
            body = pushed[e]
            if body.space is not space:
                continue
            cp = body_handle(body)
            if _lib.cpBodyGetType(cp) != _DYNAMIC or _lib.cpBodyIsSleeping(cp):
                continue
            current.add(cp)
            seeds.append(body)
        if not seeds:
            return False
        if len(seeds) > FEW:
            # many pushed bodies (a batch of thrusters): only those with a contact
            # need their contact list walked; one bulk read tells which may have one
            touching = set(self._arbiters.read(space).tolist())
            seeds = [b for b in seeds if b.id in touching]
            if not seeds:
                return False
        points, bodies = self._island(seeds, 1.0 / h)
        if not points:
            return False
        passes = max(2, min(iterations, BUDGET // len(points)))
        for _ in range(passes):
            moved = False
            for p in points:
                moved = p.solve() or moved
            if not moved:
                break
        changed = False
        for b in bodies:
            if b.im == 0.0 and b.ii == 0.0:
                continue
            if (b.vx, b.vy) != (b.vx0, b.vy0):
                _lib.cpBodySetVelocity(b.cp, (b.vx, b.vy))
                changed = True
            if b.w != b.w0:
                _lib.cpBodySetAngularVelocity(b.cp, b.w)
                changed = True
        return changed

    def _island(self, seeds: list[pymunk.Body], inv_h: float) -> tuple[list[_Point], list[_Body]]:
        """The contact points of the pushed bodies and of the dynamic bodies they
        touch, breadth first, in a deterministic order."""
        found: dict[Any, _Body] = {}
        points: list[_Point] = []
        seen_arbiters: set[Any] = set()
        a_p, b_p = self._pair
        queue: list[pymunk.Body] = []
        for body in seeds:
            found[body_handle(body)] = _Body(body_handle(body), True)
            queue.append(body)
        expanded = 0

        def body_of(cp: Any) -> _Body:
            rec = found.get(cp)
            if rec is None:
                rec = found[cp] = _Body(cp, _lib.cpBodyGetType(cp) == _DYNAMIC)
                if rec.im and len(queue) < MAX_BODIES:
                    queue.append(_from_handle(_lib.cpBodyGetUserData(cp)))
            return rec

        def visit(arb: pymunk.Arbiter) -> None:
            ca = arbiter_handle(arb)
            if ca in seen_arbiters:
                return
            seen_arbiters.add(ca)
            _lib.cpArbiterGetBodies(ca, a_p, b_p)
            a, b = body_of(a_p[0]), body_of(b_p[0])
            cps = _lib.cpArbiterGetContactPointSet(ca)
            n = cps.normal  # from a to b
            u = _lib.cpArbiterGetFriction(ca)
            sv = _lib.cpArbiterGetSurfaceVelocity(ca)
            for i in range(cps.count):
                p = cps.points[i]
                px = 0.5 * (p.pointA.x + p.pointB.x)
                py = 0.5 * (p.pointA.y + p.pointB.y)
                points.append(_Point(a, b, n.x, n.y, px, py, p.distance, u, (sv.x, sv.y), inv_h))

        while expanded < len(queue):
            body = queue[expanded]
            expanded += 1
            body.each_arbiter(visit)
        return points, list(found.values())
