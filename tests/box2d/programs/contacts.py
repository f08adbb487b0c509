"""A contact listener: a bouncing ball's begin/end counts and the first touch."""

import Box2D as b2


class Listener(b2.b2ContactListener):
    def __init__(self):
        b2.b2ContactListener.__init__(self)
        self.begins = []
        self.ends = 0
        self.step = 0
        self.same_objects = True

    def BeginContact(self, contact):
        bodies = {contact.fixtureA.body, contact.fixtureB.body}
        self.same_objects = self.same_objects and ball in bodies and ground in bodies
        self.begins.append(self.step)

    def EndContact(self, contact):
        self.ends += 1


listener = Listener()
world = b2.b2World(gravity=(0, -10), contactListener=listener)
ground = world.CreateStaticBody(shapes=b2.b2EdgeShape(vertices=[(-10, 0), (10, 0)]))
ball = world.CreateDynamicBody(position=(0, 5))
ball.CreateCircleFixture(radius=0.5, density=1, restitution=0.5)
for i in range(240):
    listener.step = i
    world.Step(1.0 / 60, 8, 3)
result = {"first_touch": float(listener.begins[0]), "bounces": float(len(listener.begins)),
          "ends": float(listener.ends), "same_objects": float(listener.same_objects),
          "rest_y": ball.position.y, "touching_now": float(len(world.contacts))}
