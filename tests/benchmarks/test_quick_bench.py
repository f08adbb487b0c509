"""The benchmark suite runs end to end at its smallest sizes, so it cannot rot.

Nothing here looks at a timing: the suite measures, the tests only check that
every scene still builds the same geometry on every engine and reports its
figures. (Timings are never asserted; see benchmarks/harness.py.)
"""

from __future__ import annotations

import json
import math

import pytest

from benchmarks import run
from benchmarks.engines import PymunkRunner, box2d_available, spec_of
from benchmarks.scenes import RawChurn, joint_quality, scenes
from kge.testbed.registry import get_sample

ENGINES = {"kge", "pymunk", "pymunk+read"} | (
    {"box2d", "box2d+sync"} if box2d_available() is None else set()
)


@pytest.fixture(scope="module")
def report(tmp_path_factory: pytest.TempPathFactory) -> dict:
    out = tmp_path_factory.mktemp("bench")
    assert run.main(["--quick", "--breakdown", "--out", str(out)]) == 0
    data = json.loads((out / "bench.json").read_text())
    data["_md"] = (out / "bench.md").read_text()
    data["_png"] = (out / "bench.png").read_bytes()
    return data


def test_every_scene_runs_on_every_engine(report: dict) -> None:
    table = {s.name: s for s in scenes(quick=True)}
    names = set(table)
    assert len(names) >= 11
    seen: dict[str, set[str]] = {}
    for r in report["results"]:
        seen.setdefault(r["scene"], set()).add(r["engine"])
        assert r["frames"] > 0 and r["median_ms"] > 0 and r["p95_ms"] >= r["median_ms"]
        assert r["quality"], f"{r['scene']} on {r['engine']} reports no quality figure"
    assert set(seen) == names
    for scene, engines in seen.items():
        # Gymnasium scenes (unit "steps") have no raw-pymunk version: kge.box2d vs pybox2d
        expected = ENGINES if table[scene].unit != "steps" else ENGINES & {"kge", "box2d"}
        assert engines == expected, f"{scene} ran on {engines}"


def test_engines_agree_on_quality(report: dict) -> None:
    """Same geometry everywhere: nothing escapes, joints hold, populations match."""
    for r in report["results"]:
        q = r["quality"]
        assert q.get("escaped", 0.0) == 0.0, r
        assert q.get("joint_gap_m", 0.0) < 0.1, r
    for scene in ("churn", "spawn", "sparse"):
        counts = {r["engine"]: r["quality"]["bodies"] for r in report["results"]
                  if r["scene"] == scene}
        assert len(set(counts.values())) == 1, (scene, counts)


def test_report_has_breakdown_targets_chart_and_markdown(report: dict) -> None:
    phases = {"sync-in", "step", "sync-out", "events", "other", "total"}
    assert report["breakdown"] and all(phases <= set(row) for row in report["breakdown"])
    assert {t["target"] for t in report["targets"]} >= {
        "kge / raw pymunk, pyramid-40", "spawning 1,000 bodies in one frame"}
    assert report["_png"][:8] == b"\x89PNG\r\n\x1a\n"
    assert "| scene | size |" in report["_md"] and report["machine"] in report["_md"]
    assert report["render"] or any("render" in s for s in report["skipped"])
    assert {r["row"] for r in report["collision"]} == {"distance", "collide", "tree query"}


def test_report_has_per_body_costs_and_their_targets(report: dict) -> None:
    """Sync-out per moved body, despawn and memory per body are measured beside raw pymunk."""
    c = report["costs"]
    assert 0 < c["sync_out_us"] < 1000 and c["sync_in_ms"] >= 0
    assert c["despawn_kge_ms"] > 0 and c["despawn_pymunk_ms"] > 0
    assert c["bytes_per_body_kge"] > 0 and c["bytes_per_body_pymunk"] > 0
    assert c["churn_kge_200_ms"] > 0 and c["churn_raw_2000_ms"] > 0
    assert "in a world of 2,000 bodies" in report["_md"]
    names = {t["target"] for t in report["targets"]}
    assert {"kge / raw pymunk, chain-200", "kge / raw pymunk, dense-pile-6000",
            "kge / raw pymunk, joint-grid-100", "kge / raw pymunk, sparse-20000",
            "spawning 1,000 bodies in one frame, kge / raw pymunk",
            "memory per body, kge / raw pymunk (fresh processes)",
            "sync-out per moved body (sparse field)",
            "spawn+despawn of 7 entities, kge in 2,000 bodies / in 200"} <= names
    sync = next(t for t in report["targets"] if t["target"].startswith("sync-out"))
    assert sync["value"] == c["sync_out_us"] and sync["met"] is not None
    memory = next(t for t in report["targets"] if t["target"].startswith("memory per body"))
    assert memory["value"] == c["bytes_per_body_kge"] / c["bytes_per_body_pymunk"]
    assert "Per-body costs" in report["_md"]


