"""Running behaviour scripts: start, fixed update, update, late update, destroy.

:class:`BehaviourRunner` is a resource that tracks every :class:`Behaviour` of a
world (through the world's add/remove hooks), binds ``script.entity`` and
``script.world``, and keeps per-hook lists sorted by entity so that calling a
hook costs one loop over the scripts that define it. The three systems below
only decide *when* it runs.

Order inside a pass is ascending entity id, so a script always runs the same way.
``on_start`` runs for every new behaviour before its first fixed or frame update.
``on_destroy`` runs when the entity is despawned, the Behaviour is removed or the
scene closes; the entity's coroutines stop at the same moment.
"""

from __future__ import annotations

from typing import Any

from kge.components.behaviour import Behaviour
from kge.coroutines import Coroutine
from kge.input import AnyEvent, GamepadEvent, Input, KeyEvent, MouseEvent, TextEvent
from kge.plugin import Plugin
from kge.schedule import Stage, System, SystemSet
from kge.world import World


class BehaviourRunner:
    """Per-world registry of scripts and coroutines (inserted as a resource)."""

    def __init__(self, world: World) -> None:
        self.world = world
        self._scripts: dict[int, Any] = {}
        self._hooks: dict[int, tuple[str, ...]] = {}
        self._unstarted: set[int] = set()
        self._lists: dict[str, list[tuple[int, Any]]] | None = None
        self._coroutines: dict[int, list[Coroutine]] = {}
        world.on_add(Behaviour, self._added)
        world.on_remove(Behaviour, self._removed)

    # -- registry -------------------------------------------------------------------
    def _added(self, entity: int, behaviour: Behaviour) -> None:
        script = behaviour.script
        try:
            script.entity = entity
            script.world = self.world
            script.__dict__["_kge_runner"] = self
        except (AttributeError, TypeError):
            pass  # scripts with __slots__ simply do not get the back-references
        self._scripts[entity] = script
        self._hooks[entity] = behaviour.hooks
        if not behaviour.started:
            self._unstarted.add(entity)
        self._lists = None
        self.adopt(script)

    def _removed(self, entity: int, behaviour: Behaviour) -> None:
        self._scripts.pop(entity, None)
        self._hooks.pop(entity, None)
        self._unstarted.discard(entity)
        self._lists = None
        for co in self._coroutines.pop(entity, ()):
            co.stop()
        if "on_destroy" in behaviour.hooks:
            behaviour.script.on_destroy()

    def refresh(self, entity: int, behaviour: Behaviour) -> None:
        """The script's class changed (hot reload): call its new hooks from now on."""
        if entity in self._scripts:
            self._scripts[entity] = behaviour.script
            self._hooks[entity] = behaviour.hooks
            self._lists = None

    def adopt(self, script: Any) -> None:
        """Take over the coroutines a script started (before or after being attached)."""
        pending = getattr(script, "__dict__", {}).get("_kge_coroutines")
        entity = getattr(script, "entity", None)
        if not pending or entity not in self._scripts:
            return
        self._coroutines.setdefault(entity, []).extend(pending)
        pending.clear()

    def _hook_lists(self) -> dict[str, list[tuple[int, Any]]]:
        if self._lists is None:
            lists: dict[str, list[tuple[int, Any]]] = {}
            for entity in sorted(self._scripts):
                script = self._scripts[entity]
                for name in self._hooks[entity]:
                    lists.setdefault(name, []).append((entity, getattr(script, name)))
            self._lists = lists
        return self._lists

    # -- calling ---------------------------------------------------------------------
    def start_new(self) -> None:
        """Call ``on_start`` of behaviours that have not started yet (entity order)."""
        while self._unstarted:
            batch = sorted(self._unstarted)
            self._unstarted.clear()
            for entity in batch:
                script = self._scripts.get(entity)
                if script is None:
                    continue
                beh = self.world.try_get(entity, Behaviour)
                if beh is not None:
                    beh.started = True
                if "on_start" in self._hooks[entity]:
                    script.on_start()

    def call(self, hook: str, *args: Any) -> None:
        """Call ``hook(*args)`` on every live script that defines it."""
        world = self.world
        for entity, fn in self._hook_lists().get(hook, ()):
            if world.exists(entity):
                fn(*args)

    @property
    def scripted(self) -> bool:
        """Does any entity hold a script? (Else every :meth:`call_one` is a no-op.)"""
        return bool(self._hooks)

    def call_one(self, entity: int, hook: str, *args: Any) -> None:
        """Call ``hook`` on ``entity``'s script, if it has one and defines the hook."""
        hooks = self._hooks.get(entity)
        if hooks is not None and hook in hooks and self.world.exists(entity):
            getattr(self._scripts[entity], hook)(*args)

    def tick_coroutines(self, dt: float) -> None:
        for entity in sorted(self._coroutines):
            cos = self._coroutines.get(entity)
            if not cos:
                continue
            for co in list(cos):
                if self.world.exists(entity):
                    co.tick(dt)
            alive = [c for c in cos if not c.done]
            if alive:
                self._coroutines[entity] = alive
            else:
                self._coroutines.pop(entity, None)

    def coroutine_count(self, entity: int | None = None) -> int:
        if entity is not None:
            return sum(not c.done for c in self._coroutines.get(entity, ()))
        return sum(not c.done for cos in self._coroutines.values() for c in cos)

    def deliver_input(self, events: list[AnyEvent]) -> None:
        for ev in events:
            if isinstance(ev, KeyEvent):
                self.call("on_key_down" if ev.down else "on_key_up", ev.key)
            elif isinstance(ev, MouseEvent):
                self.call(f"on_mouse_{ev.kind}", ev)
            elif isinstance(ev, TextEvent):
                self.call("on_text", ev.text)
            elif isinstance(ev, GamepadEvent) and ev.kind in ("down", "up"):
                self.call(f"on_gamepad_{ev.kind}", ev)


