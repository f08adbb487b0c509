"""Gymnasium throughput: the kge LunarLander beside pybox2d's, in env steps per second.

Measured in one process (so per core), interleaved in the same run, with the same
pre-drawn random actions for every variant:

* ``single``: one env from ``gymnasium.make`` (with Gymnasium's wrappers, as users
  get it), reset when an episode ends;
* ``batched``: kge's own vector env (``make_vec``'s ``vector_entry_point``:
  N worlds, batched arrays, autoreset);
* ``sync``: Gymnasium's ``SyncVectorEnv`` over N envs (for kge and for pybox2d);
* ``floor``: raw pymunk, no kge: N landers (hull, two legs on pivot + motor + limit,
  the moon's edge and chain) in one space at the env's substeps and iterations, a
  random engine impulse per lander and step. What the batched env cannot beat
  while it solves the same bodies with the same solver settings.

``python -m benchmarks.rl --profile 64`` prints where an env step of the batched
env goes (wall time per part, each exclusive of the parts it calls).

The pybox2d side is Gymnasium's ``LunarLander-v3`` (Box2D 2.3.10 through pybox2d;
it needs ``box2d`` and ``pygame``, the ``bench`` extra). Run
``python -m benchmarks.rl`` for the table alone; ``kge bench`` includes it.
"""

from __future__ import annotations

import argparse
import gc
import os
import statistics
import sys
import time
from collections.abc import Callable
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
        out.append(("pymunk", "floor", n))
    return out


def solid(outline: list[tuple[float, float]], density: float) -> Any:
    """A dynamic pymunk body with the mass of ``outline`` alone, as kge (and Box2D) count
    it: the 0.01 m skin of the shape adds no mass (pymunk's density would add it)."""
    import pymunk

    mass = density * pymunk.area_for_poly(outline)
    centre = pymunk.Poly(None, outline).center_of_gravity
    body = pymunk.Body(mass, pymunk.moment_for_poly(mass, outline, (-centre.x, -centre.y)))
    body.center_of_gravity = centre
    return body


