"""``Physics.set_velocities``: Box2D's ``SetLinearVelocity`` for many bodies in one call.

Writing ``RigidBody.velocity`` is the way to move one body; sync-in then applies
the write with the caps and checks of a whole body update, a dozen microseconds of
Python per body. A controller that drives hundreds of kinematic bodies every step
(the character system moves each character's kinematic body this way) needs the
velocity part only: this checks every row first (nothing changes if one is bad),
caps each velocity at ``PhysicsSettings.max_translation`` per step as sync-in does,
writes Chipmunk's bodies through its setters mapped over them, and writes the same
numbers into the RigidBody components and the pose table, so reading them back
gives what the step will use. Like a velocity write, it wakes a sleeping dynamic
body; static bodies keep no velocity and are skipped.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

import numpy as np

from kge.components.rigidbody import RigidBody
from kge.errors import ValidationError
from kge.physics.cp import body_handle, lib
from kge.physics.tiny import TINY
from kge.physics.writeback import set_all, slot_setter

if TYPE_CHECKING:
    from kge.physics.resource import Physics

_set_velocity = lib.cpBodySetVelocity
_set_angular_velocity = lib.cpBodySetAngularVelocity
_get_type = lib.cpBodyGetType
_is_sleeping = lib.cpBodyIsSleeping
_STATIC = lib.CP_BODY_TYPE_STATIC
_DYNAMIC = lib.CP_BODY_TYPE_DYNAMIC
_SET_VELOCITY = slot_setter(RigidBody, "velocity")
_SET_ANGULAR_VELOCITY = slot_setter(RigidBody, "angular_velocity")


def rows(owner: str, entities: Any, velocities: Any, angular: Any) -> tuple[
    list[int], np.ndarray, np.ndarray | None
]:
    """The checked rows: entity ids, (n, 2) velocities and (n,) spins or None."""
    ents = np.asarray(entities)
    if ents.ndim != 1 or (len(ents) and ents.dtype.kind not in "iu"):
        raise ValidationError(
            f"{owner}: entities must be a 1-D sequence of int ids, got {entities!r}"
        )
    try:
        v = np.asarray(velocities, dtype=np.float64)
    except (TypeError, ValueError):
        raise ValidationError(
            f"{owner}: velocities must be (x, y) pairs, got {velocities!r}"
        ) from None
    if v.shape != (len(ents), 2):
        raise ValidationError(
            f"{owner}: velocities must be {len(ents)} (x, y) pairs (one per entity), got shape "
            f"{v.shape}"
        )
    bad = ~np.isfinite(v).all(axis=1)
    if bad.any():
        k = int(np.flatnonzero(bad)[0])
        raise ValidationError(
            f"{owner}: velocities[{k}] of entity {int(ents[k])} must be finite, got "
            f"{tuple(v[k].tolist())!r}"
        )
    w = None
    if angular is not None:
        w = np.asarray(angular, dtype=np.float64)
        if w.shape != (len(ents),) or not np.isfinite(w).all():
            raise ValidationError(
                f"{owner}: angular must be {len(ents)} finite spins (rad/s) or None, "
                f"got {angular!r}"
            )
    return [int(e) for e in ents.tolist()], v, w


def set_velocities(physics: Physics, entities: Any, velocities: Any, angular: Any = None) -> None:
    """See :meth:`kge.physics.resource.Physics.set_velocities`."""
    owner = "Physics.set_velocities"
    ents, v, w = rows(owner, entities, velocities, angular)
    if not ents:
        return
    recs = physics._records(ents, "set_velocities")
    sim = physics._sim
    settings = physics.settings
    # Box2D's per-step caps, as sync-in applies them to a RigidBody velocity write
    vmax = settings.max_translation / sim.dt
    speed = np.hypot(v[:, 0], v[:, 1])
    over = speed > vmax
    if over.any():
        v = v.copy()
        v[over] *= (vmax / speed[over])[:, None]
    if w is not None:
        wmax = settings.max_rotation / sim.dt
        w = np.clip(w, -wmax, wmax)
    v[np.abs(v) < TINY] = 0.0  # kge.physics.tiny.flush
    sim.touched = True
    sim.fresh_read = None
    table = sim.poses
    get = table.slot.get
    found = [get(e, -1) for e in ents]
    if sim.poses_stale or -1 in found or not all([r.in_space for r in recs]):
        _one_by_one(physics, ents, recs, v, w)
        return
    # every body moves and is in the space (the usual case): the pose table has its
    # RigidBody and whether it sleeps, so nothing is looked up body by body
    slots = np.array(found, dtype=np.intp)
    cbs = [body_handle(r.body) for r in recs]
    pairs = list(zip(v[:, 0].tolist(), v[:, 1].tolist(), strict=True))
    sleepers = np.flatnonzero(table.asleep[slots] & table.dynamic[slots]).tolist()
    set_all(_set_velocity, cbs, pairs)  # (Chipmunk's setter wakes a sleeping body)
    if w is not None:
        set_all(_set_angular_velocity, cbs, w.tolist())
    rbs = sim._targets.rigidbodies[0][slots].tolist()
    if any(rb is None for rb in rbs):
        _components(physics, ents, pairs, w)
    else:
        set_all(_SET_VELOCITY, rbs, pairs)
        if w is not None:
            set_all(_SET_ANGULAR_VELOCITY, rbs, w.tolist())
    for k in sleepers:
        physics._mark_awake(ents[k])
    # sync-out writes what changed since: the table holds what the components hold
    table.state[slots, 3:5] = v
    if w is not None:
        table.state[slots, 5] = w


def _components(physics: Physics, ents: list[int], pairs: list[tuple[float, float]],
                w: np.ndarray | None) -> None:
    for k, (e, pair) in enumerate(zip(ents, pairs, strict=True)):
        rb = physics._world.try_get(e, RigidBody)
        if rb is not None:
            _SET_VELOCITY(rb, pair)
            if w is not None:
                _SET_ANGULAR_VELOCITY(rb, float(w[k]))


def _one_by_one(physics: Physics, ents: list[int], recs: list[Any], v: np.ndarray,
                w: np.ndarray | None) -> None:
    """The general case: static bodies skipped, bodies out of the space (disabled) get
    the velocity in their component only, rows in a stale pose table left to sync-out."""
    sim = physics._sim
    table = sim.poses
    for k, (e, rec) in enumerate(zip(ents, recs, strict=True)):
        cb = body_handle(rec.body)
        if _get_type(cb) == _STATIC:
            continue
        pair = (float(v[k, 0]), float(v[k, 1]))
        spin = None if w is None else float(w[k])
        if rec.in_space:
            woke = _get_type(cb) == _DYNAMIC and _is_sleeping(cb)
            _set_velocity(cb, pair)
            if spin is not None:
                _set_angular_velocity(cb, spin)
            if woke:
                physics._mark_awake(e)
        _components(physics, [e], [pair], None if spin is None else np.array([spin]))
        i = table.slot.get(e)
        if i is not None and not sim.poses_stale:
            table.state[i, 3:5] = pair
            if spin is not None:
                table.state[i, 5] = spin
