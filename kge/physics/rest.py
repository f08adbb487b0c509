"""Box2D's sleep rule for bodies that joints keep touching.

Box2D puts an *island* (bodies connected by contacts and joints) to sleep when
every body in it has been slower than ``b2_linearSleepTolerance`` (0.01 m/s)
and ``b2_angularSleepTolerance`` (2 deg/s) for ``b2_timeToSleep`` (0.5 s): a
rule on velocities alone. Chipmunk's own sleeping (which kge uses) counts the
same idle time, but restarts it whenever a body is written to: every setter of a
body's velocity or pose, and of a constraint's anchors or spring, "activates"
the body and everything touching it. kge's joints are partly solved in Python
(velocity steps for pulleys, welds, ropes, motors and limits; position passes
for rods and sliders; sliders' and wheels' axis rows re-centred after each
step), so islands held by prismatic, distance, pulley, weld, wheel or rope
joints had their timers restarted every step and never slept.

:class:`RestClock` keeps Box2D's clock instead, for the bodies of those joints:
after each step, from the velocities sync-out has just read, each moving body's
time at rest grows by ``dt`` or goes back to zero. When a jointed body's time
reaches ``time_to_sleep``, its island is put to sleep
(:func:`~kge.physics.bodies.sleep_island`, between steps, with Chipmunk's own
mechanism) if every awake body in it has rested as long and may sleep. The check
runs once per body and rest period (when the time crosses the threshold), so a
settled island costs one search, and a body still waiting for a restless
neighbour costs nothing until that neighbour's own time crosses it.

Sleeping joints are then left alone by the joint bridge (Box2D does not solve a
sleeping island), and wake with their bodies: a contact from an awake body, a
write from user code, a joint changed.

Forces and impulses are the other writes: Box2D's ``ApplyForce``,
``ApplyLinearImpulse`` and the like wake a *sleeping* body (its time at rest
starts again from zero) and leave an awake body's clock to its velocity, so a
body pushed every step by a force that does not move it (a top-down car's tyre
friction, an idle thruster) still sleeps after 0.5 s, and a push with ``wake``
then wakes it for another 0.5 s. Chipmunk's force and velocity setters restart
its timer instead, so :meth:`RestClock.watch` hands such a body to this clock
until it sleeps. A body put to sleep starts from zero when it wakes
(``PoseTable.rest`` is zeroed when it is put to sleep), whether or not a step saw
it asleep.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Iterable

import numpy as np

from kge.physics.sync import PoseTable

#: Box2D's b2_angularSleepTolerance, rad/s
ANGULAR_TOLERANCE = math.radians(2.0)


class RestClock:
    """Each tracked body's time at rest, and the jointed bodies whose clock decides."""

    def __init__(self) -> None:
        self._key: tuple[int, int] | None = None
        self._watched = np.empty(0, dtype=bool)  # by slot: a body of a restless joint
        self._any = False  # some slot is watched
        self._counting = False  # the clocks ran at the last tick (else they read 0)
        #: entities pushed by forces or impulses since they last slept (watched too)
        self.pushed: set[int] = set()
        self._pushed_epoch = 0

    def watch(self, entity: int) -> None:
        """A force or an impulse reached the awake body of ``entity``: its clock decides
        when it sleeps (Chipmunk's setters restarted Chipmunk's own timer)."""
        if entity not in self.pushed:
            self.pushed.add(entity)
            self._pushed_epoch += 1

    def slept(self, entity: int) -> None:
        """The body of ``entity`` was put to sleep: a push must watch it again once it
        wakes (its time at rest, zeroed by the caller, starts again from zero then)."""
        self.pushed.discard(entity)

    def tick(
        self,
        poses: PoseTable,
        dt: float,
        speed: float,
        time_to_sleep: float,
        watched: Callable[[], Iterable[int]],
        watched_epoch: int,
    ) -> list[int]:
        """Advance every slot's clock by this step; return the watched slots whose
        time at rest reached ``time_to_sleep`` in it (in entity order).

        ``watched()`` gives the entities of bodies held by restless joints; it is
        called again only when ``watched_epoch`` or the table's slots changed (a
        body that kept an island awake is watched too: bump the epoch). The bodies
        :meth:`watch` was told of are watched as well.
        """
        state = poses.state
        key = (poses.epoch, watched_epoch + self._pushed_epoch)
        if key != self._key:
            mask = np.zeros(len(state), dtype=bool)
            slot = poses.slot
            for e in watched():
                i = slot.get(e)
                if i is not None:
                    mask[i] = True
            for e in [*self.pushed]:
                i = slot.get(e)
                if i is None:
                    self.pushed.discard(e)  # gone (or no longer moving)
                else:
                    mask[i] = True
            self._watched, self._key, self._any = mask, key, bool(mask.any())
        if not self._any:
            # nothing watched (no joint solved one by one: the revolute batch leaves
            # Chipmunk's timer alone): no clock to keep; they start again from zero
            if self._counting:
                poses.rest[:] = 0.0
                self._counting = False
            return []
        self._counting = True
        v = state[:, 3:6]
        slow = (v[:, 0] * v[:, 0] + v[:, 1] * v[:, 1] <= speed * speed) & (
            np.abs(v[:, 2]) <= ANGULAR_TOLERANCE
        )
        slow &= poses.dynamic & ~poses.asleep
        before = poses.rest
        after = np.where(slow, before + dt, 0.0)
        poses.rest = after
        due = time_to_sleep - 1e-9  # thirty 1/60 s steps are 0.5 s, not 0.49999...
        crossed = np.flatnonzero(self._watched & (after >= due) & (before < due))
        if not len(crossed):
            return []
        ents = poses.entities
        return sorted(crossed.tolist(), key=lambda i: int(ents[i]))
