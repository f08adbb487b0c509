"""A/B timing: the same testbed scene on two kge checkouts, interleaved in one run.

A change to kge's physics is judged by the frame time of the same scene before
and after it. Two copies of kge cannot share a process, so each checkout runs in
a worker process of its own that builds the scene once and then steps frames on
request; the parent asks them for blocks of frames in turn (A, B, A, B, ...), so
background load on a shared machine hits both alike, and reports the median
frame time of each and their ratio, the way ``kge bench`` compares engines. It
reports each frame's CPU time too (``time.process_time`` of the worker), which a
busy machine disturbs far less than the wall clock: on a loaded machine, compare
the CPU ratio.

    python benchmarks/ab.py /path/to/main /path/to/branch pyramid:rows=40 rain:count=1000

A scene is a testbed sample slug with its size parameters (``slug:param=value``).
Timings are reported, never asserted.
"""

from __future__ import annotations

import argparse
import json
import os
import statistics
import subprocess
import sys
from typing import Any

_WORKER = r"""
import gc, json, sys, time
from kge.app import App
from kge.testbed.registry import get_sample
slug, params = sys.argv[1], json.loads(sys.argv[2])
app = App(get_sample(slug).setup, headless=True, **params)
for line in sys.stdin:
    n = int(line)
    times = []
    gc.disable()
    for _ in range(n):
        t0, c0 = time.perf_counter(), time.process_time()
        app.step()
        times.append(((time.perf_counter() - t0) * 1000.0, (time.process_time() - c0) * 1000.0))
    gc.enable()
    print(json.dumps(times), flush=True)
app.close()
"""


def _parse(scene: str) -> tuple[str, dict[str, Any]]:
    slug, _, rest = scene.partition(":")
    params: dict[str, Any] = {}
    for item in filter(None, rest.split(",")):
        key, _, value = item.partition("=")
        params[key] = json.loads(value)
    return slug, params


def _worker(tree: str, slug: str, params: dict[str, Any]) -> subprocess.Popen[str]:
    env = dict(os.environ, PYTHONPATH=tree, PYGLET_HEADLESS="1", PYGLET_AUDIO="silent")
    return subprocess.Popen(
        [sys.executable, "-c", _WORKER, slug, json.dumps(params)],
        stdin=subprocess.PIPE, stdout=subprocess.PIPE, text=True, env=env, cwd=tree,
    )


def _frames(proc: subprocess.Popen[str], n: int) -> list[tuple[float, float]]:
    """(wall ms, CPU ms) of ``n`` frames of one worker."""
    assert proc.stdin is not None and proc.stdout is not None
    proc.stdin.write(f"{n}\n")
    proc.stdin.flush()
    return [(w, c) for w, c in json.loads(proc.stdout.readline())]


def compare(tree_a: str, tree_b: str, scene: str, warmup: int = 30, frames: int = 40,
            blocks: int = 6) -> dict[str, Any]:
    """Median ms per frame of ``scene`` on both checkouts, and B / A."""
    slug, params = _parse(scene)
    procs = [_worker(tree_a, slug, params), _worker(tree_b, slug, params)]
    try:
        for p in procs:
            _frames(p, warmup)
        times: list[list[tuple[float, float]]] = [[], []]
        for _ in range(blocks):
            for k, p in enumerate(procs):
                times[k] += _frames(p, frames)
    finally:
        for p in procs:
            if p.stdin is not None:
                p.stdin.close()
            p.wait()
    a, b = (statistics.median(w for w, _ in t) for t in times)
    ca, cb = (statistics.median(c for _, c in t) for t in times)
    return {
        "scene": scene, "a_ms": round(a, 3), "b_ms": round(b, 3), "b_over_a": round(b / a, 3),
        "a_cpu_ms": round(ca, 3), "b_cpu_ms": round(cb, 3), "cpu_b_over_a": round(cb / ca, 3),
    }


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=(__doc__ or "").split("\n")[0])
    parser.add_argument("tree_a", help="checkout A (e.g. main)")
    parser.add_argument("tree_b", help="checkout B (e.g. a branch's worktree)")
    parser.add_argument("scenes", nargs="+", help="slug:param=value,... (testbed samples)")
    parser.add_argument("--warmup", type=int, default=30)
    parser.add_argument("--frames", type=int, default=40)
    parser.add_argument("--blocks", type=int, default=6)
    parser.add_argument("--out", help="append the rows as JSON lines to this file")
    args = parser.parse_args(argv)
    for scene in args.scenes:
        row = compare(args.tree_a, args.tree_b, scene, args.warmup, args.frames, args.blocks)
        print(json.dumps(row), flush=True)
        if args.out:
            with open(args.out, "a", encoding="utf-8") as f:
                f.write(json.dumps(row) + "\n")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
