"""The frame order: stages, named system sets, and where each system runs.

A frame runs five *stages* (:class:`Stage`); inside a stage, systems run in named
*sets* (:class:`SystemSet`, Bevy's system sets), in the order of :data:`FRAME`:

=========  ============================================================================
INPUT      once per frame, before the fixed steps:
           ``FIRST`` -> ``DEBUG`` (debug keys) -> ``UI`` (widgets take their input)
           -> ``SCRIPTS`` (``on_key_*``, ``on_mouse_*``) -> ``GAME`` -> ``LAST``
FIXED      zero or more times per frame, dt = fixed_dt:
           ``FIRST`` -> ``SCRIPTS`` (``on_fixed_update``) -> ``PRE_PHYSICS`` (kinematic
           tweens, controllers) -> ``PHYSICS`` (the step) -> ``PHYSICS_EVENTS`` (contact
           hooks) -> ``POST_PHYSICS`` (reactions: particle bursts) -> ``GAME`` -> ``LAST``
UPDATE     once per frame, dt = scaled frame time:
           ``FIRST`` -> ``SCRIPTS`` (``on_update``, coroutines) -> ``ANIMATION`` (clips,
           tile clips, tweens) -> ``EFFECTS`` (particles) -> ``GAME`` -> ``LAST``
LATE       ``FIRST`` -> ``SCRIPTS`` (``on_late_update``) -> ``CAMERA`` (follow) ->
           ``AUDIO`` (sounds, panning) -> ``CAMERA_EFFECTS`` (shake) -> ``GAME`` -> ``LAST``
RENDER     ``FIRST`` -> ``DRAW`` -> ``GAME`` -> ``LAST`` (when a frame is drawn)
=========  ============================================================================

A system names its stage and its set (``in_set``; ``SystemSet.GAME`` when left
out) and may order itself inside the set with ``before=`` / ``after=`` naming
other systems (their classes) or sets. Two systems of one set with no order
between them *tie*: they run in the order they were added, and
:meth:`Schedule.ties` (and ``kge schedule``) report the pair. The default plugins
have no tie. An order that contradicts itself (a cycle) is refused by the
``add_system`` that made it, with a :class:`~kge.errors.ScheduleError` naming the
systems and sets on the cycle, and the schedule is left unchanged.

>>> from kge.world import World
>>> log = []
>>> class Score(System):
...     stage = Stage.FIXED
...     def process(self, dt): log.append("score")
>>> class Bonus(System):
...     stage = Stage.FIXED
...     before = (Score,)
...     def process(self, dt): log.append("bonus")
>>> w = World()
>>> _ = w.add_system(Score()); _ = w.add_system(Bonus())
>>> w.schedule.run(Stage.FIXED, 1 / 60); log
['bonus', 'score']
>>> print(w.schedule.describe())  # doctest: +NORMALIZE_WHITESPACE
stage  #  system  set   order
FIXED  1  Bonus   GAME  before Score
FIXED  2  Score   GAME

The world is in deferred mode while a system runs and queued changes are flushed
after each system, so every system sees the changes of the ones before it.
"""

from __future__ import annotations

import heapq
import itertools
import time
from collections.abc import Callable, Iterable, Sequence
from dataclasses import dataclass
from enum import IntEnum, StrEnum
from typing import TYPE_CHECKING, Any, ClassVar, TypeVar

import esper

from kge import deprecation
from kge.errors import ScheduleError
from kge.timings import SystemTimings

if TYPE_CHECKING:
    from kge.world import World

#: a System subclass: ``add`` and ``get`` give back the type they were given
S = TypeVar("S", bound="System")


class Stage(IntEnum):
    """The parts of a frame, in the order they run (see the module docstring)."""

    INPUT = 0
    FIXED = 1
    UPDATE = 2
    LATE = 3
    RENDER = 4


