"""Scenes: how a world is filled, and the scene stack.

A scene is either a function ``setup(world, **kwargs)`` or a :class:`Scene`
subclass implementing ``setup(self, world, **kwargs)``. Every scene gets a fresh
:class:`~kge.world.World`, so nothing leaks from one level (or one test) to the
next; when a scene leaves the stack its world is closed, which despawns every
entity (running ``on_destroy``, stopping coroutines and sounds).

>>> def level(world, difficulty=1):
...     world.resource(Time)  # resources are ready in setup
>>> isinstance(as_scene(level), Scene)
True
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

from kge.errors import ComponentTypeError
from kge.world import World


class Time:
    """Resource with the clock as systems see it (game time, scaled by time_scale)."""

    __slots__ = ("alpha", "dt", "elapsed", "fixed_dt", "fixed_elapsed", "frame", "step")

    def __init__(self, fixed_dt: float) -> None:
        self.dt = 0.0  #: game time of the current frame (update pass)
        self.fixed_dt = fixed_dt
        self.elapsed = 0.0  #: game time summed over frames
        self.fixed_elapsed = 0.0  #: fixed steps run x fixed_dt
        self.frame = 0
        self.step = 0
        self.alpha = 0.0


class Scene:
    """Base class for scenes. Override :meth:`setup`; the hooks are optional."""

    name: str = ""

    def setup(self, world: World, *args: Any, **kwargs: Any) -> None:  # pragma: no cover
        """Build the scene into ``world``; ``kwargs`` come from ``App(scene, **kwargs)``.

        Declared with ``*args, **kwargs`` so that an override naming its own
        parameters (``def setup(self, world, level: int = 1)``) type-checks.
        """
        raise NotImplementedError(f"{type(self).__name__}.setup(world) is not implemented")

    def on_pause(self, world: World) -> None:
        """Another scene was pushed on top of this one."""

    def on_resume(self, world: World) -> None:
        """The scene on top was popped; this one runs again."""

    def on_exit(self, world: World) -> None:
        """The scene leaves the stack (its world closes right after)."""

    def __repr__(self) -> str:
        return f"<Scene {self.name or type(self).__name__}>"


class FunctionScene(Scene):
    """A scene made from a plain ``setup(world, **kwargs)`` function."""

    def __init__(self, fn: Callable[..., Any]) -> None:
        self.fn = fn
        self.name = getattr(fn, "__name__", "scene")

    def setup(self, world: World, **kwargs: Any) -> None:
        self.fn(world, **kwargs)


SceneLike = Scene | type[Scene] | Callable[..., Any]


def as_scene(scene: SceneLike) -> Scene:
    """Normalise a Scene instance, Scene subclass or setup function to a Scene."""
    if isinstance(scene, Scene):
        return scene
    if isinstance(scene, type) and issubclass(scene, Scene):
        return scene()
    if callable(scene):
        return FunctionScene(scene)
    hint = ""
    if scene is None:
        hint = (
            " (pass the setup function itself, App(level), not what calling it returned, "
            "App(level(world)))"
        )
    raise ComponentTypeError(
        f"a scene must be a Scene, a Scene subclass or a setup(world) function, "
        f"got {scene!r}{hint}"
    )
