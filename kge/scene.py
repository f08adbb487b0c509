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

import inspect
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
    if callable(scene) and not isinstance(scene, type):  # a class is no setup function
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


def check_setup_args(scene: Scene, kwargs: dict[str, Any]) -> None:
    """Refuse ``kwargs`` the scene's setup does not take, at the call that gave them.

    A scene change inside a frame is applied when the frame ends, so without this a
    misspelt keyword would surface as a ``TypeError`` from that later frame.

    >>> def level(world, number=1): ...
    >>> check_setup_args(FunctionScene(level), {"numbr": 2})
    Traceback (most recent call last):
    ...
    kge.errors.ComponentTypeError: scene level: setup(world, number=1) does not take numbr=2
    """
    fn: Callable[..., Any] = scene.fn if isinstance(scene, FunctionScene) else scene.setup
    try:
        sig = inspect.signature(fn)
    except (TypeError, ValueError):  # a builtin or C callable: nothing to check
        return
    params = list(sig.parameters.values())
    if not isinstance(scene, FunctionScene) and type(scene).setup is Scene.setup:
        return  # a scene that takes anything (the base signature)
    try:
        sig.bind(None, **kwargs)  # None stands for the world
    except TypeError:
        shown = ", ".join(str(p) for p in params)
        given = ", ".join(f"{k}={v!r}" for k, v in kwargs.items())
        raise ComponentTypeError(
            f"scene {scene.name or type(scene).__name__}: setup({shown}) does not take {given}"
        ) from None
