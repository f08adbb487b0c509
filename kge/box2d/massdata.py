"""``b2MassData``: a body's or fixture's mass, centre of mass and inertia (Box2D's)."""

from __future__ import annotations

from typing import Any

from kge.box2d.vec import b2Vec2


class b2MassData:
    """Mass (kg), centre of mass (body-local) and rotational inertia about the body origin."""

    def __init__(self, mass: float = 0.0, center: Any = (0.0, 0.0), I: float = 0.0) -> None:  # noqa: E741
        self.mass = float(mass)
        self.center = b2Vec2(center)
        self.I = float(I)

    def __repr__(self) -> str:
        return f"b2MassData(mass={self.mass:g}, center={self.center!r}, I={self.I:g})"
