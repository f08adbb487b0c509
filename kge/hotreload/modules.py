"""Reloading a game's Python module while it runs: scripts keep their state.

The module's new source is compiled first (a syntax error changes nothing), then
re-executed with ``importlib.reload`` (an exception restores the old namespace).
Every live Behaviour script and system whose class came from the module then
switches to the new class of the same name: its ``__dict__`` (the entity's state)
stays, its hooks are the new ones. A new hook that raises while the game runs is
caught once, reported, and the script goes back to its previous class: the game
keeps running the old code until the file is fixed.
"""

from __future__ import annotations

import importlib
import os
import sys
import traceback
from collections.abc import Callable
from pathlib import Path
from types import ModuleType
from typing import Any

from kge.components.behaviour import Behaviour, script_hooks
from kge.systems.behaviour import BehaviourRunner
from kge.world import World

Report = Callable[[str], None]


def modules_at(path: Path) -> list[ModuleType]:
    """Imported modules whose source file is ``path``."""
    out = []
    for mod in list(sys.modules.values()):
        file = getattr(mod, "__file__", None)
        if file and os.path.realpath(file) == str(path):
            out.append(mod)
    return out


def game_module(mod: ModuleType | None) -> bool:
    """A module of the game (not kge, the standard library or an installed package)."""
    if mod is None or mod.__name__.startswith(("kge.", "_")) or mod.__name__ == "kge":
        return False
    file = getattr(mod, "__file__", None)
    if not file or not file.endswith(".py"):
        return False
    real = os.path.realpath(file)
    roots = {os.path.realpath(p) for p in (sys.prefix, sys.base_prefix, sys.exec_prefix)}
    return not any(real.startswith(r + os.sep) for r in roots)


def _lookup(mod: ModuleType, qualname: str) -> Any:
    obj: Any = mod
    for part in qualname.split("."):
        obj = getattr(obj, part, None)
        if obj is None:
            return None
    return obj


def _where(exc: BaseException, path: Path) -> str:
    if isinstance(exc, SyntaxError):
        return f"{exc.filename or path}:{exc.lineno}: SyntaxError: {exc.msg}"
    frames = traceback.extract_tb(exc.__traceback__)
    here = next((f for f in reversed(frames) if os.path.realpath(f.filename) == str(path)),
                frames[-1] if frames else None)
    place = f"{here.filename}:{here.lineno}: " if here is not None else f"{path}: "
    return f"{place}{type(exc).__name__}: {exc}"


class Guard:
    """Calls a reloaded hook; if it raises, puts the script back on its previous class."""

    def __init__(self, swap: ClassSwap, script: Any, name: str) -> None:
        self.swap = swap
        self.script = script
        self.name = name

    def __call__(self, *args: Any) -> Any:
        try:
            return getattr(type(self.script), self.name)(self.script, *args)
        except Exception as exc:
            self.swap.revert(self.script, exc, self.name)
            return None


class ClassSwap:
    """The scripts of one reload: which class each had before, to go back on an error."""

    def __init__(self, report: Report, path: Path) -> None:
        self.report = report
        self.path = path
        self.previous: dict[int, tuple[World, int, type]] = {}

    def switch(self, world: World, entity: int, beh: Behaviour, new: type) -> bool:
        script = beh.script
        old = type(script)
        _unguard(script)
        try:
            script.__class__ = new
            hooks = script_hooks(script)
        except Exception as exc:
            script.__class__ = old
            self.report(f"{self.path}: {new.__qualname__} cannot replace the running script: "
                        f"{exc}")
            return False
        for name in hooks:
            script.__dict__[name] = Guard(self, script, name)
        object.__setattr__(beh, "hooks", script_hooks(script))
        self.previous[id(script)] = (world, entity, old)
        runner = world.try_resource(BehaviourRunner)
        if runner is not None:
            runner.refresh(entity, beh)
        return True

    def revert(self, script: Any, exc: BaseException, hook: str) -> None:
        entry = self.previous.pop(id(script), None)
        if entry is None:
            return
        world, entity, old = entry
        _unguard(script)
        script.__class__ = old
        self.report(f"{_where(exc, self.path)} (in {old.__qualname__}.{hook} after the reload; "
                    "running the previous code until the file is fixed)")
        beh = world.try_get(entity, Behaviour)
        if beh is not None:
            object.__setattr__(beh, "hooks", script_hooks(script))
            runner = world.try_resource(BehaviourRunner)
            if runner is not None:
                runner.refresh(entity, beh)


def _unguard(script: Any) -> None:
    for key in [k for k, v in vars(script).items() if isinstance(v, Guard)]:
        del script.__dict__[key]


def reload_module(path: Path, worlds: list[World], report: Report) -> list[str]:
    """Reload the game modules defined in ``path`` and switch live objects to the new
    classes. Returns what was switched; errors go to ``report`` and change nothing."""
    done: list[str] = []
    for mod in modules_at(path):
        if mod.__name__ == "__main__":
            report(f"{path}: the main script cannot be reloaded while it runs (it would run "
                   "again); keep scripts and systems in modules it imports")
            continue
        try:
            source = path.read_text(encoding="utf-8")
            compile(source, str(path), "exec")
        except (OSError, SyntaxError, ValueError) as exc:
            report(_where(exc, path) if isinstance(exc, SyntaxError) else f"{path}: {exc}")
            continue
        saved = dict(vars(mod))
        cached = getattr(mod, "__cached__", None)
        if cached and os.path.exists(cached):  # a same-second edit must not load stale bytecode
            os.remove(cached)
        try:
            importlib.reload(mod)
        except Exception as exc:
            mod.__dict__.clear()
            mod.__dict__.update(saved)
            report(_where(exc, path))
            continue
        swap = ClassSwap(report, path)
        for world in worlds:
            for entity, (beh,) in world.query(Behaviour):
                cls = type(beh.script)
                if cls.__module__ != mod.__name__:
                    continue
                new = _lookup(mod, cls.__qualname__)
                if isinstance(new, type) and new is not cls and swap.switch(world, entity, beh,
                                                                           new):
                    done.append(f"entity {entity}: {cls.__qualname__}")
            for system in world.schedule.systems():
                cls = type(system)
                if cls.__module__ != mod.__name__:
                    continue
                new = _lookup(mod, cls.__qualname__)
                if isinstance(new, type) and new is not cls:
                    try:
                        system.__class__ = new
                    except TypeError as exc:
                        report(f"{path}: system {cls.__qualname__} cannot switch: {exc}")
                        continue
                    done.append(f"system {cls.__qualname__}")
    return done
