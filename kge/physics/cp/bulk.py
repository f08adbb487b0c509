"""``BodyReader``: one bulk read of every body of a space, with nothing set up per call.

``pymunk.batch.get_space_bodies`` copies chosen fields of every body into a
buffer in C, which is what makes sync-out, the speed caps and continuous
collision cheap for thousands of bodies. For a handful of bodies (a small
world, a unit test) its fixed cost is what remains: each call allocates the
``pmBatchedData`` struct, looks up the iterator's address, and the caller wraps
the result in two ``ffi.buffer`` and two ``np.frombuffer`` objects. A step reads
the space up to ``substeps + 2`` times, so that setup was a third of a small
world's physics overhead.

A reader keeps the struct, the iterator address and the buffers for its whole
life and hands out numpy views of the current contents. The views alias the
buffer: they are valid until the next :meth:`BodyReader.read` of the same reader.

>>> import pymunk, pymunk.batch as pb
>>> space = pymunk.Space()
>>> body = pymunk.Body(1.0, 1.0); body.velocity = (3.0, -4.0)
>>> space.add(body, pymunk.Circle(body, 0.5))
>>> reader = BodyReader(pb.BodyFields.BODY_ID | pb.BodyFields.VELOCITY)
>>> ids, rows = reader.read(space)
>>> ids.tolist() == [body.id], rows.tolist()
(True, [[3.0, -4.0]])
"""

from __future__ import annotations

from typing import Any

import numpy as np
import pymunk
import pymunk.batch as pb

from kge.physics.cp.capi import ffi as _ffi
from kge.physics.cp.capi import raw_lib as _lib

_ITERATOR = _ffi.addressof(_lib, "pmSpaceBodyGetIteratorFuncBatched")
_FLOAT = _ffi.sizeof("cpFloat")
_INT = _ffi.sizeof("uintptr_t")

#: floats per body that each field contributes, in pymunk's order
_WIDTH = {
    pb.BodyFields.POSITION: 2,
    pb.BodyFields.ANGLE: 1,
    pb.BodyFields.VELOCITY: 2,
    pb.BodyFields.ANGULAR_VELOCITY: 1,
    pb.BodyFields.FORCE: 2,
    pb.BodyFields.TORQUE: 1,
}


class BodyReader:
    """Reads ``fields`` of every body of a space into reused buffers."""

    __slots__ = ("_buffer", "_data", "_floats", "_ints", "_view", "_view_at", "width", "with_ids")

    def __init__(self, fields: pb.BodyFields) -> None:
        self._buffer = pb.Buffer()  # owns the two growable C arrays
        self._floats = self._buffer._float_arr
        self._ints = self._buffer._int_arr
        self._data = _ffi.new("pmBatchedData *")
        self._data.fields = fields.value
        self._data.floatArray = self._floats
        self._data.intArray = self._ints
        #: floats per body
        self.width = sum(w for f, w in _WIDTH.items() if f in fields)
        self.with_ids = pb.BodyFields.BODY_ID in fields
        #: :meth:`flat`'s view and the C array it views (reused while neither changes)
        self._view = _NO_FLOATS
        self._view_at: Any = None

    def read(self, space: pymunk.Space) -> tuple[np.ndarray, np.ndarray]:
        """(ids, rows): body ids (empty unless asked for) and an (n, width) float view."""
        self._fill(space)
        rows = np.frombuffer(self._float_bytes(), dtype=np.float64)
        if self.with_ids:
            ints = self._ints
            ids = np.frombuffer(_ffi.buffer(ints.arr, _INT * ints.num), dtype=np.int64)
        else:
            ids = _NO_IDS
        return ids, rows.reshape(len(ids) if self.width == 0 else -1, self.width)

    def floats(self, space: pymunk.Space) -> memoryview[float]:
        """The float fields of every body as a flat memoryview (no numpy object at all).

        For a few bodies, Python's ``max``/``min`` over this beat numpy's reductions,
        whose fixed cost is a microsecond each.
        """
        self._fill(space)
        return memoryview(self._float_bytes()).cast("d")

    def fill(self, space: pymunk.Space) -> int:
        """Read every body of ``space`` into the buffers; returns how many floats came.

        Then :meth:`flat` (a numpy view) or :meth:`memory` (a memoryview) hands them out.
        """
        floats = self._floats
        floats.num = 0
        self._ints.num = 0
        _lib.cpSpaceEachBody(space._space, _ITERATOR, self._data)
        return floats.num

    def flat(self) -> np.ndarray:
        """The floats of the last :meth:`fill` as one flat float64 view of the buffer.

        The view is kept for the next reads while the C array neither moves nor
        changes length (a steady space), so a read creates no numpy object at all;
        like every view here it is valid until the next read.
        """
        floats = self._floats
        at, num = floats.arr, floats.num
        view = self._view
        if num != len(view) or at != self._view_at:
            view = np.frombuffer(self._float_bytes(), dtype=np.float64) if num else _NO_FLOATS
            self._view, self._view_at = view, at
        return view

    def memory(self) -> memoryview[float]:
        """The floats of the last :meth:`fill` as a flat memoryview (see :meth:`floats`)."""
        return memoryview(self._float_bytes()).cast("d")

    def _fill(self, space: pymunk.Space) -> None:
        self._floats.num = 0
        self._ints.num = 0
        _lib.cpSpaceEachBody(space._space, _ITERATOR, self._data)

    def _float_bytes(self) -> Any:
        return _ffi.buffer(self._floats.arr, _FLOAT * self._floats.num)


_NO_IDS = np.empty(0, dtype=np.int64)
_NO_IDS.flags.writeable = False
_NO_FLOATS = np.empty(0, dtype=np.float64)
_NO_FLOATS.flags.writeable = False


_ARBITER_ITERATOR = _ffi.addressof(_lib, "pmSpaceArbiterIteratorFuncBatched")


class ArbiterBodies:
    """The body ids of every cached contact of a space, in one C pass.

    A superset of the bodies touching something: Chipmunk keeps a contact for a
    few steps after its shapes part, and rejected pairs (sensors, filters) too.
    For a question about many bodies at once ("which of these touch anything?")
    it replaces one Python callback per body with one call.
    """

    __slots__ = ("_buffer", "_data", "_ints")

    def __init__(self) -> None:
        self._buffer = pb.Buffer()
        self._ints = self._buffer._int_arr
        self._data = _ffi.new("pmBatchedData *")
        self._data.fields = (pb.ArbiterFields.BODY_A_ID | pb.ArbiterFields.BODY_B_ID).value
        self._data.floatArray = self._buffer._float_arr
        self._data.intArray = self._ints

    def read(self, space: pymunk.Space) -> np.ndarray:
        """Body ids, two per cached contact (a view valid until the next read)."""
        self._ints.num = 0
        self._buffer._float_arr.num = 0
        _lib.cpSpaceEachCachedArbiter(space._space, _ARBITER_ITERATOR, self._data)
        ints = self._ints
        if not ints.num:
            return _NO_IDS
        return np.frombuffer(_ffi.buffer(ints.arr, _INT * ints.num), dtype=np.int64)

