"""CartPole on kge joints (``kge/CartPole-v0``).

Gymnasium's CartPole-v1 integrates the cart-pole equations by hand; this one is a
physical scene: a 1 kg cart on a :class:`~kge.components.PrismaticJoint` along the
ground's x axis and a 0.1 kg, 1 m pole (a thin box: inertia m L^2 / 3 about its foot,
Gymnasium's 4/3 model) on a :class:`~kge.components.RevoluteJoint` at the cart's
centre. Everything else is Gymnasium's: a 0.02 s step, a 10 N push left (action 0)
or right (action 1), the observation (cart position, cart velocity, pole angle from
vertical, positive leaning right, pole angular velocity), +1 per step, the episode
ends when the pole leans past 12 degrees or the cart leaves [-2.4, 2.4] m, and the
registered time limit is 500 steps. :func:`heuristic` balances it.
"""

from __future__ import annotations

import math
from typing import Any

import gymnasium as gym
import numpy as np

from kge.components import (
    BodyType,
    Box,
    Collider,
    Filter,
    PrismaticJoint,
    RevoluteJoint,
    RigidBody,
    Transform,
)
from kge.components import drawables as draw
from kge.components.camera import Camera
from kge.gym.env import KgeEnv
from kge.physics.resource import Physics
from kge.physics.settings import PhysicsSettings
from kge.world import World

GRAVITY = 9.8
CART_MASS, POLE_MASS = 1.0, 0.1
POLE_HALF_LENGTH = 0.5
POLE_HALF_WIDTH = 0.01
CART_HALF = (0.25, 0.15)
FORCE = 10.0
TAU = 0.02
THETA_LIMIT = 12 * 2 * math.pi / 360
X_LIMIT = 2.4

_NOTHING = Filter(category_bits=0x0001, mask_bits=0x0000)  # the parts never collide


class CartPole(KgeEnv):
    """Balance the pole by pushing the cart. Discrete(2) actions, 4-float observations."""

    metadata: dict[str, Any] = {"render_modes": ["rgb_array", "human"],  # noqa: RUF012
                                          "render_fps": round(1 / TAU)}
    fixed_dt = TAU
    size = (600, 400)
    background = (255, 255, 255)

    action_space = gym.spaces.Discrete(2)
    _high = np.array([X_LIMIT * 2, np.finfo(np.float32).max, THETA_LIMIT * 2,
                      np.finfo(np.float32).max], dtype=np.float32)
    observation_space = gym.spaces.Box(-_high, _high, dtype=np.float32)

    def __init__(self, render_mode: str | None = None) -> None:
        super().__init__(render_mode=render_mode)
        self.cart = self.pole = 0

    def build(self, world: World, rng: np.random.Generator) -> None:
        world.insert_resource(PhysicsSettings(gravity=(0.0, -GRAVITY)))
        world.insert_resource(Camera(center=(0.0, 0.5), pixels_per_meter=600 / (2 * X_LIMIT)))
        x, x_dot, theta, theta_dot = rng.uniform(-0.05, 0.05, size=(4,)).tolist()
        world.spawn(Transform(), draw.Line((-X_LIMIT * 1.2, 0.0), (X_LIMIT * 1.2, 0.0),
                                           color=(0, 0, 0), thickness=0.01, layer=-1))
        hw, hh = CART_HALF
        self.cart = cart = world.spawn(
            Transform(x, 0.0), RigidBody(BodyType.DYNAMIC, velocity=(x_dot, 0.0)),
            Collider(Box(hw, hh), density=CART_MASS / (4 * hw * hh), filter=_NOTHING),
            draw.Rect(2 * hw, 2 * hh, color=(0, 0, 0)),
        )
        # the pole leans right (theta > 0) by turning clockwise: kge angles are CCW
        angle, omega = -theta, -theta_dot
        cx = x + POLE_HALF_LENGTH * math.sin(theta)
        cy = POLE_HALF_LENGTH * math.cos(theta)
        # the centre moves with the cart plus omega x r (r from the foot to the centre)
        vx = x_dot - omega * (cy - 0.0)
        vy = omega * (cx - x)
        self.pole = pole = world.spawn(
            Transform(cx, cy, angle),
            RigidBody(BodyType.DYNAMIC, velocity=(vx, vy), angular_velocity=omega),
            Collider(Box(POLE_HALF_WIDTH, POLE_HALF_LENGTH),
                     density=POLE_MASS / (4 * POLE_HALF_WIDTH * POLE_HALF_LENGTH),
                     filter=_NOTHING),
            draw.Rect(0.1, 2 * POLE_HALF_LENGTH, color=(202, 152, 101)),
        )
        world.spawn(PrismaticJoint(None, cart, anchor=(x, 0.0), local_axis_a=(1.0, 0.0)))
        world.spawn(RevoluteJoint(cart, pole, anchor=(x, 0.0)))

    def act(self, world: World, action: Any) -> None:
        push = FORCE if int(action) == 1 else -FORCE
        world.resource(Physics).apply_force(self.cart, (push, 0.0))

    def observe(self, world: World) -> np.ndarray:
        cart = world.get(self.cart, Transform)
        cart_rb = world.get(self.cart, RigidBody)
        pole = world.get(self.pole, Transform)
        pole_rb = world.get(self.pole, RigidBody)
        return np.array([cart.x, cart_rb.velocity[0], -pole.angle, -pole_rb.angular_velocity],
                        dtype=np.float32)

    def reward(self, world: World, obs: Any, action: Any) -> float:
        return 1.0

    def terminated(self, world: World, obs: Any) -> bool:
        return bool(abs(float(obs[0])) > X_LIMIT or abs(float(obs[2])) > THETA_LIMIT)


def heuristic(obs: np.ndarray) -> int:
    """Push under the pole: a linear policy on lean, lean rate, and cart drift.

    The pole falls towards where it leans, so the cart moves under it; the small
    cart terms make the pole lean back towards the centre when the cart drifts away.
    """
    x, x_dot, theta, theta_dot = (float(v) for v in obs)
    return 1 if theta + 0.5 * theta_dot + 0.03 * x + 0.1 * x_dot > 0.0 else 0
