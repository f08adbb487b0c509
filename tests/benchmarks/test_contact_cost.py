"""The new-contact cost row: measured on a running rain scene, reported as a target."""

from __future__ import annotations

from benchmarks import contact_cost
from benchmarks.run import targets


def test_the_contact_cost_is_measured_per_call_and_reported_as_a_target() -> None:
    c = contact_cost.measure(quick=True)
    assert c["contact_begins_per_frame"] > 10 and c["contact_ends_per_frame"] > 0
    assert c["contact_begin_us"] > 0.0 and c["contact_end_us"] > 0.0
    assert c["contact_us"] == c["contact_begin_us"] + c["contact_end_us"]
    rows = {t["target"]: t for t in targets([], {}, {}, costs=c)}
    row = rows["new-contact bookkeeping, begin + end, rain-1000"]
    assert row["value"] == c["contact_us"] and row["goal"] == 3.0 and row["at_most"]
    assert row["met"] == (c["contact_us"] <= 3.0)
