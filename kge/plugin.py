"""Plugins: how a subsystem joins an App or a World (the Bevy model).

A plugin is a small object that, when an App (or a bare World) takes it, inserts
its resources, systems, component hooks and validators. The App itself knows no
subsystem by name: physics, behaviours, audio, rendering and every game-layer
feature arrive as plugins, and ``App(scene, plugins=[...])`` chooses which::

    App(level)                                   # kge.default_plugins(): everything
    App(level, plugins=[PhysicsPlugin()])        # physics only, headless, nothing else imported

A plugin is one of:

* a :class:`Plugin` subclass (or an instance of one), overriding :meth:`Plugin.build`
  (run for every world: each scene's world, or a World that takes it directly),
  and optionally :meth:`Plugin.build_app` (once per App: app-wide services such as
  the window) and :meth:`Plugin.cleanup` (when the App closes);
* a plain function ``def my_plugin(world: World) -> None``, which is its ``build``.

``requires`` names the plugins a plugin needs; they are built first whatever the
order of the list. Adding a plugin twice, or one whose requirement is missing, is
a :class:`PluginError` naming both:

>>> from kge.world import World
>>> class Score:
...     points = 0
>>> def scoring(world: World) -> None:
...     world.insert_resource(Score())
>>> class Bonus(Plugin):
...     requires = (scoring,)
...     def build(self, world: World) -> None:
...         world.resource(Score).points = 100
>>> w = World()
>>> w.add_plugins(Bonus(), scoring)          # built in dependency order
>>> w.resource(Score).points
100
>>> w.add_plugins(scoring)
Traceback (most recent call last):
...
kge.plugin.PluginError: plugin scoring was added twice (world '...' already has scoring)
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Sequence
from typing import TYPE_CHECKING, Any, ClassVar

from kge.errors import KgeError

if TYPE_CHECKING:
    from kge.host import Host
    from kge.world import World

#: a plugin as users write it: an instance, a Plugin subclass, or a function of the world
PluginLike = Any


class PluginError(KgeError, ValueError):
    """A plugin was added twice, misses a requirement, or is not a plugin at all."""


class Plugin:
    """Base class of plugins. See the module docstring."""

    #: plugins (classes, or functions for function plugins) that must be built first
    requires: ClassVar[tuple[Any, ...]] = ()

    @property
    def name(self) -> str:
        return type(self).__name__

    @property
    def key(self) -> object:
        """What makes two plugins "the same": their class (or function)."""
        return type(self)

    def build(self, world: World) -> None:
        """Insert resources, systems, hooks and validators into ``world``."""

    def build_app(self, app: Host) -> None:
        """Once, when an App takes the plugin (app-wide services); the default does nothing."""

    def cleanup(self, app: Host) -> None:
        """When the App closes (stop app-wide services); the default does nothing."""

    def __repr__(self) -> str:
        return f"{self.name}()"


class FunctionPlugin(Plugin):
    """A plain function ``fn(world)`` used as a plugin's ``build``."""

    def __init__(self, fn: Callable[[World], None]) -> None:
        self.fn = fn

    @property
    def name(self) -> str:
        return getattr(self.fn, "__qualname__", repr(self.fn))

    @property
    def key(self) -> object:
        return self.fn

    def build(self, world: World) -> None:
        self.fn(world)

    def __repr__(self) -> str:
        return self.name


def as_plugin(obj: PluginLike) -> Plugin:
    """A :class:`Plugin` from what a user wrote (instance, Plugin class or function)."""
    if isinstance(obj, Plugin):
        return obj
    if isinstance(obj, type):
        if issubclass(obj, Plugin):
            return obj()
        raise PluginError(
            f"{obj.__name__} is not a plugin: subclass kge.Plugin and override build(world), "
            "or pass a function of the world"
        )
    if callable(obj):
        return FunctionPlugin(obj)
    raise PluginError(
        f"expected a plugin (a kge.Plugin, a Plugin subclass or a function of the world), "
        f"got {type(obj).__name__} {obj!r}"
    )


def _key_of(requirement: Any) -> object:
    """The key a ``requires`` entry stands for (a class, or a function plugin's function)."""
    return requirement


def _label(requirement: Any) -> str:
    return getattr(requirement, "__qualname__", None) or repr(requirement)


def resolve(installed: Sequence[Plugin], added: Iterable[PluginLike], owner: str) -> list[Plugin]:
    """The plugins of ``added`` in build order, checked against ``installed``.

    Raises :class:`PluginError` (nothing built) on a duplicate or a missing
    requirement. Requirements are built first; otherwise the given order stays.
    """
    new = [as_plugin(p) for p in added]
    seen: dict[object, Plugin] = {p.key: p for p in installed}
    for p in new:
        old = seen.get(p.key)
        if old is not None:
            where = f"{owner} already has {old.name}" if old in installed else "listed twice"
            raise PluginError(f"plugin {p.name} was added twice ({where})")
        seen[p.key] = p
    for p in new:
        for req in p.requires:
            if _key_of(req) not in seen:
                raise PluginError(
                    f"plugin {p.name} requires {_label(req)}, which {owner} does not have: "
                    f"add {_label(req)} to the plugins before {p.name}"
                )
    ordered: list[Plugin] = []
    done = {p.key for p in installed}
    pending = list(new)
    while pending:
        for p in pending:
            if all(_key_of(r) in done for r in p.requires):
                ordered.append(p)
                done.add(p.key)
                pending.remove(p)
                break
        else:
            names = ", ".join(p.name for p in pending)
            raise PluginError(f"plugins {names} require each other in a circle")
    return ordered
