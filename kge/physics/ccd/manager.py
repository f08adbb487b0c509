"""ContinuousCollision: one bulk read per step, speed caps, and arming the fast bodies.

:class:`ContinuousCollision` owns the per-body :class:`~kge.physics.ccd.sweep.Tracked`
records and the :class:`~kge.physics.ccd.obstacles.Obstacles` index of one space.
Before each step it reads every body with ``pymunk.batch``, caps speeds, and arms
the swept integrator only on the tracked bodies that are fast and have something
within reach; after the step it caps again and disarms.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import Any

import numpy as np
import pymunk
import pymunk.batch

from kge.errors import ComponentTypeError, ValidationError
from kge.physics.callback_errors import CallbackErrors
from kge.physics.ccd.obstacles import Nearby, Obstacles
from kge.physics.ccd.parts import extent_of, parts_of
from kge.physics.ccd.sweep import Tracked, grown
from kge.physics.cp import body_shapes, shape_space
from kge.physics.cp.bulk import BodyReader
from kge.physics.shape_table import ShapeTable
from kge.physics.speed_cap import clamp_one, largest, screen
from kge.validate import boolean, integer, non_negative, positive

#: ``pair_filter(moving_shape, other_shape) -> bool``: False = they never touch.
PairFilter = Callable[[pymunk.Shape, pymunk.Shape], bool]
_ALL = pymunk.ShapeFilter()
_DYNAMIC = pymunk.Body.DYNAMIC
_KINEMATIC = pymunk.Body.KINEMATIC
_SQRT2 = math.sqrt(2.0)
_FIELDS = (
    pymunk.batch.BodyFields.BODY_ID
    | pymunk.batch.BodyFields.POSITION
    | pymunk.batch.BodyFields.ANGLE
    | pymunk.batch.BodyFields.VELOCITY
    | pymunk.batch.BodyFields.ANGULAR_VELOCITY
)


class Index:
    """The tracked bodies sorted by id, with their radii as arrays.

    Immutable: a change of the tracked set makes a new one (:meth:`changed`), so
    caches keyed on an index see the change.
    """

    __slots__ = (
        "bullet", "bullets", "core", "extent", "ids", "infos", "max_extent", "max_reach",
        "min_core", "reach",
    )

    def __init__(self, tracked: dict[int, Tracked]) -> None:
        # the keys are the body ids: no ``body.id`` (a pymunk property, a cffi cast each)
        # per body, which made this rebuild, after every track/untrack, cost ~2 us a body
        keys = sorted(tracked)
        infos = [tracked[k] for k in keys]
        n = len(keys)
        self._fill(
            np.fromiter(keys, dtype=np.int64, count=n),
            np.fromiter([t.core for t in infos], dtype=np.float64, count=n),
            np.fromiter([t.reach for t in infos], dtype=np.float64, count=n),
            np.fromiter([t.extent for t in infos], dtype=np.float64, count=n),
            np.fromiter([t.bullet for t in infos], dtype=bool, count=n),
            _objects(infos),
        )

    def _fill(self, ids: np.ndarray, core: np.ndarray, reach: np.ndarray, extent: np.ndarray,
              bullet: np.ndarray, infos: np.ndarray) -> None:
        self.ids, self.core, self.reach, self.extent = ids, core, reach, extent
        self.bullet, self.infos = bullet, infos  # infos: an object array, read by slot
        some = len(ids) > 0
        self.max_extent = float(extent.max()) if some else 0.0
        self.max_reach = float(reach.max()) if some else 0.0
        self.min_core = float(core.min()) if some else 0.0
        self.bullets = bool(bullet.any())

    def changed(self, removed: set[int], added: dict[int, Tracked]) -> Index:
        """This index without the bodies ``removed`` (ids) and with ``added`` (by id):
        what a new index of the tracked bodies would be, with Python work only for
        the change (a body spawned or despawned among thousands of tracked bodies)."""
        keep = ~np.isin(self.ids, np.fromiter(removed, dtype=np.int64, count=len(removed)))
        new = Index(added)
        ids = np.concatenate([self.ids[keep], new.ids])
        order = np.argsort(ids, kind="stable")  # unique ids: the one sorted order
        out = Index.__new__(Index)
        out._fill(*(np.concatenate([col[keep], extra])[order] for col, extra in (
            (self.ids, new.ids), (self.core, new.core), (self.reach, new.reach),
            (self.extent, new.extent), (self.bullet, new.bullet), (self.infos, new.infos))))
        return out


def _objects(items: list[Tracked]) -> np.ndarray:
    out = np.empty(len(items), dtype=object)
    for i, item in enumerate(items):
        out[i] = item
    return out


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
        shapes: ShapeTable | None = None,
    ) -> None:
        if not isinstance(space, pymunk.Space):
            raise ComponentTypeError(
                f"ContinuousCollision: expected a pymunk.Space, got {type(space).__name__}"
            )
        if pair_filter is not None and not callable(pair_filter):
            raise ComponentTypeError("ContinuousCollision.pair_filter must be callable or None")
        self.space = space
        #: kge's data about the space's shapes (their filters and one-way platforms)
        self.shapes = shapes if shapes is not None else ShapeTable.of(space)
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
        self._tracked: dict[int, Tracked] = {}
        self._bodies: dict[int, pymunk.Body] = {}  # every tracked body, for clamping by id
        self._movers: dict[int, pymunk.Body] = {}  # moving untracked (kinematic) bodies seen
        self._boosted: list[Tracked] = []
        self._armed: dict[int, Tracked] = {}  # id(info) -> info
        self._reader = BodyReader(_FIELDS)
        self._index: Index | None = None
        #: body id -> its new record (None: untracked) since the index was made
        self._index_changes: dict[int, Tracked | None] = {}
        #: the last bulk read's body ids and their rows in the index (reused while unchanged)
        self._rows: (
            tuple[bytes, Index, np.ndarray, np.ndarray, np.ndarray, np.ndarray] | None
        ) = None
        self._untracked = np.empty(0, dtype=np.int64)  # rows of _rows not tracked
        #: (rows, substeps, threshold, per-row motion limit: inf for untracked rows)
        self._limit: tuple[Any, int, float, np.ndarray] | None = None
        self._generation = 0  # bumped whenever _rows is recomputed
        self._obstacles = Obstacles(space)
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
        self._index_changed(key, None)
        self._obstacles.reclassify(body)  # its type may have changed in place
        if body.body_type != _DYNAMIC:
            return
        # only the shapes in the space: pymunk keeps a removed shape on its body (a
        # replaced collider's old shapes), which must not be swept nor bound the body
        space = self.space
        shapes = tuple(s for s in body_shapes(body) if shape_space(s) is space)
        parts, core, reach = parts_of(body, shapes, self.margin)
        self._tracked[key] = info = Tracked(
            self, body, bullet, parts, core, reach, shapes, extent_of(body, shapes, reach)
        )
        self._index_changed(key, info)

    def untrack(self, body: pymunk.Body, removed: bool = False) -> None:
        """Forget ``body`` (restores its plain integrator); unknown bodies are ignored.

        ``removed``: the body is leaving the space with all its shapes, so its
        obstacle rows are dropped at once instead of re-read one by one.
        """
        self._bodies.pop(body.id, None)
        self._movers.pop(body.id, None)  # else a removed kinematic body stays referenced
        if removed:
            self._obstacles.forget_owner(body.id)
        else:
            self._obstacles.reclassify(body)  # it may have become static or kinematic
        info = self._tracked.pop(body.id, None)
        if info is not None:
            self._index_changed(body.id, None)
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
        rows_vel = vel
        top = largest(vel)  # the largest |component|: the caps' screen and the sweeps'
        vel = self._clamp(ids, vel, dt, top)
        if vel is not rows_vel:
            top = largest(vel)  # some were capped
        for info in self._boosted:
            info.boost = 0.0
        self._boosted.clear()
        self._near_memo.clear()
        if not self._tracked:
            return 0
        pos, known, core, reach = self._rows_of(ids)
        index = self._lookup_index()
        want: dict[int, Tracked] = {}
        # one bound screens every body: no component of any velocity above ``top``
        # means no tracked body moves more than (sqrt 2 + its reach) * top * dt, and
        # when that is under the smallest threshold none is fast (a settled or slow
        # world then skips the per-body arrays below; a NaN fails the test)
        bound = (_SQRT2 + index.max_reach) * top * dt
        speed: np.ndarray | None = None
        if not bound <= self.threshold * n * index.min_core:
            speed = np.hypot(vel[:, 0], vel[:, 1])
            motion = (speed + np.abs(vel[:, 2]) * reach) * dt
            fast = np.flatnonzero(motion > self._motion_limit(n, known, core))
            if len(fast):
                self._arm_fast(fast, pos[fast], ids, pose, vel, motion[fast], want)
        untracked = self._untracked
        if self._movers or largest(vel[untracked]) > 0.0:
            if speed is None:
                speed = np.hypot(vel[:, 0], vel[:, 1])
            moving = ~known & ((speed > 0.0) | (vel[:, 2] != 0.0))
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
        want: dict[int, Tracked],
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
        # what a neighbour launched by the body could hit (see _arm_neighbours): the
        # obstacle rows in that square, found for all fast bodies in one query, answer
        # every later question about the body and its neighbours (Nearby.holds)
        wide = reach + 2.0 * self.max_translation + 2.0 * index.max_extent
        around = obstacles.nearby(x, y, wide)
        bullets = index.bullets
        fast = []
        for slot, m, near, px, py, r in zip(
            slots.tolist(), motion.tolist(), around, x.tolist(), y.tolist(), reach.tolist(),
            strict=True,
        ):
            close = bool(near.rows)
            if not (close or bullets):
                continue  # with no bullet anywhere, a body with nothing close needs no look
            info = index.infos[slot]
            if (info.bullet or (close and near.overlaps(px, py, r))) and info.near_obstacles(
                m, near
            ):
                want[id(info)] = info
            fast.append((info, m, close, near))
        self._arm_neighbours(fast, want, bullets)

    def _arm_neighbours(
        self,
        fast: list[tuple[Tracked, float, bool, Nearby]],
        want: dict[int, Tracked],
        bullets: bool,
    ) -> None:
        """Arm the bodies a fast body may hit this step.

        A collision inside the step can launch a slow body at up to the speed cap
        (Box2D computes impacts after the solve, with the new velocities), so a
        neighbour within a fast body's reach is armed when something it could
        then hit is within twice the speed cap of it; its integrator stays cheap
        until it is actually fast. A bullet neighbour is also boosted, so it
        sweeps against the fast body even while it is itself at rest.

        ``fast`` holds (body, step motion, close, the obstacle rows around it):
        ``close`` is False when no static or kinematic shape lies within what any
        neighbour could reach, so only bullet neighbours matter (none when
        ``bullets`` is False).
        """
        # a light body hit by a heavy one leaves at up to (1 + e) times its speed,
        # and only armed bodies are capped within the step
        cap = 2.0 * self.max_translation
        for info, motion, close, around in fast:
            if not (close or bullets):
                continue
            box = info._bounds()
            if box is None:
                continue
            for shape in self.space.bb_query(grown(box, motion), _ALL):
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
                    id(near) not in want
                    and (close or near.bullet)
                    and self._near_within(near, cap, around)
                ):
                    want[id(near)] = near

    def _near_within(self, info: Tracked, reach: float, around: Nearby) -> bool:
        """``info.near_obstacles(reach)``, asked at most once per body and step."""
        key = id(info)
        hit = self._near_memo.get(key)
        if hit is None:
            hit = self._near_memo[key] = info.near_obstacles(reach, around)
        return hit

    def _boost_near_movers(
        self,
        ids: np.ndarray,
        moving: np.ndarray,
        vel: np.ndarray,
        dt: float,
        substeps: int,
        want: dict[int, Tracked],
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
            region = grown(box, step + self.max_translation)
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
        ids, data = self._reader.read(self.space)
        return ids, data[:, :3], data[:, 3:]

    def _clamp(
        self, ids: np.ndarray, vel: np.ndarray, dt: float, top: float | None = None
    ) -> np.ndarray:
        """Cap the rows' bodies; ``vel`` itself when none is over (``top``: its
        :func:`largest`, when the caller has it). A copy when some were capped."""
        max_v = self.max_translation / dt
        max_w = self.max_rotation / dt
        if top is None:
            top = largest(vel)
        if not top > screen(max_v, max_w):  # maybe_over, reusing top (errstate costs more)
            return vel
        with np.errstate(over="ignore"):  # inf is over the limit; clamp_one is overflow-safe
            speed2 = vel[:, 0] ** 2 + vel[:, 1] ** 2
        over = (speed2 > max_v * max_v) | (np.abs(vel[:, 2]) > max_w)
        if not over.any():
            return vel
        vel = vel.copy()
        for row in np.flatnonzero(over):
            body = self._body_by_id(int(ids[row]))
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

    def _body_by_id(self, body_id: int) -> pymunk.Body | None:
        body = self._bodies.get(body_id) or self._movers.get(body_id)
        body = body or self._obstacles.body(body_id)
        if body is None:  # untracked (e.g. a user-made pymunk body): rare, so a plain scan
            body = next((b for b in self.space.bodies if b.id == body_id), None)
        return body

    def _index_changed(self, key: int, info: Tracked | None) -> None:
        """Record a change of the tracked set for the next :meth:`_lookup_index`."""
        if not self._tracked:  # nothing left to index: drop it (rebuilt when next needed)
            self._index = None
            self._index_changes.clear()
        elif self._index is not None:
            self._index_changes[key] = info

    def _lookup_index(self) -> Index:
        if self._index is None:
            self._index = Index(self._tracked)
            self._index_changes.clear()
        elif self._index_changes:
            changes, self._index_changes = self._index_changes, {}
            added = {k: t for k, t in changes.items() if t is not None}
            self._index = self._index.changed(set(changes), added)
        return self._index

    def _rows_of(self, ids: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        """Per bulk-read row: its slot in the index, whether tracked, core radius and reach.

        Recomputed only when the read's body order or the tracked set changed
        (bodies added, removed, falling asleep or waking), else reused.
        """
        index = self._lookup_index()
        cached = self._rows
        key = ids.tobytes()  # one memcmp, cheaper than np.array_equal
        if cached is not None and cached[1] is index and cached[0] == key:
            return cached[2:]
        pos = np.minimum(np.searchsorted(index.ids, ids), len(index.ids) - 1)
        known = index.ids[pos] == ids
        self._rows = (key, index, pos, known, index.core[pos], index.reach[pos])
        self._untracked = np.flatnonzero(~known)  # static and kinematic rows
        self._generation += 1
        return self._rows[2:]

    def _motion_limit(self, substeps: int, known: np.ndarray, core: np.ndarray) -> np.ndarray:
        """Per bulk-read row, the step motion beyond which a tracked body is fast
        (``threshold * substeps * core``; inf for untracked rows, which are never fast),
        kept while the rows, the substeps and the threshold stay."""
        rows, limit = self._rows, self._limit
        if limit is None or limit[0] is not rows or limit[1] != substeps or (
            limit[2] != self.threshold
        ):
            values = np.where(known, self.threshold * substeps * core, np.inf)
            limit = self._limit = (rows, substeps, self.threshold, values)
        return limit[3]

    @staticmethod
    def _disarm(info: Tracked) -> None:
        restore = info.saved if info.saved is not None else pymunk.Body.update_position
        info.body.position_func = restore
        info.saved = None
        info.armed = False
