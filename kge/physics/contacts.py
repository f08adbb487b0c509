"""Contact handling: Box2D's implicit rules, materials and events, at pymunk speed.

A Python call per contact per step is the most expensive thing a physics
scene can do (DESIGN.md "Performance traps"), so kge registers:

* one wildcard ``begin`` + ``separate`` pair, which run once per *new* or
  *ended* contact. ``begin`` applies the rules pymunk lacks: static and
  kinematic pairs never touch; positive filter groups (exact Box2D rule); the
  one-way platform; the user's contact filter; restitution ``max(a, b)`` only
  above the 1 m/s threshold (Chipmunk recomputes the arbiter's restitution from
  the shapes every step, so a value set here lasts for the impact only); Box2D's
  time of impact for the pairs that get one (a body that arrived deeper than the
  linear slop is moved back to it, :mod:`kge.physics.impact`); and it records the
  begin event. ``separate`` records the matching end event.
* ``pre_solve`` / ``post_solve`` only on :data:`HOOKED` collision type, given to
  colliders with ``contact_hooks=True``, for the user's per-step hooks.

``begin`` and ``separate`` run for every contact of the scene (events are
delivered for all of them), so they read the arbiter, shapes and bodies through
Chipmunk's C getters instead of pymunk's properties, which build a Vec2d or a
wrapper tuple per read: half the cost per contact.

Side A of a contact is chosen as Box2D does: edge before polygon before circle,
otherwise the older collider (lower entity id); sensors are always side A of a
sensor event. The normal reported points from A to B.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import pymunk

from kge.physics.callback_errors import CallbackErrors
from kge.physics.cp import arbiter_handle, shape_handle
from kge.physics.cp import ffi as _ffi
from kge.physics.cp import lib as _lib
from kge.physics.events import ContactBegin, ContactEnd, Hit, PhysicsEvents, SensorBegin, SensorEnd
from kge.physics.impact import Moves, settle, undo
from kge.validate import boolean, finite, non_negative

if TYPE_CHECKING:
    from kge.world import World

Vec2 = tuple[float, float]

#: collision type of shapes whose contacts run the user's pre/post-solve hooks
HOOKED = 1

DYNAMIC = pymunk.Body.DYNAMIC
_CP_DYNAMIC = _lib.CP_BODY_TYPE_DYNAMIC
_from_handle = _ffi.from_handle


@dataclass(slots=True)
class PreSolve:
    """What a pre-solve hook sees and may change for this step's contact."""

    collider_a: int
    collider_b: int
    body_a: int | None
    body_b: int | None
    normal: Vec2
    points: tuple[Vec2, ...]
    separation: float
    #: False disables the contact for this step only (re-apply it every step)
    enabled: bool = True
    friction: float = 0.0
    restitution: float = 0.0
    #: Box2D's tangentSpeed: B slides along t = (n.y, -n.x) at this speed relative to A
    tangent_speed: float = 0.0
    child_a: int = 0  #: segment of a chain collider A (0 for other shapes)
    child_b: int = 0

    def __setattr__(self, name: str, value: Any) -> None:
        # a hook's writes reach Chipmunk's solver directly: a NaN friction there is a
        # NaN pose, so they are checked at the line that wrote them, like components
        check = _PRE_SOLVE_CHECKS.get(name)
        if check is not None:
            try:
                owner = f"contact {self.collider_a}-{self.collider_b}, PreSolve"
            except AttributeError:  # still inside __init__
                owner = "PreSolve"
            value = check(value, owner, name)
        object.__setattr__(self, name, value)


_PRE_SOLVE_CHECKS: dict[str, Callable[[Any, str, str], Any]] = {
    "enabled": boolean,
    "friction": non_negative,
    "restitution": non_negative,
    "tangent_speed": finite,
}


@dataclass(slots=True, frozen=True)
class PostSolve:
    """Impulses the solver applied to this contact over the last fixed step."""

    collider_a: int
    collider_b: int
    body_a: int | None
    body_b: int | None
    normal: Vec2
    point_count: int
    normal_impulse: float  #: N*s, >= 0, summed over points and substeps
    tangent_impulse: float  #: N*s along t = (n.y, -n.x)
    child_a: int = 0
    child_b: int = 0


PreSolveFn = Callable[[PreSolve], Any]
PostSolveFn = Callable[[PostSolve], Any]
ContactFilterFn = Callable[[int, int], bool]


def a_first(sa: pymunk.Shape, sb: pymunk.Shape) -> bool:
    """True when ``sa`` is Box2D's fixture A of the pair."""
    if sa.sensor != sb.sensor:
        return bool(sa.sensor)
    return (sa.kge_rank, sa.kge_collider) <= (sb.kge_rank, sb.kge_collider)


