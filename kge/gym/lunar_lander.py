"""LunarLander, rebuilt from kge components (``kge/LunarLander-v0``).

The rules, sizes, engine impulses, reward shaping and the 8-number observation follow
Gymnasium's Box2D LunarLander (v3), so a controller or a policy written for one
transfers to the other:

* a 20 x 13.3 m moon; 11 terrain chunks of random height (uniform 0..H/2, smoothed),
  flattened around the helipad between the two flags at y = H/4;
* the lander: a 6-sided polygon (pixel outline / 30), density 5, two leg boxes (held
  rigid at the angle Gymnasium's leg motors hold them: see :func:`leg_box`); an
  initial random push;
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
LEG_ANGLE = 0.4  # where Gymnasium's leg motors hold the legs: their joint limit
# A touchdown faster than this folds Gymnasium's legs to their stop and the hull hits the
# moon: the two leg motors (40 N m) resisting over their 0.5 rad of travel absorb
# 2 * 40 * 0.5 = 40 J, the kinetic energy of the 4.8 kg hull at 4.1 m/s.
LEG_CRUSH_SPEED = 4.0


def leg_box(i: int) -> Box:
    """Leg ``i`` (-1: right, +1: left, Gymnasium's order) as a box in the hull's frame.

    Gymnasium hangs each leg on a motorised hinge that presses it against its
    limit (0.4 rad) and lets it fold to 0.9 rad on a hard landing. Here the legs
    are colliders of the hull itself, fixed where that limit holds them: a kge
    hinge motor is solved once per substep before the contact iterations, and it
    measured too weak to hold a 0.07 kg leg under the 4.8 kg hull (the legs folded
    and the hull touched down on every landing), and it writes body velocities
    every substep, which keeps the hull from ever falling asleep. Rigid legs keep
    the geometry, the contact flags and the "at rest" ending of the original, and
    cost no Python per substep; a touchdown faster than ``LEG_CRUSH_SPEED`` ends
    the game as the folding legs would.
    """
    angle = -i * LEG_ANGLE
    ax, ay = i * LEG_AWAY / SCALE, LEG_DOWN / SCALE  # the hinge point in the leg's frame
    c, s = math.cos(angle), math.sin(angle)
    center = (-(c * ax - s * ay), -(s * ax + c * ay))
    return Box(LEG_W / SCALE, LEG_H / SCALE, center=center, angle=angle)


def box_corners(box: Box) -> list[tuple[float, float]]:
    """The four corners of ``box`` in its body's frame, counter-clockwise (for drawing)."""
    c, s = math.cos(box.angle), math.sin(box.angle)
    cx, cy = box.center
    hw, hh = box.half_width, box.half_height
    return [(cx + c * x - s * y, cy + s * x + c * y)
            for x, y in ((-hw, -hh), (hw, -hh), (hw, hh), (-hw, hh))]
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
        self.legs = self._leg_sprites = (0, 0)
        self.prev_shaping: float | None = None
        self.game_over = False
        self.leg_contact = [False, False]
        self.m_power = self.s_power = 0.0
        self.helipad_x = (0.0, 0.0)
        self.helipad_y = 0.0

    # -- the scene -------------------------------------------------------------------------------
    def build(self, world: World, rng: np.random.Generator) -> None:
        world.insert_resource(PhysicsSettings(gravity=(0.0, self.gravity)))
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
        legs, sprites = [], []
        for i in (-1, +1):
            shape = leg_box(i)
            legs.append(world.spawn(Collider(
                shape, body=lander, density=1.0, friction=0.2, restitution=0.0,
                filter=Filter(category_bits=0x0020, mask_bits=0x001))))
            sprites.append(world.spawn(Transform(x0, y0), draw.Polygon(box_corners(shape),
                                                                         color=_HULL)))
        self.legs = (legs[0], legs[1])
        self._leg_sprites = (sprites[0], sprites[1])
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
                    if ev.approach_speed > LEG_CRUSH_SPEED:
                        self.game_over = True  # the leg folds to its stop: the hull hits

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

    def render(self) -> np.ndarray | None:  # type: ignore[override]
        if self._app is not None:  # the legs' drawings follow the hull
            world = self.world
            hull = world.get(self.lander, Transform)
            for sprite in self._leg_sprites:
                tf = world.get(sprite, Transform)
                tf.x, tf.y, tf.angle = hull.x, hull.y, hull.angle
        return super().render()


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
