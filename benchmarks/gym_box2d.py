"""Gymnasium's LunarLander on kge.box2d beside the same environment on pybox2d.

The environment module binds ``Box2D`` when it is imported, so it is loaded
twice under private names: once while ``import Box2D`` gives kge.box2d and once
while it gives real pybox2d. Both copies then run in this one process, stepped
in the harness's interleaved blocks with the environment's own heuristic
controller (an episode that ends is reset with the next seed). A frame is
``size`` environment steps; quality is the mean score of the episodes finished.
"""

from __future__ import annotations

import importlib.util
import sys
from types import ModuleType
from typing import Any

_MODULES: dict[tuple[str, str], ModuleType] = {}


def gymnasium_available() -> str | None:
    """None when Gymnasium is installed, else why not."""
    if importlib.util.find_spec("gymnasium") is None:
        return "gymnasium is not installed"
    return None


def lunar_lander_module(backend: str) -> ModuleType:
    """Gymnasium's lunar_lander module bound to ``backend`` ("kge" or "box2d")."""
    return env_module("lunar_lander", backend)


def env_module(name: str, backend: str) -> ModuleType:
    """Gymnasium's ``gymnasium.envs.box2d.<name>`` module bound to ``backend``
    ("kge" or "box2d"), loaded under a private name so both can live in one process."""
    if (name, backend) in _MODULES:
        return _MODULES[name, backend]
    import kge.box2d

    # the package's path only: importing gymnasium.envs.box2d runs its __init__, which
    # (Gymnasium 1.2) imports every Box2D env, and Box2D before it is bound
    found = importlib.util.find_spec("gymnasium.envs.box2d")
    assert found is not None and found.submodule_search_locations is not None
    package_dir = next(iter(found.submodule_search_locations))

    keys = ("Box2D", "Box2D.b2", "Box2D.Box2D")
    saved = {k: sys.modules.get(k) for k in keys}
    try:
        if backend == "kge":
            kge.box2d.install()
        else:
            for k in keys:
                if saved[k] is not None and saved[k].__name__.startswith("kge"):  # type: ignore[union-attr]
                    del sys.modules[k]
            import Box2D  # noqa: F401  (real pybox2d)
        path = f"{package_dir}/{name}.py"
        spec = importlib.util.spec_from_file_location(f"_{name}_{backend}", path)
        assert spec is not None and spec.loader is not None
        module = importlib.util.module_from_spec(spec)
        spec.loader.exec_module(module)
    finally:
        for k, v in saved.items():
            if v is None:
                sys.modules.pop(k, None)
            else:
                sys.modules[k] = v
    _MODULES[name, backend] = module
    return module


class LanderRunner:
    """``size`` heuristic-controlled LunarLander steps per frame on one backend."""

    def __init__(self, backend: str, size: int) -> None:
        self.module = lunar_lander_module(backend)
        self.env: Any = self.module.LunarLander()
        self.size = size
        self.seed = 0
        self.state, _ = self.env.reset(seed=self.seed)
        self.score = 0.0
        self.scores: list[float] = []

    @property
    def runner(self) -> LanderRunner:
        """The phase breakdown looks for ``runner.app``; there is no kge App here."""
        return self

    def step(self) -> None:
        env, heuristic = self.env, self.module.heuristic
        s = self.state
        for _ in range(self.size):
            s, r, term, trunc, _ = env.step(heuristic(env, s))
            self.score += float(r)
            if term or trunc:
                self.scores.append(self.score)
                self.score = 0.0
                self.seed += 1
                s, _ = env.reset(seed=self.seed)
        self.state = s

    def quality(self) -> dict[str, float]:
        done = self.scores
        return {"episodes": float(len(done)),
                "mean_score": sum(done) / len(done) if done else float("nan")}

    def close(self) -> None:
        self.env.close()


# -- the docs' side-by-side tables and the speed floor ----------------------------------------

#: Gymnasium's time limits (``gym.make``'s ``max_episode_steps``)
LIMITS = {"lunar_lander": 1000, "bipedal_walker": 1600}


