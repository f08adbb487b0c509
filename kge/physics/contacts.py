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
from kge.physics.cp import arbiter_handle
from kge.physics.cp import ffi as _ffi
from kge.physics.cp import lib as _lib
from kge.physics.cp.collisions import route_contacts
from kge.physics.events import (
    ContactBegin,
    ContactEnd,
    Hit,
    PhysicsEvents,
    SensorBegin,
    SensorEnd,
    builder,
)
from kge.physics.impact import Moves, settle, undo
from kge.physics.shape_table import (
    BOUNCY,
    GROUPED,
    HIT,
    HOOKED_FLAG,
    ONE_WAY,
    SENSOR,
    ShapeTable,
)
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


def a_first(table: ShapeTable, i: int, j: int) -> bool:
    """True when slot ``i`` is Box2D's fixture A of the pair (``i``, ``j``)."""
    si, sj = table.flags[i] & SENSOR, table.flags[j] & SENSOR
    if si != sj:
        return bool(si)
    return bool(table.order[i] <= table.order[j])


def _midpoints(cps: Any) -> tuple[Vec2, ...]:
    """World points of a Chipmunk contact point set: midpoints of the two surfaces."""
    p = cps.points[0]
    pa, pb = p.pointA, p.pointB
    first = (0.5 * (pa.x + pb.x), 0.5 * (pa.y + pb.y))
    if cps.count == 1:
        return (first,)
    p = cps.points[1]
    pa, pb = p.pointA, p.pointB
    return first, (0.5 * (pa.x + pb.x), 0.5 * (pa.y + pb.y))


def _geometry(cp_arb: Any, flip: bool) -> tuple[Vec2, tuple[Vec2, ...], float]:
    """Normal (A to B), world points (midpoints of the two surfaces) and separation.

    Read from Chipmunk's contact point set struct directly: pymunk's
    ``contact_point_set`` builds a Vec2d per number.
    """
    cps = _lib.cpArbiterGetContactPointSet(cp_arb)
    n = cps.normal
    sep = cps.points[0].distance
    if cps.count == 2:
        sep = min(sep, cps.points[1].distance)
    return ((-n.x, -n.y) if flip else (n.x, n.y)), _midpoints(cps), sep


_contact_begin = builder(ContactBegin)
_contact_end = builder(ContactEnd)
_sensor_begin = builder(SensorBegin)
_sensor_end = builder(SensorEnd)
_NO_BODY = -1


