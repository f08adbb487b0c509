"""LunarLander, rebuilt from kge components (``kge/LunarLander-v0``).

The rules, sizes, engine impulses, reward shaping and the 8-number observation follow
Gymnasium's Box2D LunarLander (v3), so a controller or a policy written for one
transfers to the other:

* a 20 x 13.3 m moon; 11 terrain chunks of random height (uniform 0..H/2, smoothed),
  flattened around the helipad between the two flags at y = H/4;
* the lander: a 6-sided polygon (pixel outline / 30), density 5, and two leg boxes
  on motorised hinges with limits (see :func:`leg_joint`); an initial random push;
* actions (discrete): 0 nothing, 1 left orientation engine, 2 main engine, 3 right
  orientation engine; or, with ``continuous=True``, Gymnasium's two throttles in
  [-1, 1] (main, side); engines are impulses at offset points with a little random
  dispersion, as in Gymnasium;
* observation: position and velocity scaled to the viewport, angle, angular velocity,
  and one contact flag per leg;
* reward: the change of a shaping potential (distance, speed, tilt, leg contacts),
  -0.3 per main-engine frame and -0.03 per side-engine frame, -100 for touching the
  moon with the hull or leaving the screen, +100 when the lander comes to rest
  (its body falls asleep).

The physics is kge's (pymunk with Box2D 2.3 rules), not Box2D's, so trajectories are
close to Gymnasium's but not identical. :func:`heuristic` is a controller that lands.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import gymnasium as gym
import numpy as np

from kge.components import (
    BodyType,
    Box,
    Chain,
    Collider,
    Edge,
    Filter,
    Polygon,
    RevoluteJoint,
    RigidBody,
    Transform,
)
from kge.components import drawables as draw
from kge.components.camera import Camera
from kge.gym.env import KgeEnv
from kge.physics.events import ContactBegin, ContactEnd
from kge.physics.resource import Physics
from kge.physics.settings import PhysicsSettings
from kge.world import World

FPS = 50
SCALE = 30.0  # pixels per metre of Gymnasium's drawing; sizes below are its pixel sizes
MAIN_ENGINE_POWER = 13.0
SIDE_ENGINE_POWER = 0.6
INITIAL_RANDOM = 1000.0  # N, the random push at the start
LANDER_POLY = ((-14, 17), (-17, 0), (-17, -10), (17, -10), (17, 0), (14, 17))
LEG_AWAY, LEG_DOWN, LEG_W, LEG_H = 20, 18, 2, 8
LEG_SPRING_TORQUE = 40.0  # N m, the leg motors' strength
LEG_TRAVEL = (0.4, 0.9)  # rad, the hinge's limits (mirrored for the left leg)
LEG_MOTOR_SPEED = 0.3  # rad/s, slow enough not to hop the lander back up
#: (pymunk substeps, iterations per substep), with the legs' limits pushing nothing back
#: (``hinge_limit_push`` 0, Box2D's rule): the motor holds each leg on its stop and the
#: landed lander falls asleep. Heuristic pilot, seeds 0-49, landings that came to rest:
#: 8 x 8 47 (pybox2d 49), as 8 x 40; 8 x 6 49; 4 x 10 46; 8 x 5 47; 2 x 10 none (the
#: hull touches down). g = -5 and g = -3, seeds 0-2: all, in about pybox2d's number of
#: steps. Eight substeps keep continuous collision's sweeps rare (a leg moves less per
#: substep): over the first episodes 4 x 10 cost 40 µs per batched env step and 8 x 8
#: 27, and six substeps about 8 µs more than eight (``benchmarks.rl --profile 64``).
#: With a 0.1 rad/s push the legs hopped on the ground for ever below 8 x 40 (4 x 10:
#: no lander of 20 came to rest).
SOLVER = (8, 8)


def leg_joint(hull: int, leg: int, i: int) -> RevoluteJoint:
    """The motorised hinge of leg ``i`` (-1: right, +1: left, Gymnasium's order).

    The hinge sits at the hull's origin, (``LEG_AWAY``, ``LEG_DOWN``) from the leg's
    centre; the motor turns the leg outwards and holds it on the near end of its
    0.5 rad of travel, and a hard landing folds it towards the far end against
    ``LEG_SPRING_TORQUE``. The reference angle is 0 (the bodies' angles are compared
    directly), so the legs, spawned almost upright, swing out to their limit at once.
    """
    lo, hi = LEG_TRAVEL
    lower, upper = (lo, hi) if i == -1 else (-hi, -lo)
    return RevoluteJoint(hull, leg, local_anchor_a=(0.0, 0.0),
                         local_anchor_b=(i * LEG_AWAY / SCALE, LEG_DOWN / SCALE),
                         reference_angle=0.0, enable_limit=True, lower_angle=lower,
                         upper_angle=upper, enable_motor=True, motor_speed=LEG_MOTOR_SPEED * i,
                         max_motor_torque=LEG_SPRING_TORQUE)


SIDE_ENGINE_HEIGHT, SIDE_ENGINE_AWAY = 14, 12
MAIN_ENGINE_Y_LOCATION = 4
VIEWPORT_W, VIEWPORT_H = 600, 400
W, H = VIEWPORT_W / SCALE, VIEWPORT_H / SCALE
CHUNKS = 11

NOOP, LEFT, MAIN, RIGHT = 0, 1, 2, 3

_HULL = (128, 102, 230)
_FLAG = (204, 204, 0)


class LunarLander(KgeEnv):
    """Land on the pad between the flags. Discrete(4) actions, 8-float observations."""

    metadata: dict[str, Any] = {"render_modes": ["rgb_array", "human"],  # noqa: RUF012
                                          "render_fps": FPS}
    fixed_dt = 1.0 / FPS
    size = (VIEWPORT_W, VIEWPORT_H)

    action_space: gym.spaces.Space[Any] = gym.spaces.Discrete(4)
    observation_space = gym.spaces.Box(
        np.array([-2.5, -2.5, -10.0, -10.0, -2 * math.pi, -10.0, 0.0, 0.0], np.float32),
        np.array([2.5, 2.5, 10.0, 10.0, 2 * math.pi, 10.0, 1.0, 1.0], np.float32),
        dtype=np.float32,
    )

    def __init__(self, render_mode: str | None = None, gravity: float = -10.0,
                 continuous: bool = False) -> None:
        if not (isinstance(gravity, (int, float)) and -12.0 < gravity < 0.0):
            raise ValueError(f"LunarLander: gravity must be in (-12, 0) m/s^2, got {gravity!r}")
        if not isinstance(continuous, bool):
            raise TypeError(f"LunarLander: continuous must be True or False, got {continuous!r}")
        self.gravity = float(gravity)
        self.continuous = continuous
        if continuous:  # Gymnasium's: [main throttle, side engines], each in [-1, 1]
            self.action_space = gym.spaces.Box(-1.0, 1.0, (2,), dtype=np.float32)
        super().__init__(render_mode=render_mode)
        self.lander = 0
        self.legs = (0, 0)
        self.prev_shaping: float | None = None
        self.game_over = False
        self.leg_contact = [False, False]
        self.m_power = self.s_power = 0.0
        self.helipad_x = (0.0, 0.0)
        self.helipad_y = 0.0

    # -- the scene -------------------------------------------------------------------------------
    def build(self, world: World, rng: np.random.Generator) -> None:
        world.insert_resource(solver_settings(self.gravity))
        world.insert_resource(Camera(center=(W / 2, H / 2), pixels_per_meter=SCALE))
        scene = spawn_scene(world, rng, (0.0, 0.0), drawn=True)
        give_push(world, [scene])
        self.lander, self.legs, self.helipad_y = scene.lander, scene.legs, scene.helipad_y
        self.helipad_x = scene.helipad_x

    def on_reset(self, world: World) -> None:
        """Gymnasium's reset ends with one no-op step: the first observation is after it."""
        self.prev_shaping = None
        self.game_over = False
        self.leg_contact = [False, False]
        self.act(world, np.zeros(2, np.float32) if self.continuous else NOOP)
        self.app.step(self.frame_skip)

    # -- one step --------------------------------------------------------------------------------
    def act(self, world: World, action: Any) -> None:
        tf = world.get(self.lander, Transform)
        m_power, s_power, direction = throttle_one(action, self.continuous)
        self.m_power, self.s_power = m_power, s_power
        d0, d1 = self.np_random.uniform(-1.0, 1.0, size=2).tolist()
        fire_one(world.resource(Physics), self.lander, (tf.x, tf.y, tf.angle), (d0, d1),
                 m_power, s_power, direction)

    def throttle(self, action: Any) -> tuple[float, float, float]:
        """(main power 0..1, side power 0..1, side direction -1/+1) for one action."""
        return throttle_one(action, self.continuous)

    def observe(self, world: World) -> np.ndarray:
        self._read_contacts(world)
        tf = world.get(self.lander, Transform)
        rb = world.get(self.lander, RigidBody)
        vx, vy = rb.velocity
        legs = (self.leg_contact[0], self.leg_contact[1])
        return observation_one((tf.x, tf.y, vx, vy, tf.angle, rb.angular_velocity), legs,
                               self.helipad_y)

    def _read_contacts(self, world: World) -> None:
        """Box2D's contact listener of the original: hull contact ends the game, legs flag."""
        for end in world.events(ContactEnd):  # ends first: a contact that ends and begins again
            for k, leg in enumerate(self.legs):  # in one step is still touching
                if leg in (end.collider_a, end.collider_b):
                    self.leg_contact[k] = False
        for ev in world.events(ContactBegin):
            colliders = (ev.collider_a, ev.collider_b)
            if self.lander in colliders:
                self.game_over = True
            for k, leg in enumerate(self.legs):
                if leg in colliders:
                    self.leg_contact[k] = True

    def reward(self, world: World, obs: Any, action: Any) -> float:
        awake = world.get(self.lander, RigidBody).awake
        r, self.prev_shaping = reward_one(obs, self.prev_shaping, self.m_power, self.s_power,
                                          self.game_over, awake)
        return r

    def terminated(self, world: World, obs: Any) -> bool:
        return (self.game_over or abs(float(obs[0])) >= 1.0
                or not world.get(self.lander, RigidBody).awake)

    def info(self, world: World) -> dict[str, Any]:
        return {"game_over": self.game_over, "awake": world.get(self.lander, RigidBody).awake}


# -- the scene and the rules, shared by LunarLander and its batched form (LunarLanderVector) --
def solver_settings(gravity: float) -> PhysicsSettings:
    """The physics of the task: iterated hinges, so the leg motors and limits are solved
    inside pymunk's iterations with the contacts, as Box2D does, and limits that only stop
    the legs (no push back: ``hinge_limit_push`` 0; see :data:`SOLVER`)."""
    substeps, iterations = SOLVER
    return PhysicsSettings(gravity=(0.0, gravity), substeps=substeps, iterations=iterations,
                           iterated_hinges=True, hinge_limit_push=0.0)


@dataclass(slots=True)
class LanderScene:
    """The entities of one episode (joints first), which the next re-uses."""

    lander: int
    legs: tuple[int, int]
    helipad_x: tuple[float, float]
    helipad_y: float
    entities: list[int]
    #: the random force of the first step, N
    push: tuple[float, float]
    #: the moon's chain (its outline changes with every episode)
    ground: int = -1
    #: the joints, hull first then legs: what :func:`replace_scene` puts back
    joints: tuple[int, ...] = ()
    #: the moon's drawables (terrain quads, flags), redrawn for every episode
    decor: tuple[int, ...] = ()


@dataclass(slots=True)
class _Moon:
    """One episode's terrain, drawn from the env's rng."""

    chunk_x: list[float]
    smooth_y: list[float]
    helipad_x: tuple[float, float]
    helipad_y: float

    def chain(self) -> Chain:
        return Chain(list(zip(self.chunk_x, self.smooth_y, strict=True)))


def _moon(rng: np.random.Generator, ox: float) -> _Moon:
    """Gymnasium's terrain: 11 chunks of random height, flat around the helipad."""
    height = rng.uniform(0, H / 2, size=(CHUNKS + 1,))
    chunk_x = [W / (CHUNKS - 1) * i for i in range(CHUNKS)]
    helipad_x = (ox + chunk_x[CHUNKS // 2 - 1], ox + chunk_x[CHUNKS // 2 + 1])
    helipad_y = H / 4
    height[CHUNKS // 2 - 2 : CHUNKS // 2 + 3] = helipad_y
    h = height.tolist()  # Python floats: the same sums, and Chain checks them fastest
    smooth_y = [0.33 * (h[i - 1] + h[i] + h[i + 1]) for i in range(CHUNKS)]
    return _Moon(chunk_x, smooth_y, helipad_x, helipad_y)


def _decor(world: World, moon: _Moon, origin: tuple[float, float]) -> tuple[int, ...]:
    """The moon's drawables: terrain quads under the outline and the two flags."""
    ox, oy = origin
    xs, ys = moon.chunk_x, moon.smooth_y
    made = []
    for i in range(CHUNKS - 1):
        quad = ((xs[i], 0.0), (xs[i + 1], 0.0), (xs[i + 1], ys[i + 1]), (xs[i], ys[i]))
        made.append(world.spawn(Transform(ox, oy),
                                draw.Polygon(quad, color=(255, 255, 255), layer=-1)))
    for x in moon.helipad_x:
        y = oy + moon.helipad_y
        made.append(world.spawn(Transform(), draw.Line(
            (x, y), (x, y + 50 / SCALE), color=(255, 255, 255), thickness=1 / SCALE)))
        made.append(world.spawn(Transform(), draw.Triangle(
            (x, y + 50 / SCALE), (x, y + 40 / SCALE), (x + 25 / SCALE, y + 45 / SCALE),
            color=_FLAG)))
    return tuple(made)


def _start_poses(origin: tuple[float, float]) -> list[tuple[float, float, float]]:
    """Where an episode starts: the hull at the top centre, then legs -1 and +1."""
    x0, y0 = origin[0] + W / 2, origin[1] + H
    return [(x0, y0, 0.0), *((x0 - i * LEG_AWAY / SCALE, y0, i * 0.05) for i in (-1, 1))]


def _push(rng: np.random.Generator) -> tuple[float, float]:
    px, py = rng.uniform(-INITIAL_RANDOM, INITIAL_RANDOM, size=2).tolist()
    return px, py


def spawn_scene(world: World, rng: np.random.Generator, origin: tuple[float, float],
                drawn: bool) -> LanderScene:
    """Spawn a moon and a lander with its origin at ``origin``; draw its random push
    (:func:`give_push` applies it).

    ``rng`` draws the terrain and the push (in Gymnasium's order). ``drawn`` adds the
    drawables (terrain quads, flags, hull and legs); an env that never renders skips them.
    Nothing here collides with another scene's moon as long as scenes lie further apart
    than a lander flies out of its screen before its episode ends (see LunarLanderVector).
    """
    ox, oy = origin
    moon = _moon(rng, ox)
    ground = Filter(category_bits=0x0001)
    edge = world.spawn(Transform(ox, oy), Collider(Edge((0.0, 0.0), (W, 0.0)), friction=0.1,
                                                   filter=ground))
    chain = world.spawn(Transform(ox, oy), Collider(moon.chain(), friction=0.1, filter=ground))
    decor = _decor(world, moon, origin) if drawn else ()

    (x0, y0, _), *leg_poses = _start_poses(origin)
    poly = [(px / SCALE, py / SCALE) for px, py in LANDER_POLY]
    looks: tuple[Any, ...] = (draw.Polygon(poly, color=_HULL),) if drawn else ()
    lander = world.spawn(
        Transform(x0, y0), RigidBody(BodyType.DYNAMIC),
        Collider(Polygon(poly), density=5.0, friction=0.1, restitution=0.0,
                 filter=Filter(category_bits=0x0010, mask_bits=0x001)),
        *looks,
    )
    legs, joints = [], []
    leg_shape = Box(LEG_W / SCALE, LEG_H / SCALE)
    for i, (x, y, angle) in zip((-1, +1), leg_poses, strict=True):
        looks = (draw.Polygon(leg_shape.vertices(), color=_HULL),) if drawn else ()
        leg = world.spawn(
            Transform(x, y, angle), RigidBody(BodyType.DYNAMIC),
            Collider(leg_shape, density=1.0, friction=0.2, restitution=0.0,
                     filter=Filter(category_bits=0x0020, mask_bits=0x001)),
            *looks,
        )
        joints.append(world.spawn(leg_joint(lander, leg, i)))
        legs.append(leg)
    return LanderScene(lander, (legs[0], legs[1]), moon.helipad_x, moon.helipad_y,
                       [*joints, edge, chain, *decor, lander, *legs], _push(rng),
                       ground=chain, joints=tuple(joints), decor=decor)


def replace_scene(world: World, scene: LanderScene, rng: np.random.Generator,
                  origin: tuple[float, float], drawn: bool) -> LanderScene:
    """A new episode on ``scene``'s entities: a new moon outline (drawn from ``rng`` as
    :func:`spawn_scene` draws it, so the episode is the one a fresh scene would get)
    and the lander and legs put back at the top, at rest, their joints starting cold.

    What an RL reset wants: nothing is built or destroyed, so the physics has no
    bodies, joints or batches to rebuild (a despawn and spawn of the scene cost
    about 2 ms in a world of 64 scenes; this costs a tenth of that).
    """
    moon = _moon(rng, origin[0])
    world.get(scene.ground, Collider).shape = moon.chain()
    for e in scene.decor:
        world.despawn(e)
    decor = _decor(world, moon, origin) if drawn else ()
    for e, (x, y, angle) in zip((scene.lander, *scene.legs), _start_poses(origin), strict=True):
        t = world.get(e, Transform)
        t.x, t.y, t.angle = x, y, angle
        rb = world.get(e, RigidBody)
        rb.velocity, rb.angular_velocity = (0.0, 0.0), 0.0
    world.resource(Physics).reset_joints(scene.joints)
    old_decor = set(scene.decor)
    entities = [e for e in scene.entities if e not in old_decor] + list(decor)
    return LanderScene(scene.lander, scene.legs, moon.helipad_x, moon.helipad_y, entities,
                       _push(rng), ground=scene.ground, joints=scene.joints, decor=decor)


def give_push(world: World, scenes: list[LanderScene]) -> None:
    """Apply each new lander's random push (a force for the first step). After all the
    spawns: the first force makes the physics build the bodies, once for all scenes."""
    physics = world.resource(Physics)
    for scene in scenes:
        physics.apply_force(scene.lander, scene.push)


def throttles(actions: np.ndarray, continuous: bool) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(main power 0..1, side power 0..1, side direction -1/+1), one row per action.

    Discrete (``actions`` of shape (n, 1)): engines fire at full power. Continuous
    (shape (n, 2), Gymnasium's rules): the main engine runs at 50-100 % for
    ``action[0]`` in (0, 1] and is off below; the side engines fire at 50-100 % for
    ``|action[1]|`` in (0.5, 1], left for negative.
    """
    if not continuous:
        a = actions[:, 0]
        side = (a == LEFT) | (a == RIGHT)
        return (a == MAIN).astype(np.float64), side.astype(np.float64), np.where(side, a - 2, 0.0)
    main, lateral = actions[:, 0], actions[:, 1]
    m_power = np.where(main > 0.0, (np.clip(main, 0.0, 1.0) + 1.0) * 0.5, 0.0)
    on = np.abs(lateral) > 0.5
    s_power = np.where(on, np.clip(np.abs(lateral), 0.5, 1.0), 0.0)
    return m_power, s_power, np.where(on, np.copysign(1.0, lateral), 0.0)


#: at most this many firing engines are pushed one call each: below it the checks and
#: numpy of Physics.apply_linear_impulses cost more than the calls (the same floats)
FEW_ENGINES = 4


def fire(physics: Physics, landers: list[int], pose: np.ndarray, dispersion: np.ndarray,
         m_power: np.ndarray, s_power: np.ndarray, direction: np.ndarray) -> None:
    """The engines' impulses, Gymnasium's geometry, for the landers whose engines fire
    (``pose`` rows x, y, angle; ``dispersion`` rows uniform in [-1, 1]), in numpy."""
    # every firing engine in one call, main engines first (the order of the calls
    # one by one, which an env whose two engines fire at once depends on); only the
    # firing rows are computed, in one set of columns for both kinds of engine
    on_main, on_side = np.flatnonzero(m_power > 0.0), np.flatnonzero(s_power > 0.0)
    k = len(on_main)
    if not (k or len(on_side)):
        return
    rows = np.concatenate([on_main, on_side])
    x, y, angle = pose[rows].T
    tip_x, tip_y = np.sin(angle), np.cos(angle)
    d0, d1 = (dispersion[rows] / SCALE).T
    # the nozzle's offset along the tip (main: below the hull; side: the dispersion)
    # and across it (main: the dispersion; side: out to the engine's side)
    along = d0.copy()
    along[:k] = MAIN_ENGINE_Y_LOCATION / SCALE + 2 * d0[:k]
    across = d1.copy()
    across[k:] = 3 * d1[k:] + direction[on_side] * SIDE_ENGINE_AWAY / SCALE
    ox = tip_x * along + (-tip_y) * across  # (side = (-tip_y, tip_x))
    oy = -tip_y * along - tip_x * across
    power = np.concatenate([MAIN_ENGINE_POWER * m_power[on_main],
                            SIDE_ENGINE_POWER * s_power[on_side]])
    out = np.empty((len(rows), 4))
    out[:, 0] = -ox * power
    out[:, 1] = -oy * power
    out[:, 2] = x + ox
    out[:, 3] = y + oy
    out[k:, 2] -= tip_x[k:] * 17 / SCALE
    out[k:, 3] += tip_y[k:] * SIDE_ENGINE_HEIGHT / SCALE
    if len(rows) <= FEW_ENGINES:  # a single env: the bulk call's numpy costs more
        for e, (jx, jy, px, py) in zip([landers[r] for r in rows.tolist()], out.tolist(),
                                       strict=True):
            physics.apply_linear_impulse(e, (jx, jy), (px, py))
        return
    who = np.asarray(landers, dtype=np.int64)[rows]
    physics.apply_linear_impulses(who, out[:, :2], out[:, 2:])


def observations(state: np.ndarray, legs: np.ndarray, helipad_y: float) -> np.ndarray:
    """The 8-float observations: ``state`` rows (x, y, vx, vy, angle, angular velocity)
    relative to each scene's origin, ``legs`` rows (left, right) contact flags 0/1."""
    out = np.empty((len(state), 8), np.float32)
    out[:, 0] = (state[:, 0] - W / 2) / (W / 2)
    out[:, 1] = (state[:, 1] - (helipad_y + LEG_DOWN / SCALE)) / (H / 2)
    out[:, 2] = state[:, 2] * (W / 2) / FPS
    out[:, 3] = state[:, 3] * (H / 2) / FPS
    out[:, 4] = state[:, 4]
    out[:, 5] = 20.0 * state[:, 5] / FPS
    out[:, 6:8] = legs
    return out


def rewards(obs: np.ndarray, prev_shaping: np.ndarray, m_power: np.ndarray,
            s_power: np.ndarray, game_over: np.ndarray,
            awake: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(reward, shaping) per row: the change of the shaping potential (0 on an episode's
    first step, where ``prev_shaping`` is NaN) minus fuel; -100 for a crash or leaving
    the screen, +100 for coming to rest."""
    s = obs.astype(np.float64)
    shaping = (-100 * np.hypot(s[:, 0], s[:, 1]) - 100 * np.hypot(s[:, 2], s[:, 3])
               - 100 * np.abs(s[:, 4]) + 10 * s[:, 6] + 10 * s[:, 7])
    r = np.where(np.isnan(prev_shaping), 0.0, shaping - prev_shaping)
    r -= m_power * 0.30 + s_power * 0.03
    r = np.where(awake, r, 100.0)
    r = np.where(game_over | (np.abs(s[:, 0]) >= 1.0), -100.0, r)
    return r, shaping


# -- one lander in Python floats: what the single env runs -------------------------------------
# The row functions above, for one lander: numpy calls on one-row arrays cost more than
# their arithmetic (about 250 µs of a 1 ms env step went there). The same formulas on
# floats, the same operations in the same order (IEEE double, as numpy's), and numpy's
# own sin, cos and hypot on the scalars: every result has the row version's bits
# (tests/gym/test_lander_one.py runs both on the same inputs).


def throttle_one(action: Any, continuous: bool) -> tuple[float, float, float]:
    """(main power 0..1, side power 0..1, side direction -1/+1): ``throttles`` for one
    action (a discrete action number, or the two continuous throttles)."""
    if not continuous:
        a = float(np.asarray(action, dtype=np.float64).reshape(-1)[0])
        side = a in (LEFT, RIGHT)
        return (1.0 if a == MAIN else 0.0), (1.0 if side else 0.0), (a - 2 if side else 0.0)
    main, lateral = (float(v) for v in np.asarray(action, dtype=np.float64).reshape(-1)[:2])
    m_power = (min(max(main, 0.0), 1.0) + 1.0) * 0.5 if main > 0.0 else 0.0
    on = abs(lateral) > 0.5
    s_power = min(max(abs(lateral), 0.5), 1.0) if on else 0.0
    return m_power, s_power, (math.copysign(1.0, lateral) if on else 0.0)


def fire_one(physics: Physics, lander: int, pose: tuple[float, float, float],
             dispersion: tuple[float, float], m_power: float, s_power: float,
             direction: float) -> None:
    """``fire`` for one lander: its main engine's impulse, then its side engine's."""
    if not (m_power > 0.0 or s_power > 0.0):
        return
    x, y, angle = pose
    tip_x, tip_y = float(np.sin(angle)), float(np.cos(angle))
    d0, d1 = dispersion[0] / SCALE, dispersion[1] / SCALE
    if m_power > 0.0:
        along = MAIN_ENGINE_Y_LOCATION / SCALE + 2 * d0
        ox = tip_x * along + (-tip_y) * d1
        oy = -tip_y * along - tip_x * d1
        power = MAIN_ENGINE_POWER * m_power
        physics.apply_linear_impulse(lander, (-ox * power, -oy * power), (x + ox, y + oy))
    if s_power > 0.0:
        across = 3 * d1 + direction * SIDE_ENGINE_AWAY / SCALE
        ox = tip_x * d0 + (-tip_y) * across
        oy = -tip_y * d0 - tip_x * across
        power = SIDE_ENGINE_POWER * s_power
        px = x + ox - tip_x * 17 / SCALE
        py = y + oy + tip_y * SIDE_ENGINE_HEIGHT / SCALE
        physics.apply_linear_impulse(lander, (-ox * power, -oy * power), (px, py))


def observation_one(state: tuple[float, float, float, float, float, float],
                    legs: tuple[bool, bool], helipad_y: float) -> np.ndarray:
    """``observations`` for one lander: ``state`` is (x, y, vx, vy, angle, angular
    velocity), ``legs`` the two contact flags."""
    x, y, vx, vy, angle, w = state
    return np.array([
        (x - W / 2) / (W / 2),
        (y - (helipad_y + LEG_DOWN / SCALE)) / (H / 2),
        vx * (W / 2) / FPS,
        vy * (H / 2) / FPS,
        angle,
        20.0 * w / FPS,
        float(legs[0]),
        float(legs[1]),
    ], np.float32)  # fmt: skip


def reward_one(obs: np.ndarray, prev_shaping: float | None, m_power: float, s_power: float,
               game_over: bool, awake: bool) -> tuple[float, float]:
    """``rewards`` for one lander: (reward, shaping); ``prev_shaping`` None on an
    episode's first step."""
    s0, s1, s2, s3, s4, _, s6, s7 = obs.tolist()  # float32 -> the same doubles as astype
    shaping = (-100 * float(np.hypot(s0, s1)) - 100 * float(np.hypot(s2, s3))
               - 100 * abs(s4) + 10 * s6 + 10 * s7)
    r = 0.0 if prev_shaping is None or math.isnan(prev_shaping) else shaping - prev_shaping
    r -= m_power * 0.30 + s_power * 0.03
    if not awake:
        r = 100.0
    if game_over or abs(s0) >= 1.0:
        r = -100.0
    return r, shaping


#: a discrete action as the continuous throttles that fire the same engine at full power
AS_CONTINUOUS = {NOOP: (-1.0, 0.0), LEFT: (-1.0, -1.0), MAIN: (1.0, 0.0), RIGHT: (-1.0, 1.0)}


def heuristic(obs: np.ndarray) -> int:
    """A controller that lands: aim the tilt at the pad, hold a descent speed, then settle.

    It is a two-loop proportional-derivative controller. The outer loop picks a
    target tilt that steers the lander over the pad (lean against the horizontal
    offset and drift, at most 0.35 rad) and a target sink rate that slows down
    near the ground; the inner loop fires a side engine to reach the tilt, or the
    main engine when the lander sinks faster than wanted. Once a leg touches, it
    only brakes the fall.
    """
    x, y, vx, vy, angle, omega, left, right = (float(v) for v in obs)
    tilt_target = float(np.clip(0.6 * x + 1.1 * vx, -0.35, 0.35))
    tilt_error = (tilt_target - angle) * 0.6 - omega * 1.0
    sink_target = -0.05 - 0.45 * max(y, 0.0)  # scaled vertical speed wanted: slow near the pad
    climb_error = (sink_target - vy) * 0.8 + (0.5 * abs(x) - y) * 0.3
    if left or right:
        tilt_error = 0.0
        climb_error = -vy * 0.5
    if climb_error > abs(tilt_error) and climb_error > 0.05:
        return MAIN
    if tilt_error < -0.05:
        return RIGHT
    if tilt_error > 0.05:
        return LEFT
    return NOOP
