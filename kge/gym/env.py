"""``KgeEnv``: a kge scene as a ``gymnasium.Env``.

An environment is a scene plus four small functions, given either as arguments
or as methods of a subclass:

* ``build(world, rng)`` spawns the scene; ``rng`` is the env's ``np_random``, the
  only source of randomness, so ``reset(seed=s)`` replays the same episode bit for
  bit (kge itself is deterministic headless: same calls, same poses);
* ``act(world, action)`` turns an action into forces, impulses or motor settings;
* ``observe(world)`` returns the observation after the step;
* ``reward(world, obs, action)`` and ``terminated(world, obs)`` score it.

Each ``reset`` replaces the scene's world with a fresh one (the App, its systems
and any render window stay), so nothing of the previous episode leaks into the
next. ``step`` runs ``frame_skip`` fixed steps of the App, calling ``act`` before
each of them (a force acts for one fixed step, as in Box2D, so the action is held).

Gymnasium's rules are enforced with errors that name the env and the value
(:mod:`kge.gym.errors`): an action outside the action space, a seed that is not
a non-negative int, ``step`` before ``reset`` or after ``terminated``, and an
observation holding NaN or inf.

Rendering: ``render_mode="rgb_array"`` returns the frame drawn headless (EGL) as
an (h, w, 3) uint8 array, top row first as Gymnasium expects; ``"human"`` shows
it in a window at ``metadata["render_fps"]`` (with no display it draws
offscreen and says so once).
"""

from __future__ import annotations

import math
import sys
import time
from collections.abc import Callable
from typing import TYPE_CHECKING, Any

import gymnasium as gym
import numpy as np

from kge.app import App
from kge.gym.errors import InvalidActionError, InvalidSeedError, ObservationError, ResetNeededError
from kge.gym.holder import AppHolder
from kge.platform import has_display
from kge.plugin import PluginLike
from kge.world import World

if TYPE_CHECKING:
    from collections.abc import Sequence

BuildFn = Callable[[World, np.random.Generator], None]
ActFn = Callable[[World, Any], None]
ObserveFn = Callable[[World], Any]
RewardFn = Callable[[World, Any, Any], float]
TerminatedFn = Callable[[World, Any], bool]
InfoFn = Callable[[World], dict[str, Any]]

RENDER_MODES = ("rgb_array", "human")


def env_plugins(render: bool) -> list[PluginLike]:
    """Behaviours and physics (and drawing when the env renders): no audio, and no
    camera-follow or render systems stepping in an env that never draws a frame."""
    from kge.systems.behaviour import BehaviourPlugin
    from kge.systems.physics import PhysicsPlugin

    plugins: list[PluginLike] = [BehaviourPlugin(), PhysicsPlugin()]
    if render:
        from kge.systems.render import RenderPlugin

        plugins.append(RenderPlugin())
    return plugins


def check_seed(env_name: str, seed: Any) -> int | None:
    """``seed`` as an int (or None), or :class:`InvalidSeedError` naming the env and value."""
    if seed is None:
        return None
    if isinstance(seed, bool) or not isinstance(seed, (int, np.integer)):
        raise InvalidSeedError(
            f"{env_name}.reset(seed=...) needs an int >= 0 or None, got {seed!r} "
            f"({type(seed).__name__})"
        )
    if seed < 0:
        raise InvalidSeedError(f"{env_name}.reset(seed=...) needs an int >= 0, got {seed!r}")
    return int(seed)


