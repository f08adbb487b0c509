"""``Drain``: joints that start their next step from zero impulse.

pymunk warm-starts every constraint with the impulse it accumulated in the
last step, applied along the Jacobian of this one. Sometimes that impulse is
wrong: a position pass has just moved the joint's bodies a long way (see
``JOLT`` in :mod:`kge.physics.joints.base`), or the game teleported them
(``Physics.reset_joints``: a ragdoll back at a checkpoint, a vehicle back
at its start). Two joints that disagree about a body's place (two hinges to
the ground at anchors that cannot both hold) fed each other that way: their equal
and opposite impulses grew about 3x per step, from 0.01 to 10^17 N·s in 30 steps,
until they no longer cancelled and threw the body 10^11 m. Box2D's position solver
moves the body just as far; a constraint that starts from zero stays bounded.
pymunk has no call that clears the impulse; this module clears it through the
clamp pymunk applies in every iteration.

>>> import pymunk
>>> space = pymunk.Space()
>>> a, b = pymunk.Body(1, 1), pymunk.Body(1, 1)
>>> pivot = pymunk.PivotJoint(a, b, (0, 0))
>>> space.add(a, b, pivot)
>>> drain = Drain()
>>> drain.add([pivot])
>>> saved = drain.start(space)  # before the first substep
>>> pivot.max_force
0.0
>>> Drain.end(saved)  # after it
>>> pivot.max_force, drain.waiting
(inf, {})
"""

from __future__ import annotations

from typing import Any

import pymunk

from kge.physics.cp import body_handle, constraint_handle, lib
from kge.physics.joint_api import in_space

_get_max_force = lib.cpConstraintGetMaxForce
_set_max_force = lib.cpConstraintSetMaxForce
_sleeping = lib.cpBodyIsSleeping


class Drain:
    """Start pymunk constraints again from zero impulse, at the next step.

    pymunk has no way to clear the accumulated impulse, but it clamps it to
    ``max_force·h`` in every iteration: with ``max_force`` 0 for the first substep
    of the next step the warm start is undone and the accumulator ends at zero;
    then ``max_force`` comes back and the constraint carries on from nothing.
    :meth:`start` and :meth:`end` bracket that substep (the simulation calls them);
    a constraint not in the space then waits for a step that has it. Doing it here
    rather than from the constraint's ``pre_solve`` keeps Python out of pymunk's
    step: an RL batch re-lays a scene (six constraints) at most steps.
    """

    __slots__ = ("waiting",)

    def __init__(self) -> None:
        #: the constraints to drain, in the order they were asked for (an ordered set)
        self.waiting: dict[pymunk.Constraint, None] = {}

    def add(self, constraints: list[pymunk.Constraint]) -> None:
        self.waiting.update(dict.fromkeys(constraints))

    def discard(self, constraints: list[pymunk.Constraint]) -> None:
        """Forget constraints that leave for good (their joint was destroyed)."""
        for c in constraints:
            self.waiting.pop(c, None)

    def start(self, space: pymunk.Space) -> list[tuple[Any, float]]:
        """``max_force`` 0 on the waiting constraints in ``space``; returns what :meth:`end`
        puts back."""
        if not self.waiting:
            return []
        saved = []
        # a sleeping joint is not stepped: it waits, as its bodies' warm start does
        for c in [c for c in self.waiting if in_space(space, c) and not _asleep(c)]:
            del self.waiting[c]
            cc = constraint_handle(c)
            saved.append((cc, _get_max_force(cc)))
            _set_max_force(cc, 0.0)
        return saved

    @staticmethod
    def end(saved: list[tuple[Any, float]]) -> None:
        """Put back the ``max_force`` values :meth:`start` took (after the first substep)."""
        for cc, force in saved:
            _set_max_force(cc, force)


def _asleep(c: pymunk.Constraint) -> bool:
    return bool(_sleeping(body_handle(c.a)) or _sleeping(body_handle(c.b)))
