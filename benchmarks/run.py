"""``kge bench`` / ``make bench``: every scene, every engine, one table.

Writes a table to the terminal (with progress on stderr), ``out/bench.json``,
``out/bench.png`` (matplotlib) and ``out/bench.md`` (the same report as
markdown, as kept in benchmarks/results/bench.md). ``--quick`` runs every scene at its
smallest size in seconds (the test suite does this so the benchmarks cannot rot);
``--breakdown`` adds kge's time per phase (sync-in, step, sync-out, events).
Render sync (sprites moved per frame, headless) is measured in the same run
unless ``--no-render``; the issue's targets are checked against the numbers at
the end (reported, never asserted).
"""

from __future__ import annotations

import argparse
import datetime as dt
import json
import os
import platform
import sys
from collections.abc import Callable
from pathlib import Path
from typing import Any

from benchmarks.harness import FRAME_BUDGET_MS, Result, fitting_label, largest_fitting, measure
from benchmarks.scenes import scenes, skipped_engines

#: kge and its peers, each peer bare and with what a game on it adds every frame:
#: raw pymunk, + a bulk pose read-out; pybox2d's step alone, + KGE 1.0's pose-copy loop
ENGINES = ("kge", "pymunk", "pymunk+read", "box2d", "box2d+sync")
#: the ratio columns: kge against each peer, from medians of the same run
PEERS = ENGINES[1:]
RENDER_SIZES = (1000, 5000, 10000)
Progress = Callable[[str], None]


def machine() -> str:
    cpu = platform.processor() or platform.machine()
    try:
        with open("/proc/cpuinfo") as f:
            cpu = next((ln.split(":", 1)[1].strip() for ln in f if ln.startswith("model name")),
                       cpu)
    except OSError:
        pass
    return (f"{cpu}, {os.cpu_count()} cores, {platform.system()}, "
            f"Python {platform.python_version()}")


def versions() -> dict[str, str]:
    from importlib.metadata import PackageNotFoundError, version

    out = {}
    for pkg in ("pymunk", "esper", "pyglet", "numpy", "box2d"):
        try:
            out[pkg] = version(pkg)
        except PackageNotFoundError:
            out[pkg] = "not installed"
    return out


def ratio(results: list[Result], scene: str, size: int, a: str, b: str) -> float | None:
    by = {r.engine: r.median_ms for r in results if r.scene == scene and r.size == size}
    if a in by and b in by and by[b] > 0:
        return by[a] / by[b]
    return None


def _fmt_q(q: dict[str, float]) -> str:
    return ", ".join(f"{k}={v:g}" for k, v in q.items())


def _ratio_cells(results: list[Result], scene: str, size: int) -> list[str]:
    return [("-" if (v := ratio(results, scene, size, "kge", p)) is None else f"{v:.2f}")
            for p in PEERS]


def table(results: list[Result]) -> str:
    """The terminal table: one row per engine; the kge row carries kge / each peer."""
    lines = [
        f"{'scene':<15}{'size':>7}  {'engine':<12}{'median ms':>10}{'p95 ms':>9}"
        + "".join(f"{'kge/' + p:>17}" for p in PEERS) + "  quality"
    ]
    for r in results:
        cells = _ratio_cells(results, r.scene, r.size) if r.engine == "kge" else [""] * len(PEERS)
        lines.append(
            f"{r.scene:<15}{r.size:>7}  {r.engine:<12}{r.median_ms:>10.3f}{r.p95_ms:>9.3f}"
            + "".join(f"{c:>17}" for c in cells) + f"  {_fmt_q(r.quality)}"
        )
    return "\n".join(lines)


def fits(results: list[Result]) -> dict[str, dict[str, float]]:
    """Largest size per scene and engine that fits a 16.7 ms frame (interpolated between
    measured sizes; ``inf`` / ``0.0`` when outside them, see :func:`largest_fitting`)."""
    out: dict[str, dict[str, float]] = {}
    for name in sorted({r.scene for r in results}):
        for engine in ENGINES:
            pts = [(r.size, r.median_ms) for r in results
                   if r.scene == name and r.engine == engine]
            if pts:
                out.setdefault(name, {})[engine] = round(largest_fitting(pts, FRAME_BUDGET_MS), 1)
    return out


def _median(results: list[Result], scene: str, size: int, engine: str) -> float | None:
    return next((r.median_ms for r in results
                 if (r.scene, r.size, r.engine) == (scene, size, engine)), None)