class SystemSet(StrEnum):
    """The named anchors of the frame: each stage runs its sets in the order of :data:`FRAME`."""

    FIRST = "first"  #: every stage: clocks and per-frame resets
    DEBUG = "debug"  #: INPUT: debug keys read the raw input
    UI = "ui"  #: INPUT: the UI takes the input it uses
    SCRIPTS = "scripts"  #: INPUT, FIXED, UPDATE, LATE: the Behaviour hooks of the stage
    PRE_PHYSICS = "pre_physics"  #: FIXED: what moves bodies before the step
    PHYSICS = "physics"  #: FIXED: the physics step
    PHYSICS_EVENTS = "physics_events"  #: FIXED: contact hooks of the step
    POST_PHYSICS = "post_physics"  #: FIXED: reactions to the step's events
    ANIMATION = "animation"  #: UPDATE: sprite clips, tile clips, tweens
    EFFECTS = "effects"  #: UPDATE: particles
    CAMERA = "camera"  #: LATE: camera follow
    AUDIO = "audio"  #: LATE: sounds and panning (from the followed camera)
    CAMERA_EFFECTS = "camera_effects"  #: LATE: camera shake
    DRAW = "draw"  #: RENDER: the world's drawing
    GAME = "game"  #: every stage: game systems (the default set)
    LAST = "last"  #: every stage: what closes the stage (recording poses)


_ = SystemSet
#: the sets of each stage, in the order they run
FRAME: dict[Stage, tuple[SystemSet, ...]] = {
    Stage.INPUT: (_.FIRST, _.DEBUG, _.UI, _.SCRIPTS, _.GAME, _.LAST),
    Stage.FIXED: (
        _.FIRST,
        _.SCRIPTS,
        _.PRE_PHYSICS,
        _.PHYSICS,
        _.PHYSICS_EVENTS,
        _.POST_PHYSICS,
        _.GAME,
        _.LAST,
    ),
    Stage.UPDATE: (_.FIRST, _.SCRIPTS, _.ANIMATION, _.EFFECTS, _.GAME, _.LAST),
    Stage.LATE: (_.FIRST, _.SCRIPTS, _.CAMERA, _.AUDIO, _.CAMERA_EFFECTS, _.GAME, _.LAST),
    Stage.RENDER: (_.FIRST, _.DRAW, _.GAME, _.LAST),
}

#: the integers of the deprecated ``order``, by set: an ``order`` lands in the last
#: set of its stage whose number is <= it (what the built-in systems had before sets)
_LEGACY_ORDER: dict[Stage, tuple[tuple[int, SystemSet], ...]] = {
    Stage.INPUT: ((-1000, _.FIRST), (50, _.DEBUG), (50, _.UI), (100, _.SCRIPTS), (500, _.GAME)),
    Stage.FIXED: (
        (-1_000_000, _.FIRST),
        (100, _.SCRIPTS),
        (150, _.PRE_PHYSICS),
        (200, _.PHYSICS),
        (300, _.PHYSICS_EVENTS),
        (350, _.POST_PHYSICS),
        (500, _.GAME),
        (1_000_000, _.LAST),
    ),
    Stage.UPDATE: (
        (0, _.FIRST), (100, _.SCRIPTS), (200, _.ANIMATION), (300, _.EFFECTS), (500, _.GAME)
    ),
    Stage.LATE: (
        (0, _.FIRST),
        (100, _.SCRIPTS),
        (200, _.CAMERA),
        (300, _.AUDIO),
        (300, _.CAMERA_EFFECTS),
        (500, _.GAME),
    ),
    Stage.RENDER: ((-1_000_000, _.FIRST), (0, _.DRAW), (500, _.GAME), (1_000_000, _.LAST)),
}
del _
_BUILTIN_SETS = frozenset(str(s) for s in SystemSet)

#: what ``before=`` / ``after=`` may name: a set (its name), a System class or instance
Anchor = Any


