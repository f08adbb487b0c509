"""The testbed: Box2D-style sample scenes, one registry reused by the testbed
app, the tests and the benchmarks (as in Box2D v3's samples)."""

from kge.testbed.registry import Sample, all_samples, get_sample, sample

__all__ = ["Sample", "all_samples", "get_sample", "sample"]