def targets(results: list[Result], fitting: dict[str, dict[str, float]],
            render: dict[int, dict[str, float]],
            rl: list[dict[str, Any]] | None = None,
            animation: dict[int, dict[str, float]] | None = None,
            costs: dict[str, float] | None = None,
            game: dict[str, Any] | None = None) -> list[dict[str, Any]]:
    """The issues' targets beside the measured figures (None when not measured)."""
    rows: list[dict[str, Any]] = []
    c = costs or {}

    def add(what: str, value: float | None, goal: float, at_most: bool, unit: str = "") -> None:
        met = None if value is None else (value <= goal if at_most else value >= goal)
        rows.append({"target": what, "value": value, "goal": goal,
                     "at_most": at_most, "unit": unit, "met": met})

    # a kge frame at the cost of the pymunk step under it (issues 16 and 36)
    for scene, size, goal in (("sparse", 20000, 1.30), ("rain", 5000, 1.30),
                              ("pyramid", 40, 1.25), ("dense-pile", 6000, 1.25),
                              ("chain", 200, 2.0), ("chain", 1000, 1.25),
                              ("joint-grid", 100, 2.0)):
        add(f"kge / raw pymunk, {scene}-{size}", ratio(results, scene, size, "kge", "pymunk"),
            goal, True)
    add("spawning 1,000 bodies in one frame, kge / raw pymunk",
        ratio(results, "spawn", 1000, "kge", "pymunk"), 1.5, True)
    memory = (c["bytes_per_body_kge"] / c["bytes_per_body_pymunk"]
              if c.get("bytes_per_body_pymunk") else None)
    add("memory per body, kge / raw pymunk (fresh processes)", memory, 2.0, True)
    add("sync-out per moved body (sparse field)", c.get("sync_out_us"), 0.10, True, "µs")
    # issue 36: kge's begin + end of one new contact (benchmarks/contact_cost.py)
    add(f"new-contact bookkeeping, begin + end, rain-{c.get('contact_bodies', 5000):.0f}",
        c.get("contact_us"), 3.0, True, "µs")
    despawn = c.get("despawn_kge_ms") if c.get("despawn_count") == 1000 else None
    add("despawning 1,000 bodies in one frame", despawn, 25.0, True, "ms")
    # a structural change costs what it changes: the same in a 10x larger world
    add("spawn+despawn of 7 entities, kge in 2,000 bodies / in 200",
        c["churn_kge_2000_ms"] / c["churn_kge_200_ms"] if "churn_kge_2000_ms" in c else None,
        1.3, True)
    # lunar-lander: Gymnasium's LunarLander on kge.box2d vs on pybox2d (goal: half its speed)
    for scene, size, goal in (("pyramid", 40, 0.80), ("chain", 200, 0.70),
                              ("many-sleeping", 5000, 0.10), ("lunar-lander", 50, 2.0)):
        add(f"kge / pybox2d, {scene}-{size}", ratio(results, scene, size, "kge", "box2d"),
            goal, True)
    # a 60 Hz frame with one fixed step pays the per-frame sync and the per-step record
    per_sprite = [r["kge_sync"] + r["record"] for n, r in sorted(render.items()) if n >= 1000]
    add("render sync per sprite and frame (kge_sync + record, largest N)",
        per_sprite[-1] if per_sprite else None, 0.15, True, "µs")
    add("bodies in a dense pile at 60 Hz (dense-pile, sleep off)",
        fitting.get("dense-pile", {}).get("kge"), 6000, False)
    add("sparse bodies at 60 Hz (sparse)", fitting.get("sparse", {}).get("kge"), 20000, False)
    add("spawning 1,000 bodies in one frame", _median(results, "spawn", 1000, "kge"),
        25.0, True, "ms")
    from benchmarks.rl import ratio as rl_ratio

    add("LunarLander steps/s, kge batched / pybox2d SyncVectorEnv, N = 64 (one core)",
        rl_ratio(rl or [], 64), 1.0, False)
    from benchmarks.rl import single_ratio

    add("LunarLander steps/s, kge/LunarLander-v0 / pybox2d LunarLander-v3, one env each",
        single_ratio(rl or []), 0.3, False)
    lander = ratio(results, "lunar-lander", 50, "kge", "box2d")
    add("Gymnasium LunarLander-v3 steps/s, on kge.box2d / on pybox2d",
        None if not lander else 1.0 / lander, 0.25, False)
    anim = animation[max(animation)] if animation else {}
    add("animated sprites per sprite and frame (advance + tex coords + upload, largest N)",
        anim.get("kge_total"), 0.3, True, "µs")
    add("pyglet animated Sprite / kge per animated sprite (largest N)",
        anim["pyglet_sprite"] / anim["kge_total"] if anim else None, 10.0, False)
    add("Arcade TextureAnimationSprite / kge per animated sprite (largest N)",
        anim["arcade_sprite"] / anim["kge_total"] if "arcade_sprite" in anim else None,
        10.0, False)
    add("live tweens per tween and frame (largest N)", anim.get("tweens"), 0.5, True, "µs")
    add("cross-fading animated sprites per sprite and frame (advance + ghosts, largest N)",
        anim.get("crossfade"), 2.0, True, "µs")
    add("keyframe timelines (2 tracks) per player and frame (largest N)", anim.get("timeline"),
        2.0, True, "µs")
    if game is not None:
        from benchmarks.particles_lights import game_ratios, game_targets

        for what, value, goal, unit in game_targets(game):
            add(what, value, goal, True, unit)
        for what, value, goal, unit in game_ratios(game):
            add(what, value, goal, False, unit)
    return rows


