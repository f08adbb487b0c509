"""Running tweens: every live tween is a row of numpy arrays, eased in one pass per frame.

A started spec (a :class:`~kge.components.tween.Tween`, or a TweenSequence/Parallel
tree of them) becomes one *group* and one *channel* per Tween: the tree is
flattened into start offsets inside the group, so sequences and parallel
groups cost nothing per frame beyond their channels. Each pass:

1. group clocks advance by ``dt`` (game time); a repeating group wraps;
2. every channel's local time ``u = group time - offset`` gives its cycle and
   progress (``repeat`` and ``yoyo`` folded in), eased with one numpy call per
   easing used, and lerped from its start value to its end value;
3. values are written back to the components; only that step is per channel
   Python (a plain float field of a tracked component is written without
   re-validation: a lerp of finite values is finite).

Tweens of a physics body's ``Transform`` (x, y, angle of a dynamic or kinematic
body) are not written as poses, which physics would take as a teleport: they
advance in the fixed step, before physics, and set the body's velocity so the
step carries it to the eased pose (a *kinematic move*: contacts respond, no jump),
then stop it where the tween ends.
"""

from __future__ import annotations

import dataclasses
import math
from collections import deque
from collections.abc import Callable
from operator import attrgetter, itemgetter
from typing import Any

import numpy as np

from kge.animation.easing import apply, easing_code
from kge.components.rigidbody import BodyType, RigidBody
from kge.components.tracked import Tracked, raw_set
from kge.components.transform import Transform
from kge.components.tween import Call, Delay, Parallel, Tween, TweenSequence
from kge.errors import ComponentTypeError, ValidationError, where
from kge.snapshot import carry_running
from kge.validate import MAX_COORDINATE, coordinate, finite

WIDTH = 4  # widest value: an RGBA colour
_binding = attrgetter("_binding")
_AXES = {"x": 0, "y": 1, "angle": 2}


class TweenHandle:
    """A started tween: ``done``, ``cancelled``, ``cancel()``; ``pause()``, ``resume()``
    and ``speed`` (1: as written, 2: twice as fast); a coroutine may ``yield`` it."""

    __slots__ = ("_table", "cancelled", "done", "entity", "group", "name")

    def __init__(self, table: TweenTable, group: int, entity: int | None, name: str) -> None:
        self._table = table
        self.group = group
        self.entity = entity
        self.name = name
        self.done = False
        self.cancelled = False

    def cancel(self) -> None:
        """Stop where it is (no finished event; a waiting coroutine resumes)."""
        if not self.done:
            self._table.cancel(self)

    def is_done(self) -> bool:
        """True once finished or cancelled (what ``yield handle`` waits for)."""
        return self.done

    def pause(self) -> None:
        """Hold it where it is until :meth:`resume` (the game runs on)."""
        self._table.set_paused(self, True)

    def resume(self) -> None:
        self._table.set_paused(self, False)

    @property
    def paused(self) -> bool:
        return self._table.group_value(self, "g_paused", False)

    @property
    def speed(self) -> float:
        """How fast its clock runs: 1 as written, 0.5 half speed (>= 0)."""
        return self._table.group_value(self, "g_speed", 1.0)

    @speed.setter
    def speed(self, value: float) -> None:
        self._table.set_speed(self, value)

    def __repr__(self) -> str:
        state = "cancelled" if self.cancelled else "done" if self.done else "running"
        return f"<TweenHandle {self.name or self.group} {state}>"


def _field_ok(cls: type, name: str) -> bool:
    tweenable = getattr(cls, "tweenable", None)  # fields a component names itself
    if callable(tweenable) and tweenable(name):
        return True
    if dataclasses.is_dataclass(cls) and any(
        f.name == name and not f.name.startswith("_") for f in dataclasses.fields(cls)
    ):
        return True
    prop = getattr(cls, name, None)
    return isinstance(prop, property) and prop.fset is not None


#: the largest magnitude of a tween's start, current and target values: the eased
#: value ``start + (end - start) * eased`` then stays finite for every easing (Penner's
#: curves overshoot to at most -0.5..1.5), so no tween can write an overflow
MAX_VALUE = 1e300
#: the most tween channels one start may make (a TweenSequence's repeats are unrolled into
#: channels, so ``TweenSequence(..., repeat=10**9)`` would allocate until memory runs out)
MAX_CHANNELS = 100_000


