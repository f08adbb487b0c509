"""Sub-emitters: the births, collisions and deaths of one emitter's particles become
bursts of other emitters, all in numpy.

The parent's pool records where its particles hit and die while ``watch`` is on
(:class:`~kge.particles.pool.ParticlePool`: (4, k) arrays of x, y, vx, vy per step);
its births are the newest rows of its pool (counted by ``EmitterState.born``). Each
event kind's rows (world metres, at most ``max_events`` a frame) become the origins
of a sub-emitter's ``count`` particles each: :meth:`EmitterState.spawn` samples the
sub-emitter's shape, cone, speeds, lifetimes and spins from its own seeded generator
for all of them at once, and ``inherit_velocity`` of each event particle's velocity
is added to its new particles. Nothing loops over particles in Python.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from kge.components.particle_subemitters import ParticleSubEmitters, SubEmitEvent
from kge.components.particles import ParticleEmitter
from kge.particles.emitter import EmitterState, Particles

KEY = "subemitters"


def _marks(st: EmitterState) -> dict[str, Any]:
    """The parent's sub-emitter bookkeeping: births already taken, events dropped."""
    mark = st.extras.get(KEY)
    if mark is None:
        mark = st.extras[KEY] = {"born": st.born - st.pool.count, "dropped": 0, "events": 0}
    return mark


def _to_world(rows: np.ndarray, st: EmitterState, em: ParticleEmitter) -> np.ndarray:
    """(4, k) x, y, vx, vy of a local-space emitter's particles, into world metres."""
    if em.space != "local" or rows.shape[1] == 0:
        return rows
    x, y, a = st.pose
    c, s = math.cos(a), math.sin(a)
    out = np.empty_like(rows)
    out[0] = x + c * rows[0] - s * rows[1]
    out[1] = y + s * rows[0] + c * rows[1]
    out[2] = c * rows[2] - s * rows[3]
    out[3] = s * rows[2] + c * rows[3]
    return out


def take_events(st: EmitterState, em: ParticleEmitter, subs: ParticleSubEmitters
                ) -> dict[SubEmitEvent, np.ndarray]:  # fmt: skip
    """This frame's events of the parent, by kind: (4, k) world rows, at most
    ``subs.max_events`` in all (the rest dropped and counted)."""
    pool = st.pool
    kinds = {s.on for s in subs.emitters}
    pool.watch = SubEmitEvent.DEATH in kinds or SubEmitEvent.COLLISION in kinds
    mark = _marks(st)
    new = min(st.born - mark["born"], pool.count)
    mark["born"] = st.born
    found: dict[SubEmitEvent, np.ndarray] = {}
    if SubEmitEvent.BIRTH in kinds and new > 0:
        found[SubEmitEvent.BIRTH] = pool.data[0:4, pool.count - new : pool.count].copy()
    for kind, kept in ((SubEmitEvent.COLLISION, pool.hits), (SubEmitEvent.DEATH, pool.deaths)):
        if kind in kinds and kept:
            found[kind] = np.concatenate(kept, axis=1)
    pool.hits, pool.deaths = [], []
    budget = subs.max_events
    out: dict[SubEmitEvent, np.ndarray] = {}
    for kind in SubEmitEvent:  # a fixed order: births, collisions, deaths
        rows = found.get(kind)
        if rows is None:
            continue
        k = rows.shape[1]
        mark["events"] += min(k, budget)
        if k > budget:
            mark["dropped"] += k - budget
            rows = rows[:, :budget]
        budget -= rows.shape[1]
        if rows.shape[1]:
            out[kind] = _to_world(rows, st, em)
    return out


def fire(particles: Particles, world: Any, sub_entity: int, count: int, inherit: float,
         rows: np.ndarray) -> int:  # fmt: skip
    """``count`` particles of the emitter ``sub_entity`` at each event row (x, y, vx, vy);
    returns how many were born (the sub-emitter's ``max_particles`` caps them)."""
    from kge.components.transform import Transform

    em = world.try_get(sub_entity, ParticleEmitter)
    k = rows.shape[1]
    if em is None or count == 0 or k == 0:
        return 0
    st = particles.state(sub_entity)
    st.refresh_style(em)
    t = world.try_get(sub_entity, Transform)
    pose = (0.0, 0.0, 0.0) if t is None else (t.x, t.y, t.angle)
    room = max(st.pool.max_particles - st.pool.count, 0)
    n = min(k * count, room)  # the first events' particles: full pools drop the rest
    st.pool.dropped += k * count - n
    if n == 0 or em.space == "local":  # sub-emitters are world-space (checked at the add)
        return 0
    events = -(-n // count)
    origins = np.repeat(rows[0:2, :events].T.astype(float), count, axis=0)[:n]
    before = st.pool.count
    spawn: Any = st.spawn  # ``position`` takes one origin per particle here
    spawn(em, n, pose, pose, (0.0, 0.0), None, 0.0, position=origins)
    born = st.pool.count - before
    if inherit and born:
        carried = np.repeat(rows[2:4, :events].T, count, axis=0)[:born] * np.float32(inherit)
        st.pool.data[2:4, before : st.pool.count] += carried.T
    return born