def _fmt_target(t: dict[str, Any]) -> tuple[str, str, str, str]:
    value = "not measured" if t["value"] is None else f"{t['value']:.3g} {t['unit']}".strip()
    goal = f"{'≤' if t['at_most'] else '≥'} {t['goal']:g} {t['unit']}".strip()
    met = {None: "-", True: "met", False: "missed"}[t["met"]]
    return t["target"], value, goal, met


def chart(results: list[Result], path: Path, stamp: str) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    groups = list(dict.fromkeys((r.scene, r.size) for r in results))  # run order
    fig, ax = plt.subplots(figsize=(max(6.0, 0.75 * len(groups)), 4.5))
    width = 0.8 / len(ENGINES)
    for i, engine in enumerate(ENGINES):
        xs, ys = [], []
        for g, (scene, size) in enumerate(groups):
            ms = _median(results, scene, size, engine)
            if ms is not None:
                xs.append(g + (i - (len(ENGINES) - 1) / 2) * width)
                ys.append(ms)
        if xs:
            ax.bar(xs, ys, width, label=engine)
    ax.axhline(FRAME_BUDGET_MS, color="grey", linestyle="--", linewidth=1, label="16.7 ms")
    ax.set_xticks(range(len(groups)), [f"{s}\n{n}" for s, n in groups], fontsize=7,
                  rotation=60)
    ax.set_ylabel("median ms per frame (log)")
    ax.set_yscale("log")
    ax.set_title(f"kge vs raw pymunk vs pybox2d, {stamp}", fontsize=8)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def run_breakdown(chosen: list[Any], progress: Progress, quick: bool) -> list[dict[str, Any]]:
    """kge's phases per scene and size (median ms), from a separate kge-only pass."""
    from benchmarks.breakdown import breakdown

    rows = []
    for scene in chosen:
        for size in scene.sizes:
            measured = scene.engines["kge"](size)
            app = getattr(measured.runner, "app", None)
            if app is None or getattr(measured.runner, "prepare", None) is not None:
                measured.close()  # the spawn scene's frame is not a plain App.step
                continue
            progress(f"breakdown {scene.name}[{size}]")
            phases = breakdown(app, scene.warmup, scene.frames)
            rows.append({"scene": scene.name, "size": size, **phases})
            measured.close()
    return rows


def breakdown_table(rows: list[dict[str, Any]]) -> str:
    from benchmarks.breakdown import PHASES

    head = f"{'scene':<15}{'size':>7}" + "".join(f"{p:>10}" for p in (*PHASES, "total"))
    lines = [head]
    for r in rows:
        lines.append(f"{r['scene']:<15}{r['size']:>7}"
                     + "".join(f"{r[p]:>10.3f}" for p in (*PHASES, "total")))
    return "\n".join(lines)


def run_render(sizes: tuple[int, ...], repeats: int, progress: Progress
               ) -> tuple[dict[int, dict[str, float]], str | None]:
    """Render sync per sprite (µs) at each size, or the reason it could not run."""
    try:
        from benchmarks.render_sync import measure as render_measure

        out = {}
        for n in sizes:
            progress(f"render sync [{n} sprites]")
            out[n] = render_measure(n, repeats)
        return out, None
    except Exception as err:  # no GL (headless EGL missing): report, do not fail the run
        return {}, f"render sync skipped: {type(err).__name__}: {err}"