def test_ground_pinned_chain_mirrors_on_raw_pymunk() -> None:
    spec = spec_of(get_sample("chains"), count=40, links=40)
    assert sum(j.body_a is None for j in spec.joints) == 1
    runner = PymunkRunner(spec)
    first = runner.poses()
    for _ in range(60):
        runner.step()
    last = runner.poses()
    assert joint_quality(spec, first, last)["joint_gap_m"] < 0.05
    tip = max(last, key=lambda e: first[e][0])
    assert last[tip][1] < first[tip][1] - 1.0, "the chain should swing down under gravity"
    assert all(math.isfinite(v) for p in last.values() for v in p)


def test_raw_churn_keeps_the_population() -> None:
    spec = spec_of(get_sample("churn"), count=40)
    churn = RawChurn(PymunkRunner(spec), spec, 40)
    for _ in range(23):
        churn.step()
    assert len(churn.poses()) == 40
    assert churn.spawned == 4 * 4  # four periods of 5 steps, a tenth (4) each


def test_gymnasium_lander_throughput_is_reported(report: dict) -> None:
    from benchmarks.rl import box2d_lander_missing

    seen = {(r["engine"], r["mode"], r["n"]) for r in report["rl"]}
    want = {("kge", "single", 1), ("kge", "batched", 1), ("kge", "batched", 4),
            ("kge", "sync", 4), ("pymunk", "floor", 4)}
    if box2d_lander_missing() is None:
        want |= {("box2d", "single", 1), ("box2d", "sync", 4)}
    assert want <= seen
    assert all(r["steps_per_s"] > 0 for r in report["rl"])
    assert "Gymnasium LunarLander, env steps per second" in report["_md"]
    assert "floor: raw pymunk, no kge" in report["_md"] and "load average" in report["_md"]
    assert any(t["target"].startswith("LunarLander steps/s") for t in report["targets"])


def test_the_report_has_a_ratio_column_per_peer_and_no_extrapolated_sizes(report: dict) -> None:
    header = next(line for line in report["_md"].splitlines() if line.startswith("| scene | size"))
    for peer in ("pymunk", "pymunk+read", "box2d", "box2d+sync"):
        if peer in ENGINES:
            assert f"kge/{peer}" in header
    for per in report["largest_fitting"].values():
        for label in per.values():  # a size between two measured ones, or a bound
            assert label[0] in "<>-" or label.replace(",", "").isdigit(), label
    assert report["order_seed"] == 0


def test_pymunk_read_reads_every_body_pose_in_bulk() -> None:
    spec = spec_of(get_sample("pyramid"), rows=5)
    runner = PymunkRunner(spec, read=True)
    for _ in range(3):
        runner.step()
    poses = runner.poses_out
    assert poses.shape == (len(runner.space.bodies), 3)
    expected = sorted((b.position.x, b.position.y, b.angle) for b in runner.space.bodies)
    assert sorted(map(tuple, poses.tolist())) == expected


@pytest.mark.skipif(box2d_available() is not None, reason="pybox2d is not installed")
def test_box2d_step_alone_copies_nothing_and_sync_copies_every_awake_pose() -> None:
    from benchmarks.engines import Box2DRunner

    spec = spec_of(get_sample("pyramid"), rows=5)
    alone, synced = Box2DRunner(spec), Box2DRunner(spec, sync=True)
    start = {e: list(p) for e, p in alone.mirror.items()}
    for _ in range(30):
        alone.step()
        synced.step()
    assert alone.mirror == start
    for e, pose in synced.mirror.items():
        body = synced.bodies[e]
        assert pose == [body.position.x, body.position.y, body.angle]
    assert synced.mirror != start


def test_measure_shuffles_the_engine_order_of_every_block() -> None:
    from benchmarks.harness import Factory, Scene, measure

    calls: list[str] = []

    class Fake:
        def __init__(self, name: str) -> None:
            self.name = name

        def step(self) -> None:
            calls.append(self.name)

        def quality(self) -> dict[str, float]:
            return {"q": 1.0}

        def close(self) -> None:
            pass

    def factory(name: str) -> Factory:
        return lambda size: Fake(name)

    engines = {n: factory(n) for n in "abcd"}
    scene = Scene("fake", (1,), engines, warmup=0, frames=40)
    orders = set()
    for seed in range(3):
        calls.clear()
        measure(scene, 1, "abcd", blocks=40, seed=seed)
        blocks = [tuple(calls[i : i + 4]) for i in range(0, len(calls), 4)]
        assert all(sorted(b) == list("abcd") for b in blocks)
        orders |= set(blocks)
    assert len(orders) > 6  # not one fixed order (24 are possible)
