"""The swept integrator of one tracked body: its ``position_func`` while armed.

Chipmunk calls ``position_func`` once per substep to move a body by its
velocity. An armed body's :class:`Tracked` instead sweeps the body's points
(:mod:`kge.physics.ccd.parts`) along that motion against the shapes it could
hit, stops at the earliest impact and keeps its velocity, so the contact solver
of the same substep resolves the collision as for any other contact. An
exception raised here is kept by the owner's ``errors`` and raised after the
step (cffi would swallow it).

Most calls are an armed body that is not fast in this substep (a neighbour
armed in case a collision launches it): it reads its velocity through
Chipmunk's getters, finds its motion under the threshold and calls Chipmunk's
own integrator, with no Vec2d or pymunk wrapper in between.
"""

from __future__ import annotations

import math
from collections.abc import Iterable
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import pymunk

from kge.physics.ccd.parts import Part
from kge.physics.cp import body_constraints, body_handle, shape_handle
from kge.physics.cp import lib as _lib
from kge.physics.speed_cap import clamp_one

if TYPE_CHECKING:
    from kge.physics.ccd.manager import ContinuousCollision
    from kge.physics.ccd.obstacles import Nearby


#: (fraction, carry dx, carry dy, hold normal or None), see Tracked._time_of_impact
_Impact = tuple[float, float, float, tuple[float, float] | None]
_ALL = pymunk.ShapeFilter()
_DYNAMIC = pymunk.Body.DYNAMIC
_KINEMATIC = pymunk.Body.KINEMATIC
_STATIC = pymunk.Body.STATIC
_PLAIN = pymunk.Body.update_position
_shape_bb = _lib.cpShapeGetBB
_update_position = _lib.cpBodyUpdatePosition
#: largest rotation (rad) swept as one straight chord (sagitta <= 0.5 % of the reach)
_MAX_CHORD = 0.2


