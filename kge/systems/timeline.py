"""The timeline system: every TimelinePlayer advanced at once, tracks written, cues fired.

``TimelineSystem`` runs in UPDATE / ANIMATION (after the clips and tweens, on game time:
it freezes with the pause, slows with ``time_scale``). Each frame it

1. syncs the players whose component was written (``play``, ``seek``, ``speed``...);
2. advances every playhead in one numpy pass (:mod:`kge.animation.timeline`);
3. samples each property track once for all the players of its timeline and writes
   the values that changed into the components (a write marks them, as any write);
4. fires the call and sound keys crossed, in entity then time order, and emits
   :class:`~kge.animation.events.TimelineFinished` (hook ``on_timeline_end``).

A track naming a component the entity lacks, or a method its Behaviour script lacks,
is refused at ``play`` (and at the first frame for a player spawned that way) with the
entity, timeline and track named.
"""

from __future__ import annotations

import functools
from collections import deque
from itertools import repeat
from operator import attrgetter
from typing import Any

import numpy as np

from kge.animation.events import TimelineFinished
from kge.animation.timeline import PropertyTrack, TimelineState
from kge.components.behaviour import Behaviour
from kge.components.timeline import Calls, Keys, Sounds, Timeline, TimelinePlayer
from kge.components.tracked import Tracked, bind, raw_set, unbind
from kge.errors import MissingComponentError, ValidationError, where
from kge.plugin import Plugin
from kge.schedule import Stage, System, SystemSet
from kge.systems.behaviour import BehaviourRunner
from kge.validate import MAX_COORDINATE, coordinate, finite
from kge.world import World

_binding = attrgetter("_binding")


def check_player(world: World, entity: int | None, player: TimelinePlayer) -> None:
    """Every track of the timeline that plays has its component (and method) on ``entity``
    (checked at ``play``; the other timelines when they are played)."""
    if entity is None or not world.exists(entity) or player.current is None:
        return  # inside spawn: the system checks at the first frame
    name = str(player.current)
    check_timeline(world, entity, name, player.timelines[name])


def check_timeline(world: World, entity: int, name: str, timeline: Timeline) -> None:
    for i, track in enumerate(timeline.tracks):
        label = f"{where(entity, 'TimelinePlayer')}: timeline {name!r} track {i}"
        if isinstance(track, Keys):
            if world.try_get(entity, track.component) is None:
                raise ValidationError(
                    f"{label} animates {track.component.__name__}.{track.field}, but the "
                    f"entity has no {track.component.__name__}"
                )
        elif isinstance(track, Calls):
            beh = world.try_get(entity, Behaviour)
            for key in track.keys:
                if beh is None or not callable(getattr(beh.script, key[1], None)):
                    raise ValidationError(
                        f"{label} calls {key[1]}() at {key[0]:g} s, but the entity's "
                        + ("Behaviour script has no such method" if beh is not None
                           else "has no Behaviour")
                    )


class Timelines:
    """Every TimelinePlayer of a world as numpy rows (a resource): what the system
    advances and what game code can ask (``time(entity)``, ``finished(entity)``)."""

    def __init__(self, world: World) -> None:
        self.world = world
        self.state = TimelineState()
        self.dirty: set[int] = set()
        self._serials: dict[int, int] = {}
        world.on_add(TimelinePlayer, self._added)
        world.on_remove(TimelinePlayer, self._removed)

    def _added(self, entity: int, player: TimelinePlayer) -> None:
        bind(player, entity, self.dirty, self.world.validate)
        self.dirty.add(entity)
        self.state.add(entity)
        self._serials.pop(entity, None)

    def _removed(self, entity: int, player: TimelinePlayer) -> None:
        unbind(player, self.dirty)
        self.dirty.discard(entity)
        self.state.remove(entity)
        self._serials.pop(entity, None)

    def time(self, entity: int) -> float:
        """Where ``entity``'s playhead is in its timeline, seconds."""
        self.sync()
        return float(self.state.time[self._row(entity)])

    def finished(self, entity: int) -> bool:
        """True once a timeline that does not loop has reached its end."""
        self.sync()
        return bool(self.state.finished[self._row(entity)])

    def _row(self, entity: int) -> int:
        row = self.state.rows.get(entity)
        if row is None:
            raise MissingComponentError(f"entity {entity} has no TimelinePlayer component")
        return row

    def sync(self) -> None:
        for entity in sorted(self.dirty):
            self._sync_one(entity)
        self.dirty.clear()

    def _sync_one(self, entity: int) -> None:
        player = self.world.try_get(entity, TimelinePlayer)
        row = self.state.rows.get(entity)
        if player is None or row is None:
            return
        state = self.state
        name = str(player.current)
        timeline = player.timelines[name]
        info = state.table.register(timeline)
        state.speed[row] = player.speed
        state.playing[row] = player.playing
        if self._serials.get(entity) != player.serial or state.slot[row] != info.slot:
            if entity not in self._serials:
                check_timeline(self.world, entity, name, timeline)
            state.start(row, info.slot, player.seek_to)
            self._serials[entity] = player.serial


def timelines_of(world: World) -> Timelines:
    """The world's :class:`Timelines`, created on first use."""
    found = world.try_resource(Timelines)
    if found is None:
        found = world.insert_resource(Timelines(world))
    return found


