"""The testbed: Box2D-style sample scenes, one registry reused by the testbed
app, the tests and the benchmarks (as in Box2D v3's samples).

Importing this package imports every sample module (:mod:`kge.testbed.samples`),
which registers them; the registry itself imports none of them.
"""

from kge.testbed import samples as _samples  # noqa: F401  (fills the registry)
from kge.testbed.registry import Sample, all_samples, get_sample, sample

__all__ = ["Sample", "all_samples", "get_sample", "sample"]