@dataclass(slots=True, eq=False)
class Tracked:
    """A tracked dynamic body; when armed it *is* the body's ``position_func``."""

    owner: ContinuousCollision
    body: pymunk.Body
    bullet: bool
    parts: list[Part]
    core: float
    reach: float
    shapes: tuple[pymunk.Shape, ...] = ()
    #: radius about the body's origin that holds every shape's bounding box
    extent: float = math.inf
    saved: Any = None  # the position_func to restore when disarmed
    armed: bool = False
    sweeps: int = 0  # sweeps run (statistics for benchmarks)
    impacts: int = 0  # sweeps that stopped the body early
    #: this step's motion (m) of the fastest body that may hit this one: a kinematic
    #: body, or for a bullet any fast body
    boost: float = 0.0
    #: shapes in an accepted contact with the body after the last substep's solve,
    #: recorded by a post-step callback whenever the body swept near obstacles
    contacts: frozenset[pymunk.Shape] = frozenset()
    fresh: bool = False

    def __reduce__(self) -> tuple[Any, tuple[Any, ...]]:
        # A copied or pickled space (save games) gets pymunk's plain integrator:
        # the ContinuousCollision that owns this sweep belongs to the live space.
        return (getattr, (pymunk.Body, "update_position"))

    def __call__(self, body: pymunk.Body, dt: float) -> None:
        try:
            self._move(body, dt)
        except Exception as exc:  # pymunk called this from C: kept for after the step
            self.owner.errors.keep(exc)

    def _move(self, body: pymunk.Body, dt: float) -> None:
        owner = self.owner
        known = self.contacts if self.fresh else None  # valid for this substep only
        self.fresh = False
        # read through Chipmunk's getters (body.velocity builds a Vec2d): most calls
        # end at the first test below, an armed body that is not fast this substep
        cp = body_handle(body)
        v = _lib.cpBodyGetVelocity(cp)
        vx, vy = v.x, v.y
        w = _lib.cpBodyGetAngularVelocity(cp)
        step_dt = owner.step_dt
        # Box2D caps the speed after every solve; collisions inside a step can
        # exceed it, so an armed body is capped again before each substep.
        vmax, wmax = owner.max_translation / step_dt, owner.max_rotation / step_dt
        if math.hypot(vx, vy) > vmax or abs(w) > wmax:  # clamp_one's own tests
            nv, nw = clamp_one(vx, vy, w, vmax, wmax)
            if nv is not None:
                body.velocity = nv
                vx, vy = nv
            if nw is not None:
                body.angular_velocity = w = nw
        da = w * dt
        dx, dy = vx * dt, vy * dt
        integrate = self.saved
        others = self.boost * dt / step_dt
        own = math.hypot(dx, dy) + abs(da) * self.reach
        if own + others <= owner.threshold * self.core:
            if integrate is _PLAIN:
                _update_position(cp, dt)  # what pymunk's update_position calls
            else:
                integrate(body, dt)
            return
        self.sweeps += 1
        if self.bullet:  # dynamic obstacles may close in at up to the speed cap
            others = max(others, owner.max_translation * dt / owner.step_dt)
        impact = self._time_of_impact(body, dx, dy, da, others, dt, known)
        if impact is None:
            integrate(body, dt)
            return
        self.impacts += 1
        t, odx, ody, hold = impact
        if hold is not None:
            # driven deep into an obstacle it touches: hold still for this substep and
            # take out the approaching velocity, as the contact would
            nx, ny = hold
            vn = vx * nx + vy * ny
            if vn < 0.0:
                body.velocity = (vx - vn * nx, vy - vn * ny)
            integrate(body, 0.0)
            return
        if not (odx or ody):
            integrate(body, dt * t)  # stop at the impact; the velocity is kept
            return
        # A moving obstacle carries the body for the rest of the substep - but never
        # through static geometry: the whole displacement is swept against it again.
        mx, my = dx * t + (1.0 - t) * odx, dy * t + (1.0 - t) * ody
        again = self._time_of_impact(body, mx, my, da * t, 0.0, dt, known, static_only=True)
        k = 1.0 if again is None else again[0]
        x0, y0 = body.local_to_world(body.center_of_gravity)
        integrate(body, dt * t * k)  # own motion and rotation up to the impact
        x1, y1 = body.local_to_world(body.center_of_gravity)
        ox, oy = body.position
        body.position = (ox + x0 + mx * k - x1, oy + y0 + my * k - y1)

    def _time_of_impact(
        self,
        body: pymunk.Body,
        dx: float,
        dy: float,
        da: float,
        others: float,
        dt: float,
        known: frozenset[pymunk.Shape] | None,
        static_only: bool = False,
    ) -> _Impact | None:
        """Earliest fraction of this motion at which a shrunk shape touches an obstacle.

        Returns (fraction, displacement by which the obstacle carries the body for
        the rest of the substep - zero unless it is sure to complete its motion -,
        hold normal) or None. A hold normal is
        set when a guard - a circle deep inside a shape - already touches an
        obstacle and is driven into it: the contact solver failed to stop the
        body (it is being crushed, or spins into the obstacle), so it must not
        move further in.

        Moving obstacles are swept against in their own frame (relative
        translation; their rotation within a substep is ignored). ``others``
        bounds how far they may move in this substep.
        """
        space = body.space
        box = self._bounds()
        if space is None or box is None:
            return None
        swept = grown(
            pymunk.BB(
                min(box.left, box.left + dx),
                min(box.bottom, box.bottom + dy),
                max(box.right, box.right + dx),
                max(box.top, box.top + dy),
            ),
            abs(da) * self.reach + others,
        )
        nearby = space.bb_query(swept, _ALL)
        if not nearby:
            return None
        joint_free = JointFree(body)
        obstacles = []
        for s in nearby:
            if self._is_obstacle(s, joint_free):
                ob = s.body
                if static_only and ob is not None and ob.body_type != _STATIC:
                    continue
                ov = ob.velocity if ob is not None and ob.body_type != _STATIC else (0.0, 0.0)
                # A moving obstacle that completes its motion carries what it hits:
                # a kinematic body always; a dynamic one unless it is a bullet too
                # (then both stop at their common time of impact instead).
                carries = ob is not None and (
                    ob.body_type == _KINEMATIC
                    or (ob.body_type == _DYNAMIC and not self.owner._is_bullet(ob))
                )
                flt = self.owner.shapes.filter_of(s)
                obstacles.append((s, s.bb, flt, ov[0] * dt, ov[1] * dt, carries))
        if not obstacles:
            return None

        # Points move with the centre of gravity plus a rotation about it. A spinning
        # body's points move on arcs: the sweep follows them as chords of at most
        # _MAX_CHORD radians, so a corner never bulges more than a few mm past them.
        px, py = body.position
        a0 = body.angle
        gx, gy = body.center_of_gravity
        cx = px + math.cos(a0) * gx - math.sin(a0) * gy
        cy = py + math.sin(a0) * gx + math.cos(a0) * gy
        pieces = max(1, math.ceil(abs(da) / _MAX_CHORD))
        poses = []
        for j in range(pieces + 1):
            f = j / pieces
            a = a0 + da * f
            poses.append((f, cx + dx * f, cy + dy * f, math.cos(a), math.sin(a)))
        pair_filter = self.owner.pair_filter
        touching = 0.25 * self.owner.margin
        gentle = self.owner.threshold * self.core
        best: _Impact | None = None
        recording = False
        for part in self.parts:
            own = part.shape
            if own.sensor:
                continue
            own_filter = self.owner.shapes.filter_of(own)
            targets = [
                (o, bb, odx, ody, carries)
                for o, bb, f, odx, ody, carries in obstacles
                if own_filter.collides_with(f)
            ]
            for lx, ly, radius, guard in part.points:
                rx, ry = lx - gx, ly - gy
                path = [
                    (f, qx + c * rx - sn * ry, qy + sn * rx + c * ry) for f, qx, qy, c, sn in poses
                ]
                for other, bb, odx, ody, carries in targets:
                    for j in range(pieces):
                        f0, x0, y0 = path[j]
                        f1, x1, y1 = path[j + 1]
                        if best is not None and f0 >= best[0]:
                            break
                        # the chord in the obstacle's frame (it moves by odx, ody per substep)
                        sx, sy = x0 - odx * f0, y0 - ody * f0
                        tx, ty = x1 - odx * f1, y1 - ody * f1
                        if (
                            min(sx, tx) - radius > bb.right
                            or max(sx, tx) + radius < bb.left
                            or min(sy, ty) - radius > bb.top
                            or max(sy, ty) + radius < bb.bottom
                        ):
                            continue
                        if not recording:
                            # close to something: record which contacts the world
                            # accepts, for the next substep's guard test
                            recording = True
                            space.add_post_step_callback(self._record_contacts, id(self))
                        info = other.segment_query((sx, sy), (tx, ty), radius)
                        if info is None or info.shape is None:
                            continue
                        t = f0 + (f1 - f0) * info.alpha
                        if best is not None and t >= best[0]:
                            break
                        nx, ny = info.normal
                        approach = -(nx * (tx - sx) + ny * (ty - sy))
                        if approach <= 0.0:
                            continue  # moving away from (or along) that surface
                        one_way = self.owner.shapes.oneway_of(other)
                        if one_way is not None:
                            (ux, uy), min_cos = one_way
                            if nx * ux + ny * uy < min_cos:
                                break  # arriving from the platform's open side
                        if pair_filter is not None and not pair_filter(own, other):
                            break
                        carry = (odx, ody) if carries else (0.0, 0.0)
                        if j == 0 and info.alpha * math.hypot(tx - sx, ty - sy) <= touching:
                            # Already touching: the real outline overlaps, so this is
                            # the contact solver's job - unless a guard touches and is
                            # driven in (see above) through a contact the world has
                            # accepted. Had it rejected it (a pre-solve hook), there
                            # would be no arbiter and the body passes on.
                            accepted = known is None or other in known
                            if guard and approach * pieces > gentle and accepted:
                                best = (0.0, *carry, (nx, ny))
                            break
                        best = (t, *carry, None)
                        break
        return best

    def _record_contacts(self, space: pymunk.Space, key: Any) -> None:
        """Post-step: the shapes the solver just treated as touching this body."""
        body = self.body
        found: set[pymunk.Shape] = set()

        def visit(arb: pymunk.Arbiter) -> None:
            a, b = arb.shapes
            found.add(b if a.body is body else a)

        try:
            body.each_arbiter(visit)
        except Exception as exc:  # called from C, like __call__
            self.owner.errors.keep(exc)
            return
        self.contacts = frozenset(found)
        self.fresh = True

    def _bounds(self) -> pymunk.BB | None:
        """The body's current bounding box (its shapes' cached BBs)."""
        box = bounds_of(self.shapes)
        return None if box is None else pymunk.BB(*box)

    def near_obstacles(self, motion: float, near: Nearby | None = None) -> bool:
        """Could anything stop this body within ``motion`` metres, in any direction?

        Static shapes are tested against the body's box grown by ``motion``;
        moving ones (kinematic, or dynamic for bullets) may approach by up to
        their own step motion too, so the search is widened by the speed cap.
        A non-bullet asks the owner's index of static and kinematic shapes
        (the only ones that can stop it), never walking the dynamic shapes
        around it; a bullet, which every body can stop, asks the space.
        ``near``: obstacle rows already found around the body (see
        :meth:`~kge.physics.ccd.obstacles.Obstacles.candidates`).
        """
        edges = bounds_of(self.shapes)
        space = self.body.space
        if edges is None or space is None:
            return False
        box = pymunk.BB(*edges)
        reach = motion + self.owner.max_translation
        shapes: Iterable[pymunk.Shape]
        if self.bullet:
            shapes = space.bb_query(grown(box, reach), _ALL)
        else:  # one at a time: the first obstacle in reach ends the search
            shapes = self.owner._obstacles.iter_candidates(box, motion, reach, near)
        joint_free = JointFree(self.body)
        left, bottom, right, top = edges
        for shape in shapes:
            if not self._is_obstacle(shape, joint_free):
                continue
            moving = shape.body is not None and shape.body.body_type != pymunk.Body.STATIC
            g = reach if moving else motion
            # grown(box, g).intersects(shape.bb), without building either BB
            bb = _shape_bb(shape_handle(shape))
            if left - g <= bb.r and bb.l <= right + g and bottom - g <= bb.t and bb.b <= top + g:
                return True
        return False

    def _is_obstacle(self, shape: pymunk.Shape, joint_free: JointFree) -> bool:
        other = shape.body
        if other is self.body or other is None or shape.sensor:
            return False
        if other.body_type == _DYNAMIC and not self.bullet:
            return False
        return other not in joint_free


