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
from kge.physics.events import PhysicsEvents
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
#: (pymunk substeps, iterations per substep). Each 0.07 kg leg hangs on a pivot under
#: the 4.8 kg hull; pymunk's iterative solver needs many passes at that mass ratio, or the
#: legs hop on the ground and the lander never falls asleep. Heuristic pilot, seeds 0-9,
#: g = -10, landings that came to rest: 4 x 10 (kge's default) 0, 8 x 15 1, 8 x 23
#: (Gymnasium's 6 * 30 velocity iterations as kge.box2d maps them) 9, 8 x 40 10; at
#: g = -5, seeds 0-2: 8 x 23 none, 8 x 40 all. It costs throughput: see docs/rl.md.
SOLVER = (8, 40)


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
        # iterated hinges: the leg motors and limits are solved inside pymunk's iterations,
        # with the contacts, as Box2D does, so they hold the legs on their limits (SOLVER)
        substeps, iterations = SOLVER
        world.insert_resource(PhysicsSettings(gravity=(0.0, self.gravity), substeps=substeps,
                                              iterations=iterations, iterated_hinges=True))
        height = rng.uniform(0, H / 2, size=(CHUNKS + 1,))
        chunk_x = [W / (CHUNKS - 1) * i for i in range(CHUNKS)]
        self.helipad_x = (chunk_x[CHUNKS // 2 - 1], chunk_x[CHUNKS // 2 + 1])
        self.helipad_y = H / 4
        height[CHUNKS // 2 - 2 : CHUNKS // 2 + 3] = self.helipad_y
        smooth_y = [0.33 * (height[i - 1] + height[i] + height[i + 1]) for i in range(CHUNKS)]
        ground = Filter(category_bits=0x0001)
        world.spawn(Transform(), Collider(Edge((0.0, 0.0), (W, 0.0)), friction=0.1, filter=ground))
        world.spawn(Transform(), Collider(Chain(list(zip(chunk_x, smooth_y, strict=True))),
                                          friction=0.1, filter=ground))
        for i in range(CHUNKS - 1):
            quad = ((chunk_x[i], 0.0), (chunk_x[i + 1], 0.0),
                    (chunk_x[i + 1], smooth_y[i + 1]), (chunk_x[i], smooth_y[i]))
            world.spawn(Transform(), draw.Polygon(quad, color=(255, 255, 255), layer=-1))
        for x in self.helipad_x:
            y = self.helipad_y
            world.spawn(Transform(), draw.Line((x, y), (x, y + 50 / SCALE), color=(255, 255, 255),
                                               thickness=1 / SCALE))
            world.spawn(Transform(), draw.Triangle((x, y + 50 / SCALE), (x, y + 40 / SCALE),
                                                   (x + 25 / SCALE, y + 45 / SCALE), color=_FLAG))
        world.insert_resource(Camera(center=(W / 2, H / 2), pixels_per_meter=SCALE))

        x0, y0 = W / 2, H
        poly = [(px / SCALE, py / SCALE) for px, py in LANDER_POLY]
        self.lander = lander = world.spawn(
            Transform(x0, y0), RigidBody(BodyType.DYNAMIC),
            Collider(Polygon(poly), density=5.0, friction=0.1, restitution=0.0,
                     filter=Filter(category_bits=0x0010, mask_bits=0x001)),
            draw.Polygon(poly, color=_HULL),
        )
        legs = []
        leg_shape = Box(LEG_W / SCALE, LEG_H / SCALE)
        for i in (-1, +1):
            leg = world.spawn(
                Transform(x0 - i * LEG_AWAY / SCALE, y0, i * 0.05), RigidBody(BodyType.DYNAMIC),
                Collider(leg_shape, density=1.0, friction=0.2, restitution=0.0,
                         filter=Filter(category_bits=0x0020, mask_bits=0x001)),
                draw.Polygon(leg_shape.vertices(), color=_HULL),
            )
            world.spawn(leg_joint(lander, leg, i))
            legs.append(leg)
        self.legs = (legs[0], legs[1])
        push = rng.uniform(-INITIAL_RANDOM, INITIAL_RANDOM, size=2)
        world.resource(Physics).apply_force(lander, (float(push[0]), float(push[1])))

    def on_reset(self, world: World) -> None:
        """Gymnasium's reset ends with one no-op step: the first observation is after it."""
        self.prev_shaping = None
        self.game_over = False
        self.leg_contact = [False, False]
        self.act(world, np.zeros(2, np.float32) if self.continuous else NOOP)
        self.app.step(self.frame_skip)

    # -- one step --------------------------------------------------------------------------------
    def act(self, world: World, action: Any) -> None:
        physics = world.resource(Physics)
        tf = world.get(self.lander, Transform)
        tip = (math.sin(tf.angle), math.cos(tf.angle))
        side = (-tip[1], tip[0])
        d0, d1 = (self.np_random.uniform(-1.0, 1.0, size=2) / SCALE).tolist()
        self.m_power, self.s_power, direction = self.throttle(action)
        if self.m_power > 0.0:
            ox = tip[0] * (MAIN_ENGINE_Y_LOCATION / SCALE + 2 * d0) + side[0] * d1
            oy = -tip[1] * (MAIN_ENGINE_Y_LOCATION / SCALE + 2 * d0) - side[1] * d1
            p = MAIN_ENGINE_POWER * self.m_power
            physics.apply_linear_impulse(self.lander, (-ox * p, -oy * p), (tf.x + ox, tf.y + oy))
        if self.s_power > 0.0:
            lever = 3 * d1 + direction * SIDE_ENGINE_AWAY / SCALE
            ox = tip[0] * d0 + side[0] * lever
            oy = -tip[1] * d0 - side[1] * lever
            at = (tf.x + ox - tip[0] * 17 / SCALE, tf.y + oy + tip[1] * SIDE_ENGINE_HEIGHT / SCALE)
            p = SIDE_ENGINE_POWER * self.s_power
            physics.apply_linear_impulse(self.lander, (-ox * p, -oy * p), at)

    def throttle(self, action: Any) -> tuple[float, float, float]:
        """(main power 0..1, side power 0..1, side direction -1/+1) for an action.

        Discrete: engines fire at full power. Continuous (Gymnasium's rules): the main
        engine runs at 50-100 % for ``action[0]`` in (0, 1] and is off below; the side
        engines fire at 50-100 % for ``|action[1]|`` in (0.5, 1], left for negative.
        """
        if not self.continuous:
            a = int(action)
            if a == MAIN:
                return 1.0, 0.0, 0.0
            if a in (LEFT, RIGHT):
                return 0.0, 1.0, float(a - 2)
            return 0.0, 0.0, 0.0
        main, lateral = (float(v) for v in np.asarray(action, dtype=np.float64))
        m_power = (min(max(main, 0.0), 1.0) + 1.0) * 0.5 if main > 0.0 else 0.0
        if abs(lateral) > 0.5:
            return m_power, min(max(abs(lateral), 0.5), 1.0), math.copysign(1.0, lateral)
        return m_power, 0.0, 0.0

    def observe(self, world: World) -> np.ndarray:
        self._read_contacts(world)
        tf = world.get(self.lander, Transform)
        rb = world.get(self.lander, RigidBody)
        vx, vy = rb.velocity
        return np.array([
            (tf.x - W / 2) / (W / 2),
            (tf.y - (self.helipad_y + LEG_DOWN / SCALE)) / (H / 2),
            vx * (W / 2) / FPS,
            vy * (H / 2) / FPS,
            tf.angle,
            20.0 * rb.angular_velocity / FPS,
            1.0 if self.leg_contact[0] else 0.0,
            1.0 if self.leg_contact[1] else 0.0,
        ], dtype=np.float32)

    def _read_contacts(self, world: World) -> None:
        """Box2D's contact listener of the original: hull contact ends the game, legs flag."""
        events = world.resource(PhysicsEvents)
        for end in events.contact_end:  # ends first: a contact that ends and begins again
            for k, leg in enumerate(self.legs):  # in one step is still touching
                if leg in (end.collider_a, end.collider_b):
                    self.leg_contact[k] = False
        for ev in events.contact_begin:
            colliders = (ev.collider_a, ev.collider_b)
            if self.lander in colliders:
                self.game_over = True
            for k, leg in enumerate(self.legs):
                if leg in colliders:
                    self.leg_contact[k] = True

    def reward(self, world: World, obs: Any, action: Any) -> float:
        s = obs.astype(np.float64)
        shaping = (-100 * math.hypot(s[0], s[1]) - 100 * math.hypot(s[2], s[3])
                   - 100 * abs(s[4]) + 10 * s[6] + 10 * s[7])
        r = 0.0 if self.prev_shaping is None else shaping - self.prev_shaping
        self.prev_shaping = shaping
        r -= self.m_power * 0.30 + self.s_power * 0.03
        if self.game_over or abs(s[0]) >= 1.0:
            return -100.0
        if not world.get(self.lander, RigidBody).awake:  # at rest: Box2D put it to sleep
            return 100.0
        return r

    def terminated(self, world: World, obs: Any) -> bool:
        return (self.game_over or abs(float(obs[0])) >= 1.0
                or not world.get(self.lander, RigidBody).awake)

    def info(self, world: World) -> dict[str, Any]:
        return {"game_over": self.game_over, "awake": world.get(self.lander, RigidBody).awake}


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