class System(esper.Processor):
    """Base class for kge systems. Override :meth:`process` (and optionally the others).

    Class attributes place it in the frame: ``stage``, ``in_set`` (a
    :class:`SystemSet` or a set added with :meth:`Schedule.add_set`; default
    ``GAME``), and ``before`` / ``after`` (tuples of System classes or sets).
    """

    stage: ClassVar[Stage] = Stage.UPDATE
    in_set: SystemSet | str | None = None
    before: tuple[Anchor, ...] = ()
    after: tuple[Anchor, ...] = ()
    world: World

    def attach(self, world: World) -> None:
        """Called once when the system is added to ``world``."""
        self.world = world

    def process(self, dt: float) -> None:  # pragma: no cover - abstract
        raise NotImplementedError

    def detach(self) -> None:
        """Called when the world closes (free windows, players, spaces)."""


@dataclass(slots=True)
class _Entry:
    """One system of the schedule and where it was put."""

    system: System
    stage: Stage
    set: str
    after: tuple[Anchor, ...]
    before: tuple[Anchor, ...]
    seq: int
    plugin: str | None
    legacy: int | None  #: a deprecated integer ``order``


@dataclass(slots=True, frozen=True)
class Row:
    """One line of :meth:`Schedule.table`."""

    stage: Stage
    position: int  #: 1-based, inside the stage
    system: str
    set: str
    order: str  #: the system's own before/after constraints, as written
    plugin: str | None  #: the plugin whose build added it (None: added directly)
    tie: str | None  #: the system it ties with (runs just before it, unordered), if any


def _name(system: System) -> str:
    """How the schedule names a system (its class)."""
    return type(system).__name__


def _set_label(name: str) -> str:
    """A built-in set as code names it (``PHYSICS``); a custom set as it was named."""
    return SystemSet(name).name if name in _BUILTIN_SETS else name


def _anchor_name(anchor: Anchor) -> str:
    if isinstance(anchor, str):
        return _set_label(str(anchor))
    if isinstance(anchor, type):
        return anchor.__name__
    return type(anchor).__name__