def runner(world: World) -> BehaviourRunner:
    """The world's BehaviourRunner, created on first use."""
    r = world.try_resource(BehaviourRunner)
    if r is None:
        r = world.insert_resource(BehaviourRunner(world))
    return r


class _BehaviourStage(System):
    runner: BehaviourRunner

    def attach(self, world: World) -> None:
        super().attach(world)
        self.runner = runner(world)


class InputBehaviours(_BehaviourStage):
    """Deliver this frame's key and mouse events to ``on_key_*`` / ``on_mouse_*``."""

    stage = Stage.INPUT
    in_set = SystemSet.SCRIPTS

    def process(self, dt: float) -> None:
        inp = self.world.try_resource(Input)
        if inp is not None and inp.events:
            self.runner.start_new()
            self.runner.deliver_input(list(inp.events))


class FixedBehaviours(_BehaviourStage):
    """``on_start`` for new scripts, then ``on_fixed_update(dt)``."""

    stage = Stage.FIXED
    in_set = SystemSet.SCRIPTS

    def process(self, dt: float) -> None:
        self.runner.start_new()
        self.runner.call("on_fixed_update", dt)


class UpdateBehaviours(_BehaviourStage):
    """``on_update(dt)``, then coroutines."""

    stage = Stage.UPDATE
    in_set = SystemSet.SCRIPTS

    def process(self, dt: float) -> None:
        self.runner.start_new()
        self.runner.call("on_update", dt)
        self.runner.tick_coroutines(dt)


class LateBehaviours(_BehaviourStage):
    """``on_late_update(dt)`` after every other update."""

    stage = Stage.LATE
    in_set = SystemSet.SCRIPTS

    def process(self, dt: float) -> None:
        self.runner.call("on_late_update", dt)


class BehaviourPlugin(Plugin):
    """Runs :class:`~kge.components.behaviour.Behaviour` scripts: input hooks (INPUT),
    ``on_fixed_update`` (FIXED), ``on_update`` and coroutines (UPDATE), ``on_late_update``
    (LATE)."""

    def build(self, world: World) -> None:
        for stage in (InputBehaviours, FixedBehaviours, UpdateBehaviours, LateBehaviours):
            world.add_system(stage())