def heuristic_episodes(name: str, backend: str, seeds: range, **kwargs: Any) -> list[str]:
    """Each seed's ``score (steps)`` under the environment's own heuristic controller
    (and, for the walker, the hull's final x).

    LunarLander's ``heuristic(env, s)`` is a function; BipedalWalker's
    ``BipedalWalkerHeuristics`` keeps its state machine between episodes, as in
    Gymnasium's own ``__main__`` loop, so one instance plays all seeds in order.
    """
    import numpy as np

    module = env_module(name, backend)
    out = []
    walker = module.BipedalWalkerHeuristics() if name == "bipedal_walker" else None
    for seed in seeds:
        env: Any = module.LunarLander(**kwargs) if walker is None else module.BipedalWalker()
        s, _ = env.reset(seed=seed)
        total, action, steps, term = 0.0, np.zeros(4), 0, False
        while steps < LIMITS[name] and not term:
            steps += 1
            if walker is None:
                action = module.heuristic(env, s)
            s, r, term, _trunc, _ = env.step(action)
            total += float(r)
            if walker is not None:
                action = walker.step_heuristic(s)
        note = "" if term else ", time limit"
        if walker is not None:  # how far it walked: the course ends at x = 88.7 m
            note += f", x = {float(env.hull.position[0]):.1f} m"
        out.append(f"{total:.1f} ({steps}{note})")
        env.close()
    return out


def tables(seeds: range = range(10)) -> str:
    """The docs' markdown tables: pybox2d and kge.box2d side by side, seeds 0-9."""
    runs = [("LunarLander-v3, discrete", "lunar_lander", {"continuous": False}),
            ("LunarLander-v3, continuous", "lunar_lander", {"continuous": True}),
            ("BipedalWalker-v3", "bipedal_walker", {})]
    parts = []
    for title, name, kwargs in runs:
        real = heuristic_episodes(name, "box2d", seeds, **kwargs)
        ours = heuristic_episodes(name, "kge", seeds, **kwargs)
        rows = [f"| {s} | {a} | {b} |" for s, a, b in zip(seeds, real, ours, strict=True)]
        parts.append("\n".join([f"{title}:", "", "| seed | pybox2d | kge.box2d |", "|---|---|---|",
                                *rows]))
    return "\n\n".join(parts)


def floor(steps: int = 3000) -> dict[str, float]:
    """LunarLander's cost per environment step, µs: what no engine-side work can
    remove on kge.box2d, and the rest, with pybox2d's beside it (one process).

    ``*_total``: the whole environment step with the heuristic, episodes reset as
    they end; ``*_gym``: that minus ``b2World.Step`` (Gymnasium's own Python, on
    each backend's objects); ``pymunk``: the time inside pymunk's ``Space.step``
    during kge.box2d's steps (the same lander at the same substeps and
    iterations; timed around each call, so a little high); ``floor``:
    ``pymunk + kge_gym``.
    """
    import time

    import pymunk

    out: dict[str, float] = {}
    in_pymunk = [0.0]
    space_step = pymunk.Space.step

    def timed_space(self: Any, dt: float, _step: Any = space_step,
                    _spent: list[float] = in_pymunk) -> None:
        t = time.perf_counter()
        _step(self, dt)
        _spent[0] += time.perf_counter() - t

    for backend in ("box2d", "kge"):
        runner = LanderRunner(backend, 100)
        world_cls = type(runner.env.world)
        spent = [0.0]
        original = world_cls.Step

        def timed(self: Any, *args: Any, _step: Any = original,
                  _spent: list[float] = spent) -> None:
            t = time.perf_counter()
            _step(self, *args)
            _spent[0] += time.perf_counter() - t

        world_cls.Step = timed
        if backend == "kge":
            pymunk.Space.step = timed_space  # type: ignore[method-assign]
        try:
            t0 = time.perf_counter()
            for _ in range(steps // 100):
                runner.step()
            total = time.perf_counter() - t0
        finally:
            world_cls.Step = original
            pymunk.Space.step = space_step  # type: ignore[method-assign]
        n = steps // 100 * 100
        out[f"{backend}_total"] = total / n * 1e6
        out[f"{backend}_gym"] = (total - spent[0]) / n * 1e6
        if backend == "kge":
            out["pymunk"] = in_pymunk[0] / n * 1e6
        runner.close()
    out["floor"] = out["pymunk"] + out["kge_gym"]
    return out


if __name__ == "__main__":
    if sys.argv[1:] == ["tables"]:
        print(tables())
    else:
        print({k: round(v, 1) for k, v in floor().items()})