class Schedule:
    """The systems of one world, by stage, in the order the sets and constraints give."""

    def __init__(self, world: World) -> None:
        self.world = world
        self._entries: list[_Entry] = []
        self._custom: dict[str, tuple[Stage, tuple[Anchor, ...], tuple[Anchor, ...]]] = {}
        self._order: dict[Stage, list[System]] = {s: [] for s in Stage}
        self._ties: dict[Stage, list[tuple[System, System]]] = {s: [] for s in Stage}
        self._seq = itertools.count()
        #: the plugin being built (World.add_plugins sets it): recorded with each system
        self.building: str | None = None
        #: per-system timings while enabled (:meth:`enable_timings`), else None: no cost
        self.timings: SystemTimings | None = None

    # -- sets ----------------------------------------------------------------------------
    def sets(self, stage: Stage) -> list[str]:
        """The sets of ``stage``: the :data:`FRAME` ones, then those added by :meth:`add_set`."""
        return [*FRAME[stage], *(n for n, (st, _, _) in self._custom.items() if st is stage)]

    def add_set(
        self,
        name: str,
        stage: Stage,
        *,
        after: Iterable[Anchor] = (),
        before: Iterable[Anchor] = (),
    ) -> str:
        """Add a named set to ``stage``, placed by ``after`` / ``before`` (other sets).

        >>> from kge.world import World
        >>> s = World().schedule
        >>> s.add_set("ai", Stage.FIXED, after=[SystemSet.SCRIPTS], before=[SystemSet.PHYSICS])
        'ai'
        """
        name = str(name)
        if name in SystemSet.__members__.values() or name in self._custom:
            raise ScheduleError(f"Schedule.add_set: a set named {name!r} already exists")
        if not isinstance(stage, Stage):
            raise ScheduleError(f"Schedule.add_set: stage must be a kge.Stage, got {stage!r}")
        placed = (stage, tuple(after), tuple(before))
        for anchor in (*placed[1], *placed[2]):
            if not isinstance(anchor, str) or str(anchor) not in self.sets(stage):
                raise ScheduleError(
                    f"Schedule.add_set({name!r}): {anchor!r} is not a set of {stage.name} "
                    f"(its sets: {', '.join(self.sets(stage))})"
                )
        self._custom[name] = placed
        try:
            self._sort(stage, self._entries)
        except ScheduleError:
            del self._custom[name]
            raise
        return name

    # -- systems ---------------------------------------------------------------------------
    def add(
        self,
        system: S,
        *,
        in_set: SystemSet | str | None = None,
        after: Iterable[Anchor] | None = None,
        before: Iterable[Anchor] | None = None,
    ) -> S:
        """Add ``system``; the keywords override its class's ``in_set`` / ``after`` / ``before``.

        Raises :class:`~kge.errors.ScheduleError` (nothing added) when a set is
        unknown, an anchor names a system of another stage, or the order has a cycle.
        """
        if not isinstance(system, System):
            raise TypeError(f"expected a kge.System instance, got {type(system).__name__}")
        if in_set is not None:
            system.in_set = in_set
        if after is not None:
            system.after = tuple(after)
        if before is not None:
            system.before = tuple(before)
        entry = self._entry(system)
        stage_entries = [*self._entries, entry]
        order, ties = self._sort(entry.stage, stage_entries)
        self._entries.append(entry)
        self._order[entry.stage], self._ties[entry.stage] = order, ties
        try:
            system.attach(self.world)
        except BaseException:
            self._drop(entry)
            raise
        return system

    def _entry(self, system: System) -> _Entry:
        stage = system.stage
        if not isinstance(stage, Stage):
            raise ScheduleError(f"{_name(system)}.stage must be a kge.Stage, got {stage!r}")
        legacy = getattr(system, "order", None)
        if isinstance(legacy, bool) or not isinstance(legacy, int):
            legacy = None
        set_name = system.in_set
        if legacy is not None:
            deprecation.warn(
                f"{_name(system)}.order = {legacy}: place the system with "
                "in_set = SystemSet.<NAME> and before= / after= (kge schedule prints the "
                "frame); the integer still places it"
            )
            if set_name is None:
                set_name = _legacy_set(stage, legacy)
        if set_name is None:
            set_name = SystemSet.GAME
        if str(set_name) not in self.sets(stage):
            raise ScheduleError(
                f"{_name(system)}.in_set: {str(set_name)!r} is not a set of {stage.name} "
                f"(its sets: {', '.join(self.sets(stage))})"
            )
        return _Entry(
            system, stage, str(set_name), tuple(system.after), tuple(system.before),
            next(self._seq), self.building, legacy,
        )  # fmt: skip

    def _drop(self, entry: _Entry) -> None:
        self._entries.remove(entry)
        self._order[entry.stage], self._ties[entry.stage] = self._sort(entry.stage, self._entries)
        self.world.eventlog.forget(entry.system)
        if self.timings is not None:
            self.timings.forget(entry.system)

    def get(self, system_type: type[S]) -> S | None:
        for e in self._entries:
            if isinstance(e.system, system_type):
                return e.system
        return None

    def remove(self, system_type: type[System]) -> None:
        """Remove (and detach) every system that is a ``system_type``."""
        for e in [e for e in self._entries if isinstance(e.system, system_type)]:
            self._drop(e)
            e.system.detach()

    def run(self, stage: Stage, dt: float) -> None:
        """Run every system of ``stage`` in order, flushing queued changes after each."""
        world = self.world
        timings = self.timings
        if timings is None:
            world.eventlog.run(self._order[stage], stage is Stage.FIXED, world.run_deferred, dt)
            return
        world.eventlog.run(
            self._order[stage], stage is Stage.FIXED, _timed(world.run_deferred, timings,
                                                             stage.name), dt
        )  # fmt: skip

    # -- timings ---------------------------------------------------------------------------
    def enable_timings(self, clock: Callable[[], float] | None = None) -> SystemTimings:
        """Time every system from now on (see :mod:`kge.timings`); returns the timings.

        ``clock`` (seconds) defaults to ``time.perf_counter`` (wall time);
        ``time.thread_time`` counts the game thread's CPU only (what the benchmarks use
        on a busy machine). Timings already enabled keep their clock.

        >>> from kge.world import World
        >>> w = World()
        >>> t = w.schedule.enable_timings()
        >>> w.schedule.timings is t, w.schedule.enable_timings() is t
        (True, True)
        """
        if self.timings is None:
            self.timings = SystemTimings(clock)
        return self.timings

    def disable_timings(self) -> None:
        """Stop timing (the numbers are dropped; the schedule runs at full speed)."""
        self.timings = None

    def end_frame(self) -> None:
        """The App closed a frame of this world: timings fold it into their averages."""
        if self.timings is not None:
            self.timings.end_frame()

    def systems(self, stage: Stage | None = None) -> list[System]:
        """The systems of ``stage`` in the order they run (all stages, in frame order)."""
        if stage is not None:
            return list(self._order[stage])
        return [s for st in Stage for s in self._order[st]]

    def ties(self, stage: Stage | None = None) -> list[tuple[Stage, System, System]]:
        """Pairs of systems that run one after the other with no order between them
        (same set, no before/after): they run in the order they were added."""
        stages = list(Stage) if stage is None else [stage]
        return [(st, a, b) for st in stages for a, b in self._ties[st]]

    def close(self) -> None:
        for e in reversed(self._entries):
            e.system.detach()
        self._entries.clear()
        for st in Stage:
            self._order[st] = []
            self._ties[st] = []

    # -- the table ------------------------------------------------------------------------
    def table(self) -> list[Row]:
        """Every system in the order it runs, with its set, constraints and plugin."""
        by_system = {id(e.system): e for e in self._entries}
        rows = []
        for st in Stage:
            tie_next = {id(a): b for a, b in self._ties[st]}
            for i, system in enumerate(self._order[st], 1):
                e = by_system[id(system)]
                order = [f"after {_anchor_name(a)}" for a in e.after]
                order += [f"before {_anchor_name(b)}" for b in e.before]
                if e.legacy is not None:
                    order.append(f"order={e.legacy} (deprecated)")
                nxt = tie_next.get(id(system))
                rows.append(Row(st, i, _name(system), e.set, ", ".join(order), e.plugin,
                                None if nxt is None else _name(nxt)))  # fmt: skip
        return rows

    def describe(self, plugins: bool = False) -> str:
        """The table as text (what ``kge schedule`` prints)."""
        head = ["stage", "#", "system", "set", "order"] + (["plugin"] if plugins else [])
        lines = [head]
        for r in self.table():
            order = r.order + (f"{'; ' if r.order else ''}TIE with {r.tie}" if r.tie else "")
            line = [r.stage.name, str(r.position), r.system, _set_label(r.set), order]
            lines.append(line + ([r.plugin or "-"] if plugins else []))
        widths = [max(len(line[i]) for line in lines) for i in range(len(head))]
        return "\n".join(
            "  ".join(c.ljust(w) for c, w in zip(line, widths, strict=True)).rstrip()
            for line in lines
        )

    # -- ordering -------------------------------------------------------------------------
    def _sort(
        self, stage: Stage, entries: list[_Entry]
    ) -> tuple[list[System], list[tuple[System, System]]]:
        """The run order of ``stage`` and its ties; ScheduleError on a cycle or a bad anchor."""
        graph = _Graph()
        sets = self.sets(stage)
        chain = list(FRAME[stage])
        rank: dict[str, float] = {s: float(i) for i, s in enumerate(chain)}
        for a, b in itertools.pairwise(chain):
            graph.edge(("end", a), ("start", b))
        for name, (_, after, before) in self._custom.items():
            if name not in sets:
                continue
            anchors = [rank[str(a)] for a in (*after, *before) if str(a) in rank]
            rank[name] = (min(anchors) if anchors else len(chain)) + 0.5
            for a in after:
                graph.edge(("end", str(a)), ("start", name))
            for b in before:
                graph.edge(("end", name), ("start", str(b)))
        for s in sets:
            graph.node(("start", s), (rank[s], 0, 0))
            graph.node(("end", s), (rank[s], 2, 0))
            graph.edge(("start", s), ("end", s))
        mine = [e for e in entries if e.stage is stage]
        for e in mine:
            node = ("system", id(e.system))
            graph.node(node, (rank[e.set], 1, e.seq))
            graph.edge(("start", e.set), node)
            graph.edge(node, ("end", e.set))
            for a in e.after:
                for src in self._resolve(e, a, "after", mine, sets):
                    graph.edge(src if src[0] == "system" else ("end", src[1]), node)
            for b in e.before:
                for dst in self._resolve(e, b, "before", mine, sets):
                    graph.edge(node, dst if dst[0] == "system" else ("start", dst[1]))
        legacy = sorted((e for e in mine if e.legacy is not None), key=lambda e: e.seq)
        for x, y in itertools.combinations(legacy, 2):
            if x.set == y.set and x.legacy != y.legacy:
                lo, hi = (x, y) if (x.legacy or 0) < (y.legacy or 0) else (y, x)
                graph.edge(("system", id(lo.system)), ("system", id(hi.system)))
        names = {("system", id(e.system)): _name(e.system) for e in mine}
        ordered = graph.sort(lambda n: names.get(n) or f"set {n[1]!r} ({n[0]})", stage.name)
        by_id = {id(e.system): e.system for e in mine}
        systems = [by_id[n[1]] for n in ordered if n[0] == "system"]
        ties = [
            (a, b)
            for a, b in itertools.pairwise(systems)
            if not graph.reaches(("system", id(a)), ("system", id(b)))
        ]
        return systems, ties

    def _resolve(
        self, entry: _Entry, anchor: Anchor, kind: str, mine: list[_Entry], sets: list[str]
    ) -> list[tuple[str, Any]]:
        """The graph nodes an anchor stands for (none: a system class not in the world)."""
        who = f"{_name(entry.system)}.{kind}"
        if isinstance(anchor, str):
            if str(anchor) not in sets:
                raise ScheduleError(
                    f"{who}: {str(anchor)!r} is not a set of {entry.stage.name} "
                    f"(its sets: {', '.join(sets)})"
                )
            return [("set", str(anchor))]
        if isinstance(anchor, System):
            cls: type = type(anchor)
            found = [e for e in mine if e.system is anchor]
        elif isinstance(anchor, type) and issubclass(anchor, System):
            cls = anchor
            found = [e for e in mine if isinstance(e.system, anchor)]
        else:
            raise ScheduleError(
                f"{who}: expected a System class or a set name, got {type(anchor).__name__} "
                f"{anchor!r}"
            )
        other = getattr(cls, "stage", None)
        if other is not entry.stage and not found:
            raise ScheduleError(
                f"{who}: {cls.__name__} runs in {getattr(other, 'name', other)}, "
                f"{_name(entry.system)} in {entry.stage.name}: order systems of one stage"
            )
        return [("system", id(e.system)) for e in found if e is not entry]