def run_animation(sizes: tuple[int, ...], repeats: int, progress: Progress
                  ) -> tuple[dict[int, dict[str, float]], str | None]:
    """Animated sprites and tweens, µs per item and frame, or why it could not run."""
    try:
        from benchmarks.animation import measure as animation_measure

        out = {}
        for n in sizes:
            progress(f"animation [{n} sprites, {n} tweens]")
            out[n] = animation_measure(n, repeats)
    except Exception as err:  # no GL: report, do not fail the run
        return {}, f"animation skipped: {type(err).__name__}: {err}"
    from benchmarks.animation import measure_arcade

    try:
        progress("animation [Arcade 3, its own venv]")
        for n, us in measure_arcade(sizes, repeats).items():
            out[n]["arcade_sprite"] = us
    except (OSError, RuntimeError, ValueError) as err:
        return out, f"Arcade animation column skipped: {err}"
    return out, None


def render_table(render: dict[int, dict[str, float]]) -> str:
    cols = ("blend", "bulk_write", "kge_sync", "record", "sprite_update", "frame")
    lines = [f"{'sprites':>8}" + "".join(f"{c:>15}" for c in cols)]
    for n, r in sorted(render.items()):
        lines.append(f"{n:>8}" + "".join(f"{r[c]:>15.3f}" for c in cols))
    return "\n".join(lines)


