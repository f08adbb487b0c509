"""PreSolve with b2GetPointStates: a box lands; its points are added once, then persist."""

import Box2D as b2


class States(b2.b2ContactListener):
    def __init__(self):
        b2.b2ContactListener.__init__(self)
        self.seen = []

    def PreSolve(self, contact, oldManifold):
        self.seen.append(b2.b2GetPointStates(oldManifold, contact.manifold))


listener = States()
world = b2.b2World(gravity=(0, -10), contactListener=listener)
world.CreateStaticBody(shapes=b2.b2PolygonShape(box=(10, 1)))
box = world.CreateDynamicBody(position=(0, 1.6))
box.CreatePolygonFixture(box=(1, 0.5), density=1)
for _ in range(60):
    world.Step(1.0 / 60, 8, 3)
first_old, first_new = listener.seen[0]
last_old, last_new = listener.seen[-1]
adds = sum(s == b2.b2_addState for _, new in listener.seen for s in new)
result = {"first_new_added": float(first_new == (b2.b2_addState, b2.b2_addState)),
          "first_old_null": float(first_old == (b2.b2_nullState, b2.b2_nullState)),
          "last_persist": float(last_new == (b2.b2_persistState, b2.b2_persistState)
                                and last_old == (b2.b2_persistState, b2.b2_persistState)),
          "adds": float(adds)}
