"""``kge bench`` / ``make bench``: every scene, every engine, one table.

Writes a table to the terminal (with progress on stderr), ``out/bench.json`` and
``out/bench.png`` (matplotlib). ``--quick`` runs every scene at its smallest size
in seconds (the test suite does this so the benchmarks cannot rot);
``--breakdown`` adds kge's time per phase (sync-in, step, sync-out, events).
"""

from __future__ import annotations

import argparse
import datetime as dt
import json
import os
import platform
import sys
from pathlib import Path

from benchmarks.harness import FRAME_BUDGET_MS, Result, largest_fitting, measure
from benchmarks.scenes import scenes, skipped_engines

ENGINES = ("kge", "pymunk", "box2d")


def machine() -> str:
    return f"{platform.machine()}, {os.cpu_count()} cores, Python {platform.python_version()}"


def ratio(results: list[Result], scene: str, size: int, a: str, b: str) -> float | None:
    by = {r.engine: r.median_ms for r in results if r.scene == scene and r.size == size}
    if a in by and b in by and by[b] > 0:
        return by[a] / by[b]
    return None


def table(results: list[Result]) -> str:
    lines = [
        f"{'scene':<15}{'size':>7}  {'engine':<7}{'median ms':>10}{'p95 ms':>9}"
        f"{'kge/pymunk':>11}{'kge/box2d':>10}  quality"
    ]
    for r in results:
        rp = ratio(results, r.scene, r.size, "kge", "pymunk") if r.engine == "kge" else None
        rb = ratio(results, r.scene, r.size, "kge", "box2d") if r.engine == "kge" else None
        q = ", ".join(f"{k}={v:g}" for k, v in r.quality.items())
        lines.append(
            f"{r.scene:<15}{r.size:>7}  {r.engine:<7}{r.median_ms:>10.3f}{r.p95_ms:>9.3f}"
            f"{'' if rp is None else f'{rp:.2f}':>11}{'' if rb is None else f'{rb:.2f}':>10}  {q}"
        )
    return "\n".join(lines)


def fits(results: list[Result]) -> dict[str, dict[str, float]]:
    """Largest size per scene and engine that fits a 16.7 ms frame (interpolated)."""
    out: dict[str, dict[str, float]] = {}
    for name in sorted({r.scene for r in results}):
        for engine in ENGINES:
            pts = [(r.size, r.median_ms) for r in results
                   if r.scene == name and r.engine == engine]
            if pts:
                out.setdefault(name, {})[engine] = round(largest_fitting(pts, FRAME_BUDGET_MS), 1)
    return out


def chart(results: list[Result], path: Path) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    groups = sorted({(r.scene, r.size) for r in results})
    fig, ax = plt.subplots(figsize=(max(6, 1.2 * len(groups)), 4))
    width = 0.8 / len(ENGINES)
    for i, engine in enumerate(ENGINES):
        xs, ys = [], []
        for g, (scene, size) in enumerate(groups):
            for r in results:
                if (r.scene, r.size, r.engine) == (scene, size, engine):
                    xs.append(g + (i - 1) * width)
                    ys.append(r.median_ms)
        if xs:
            ax.bar(xs, ys, width, label=engine)
    ax.axhline(FRAME_BUDGET_MS, color="grey", linestyle="--", linewidth=1, label="16.7 ms")
    ax.set_xticks(range(len(groups)), [f"{s}\n{n}" for s, n in groups], fontsize=8)
    ax.set_ylabel("median ms per frame")
    ax.set_yscale("log")
    ax.set_title(f"kge vs raw pymunk vs pybox2d ({dt.date.today()}, {machine()})", fontsize=9)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="kge bench", description=__doc__.split("\n")[0])
    parser.add_argument("--quick", action="store_true", help="smallest sizes, few frames")
    parser.add_argument("--scene", action="append", help="only these scenes")
    parser.add_argument("--blocks", type=int, default=5, help="interleaved blocks per engine")
    parser.add_argument("--out", default="out", help="folder for bench.json and bench.png")
    parser.add_argument("--no-chart", action="store_true")
    args = parser.parse_args(argv)

    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    for line in skipped_engines():
        print(f"skipped {line}", file=sys.stderr)
    results: list[Result] = []
    chosen = [s for s in scenes(args.quick) if not args.scene or s.name in args.scene]
    for scene in chosen:
        for size in scene.sizes:
            results += measure(scene, size, ENGINES, blocks=2 if args.quick else args.blocks,
                               progress=lambda msg: print(f"  {msg}", file=sys.stderr))
    print(table(results))
    fitting = fits(results)
    print("\nlargest size fitting a 16.7 ms frame (log-log interpolation):")
    for name, per in fitting.items():
        print(f"  {name:<15} " + "  ".join(f"{e} {n:g}" for e, n in per.items()))
    report = {
        "date": dt.datetime.now().isoformat(timespec="seconds"),
        "machine": machine(),
        "results": [r.as_dict() for r in results],
        "largest_fitting": fitting,
        "skipped": skipped_engines(),
    }
    (out / "bench.json").write_text(json.dumps(report, indent=2))
    if not args.no_chart:
        chart(results, out / "bench.png")
    print(f"\nwrote {out / 'bench.json'}" + ("" if args.no_chart else f" and {out / 'bench.png'}"))
    return 0


if __name__ == "__main__":
    sys.exit(main())
