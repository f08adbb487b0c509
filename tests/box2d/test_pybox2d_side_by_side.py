"""pybox2d's one-sided platform and breakable body examples, run unmodified on pybox2d and
on kge.box2d in the same test (the same framework stand-in, the same frames), must end
the same way."""

from __future__ import annotations

import contextlib
import importlib.util
import io
from typing import Any

import pytest

import kge.box2d as b2
from kge.box2d.testbed import examples
from kge.box2d.testbed.headless import HeadlessBackend

pytestmark = pytest.mark.skipif(
    importlib.util.find_spec("Box2D") is None or examples.examples_dir() is None,
    reason="pybox2d (box2d 2.3.10, the dev extra) is not installed")


class Traced(HeadlessBackend):
    """Headless frames, with ``probe(test)`` recorded after each."""

    def __init__(self, frames: int, probe: Any) -> None:
        super().__init__(frames)
        self.probe = probe
        self.trace: list[Any] = []

    def run(self, test: Any) -> None:
        self.test = test
        for _ in range(self.frames):
            test.Frame()
            self.trace.append(self.probe(test))
            self.frames_run += 1


def _both(name: str, frames: int, probe: Any) -> dict[str, Traced]:
    out = {}
    for engine in examples.ENGINES:
        backend = Traced(frames, probe)
        with contextlib.redirect_stdout(io.StringIO()):
            examples.run(name, backend, engine)
        out[engine] = backend
    return out


def _pieces(test: Any) -> list[tuple[float, float]]:
    return sorted((b.position.x, b.position.y) for b in test.world.bodies if b.type == 2)


def test_breakable_body_splits_on_impact_and_its_pieces_stop_where_pybox2d_s_do() -> None:
    runs = _both("breakable", 240, lambda t: (t.broke, _pieces(t)))
    broke_at = {e: next(i for i, (broke, _) in enumerate(r.trace) if broke)
                for e, r in runs.items()}
    # the 27.8 m/s impact breaks it on landing (pybox2d: frame 166; kge.box2d 167: its
    # free fall lags Box2D's by one frame over 40 m)
    assert abs(broke_at["kge"] - broke_at["pybox2d"]) <= 1
    kge_end, ref_end = runs["kge"].trace[-1][1], runs["pybox2d"].trace[-1][1]
    assert len(kge_end) == len(ref_end) == 2
    for (kx, ky), (rx, ry) in zip(kge_end, ref_end, strict=True):
        # pybox2d's pieces rest at x = 1.1 and 2.04 m; they were thrown 3-5 m when
        # kge.box2d did not move the centre's velocity with the centre (ResetMassData)
        assert abs(kx - rx) < 0.4 and abs(ky - ry) < 0.05


def _fast_impacts_stop_at_the_surface() -> bool:
    """Does kge's physics stop a 50 m/s circle at a box's surface, as Box2D does? (Not
    yet: it goes 17 cm in before it is pushed out; being fixed in kge's physics.)"""
    world = b2.b2World(gravity=(0, -10))
    world.CreateStaticBody(position=(0, -1), shapes=b2.b2PolygonShape(box=(5, 1)))
    ball = world.CreateDynamicBody(position=(0, 2), linearVelocity=(0, -50))
    ball.CreateCircleFixture(radius=0.5, density=1)
    lowest = 1.0
    for _ in range(30):
        world.Step(1 / 60, 8, 3)
        lowest = min(lowest, ball.position.y - 0.5)
    return lowest > -2.0 * b2.b2_polygonRadius


@pytest.mark.xfail(not _fast_impacts_stop_at_the_surface(), strict=True, reason=(
    "kge's physics stops a 50 m/s circle inside the platform, so the example's PreSolve "
    "check (bottom above the top - 3 linear slops) turns the contact off and the "
    "character falls through"))
def test_one_sided_platform_holds_the_character_as_pybox2d_does() -> None:
    runs = _both("one_sided_platform", 180,
                 lambda t: (t.character.body.position.y, t.character.body.awake))
    ref = runs["pybox2d"].trace
    assert ref[-1][0] == pytest.approx(11.005, abs=0.01) and not ref[-1][1]  # landed, asleep
    for (ky, _), (ry, _) in zip(runs["kge"].trace, ref, strict=True):
        assert ky == pytest.approx(ry, abs=0.02)
    assert not runs["kge"].trace[-1][1]