class KgeEnv(AppHolder, gym.Env[Any, Any]):
    """A kge scene driven by Gymnasium's ``reset`` / ``step`` protocol.

    Pass ``build``, ``act``, ``observe``, ``reward`` and ``terminated`` as functions,
    or subclass and override the methods of the same names (the arguments win).
    """

    metadata: dict[str, Any] = {"render_modes": list(RENDER_MODES), "render_fps": 60}  # noqa: RUF012

    #: fixed step of the App (seconds); ``step`` advances ``frame_skip`` of them
    fixed_dt: float = 1.0 / 60.0
    frame_skip: int = 1
    #: window / frame size in pixels and clear colour
    size: tuple[int, int] = (600, 400)
    background: tuple[int, int, int] = (0, 0, 0)

    def __init__(
        self,
        build: BuildFn | None = None,
        *,
        action_space: gym.Space[Any] | None = None,
        observation_space: gym.Space[Any] | None = None,
        act: ActFn | None = None,
        observe: ObserveFn | None = None,
        reward: RewardFn | None = None,
        terminated: TerminatedFn | None = None,
        info: InfoFn | None = None,
        render_mode: str | None = None,
        fixed_dt: float | None = None,
        frame_skip: int | None = None,
        size: tuple[int, int] | None = None,
        plugins: Sequence[PluginLike] | None = None,
        render_fps: float | None = None,
    ) -> None:
        name = type(self).__name__
        if render_mode is not None and render_mode not in RENDER_MODES:
            raise ValueError(
                f"{name}: render_mode must be one of {RENDER_MODES} or None, got {render_mode!r}"
            )
        self.render_mode = render_mode
        if action_space is not None:
            self.action_space = action_space
        if observation_space is not None:
            self.observation_space = observation_space
        for attr in ("action_space", "observation_space"):
            if not isinstance(getattr(self, attr, None), gym.Space):
                raise TypeError(f"{name}: {attr} must be a gymnasium Space (argument or attribute)")
        fns = {"build": build, "act": act, "observe": observe, "reward": reward,
               "terminated": terminated, "info": info}
        for key, fn in fns.items():
            if fn is not None:
                if not callable(fn):
                    raise TypeError(f"{name}: {key} must be callable, got {fn!r}")
                setattr(self, key, fn)  # an instance attribute shadows the method
        if fixed_dt is not None:
            if not (isinstance(fixed_dt, (int, float)) and 0 < fixed_dt < math.inf):
                raise ValueError(f"{name}: fixed_dt must be a number > 0, got {fixed_dt!r}")
            self.fixed_dt = float(fixed_dt)
        if frame_skip is not None:
            if isinstance(frame_skip, bool) or not isinstance(frame_skip, int) or frame_skip < 1:
                raise ValueError(f"{name}: frame_skip must be an int >= 1, got {frame_skip!r}")
            self.frame_skip = frame_skip
        if size is not None:
            self.size = (int(size[0]), int(size[1]))
        self.metadata = dict(type(self).metadata)
        self.metadata["render_fps"] = (
            render_fps if render_fps is not None else round(1.0 / (self.fixed_dt * self.frame_skip))
        )
        self._plugins = list(plugins) if plugins is not None else None
        self._app: App | None = None
        self._needs_reset = True
        self._last_frame_time = 0.0
        self._warned_headless_human = False
        self.options: dict[str, Any] = {}

    # -- what a scene provides (override, or pass functions) ----------------------------------
    def build(self, world: World, rng: np.random.Generator) -> None:
        raise NotImplementedError(f"{self.env_name}: pass build= or override build(world, rng)")

    def act(self, world: World, action: Any) -> None:
        raise NotImplementedError(f"{self.env_name}: pass act= or override act(world, action)")

    def observe(self, world: World) -> Any:
        raise NotImplementedError(f"{self.env_name}: pass observe= or override observe(world)")

    def reward(self, world: World, obs: Any, action: Any) -> float:
        return 0.0

    def terminated(self, world: World, obs: Any) -> bool:
        return False

    def info(self, world: World) -> dict[str, Any]:
        return {}

    def on_reset(self, world: World) -> None:
        """Called after ``build``, before the first observation (reset episode state here)."""

    # -- the App ------------------------------------------------------------------------------
    @property
    def env_name(self) -> str:
        """The registered id (``kge/LunarLander-v0``) or the class name: used in every error."""
        spec = getattr(self, "spec", None)
        return spec.id if spec is not None else type(self).__name__


    def _setup(self, world: World) -> None:
        self.build(world, self.np_random)

    def _new_world(self) -> World:
        if self._app is None:
            headless = self.render_mode != "human" or not has_display()
            plugins = self._plugins
            if plugins is None:
                plugins = env_plugins(render=self.render_mode is not None)
            self._app = App(
                self._setup, headless=headless, size=self.size, fixed_dt=self.fixed_dt,
                background=self.background, plugins=plugins,
            )
        else:
            self._app.replace_scene(self._setup)
        return self._app.world

    # -- Gymnasium protocol ----------------------------------------------------------------------
    def reset(
        self, *, seed: int | None = None, options: dict[str, Any] | None = None
    ) -> tuple[Any, dict[str, Any]]:
        seed = check_seed(self.env_name, seed)
        if options is not None and not isinstance(options, dict):
            raise TypeError(f"{self.env_name}.reset(options=...) must be a dict or None, "
                            f"got {options!r}")
        super().reset(seed=seed)
        self.options = dict(options or {})  # build() may read the reset's options
        world = self._new_world()
        self.on_reset(world)
        obs = self._observe(world)
        self._needs_reset = False
        if self.render_mode == "human":
            self.render()
        return obs, self.info(world)

    def step(self, action: Any) -> tuple[Any, float, bool, bool, dict[str, Any]]:
        if self._needs_reset:
            why = "before reset()" if self._app is None else "after the episode terminated"
            raise ResetNeededError(f"{self.env_name}.step() called {why}: call reset() first")
        self.check_action(action)
        result = self.advance(action)
        if self.render_mode == "human":
            self.render()
        return result

    def advance(self, action: Any) -> tuple[Any, float, bool, bool, dict[str, Any]]:
        """One step with an action already checked (the vector env checks a whole batch)."""
        world = self.world
        app = self.app
        for _ in range(self.frame_skip):  # the action is held: forces last one fixed step
            self.act(world, action)
            app.step(1)
        obs = self._observe(world)
        reward = float(self.reward(world, obs, action))
        done = bool(self.terminated(world, obs))
        if done:
            self._needs_reset = True
        return obs, reward, done, False, self.info(world)

    def check_action(self, action: Any) -> None:
        """:class:`InvalidActionError` unless ``action`` is in the action space."""
        try:
            ok = self.action_space.contains(action)
        except (TypeError, ValueError):
            ok = False
        if not ok:
            raise InvalidActionError(
                f"{self.env_name}.step(): action {action!r} is not in the action space "
                f"{self.action_space}"
            )

    def _observe(self, world: World) -> Any:
        obs = self.observe(world)
        space = self.observation_space
        if isinstance(space, gym.spaces.Box):
            obs = np.asarray(obs, dtype=space.dtype)
            if obs.shape != space.shape:
                raise ObservationError(
                    f"{self.env_name}: observe() returned shape {obs.shape}, "
                    f"the observation space has {space.shape}"
                )
            if not np.isfinite(obs).all():
                bad = np.flatnonzero(~np.isfinite(obs)).tolist()
                raise ObservationError(
                    f"{self.env_name}: observe() returned a non-finite value at index "
                    f"{bad}: {obs!r}"
                )
        return obs

    # -- rendering -----------------------------------------------------------------------------
    def render(self) -> np.ndarray | None:  # type: ignore[override]
        if self.render_mode is None:
            gym.logger.warn(f"{self.env_name}.render() without a render_mode: nothing drawn")
            return None
        app = self.app
        app.render()
        if self.render_mode == "rgb_array":
            from kge.render.setup import frame_pixels

            pixels = frame_pixels(app)
            return np.ascontiguousarray(pixels[::-1, :, :3])
        self._show(app)
        return None

    def _show(self, app: App) -> None:
        from kge.render.setup import renderer_for

        renderer = renderer_for(app)
        if renderer is None:
            return
        if app.headless:
            if not self._warned_headless_human:
                gym.logger.warn(f"{self.env_name}: render_mode='human' with no display; "
                                "frames are drawn offscreen")
                self._warned_headless_human = True
            return
        window = renderer.window
        if not window.visible:
            window.set_caption(self.env_name)
            window.set_visible(True)
        window.dispatch_events()
        window.flip()
        wait = 1.0 / float(self.metadata["render_fps"]) - (time.perf_counter()
                                                          - self._last_frame_time)
        if wait > 0:
            time.sleep(wait)
        self._last_frame_time = time.perf_counter()

    def close(self) -> None:
        app, self._app = self._app, None
        self._needs_reset = True
        if app is None:
            return
        app.close()
        setup = sys.modules.get("kge.render.setup")  # loaded iff this process ever drew
        if setup is not None:
            setup.release(app)
