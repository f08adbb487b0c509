"""Continuous collision for pymunk: Box2D's speed caps and time-of-impact sweeps.

pymunk moves every body by ``v*dt`` and only then looks for overlaps, so a
body that travels further than its own thickness in one step can jump clean
over a thin wall (tunnelling). Box2D 2.3 prevents that with two rules, which
this module reproduces:

* **speed caps**: a body moves at most ``max_translation`` (2 m) and rotates at
  most ``max_rotation`` (pi/2) per fixed step, and the *clamped velocity is
  kept* (120 m/s and 94.25 rad/s at 60 Hz);
* **time of impact**: a dynamic body never passes through static or kinematic
  geometry, and a ``bullet`` body never passes through dynamic bodies either.
  Ordinary dynamic bodies may tunnel through each other, as in Box2D (that is
  what the bullet flag is for).

How: :class:`ContinuousCollision` reads every body's pose and velocity once
per step with ``pymunk.batch`` (about 0.5 ms for 20,000 bodies), clamps the few
that exceed the caps, and *arms* a swept integrator - a pymunk
``position_func`` - only on tracked dynamic bodies that move more than
``threshold`` times their core radius per substep *and* have something they
could hit within reach, on the neighbours such a body could launch, and on
bodies a fast kinematic body is about to sweep over. All other bodies keep
pymunk's C integrator, so a scene of slow bodies pays nothing but the read.
"Within reach" is answered by a numpy index of the static and kinematic
shapes (the only ones that stop a non-bullet), which screens all fast bodies
in one vectorised pass: a swinging chain far from any wall costs no shape
walk at all, and a bullet in open air a couple of box queries per step.

An armed body, at each substep whose motion is still fast, is capped again
(collisions inside a step can exceed the caps) and sweeps its shapes along
the motion against the candidate shapes in its swept bounding box: circles as
swept circles, polygons as their vertices plus an inscribed circle, all
shrunk by ``margin`` so that surfaces it already rests on are never "hit";
a spinning body's points follow their arcs as short chords. At the earliest
impact it stops (its shapes then overlap by about ``margin``) and keeps its
velocity; pymunk's contact solver, which runs right after in the same
substep, resolves the contact (bounce, friction, events) as for any other.
A small *guard* circle deep inside each shape catches the rare body that the
solver fails to stop at a contact the world accepted (crushed by others, or
spinning into a wall): it is held for that substep and its approach removed.

The sweep honours everything that decides whether two colliders touch: same
body, sensors, Box2D filtering (``shape.kge_filter``), joints without
``collide_bodies``, one-way platforms (``shape.kge_oneway``), an optional
``pair_filter`` (the world's contact filter) and, for the guard, the contacts
pymunk actually accepted in the last substep (pre-solve hooks). Moving
obstacles (kinematic bodies, and dynamic ones for bullets) are swept against
in their own frame; a kinematic one carries what it hits along for the rest
of the substep (never through static geometry), so a fast paddle pushes a
ball instead of passing over it.

>>> import math, pymunk
>>> space = pymunk.Space()
>>> wall = pymunk.Poly(space.static_body, [(5, -2), (5.1, -2), (5.1, 2), (5, 2)], radius=0.01)
>>> ball = pymunk.Body()
>>> shot = pymunk.Circle(ball, 0.05)
>>> shot.density = 1.0
>>> space.add(wall, ball, shot)
>>> ball.velocity = (500.0, 0.0)
>>> ccd = ContinuousCollision(space)
>>> ccd.track(ball)
>>> for _ in range(5):
...     armed = ccd.before_step(1 / 60)
...     space.step(1 / 60)
...     ccd.after_step(1 / 60)
>>> round(ball.velocity.x, 6) <= 120.0, ball.position.x < 5.0
(True, True)
"""

from __future__ import annotations

import functools
import math
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

import numpy as np
import pymunk
import pymunk.batch
from pymunk._chipmunk import lib as _lib

from kge.components.filter import Filter
from kge.errors import ComponentTypeError, ValidationError
from kge.physics.callback_errors import CallbackErrors
from kge.physics.speed_cap import clamp_one
from kge.validate import boolean, integer, non_negative, positive

Vec2 = tuple[float, float]
#: ``pair_filter(moving_shape, other_shape) -> bool``: False = they never touch.
PairFilter = Callable[[pymunk.Shape, pymunk.Shape], bool]
#: (fraction, carry dx, carry dy, hold normal or None), see _Tracked._time_of_impact
_Impact = tuple[float, float, float, tuple[float, float] | None]

_ALL = pymunk.ShapeFilter()
_DEFAULT_FILTER = Filter()
_DYNAMIC = pymunk.Body.DYNAMIC
_KINEMATIC = pymunk.Body.KINEMATIC
_STATIC = pymunk.Body.STATIC
#: largest rotation (rad) swept as one straight chord (sagitta <= 0.5 % of the reach)
_MAX_CHORD = 0.2
_FIELDS = (
    pymunk.batch.BodyFields.BODY_ID
    | pymunk.batch.BodyFields.POSITION
    | pymunk.batch.BodyFields.ANGLE
    | pymunk.batch.BodyFields.VELOCITY
    | pymunk.batch.BodyFields.ANGULAR_VELOCITY
)


