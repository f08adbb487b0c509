"""A parameter sweep of a kge scene as Ray tasks: LunarLander under different gravities.

Every (gravity, seed) pair is one Ray task that flies one episode of the kge
LunarLander with the heuristic controller. The results come back as rows, are
summarised per gravity in a table, and drawn as a chart::

    python examples/rl/sweep.py                      # a local Ray with this machine's cores
    python examples/rl/sweep.py --address auto       # the Ray cluster this machine joined

On a cluster (``ray start --head`` on one machine, ``ray start --address=HEAD:6379``
on the others, kge installed on each) the same tasks spread over every machine's
cores; nothing in this file changes.
"""

from __future__ import annotations

import argparse
import statistics
from collections import defaultdict
from collections.abc import Sequence
from pathlib import Path
from typing import Any

import ray


def fly(gravity: float, seed: int, max_steps: int = 1000) -> dict[str, Any]:
    """Fly one seeded episode with the heuristic pilot (the body of one Ray task)."""
    from kge.gym.lunar_lander import LunarLander, heuristic

    env = LunarLander(gravity=gravity)
    obs, _ = env.reset(seed=seed)
    total, steps = 0.0, 0
    info: dict[str, Any] = {}
    terminated = False
    while not terminated and steps < max_steps:
        obs, reward, terminated, _, info = env.step(heuristic(obs))
        total += reward
        steps += 1
    env.close()
    landed = terminated and not info["game_over"] and not info["awake"]
    return {"gravity": gravity, "seed": seed, "return": total, "steps": steps,
            "landed": bool(landed)}


#: ``fly`` as a Ray task: ``episode.remote(g, s)`` runs wherever Ray schedules it
episode = ray.remote(fly)


def sweep(gravities: Sequence[float], seeds: Sequence[int]) -> list[dict[str, Any]]:
    """Run every (gravity, seed) pair as a Ray task; rows in submission order."""
    futures = [episode.remote(g, s) for g in gravities for s in seeds]
    return list(ray.get(futures))


def summarise(rows: list[dict[str, Any]]) -> list[dict[str, Any]]:
    """One line per gravity: episodes, mean and spread of the return, landings, length."""
    groups: dict[float, list[dict[str, Any]]] = defaultdict(list)
    for row in rows:
        groups[row["gravity"]].append(row)
    out = []
    for gravity in sorted(groups, reverse=True):
        group = groups[gravity]
        returns = [r["return"] for r in group]
        out.append({
            "gravity": gravity,
            "episodes": len(group),
            "mean_return": statistics.fmean(returns),
            "std_return": statistics.pstdev(returns),
            "landed": sum(r["landed"] for r in group) / len(group),
            "mean_steps": statistics.fmean(r["steps"] for r in group),
        })
    return out


def table(summary: list[dict[str, Any]]) -> str:
    """The summary as a Markdown table."""
    lines = ["| gravity m/s² | episodes | mean return | std | landed | mean steps |",
             "|---:|---:|---:|---:|---:|---:|"]
    for s in summary:
        lines.append(f"| {s['gravity']:.1f} | {s['episodes']} | {s['mean_return']:.1f} | "
                     f"{s['std_return']:.1f} | {100 * s['landed']:.0f} % | "
                     f"{s['mean_steps']:.0f} |")
    return "\n".join(lines)


def chart(summary: list[dict[str, Any]], path: str | Path) -> Path:
    """Mean return (with its spread) and landing rate against gravity, as a PNG."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    g = [-s["gravity"] for s in summary]
    fig, ax = plt.subplots(figsize=(6, 3.5), dpi=100)
    ax.errorbar(g, [s["mean_return"] for s in summary], yerr=[s["std_return"] for s in summary],
                marker="o", capsize=3, label="mean return")
    ax.axhline(200, color="grey", linestyle=":", linewidth=1)
    ax.set_xlabel("gravity (m/s², downwards)")
    ax.set_ylabel("episode return")
    rate = ax.twinx()
    rate.plot(g, [100 * s["landed"] for s in summary], "s--", color="tab:green",
              label="landed %")
    rate.set_ylabel("landed (%)")
    rate.set_ylim(0, 105)
    ax.set_title("kge LunarLander, heuristic pilot: a Ray sweep")
    fig.tight_layout()
    out = Path(path)
    out.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(out)
    plt.close(fig)
    return out


def main(argv: Sequence[str] | None = None) -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--address", default=None,
                        help="Ray cluster address ('auto' = the cluster this machine joined)")
    parser.add_argument("--seeds", type=int, default=8, help="episodes per gravity")
    parser.add_argument("--gravities", type=float, nargs="+",
                        default=[-4.0, -6.0, -8.0, -10.0, -11.5])
    parser.add_argument("--out", default="out/rl-sweep.png")
    args = parser.parse_args(argv)
    ray.init(address=args.address)
    summary = summarise(sweep(args.gravities, range(args.seeds)))
    print(table(summary))
    print(f"chart: {chart(summary, args.out)}")
    ray.shutdown()


if __name__ == "__main__":
    main()
