"""Stacking samples: the solver's hardest everyday job (Box2D testbed "Stacking")."""

from __future__ import annotations

from kge.components import Transform
from kge.testbed.registry import sample
from kge.testbed.samples.build import ball, box, ground, named, static_box
from kge.world import World


@sample("Stacking", "Vertical Stack", help="Ten boxes with 2 cm gaps; they must not drift.")
def vertical_stack(world: World, count: int = 10, columns: int = 1) -> None:
    static_box(world, 0.0, -10.0, 50.0, 10.0, name="ground")
    for c in range(columns):
        x = (c - (columns - 1) / 2) * 3.0
        for i in range(count):
            box(world, x, 0.5 + i * 1.02, density=1.0, friction=0.3, name="stack")


@vertical_stack.claim
def _stack_stands(app) -> None:  # type: ignore[no-untyped-def]
    xs = [app.world.get(e, Transform).x for e in named(app.world, "stack")]
    assert max(abs(x) for x in xs) < 0.01, f"stack drifted: {xs}"


@sample("Stacking", "Pyramid", help="A pyramid of boxes (10 rows by default) that must stand.")
def pyramid(world: World, rows: int = 10, density: float = 5.0, friction: float = 0.2) -> None:
    static_box(world, 0.0, -10.0, 50.0, 10.0, name="ground")
    x0, y0 = -0.5625 * (rows - 1), 0.75
    for i in range(rows):
        for j in range(rows - i):
            box(world, x0 + 0.5625 * i + 1.125 * j, y0 + 1.25 * i,
                density=density, friction=friction, name=f"row{i}")


@pyramid.claim
def _pyramid_stands(app) -> None:  # type: ignore[no-untyped-def]
    top = named(app.world, "row9")
    t = app.world.get(top[0], Transform)
    assert abs(t.x) < 0.05 and 9.45 < t.y < 9.75, f"top box at {t}"


@sample("Stacking", "Mass Ratio", help="Heavy boxes (10x and 100x) on light ones: no sinking.")
def mass_ratio(world: World) -> None:
    static_box(world, 0.0, -10.0, 50.0, 10.0, name="ground")
    for x, heavy in ((-3.0, 10.0), (0.0, 100.0)):
        box(world, x, 0.52, density=1.0, name="light")
        box(world, x, 1.54, density=heavy, name="heavy")
    for i, d in enumerate((1.0, 10.0, 1.0, 10.0, 1.0)):
        box(world, 3.0, 0.52 + 1.02 * i, density=d, name="alternating")


@mass_ratio.claim
def _no_sinking(app) -> None:  # type: ignore[no-untyped-def]
    for e in named(app.world, "light"):
        assert app.world.get(e, Transform).y > 0.5 - 0.02
    for e in named(app.world, "heavy"):
        assert app.world.get(e, Transform).y > 1.5 - 0.04


@sample("Stacking", "Dominoes", help="A row of thin dominoes knocked over by a ball.")
def dominoes(world: World, count: int = 12) -> None:
    ground(world)
    for i in range(count):
        box(world, -6.0 + i * 1.0, 1.0, 0.1, 1.0, density=10.0, friction=0.1, name="domino")
    ball(world, -8.0, 1.0, 0.25, density=10.0, velocity=(6.0, 0.0), name="striker")


@dominoes.claim
def _dominoes_fall(app) -> None:  # type: ignore[no-untyped-def]
    last = named(app.world, "domino")[-1]
    assert abs(app.world.get(last, Transform).angle) > 0.5, "the last domino is still standing"


@sample("Stacking", "Confined", help="Circles packed in a closed box, settling without escaping.")
def confined(world: World, columns: int = 10, rows: int = 10) -> None:
    static_box(world, 0.0, -0.5, 10.5, 0.5, name="wall")
    static_box(world, 0.0, 20.5, 10.5, 0.5, name="wall")
    static_box(world, -10.5, 10.0, 0.5, 11.0, name="wall")
    static_box(world, 10.5, 10.0, 0.5, 11.0, name="wall")
    for i in range(columns):
        for j in range(rows):
            ball(world, -9.0 + 2.0 * i, 1.0 + 2.0 * j, 0.5, friction=0.1, name="circle",
                 velocity=((i % 3) - 1.0, (j % 3) - 1.0))


@confined.claim
def _confined_stays_inside(app) -> None:  # type: ignore[no-untyped-def]
    for e in named(app.world, "circle"):
        t = app.world.get(e, Transform)
        assert -10.0 < t.x < 10.0 and 0.0 < t.y < 20.0, f"circle escaped to {t}"