def _timed(
    run: Callable[[Callable[[float], None], float], None], timings: SystemTimings, stage: str
) -> Callable[[Callable[[float], None], float], None]:
    """``run`` with a pair of clock readings around each system (its flush included)."""
    clock = timings.clock or time.perf_counter
    add = timings.add

    def call(process: Callable[[float], None], dt: float) -> None:
        start = clock()
        try:
            run(process, dt)
        finally:
            add(getattr(process, "__self__", process), stage, clock() - start)

    return call


def order_items(
    labels: Sequence[str], edges: Iterable[tuple[int, int]], what: str
) -> tuple[list[int], list[tuple[int, int]]]:
    """Indices of ``labels`` in an order honouring ``edges`` (a, b: a runs first), ties
    broken by index, and the consecutive pairs nothing orders (the ties).

    The same rules as the schedule's, for other ordered lists (render passes). A cycle
    raises :class:`~kge.errors.ScheduleError` naming ``what`` and the labels on it.

    >>> order_items(["lights", "tiles", "particles"], [(1, 0)], "pass")
    ([1, 0, 2], [(0, 2)])
    """
    graph = _Graph()
    for i in range(len(labels)):
        graph.node(i, (0.0, 0, i))
    for a, b in edges:
        graph.edge(a, b)
    order = graph.sort(lambda n: labels[n], what)
    return order, [(a, b) for a, b in itertools.pairwise(order) if not graph.reaches(a, b)]