def bounds_of(shapes: tuple[pymunk.Shape, ...]) -> tuple[float, float, float, float] | None:
    """The merged cached BBs of ``shapes`` as (left, bottom, right, top); None for none.

    Read through Chipmunk's getter and merged as ``cpBBMerge`` does (its min and max
    keep the second operand unless the first is smaller, resp. larger, also for a
    NaN), so the result equals ``shape.bb.merge(...)`` without building a BB per shape.
    """
    box = None
    for shape in shapes:
        bb = _shape_bb(shape_handle(shape))
        if box is None:
            box = (bb.l, bb.b, bb.r, bb.t)
            continue
        left, bottom, right, top = box
        box = (
            left if left < bb.l else bb.l,
            bottom if bottom < bb.b else bb.b,
            right if right > bb.r else bb.r,
            top if top > bb.t else bb.t,
        )
    return box


def grown(box: pymunk.BB, by: float) -> pymunk.BB:
    return pymunk.BB(box.left - by, box.bottom - by, box.right + by, box.top + by)


class JointFree:
    """:func:`joint_free_bodies` of ``body``, computed on the first ``in`` that needs it.

    Most obstacles (the ground, walls, a tile map's static bodies) are joined to
    nothing, and a body joined to nothing cannot be joined to ``body``: pymunk
    records every constraint on both of its bodies (``body_constraints``), so
    ``other in joint_free`` answers False from ``other``'s own record without
    walking ``body``'s constraints (about 9 µs for a jointed leg) or any cffi call.

    >>> a, b, c = pymunk.Body(1, 1), pymunk.Body(1, 1), pymunk.Body(1, 1)
    >>> pivot = pymunk.PivotJoint(a, b, (0, 0)); pivot.collide_bodies = False
    >>> free = JointFree(a)
    >>> b in free, c in free, a in free
    (True, False, False)
    """

    __slots__ = ("_bodies", "_start")

    def __init__(self, body: pymunk.Body) -> None:
        self._start = body
        self._bodies: set[pymunk.Body] | None = None

    def __contains__(self, other: pymunk.Body) -> bool:
        if not body_constraints(other):  # joined to nothing, so not to ``body``
            return False
        bodies = self._bodies
        if bodies is None:
            bodies = self._bodies = joint_free_bodies(self._start)
        return other in bodies


def joint_free_bodies(body: pymunk.Body) -> set[pymunk.Body]:
    """Bodies joined to ``body`` by a constraint that disables their collision."""
    out: set[pymunk.Body] = set()
    for c in body.constraints:
        if not c.collide_bodies:
            out.add(c.b if c.a is body else c.a)
    return out