def _as_vector(value: Any, label: str, what: str) -> tuple[list[float], bool]:
    """``value`` as up to 4 numbers, and whether they are all integers."""
    items = list(value) if isinstance(value, (tuple, list)) else [value]
    if not 1 <= len(items) <= WIDTH:
        raise ValidationError(f"{label}: {what} {value!r} is not a number, vector or colour")
    out = []
    for v in items:
        if isinstance(v, bool) or not isinstance(v, (int, float, np.integer, np.floating)):
            raise ValidationError(
                f"{label}: {what} {value!r} is not numeric (a tween animates numbers, "
                "vectors and colours)"
            )
        try:
            f = float(v)
        except OverflowError:  # an int beyond float64
            f = math.inf
        if not math.isfinite(f):
            raise ValidationError(f"{label}: {what} must be finite, got {value!r}")
        if abs(f) > MAX_VALUE:
            raise ValidationError(
                f"{label}: {what} must be within +-{MAX_VALUE:g}, got {value!r}"
            )
        out.append(f)
    ints = all(isinstance(v, (int, np.integer)) for v in items)
    return out, ints


def _check_ends(obj: Any, field: str, entity: int | None, label: str, vector: bool,
                ints: bool, to: list[float], start: list[float] | None) -> None:
    """Run the field's own check on the target (and start) value, so a tween that would
    end outside the field's range (an opacity of 300, a zoom of 0) is refused here, at
    the start, instead of failing at a later frame."""
    check = getattr(type(obj), "_checks", {}).get(field)
    if check is None:
        return
    for what, nums in (("target value", to), ("start value", start)):
        if nums is None:
            continue
        vals = [round(v) for v in nums] if ints else nums
        value = tuple(vals) if vector else vals[0]
        try:
            check(value, where(entity, type(obj).__name__), field)
        except ValidationError as err:
            raise ValidationError(
                f"{label}: the {what} is out of the field's range: {err}"
            ) from None


@dataclasses.dataclass(slots=True)
class _Plan:
    """One flattened Tween (or Call): where it starts in its group."""

    spec: Tween | Call
    offset: float


def channels(spec: Any) -> int:
    """How many channels ``spec`` makes once flattened (its Sequences' repeats unrolled).

    >>> from kge.components.transform import Transform
    >>> step = Tween(Transform, "x", 1.0, 0.1)
    >>> channels(TweenSequence(step, Parallel(step, step), repeat=2))
    9
    """
    if isinstance(spec, Tween):
        return 1
    if isinstance(spec, Parallel):
        return sum(channels(s) for s in spec.steps)
    if isinstance(spec, TweenSequence):
        reps = 1 if spec.repeat < 0 else spec.repeat + 1
        return reps * sum(channels(s) for s in spec.steps)
    return 0


class _Pending:
    """A Call of a running group: when it is next due (group time; inf: never again)."""

    __slots__ = ("call", "due", "period")

    def __init__(self, call: Call, due: float, period: float) -> None:
        self.call, self.due, self.period = call, due, period


class MethodTarget:
    """What :meth:`Tweens.method` animates: ``value``, whose every write calls ``fn``."""

    __slots__ = ("_value", "fn")

    def __init__(self, fn: Callable[[Any], Any], value: Any) -> None:
        self.fn = fn
        self._value = value

    @property
    def value(self) -> Any:
        return self._value

    @value.setter
    def value(self, v: Any) -> None:
        self._value = v
        self.fn(v)


def _flatten(spec: Any, offset: float, out: list[_Plan], top: bool) -> float:
    """Append ``spec``'s tweens and calls with their offsets; return its length (inf:
    forever)."""
    if isinstance(spec, Tween):
        out.append(_Plan(spec, offset))
        return spec.total
    if isinstance(spec, Call):
        out.append(_Plan(spec, offset))
        return 0.0
    if isinstance(spec, Delay):
        return spec.total
    if isinstance(spec, Parallel):
        return max(_flatten(s, offset, out, False) for s in spec.steps)
    if isinstance(spec, TweenSequence):
        if spec.repeat < 0 and not top:
            raise ValidationError(
                "TweenSequence(repeat=-1) repeats forever: only the outermost may"
            )
        reps = 1 if spec.repeat < 0 else spec.repeat + 1
        t = offset
        for _ in range(reps):
            for s in spec.steps:
                t += _flatten(s, t, out, False)
        return (t - offset) if spec.repeat >= 0 else math.inf
    raise ComponentTypeError(f"cannot start {spec!r}: expected a Tween, TweenSequence or Parallel")