def markdown(report: dict[str, Any], chart_link: str | None) -> str:
    """The report as markdown (what benchmarks/results/bench.md keeps)."""
    res = [Result(**r) for r in report["results"]]
    out = [f"Measured {report['date']} on {report['machine']}.", "",
           "Versions: " + ", ".join(f"{k} {v}" for k, v in report["versions"].items()) + ".", ""]
    if chart_link:
        out += [f"![kge vs raw pymunk vs pybox2d]({chart_link})", ""]
    out += ["| scene | size | kge ms (p95) | " + " | ".join(f"{p} ms" for p in PEERS) + " | "
            + " | ".join(f"kge/{p}" for p in PEERS) + " | quality (" + "; ".join(ENGINES)
            + ") |", "|---|---:|" + "---:|" * (1 + 2 * len(PEERS)) + "---|"]
    for scene, size in dict.fromkeys((r.scene, r.size) for r in res):
        by = {r.engine: r for r in res if (r.scene, r.size) == (scene, size)}
        k = by.get("kge")

        def ms(e: str, by: dict[str, Result] = by) -> str:
            r = by.get(e)
            return "-" if r is None else f"{r.median_ms:.2f}"

        q = "; ".join(_fmt_q(by[e].quality) for e in ENGINES if e in by)
        out.append(f"| {scene} | {size} | {'-' if k is None else f'{k.median_ms:.2f} '}"
                   f"({'-' if k is None else f'{k.p95_ms:.2f}'}) | "
                   + " | ".join(ms(p) for p in PEERS) + " | "
                   + " | ".join(_ratio_cells(res, scene, size)) + f" | {q} |")
    out += ["", "Largest size fitting a 16.7 ms frame (log-log interpolation between the "
            "measured sizes; \"> N\" fits at every size measured, \"< N\" at none):", "",
            "| scene | " + " | ".join(ENGINES) + " |", "|---|" + "---:|" * len(ENGINES)]
    for name, per in report["largest_fitting"].items():
        out.append(f"| {name} | " + " | ".join(per.get(e, "-") for e in ENGINES) + " |")
    if report.get("render"):
        out += ["", "Render sync, µs per sprite (median; `kge_sync` = pose blend + bulk "
                "vertex write, per frame; `record` = history roll + physics adoption, per "
                "fixed step; `sprite_update` = pyglet's per-sprite `Sprite.update`):", "",
                "| sprites | blend | bulk_write | kge_sync | record | sprite_update "
                "| whole frame |",
                "|---:|---:|---:|---:|---:|---:|---:|"]
        for n, r in sorted(report["render"].items(), key=lambda kv: int(kv[0])):
            out.append(f"| {n} | {r['blend']:.3f} | {r['bulk_write']:.3f} | {r['kge_sync']:.3f}"
                       f" | {r['record']:.3f} | {r['sprite_update']:.3f} | {r['frame']:.3f} |")
    if report.get("animation"):
        out += ["", "Animation, µs per item and frame (median; kge = numpy advance + bulk "
                "texture-coordinate write + GPU upload; pyglet = its animated `Sprite` on a "
                "clock; every sprite changes frame every frame):", "",
                "| N | advance | tex coords | upload | kge total | pyglet Sprite | pyglet/kge "
                "| Arcade 3 | Arcade/kge | tweens |",
                "|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"]
        for n, r in sorted(report["animation"].items(), key=lambda kv: int(kv[0])):
            arc = r.get("arcade_sprite")
            arcade_cells = "- | -" if arc is None else f"{arc:.3f} | {arc / r['kge_total']:.0f}"
            out.append(f"| {n} | {r['advance']:.3f} | {r['texcoords']:.3f} | {r['upload']:.3f}"
                       f" | {r['kge_total']:.3f} | {r['pyglet_sprite']:.3f}"
                       f" | {r['pyglet_sprite'] / r['kge_total']:.0f} | {arcade_cells}"
                       f" | {r['tweens']:.3f} |")
    if report.get("ui"):
        from benchmarks.ui import markdown_lines

        out += markdown_lines(report["ui"])
    if report.get("editor"):
        from benchmarks import editor as editor_bench

        out += editor_bench.markdown_lines(report["editor"])
    if report.get("game"):
        from benchmarks.particles_lights import game_lines

        out += game_lines(report["game"])
    if report.get("game_frame"):
        from benchmarks.game_frame import lines as frame_lines

        out += frame_lines(report["game_frame"])
    if report.get("rendering"):
        from benchmarks.rendering import lines as rendering_lines

        out += rendering_lines(report["rendering"])
    if report.get("features"):
        from benchmarks.features import feature_lines

        out += feature_lines(report["features"])
    if report.get("breakdown"):
        from benchmarks.breakdown import PHASES

        out += ["", "kge frame breakdown, median ms per phase:", "",
                "| scene | size | " + " | ".join((*PHASES, "total")) + " |",
                "|---|---:|" + "---:|" * (len(PHASES) + 1)]
        for r in report["breakdown"]:
            out.append(f"| {r['scene']} | {r['size']} | "
                       + " | ".join(f"{r[p]:.2f}" for p in (*PHASES, "total")) + " |")
    if report.get("collision"):
        from benchmarks.collision import markdown as collision_markdown

        out += collision_markdown(report["collision"])
    if report.get("rl"):
        from benchmarks.rl import table as rl_table

        out += ["", "Gymnasium LunarLander, env steps per second in one process (random "
                "actions, episodes reset as they end):", "", rl_table(report["rl"], True)]
    if report.get("characters"):
        from benchmarks.character import markdown_lines as character_lines

        out += character_lines(report["characters"])
    if report.get("costs"):
        from benchmarks.costs import markdown as costs_markdown

        out += costs_markdown(report["costs"])
    out += ["", "Targets:", "", "| target | measured | goal | |", "|---|---:|---:|---|"]
    for t in report["targets"]:
        out.append("| " + " | ".join(_fmt_target(t)) + " |")
    if report["skipped"]:
        out += ["", "Skipped: " + "; ".join(report["skipped"])]
    return "\n".join(out) + "\n"


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="kge bench", description=(__doc__ or "").split("\n")[0])
    parser.add_argument("--quick", action="store_true", help="smallest sizes, few frames")
    parser.add_argument("--scene", action="append", help="only these scenes")
    parser.add_argument("--blocks", type=int, default=5, help="interleaved blocks per engine")
    parser.add_argument("--seed", type=int, default=0,
                        help="seed of the shuffled engine order (the report records it)")
    parser.add_argument("--out", default="out", help="folder for bench.json/.png/.md")
    parser.add_argument("--no-chart", action="store_true")
    parser.add_argument("--no-render", action="store_true", help="skip the render sync section")
    parser.add_argument("--no-rl", action="store_true",
                        help="skip the Gymnasium LunarLander throughput section")
    parser.add_argument("--no-game", action="store_true", help="skip particles and lights")
    parser.add_argument("--breakdown", action="store_true",
                        help="also time kge's phases (sync-in, step, sync-out, events)")
    args = parser.parse_args(argv)

    def progress(msg: str) -> None:
        print(f"  {msg}", file=sys.stderr, flush=True)

    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    for line in skipped_engines():
        print(f"skipped {line}", file=sys.stderr)
    started = dt.datetime.now(dt.UTC)
    results: list[Result] = []
    chosen = [s for s in scenes(args.quick) if not args.scene or s.name in args.scene]
    for scene in chosen:
        for size in scene.sizes:
            results += measure(scene, size, ENGINES, blocks=2 if args.quick else args.blocks,
                               progress=progress, seed=args.seed)
    print(table(results))
    fitting = fits(results)
    scene_sizes = {s.name: s.sizes for s in chosen}
    labels = {name: {e: fitting_label(n, scene_sizes[name]) for e, n in per.items()}
              for name, per in fitting.items()}
    print("\nlargest size fitting a 16.7 ms frame (interpolated between measured sizes):")
    for name, per in labels.items():
        print(f"  {name:<15} " + "  ".join(f"{e} {n}" for e, n in per.items()))
    skipped = skipped_engines()
    render: dict[int, dict[str, float]] = {}
    if not args.no_render and not args.scene:
        sizes = (200,) if args.quick else RENDER_SIZES
        render, why = run_render(sizes, 2 if args.quick else 9, progress)
        if why:
            skipped.append(why)
            print(why, file=sys.stderr)
        else:
            print("\nrender sync, µs per sprite (median):")
            print(render_table(render))
    rl: list[dict[str, Any]] = []
    if not args.no_rl and not args.scene:
        from benchmarks.rl import box2d_lander_missing
        from benchmarks.rl import measure as rl_measure
        from benchmarks.rl import table as rl_table

        progress("gymnasium LunarLander steps per second")
        if args.quick:
            rl = rl_measure(sizes=(1, 4), env_steps=100, repeats=1)
        else:
            rl = rl_measure()
        missing = box2d_lander_missing()
        if missing:
            skipped.append(missing)
        print("\nGymnasium LunarLander, env steps per second (one process):")
        print(rl_table(rl))
    animation: dict[int, dict[str, float]] = {}
    if not args.no_render and not args.scene:
        animation, why = run_animation((200,) if args.quick else (1000, 10000),
                                       2 if args.quick else 9, progress)
        if why:
            skipped.append(why)
            print(why, file=sys.stderr)
        if animation:
            from benchmarks.animation import table as animation_table

            print("\nanimation, µs per sprite (tween) and frame (median):")
            print(animation_table(animation))
    ui_rows: dict[str, Any] = {}
    if not args.no_render and not args.scene:
        from benchmarks import ui as ui_bench

        ui_rows, why = ui_bench.bench_section(args.quick, progress)
        print(why or "\nui, µs of CPU per frame (median):\n" + ui_bench.text(ui_rows),
              file=sys.stderr if why else sys.stdout)
        skipped += [why] if why else []
    game: dict[str, Any] = {}
    if not args.no_game and not args.scene:
        from benchmarks.particles_lights import run_game

        game, why = run_game(args.quick, progress)
        if why:
            skipped.append(why)
            print(why, file=sys.stderr)
        if game:
            from benchmarks.particles_lights import game_lines

            print("\n".join(game_lines(game)))
    frame: dict[str, Any] = {}
    if not args.no_game and not args.no_render and not args.scene:
        from benchmarks import game_frame

        frame, why = game_frame.run_section(args.quick, progress)
        if why:
            skipped.append(why)
            print(why, file=sys.stderr)
        else:
            print("\n".join(game_frame.lines(frame)))
    rows: list[dict[str, Any]] = []
    if args.breakdown:
        rows = run_breakdown(chosen, progress, args.quick)
        print("\nkge frame breakdown, median ms per phase:")
        print(breakdown_table(rows))
    collision: list[dict[str, Any]] = []
    if not args.scene:  # kge.collision queries beside pybox2d and brute force
        from benchmarks.collision import measure as collision_measure
        from benchmarks.collision import table as collision_table

        progress("kge.collision queries")
        collision = collision_measure(args.quick)
        print("\nkge.collision, queries per second:")
        print(collision_table(collision))
    costs: dict[str, float] = {}
    if not args.scene:  # per-body costs beside raw pymunk (sync-out, despawn, memory)
        from benchmarks.costs import measure as costs_measure
        from benchmarks.costs import table as costs_table

        progress("per-body costs")
        costs = costs_measure(args.quick)
        print("\nper-body costs:")
        print(costs_table(costs))
        from benchmarks import contact_cost

        progress("kge's work per new contact")
        costs.update(contact_cost.measure(args.quick))
        print(contact_cost.line(costs))
    features: dict[str, Any] = {}
    if not args.no_game and not args.scene:  # per-frame costs of game-layer features
        from benchmarks.features import feature_lines, run_features

        features, why = run_features(args.quick, progress)
        if why:
            skipped.append(why)
            print(why, file=sys.stderr)
        print("\n".join(feature_lines(features)))
    tiles: dict[str, float] = {}
    if not args.scene:
        from benchmarks import tilemap

        tiles, why = tilemap.run_section(args.quick, progress)
        if why:
            skipped.append(why)
        else:
            print("\ntile map:", tilemap.table(tiles))
    drawing: dict[str, Any] = {}
    if not args.no_render and not args.scene:
        from benchmarks import rendering

        drawing, why = rendering.run_section(args.quick, progress)
        if why:
            skipped.append(why)
        else:
            print("\n".join(rendering.lines(drawing)))
    characters: dict[str, float] = {}
    if not args.scene:  # character controllers beside the same bodies as dynamic bodies
        from benchmarks import character

        characters, why = character.run_section(args.quick, progress)
        if why:
            skipped.append(why)
        else:
            print("\ncharacters:", character.table(characters))
    editor_rows: dict[str, Any] = {}
    if not args.no_render and not args.scene:
        from benchmarks import editor as editor_bench

        editor_rows, why = editor_bench.run_section(args.quick, progress)
        if why:
            skipped.append(why)
        else:
            print("\neditor (kge edit), µs of CPU per frame (median):")
            print(editor_bench.table({int(n): r for n, r in editor_rows.items()}))
    goals = targets(results, fitting, render, rl, animation, costs, game if game else None)
    if frame:
        from benchmarks.game_frame import targets as frame_targets

        for f_name, f_value, f_goal, f_at_most, f_unit in frame_targets(frame):
            goals.append({"target": f_name, "value": f_value, "goal": f_goal,
                          "at_most": f_at_most, "unit": f_unit,
                          "met": None if f_value is None else (
                              f_value <= f_goal if f_at_most else f_value >= f_goal)})
    if tiles:
        goals += tilemap.targets(tiles)
    if drawing:
        goals += rendering.targets(drawing)
    if characters:
        goals += character.targets(characters)
    if features:
        from benchmarks.features import feature_targets

        for f_name, f_value, f_goal, f_unit in feature_targets(features):
            goals.append({"target": f_name, "value": f_value, "goal": f_goal, "at_most": True,
                          "unit": f_unit,
                          "met": None if f_value is None else f_value <= f_goal})  # fmt: skip
    print("\ntargets:")
    for t in goals:
        what, value, goal, met = _fmt_target(t)
        print(f"  {what:<58} {value:>14}  goal {goal:<10} {met}")
    seconds = (dt.datetime.now(dt.UTC) - started).total_seconds()
    report = {
        "date": started.strftime("%Y-%m-%d %H:%M UTC"),
        "machine": machine(),
        "versions": versions(),
        "seconds": round(seconds, 1),
        "quick": args.quick,
        "results": [r.as_dict() for r in results],
        "largest_fitting": labels,
        "order_seed": args.seed,
        "render": {str(n): r for n, r in render.items()},
        "animation": {str(n): r for n, r in animation.items()},
        "breakdown": rows,
        "collision": collision,
        "rl": rl,
        "ui": ui_rows,
        "costs": costs,
        "game": game,
        "game_frame": frame,
        "tilemap": tiles,
        "rendering": drawing,
        "characters": characters,
        "features": features,
        "editor": editor_rows,
        "targets": goals,
        "skipped": skipped,
    }
    (out / "bench.json").write_text(json.dumps(report, indent=2))
    chart_name = None
    if not args.no_chart:
        chart(results, out / "bench.png", f"{report['date']}, {report['machine']}")
        chart_name = "bench.png"
    (out / "bench.md").write_text(markdown(report, chart_name))
    print(f"\nwrote {out / 'bench.json'}, {out / 'bench.md'}"
          + ("" if args.no_chart else f" and {out / 'bench.png'}")
          + f" in {seconds:.0f} s")
    return 0


if __name__ == "__main__":
    sys.exit(main())
