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