def _raw(prop: PropertyTrack) -> bool:
    """Can ``prop`` be written without re-validation? A plain float of a tracked
    component whose check only asks for a finite number (or a coordinate well inside
    the world bound: a cubic's overshoot stays inside it)."""
    ctype, field = prop.track.component, prop.track.field
    if prop.values is None or prop.ints or prop.vector or not issubclass(ctype, Tracked):
        return False
    check = getattr(ctype, "_checks", {}).get(field)
    if check is finite:
        return True
    return check is coordinate and float(np.abs(prop.values).max()) <= MAX_COORDINATE / 4


class _Objects:
    """entity -> component of one type, forgotten when it is added again or removed."""

    def __init__(self, world: World, ctype: type) -> None:
        self.world, self.ctype = world, ctype
        self.found: dict[int, Any] = {}
        world.on_add(ctype, self._forget)
        world.on_remove(ctype, self._forget)

    def _forget(self, entity: int, _component: Any) -> None:
        self.found.pop(entity, None)

    def get(self, entities: list[int]) -> list[Any]:
        found, out = self.found, []
        for e in entities:
            obj = found.get(e)
            if obj is None:
                obj = self.world.try_get(e, self.ctype)
                if obj is not None:
                    found[e] = obj
            out.append(obj)
        return out


def _write(prop: PropertyTrack, objs: list[Any], values: list[Any]) -> None:
    field = prop.track.field
    if prop.raw:  # the common case, kept tight: C-level loops of raw writes and marks
        live = [o for o in objs if o is not None]
        if len(live) != len(objs):
            values = [v for o, v in zip(objs, values, strict=True) if o is not None]
        deque(map(raw_set, live, repeat(field), values), maxlen=0)
        for b in filter(None, map(_binding, live)):
            b.dirty.add(b.entity)
        return
    for obj, value in zip(objs, values, strict=True):
        if obj is None or getattr(obj, field) == value:
            continue
        try:
            setattr(obj, field, value)
        except ValidationError:
            # a cubic curve overshot the field's range: hold the nearest key value inside
            if prop.values is None:
                raise
            lo, hi = prop.values.min(axis=0), prop.values.max(axis=0)
            row = np.clip(np.atleast_1d(np.asarray(value, float)), lo, hi)
            vals = [round(v) if prop.ints else float(v) for v in row.tolist()]
            setattr(obj, field, tuple(vals) if prop.vector else vals[0])


class TimelineSystem(System):
    """Advances every TimelinePlayer; see the module docstring."""

    stage = Stage.UPDATE
    in_set = SystemSet.ANIMATION

    def attach(self, world: World) -> None:
        super().attach(world)
        self.timelines = timelines_of(world)
        self._objects: dict[type, _Objects] = {}

    def _objs(self, ctype: type, entities: list[int]) -> list[Any]:
        found = self._objects.get(ctype)
        if found is None:
            found = self._objects[ctype] = _Objects(self.world, ctype)
        return found.get(entities)

    def process(self, dt: float) -> None:
        timelines = self.timelines
        timelines.sync()
        state = timelines.state
        if not len(state):
            return
        step = state.advance(dt)
        world = self.world
        if len(step.moved):
            slots = state.slot[step.moved]
            for s in np.unique(slots).tolist():
                rows = step.moved[slots == s]
                info = state.table.infos[s]
                times = state.time[rows]
                entities = [int(e) for e in state.entity[rows].tolist()]
                for prop in info.properties:
                    if prop.raw is None:
                        prop.raw = _raw(prop)
                    _write(prop, self._objs(prop.track.component, entities), prop.at(times))
        for row, info, ti, ki in step.cues:
            self._cue(int(state.entity[row]), info.timeline.tracks[ti], ki)
        runner = world.try_resource(BehaviourRunner)
        for row in sorted(step.finished.tolist(), key=lambda r: int(state.entity[r])):
            entity = int(state.entity[row])
            player = world.try_get(entity, TimelinePlayer)
            if player is None:
                continue
            ev = TimelineFinished(entity, str(player.current))
            world.emit(ev)
            if runner is not None:
                runner.call_one(entity, "on_timeline_end", ev)

    def _cue(self, entity: int, track: Any, k: int) -> None:
        world = self.world
        if not world.exists(entity):
            return  # despawned by an earlier call this frame
        key = track.keys[k]
        if isinstance(track, Calls):
            beh = world.try_get(entity, Behaviour)
            if beh is not None:
                getattr(beh.script, key[1])(*key[2:])
        elif isinstance(track, Sounds):
            from kge.audio.resource import Audio

            audio = world.try_resource(Audio)
            if audio is not None:
                audio.play(key[1], volume=track.volume, bus=track.bus)


def install(world: World, after: tuple[Any, ...] = ()) -> None:
    """Add the timeline system (ordered ``after`` those systems) and its checks."""
    timelines_of(world)
    world.add_system(TimelineSystem(), after=after)
    world.validator(TimelinePlayer, functools.partial(check_player, world))


class TimelinePlugin(Plugin):
    """Keyframe timelines (TimelinePlayer): property, call and sound tracks. The
    AnimationPlugin installs them too, after its tweens."""

    def build(self, world: World) -> None:
        install(world)


__all__ = ["TimelinePlugin", "TimelineSystem", "Timelines", "timelines_of"]
