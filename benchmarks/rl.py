"""Gymnasium throughput: the kge LunarLander beside pybox2d's, in env steps per second.

Measured in one process (so per core), interleaved in the same run, with the same
pre-drawn random actions for every variant:

* ``single``: one env from ``gymnasium.make`` (with Gymnasium's wrappers, as users
  get it), reset when an episode ends;
* ``batched``: kge's own vector env (``make_vec``'s ``vector_entry_point``:
  N worlds, batched arrays, autoreset);
* ``sync``: Gymnasium's ``SyncVectorEnv`` over N envs (for kge and for pybox2d).

The pybox2d side is Gymnasium's ``LunarLander-v3`` (Box2D 2.3.10 through pybox2d;
it needs ``box2d`` and ``pygame``, the ``bench`` extra). Run
``python -m benchmarks.rl`` for the table alone; ``kge bench`` includes it.
"""

from __future__ import annotations

import argparse
import os
import statistics
import sys
import time
from typing import Any

os.environ.setdefault("PYGLET_HEADLESS", "1")

if __package__ in (None, ""):  # run as a script: make the repository importable
    sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))

import numpy as np

SIZES = (1, 8, 64)
KGE_ID = "kge/LunarLander-v0"
BOX2D_ID = "LunarLander-v3"


def box2d_lander_missing() -> str | None:
    """Why pybox2d's LunarLander cannot run here, or None when it can."""
    try:
        import gymnasium.envs.box2d.lunar_lander  # noqa: F401
    except Exception as err:  # Box2D or pygame missing
        return f"pybox2d LunarLander: {type(err).__name__}: {err}"
    return None


def _make(engine: str, mode: str, n: int) -> Any:
    import gymnasium as gym

    import kge.gym  # noqa: F401  (registers kge/LunarLander-v0)

    env_id = KGE_ID if engine == "kge" else BOX2D_ID
    if mode == "single":
        return gym.make(env_id)
    vectorization = "vector_entry_point" if mode == "batched" else "sync"
    return gym.make_vec(env_id, num_envs=n, vectorization_mode=vectorization)


def variants(sizes: tuple[int, ...]) -> list[tuple[str, str, int]]:
    """(engine, mode, N) in measuring order; pybox2d only when it is installed."""
    engines = ["kge"] + ([] if box2d_lander_missing() else ["box2d"])
    out = [(e, "single", 1) for e in engines]
    for n in sizes:
        out.append(("kge", "batched", n))
        out += [(e, "sync", n) for e in engines]
    return out


def steps_per_second(env: Any, mode: str, n: int, env_steps: int, seed: int = 0) -> float:
    """Env steps per second over about ``env_steps`` steps (after 10 warm-up steps)."""
    rng = np.random.default_rng(seed)
    calls = max(1, env_steps // n)
    actions = rng.integers(0, 4, size=(calls + 10, n))
    env.reset(seed=seed)
    if mode == "single":
        def step(a: np.ndarray) -> None:
            _, _, term, trunc, _ = env.step(int(a[0]))
            if term or trunc:
                env.reset()
    else:
        def step(a: np.ndarray) -> None:
            env.step(a)
    for a in actions[:10]:
        step(a)
    start = time.perf_counter()
    for a in actions[10:]:
        step(a)
    return calls * n / (time.perf_counter() - start)


def measure(sizes: tuple[int, ...] = SIZES, env_steps: int = 4000,
            repeats: int = 3) -> list[dict[str, Any]]:
    """Median env steps per second per variant, repeats interleaved across variants."""
    chosen = variants(sizes)
    envs = {v: _make(*v) for v in chosen}
    samples: dict[tuple[str, str, int], list[float]] = {v: [] for v in chosen}
    try:
        for r in range(repeats):
            for v in chosen:
                samples[v].append(steps_per_second(envs[v], v[1], v[2], env_steps, seed=r))
    finally:
        for env in envs.values():
            env.close()
    return [{"engine": e, "mode": m, "n": n, "steps_per_s": statistics.median(samples[(e, m, n)])}
            for e, m, n in chosen]


def ratio(rows: list[dict[str, Any]], n: int) -> float | None:
    """kge batched / pybox2d SyncVectorEnv at N = n (None if either is missing)."""
    by = {(r["engine"], r["mode"], r["n"]): r["steps_per_s"] for r in rows}
    kge, box2d = by.get(("kge", "batched", n)), by.get(("box2d", "sync", n))
    return None if kge is None or box2d is None else kge / box2d


def table(rows: list[dict[str, Any]], markdown: bool = False) -> str:
    """Steps per second, one line per (mode, N): kge beside pybox2d."""
    by = {(r["engine"], r["mode"], r["n"]): r["steps_per_s"] for r in rows}
    keys = list(dict.fromkeys((r["mode"], r["n"]) for r in rows))

    def cell(engine: str, mode: str, n: int) -> str:
        v = by.get((engine, mode, n))
        return "-" if v is None else f"{v:,.0f}"

    head = ("env", "N", "kge steps/s", "pybox2d steps/s", "kge / pybox2d")
    lines = []
    for mode, n in keys:
        k, b = by.get(("kge", mode, n)), by.get(("box2d", "sync" if mode == "batched" else mode, n))
        label = {"single": "gymnasium.make", "batched": "kge batched (make_vec)",
                 "sync": "SyncVectorEnv"}[mode]
        vs = "pybox2d SyncVectorEnv" if mode == "batched" else "pybox2d"
        r = "-" if k is None or b is None else f"{k / b:.2f} (vs {vs})"
        lines.append((label, str(n), cell("kge", mode, n),
                      cell("box2d", "sync" if mode == "batched" else mode, n), r))
    if markdown:
        out = ["| " + " | ".join(head) + " |", "|---|---:|---:|---:|---:|"]
        out += ["| " + " | ".join(cols) + " |" for cols in lines]
        return "\n".join(out)
    widths = [max(len(c[i]) for c in [head, *lines]) for i in range(len(head))]
    return "\n".join("  ".join(c[i].rjust(widths[i]) for i in range(len(head)))
                     for c in [head, *lines])


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=(__doc__ or "").split("\n")[0])
    parser.add_argument("--sizes", type=int, nargs="+", default=list(SIZES))
    parser.add_argument("--steps", type=int, default=4000, help="env steps per measurement")
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--markdown", action="store_true", help="print a Markdown table")
    args = parser.parse_args(argv)
    missing = box2d_lander_missing()
    if missing:
        print(f"skipped {missing}", file=sys.stderr)
    print(table(measure(tuple(args.sizes), args.steps, args.repeats), args.markdown))
    return 0


if __name__ == "__main__":
    sys.exit(main())