def _geometry(arb: pymunk.Arbiter, flip: bool) -> tuple[Vec2, tuple[Vec2, ...], float]:
    """Normal (A to B), world points (midpoints of the two surfaces) and separation.

    Read from Chipmunk's contact point set struct directly: pymunk's
    ``contact_point_set`` builds a Vec2d per number, and this runs for every
    new contact.
    """
    cps = _lib.cpArbiterGetContactPointSet(arbiter_handle(arb))
    n = cps.normal
    nx, ny = (-n.x, -n.y) if flip else (n.x, n.y)
    p = cps.points[0]
    pa, pb = p.pointA, p.pointB
    sep = p.distance
    first = (0.5 * (pa.x + pb.x), 0.5 * (pa.y + pb.y))
    if cps.count == 1:
        return (nx, ny), (first,), sep
    p = cps.points[1]
    pa, pb = p.pointA, p.pointB
    return (nx, ny), (first, (0.5 * (pa.x + pb.x), 0.5 * (pa.y + pb.y))), min(sep, p.distance)


def _approach(sa: pymunk.Shape, sb: pymunk.Shape, normal: Vec2, point: Vec2) -> float:
    """Speed at which B approaches A along the normal A->B at ``point`` (>= 0)."""
    va = _lib.cpBodyGetVelocityAtWorldPoint(_lib.cpShapeGetBody(shape_handle(sa)), point)
    vb = _lib.cpBodyGetVelocityAtWorldPoint(_lib.cpShapeGetBody(shape_handle(sb)), point)
    rel = (vb.x - va.x) * normal[0] + (vb.y - va.y) * normal[1]
    return max(0.0, -rel)


