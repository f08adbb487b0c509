"""The manual's hello world: a 1x1 m box dropped onto a ground box, 60 steps of 1/60 s."""

import Box2D as b2

world = b2.b2World(gravity=(0, -10), doSleep=True)
ground = world.CreateStaticBody(position=(0, -10), shapes=b2.b2PolygonShape(box=(50, 10)))
body = world.CreateDynamicBody(position=(0, 4), angle=0)
body.CreatePolygonFixture(box=(1, 1), density=1, friction=0.3)
for _ in range(60):
    world.Step(1.0 / 60, 6, 2)
result = {"y": body.position.y, "x": body.position.x, "angle": body.angle,
          "mass": body.mass, "awake": float(body.awake)}
