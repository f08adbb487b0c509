# mypy: ignore-errors
"""Ray casts against a static scene: the closest hit, every hit, and a filtered cast."""

import Box2D as b2


class Closest(b2.b2RayCastCallback):
    def __init__(self, skip=None):
        b2.b2RayCastCallback.__init__(self)
        self.skip = skip
        self.hit = None

    def ReportFixture(self, fixture, point, normal, fraction):
        if self.skip is not None and fixture.userData == self.skip:
            return -1
        self.hit = (fixture.userData, tuple(point), tuple(normal), fraction)
        return fraction


class Every(b2.b2RayCastCallback):
    def __init__(self):
        b2.b2RayCastCallback.__init__(self)
        self.names = []

    def ReportFixture(self, fixture, point, normal, fraction):
        self.names.append(fixture.userData)
        return 1.0


world = b2.b2World(gravity=(0, -10))
ground = world.CreateStaticBody()
ground.CreatePolygonFixture(box=(1, 1, (5, 0), 0), userData="box")
ground.CreateCircleFixture(radius=1, pos=(10, 0), userData="circle")
ground.CreateEdgeFixture(vertices=[(15, -2), (15, 2)], userData="edge")

closest = Closest()
world.RayCast(closest, (0, 0), (20, 0))
skipping = Closest(skip="box")
world.RayCast(skipping, (0, 0.5), (20, 0.5))
every = Every()
world.RayCast(every, (0, 0.2), (20, 0.2))
name, point, normal, fraction = closest.hit
result = {
    "closest_is_box": float(name == "box"), "x": point[0], "nx": normal[0], "fraction": fraction,
    "skip_is_circle": float(skipping.hit[0] == "circle"), "skip_x": skipping.hit[1][0],
    "every_count": float(len(every.names)),
}
