"""Events: one model for every event of a world (physics, animation, UI, your own).

Anything is an event: ``world.emit(event)`` appends it to the list of its type,
and ``world.events(EventType)`` reads that list. Reading never consumes, so any
number of systems and scripts read the same events and none takes them from
another. How long an event stays readable follows one rule with two clocks:

* **per fixed step**: code running in the fixed step (FIXED-stage systems,
  ``on_fixed_update``, contact hooks) sees an event from the moment it is
  emitted until the same point of the next fixed step;
* **per frame**: code running once per frame (INPUT, UPDATE, LATE and RENDER
  systems, ``on_update``, ``on_late_update``, UI and animation hooks) sees it
  until the same point of the next frame. Code outside the frame (a test
  between ``app.step()`` calls, a scene's setup) sees the events of the last
  frame and those emitted since.

So a reader that runs once per step (or once per frame) sees each event exactly
once, whichever system emitted it, whether the frame ran no fixed step or five:

>>> from kge.world import World
>>> from dataclasses import dataclass
>>> @dataclass
... class Scored:
...     points: int
>>> world = World()
>>> world.emit(Scored(10)); world.emit(Scored(5))
>>> [e.points for e in world.events(Scored)], [e.points for e in world.events(Scored)]
([10, 5], [10, 5])

Inside an :class:`~kge.app.App` nothing else is needed. A bare World run by hand
(``world.schedule.run(Stage.FIXED, dt)`` in a test) keeps its events until
``world.clear_events()``.
"""

from __future__ import annotations

import heapq
from bisect import bisect_left
from collections.abc import Callable
from typing import Any, TypeVar

T = TypeVar("T")


class EventLog:
    """Every event of one world, by type (``world.eventlog``; see the module docstring).

    Each event gets a serial number. A reading position (a system) remembers the
    serial at which it last ran: when it runs again, it reads from there. The App
    marks frames and fixed steps (:meth:`begin_frame`, :meth:`begin_step`,
    :meth:`end_frame`), which decide what code outside systems reads and when old
    events are dropped.
    """

    __slots__ = (
        "_frame_start",
        "_marks",
        "_next",
        "_outside",
        "_prev_frame_start",
        "_prev_step_start",
        "_start",
        "_step_start",
        "_types",
    )

    def __init__(self) -> None:
        self._next = 0  #: the serial of the next event
        self._types: dict[type, tuple[list[int], list[Any]]] = {}
        self._marks: dict[int, int] = {}  #: id(system) -> serial when it last began
        self._start: int | None = None  #: the running reader's window (None: outside)
        self._outside = 0  #: window start of code outside systems
        self._frame_start = self._prev_frame_start = 0
        self._step_start = self._prev_step_start = 0

    # -- writing --------------------------------------------------------------------------
    def emit(self, event: Any) -> None:
        """Append ``event`` to the list of its type."""
        entry = self._types.get(type(event))
        if entry is None:
            entry = self._types[type(event)] = ([], [])
        entry[0].append(self._next)
        entry[1].append(event)
        self._next += 1

    def extend(self, event_type: type, events: list[Any]) -> None:
        """Append ``events`` (all of ``event_type``) at once (a physics step's contacts)."""
        n = len(events)
        if not n:
            return
        entry = self._types.get(event_type)
        if entry is None:
            entry = self._types[event_type] = ([], [])
        entry[0].extend(range(self._next, self._next + n))
        entry[1].extend(events)
        self._next += n

    # -- reading --------------------------------------------------------------------------
    def read(self, event_type: type[T]) -> list[T]:
        """The events of ``event_type`` the current reader may see (a new list)."""
        entry = self._types.get(event_type)
        if entry is None:
            return []
        serials, items = entry
        start = self._outside if self._start is None else self._start
        if not serials or serials[-1] < start:
            return []
        if serials[0] >= start:
            return list(items)
        return items[bisect_left(serials, start) :]

    def read_many(self, event_types: tuple[type, ...]) -> list[Any]:
        """The events of any of ``event_types`` the current reader may see, in the order
        they were emitted."""
        start = self._outside if self._start is None else self._start
        runs = []
        for kind in dict.fromkeys(event_types):  # each type once
            entry = self._types.get(kind)
            if entry is not None and entry[0] and entry[0][-1] >= start:
                i = bisect_left(entry[0], start)
                runs.append(zip(entry[0][i:], entry[1][i:], strict=True))
        return [event for _, event in heapq.merge(*runs, key=lambda pair: pair[0])]

    # -- reading positions (the schedule) ---------------------------------------------------
    def run(
        self,
        systems: list[Any],
        fixed: bool,
        call: Callable[[Callable[[float], None], float], None],
        dt: float,
    ) -> None:
        """``call(system.process, dt)`` for each system, in order. While a system runs,
        it reads the events emitted since it began last time (on its first run: since
        the previous step or frame began)."""
        marks = self._marks
        fallback = self._prev_step_start if fixed else self._prev_frame_start
        outer = self._start
        try:
            for system in systems:
                key = id(system)
                self._start = marks.get(key, fallback)
                marks[key] = self._next
                call(system.process, dt)
        finally:
            self._start = outer

    def forget(self, system: object) -> None:
        """``system`` left the schedule."""
        self._marks.pop(id(system), None)

    # -- clocks (the App) -----------------------------------------------------------------
    def begin_frame(self) -> None:
        self._prev_frame_start, self._frame_start = self._frame_start, self._next
        self._outside = self._next

    def begin_step(self) -> None:
        self._prev_step_start, self._step_start = self._step_start, self._next

    def end_frame(self) -> None:
        """Drop the events no reader can see any more."""
        self._trim(min(self._frame_start, self._step_start, self._outside))

    def clear(self) -> None:
        """Drop every event (a bare World's step boundary: ``world.clear_events()``)."""
        for serials, items in self._types.values():
            serials.clear()
            items.clear()
        self._outside = self._next

    def _trim(self, floor: int) -> None:
        for serials, items in self._types.values():
            if serials and serials[0] < floor:
                i = bisect_left(serials, floor)
                del serials[:i]
                del items[:i]

    def __len__(self) -> int:
        """How many events are kept."""
        return sum(len(items) for _, items in self._types.values())