# --------------------------------------------------------------------------- per-body data


@dataclass(slots=True)
class _Part:
    """One shape of a tracked body and the points swept for it (body-local)."""

    shape: pymunk.Shape
    #: (x, y, radius, guard): the point is swept as a circle of that radius; a
    #: guard is a small circle deep inside the shape (see _Tracked._time_of_impact)
    points: tuple[tuple[float, float, float, bool], ...]


#: what :func:`_shape_points` computes for one shape: points, core radius, reach
_ShapePoints = tuple[tuple[tuple[float, float, float, bool], ...], float, float]


def _geometry(shape: pymunk.Shape) -> tuple[Any, ...] | None:
    """A hashable description of a shape's body-local geometry (Chipmunk's getters).

    Read through Chipmunk directly: pymunk's ``get_vertices`` builds a Vec2d per
    vertex, and a game spawning a wave of 1,000 boxes tracks 1,000 bodies at once.
    """
    cp = shape._shape
    if isinstance(shape, pymunk.Circle):
        o = _lib.cpCircleShapeGetOffset(cp)
        return ("circle", _lib.cpCircleShapeGetRadius(cp), o.x, o.y)
    if isinstance(shape, pymunk.Poly):
        verts = []
        for i in range(_lib.cpPolyShapeGetCount(cp)):
            v = _lib.cpPolyShapeGetVert(cp, i)
            verts.append((v.x, v.y))
        c = _lib.cpShapeGetCenterOfGravity(cp)
        return ("poly", _lib.cpPolyShapeGetRadius(cp), tuple(verts), (c.x, c.y))
    if isinstance(shape, pymunk.Segment):
        a, b = _lib.cpSegmentShapeGetA(cp), _lib.cpSegmentShapeGetB(cp)
        return ("segment", _lib.cpSegmentShapeGetRadius(cp), (a.x, a.y), (b.x, b.y))
    return None


@functools.lru_cache(maxsize=128)
def _shape_points(
    geometry: tuple[Any, ...], cog: tuple[float, float], margin: float
) -> _ShapePoints:
    """Sweep points, core radius and reach (from ``cog``) of one shape's geometry.

    Cached: a wave of identical boxes shares one answer.
    """
    kind, skin = geometry[0], geometry[1]
    points: list[tuple[float, float, float, bool]] = []
    if kind == "circle":
        r, ox, oy = skin, geometry[2], geometry[3]
        points.append((ox, oy, max(r - margin, 0.5 * r), False))
        points.append((ox, oy, 0.5 * r, True))
        return tuple(points), r, math.dist((ox, oy), cog) + r
    if kind == "poly":
        verts: tuple[tuple[float, float], ...] = geometry[2]
        cx, cy = geometry[3]
        inradius = min(
            abs((q[0] - p[0]) * (cy - p[1]) - (q[1] - p[1]) * (cx - p[0])) / math.dist(p, q)
            for p, q in zip(verts, verts[1:] + verts[:1], strict=True)
            if p != q
        )
        points.append((cx, cy, max(inradius + skin - margin, 0.5 * inradius), False))
        points.append((cx, cy, 0.5 * inradius, True))
        reach = 0.0
        for vx, vy in verts:
            d = math.hypot(cx - vx, cy - vy)
            k = min(margin, 0.5 * d) / d if d > 0 else 0.0
            points.append((vx + (cx - vx) * k, vy + (cy - vy) * k, 0.0, False))
            reach = max(reach, math.dist((vx, vy), cog) + skin)
        return tuple(points), inradius + skin, reach
    (ax, ay), (bx, by) = geometry[2], geometry[3]
    points.extend(
        (x, y, 0.0, False) for x, y in ((ax, ay), ((ax + bx) / 2, (ay + by) / 2), (bx, by))
    )
    return tuple(points), max(skin, margin), max(math.dist((ax, ay), cog), math.dist((bx, by), cog))


def _parts(
    body: pymunk.Body, shapes: tuple[pymunk.Shape, ...], margin: float
) -> tuple[list[_Part], float, float]:
    """Sweep points per shape, core radius (thinnest part) and reach (from the centre of gravity).

    Circles sweep their centre with the radius shrunk by ``margin``; polygons
    sweep an inscribed circle plus their vertices pulled ``margin`` inwards;
    segments their ends and middle. Shrinking keeps a body that already rests
    on a surface (overlap about one slop) from "hitting" it, or the next
    segment of a chain, while it slides. Circles and polygons also get a guard:
    a circle of half their core radius at their centre.
    """
    g = _lib.cpBodyGetCenterOfGravity(body._body)
    cog = (g.x, g.y)
    parts: list[_Part] = []
    core = math.inf
    reach = 0.0
    for shape in shapes:
        geometry = _geometry(shape)
        if geometry is None:
            continue
        points, shape_core, shape_reach = _shape_points(geometry, cog, margin)
        core = min(core, shape_core)
        reach = max(reach, shape_reach)
        parts.append(_Part(shape, points))
    return parts, (core if math.isfinite(core) else margin), reach