def _legacy_set(stage: Stage, order: int) -> SystemSet:
    """The set a deprecated integer ``order`` stands for (see ``_LEGACY_ORDER``)."""
    table = _LEGACY_ORDER[stage]
    chosen = table[0][1]
    for number, name in table:
        if number <= order:
            chosen = name
    return chosen


class _Graph:
    """A small DAG for one stage: nodes with tie-break priorities, Kahn's sort."""

    def __init__(self) -> None:
        self.succ: dict[Any, set[Any]] = {}
        self.prio: dict[Any, tuple[float, int, int]] = {}

    def node(self, n: Any, priority: tuple[float, int, int]) -> None:
        self.succ.setdefault(n, set())
        self.prio[n] = priority

    def edge(self, a: Any, b: Any) -> None:
        self.succ.setdefault(a, set()).add(b)
        self.succ.setdefault(b, set())

    def sort(self, label: Any, what: str) -> list[Any]:
        indegree = dict.fromkeys(self.succ, 0)
        for targets in self.succ.values():
            for t in targets:
                indegree[t] += 1
        ready = [(self.prio.get(n, (1e9, 0, 0)), i, n) for i, n in enumerate(self.succ)
                 if not indegree[n]]  # fmt: skip
        heapq.heapify(ready)
        index = {n: i for i, n in enumerate(self.succ)}
        out = []
        while ready:
            _, _, n = heapq.heappop(ready)
            out.append(n)
            for t in self.succ[n]:
                indegree[t] -= 1
                if not indegree[t]:
                    heapq.heappush(ready, (self.prio.get(t, (1e9, 0, 0)), index[t], t))
        if len(out) < len(self.succ):
            cycle = self._cycle({n for n, d in indegree.items() if d})
            raise ScheduleError(
                f"the {what} order has a cycle: "
                + " -> ".join(label(n) for n in cycle)
                + " (check in_set, before= and after=)"
            )
        return out

    def _cycle(self, stuck: set[Any]) -> list[Any]:
        """One cycle among the nodes Kahn's sort could not place (for the error).

        Every such node has a predecessor among them, so walking predecessors loops.
        """
        pred: dict[Any, list[Any]] = {n: [] for n in stuck}
        for a, targets in self.succ.items():
            for t in targets:
                if a in stuck and t in stuck:
                    pred[t].append(a)
        node = min(stuck, key=repr)
        path, seen = [node], {node: 0}
        while True:
            node = min(pred[node], key=repr)
            if node in seen:
                return [*path[seen[node] :], node][::-1]
            seen[node] = len(path)
            path.append(node)

    def reaches(self, a: Any, b: Any) -> bool:
        stack, seen = [a], {a}
        while stack:
            for t in self.succ[stack.pop()]:
                if t == b:
                    return True
                if t not in seen:
                    seen.add(t)
                    stack.append(t)
        return False
