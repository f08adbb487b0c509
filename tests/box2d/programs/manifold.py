"""A box resting on a ground box: its contact's manifold (type, normal, points).

(pybox2d 2.3.10's ``contact.worldManifold.normal`` reads freed memory, so the
comparison uses the local manifold, which both give correctly.)
"""

import Box2D as b2

world = b2.b2World(gravity=(0, -10))
ground = world.CreateStaticBody(shapes=b2.b2PolygonShape(box=(10, 1)))
box = world.CreateDynamicBody(position=(0, 1.6), angle=0.0)
box.CreatePolygonFixture(box=(1, 0.5), density=1, friction=0.6)
for _ in range(120):
    world.Step(1.0 / 60, 8, 3)
contact = world.contacts[0]
m = contact.manifold
local = sorted(tuple(p.localPoint) for p in m.points)
result = {"touching": float(contact.touching), "points": float(m.pointCount),
          "ground_is_a": float(contact.fixtureA.body == ground),
          "nx": m.localNormal[0], "ny": m.localNormal[1],
          "x0": local[0][0], "y0": local[0][1], "x1": local[1][0], "y1": local[1][1],
          "box_y": box.position.y}
