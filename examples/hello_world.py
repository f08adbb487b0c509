"""The pybox2d manual's Hello World, as kge components.

A static ground box (half extents 50 x 10, centred at (0, -10), so its top is
y = 0) and a dynamic 2 x 2 box dropped from y = 4. Sixty steps of 1/60 s print
the box's position and angle; it lands and comes to rest at y ~ 1.015 (Box2D
keeps a 0.01 m polygon skin).

Run it: ``python examples/hello_world.py`` (or ``make demo`` before the testbed).
"""

from __future__ import annotations

import kge_required  # noqa: F401  (first: names the Python to use when kge is missing)

import kge
from kge import App, BodyType, Box, Collider, Name, RigidBody, Transform, World


def hello_world(world: World) -> None:
    # Ground: a collider with no RigidBody sits on an implicit static body.
    world.spawn(Transform(0.0, -10.0), Collider(Box(50.0, 10.0)))
    # The falling box.
    world.spawn(
        Transform(0.0, 4.0),
        RigidBody(type=BodyType.DYNAMIC),
        Collider(Box(1.0, 1.0), density=1.0, friction=0.3),
        Name("box"),
    )


def main(steps: int = 60) -> Transform:
    app = App(hello_world, headless=True)
    box = next(e for e, (n,) in app.world.query(Name) if n.value == "box")
    t = app.world.get(box, Transform)
    for i in range(steps):
        app.step()
        print(f"step {i + 1:3d}: x={t.x:6.3f} y={t.y:6.3f} angle={t.angle:6.3f}")
    app.step(120)
    print(f"after {steps + 120} steps the box rests at y={t.y:.3f} (Box2D: 1.015)")
    return t


if __name__ == "__main__":
    print(f"kge {kge.__version__}: the pybox2d manual's hello world")
    main()
