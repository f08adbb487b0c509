"""Every registered sample runs headless for 300 steps and keeps its physical claim."""

import math

import pytest

from kge import App, Transform
from kge.components.rigidbody import RigidBody
from kge.testbed import all_samples

SAMPLES = all_samples()


def test_registry_covers_the_manual() -> None:
    assert len(SAMPLES) >= 25
    slugs = [s.slug for s in SAMPLES]
    assert len(set(slugs)) == len(slugs)
    for s in SAMPLES:
        assert s.help, f"{s.slug} has no help text"


@pytest.mark.parametrize("sample", SAMPLES, ids=[s.slug for s in SAMPLES])
def test_sample_runs_and_keeps_its_claim(sample) -> None:
    app = App(sample.setup, headless=True)
    app.step(300)
    world = app.world
    for e, (t, rb) in world.query(Transform, RigidBody):
        assert all(map(math.isfinite, (t.x, t.y, t.angle))), f"entity {e} has NaN pose {t}"
        assert all(map(math.isfinite, (*rb.velocity, rb.angular_velocity)))
        assert t.y > -1000.0, f"entity {e} fell out of the world: {t}"
    for claim in sample.claims:
        claim(app)
    app.close()
