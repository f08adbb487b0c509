"""``LunarLanderVector``: N LunarLanders in ONE kge world, stepped as one batch.

:class:`~kge.gym.vector.KgeVectorEnv` steps N complete envs, each its own App,
World and pymunk space, so every env step pays kge's per-world Python (systems,
sync, speed caps, continuous collision) N times. Here the N scenes share one
world: each lies at its own origin along x, :data:`SPACING` metres apart, and the
landers collide with the ground only (their filters), so scenes never touch. One
``app.step`` runs one pymunk step for all of them; the engines' impulses, the
observations, rewards and terminations are numpy over the whole batch
(:func:`~kge.gym.lunar_lander.fire`, :func:`~kge.gym.lunar_lander.observations`,
:func:`~kge.gym.lunar_lander.rewards`: the same functions the single env calls).

Why scenes cannot meet: an episode ends on the step its lander leaves its screen
sideways (``|obs[0]| >= 1``), and a step moves a body at most
``PhysicsSettings.max_translation`` (2 m); the next step re-lays that scene.
So a lander never gets nearer than ``SPACING - W - 2`` m to another scene's ground.

Resets re-lay one scene: next-step autoreset gives env i's moon a new outline and
puts its lander and legs back at the top, at rest, their joints starting cold
(:func:`~kge.gym.lunar_lander.replace_scene`), and the batch step that follows is
that env's reset step (a no-op, as a single env's ``reset`` ends with one). Nothing
is despawned or spawned, so the physics rebuilds no bodies, joints or joint batch:
a despawn and spawn of the scene cost about 2 ms in a world of 64 scenes.

What holds, and what does not (tested in ``tests/gym/test_lander_vector.py``):

* the whole vector run is deterministic: the same seeds and actions give the same
  observations, rewards and flags bit for bit;
* env i is seeded like a single env reset with ``s + i`` and starts from the same
  terrain and push; its first observation equals the single env's to float32
  rounding. Its trajectory is the single env's physics, but not bit for bit: the
  scene sits 32 i metres along x (so positions round differently) and shares the
  solver with the other scenes (pymunk orders contacts by its spatial index), and
  the differences grow over an episode as they do between any two Box2D builds.
  Episode statistics (scores and outcomes of the heuristic pilot) agree with the
  single env's within the band the test states.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

import numpy as np
from gymnasium.utils import seeding

from kge.app import App
from kge.components.camera import Camera
from kge.gym.draws import PairDraws
from kge.gym.env import env_plugins
from kge.gym.errors import ObservationError
from kge.gym.holder import AppHolder
from kge.gym.lunar_lander import (
    FPS,
    SCALE,
    VIEWPORT_H,
    VIEWPORT_W,
    H,
    LanderScene,
    LunarLander,
    W,
    fire,
    give_push,
    observations,
    replace_scene,
    rewards,
    solver_settings,
    spawn_scene,
    throttles,
)
from kge.gym.vector import BatchVectorEnv
from kge.physics.events import ContactBegin, ContactEnd
from kge.physics.resource import Physics
from kge.world import World

#: metres between two scenes' origins along x (a screen is W = 20 m wide); a power of
#: two, so every origin is exact
SPACING = 32.0

#: what a collider is in its scene: the hull, or leg 0 / leg 1
HULL = -1

#: the pose table's columns (x, y, angle, vx, vy, w) in the observations' order
_OBS_COLUMNS = [0, 1, 3, 4, 2, 5]


class LunarLanderVector(AppHolder, BatchVectorEnv):
    """``num_envs`` LunarLanders sharing one kge world (``make_vec``'s default)."""

    def __init__(
        self,
        num_envs: int = 1,
        *,
        max_episode_steps: int | None = None,
        render_mode: str | None = None,
        gravity: float = -10.0,
        continuous: bool = False,
        name: str | None = None,
    ) -> None:
        label = name or type(self).__name__
        if render_mode not in (None, "rgb_array"):
            raise ValueError(f"{label}: render_mode must be 'rgb_array' or None, got "
                             f"{render_mode!r} (a window per env: use vectorization_mode="
                             "'sync')")
        self._setup_batch(label, num_envs, max_episode_steps, render_mode)
        self._template = LunarLander(gravity=gravity, continuous=continuous)  # checks both
        self.gravity, self.continuous = float(gravity), continuous
        self.env_name = f"{name or 'LunarLander'} (vector of {num_envs})"
        self._setup_spaces(self._template)
        self.metadata["render_modes"] = ["rgb_array"]
        self.metadata["render_fps"] = FPS
        n = num_envs
        self.origins = np.arange(n, dtype=np.float64) * SPACING
        self._app: App | None = None
        self._rngs: list[np.random.Generator | None] = [None] * n
        #: the engines' dispersion, drawn from ``_rngs`` a block of steps at a time
        self._draws = PairDraws(n)
        #: the landers' states after the last step (``Physics.states`` rows)
        self._stepped: np.ndarray | None = None
        self._scenes: list[LanderScene | None] = [None] * n
        self._landers: list[int] = [0] * n
        #: collider entity -> (env, HULL or leg index)
        self._parts: dict[int, tuple[int, int]] = {}
        self.game_over = np.zeros(n, np.bool_)
        self.leg_contact = np.zeros((n, 2), np.float64)
        self.prev_shaping = np.full(n, np.nan)
        self.m_power = np.zeros(n)
        self.s_power = np.zeros(n)
        self.awake = np.ones(n, np.bool_)

    # -- the shared world ------------------------------------------------------------------

    def _setup(self, world: World) -> None:
        world.insert_resource(solver_settings(self.gravity))
        world.insert_resource(Camera(center=(W / 2, H / 2), pixels_per_meter=SCALE))

    def _new_world(self) -> World:
        """A fresh world for a full reset: the run replays exactly from it."""
        if self._app is None:
            self._app = App(self._setup, headless=True, size=(VIEWPORT_W, VIEWPORT_H),
                            fixed_dt=1.0 / FPS, background=(0, 0, 0),
                            plugins=env_plugins(render=self.render_mode is not None))
        else:
            self._app.replace_scene(self._setup)
        self._scenes = [None] * self.num_envs
        self._parts.clear()
        return self._app.world

    def _respawn(self, world: World, envs: list[int]) -> None:
        """New episodes for these envs (drawn from their rngs): a fresh world's scenes
        are spawned; a finished episode's are re-laid (:func:`replace_scene`)."""
        give_push(world, [self._respawn_one(world, i) for i in envs])

    def _respawn_one(self, world: World, i: int) -> LanderScene:
        rng = self._rngs[i]
        if rng is None:
            rng = self._rngs[i] = seeding.np_random(None)[0]
        origin, drawn = (float(self.origins[i]), 0.0), self.render_mode is not None
        old = self._scenes[i]
        if old is None:
            scene = spawn_scene(world, rng, origin, drawn)
        else:
            scene = replace_scene(world, old, rng, origin, drawn)
        self._scenes[i] = scene
        self._landers[i] = scene.lander
        self._parts[scene.lander] = (i, HULL)
        self._parts[scene.legs[0]] = (i, 0)
        self._parts[scene.legs[1]] = (i, 1)
        self.game_over[i] = False
        self.leg_contact[i] = 0.0
        self.prev_shaping[i] = np.nan
        return scene

    # -- Gymnasium protocol -----------------------------------------------------------------
    def reset(
        self,
        *,
        seed: int | Sequence[int | None] | None = None,
        options: dict[str, Any] | None = None,
    ) -> tuple[np.ndarray, dict[str, Any]]:
        seeds = self._seeds(seed)
        if options is not None and not isinstance(options, dict):
            raise TypeError(f"{self.env_name}.reset(options=...) must be a dict or None, "
                            f"got {options!r}")
        self._draws.give_back(range(self.num_envs))  # the scenes draw from the same streams
        self._stepped = None
        for i, s in enumerate(seeds):
            if s is not None:
                self._rngs[i] = seeding.np_random(s)[0]
        world = self._new_world()
        self._respawn(world, list(range(self.num_envs)))
        every = np.ones(self.num_envs, np.bool_)
        self._advance(world, np.zeros((self.num_envs, 0)), every)
        self._autoreset[:] = False
        self._steps[:] = 0
        self._started = True
        return self._obs.copy(), self._infos()

    def step(
        self, actions: Any
    ) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, dict[str, Any]]:
        batch = self._check_actions(actions)
        world = self.world
        resetting = self._autoreset.copy()
        if resetting.any():
            envs = np.flatnonzero(resetting).tolist()
            self._draws.give_back(envs)  # their new scenes draw from the same streams
            self._respawn(world, envs)
        self._advance(world, batch.reshape(self.num_envs, -1), resetting)
        self._truncations[:] = False
        self._time_limit(~resetting)
        return self._results(self._infos())

    def _advance(self, world: World, actions: np.ndarray, resetting: np.ndarray) -> None:
        """One fixed step of the whole batch; ``resetting`` envs take their reset step (a
        no-op, scored 0, never terminal) with the others' actions."""
        n = self.num_envs
        if actions.shape[1]:
            m_power, s_power, direction = throttles(actions.astype(np.float64), self.continuous)
            m_power[resetting] = s_power[resetting] = 0.0
        else:
            m_power, s_power, direction = np.zeros(n), np.zeros(n), np.zeros(n)
        self.m_power, self.s_power = m_power, s_power
        # each env's own stream, in the single env's order (one pair of draws per step)
        dispersion = self._draws.take(self._rngs)  # type: ignore[arg-type]
        physics = world.resource(Physics)
        landers = np.array(self._landers, dtype=np.int64)
        # the landers' poses as the last step left them: that step's rows (nothing moved
        # them since; a lander respawned since takes its reset step now and fires nothing)
        before = self._stepped
        if before is None:
            before, _ = physics.states(landers)
        fire(physics, self._landers, before[:, :3], dispersion, m_power, s_power, direction)
        self.app.step(1)
        self._read_contacts(world)
        # the landers' rows of the physics' pose table: one gather, not 64 component reads
        after, self.awake = physics.states(landers)
        self._stepped = after
        state = after[:, _OBS_COLUMNS]
        state[:, 0] -= self.origins
        obs = observations(state, self.leg_contact, H / 4)
        if not np.isfinite(obs).all():
            rows = np.flatnonzero(~np.isfinite(obs).all(axis=1)).tolist()
            raise ObservationError(f"{self.env_name}: a non-finite observation in env(s) "
                                   f"{rows}: {obs[rows]!r}")
        reward, shaping = rewards(obs, self.prev_shaping, m_power, s_power, self.game_over,
                                  self.awake)
        # a reset step scores nothing and leaves the shaping unset, as a single env's reset
        self.prev_shaping = np.where(resetting, np.nan, shaping)
        self._obs[:] = obs
        self._rewards[:] = np.where(resetting, 0.0, reward)
        self._terminations[:] = ~resetting & (self.game_over | (np.abs(obs[:, 0]) >= 1.0)
                                              | ~self.awake)

    def _read_contacts(self, world: World) -> None:
        """The single env's contact listener, for every scene: ends first, then begins."""
        parts = self._parts
        for end in world.events(ContactEnd):
            for e in (end.collider_a, end.collider_b):
                hit = parts.get(e)
                if hit is not None and hit[1] != HULL:
                    self.leg_contact[hit] = 0.0
        for ev in world.events(ContactBegin):
            for e in (ev.collider_a, ev.collider_b):
                hit = parts.get(e)
                if hit is None:
                    continue
                if hit[1] == HULL:
                    self.game_over[hit[0]] = True
                else:
                    self.leg_contact[hit] = 1.0

    def _infos(self) -> dict[str, Any]:
        every = np.ones(self.num_envs, np.bool_)
        return {"game_over": self.game_over.copy(), "_game_over": every,
                "awake": self.awake.copy(), "_awake": every.copy()}

    # -- rendering ---------------------------------------------------------------------------
    def render(self) -> tuple[Any, ...] | None:
        """One (h, w, 3) frame per env: the camera visits each scene in turn."""
        if self.render_mode is None:
            import gymnasium as gym

            gym.logger.warn(f"{self.env_name}.render() without a render_mode: nothing drawn")
            return None
        from kge.render.setup import frame_pixels

        app = self.app
        camera = app.world.resource(Camera)
        frames = []
        for ox in self.origins.tolist():
            camera.center = (ox + W / 2, H / 2)
            app.render()
            frames.append(np.ascontiguousarray(frame_pixels(app)[::-1, :, :3]))
        camera.center = (W / 2, H / 2)
        return tuple(frames)

    def close_extras(self, **kwargs: Any) -> None:
        # also reached from __del__ of an env whose __init__ refused its arguments
        app, self._app = getattr(self, "_app", None), None
        self._started = False
        if app is not None:
            app.close()
