"""Point on a line: keep body B's anchor on the line through A's anchor along A's axis.

Prismatic and wheel joints need this constraint. pymunk's ``GrooveJoint`` looks
like it, but it solves the anchor as a 2-D point, with the full 2x2 effective
mass matrix, and then projects the impulse onto the groove normal. That is right
only while the matrix is isotropic, that is, while the anchor sits near the
centre of a body that cannot turn easily. Put the line metres away from the
centre of a light body (a slider created between bodies metres apart) and the
matrix is far from isotropic. The free sliding velocity then leaks into the
normal impulse through the off-diagonal terms, and pymunk's iterations amplify
it. Together with a contact, this flung a 0.46 kg body 10^7 m within three steps,
and NaN followed.

Box2D solves the perpendicular direction as one scalar row, with effective mass
``1 / (mA⁻¹ + mB⁻¹ + IA⁻¹·sA² + IB⁻¹·sB²)``. A pymunk ``PinJoint`` is exactly
such a row, solved inside pymunk's iterations. Pin B's anchor to a point
``RADIUS`` out along the line's normal on A, at distance ``RADIUS``: the circle
it keeps B on is tangent to the line at the foot of that normal. The foot is
moved to B's current place on the line after every step (:meth:`Line.follow`),
so over one step's travel (at most 2 m) the circle departs from the line by less
than (2 m)²/(2·RADIUS) = 0.2 mm.

The pin carries no velocity bias: like Box2D, the drift off the line is removed
by a position pass after the step (:meth:`Line.project`).
"""

from __future__ import annotations

import pymunk

from kge.physics.joints.mechanics import cog_world, cross
from kge.physics.joints.positions import MAX_CORRECTION, SETTLED, project_rows
from kge.physics.joints.rows import Row

Vec2 = tuple[float, float]

#: distance of the pin's far end from the line, m
RADIUS = 1e4


class Line:
    """The geometry of "B's anchor on A's line", and the pymunk row that holds it."""

    def __init__(self, a: pymunk.Body, b: pymunk.Body) -> None:
        self.a, self.b = a, b
        self.anchor_a = pymunk.Vec2d(0.0, 0.0)
        self.anchor_b = pymunk.Vec2d(0.0, 0.0)
        self.axis = pymunk.Vec2d(1.0, 0.0)
        #: the pymunk row, once :meth:`make_pin` built it (bodies that pymunk accepts)
        self.pin: pymunk.PinJoint | None = None

    def make_pin(self) -> pymunk.PinJoint:
        self.pin = pymunk.PinJoint(self.a, self.b, (0.0, 0.0), (0.0, 0.0))
        self.pin.distance = RADIUS
        self.follow()
        return self.pin

    def place(self, anchor_a: Vec2, axis: Vec2, anchor_b: Vec2) -> None:
        """Set the line (A's local anchor and unit axis) and B's local anchor."""
        self.anchor_a = pymunk.Vec2d(*anchor_a)
        self.axis = pymunk.Vec2d(*axis)
        self.anchor_b = pymunk.Vec2d(*anchor_b)
        self.follow()

    def offset(self, axis: pymunk.Vec2d) -> float:
        """B's anchor from A's, along ``axis`` (a unit vector in A's frame), m."""
        pa = self.a.local_to_world(self.anchor_a)
        pb = self.b.local_to_world(self.anchor_b)
        return float((pb - pa).dot(axis.rotated(self.a.angle)))

    def translation(self) -> float:
        """B's anchor along the line, from A's anchor, m."""
        return self.offset(self.axis)

    def rows(self, scale: float, axis: pymunk.Vec2d | None = None) -> list[Row]:
        """d(offset along ``axis``)/dt (default: the line's own axis), A's turning included.

        Along the normal this is Box2D's prismatic row ``(-n, -(d + rA)×n, n, rB×n)``.
        """
        pa = self.a.local_to_world(self.anchor_a)
        pb = self.b.local_to_world(self.anchor_b)
        u = (self.axis if axis is None else axis).rotated(self.a.angle)
        d = pb - pa
        rb = pb - cog_world(self.b)
        ra = pa - cog_world(self.a)
        return [
            (self.b, scale * u.x, scale * u.y, scale * cross(rb.x, rb.y, u.x, u.y)),
            (self.a, -scale * u.x, -scale * u.y, -scale * cross(ra.x + d.x, ra.y + d.y, u.x, u.y)),
        ]

    def follow(self, translation: float | None = None) -> None:
        """Put the tangent point of the pin's circle where B's anchor is now.

        ``translation``: B's place on the line if the caller has just measured it.
        """
        if self.pin is not None:
            t = self.translation() if translation is None else translation
            foot = self.anchor_a + self.axis * t
            self.pin.anchor_a = foot + self.axis.perpendicular() * RADIUS
            self.pin.anchor_b = self.anchor_b

    def project(self) -> float:
        """Box2D's position pass: move B's anchor back onto the line (0.2 m per step at most).

        Returns the distance found off the line, m.
        """
        normal = self.axis.perpendicular()
        error = self.offset(normal)
        if abs(error) > SETTLED:
            project_rows(self.rows(1.0, normal), error, MAX_CORRECTION)
        return abs(error)