class PymunkFloor:
    """N LunarLander scenes in one raw pymunk space: the kge env's bodies, joints and
    solver settings with no kge at all (the same geometry constants, origins 32 m apart).
    ``step(actions)`` fires the main engine (a plain impulse at the hull's centre) of the
    landers whose action is 2, then takes the substeps; a lander that leaves its screen
    or lands is put back at the top (its velocity zeroed), so the space stays as busy
    as the env's with its resets."""

    def __init__(self, n: int, seed: int = 0) -> None:
        import pymunk

        from kge.gym import lunar_lander as L
        from kge.gym.lander_vector import SPACING
        from kge.physics.joints.revolute import ITERATED_LIMIT_ERROR_BIAS

        substeps, iterations = L.SOLVER
        self.substeps, self.h = substeps, 1.0 / L.FPS / substeps
        space = self.space = pymunk.Space()
        space.gravity = (0.0, -10.0)
        space.iterations = iterations
        space.collision_slop = 0.005
        space.sleep_time_threshold = 0.5
        space.idle_speed_threshold = 0.01
        rng = np.random.default_rng(seed)
        ground = pymunk.ShapeFilter(categories=1)
        self.hulls: list[Any] = []
        self.parts: list[list[tuple[Any, tuple[float, float], float]]] = []
        for k in range(n):
            ox = k * SPACING
            height = rng.uniform(0, L.H / 2, size=L.CHUNKS + 1)
            height[L.CHUNKS // 2 - 2 : L.CHUNKS // 2 + 3] = L.H / 4
            xs = [ox + L.W / (L.CHUNKS - 1) * i for i in range(L.CHUNKS)]
            ys = [0.33 * (height[i - 1] + height[i] + height[i + 1]) for i in range(L.CHUNKS)]
            segs = [pymunk.Segment(space.static_body, (ox, 0.0), (ox + L.W, 0.0), 0.01)]
            segs += [pymunk.Segment(space.static_body, (xs[i], ys[i]), (xs[i + 1], ys[i + 1]),
                                    0.01) for i in range(L.CHUNKS - 1)]
            for seg in segs:
                seg.friction, seg.filter = 0.1, ground
            space.add(*segs)
            x0, y0 = ox + L.W / 2, L.H
            outline = [(x / L.SCALE, y / L.SCALE) for x, y in L.LANDER_POLY]
            hull = solid(outline, 5.0)
            hull.position = (x0, y0)
            shape = pymunk.Poly(hull, outline, radius=0.01)
            shape.friction = 0.1
            shape.filter = pymunk.ShapeFilter(categories=0x10, mask=1)
            space.add(hull, shape)
            parts = [(hull, (x0, y0), 0.0)]
            for i in (-1, 1):
                hw, hh = L.LEG_W / L.SCALE, L.LEG_H / L.SCALE
                corners = [(-hw, -hh), (hw, -hh), (hw, hh), (-hw, hh)]
                leg = solid(corners, 1.0)
                leg.position, leg.angle = (x0 - i * L.LEG_AWAY / L.SCALE, y0), i * 0.05
                box = pymunk.Poly(leg, corners, radius=0.01)
                box.friction = 0.2
                box.filter = pymunk.ShapeFilter(categories=0x20, mask=1)
                pivot = pymunk.PivotJoint(hull, leg, (0.0, 0.0),
                                          (i * L.LEG_AWAY / L.SCALE, L.LEG_DOWN / L.SCALE))
                pivot.error_bias = 1.0
                motor = pymunk.SimpleMotor(hull, leg, -L.LEG_MOTOR_SPEED * i)
                motor.max_force = L.LEG_SPRING_TORQUE
                lo, hi = L.LEG_TRAVEL
                limit = pymunk.RotaryLimitJoint(hull, leg, *((lo, hi) if i == -1 else (-hi, -lo)))
                limit.error_bias = ITERATED_LIMIT_ERROR_BIAS
                for c in (pivot, motor, limit):
                    c.collide_bodies = False
                space.add(leg, box, pivot, motor, limit)
                parts.append((leg, leg.position, leg.angle))
            self.hulls.append(hull)
            self.parts.append(parts)
        self.origins = np.arange(n) * SPACING

    def step(self, actions: np.ndarray) -> None:
        from kge.gym import lunar_lander as L

        for k in np.flatnonzero(actions == 2).tolist():
            self.hulls[k].apply_impulse_at_local_point((0.0, L.MAIN_ENGINE_POWER * 4 / L.SCALE))
        for _ in range(self.substeps):
            self.space.step(self.h)
        for k, hull in enumerate(self.hulls):
            x, y = hull.position
            if abs(x - self.origins[k] - L.W / 2) > L.W / 2 or y > 3 * L.H or hull.is_sleeping:
                for body, pos, angle in self.parts[k]:
                    body.position, body.angle = pos, angle
                    body.velocity, body.angular_velocity = (0.0, 0.0), 0.0
                    body.activate()


#: calls (batch steps) before the clock starts: random pilots crash or fly off within
#: about 100 steps, so after 150 the envs are in their steady state (some landers in the
#: air, some on the ground, a few resetting). Measured from the first steps, every
#: lander is still falling from the top: at N = 64 that flattered kge (1.2x pybox2d
#: over steps 10-72, 0.92x over steps 10-510), whose resets and ground contacts cost
#: more than pybox2d's.
WARMUP = 150


def steps_per_second(env: Any, mode: str, n: int, env_steps: int, seed: int = 0,
                     warmup: int = WARMUP) -> float:
    """Env steps per second over about ``env_steps`` steps, after ``warmup`` calls."""
    rng = np.random.default_rng(seed)
    calls = max(1, env_steps // n)
    actions = rng.integers(0, 4, size=(calls + warmup, n))
    if mode == "floor":
        env = PymunkFloor(n, seed)
        step = env.step
    elif mode == "single":
        env.reset(seed=seed)

        def step(a: np.ndarray) -> None:
            _, _, term, trunc, _ = env.step(int(a[0]))
            if term or trunc:
                env.reset()
    else:
        env.reset(seed=seed)

        def step(a: np.ndarray) -> None:
            env.step(a)
    for a in actions[:warmup]:
        step(a)
    start = time.perf_counter()
    for a in actions[warmup:]:
        step(a)
    return calls * n / (time.perf_counter() - start)


def measure(sizes: tuple[int, ...] = SIZES, env_steps: int = 4000,
            repeats: int = 3, warmup: int = WARMUP) -> list[dict[str, Any]]:
    """Median env steps per second per variant, repeats interleaved across variants.

    Each measurement builds its env, measures and closes it, so no variant runs with the
    others' objects on the heap (Python's cycle collector walks the whole heap: 64 kge
    Apps kept alive for a later variant slowed every allocating variant by up to 2.5x).
    """
    chosen = variants(sizes)
    samples: dict[tuple[str, str, int], list[float]] = {v: [] for v in chosen}
    before = os.getloadavg()[0]
    for r in range(repeats):
        for v in chosen:
            env = None if v[1] == "floor" else _make(*v)
            gc.collect()
            try:
                samples[v].append(steps_per_second(env, v[1], v[2], env_steps, seed=r,
                                                   warmup=warmup))
            finally:
                if env is not None:
                    env.close()
    load = (before, os.getloadavg()[0])  # the machine is shared: say how busy it was
    return [{"engine": e, "mode": m, "n": n, "steps_per_s": statistics.median(samples[(e, m, n)]),
             "load": load} for e, m, n in chosen]


class Exclusive:
    """Wall time per part of a step, each part timed *exclusive* of the parts it calls.

    The parts are wrapped on their instances (or, for a module's function, on the
    module, restored by :meth:`restore`), so kge carries no timing code. A wrapper
    costs about half a microsecond per call; unlike cProfile, it leaves numpy's
    many short calls at their real cost (cProfile's overhead, scaled out evenly,
    under-counted the joint batch by 3x).
    """

    def __init__(self, clock: Callable[[], float] = time.perf_counter) -> None:
        self.acc: dict[str, float] = {}
        self.clock = clock  #: seconds (a test passes a fake clock)
        self._stack: list[float] = []
        self._undo: list[tuple[Any, str, Any]] = []

    def wrap(self, obj: Any, name: str, key: str) -> None:
        inner = getattr(obj, name)
        acc, stack, clock = self.acc, self._stack, self.clock
        acc.setdefault(key, 0.0)

        def timed(*args: Any, **kwargs: Any) -> Any:
            t0 = clock()
            stack.append(0.0)
            try:
                return inner(*args, **kwargs)
            finally:
                spent = clock() - t0
                acc[key] += spent - stack.pop()
                if stack:
                    stack[-1] += spent

        self._undo.append((obj, name, inner))
        setattr(obj, name, timed)

    def restore(self) -> None:
        for obj, name, inner in reversed(self._undo):
            setattr(obj, name, inner)
        self._undo.clear()


def breakdown(n: int, env_steps: int = 4000, warmup: int = WARMUP) -> str:
    """Where an env step goes at ``n`` envs (the batched env; ``n`` = 1: one env from
    ``gymnasium.make``, the single-env layout of RLlib and SB3), random actions, resets
    as episodes end, after ``warmup`` steps: time per part, each exclusive of the parts it
    calls (the game thread's CPU time: steadier than wall time on a shared machine)."""
    from kge.gym import lander_vector, lunar_lander
    from kge.systems.physics import PhysicsSystem

    single = n == 1
    env = _make("kge", "single" if single else "batched", n)
    rng = np.random.default_rng(0)
    calls = max(1, env_steps // n)
    actions = rng.integers(0, 4, size=(calls + warmup, n))
    env.reset(seed=0)

    def step(a: np.ndarray) -> None:
        if not single:
            env.step(a)
            return
        _, _, terminated, truncated, _ = env.step(int(a[0]))
        if terminated or truncated:
            env.reset()

    for a in actions[:warmup]:
        step(a)
    inner = env.unwrapped
    sim = inner.world.get_system(PhysicsSystem).sim
    parts = Exclusive(time.thread_time)
    if single:
        parts.wrap(inner, "reset", "env resets: a new scene (world, plugins, bodies)")
        parts.wrap(lunar_lander, "fire_one", "engine impulses: geometry, apply_linear_impulse")
        parts.wrap(inner, "_observe", "observation: components read, floats, checks")
        parts.wrap(inner, "reward", "reward: shaping")
    else:
        parts.wrap(env, "_respawn", "scene resets: re-lay the finished envs' scenes")
        parts.wrap(lander_vector, "fire",
                   "engine impulses: numpy geometry, Physics.apply_linear_impulses")
    # on the classes: a reset of the single env makes a new world (and simulation)
    sim_cls, joints_cls = type(sim), type(sim.joints)
    parts.wrap(sim_cls, "sync_in", "physics sync-in: the resets' and impulses' changes into pymunk")
    parts.wrap(joints_cls, "before_step", "joints before the step")
    if sim.ccd is not None:
        parts.wrap(type(sim.ccd), "before_step", "continuous collision before the step")
    parts.wrap(type(sim._speed_cap), "before_substep", "speed caps between substeps")
    parts.wrap(type(sim.space), "step",
               "pymunk space.step: the solver (C), kge's contact callbacks")
    parts.wrap(joints_cls, "after_step", "joints after the step: position pass, read-back")
    parts.wrap(sim_cls, "sync_out", "physics sync-out: bulk pose read, component write-back")
    parts.wrap(sim_cls, "step", "physics step: the rest of Simulation.step")
    gc.collect()
    start = time.thread_time()
    for a in actions[warmup:]:
        step(a)
    real = (time.thread_time() - start) / (calls * n) * 1e6
    parts.restore()
    env.close()
    per_step = 1e6 / (calls * n)
    what = "gymnasium.make LunarLander" if single else f"batched LunarLander, N = {n}"
    lines = [f"{what}: {real:.1f} µs per env step ({1e6 / real:,.0f} steps/s), "
             f"load average {os.getloadavg()[0]:.2f}",
             "| part | µs per env step | share |", "|---|---:|---:|"]
    accounted = 0.0
    for label, t in parts.acc.items():
        t *= per_step
        accounted += t
        lines.append(f"| {label} | {t:.1f} | {t / real:.0%} |")
    rest = real - accounted
    lines.append(f"| the rest: App frame, schedule and systems, Gymnasium's wrappers, the "
                 f"env's numpy, contacts | {rest:.1f} | {rest / real:.0%} |")
    lines.append("(game-thread CPU time, each part exclusive of the parts it calls; the "
                 "timers cost about 0.5 µs per call)")
    return "\n".join(lines)


def single_ratio(rows: list[dict[str, Any]]) -> float | None:
    """kge/LunarLander-v0 / pybox2d LunarLander-v3, one env each (None if either is missing)."""
    by = {(r["engine"], r["mode"]): r["steps_per_s"] for r in rows if r["mode"] == "single"}
    kge, box2d = by.get(("kge", "single")), by.get(("box2d", "single"))
    return None if kge is None or box2d is None else kge / box2d


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
        engine = "pymunk" if mode == "floor" else "kge"
        other = "sync" if mode in ("batched", "floor") else mode
        k, b = by.get((engine, mode, n)), by.get(("box2d", other, n))
        label = {"single": "gymnasium.make", "batched": "kge batched (make_vec)",
                 "sync": "SyncVectorEnv", "floor": "floor: raw pymunk, no kge"}[mode]
        vs = "pybox2d SyncVectorEnv" if other == "sync" and mode != "sync" else "pybox2d"
        r = "-" if k is None or b is None else f"{k / b:.2f} (vs {vs})"
        lines.append((label, str(n), cell(engine, mode, n), cell("box2d", other, n), r))
    loads = [r["load"] for r in rows if "load" in r]
    note = ("" if not loads else f"\n\nload average before / after the run: {loads[0][0]:.2f} / "
            f"{loads[0][1]:.2f} ({os.cpu_count()} cores); the floor is raw pymunk stepping "
            "the same bodies, joints and solver settings with no kge")
    if markdown:
        out = ["| " + " | ".join(head) + " |", "|---|---:|---:|---:|---:|"]
        out += ["| " + " | ".join(cols) + " |" for cols in lines]
        return "\n".join(out) + note
    widths = [max(len(c[i]) for c in [head, *lines]) for i in range(len(head))]
    return "\n".join("  ".join(c[i].rjust(widths[i]) for i in range(len(head)))
                     for c in [head, *lines]) + note


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=(__doc__ or "").split("\n")[0])
    parser.add_argument("--sizes", type=int, nargs="+", default=list(SIZES))
    parser.add_argument("--steps", type=int, default=4000, help="env steps per measurement")
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--warmup", type=int, default=WARMUP,
                        help="batch steps before the clock starts (steady state)")
    parser.add_argument("--markdown", action="store_true", help="print a Markdown table")
    parser.add_argument("--profile", type=int, metavar="N", default=0,
                        help="print where a batched env step goes at N envs instead")
    args = parser.parse_args(argv)
    missing = box2d_lander_missing()
    if missing:
        print(f"skipped {missing}", file=sys.stderr)
    if args.profile:
        print(breakdown(args.profile, args.steps, args.warmup))
        return 0
    print(table(measure(tuple(args.sizes), args.steps, args.repeats, args.warmup),
                args.markdown))
    return 0


if __name__ == "__main__":
    sys.exit(main())
