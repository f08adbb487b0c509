"""The collision functions: b2Distance between two placed shapes, b2TimeOfImpact of two sweeps."""

import Box2D as b2

box = b2.b2PolygonShape(box=(1, 1))
small = b2.b2PolygonShape(box=(0.5, 0.5))
ball = b2.b2CircleShape(radius=0.5)
here = b2.b2Transform()
here.SetIdentity()
there = b2.b2Transform()
there.Set((4, 0), 0.3)

d = b2.b2Distance(shapeA=box, shapeB=small, transformA=here, transformB=there)
d_ball = b2.b2Distance(shapeA=box, shapeB=ball, transformA=here, transformB=there, useRadii=False)

still = b2.b2Sweep(a=0, a0=0, c=(0, 0), c0=(0, 0), localCenter=(0, 0))
moving = b2.b2Sweep(a=0.5, a0=0, c=(-4, 0.2), c0=(6, 0), localCenter=(0, 0))
state, t = b2.b2TimeOfImpact(shapeA=box, shapeB=small, sweepA=still, sweepB=moving, tMax=1.0)
missing = b2.b2Sweep(a=0, a0=0, c=(6, 5), c0=(-6, 5), localCenter=(0, 0))
state2, t2 = b2.b2TimeOfImpact(shapeA=box, shapeB=ball, sweepA=still, sweepB=missing, tMax=1.0)

result = {"distance": d.distance, "ax": d.pointA[0], "ay": d.pointA[1], "bx": d.pointB[0],
          "ball_distance": d_ball.distance, "toi_state": float(state), "toi": t,
          "miss_state": float(state2), "miss_t": t2}
