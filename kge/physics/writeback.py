"""Sync-out's writes: moved bodies' poses and velocities back into their components.

After a step, sync-out (:mod:`kge.physics.sync`) knows which tracked bodies
moved and their new rows ``(x, y, angle, vx, vy, w)``. Writing those into the
Transform and RigidBody components is the part of a step that grows with the
number of moving bodies in Python, so it is done a column at a time: each
column goes through the component slot's own C setter mapped over the
objects (no Python frame per body, about 2x faster than a loop), bypassing
the change tracking that marks user writes (these are physics' own values).
Five slot stores per body are the floor of this design (0.19 us per body,
docs/benchmarks.md); when every tracked body moved (a falling crowd) the
columns go from one ``tolist`` straight to the setters, with no gather.
"""

from __future__ import annotations

import types
from collections import deque
from collections.abc import Callable
from typing import Any

import numpy as np

from kge.components.rigidbody import RigidBody
from kge.components.tracked import raw_set
from kge.components.transform import Transform

#: (components as an object array indexed by slot, mask of the slots that have one)
Components = tuple[np.ndarray, np.ndarray]


class Targets:
    """The Transform and RigidBody of every pose-table slot (re-slotted with the table)."""

    __slots__ = ("_columns", "rigidbodies", "transforms")

    def __init__(self, transforms: list[Any], rigidbodies: list[Any]) -> None:
        self._columns = (_Column(transforms), _Column(rigidbodies))
        self._views()

    def reslot(self, r: Any, transforms: list[Any], rigidbodies: list[Any]) -> None:
        """Follow :meth:`~kge.physics.sync.PoseTable.update`'s :class:`Reslot` ``r``:
        the entities re-slotted get ``transforms`` and ``rigidbodies`` (in the order
        of its items). The work is proportional to the change."""
        tf, rb = self._columns
        tf.reslot(r, transforms)
        rb.reslot(r, rigidbodies)
        self._views()

    def _views(self) -> None:
        tf, rb = self._columns
        self.transforms = tf.view()
        self.rigidbodies = rb.view()


class _Column:
    """One component per slot in a buffer with room to grow (views are handed out)."""

    __slots__ = ("has", "n", "objs")

    def __init__(self, items: list[Any]) -> None:
        self.objs, self.has = component_array(items)
        self.n = len(items)

    def view(self) -> Components:
        return self.objs[: self.n], self.has[: self.n]

    def reslot(self, r: Any, items: list[Any]) -> None:
        objs, has = self.objs, self.has
        if r.holes:
            objs[r.holes] = objs[r.movers]
            has[r.holes] = has[r.movers]
        objs[r.kept : self.n] = None  # let go of the removed ones
        has[r.kept : self.n] = False
        if r.size > len(objs):
            grown = max(r.size, 2 * len(objs))
            more = np.empty(grown, dtype=object)
            more[: r.kept] = objs[: r.kept]
            mask = np.zeros(grown, dtype=bool)
            mask[: r.kept] = has[: r.kept]
            self.objs, self.has = objs, has = more, mask
        self.n = r.size
        for i, item in zip(r.placed, items, strict=True):
            objs[i] = item
            has[i] = item is not None


def write_poses(targets: Targets, moved: np.ndarray | None, new: np.ndarray) -> None:
    """Write columns x, y, angle of rows ``new`` to the Transforms of the ``moved``
    slots (None: every slot, ``new`` in slot order)."""
    tfs, x, y, a = _columns(targets.transforms, 0, moved, new)
    set_all(_SET_X, tfs, x)
    set_all(_SET_Y, tfs, y)
    set_all(_SET_ANGLE, tfs, a)


def write_velocities(targets: Targets, moved: np.ndarray | None, new: np.ndarray) -> None:
    """Write columns vx, vy, w of rows ``new`` to the RigidBodies of the ``moved``
    slots (None: every slot, ``new`` in slot order)."""
    rbs, vx, vy, w = _columns(targets.rigidbodies, 3, moved, new)
    set_all(_SET_VELOCITY, rbs, zip(vx, vy, strict=True))
    set_all(_SET_ANGULAR_VELOCITY, rbs, w)


def _columns(
    components: Components, first: int, moved: np.ndarray | None, new: np.ndarray
) -> tuple[list[Any], list[float], list[float], list[float]]:
    """The components to write and their three columns from ``first`` on, as lists.

    No mask when every slot has a component (the usual case); the object gather is
    skipped when every slot is written.
    """
    objs, has = components
    if has.all():
        chosen = objs.tolist() if moved is None else objs[moved].tolist()
        c0, c1, c2 = new[:, first:first + 3].T.tolist()
        return chosen, c0, c1, c2
    if moved is None:
        moved = np.arange(len(new))
    sel = has[moved]
    c0, c1, c2 = new[sel, first:first + 3].T.tolist()
    return objs[moved[sel]].tolist(), c0, c1, c2


def component_array(items: list[Any]) -> Components:
    """``items`` as an object array (for fancy indexing) and the mask of the non-None ones.

    >>> objs, has = component_array([Transform(1.0, 2.0), None])
    >>> objs[0].y, has.tolist()
    (2.0, [True, False])
    """
    arr = np.empty(len(items), dtype=object)
    for i, item in enumerate(items):
        arr[i] = item
    return arr, np.fromiter((item is not None for item in items), dtype=bool, count=len(items))


def slot_setter(cls: type, name: str) -> Callable[[Any, Any], None]:
    """The slot's C setter: like ``raw_set`` (no validation, no dirty mark), without a lookup."""
    for klass in cls.__mro__:
        d = klass.__dict__.get(name)
        if isinstance(d, types.MemberDescriptorType):
            return d.__set__
    return lambda obj, value: raw_set(obj, name, value)


def set_all(setter: Callable[[Any, Any], None], objs: Any, values: Any) -> None:
    """``setter(obj, value)`` for each pair, in a C loop (no Python frame per item)."""
    deque(map(setter, objs, values), maxlen=0)


_SET_X = slot_setter(Transform, "x")
_SET_Y = slot_setter(Transform, "y")
_SET_ANGLE = slot_setter(Transform, "angle")
_SET_VELOCITY = slot_setter(RigidBody, "velocity")
_SET_ANGULAR_VELOCITY = slot_setter(RigidBody, "angular_velocity")