class ContactRecorder:
    """Owns the collision handlers of one space and records events into ``events``."""

    def __init__(
        self, world: World, space: pymunk.Space, events: PhysicsEvents, errors: CallbackErrors
    ) -> None:
        self.world = world
        self.space = space
        self.events = events
        self.velocity_threshold = 1.0
        #: canonical shape pair -> (A shape, B shape, is sensor pair)
        self.active: dict[tuple[int, int], tuple[pymunk.Shape, pymunk.Shape, bool]] = {}
        self.contact_filter: ContactFilterFn | None = None
        self.pre_solve: list[PreSolveFn] = []
        self.post_solve: list[PostSolveFn] = []
        self.substep = 0
        #: Box2D's linear slop, where new contacts are settled (kge.physics.impact)
        self.slop = 0.005
        #: the current substep's length (s)
        self.substep_dt = 1.0 / 240.0
        #: Chipmunk bodies that get a time of impact against dynamic bodies too: bullets,
        #: and the bodies whose velocity was set from outside the solver this step
        self.toi: set[Any] = set()
        #: contacts settled in this substep -> the moves, undone if a hook disables them
        self._settled: dict[tuple[int, int], Moves] = {}
        self._pre_cache: dict[tuple[int, int], PreSolve] = {}
        self._post_acc: dict[tuple[int, int], list[Any]] = {}
        self._shape_ptrs = (_ffi.new("cpShape *[1]"), _ffi.new("cpShape *[1]"))
        self._errors = errors
        self.bind(space)

    def bind(self, space: pymunk.Space) -> None:
        """Register the handlers on ``space`` (a new, empty one replaces the first)."""
        self.space = space
        # an exception in a handler (a WorldLockedError from a hook) is raised after the step
        guard = self._errors.guard
        space.on_collision(None, None, begin=guard(self._begin), separate=guard(self._separate))
        space.on_collision(
            HOOKED, None, pre_solve=guard(self._pre_solve), post_solve=guard(self._post_solve)
        )

    # -- begin / separate (once per contact) ------------------------------------------
    def _arbiter_shapes(self, arb: pymunk.Arbiter) -> tuple[pymunk.Shape, pymunk.Shape]:
        """``arb.shapes`` without its two allocations.

        The two pointer cells are reused: they are read back at once, with no
        Python call in between that could run another callback.
        """
        pa, pb = self._shape_ptrs
        _lib.cpArbiterGetShapes(arbiter_handle(arb), pa, pb)
        return (
            _from_handle(_lib.cpShapeGetUserData(pa[0])),
            _from_handle(_lib.cpShapeGetUserData(pb[0])),
        )

    def _begin(self, arb: pymunk.Arbiter, space: pymunk.Space, data: Any) -> None:
        s0, s1 = self._arbiter_shapes(arb)
        b0, b1 = _lib.cpShapeGetBody(shape_handle(s0)), _lib.cpShapeGetBody(shape_handle(s1))
        d0 = _lib.cpBodyGetType(b0) == _CP_DYNAMIC
        d1 = _lib.cpBodyGetType(b1) == _CP_DYNAMIC
        if not (d0 or d1):
            arb.process_collision = False  # Box2D: static/kinematic pairs never touch
            return
        cp_arb = arbiter_handle(arb)
        if not _lib.cpArbiterGetProcessCollision(cp_arb):
            return
        fa, fb = s0.kge_filter, s1.kge_filter
        if (fa.group_index > 0 or fb.group_index > 0) and not fa.collides_with(fb):
            _lib.cpArbiterSetProcessCollision(cp_arb, False)
            return
        sensor0 = _lib.cpShapeGetSensor(shape_handle(s0))
        sensor1 = _lib.cpShapeGetSensor(shape_handle(s1))
        if sensor0 != sensor1:
            flip = not sensor0
        else:
            flip = (s0.kge_rank, s0.kge_collider) > (s1.kge_rank, s1.kge_collider)
        sa, sb = (s1, s0) if flip else (s0, s1)
        sensor = bool(sensor0 or sensor1)
        normal, points, sep = _geometry(arb, flip)
        one_way = sa.kge_oneway is not None or sb.kge_oneway is not None
        if one_way and not sensor and not self._one_way_accepts(sa, sb, normal):
            _lib.cpArbiterSetProcessCollision(cp_arb, False)
            return
        if self.contact_filter is not None:
            with self.world.locked():
                ok = self.contact_filter(sa.kge_collider, sb.kge_collider)
            if not ok:
                _lib.cpArbiterSetProcessCollision(cp_arb, False)
                return
        key = (id(sa), id(sb))
        self.active[key] = (sa, sb, sensor)
        ca, cb, ba, bb = sa.kge_collider, sb.kge_collider, sa.kge_body, sb.kge_body
        ka, kb = sa.kge_child, sb.kge_child
        events = self.events
        if sensor:
            events.sensor_begin.append(SensorBegin(ca, cb, ba, bb, ka, kb))
            return
        speed = _approach(sa, sb, normal, points[0])
        # Box2D's time of impact: a dynamic body against a static or kinematic one, or a
        # pair with a bullet (here also with a body pushed from outside this step)
        if sep < -self.slop and (
            not (d0 and d1) or b0 in self.toi or b1 in self.toi
        ):
            moves = settle(cp_arb, self.slop, self.substep_dt)
            if moves:
                self._settled[key] = moves
                normal, points, sep = _geometry(arb, flip)
        ea, eb = sa.kge_material[1], sb.kge_material[1]
        e = ea if ea > eb else eb
        if e > 0.0 and speed > self.velocity_threshold:
            arb.restitution = e
        events.contact_begin.append(
            ContactBegin(ca, cb, ba, bb, normal, points, sep, speed, ka, kb)
        )
        ta, tb = sa.kge_hit, sb.kge_hit
        if ta is not None or tb is not None:
            limit = max(t for t in (ta, tb) if t is not None)
            if speed > limit:
                events.hits.append(Hit(ca, cb, ba, bb, points[0], normal, speed, ka, kb))

    @staticmethod
    def _one_way_accepts(sa: pymunk.Shape, sb: pymunk.Shape, normal: Vec2) -> bool:
        for plat, sign in ((sa, 1.0), (sb, -1.0)):
            spec = plat.kge_oneway
            if spec is None:
                continue
            (ux, uy), min_cos = spec
            # normal from the platform to the other shape
            if sign * (normal[0] * ux + normal[1] * uy) < min_cos:
                return False
        return True

    def _separate(self, arb: pymunk.Arbiter, space: pymunk.Space, data: Any) -> None:
        s0, s1 = self._arbiter_shapes(arb)
        key = (id(s0), id(s1))
        rec = self.active.pop(key, None)
        if rec is None:
            rec = self.active.pop((key[1], key[0]), None)
            if rec is None:
                return
        if self._pre_cache:
            self._pre_cache.pop(key, None)
        sa, sb, sensor = rec
        ca, cb, ba, bb = sa.kge_collider, sb.kge_collider, sa.kge_body, sb.kge_body
        ka, kb = sa.kge_child, sb.kge_child
        if sensor:
            self.events.sensor_end.append(SensorEnd(ca, cb, ba, bb, ka, kb))
        else:
            self.events.contact_end.append(ContactEnd(ca, cb, ba, bb, ka, kb))

    # -- user hooks (per step, only for HOOKED shapes) -------------------------------------
    def _ordered(self, arb: pymunk.Arbiter) -> tuple[pymunk.Shape, pymunk.Shape, bool] | None:
        """Canonical (A, B, flip) of a hooked contact, or None to skip this call.

        pymunk runs the (HOOKED, None) handler twice when both shapes are hooked,
        once per order; only the call seeing A first goes on.
        """
        s0, s1 = arb.shapes
        flip = not a_first(s0, s1)
        if flip and s1.collision_type == HOOKED:
            return None
        sa, sb = (s1, s0) if flip else (s0, s1)
        if (id(sa), id(sb)) not in self.active or sa.sensor or sb.sensor:
            return None
        return sa, sb, flip

    def _pre_solve(self, arb: pymunk.Arbiter, space: pymunk.Space, data: Any) -> None:
        if not self.pre_solve:
            return
        got = self._ordered(arb)
        if got is None:
            return
        sa, sb, flip = got
        key = (id(sa), id(sb))
        contact = self._pre_cache.get(key) if self.substep > 0 else None
        fresh = contact is None
        if contact is None:
            normal, points, sep = _geometry(arb, flip)
            fr = (sa.kge_material[0] * sb.kge_material[0]) ** 0.5
            contact = PreSolve(
                sa.kge_collider, sb.kge_collider, sa.kge_body, sb.kge_body, normal, points, sep,
                True, fr, arb.restitution, 0.0, sa.kge_child, sb.kge_child,
            )
            with self.world.locked():
                for fn in self.pre_solve:
                    fn(contact)
            self._pre_cache[key] = contact
        if not contact.enabled:
            arb.process_collision = False
            moves = self._settled.pop(key, None)
            if moves:  # Box2D drops a time of impact whose contact a hook disables
                undo(moves)
            return
        arb.process_collision = True
        arb.friction = contact.friction
        if fresh and contact.restitution != arb.restitution:
            arb.restitution = contact.restitution
        if contact.tangent_speed:
            nx, ny = contact.normal
            t = (ny * contact.tangent_speed, -nx * contact.tangent_speed)
            # pymunk drives v(shape0) - v(shape1) to the surface velocity
            arb.surface_velocity = t if flip else (-t[0], -t[1])

    def _post_solve(self, arb: pymunk.Arbiter, space: pymunk.Space, data: Any) -> None:
        if not self.post_solve:
            return
        got = self._ordered(arb)
        if got is None:
            return
        sa, sb, flip = got
        key = (id(sa), id(sb))
        j = arb.total_impulse  # applied to shapes[0]
        n = arb.normal  # shapes[0] -> shapes[1]
        acc = self._post_acc.get(key)
        if acc is None:
            acc = self._post_acc[key] = [sa, sb, flip, 0.0, 0.0, 0, (0.0, 0.0)]
        nx, ny = (-n.x, -n.y) if flip else (n.x, n.y)
        # impulse on B = -impulse on shapes[0] when A is shapes[0]
        jb = (j.x, j.y) if flip else (-j.x, -j.y)
        acc[3] += jb[0] * nx + jb[1] * ny
        acc[4] += jb[0] * ny - jb[1] * nx
        acc[5] = len(arb.contact_point_set.points)
        acc[6] = (nx, ny)

    def begin_step(self) -> None:
        self._pre_cache.clear()
        self._post_acc.clear()

    def begin_substep(self, i: int, h: float) -> None:
        self.substep = i
        self.substep_dt = h
        if self._settled:
            self._settled.clear()

    def deliver_post_solve(self) -> None:
        """Call the post-solve hooks once per hooked contact with the step's impulses."""
        if not self._post_acc:
            return
        items = sorted(
            self._post_acc.values(),
            key=lambda a: (a[0].kge_collider, a[1].kge_collider, a[0].kge_child, a[1].kge_child),
        )
        self._post_acc.clear()
        with self.world.locked():
            for sa, sb, _flip, jn, jt, count, normal in items:
                ev = PostSolve(
                    sa.kge_collider, sb.kge_collider, sa.kge_body, sb.kge_body, normal, count,
                    abs(jn), jt, sa.kge_child, sb.kge_child,
                )
                for fn in self.post_solve:
                    fn(ev)

    def forget_shapes(self, shapes: list[pymunk.Shape]) -> None:
        """Drop cached state of shapes leaving the space (their separates already ran)."""
        if not self._pre_cache:  # the usual case: no pre-solve hook holds a contact
            return
        gone = {id(s) for s in shapes}
        for key in [k for k in self._pre_cache if k[0] in gone or k[1] in gone]:
            del self._pre_cache[key]
