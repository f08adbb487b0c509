"""What a scene registered in code survives ``App.restore``.

A snapshot holds data: entities, components and the physics settings. A scene
also registers behaviour in code when its ``setup`` runs: pre- and post-solve
hooks and a contact filter on :class:`~kge.physics.resource.Physics`, handlers
(``world.set_handler``), ``on_add`` / ``on_remove`` hooks and validators, its own
resources and systems. ``App.restore`` builds a fresh world for the restored
data and :func:`carry_over` moves all of that onto it:

* physics hooks and the contact filter, handlers, and world hooks and validators
  that the fresh world's own systems did not register again;
* resources the fresh world has no value of that type for (their current value:
  snapshots do not hold them);
* systems the fresh world lacks (detached from the old world, attached to the
  new one, so their own hooks are registered there).

A function that captured the old world in a closure (``def setup(world): ...
physics.on_pre_solve(lambda c: world.get(...))``) has that closure cell pointed
at the new world (and at its Physics), since the old one is closed. Whatever is
still tied to the old world after that (a bound method of an object whose
``world`` is the old one) is carried but reported with a :class:`RestoreWarning`
naming it: it would act on a closed world.
"""

from __future__ import annotations

import sys
import warnings
from collections.abc import Callable
from typing import Any

from kge.world import World


class RestoreWarning(UserWarning):
    """Something a scene registered in code could not be carried over cleanly."""


def _underlying(fn: Any) -> Any:
    return getattr(fn, "__func__", fn)


def _retarget(fn: Any, swaps: dict[int, Any]) -> None:
    """Point closure cells holding an old object (world, Physics) at its replacement."""
    func = _underlying(fn)
    for cell in getattr(func, "__closure__", None) or ():
        try:
            value = cell.cell_contents
        except ValueError:  # an empty cell
            continue
        if id(value) in swaps:
            cell.cell_contents = swaps[id(value)]


def _tied_to(fn: Any, old: World) -> bool:
    owner = getattr(fn, "__self__", None)
    return owner is old or getattr(owner, "world", None) is old or getattr(
        owner, "_world", None
    ) is old


def _carry_hooks(
    old: dict[type, list[Any]], new: dict[type, list[Any]], add: Callable[[type, Any], None],
    moved: set[int],
) -> list[Any]:
    carried = []
    for ctype, fns in old.items():
        have = {_underlying(f) for f in new.get(ctype, ())}
        for fn in fns:
            if id(getattr(fn, "__self__", None)) in moved or _underlying(fn) in have:
                continue  # a moved system registered it again / the new world's own
            add(ctype, fn)
            carried.append(fn)
    return carried


def carry_over(old: World, new: World) -> list[str]:
    """Move what ``old``'s scene registered in code onto ``new``; returns what was warned."""
    carried: list[Any] = []
    moved: set[int] = set()
    for system in old.schedule.systems():
        if new.get_system(type(system)) is None:
            old.schedule.remove(type(system))
            new.add_system(system)
            moved.add(id(system))
    for rtype, resource in list(old._resources.items()):
        if rtype not in new._resources:
            new.insert_resource(resource)
    swaps: dict[int, Any] = {id(old): new}
    # physics is a plugin: a world has a Physics only if kge.physics was imported
    physics_module = sys.modules.get("kge.physics.resource")
    physics = None if physics_module is None else physics_module.Physics
    old_physics = None if physics is None else old.try_resource(physics)
    new_physics = None if physics is None else new.try_resource(physics)
    if old_physics is not None and new_physics is not None:
        swaps[id(old_physics)] = new_physics
        rec = old_physics._sim.recorder
        for pre in rec.pre_solve:
            new_physics.on_pre_solve(pre)
        for post in rec.post_solve:
            new_physics.on_post_solve(post)
        carried += [*rec.pre_solve, *rec.post_solve]
        if rec.contact_filter is not None:
            new_physics.contact_filter = rec.contact_filter
            carried.append(rec.contact_filter)
    for name, fns in old._handlers.items():
        for fn in fns:
            if fn not in new._handlers.get(name, ()):
                new._handlers[name].append(fn)  # as set_handler, without its warnings
                carried.append(fn)
    carried += _carry_hooks(old._on_add, new._on_add, new.on_add, moved)
    carried += _carry_hooks(old._on_remove, new._on_remove, new.on_remove, moved)
    carried += _carry_hooks(old._validators, new._validators, new.validator, moved)
    problems = []
    for fn in carried:
        _retarget(fn, swaps)
        if _tied_to(fn, old):
            problems.append(getattr(fn, "__qualname__", repr(fn)))
    if problems:
        warnings.warn(
            RestoreWarning(
                "App.restore carried these callables, but they are bound to an object "
                f"of the old (closed) world: {', '.join(problems)}; register them from "
                "objects that read the world when called (app.world, script.world)"
            ),
            stacklevel=3,
        )
    return problems
