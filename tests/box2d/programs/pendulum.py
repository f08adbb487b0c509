"""A revolute pendulum: a 0.25 m ball on a 2 m arm, released horizontal; its period."""

import math

import Box2D as b2

world = b2.b2World(gravity=(0, -10))
ground = world.CreateStaticBody(position=(0, 10))
bob = world.CreateDynamicBody(position=(2, 10))
bob.CreateCircleFixture(radius=0.25, density=20)
joint = world.CreateRevoluteJoint(bodyA=ground, bodyB=bob, anchor=(0, 10))
crossings = []
prev = bob.position.x
dt = 1.0 / 120
for i in range(1, 1200):
    world.Step(dt, 8, 3)
    x = bob.position.x
    if prev > 0 >= x:  # swinging right to left through the bottom
        crossings.append(i * dt)
    prev = x
period = crossings[1] - crossings[0]
result = {"period": period, "arm": math.hypot(bob.position.x, bob.position.y - 10),
          "joint_angle_at_end": abs(joint.angle) < 4.0}
result["joint_angle_at_end"] = float(result["joint_angle_at_end"])