class TweenTable:
    """The tween rows of one world (see the module docstring)."""

    def __init__(self, world: Any) -> None:
        self.world = world
        self.handles: dict[int, TweenHandle] = {}
        self._serial = 0
        n = 0
        # channels
        self.group = np.zeros(n, np.int64)
        self.offset = np.zeros(n)
        self.duration = np.ones(n)
        self.cycles = np.ones(n)  # repeat + 1 (inf: forever)
        self.yoyo = np.zeros(n, bool)
        self.ease = np.zeros(n, np.intp)
        self.v_start = np.zeros((n, WIDTH))
        self.v_end = np.zeros((n, WIDTH))
        self.captured = np.zeros(n, bool)
        self.prev_u = np.zeros(n)
        self.live = np.zeros(n, bool)
        self.fixed = np.zeros(n, bool)  # advanced in the fixed step (physics bodies)
        self.kind = np.zeros(n, np.int8)  # how the value is written (see _resolve)
        self.gslot = np.zeros(n, np.intp)  # the row of each channel's group in the g_ arrays
        self.objs: list[Any] = []  # the component of each channel
        self.fields: list[str] = []
        #: (component, field, width, kind, entity, axis) per channel
        self.targets: list[tuple[Any, str, int, int, int | None, int]] = []
        # groups (by group id -> arrays indexed by group slot)
        self.g_ids = np.zeros(0, np.int64)
        self.g_elapsed = np.zeros(0)
        self.g_period = np.zeros(0)  # one pass (repeat-forever sequences wrap at it)
        self.g_total = np.zeros(0)  # inf for forever
        self.g_fixed = np.zeros(0, bool)
        self.g_live = np.zeros(0, bool)
        self.g_speed = np.zeros(0)  # per-tween speed (handle.speed)
        self.g_paused = np.zeros(0, bool)
        self.relative = np.zeros(0, bool)  # v_end holds an offset until the start is known
        self.calls: dict[int, list[_Pending]] = {}  # group id -> its Call steps
        self._by_target: dict[tuple[int, type], list[int]] = {}
        self._hooked: set[type] = set()
        self.stop_next: list[tuple[int, int]] = []  # (entity, axis): zero velocity next step
        self.on_finish: Callable[[TweenHandle], None] | None = None

    def __len__(self) -> int:
        """How many tween channels are running."""
        return int(np.count_nonzero(self.live))

    @property
    def rows(self) -> int:
        """Channel rows held: the running ones and finished ones not yet compacted away
        (never more than twice the running ones, plus a little slack)."""
        return len(self.live)

    # -- snapshots (kge.snapshot.carry_running) ------------------------------------------
    def export_running(self) -> dict[str, Any]:
        """The rows and groups, with each channel's target named by entity and type (or
        by resource type): a restored world finds its own components again."""
        world, keys = self.world, []
        for i, (obj, field, width, kind, ent, axis) in enumerate(self.targets):
            key: tuple[Any, ...] | None = None
            if self.live[i] and ent is not None:
                key = ("entity", ent, type(obj))
            elif self.live[i] and world.try_resource(type(obj)) is obj:
                key = ("resource", type(obj))
            keys.append(None if key is None else (*key, field, width, kind, axis))
        arrays = {k: v.copy() for k, v in vars(self).items() if isinstance(v, np.ndarray)}
        groups = {gid: (h.entity, h.name) for gid, h in self.handles.items()}
        return {"arrays": arrays, "targets": keys, "groups": groups, "serial": self._serial,
                "stop_next": list(self.stop_next)}  # fmt: skip

    def import_running(self, data: dict[str, Any]) -> None:
        """Continue the tweens of a restored world; a channel whose target is gone ends."""
        world = self.world
        for name, arr in data["arrays"].items():
            setattr(self, name, arr)
        self.targets, self.objs, self.fields, self._by_target = [], [], [], {}
        for i, key in enumerate(data["targets"]):
            obj = None
            if key is not None and key[0] == "entity":
                _, ent, ctype, field, width, kind, axis = key
                obj = world.try_get(ent, ctype) if world.exists(ent) else None
            elif key is not None:
                _, ctype, field, width, kind, axis = key
                ent, obj = None, world.try_resource(ctype)
            if obj is None:
                self.live[i] = False
                self.targets.append((None, "", 0, 0, None, -1))
                self.objs.append(None)
                self.fields.append("")
                continue
            self.targets.append((obj, field, width, kind, ent, axis))
            self.objs.append(obj)
            self.fields.append(field)
            if ent is not None:
                self._by_target.setdefault((ent, ctype), []).append(i)
                self._hook(ctype)
        self.handles = {}
        for gid, (ent, name) in data["groups"].items():
            self.handles[gid] = TweenHandle(self, gid, ent, name)
            self._group_maybe_gone(gid)
        self._serial = data["serial"]
        self.stop_next = list(data["stop_next"])

    # -- starting ----------------------------------------------------------------------
    def start(self, target: Any, spec: Any) -> TweenHandle:
        """Start ``spec`` on ``target`` (an entity id, or a component/resource instance).

        Everything is checked before anything is added: a bad target, field or
        value raises and leaves the table as it was.
        """
        n = channels(spec)
        if n > MAX_CHANNELS:
            raise ValidationError(
                f"{spec!r:.80} makes {n:,} tween channels once its repeats are unrolled, "
                f"more than {MAX_CHANNELS:,}: repeat the Tweens inside it instead"
            )
        found: list[_Plan] = []
        top_total = _flatten(spec, 0.0, found, True)
        forever_seq = isinstance(spec, TweenSequence) and spec.repeat < 0
        period = spec.once if forever_seq else top_total
        if not found:
            raise ValidationError(f"{spec!r} animates nothing (only delays)")
        if forever_seq and not period > 0:
            raise ValidationError(f"{spec!r} repeats forever but takes no time")
        plans = [p for p in found if isinstance(p.spec, Tween)]
        specs: list[Tween] = [p.spec for p in plans if isinstance(p.spec, Tween)]
        rows = [self._resolve(target, p) for p in plans]
        self._serial += 1
        gid = self._serial
        entity = target if isinstance(target, int) and not isinstance(target, bool) else None
        name = getattr(spec, "name", "")
        handle = TweenHandle(self, gid, entity, name)
        self.handles[gid] = handle
        any_fixed = any(r[5] == 2 for r in rows)
        self.g_ids = np.append(self.g_ids, gid)
        self.g_elapsed = np.append(self.g_elapsed, 0.0)
        self.g_period = np.append(self.g_period, period if forever_seq else math.inf)
        self.g_total = np.append(self.g_total, math.inf if forever_seq else top_total)
        self.g_fixed = np.append(self.g_fixed, any_fixed)
        self.g_live = np.append(self.g_live, True)
        self.g_speed = np.append(self.g_speed, 1.0)
        self.g_paused = np.append(self.g_paused, False)
        loop = period if forever_seq else math.inf
        pending = [_Pending(p.spec, p.offset, loop) for p in found if isinstance(p.spec, Call)]
        if pending:
            self.calls[gid] = pending
        k = len(rows)
        base = len(self.targets)
        start = np.zeros((k, WIDTH))
        end = np.zeros((k, WIDTH))
        captured = np.zeros(k, bool)
        for i, r in enumerate(rows):
            obj, field, width, s, e, kind, ent, axis = r
            end[i, :width] = e
            if s is not None:
                start[i, :width] = s
                captured[i] = True
            self.targets.append((obj, field, width, kind, ent, axis))
            self.objs.append(obj)
            self.fields.append(field)
            if ent is not None:
                self._by_target.setdefault((ent, specs[i].component), []).append(base + i)
                self._hook(specs[i].component)
        self.relative = np.concatenate(
            [self.relative, [bool(s.relative) and s.start is None for s in specs]]
        ).astype(bool)
        self.group = np.concatenate([self.group, np.full(k, gid, np.int64)])
        self.offset = np.concatenate(
            [self.offset, [p.offset + s.delay for p, s in zip(plans, specs, strict=True)]]
        )
        self.duration = np.concatenate([self.duration, [float(s.duration) for s in specs]])
        self.cycles = np.concatenate(
            [self.cycles, [math.inf if s.repeat < 0 else s.repeat + 1.0 for s in specs]]
        )
        self.yoyo = np.concatenate([self.yoyo, [bool(s.yoyo) for s in specs]])
        codes = [easing_code(s.ease) for s in specs]
        self.ease = np.concatenate([self.ease, codes]).astype(np.intp)
        self.v_start = np.concatenate([self.v_start, start])
        self.v_end = np.concatenate([self.v_end, end])
        self.captured = np.concatenate([self.captured, captured])
        self.prev_u = np.concatenate([self.prev_u, np.full(k, -1.0)])
        self.live = np.concatenate([self.live, np.ones(k, bool)])
        self.fixed = np.concatenate([self.fixed, np.full(k, any_fixed)])
        self.kind = np.concatenate([self.kind, np.array([r[5] for r in rows], np.int8)])
        self.gslot = np.concatenate([self.gslot, np.full(k, len(self.g_ids) - 1, np.intp)])
        return handle

    def _resolve(self, target: Any, plan: _Plan) -> tuple[Any, ...]:
        spec = plan.spec
        assert isinstance(spec, Tween)
        ctype = spec.component
        if isinstance(target, bool):
            raise ComponentTypeError(f"{spec.label}: target must be an entity id or a component")
        entity: int | None = None
        if isinstance(target, int):
            entity = target
            if not self.world.exists(entity):
                raise ValidationError(f"{spec.label}: entity {entity} does not exist")
            obj = self.world.try_get(entity, ctype)
            if obj is None:
                raise ValidationError(
                    f"{spec.label}: entity {entity} has no {ctype.__name__} component"
                )
        else:
            obj = target
            if not isinstance(obj, ctype):
                raise ComponentTypeError(
                    f"{spec.label}: target {obj!r} is not a {ctype.__name__} (pass an entity id "
                    "or the component itself)"
                )
        label = f"{where(entity, ctype.__name__, spec.field)}"
        if not _field_ok(ctype, spec.field):
            raise ValidationError(f"{label}: {ctype.__name__} has no field {spec.field!r}")
        now, ints = _as_vector(getattr(obj, spec.field), label, "current value")
        to, _ = _as_vector(spec.to, label, "target value")
        if len(to) != len(now):
            raise ValidationError(
                f"{label}: target value {spec.to!r} has {len(to)} numbers, the field holds "
                f"{len(now)}"
            )
        start = None
        if spec.start is not None:
            start, _ = _as_vector(spec.start, label, "start value")
            if len(start) != len(now):
                raise ValidationError(f"{label}: start value {spec.start!r} has the wrong size")
        if spec.relative and start is not None:
            to = [s + d for s, d in zip(start, to, strict=True)]
        vector = isinstance(getattr(obj, spec.field), (tuple, list))
        # a relative move without a start goes by ``to`` from where the field is
        end = to
        if spec.relative and start is None:
            end = [n + d for n, d in zip(now, to, strict=True)]
        _check_ends(obj, spec.field, entity, label, vector, ints, end, start)
        kind, axis = (1 if ints else 0), -1
        if vector:
            kind += 4
        rb = None
        if entity is not None and ctype is Transform and spec.field in _AXES:
            rb = self.world.try_get(entity, RigidBody)
        if rb is not None and rb.type != BodyType.STATIC:
            kind, axis = 2, _AXES[spec.field]
        elif kind == 0:
            check = getattr(ctype, "_checks", {}).get(spec.field)
            ends = [*now, *to, *(start or ())]
            if spec.relative:
                ends += [a + b for a, b in zip(now, to, strict=True)]
            # a coordinate between ends within a quarter of the world bound stays inside it
            # whatever the easing's overshoot (Penner's curves stay within -0.5..1.5)
            inside = check is coordinate and max(map(abs, ends)) <= MAX_COORDINATE / 4
            if isinstance(obj, Tracked) and (check is finite or inside):
                kind = 3  # plain finite float of a tracked component: the raw write
        return (obj, spec.field, len(now), start, to, kind, entity, axis)

    def _hook(self, ctype: type) -> None:
        if ctype not in self._hooked:
            self._hooked.add(ctype)
            self.world.on_remove(ctype, lambda e, c, t=ctype: self._target_gone(e, t))

    def _target_gone(self, entity: int, ctype: type) -> None:
        for i in self._by_target.pop((entity, ctype), ()):
            if self.live[i]:
                self.live[i] = False
                self._group_maybe_gone(int(self.group[i]))

    def _group_maybe_gone(self, gid: int) -> None:
        if not np.any(self.live & (self.group == gid)):
            h = self.handles.pop(gid, None)
            if h is not None:
                h.done = h.cancelled = True
            self.g_live[self.g_ids == gid] = False

    def cancel(self, handle: TweenHandle) -> None:
        self.live[self.group == handle.group] = False
        self.g_live[self.g_ids == handle.group] = False
        self.handles.pop(handle.group, None)
        self.calls.pop(handle.group, None)
        handle.done = handle.cancelled = True

    # -- pause and speed per tween -------------------------------------------------------
    def _slot(self, handle: TweenHandle) -> int | None:
        if handle.done:
            return None
        found = np.flatnonzero(self.g_ids == handle.group)
        return int(found[0]) if len(found) else None

    def group_value(self, handle: TweenHandle, name: str, default: Any) -> Any:
        slot = self._slot(handle)
        return default if slot is None else getattr(self, name)[slot].item()

    def set_paused(self, handle: TweenHandle, paused: bool) -> None:
        slot = self._slot(handle)
        if slot is not None:
            self.g_paused[slot] = bool(paused)

    def set_speed(self, handle: TweenHandle, value: float) -> None:
        speed = finite(value, f"tween {handle.name or handle.group}", "speed")
        if speed < 0:
            raise ValidationError(
                f"tween {handle.name or handle.group}: speed must be >= 0 (yoyo plays "
                f"backwards), got {value!r}"
            )
        slot = self._slot(handle)
        if slot is not None:
            self.g_speed[slot] = speed

    def cancel_all(self, entity: int) -> int:
        """Cancel every tween started on ``entity``; returns how many."""
        hs = [h for h in self.handles.values() if h.entity == entity]
        for h in hs:
            self.cancel(h)
        return len(hs)

    # -- advancing -----------------------------------------------------------------------
    def advance(self, dt: float, fixed: bool) -> list[TweenHandle]:
        """Advance the fixed (physics) or frame groups by ``dt``; returns finished handles.

        Written for thousands of rows: when every live row takes part (the usual
        frame pass) the arrays are used whole, without gathering.
        """
        if fixed:
            self._stop_bodies(dt)
        gsel = self.g_live & (self.g_fixed == fixed)
        if not gsel.any():
            self._maybe_compact()
            return []
        if self.g_paused.any() or (self.g_speed != 1.0).any():
            rate = np.where(self.g_paused, 0.0, self.g_speed)
            self.g_elapsed[gsel] += dt * rate[gsel]
        else:
            self.g_elapsed[gsel] += dt
        due_calls = self._due_calls(gsel) if self.calls else []
        sel = self.live & (self.fixed == fixed)
        finished: list[TweenHandle] = []
        if sel.any():
            rows = np.arange(len(sel)) if sel.all() else np.flatnonzero(sel)
            whole = len(rows) == len(sel)

            def take(arr: np.ndarray) -> np.ndarray:
                return arr if whole else arr[rows]

            slot = take(self.gslot)
            el = self.g_elapsed[slot]
            if np.isfinite(self.g_period).any():
                period = self.g_period[slot]
                looping = np.isfinite(period)
                el = np.where(looping, np.mod(el, np.where(looping, period, 1.0)), el)
            u = el - take(self.offset)
            dur = take(self.duration)
            cyc = take(self.cycles)
            prev = take(self.prev_u)
            with np.errstate(over="ignore"):  # 1e308 s x repeats: inf, "never ends"
                end = dur * cyc
            due = (u >= 0) & ((prev < end) | (u < prev))
            if whole:
                self.prev_u = u
            else:
                self.prev_u[rows] = u
            if due.all():
                self._write(rows, u, dur, cyc, dt)
            elif due.any():
                self._write(rows[due], u[due], dur[due], cyc[due], dt)
        done_groups = np.flatnonzero(gsel & (self.g_elapsed >= self.g_total))
        for gi in done_groups.tolist():
            gid = int(self.g_ids[gi])
            self.g_live[gi] = False
            self.live[self.group == gid] = False
            self.calls.pop(gid, None)
            h = self.handles.pop(gid, None)
            if h is not None:
                h.done = True
                finished.append(h)
        for call in due_calls:  # after the writes: a call sees the values of its moment
            call.fn(*call.args)
        self._maybe_compact()
        return finished

    def _due_calls(self, gsel: np.ndarray) -> list[Call]:
        """The Call steps whose time the selected groups reached in this advance."""
        out: list[Call] = []
        for gi in np.flatnonzero(gsel).tolist():
            pending = self.calls.get(int(self.g_ids[gi]))
            if not pending:
                continue
            now = float(self.g_elapsed[gi])
            for p in pending:
                while p.due <= now:
                    out.append(p.call)
                    p.due += p.period
        return out

    def _write(self, rows: np.ndarray, u: np.ndarray, dur: np.ndarray, cyc: np.ndarray,
               dt: float) -> None:
        """Write the rows already under way, then capture and write the ones starting now
        (so a tween following another in a sequence starts from where that one ended)."""
        fresh = ~self.captured[rows]
        if fresh.any():
            old = ~fresh
            self._apply(rows[old], u[old], dur[old], cyc[old], dt)
            for i in rows[fresh].tolist():
                obj, field, width, _, _, _ = self.targets[i]
                value = getattr(obj, field)
                vec = list(value) if isinstance(value, (tuple, list)) else [value]
                # a field holding more than MAX_VALUE now (it was written since the start)
                # starts from MAX_VALUE: the eased values must stay finite
                self.v_start[i, :width] = np.clip(vec, -MAX_VALUE, MAX_VALUE)
                self.captured[i] = True
                if self.relative[i]:  # a move by: the end is the offset from here
                    self.v_end[i, :width] += self.v_start[i, :width]
                    self.relative[i] = False
            self._apply(rows[fresh], u[fresh], dur[fresh], cyc[fresh], dt)
        else:
            self._apply(rows, u, dur, cyc, dt)

    def _progress(self, rows: np.ndarray, u: np.ndarray, dur: np.ndarray, cyc: np.ndarray
                  ) -> np.ndarray:
        """Eased progress of each row at local time ``u`` (repeats and yoyo folded in)."""
        with np.errstate(over="ignore", invalid="ignore"):  # durations of 1e-300 s
            return self._eased(rows, u, dur, cyc)

    def _eased(self, rows: np.ndarray, u: np.ndarray, dur: np.ndarray, cyc: np.ndarray
               ) -> np.ndarray:
        k = np.floor(u / dur)
        over = k > cyc - 1
        if over.any():
            k = np.where(over, cyc - 1, k)
        p = np.clip((u - k * dur) / dur, 0.0, 1.0)
        if over.any():
            p[over] = 1.0
        yoyo = self.yoyo[rows]
        if yoyo.any():
            back = yoyo & (np.mod(k, 2) == 1)
            p = np.where(back, 1.0 - p, p)
        return apply(self.ease[rows], p)

    def _apply(self, rows: np.ndarray, u: np.ndarray, dur: np.ndarray, cyc: np.ndarray,
               dt: float) -> None:
        if not len(rows):
            return
        eased = self._progress(rows, u, dur, cyc)
        raw = self.kind[rows] == 3
        if raw.any():  # the common case, kept tight: one raw write and one mark per tween
            if raw.all():
                sub, e = rows, eased
            else:
                sub, e = rows[raw], eased[raw]
            s0 = self.v_start[sub, 0]
            first = s0 + (self.v_end[sub, 0] - s0) * e
            idx = sub.tolist()
            pick = itemgetter(*idx)
            objs = pick(self.objs) if len(idx) > 1 else (self.objs[idx[0]],)
            fields = pick(self.fields) if len(idx) > 1 else (self.fields[idx[0]],)
            # C-level loops: the writes, then the bindings (tracked components' dirty marks)
            deque(map(raw_set, objs, fields, first.tolist()), maxlen=0)
            for b in filter(None, map(_binding, objs)):
                b.dirty.add(b.entity)
            if raw.all():
                return
            rows, eased = rows[~raw], eased[~raw]
        s = self.v_start[rows]
        values = s + (self.v_end[rows] - s) * eased[:, None]
        targets = self.targets
        world = self.world
        for i, row in zip(rows.tolist(), values.tolist(), strict=True):
            obj, field, width, kind, entity, axis = targets[i]
            if kind == 2:
                self._drive(world, entity, axis, row[0], dt)
            else:
                self._set(obj, field, width, kind, row, i)

    def _set(self, obj: Any, field: str, width: int, kind: int, row: list[float], i: int) -> None:
        ints = kind in (1, 5)
        vals = [round(v) for v in row[:width]] if ints else row[:width]
        value: Any = tuple(vals) if kind >= 4 else vals[0]
        try:
            setattr(obj, field, value)
        except ValidationError:
            # an overshooting easing (back, elastic) left the field's range: clamp to the ends
            lo = np.minimum(self.v_start[i, :width], self.v_end[i, :width])
            hi = np.maximum(self.v_start[i, :width], self.v_end[i, :width])
            clamped = np.clip(np.array(row[:width]), lo, hi).tolist()
            vals = [round(v) for v in clamped] if ints else clamped
            setattr(obj, field, tuple(vals) if kind >= 4 else vals[0])

    def _drive(self, world: Any, entity: int, axis: int, target: float, dt: float) -> None:
        """Set the body's velocity on ``axis`` so this step ends at ``target``."""
        t = world.try_get(entity, Transform)
        rb = world.try_get(entity, RigidBody)
        if t is None or rb is None or dt <= 0:
            return
        if axis == 2:
            rb.angular_velocity = (target - t.angle) / dt
        else:
            cur = t.x if axis == 0 else t.y
            v = list(rb.velocity)
            v[axis] = (target - cur) / dt
            rb.velocity = (v[0], v[1])
        self.stop_next.append((entity, axis))

    def _stop_bodies(self, dt: float) -> None:
        """Zero the velocities set in the last step unless a tween drives them again now."""
        pending, self.stop_next = self.stop_next, []
        world = self.world
        for entity, axis in pending:
            rb = world.try_get(entity, RigidBody)
            if rb is None:
                continue
            if axis == 2:
                rb.angular_velocity = 0.0
            else:
                v = list(rb.velocity)
                v[axis] = 0.0
                rb.velocity = (v[0], v[1])

    def _maybe_compact(self, slack: int = 32) -> None:
        """Drop finished rows once they outnumber the running ones (plus ``slack``; all
        of them once nothing runs), so the table tracks what is alive in a long game."""
        live = int(np.count_nonzero(self.live))
        dead = len(self.live) - live
        if dead == 0 or (live and dead <= max(live, slack)):
            return
        keep = np.flatnonzero(self.live)
        remap = {int(old): new for new, old in enumerate(keep.tolist())}
        for name in ("group", "offset", "duration", "cycles", "yoyo", "ease", "v_start", "v_end",
                     "captured", "prev_u", "live", "fixed", "kind", "gslot", "relative"):
            setattr(self, name, getattr(self, name)[keep])
        kept = keep.tolist()
        self.targets = [self.targets[i] for i in kept]
        self.objs = [self.objs[i] for i in kept]
        self.fields = [self.fields[i] for i in kept]
        self._by_target = {
            key: [remap[i] for i in idx if i in remap] for key, idx in self._by_target.items()
        }
        self._by_target = {k: v for k, v in self._by_target.items() if v}
        gkeep = np.flatnonzero(self.g_live)
        new_slot = np.full(len(self.g_live), -1, np.intp)
        new_slot[gkeep] = np.arange(len(gkeep))
        self.gslot = new_slot[self.gslot]  # live channels belong to live groups
        for name in ("g_ids", "g_elapsed", "g_period", "g_total", "g_fixed", "g_live",
                     "g_speed", "g_paused"):
            setattr(self, name, getattr(self, name)[gkeep])