class ContactRecorder:
    """Owns the collision handlers of one space and records events into ``events``.

    The handlers read kge's data about both shapes from the space's
    :class:`~kge.physics.shape_table.ShapeTable` by slot. A plain contact (no
    sensor, filter group, one-way platform, restitution, hit threshold, hook or
    contact filter on either shape: the table's flags say so in one read) skips
    every rule that cannot apply to it.
    """

    def __init__(
        self, world: World, space: pymunk.Space, events: PhysicsEvents, errors: CallbackErrors,
        table: ShapeTable,
    ) -> None:
        self.world = world
        self.space = space
        self.events = events
        self.table = table
        self.velocity_threshold = 1.0
        #: (slot A, slot B) of every touching pair -> is it a sensor pair
        self.active: dict[tuple[int, int], bool] = {}
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
        route_contacts(space, self._begin, self._separate, self._errors)
        space.on_collision(
            HOOKED, None, pre_solve=guard(self._pre_solve), post_solve=guard(self._post_solve)
        )

    # -- begin / separate (once per contact) ------------------------------------------
    def _slots(self, cp_arb: Any) -> tuple[Any, Any, int, int]:
        """Chipmunk's two shapes of the arbiter, in its order, and their slots.

        The two pointer cells are reused: they are read back at once, with no
        Python call in between that could run another callback.
        """
        pa, pb = self._shape_ptrs
        _lib.cpArbiterGetShapes(cp_arb, pa, pb)
        p0, p1 = pa[0], pb[0]
        index = self.table.index
        return p0, p1, index[p0], index[p1]

    def _begin(self, cp_arb: Any) -> None:
        pa, pb = self._shape_ptrs  # (what _slots does, without its frame)
        _lib.cpArbiterGetShapes(cp_arb, pa, pb)
        p0, p1 = pa[0], pb[0]
        index = self.table.index
        i, j = index[p0], index[p1]
        b0, b1 = _lib.cpShapeGetBody(p0), _lib.cpShapeGetBody(p1)
        d0 = _lib.cpBodyGetType(b0) == _CP_DYNAMIC
        d1 = _lib.cpBodyGetType(b1) == _CP_DYNAMIC
        if not (d0 or d1) or not _lib.cpArbiterGetProcessCollision(cp_arb):
            # Box2D: static/kinematic pairs never touch
            _lib.cpArbiterSetProcessCollision(cp_arb, False)
            return
        table = self.table
        flags = table.flags
        f0, f1 = flags[i], flags[j]
        either = f0 | f1
        order = table.order
        if (f0 ^ f1) & SENSOR:
            flip = not f0 & SENSOR  # the sensor is side A
        else:
            flip = order[i] > order[j]
        ia, ib = (j, i) if flip else (i, j)
        if either & GROUPED and not table.filters[i].collides_with(table.filters[j]):
            _lib.cpArbiterSetProcessCollision(cp_arb, False)
            return
        sensor = bool(either & SENSOR)
        collider, body, child = table.collider, table.body, table.child
        ca, cb = collider[ia], collider[ib]
        if (
            not sensor and either & ONE_WAY
            and not self._one_way_accepts(ia, ib, _geometry(cp_arb, flip)[0])
        ):
            _lib.cpArbiterSetProcessCollision(cp_arb, False)
            return
        if self.contact_filter is not None:
            with self.world.locked():
                ok = self.contact_filter(ca, cb)
            if not ok:
                _lib.cpArbiterSetProcessCollision(cp_arb, False)
                return
        key = (ia, ib)
        self.active[key] = sensor
        ra, rb = body[ia], body[ib]
        ba = None if ra == _NO_BODY else ra
        bb = None if rb == _NO_BODY else rb
        ka, kb = child[ia], child[ib]
        if sensor:
            self.events.sensor_begin.append(_sensor_begin(ca, cb, ba, bb, ka, kb))
            return
        normal, points, sep = _geometry(cp_arb, flip)
        px, py = points[0]
        va = _lib.cpBodyGetVelocityAtWorldPoint(b0, (px, py))
        vb = _lib.cpBodyGetVelocityAtWorldPoint(b1, (px, py))
        # B's speed towards A along the normal, in Chipmunk's order (the same number)
        rel = (vb.x - va.x) * normal[0] + (vb.y - va.y) * normal[1]
        speed = (rel if flip else -rel) if (rel > 0.0 if flip else rel < 0.0) else 0.0
        # Box2D's time of impact: a dynamic body against a static or kinematic one, or a
        # pair with a bullet (here also with a body pushed from outside this step)
        if sep < -self.slop and (not (d0 and d1) or b0 in self.toi or b1 in self.toi):
            moves = settle(cp_arb, self.slop, self.substep_dt)
            if moves:
                self._settled[key] = moves
                normal, points, sep = _geometry(cp_arb, flip)
        if either & BOUNCY:
            ea, eb = table.restitution[i], table.restitution[j]
            e = ea if ea > eb else eb
            if e > 0.0 and speed > self.velocity_threshold:
                _lib.cpArbiterSetRestitution(cp_arb, e)
        self.events.contact_begin.append(
            _contact_begin(ca, cb, ba, bb, normal, points, sep, speed, ka, kb)
        )
        if either & HIT:
            ta, tb = table.hit[ia], table.hit[ib]
            limit = tb if ta != ta else (ta if tb != tb or ta > tb else tb)  # NaN: none
            if speed > limit:
                self.events.hits.append(Hit(ca, cb, ba, bb, points[0], normal, speed, ka, kb))

    def _one_way_accepts(self, ia: int, ib: int, normal: Vec2) -> bool:
        oneway = self.table.oneway
        for plat, sign in ((ia, 1.0), (ib, -1.0)):
            spec = oneway[plat]
            if spec is None:
                continue
            (ux, uy), min_cos = spec
            # normal from the platform to the other shape
            if sign * (normal[0] * ux + normal[1] * uy) < min_cos:
                return False
        return True

    def _separate(self, cp_arb: Any) -> None:
        _p0, _p1, i, j = self._slots(cp_arb)
        key = (i, j)
        sensor = self.active.pop(key, None)
        if sensor is None:
            key = (j, i)
            sensor = self.active.pop(key, None)
            if sensor is None:
                return
        if self._pre_cache:
            self._pre_cache.pop(key, None)
        table = self.table
        ia, ib = key
        ra, rb = table.body[ia], table.body[ib]
        ident = (
            table.collider[ia], table.collider[ib], None if ra == _NO_BODY else ra,
            None if rb == _NO_BODY else rb, table.child[ia], table.child[ib],
        )
        if sensor:
            self.events.sensor_end.append(_sensor_end(*ident))
        else:
            self.events.contact_end.append(_contact_end(*ident))

    # -- user hooks (per step, only for HOOKED shapes) -------------------------------------
    def _ordered(self, arb: pymunk.Arbiter) -> tuple[int, int, bool] | None:
        """Canonical (slot A, slot B, flip) of a hooked contact, or None to skip this call.

        pymunk runs the (HOOKED, None) handler twice when both shapes are hooked,
        once per order; only the call seeing A first goes on.
        """
        _p0, _p1, i, j = self._slots(arbiter_handle(arb))
        table = self.table
        flip = not a_first(table, i, j)
        if flip and table.flags[j] & HOOKED_FLAG:
            return None
        ia, ib = (j, i) if flip else (i, j)
        if (ia, ib) not in self.active or (table.flags[ia] | table.flags[ib]) & SENSOR:
            return None
        return ia, ib, flip

    def _pre_solve(self, arb: pymunk.Arbiter, space: pymunk.Space, data: Any) -> None:
        if not self.pre_solve:
            return
        got = self._ordered(arb)
        if got is None:
            return
        ia, ib, flip = got
        key = (ia, ib)
        contact = self._pre_cache.get(key) if self.substep > 0 else None
        fresh = contact is None
        if contact is None:
            table = self.table
            normal, points, sep = _geometry(arbiter_handle(arb), flip)
            fr = float(table.friction[ia] * table.friction[ib]) ** 0.5
            contact = PreSolve(
                int(table.collider[ia]), int(table.collider[ib]), table.body_entity(ia),
                table.body_entity(ib), normal, points, sep, True, fr, arb.restitution, 0.0,
                int(table.child[ia]), int(table.child[ib]),
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
        ia, ib, flip = got
        key = (ia, ib)
        j = arb.total_impulse  # applied to shapes[0]
        n = arb.normal  # shapes[0] -> shapes[1]
        acc = self._post_acc.get(key)
        if acc is None:
            acc = self._post_acc[key] = [ia, ib, flip, 0.0, 0.0, 0, (0.0, 0.0)]
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
        table = self.table

        def ident(a: list[Any]) -> tuple[int, int, int, int]:
            ia, ib = a[0], a[1]
            return (int(table.collider[ia]), int(table.collider[ib]), int(table.child[ia]),
                    int(table.child[ib]))

        items = sorted(self._post_acc.values(), key=ident)
        self._post_acc.clear()
        with self.world.locked():
            for ia, ib, _flip, jn, jt, count, normal in items:
                ev = PostSolve(
                    int(table.collider[ia]), int(table.collider[ib]), table.body_entity(ia),
                    table.body_entity(ib), normal, count, abs(jn), jt, int(table.child[ia]),
                    int(table.child[ib]),
                )
                for fn in self.post_solve:
                    fn(ev)

    def forget_shapes(self, shapes: list[pymunk.Shape]) -> None:
        """Drop cached state of shapes leaving the space (their separates already ran)."""
        if not self._pre_cache:  # the usual case: no pre-solve hook holds a contact
            return
        gone = {self.table.slot(s) for s in shapes}
        for key in [k for k in self._pre_cache if k[0] in gone or k[1] in gone]:
            del self._pre_cache[key]
