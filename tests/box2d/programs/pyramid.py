"""A 10-row pyramid of 0.5 m boxes on the ground, 4 s at 60 Hz with 8/3 iterations."""

import Box2D as b2

world = b2.b2World(gravity=(0, -10))
world.CreateStaticBody(shapes=b2.b2EdgeShape(vertices=[(-40, 0), (40, 0)]))
box = b2.b2FixtureDef(shape=b2.b2PolygonShape(box=(0.5, 0.5)), density=5, friction=0.6)
bodies = []
rows = 10
for row in range(rows):
    for i in range(rows - row):
        x = -0.5 * (rows - row - 1) * 1.125 + i * 1.125
        bodies.append(world.CreateDynamicBody(position=(x, 0.5 + row * 1.0), fixtures=box))
top = bodies[-1]
for _ in range(240):
    world.Step(1.0 / 60, 8, 3)
result = {"top_y": top.position.y, "top_x": top.position.x,
          "max_drift": max(abs(b.angle) for b in bodies),
          "asleep": float(sum(not b.awake for b in bodies)) / len(bodies)}