def _extent(body: pymunk.Body, shapes: tuple[pymunk.Shape, ...], reach: float) -> float:
    """Radius about the body's origin that holds all its shapes' bounding boxes (skin included).

    With the positions read in bulk, ``position ± extent`` bounds the body in
    any orientation, so fast bodies are screened against the obstacle index
    in one vectorised pass. ``reach`` (from the centre of gravity, see
    :func:`_parts`) leaves out only a segment's radius.
    """
    pad = 0.0
    for shape in shapes:
        if isinstance(shape, pymunk.Segment):
            pad = max(pad, shape.radius)
        elif not isinstance(shape, (pymunk.Circle, pymunk.Poly)):
            return math.inf
    gx, gy = body.center_of_gravity
    return math.hypot(gx, gy) + reach + pad


@dataclass(slots=True, eq=False)
class _Tracked:
    """A tracked dynamic body; when armed it *is* the body's ``position_func``."""

    owner: ContinuousCollision
    body: pymunk.Body
    bullet: bool
    parts: list[_Part]
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
        vx, vy = body.velocity
        w = body.angular_velocity
        # Box2D caps the speed after every solve; collisions inside a step can
        # exceed it, so an armed body is capped again before each substep.
        nv, nw = clamp_one(
            vx, vy, w, owner.max_translation / owner.step_dt, owner.max_rotation / owner.step_dt
        )
        if nv is not None:
            body.velocity = nv
            vx, vy = nv
        if nw is not None:
            body.angular_velocity = w = nw
        da = w * dt
        dx, dy = vx * dt, vy * dt
        integrate = self.saved
        others = self.boost * dt / owner.step_dt
        own = math.hypot(dx, dy) + abs(da) * self.reach
        if own + others <= owner.threshold * self.core:
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
        swept = _grown(
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
        joint_free = _joint_free_bodies(body)
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
                flt = getattr(s, "kge_filter", None) or _DEFAULT_FILTER
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
            own_filter = getattr(own, "kge_filter", None) or _DEFAULT_FILTER
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
                        one_way = getattr(other, "kge_oneway", None)
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
        box: pymunk.BB | None = None
        for shape in self.shapes:
            box = shape.bb if box is None else box.merge(shape.bb)
        return box

    def near_obstacles(self, motion: float) -> bool:
        """Could anything stop this body within ``motion`` metres, in any direction?

        Static shapes are tested against the body's box grown by ``motion``;
        moving ones (kinematic, or dynamic for bullets) may approach by up to
        their own step motion too, so the search is widened by the speed cap.
        A non-bullet asks the owner's index of static and kinematic shapes
        (the only ones that can stop it), never walking the dynamic shapes
        around it; a bullet, which every body can stop, asks the space.
        """
        box = self._bounds()
        space = self.body.space
        if box is None or space is None:
            return False
        reach = motion + self.owner.max_translation
        if self.bullet:
            shapes = space.bb_query(_grown(box, reach), _ALL)
        else:
            shapes = self.owner._obstacles.candidates(box, motion, reach)
        joint_free: set[pymunk.Body] | None = None
        for shape in shapes:
            if joint_free is None:
                joint_free = _joint_free_bodies(self.body)
            if not self._is_obstacle(shape, joint_free):
                continue
            moving = shape.body is not None and shape.body.body_type != pymunk.Body.STATIC
            if _grown(box, reach if moving else motion).intersects(shape.bb):
                return True
        return False

    def _is_obstacle(self, shape: pymunk.Shape, joint_free: set[pymunk.Body]) -> bool:
        other = shape.body
        if other is self.body or other is None or shape.sensor:
            return False
        if other.body_type == _DYNAMIC and not self.bullet:
            return False
        return other not in joint_free


def _grown(box: pymunk.BB, by: float) -> pymunk.BB:
    return pymunk.BB(box.left - by, box.bottom - by, box.right + by, box.top + by)


def _joint_free_bodies(body: pymunk.Body) -> set[pymunk.Body]:
    """Bodies joined to ``body`` by a constraint that disables their collision."""
    out: set[pymunk.Body] = set()
    for c in body.constraints:
        if not c.collide_bodies:
            out.add(c.b if c.a is body else c.a)
    return out


# --------------------------------------------------------------------------- obstacle index

#: rows x fast bodies compared at once by _Obstacles.near_any (bounds temporary memory)
_CHUNK = 1 << 16


class _Obstacles:
    """Bounding boxes of the space's static and kinematic shapes, in numpy.

    A non-bullet body can only be stopped by static or kinematic geometry, so
    "is anything within reach?" must not walk the (often many) dynamic shapes
    around it, as ``space.bb_query`` would. This index holds one row per
    static or kinematic shape: its cached bounding box and whether its body
    moves (kinematic). It is kept current at a cost proportional to what
    changed, never to the size of the space:

    * **new shapes**: Chipmunk gives every shape added to a space the next
      ``hashid``, and pymunk keeps ``space.shapes`` in insertion order, so the
      shapes added since the last look are the tail of that view whose hashid
      exceeds the newest one seen;
    * **removed shapes**: rows whose shape left the space are dropped when a
      query meets them, and swept out once removals outnumber the rows; dropped
      rows are reused by the next shapes, so the table never outgrows the most
      static and kinematic shapes the space held at once (a game that keeps
      spawning kinematic bodies must not grow it forever);
    * **moved bodies**: the owners' poses, read in bulk with the velocities,
      are compared with the last ones; the boxes of a body that moved (and of
      every moving kinematic body) are re-read, also on the next step, so a
      ``reindex`` that lags a move by one step is still seen;
    * **type changes**: :meth:`reclassify`, called by ``track``/``untrack``
      (the physics system calls one of them after every type change).

    Rows are candidates only: every hit is re-checked on the live shape.
    """

    def __init__(self, space: pymunk.Space) -> None:
        self.space = space
        self.shapes: list[pymunk.Shape | None] = []
        self.owner_of: list[int] = []  # row -> owner body id
        self.row_of: dict[pymunk.Shape, int] = {}
        self.box = np.full((16, 4), np.nan)  # left, bottom, right, top (nan: free row)
        self.kinematic = np.zeros(16, dtype=bool)
        self.live = 0
        self._free: list[int] = []  # dropped rows, reused first
        self._count = 0  # len(space.shapes) at the last scan
        self._newest = -1  # largest hashid seen
        self._removed = 0  # removals seen since the last sweep of dead rows
        self._owners: dict[int, pymunk.Body] = {}  # body id -> body owning rows
        self._owner_rows: dict[int, list[int]] = {}
        self._owners_dirty = True
        self._oids = np.empty(0, dtype=np.int64)  # sorted owner ids
        self._opose = np.empty((0, 3))
        self._orow = np.empty(0, dtype=np.intp)  # owner -> row in the bulk read (-1: none)
        self._recent = np.empty(0, dtype=bool)
        self._order = -1  # the bulk-read order _orow was computed for

    # ----------------------------------------------------------------- upkeep

    def refresh(self, ids: np.ndarray, pose: np.ndarray, vel: np.ndarray, order: int) -> None:
        """Bring the rows up to date from this step's bulk read.

        ``order`` changes whenever the read's body order may have changed.
        """
        self._scan()
        fresh = order != self._order
        self._order = order
        if self._owners_dirty:
            self._oids = np.array(sorted(self._owners), dtype=np.int64)
            self._opose = np.full((len(self._oids), 3), np.nan)
            self._recent = np.zeros(len(self._oids), dtype=bool)
            self._owners_dirty = False
            fresh = True
        k = len(self._oids)
        if k == 0:
            return
        if fresh:
            at = np.minimum(np.searchsorted(self._oids, ids), k - 1)
            hit = self._oids[at] == ids
            self._orow = np.full(k, -1, dtype=np.intp)
            self._orow[at[hit]] = np.flatnonzero(hit)
        present = self._orow >= 0
        rows = np.where(present, self._orow, 0)
        cur = np.where(present[:, None], pose[rows], np.nan)
        moved = ~(cur == self._opose).all(axis=1)  # nan (absent) counts as moved
        spinning = present & (vel[rows] != 0.0).any(axis=1)
        update = moved | spinning | self._recent
        self._recent = moved
        self._opose = cur
        if update.any():
            for j in np.flatnonzero(update).tolist():
                self._update_owner(int(self._oids[j]))

    def _scan(self) -> None:
        """Index the shapes added since the last scan (see the class docstring)."""
        shapes: Any = self.space.shapes  # a dict keys view: insertion order, reversible
        n = len(shapes)
        if n == self._count and (n == 0 or next(reversed(shapes))._hashid == self._newest):
            return
        added = 0
        newest = self._newest
        for shape in reversed(shapes):
            h = shape._hashid
            if h <= self._newest:
                break
            added += 1
            newest = max(newest, h)
            body = shape.body
            if shape in self.row_of or (body is not None and body.body_type != _DYNAMIC):
                self._classify(shape)
        self._newest = newest
        self._removed += max(0, self._count + added - n)
        self._count = n
        if self._removed > max(32, self.live):
            self._removed = 0
            for shape in [s for s in self.shapes if s is not None]:
                if shape.space is not self.space:
                    self._drop(shape)

    def reclassify(self, body: pymunk.Body) -> None:
        """Re-read ``body``'s shapes after its type (or shape set) may have changed."""
        if body.body_type == _DYNAMIC and body.id not in self._owner_rows:
            return  # the common case (a dynamic body tracked): nothing of it is indexed
        own = set(body.shapes)
        for shape in own:
            self._classify(shape)
        for row in list(self._owner_rows.get(body.id, ())):
            gone = self.shapes[row]
            if gone is not None and gone not in own:
                self._classify(gone)

    def _classify(self, shape: pymunk.Shape) -> None:
        body = shape.body
        if body is None or shape.space is not self.space or body.body_type == _DYNAMIC:
            self._drop(shape)
            return
        row = self.row_of.get(shape)
        if row is None:
            row = self._free_row()
            self.row_of[shape] = row
            self.shapes[row] = shape
            self.owner_of[row] = body.id
            self.live += 1
            rows = self._owner_rows.setdefault(body.id, [])
            if not rows:
                self._owners[body.id] = body
                self._owners_dirty = True
            rows.append(row)
        bb = shape.bb
        self.box[row] = (bb.left, bb.bottom, bb.right, bb.top)
        self.kinematic[row] = body.body_type == _KINEMATIC

    def _free_row(self) -> int:
        if self._free:
            return self._free.pop()
        if len(self.shapes) == len(self.box):
            grow = len(self.box)
            self.box = np.concatenate([self.box, np.full((grow, 4), np.nan)])
            self.kinematic = np.concatenate([self.kinematic, np.zeros(grow, dtype=bool)])
        self.shapes.append(None)
        self.owner_of.append(0)
        return len(self.shapes) - 1

    def _drop(self, shape: pymunk.Shape) -> None:
        row = self.row_of.pop(shape, None)
        if row is None:
            return
        self.shapes[row] = None
        self.box[row] = np.nan
        self._free.append(row)
        self.live -= 1
        key = self.owner_of[row]
        rows = self._owner_rows.get(key)
        if rows is not None and row in rows:
            rows.remove(row)
            if not rows:
                del self._owner_rows[key]
                self._owners.pop(key, None)
                self._owners_dirty = True
        if self.live == 0:  # compact: nothing left to keep
            self.shapes.clear()
            self.owner_of.clear()
            self._free.clear()
            self.box[:] = np.nan
            self._owner_rows.clear()
            self._owners.clear()
            self._owners_dirty = True

    def _update_owner(self, body_id: int) -> None:
        for row in list(self._owner_rows.get(body_id, ())):
            shape = self.shapes[row]
            if shape is not None:
                self._classify(shape)

    def body(self, body_id: int) -> pymunk.Body | None:
        """A static or kinematic body that owns indexed shapes, by id."""
        return self._owners.get(body_id)

    # ----------------------------------------------------------------- queries

    def near_any(self, x: np.ndarray, y: np.ndarray, r: np.ndarray) -> np.ndarray:
        """For each square ``(x, y) ± r``: does it overlap any row's box?"""
        out = np.zeros(len(x), dtype=bool)
        m = len(self.shapes)
        if self.live == 0 or m == 0:
            return out
        left, bottom, right, top = (self.box[:m, i] for i in range(4))
        step = max(1, _CHUNK // m)
        for i in range(0, len(x), step):
            xs, ys, rs = x[i : i + step, None], y[i : i + step, None], r[i : i + step, None]
            hit = (left <= xs + rs) & (right >= xs - rs) & (bottom <= ys + rs) & (top >= ys - rs)
            out[i : i + step] = hit.any(axis=1)
        return out

    def candidates(self, box: pymunk.BB, still: float, moving: float) -> list[pymunk.Shape]:
        """Shapes whose cached box overlaps ``box`` grown by ``still`` (static) or ``moving``."""
        m = len(self.shapes)
        if self.live == 0 or m == 0:
            return []
        g = np.where(self.kinematic[:m], moving, still)
        b = self.box[:m]
        hit = (
            (b[:, 0] <= box.right + g)
            & (b[:, 2] >= box.left - g)
            & (b[:, 1] <= box.top + g)
            & (b[:, 3] >= box.bottom - g)
        )
        out = []
        for row in np.flatnonzero(hit).tolist():
            shape = self.shapes[row]
            if shape is None:
                continue
            if shape.space is not self.space:
                self._drop(shape)
                continue
            out.append(shape)
        return out


class _Index:
    """The tracked bodies sorted by id, with their radii as arrays (rebuilt on track/untrack)."""

    __slots__ = ("bullets", "core", "extent", "ids", "infos", "max_extent", "reach")

    def __init__(self, infos: list[_Tracked]) -> None:
        self.infos = infos
        self.ids = np.array([t.body.id for t in infos], dtype=np.int64)
        self.core = np.array([t.core for t in infos], dtype=np.float64)
        self.reach = np.array([t.reach for t in infos], dtype=np.float64)
        self.extent = np.array([t.extent for t in infos], dtype=np.float64)
        self.max_extent = float(self.extent.max()) if infos else 0.0
        self.bullets = any(t.bullet for t in infos)


# --------------------------------------------------------------------------- the manager


class ContinuousCollision:
    """Speed caps for every body of ``space`` and sweeps for tracked dynamic bodies.

    Call :meth:`track` for each dynamic body (``bullet=True`` for bullets)
    once its shapes are in the space, and again when its shapes, joints or
    bullet flag change; :meth:`untrack` before removing it. Each fixed step:
    :meth:`before_step` after writing user velocities and before the
    substeps, :meth:`after_step` after them and before reading velocities back.

    ``threshold``: a body is swept when it moves more than this fraction of its
    core radius (circle radius, polygon inradius + skin) in a step; below it
    the contact solver cannot be fooled (the body's centre stays on the near
    side of anything it penetrates). ``margin``: how far the swept outline is
    shrunk, i.e. the overlap a body is left with at the impact (Box2D's target
    is about one linear slop).
    """

    def __init__(
        self,
        space: pymunk.Space,
        *,
        max_translation: float = 2.0,
        max_rotation: float = 0.5 * math.pi,
        threshold: float = 0.5,
        margin: float = 0.01,
        pair_filter: PairFilter | None = None,
        errors: CallbackErrors | None = None,
    ) -> None:
        if not isinstance(space, pymunk.Space):
            raise ComponentTypeError(
                f"ContinuousCollision: expected a pymunk.Space, got {type(space).__name__}"
            )
        if pair_filter is not None and not callable(pair_filter):
            raise ComponentTypeError("ContinuousCollision.pair_filter must be callable or None")
        self.space = space
        self.max_translation = positive(max_translation, "ContinuousCollision", "max_translation")
        self.max_rotation = positive(max_rotation, "ContinuousCollision", "max_rotation")
        self.threshold = positive(threshold, "ContinuousCollision", "threshold")
        self.margin = non_negative(margin, "ContinuousCollision", "margin")
        self.pair_filter = pair_filter
        #: where an exception raised inside the sweeps (called from C) is kept; without
        #: an owner's (a Simulation's), :meth:`after_step` raises it
        self.errors = errors if errors is not None else CallbackErrors()
        self._raises = errors is None
        #: the fixed step of the current step (set by before_step)
        self.step_dt = 1.0 / 60.0
        self._tracked: dict[int, _Tracked] = {}
        self._bodies: dict[int, pymunk.Body] = {}  # every tracked body, for clamping by id
        self._movers: dict[int, pymunk.Body] = {}  # moving untracked (kinematic) bodies seen
        self._boosted: list[_Tracked] = []
        self._armed: dict[int, _Tracked] = {}  # id(info) -> info
        self._buffer = pymunk.batch.Buffer()
        self._index: _Index | None = None
        #: the last bulk read's body ids and their rows in the index (reused while unchanged)
        self._rows: (
            tuple[np.ndarray, _Index, np.ndarray, np.ndarray, np.ndarray, np.ndarray] | None
        ) = None
        self._generation = 0  # bumped whenever _rows is recomputed
        self._obstacles = _Obstacles(space)
        #: this step's answers of near_obstacles(cap) for neighbours of fast bodies
        self._near_memo: dict[int, bool] = {}

    # ----------------------------------------------------------------- bookkeeping

    def track(self, body: pymunk.Body, *, bullet: bool = False) -> None:
        """Start (or refresh) CCD for ``body``; non-dynamic bodies are only speed-capped."""
        if not isinstance(body, pymunk.Body):
            raise ComponentTypeError(
                f"ContinuousCollision.track: expected a pymunk.Body, got {type(body).__name__}"
            )
        bullet = boolean(bullet, "ContinuousCollision.track", "bullet")
        key = body.id
        self._bodies[key] = body
        old = self._tracked.pop(key, None)
        if old is not None and old.armed:
            self._disarm(self._armed.pop(id(old)))
        self._index = None
        self._obstacles.reclassify(body)  # its type may have changed in place
        if body.body_type != _DYNAMIC:
            return
        shapes = tuple(body.shapes)  # pymunk builds a new set per read
        parts, core, reach = _parts(body, shapes, self.margin)
        self._tracked[key] = _Tracked(
            self, body, bullet, parts, core, reach, shapes, _extent(body, shapes, reach)
        )

    def untrack(self, body: pymunk.Body) -> None:
        """Forget ``body`` (restores its plain integrator); unknown bodies are ignored."""
        self._bodies.pop(body.id, None)
        self._movers.pop(body.id, None)  # else a removed kinematic body stays referenced
        self._obstacles.reclassify(body)  # it may have become static or kinematic
        info = self._tracked.pop(body.id, None)
        if info is not None:
            self._index = None
            if info.armed:
                self._disarm(self._armed.pop(id(info)))

    def _is_bullet(self, body: pymunk.Body) -> bool:
        info = self._tracked.get(body.id)
        return info is not None and info.bullet

    def is_armed(self, body: pymunk.Body) -> bool:
        """True when ``body`` carries the swept integrator for the current step."""
        info = self._tracked.get(body.id)
        return info is not None and info.armed

    @property
    def armed_count(self) -> int:
        """How many bodies carry the swept integrator for the current step."""
        return len(self._armed)

    def stats(self) -> tuple[int, int]:
        """(sweeps run, sweeps that found an impact) since the bodies were tracked."""
        return (
            sum(t.sweeps for t in self._tracked.values()),
            sum(t.impacts for t in self._tracked.values()),
        )

    # ----------------------------------------------------------------- per step

    def before_step(
        self,
        step_dt: float,
        substeps: int = 1,
        read: tuple[np.ndarray, np.ndarray] | None = None,
    ) -> int:
        """Clamp speeds and arm the sweep on fast tracked bodies; returns how many are armed.

        ``substeps``: how many ``space.step`` calls make up this fixed step. A
        body is armed when its motion per substep exceeds the threshold, so
        passing the real count skips bodies that are only fast per step.
        ``read``: (ids, rows of x, y, angle, vx, vy, w) of every body, when the
        caller already holds a bulk read that is still current (the physics
        system's sync-out read, if nothing touched a body since); saves a read.
        """
        dt = positive(step_dt, "ContinuousCollision.before_step", "step_dt")
        n = integer(substeps, "ContinuousCollision.before_step", "substeps")
        if n < 1:
            raise ValidationError(
                f"ContinuousCollision.before_step: substeps must be >= 1, got {n}"
            )
        self.step_dt = dt
        if read is None:
            ids, pose, vel = self._read()
        else:
            ids, rows = read
            pose, vel = rows[:, :3], rows[:, 3:]
        vel = self._clamp(ids, vel, dt)
        for info in self._boosted:
            info.boost = 0.0
        self._boosted.clear()
        self._near_memo.clear()
        if not self._tracked:
            return 0
        pos, known, core, reach = self._rows_of(ids)
        speed = np.hypot(vel[:, 0], vel[:, 1])
        motion = (speed + np.abs(vel[:, 2]) * reach) * dt
        fast = np.flatnonzero(known & (motion > self.threshold * n * core))
        want: dict[int, _Tracked] = {}
        if len(fast):
            self._arm_fast(fast, pos[fast], ids, pose, vel, motion[fast], want)
        moving = ~known & ((speed > 0.0) | (vel[:, 2] != 0.0))
        if moving.any() or self._movers:
            self._boost_near_movers(ids, moving, vel, dt, n, want)
        for key in [k for k in self._armed if k not in want]:
            self._disarm(self._armed.pop(key))
        for key, info in want.items():
            if key not in self._armed:
                info.saved = info.body.position_func
                info.body.position_func = info
                info.armed = True
                self._armed[key] = info
        return len(want)

    def after_step(self, step_dt: float) -> None:
        """Clamp speeds again, so the velocity read back is the capped one (Box2D keeps it)."""
        dt = positive(step_dt, "ContinuousCollision.after_step", "step_dt")
        if self._raises:
            self.errors.raise_pending()
        ids, _, vel = self._read()
        self._clamp(ids, vel, dt)

    # ----------------------------------------------------------------- internals

    def _arm_fast(
        self,
        rows: np.ndarray,
        slots: np.ndarray,
        ids: np.ndarray,
        pose: np.ndarray,
        vel: np.ndarray,
        motion: np.ndarray,
        want: dict[int, _Tracked],
    ) -> None:
        """Arm the fast tracked bodies (bulk-read ``rows``) that have something in reach.

        The obstacle index screens them all in one vectorised pass (a square of
        ``extent`` plus the reach around each position), so only bodies near a
        static or kinematic shape - and bullets - are examined one by one.
        """
        index = self._lookup_index()
        obstacles = self._obstacles
        obstacles.refresh(ids, pose, vel, self._generation)
        x, y = pose[rows, 0], pose[rows, 1]
        reach = index.extent[slots] + motion + self.max_translation
        # what a neighbour launched by the body could hit (see _arm_neighbours)
        wide = reach + 2.0 * self.max_translation + 2.0 * index.max_extent
        close = obstacles.near_any(x, y, wide)
        near = close.copy()
        if close.any():
            near[close] = obstacles.near_any(x[close], y[close], reach[close])
        # with no bullet anywhere, a body with nothing close needs no look at all
        todo = np.arange(len(slots)) if index.bullets else np.flatnonzero(close)
        fast = []
        for k, slot in zip(todo.tolist(), slots[todo].tolist(), strict=True):
            info = index.infos[slot]
            m = float(motion[k])
            if (info.bullet or near[k]) and info.near_obstacles(m):
                want[id(info)] = info
            fast.append((info, m, bool(close[k])))
        self._arm_neighbours(fast, want, index.bullets)

    def _arm_neighbours(
        self, fast: list[tuple[_Tracked, float, bool]], want: dict[int, _Tracked], bullets: bool
    ) -> None:
        """Arm the bodies a fast body may hit this step.

        A collision inside the step can launch a slow body at up to the speed cap
        (Box2D computes impacts after the solve, with the new velocities), so a
        neighbour within a fast body's reach is armed when something it could
        then hit is within twice the speed cap of it; its integrator stays cheap
        until it is actually fast. A bullet neighbour is also boosted, so it
        sweeps against the fast body even while it is itself at rest.

        ``fast`` holds (body, step motion, close): ``close`` is False when no
        static or kinematic shape lies within what any neighbour could reach,
        so only bullet neighbours matter (none when ``bullets`` is False).
        """
        # a light body hit by a heavy one leaves at up to (1 + e) times its speed,
        # and only armed bodies are capped within the step
        cap = 2.0 * self.max_translation
        for info, motion, close in fast:
            if not (close or bullets):
                continue
            box = info._bounds()
            if box is None:
                continue
            for shape in self.space.bb_query(_grown(box, motion), _ALL):
                other = shape.body
                near = self._tracked.get(other.id) if other is not None else None
                if near is None or near is info:
                    continue
                if near.bullet and motion > near.boost:
                    # Box2D sweeps every pair with a bullet in it: a slow bullet must
                    # see the fast body coming, in that body's frame
                    if near.boost == 0.0:
                        self._boosted.append(near)
                    near.boost = motion
                    want[id(near)] = near
                elif (
                    id(near) not in want and (close or near.bullet) and self._near_within(near, cap)
                ):
                    want[id(near)] = near

    def _near_within(self, info: _Tracked, reach: float) -> bool:
        """``info.near_obstacles(reach)``, asked at most once per body and step."""
        key = id(info)
        hit = self._near_memo.get(key)
        if hit is None:
            hit = self._near_memo[key] = info.near_obstacles(reach)
        return hit

    def _boost_near_movers(
        self,
        ids: np.ndarray,
        moving: np.ndarray,
        vel: np.ndarray,
        dt: float,
        substeps: int,
        want: dict[int, _Tracked],
    ) -> None:
        """Arm slow dynamic bodies that a fast kinematic body could sweep over this step.

        Box2D computes the time of impact from both bodies' motion; here each
        dynamic body near a moving kinematic one gets that body's step motion
        as a ``boost`` and, when the sum could tunnel, the swept integrator,
        which then sweeps in the kinematic body's frame.
        """
        alive = set(ids[moving].tolist())
        self._movers = {k: b for k, b in self._movers.items() if k in alive}
        for row in np.flatnonzero(moving).tolist():
            key = int(ids[row])
            body = self._movers.get(key) or self._bodies.get(key) or self._obstacles.body(key)
            if body is None:
                body = next((b for b in self.space.bodies if b.id == key), None)
                if body is None:
                    continue
                self._movers[key] = body
            if body.body_type != _KINEMATIC or not body.shapes:
                continue
            box: pymunk.BB | None = None
            for shape in body.shapes:
                box = shape.bb if box is None else box.merge(shape.bb)
            assert box is not None
            radius = math.dist((box.left, box.bottom), (box.right, box.top))
            step = (math.hypot(vel[row, 0], vel[row, 1]) + abs(vel[row, 2]) * radius) * dt
            # a dynamic body closes in by up to the speed cap itself
            region = _grown(box, step + self.max_translation)
            for shape in self.space.bb_query(region, _ALL):
                other = shape.body
                info = self._tracked.get(other.id) if other is not None else None
                if info is None or step <= info.boost:
                    continue
                if info.boost == 0.0:
                    self._boosted.append(info)
                info.boost = step
                if step > self.threshold * info.core * substeps:
                    want[id(info)] = info

    def _read(self) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Every body's id, pose (x, y, angle) and velocity (vx, vy, w), in one bulk read."""
        buf = self._buffer
        buf.clear()
        pymunk.batch.get_space_bodies(self.space, _FIELDS, buf)
        ids = np.frombuffer(buf.int_buf(), dtype=np.int64)
        data = np.frombuffer(buf.float_buf(), dtype=np.float64).reshape(-1, 6)
        return ids, data[:, :3], data[:, 3:]

    def _clamp(self, ids: np.ndarray, vel: np.ndarray, dt: float) -> np.ndarray:
        max_v = self.max_translation / dt
        max_w = self.max_rotation / dt
        speed2 = vel[:, 0] ** 2 + vel[:, 1] ** 2
        over = (speed2 > max_v * max_v) | (np.abs(vel[:, 2]) > max_w)
        if not over.any():
            return vel
        vel = vel.copy()
        for row in np.flatnonzero(over):
            body = self._body(int(ids[row]))
            if body is None:
                continue
            vx, vy, w = (float(x) for x in vel[row])
            nv, nw = clamp_one(vx, vy, w, max_v, max_w)
            if nv is not None:
                body.velocity = nv
                vel[row, :2] = nv
            if nw is not None:
                body.angular_velocity = nw
                vel[row, 2] = nw
        return vel

    def _body(self, body_id: int) -> pymunk.Body | None:
        body = self._bodies.get(body_id) or self._movers.get(body_id)
        body = body or self._obstacles.body(body_id)
        if body is None:  # untracked (e.g. a user-made pymunk body): rare, so a plain scan
            body = next((b for b in self.space.bodies if b.id == body_id), None)
        return body

    def _lookup_index(self) -> _Index:
        if self._index is None:
            self._index = _Index(sorted(self._tracked.values(), key=lambda t: t.body.id))
        return self._index

    def _rows_of(self, ids: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        """Per bulk-read row: its slot in the index, whether tracked, core radius and reach.

        Recomputed only when the read's body order or the tracked set changed
        (bodies added, removed, falling asleep or waking), else reused.
        """
        index = self._lookup_index()
        cached = self._rows
        if cached is not None and cached[1] is index and np.array_equal(cached[0], ids):
            return cached[2:]
        pos = np.minimum(np.searchsorted(index.ids, ids), len(index.ids) - 1)
        self._rows = (
            ids.copy(),
            index,
            pos,
            index.ids[pos] == ids,
            index.core[pos],
            index.reach[pos],
        )
        self._generation += 1
        return self._rows[2:]

    @staticmethod
    def _disarm(info: _Tracked) -> None:
        restore = info.saved if info.saved is not None else pymunk.Body.update_position
        info.body.position_func = restore
        info.saved = None
        info.armed = False