@carry_running
class Tweens(TweenTable):
    """The world's tweens (a resource): ``start(target, spec)`` or the one-line :meth:`to`.

    >>> from kge.world import World
    >>> from kge.components.transform import Transform
    >>> w = World(); e = w.spawn(Transform())
    >>> tweens = Tweens(w)
    >>> h = tweens.to(e, Transform, "x", 2.0, 0.5, ease="quad_out")
    >>> _ = tweens.advance(0.25, fixed=False); round(w.get(e, Transform).x, 4)
    1.5
    >>> tweens.to(e, Transform, "z", 1.0, 0.5)
    Traceback (most recent call last):
    ...
    kge.errors.ValidationError: entity 1, Transform.z: Transform has no field 'z'
    """

    def to(
        self, target: Any, component: type, field: str, to: Any, duration: float, **options: Any
    ) -> TweenHandle:
        """Start ``Tween(component, field, to, duration, **options)`` on ``target``."""
        return self.start(target, Tween(component, field, to, duration, **options))

    def by(
        self, target: Any, component: type, field: str, by: Any, duration: float, **options: Any
    ) -> TweenHandle:
        """Move ``component.field`` *by* ``by`` from wherever it is when the tween starts."""
        return self.start(target, Tween(component, field, by, duration, relative=True, **options))

    def method(
        self, fn: Callable[[Any], Any], start: Any, end: Any, duration: float, **options: Any
    ) -> TweenHandle:
        """Call ``fn(value)`` every frame with a value eased from ``start`` to ``end``
        (a number, vector or colour): tween anything a function can set."""
        if not callable(fn):
            raise ValidationError(f"Tweens.method needs a function, got {fn!r}")
        target = MethodTarget(fn, start)
        return self.start(target, Tween(MethodTarget, "value", end, duration, start=start,
                                        **options))  # fmt: skip

    def _camera_target(self) -> Any:
        from kge.components.camera import Camera

        cams = self.world.query(Camera)
        if cams:
            return min(cams, key=lambda item: item[0])[0]
        cam = self.world.try_resource(Camera)
        if cam is None:
            cam = self.world.insert_resource(Camera())
        return cam

    def zoom_to(self, zoom: float, duration: float, ease: str = "sine_in_out") -> TweenHandle:
        """Smoothly zoom the active camera to ``zoom``."""
        from kge.components.camera import Camera

        return self.to(self._camera_target(), Camera, "zoom", zoom, duration, ease=ease)

    def move_to(
        self, center: tuple[float, float], duration: float, ease: str = "sine_in_out"
    ) -> TweenHandle:
        """Smoothly move the active camera's centre to ``center`` (metres)."""
        from kge.components.camera import Camera

        return self.to(self._camera_target(), Camera, "center", center, duration, ease=ease)
