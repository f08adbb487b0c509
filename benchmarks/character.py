"""Character controllers beside the same bodies as plain dynamic bodies.

N capsules (0.6 x 1.8 m) walk back and forth on hilly ground (slopes up to 20
degrees), turning every two seconds; their game code writes their velocity every
fixed step, as a player's or an enemy's script does. Three worlds, built the same and
stepped interleaved (a block of steps each in turn, so background load hits all
alike), timed per fixed step (``App.step``: behaviours, characters, physics, events):

* ``characters``: N ``CharacterBody`` (collide and slide, floors, snapping, flags);
* ``dynamic``: N dynamic bodies of the same outline (fixed rotation, no friction)
  whose script writes ``RigidBody.velocity`` (run speed, the fall kept): what a game
  without a controller does;
* ``kinematic``: N kinematic bodies given the same walking velocities in one
  ``Physics.set_velocities`` call (no collision handling at all): the floor of the
  physics cost of N moving bodies, so ``characters - kinematic`` is what the
  controller itself costs.

Medians in ms per step; ``ratio`` is characters / dynamic. Quality figures: how many
characters stand on the ground at the end and the deepest any dynamic body sank into
it (the controller never sinks). Run ``python benchmarks/character.py --size 1000``.
"""

from __future__ import annotations

import argparse
import math
import os
import statistics
import sys
import time
from typing import Any

os.environ.setdefault("PYGLET_HEADLESS", "1")

if __package__ in (None, ""):  # run as a script: make the repository importable
    sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))

import numpy as np

SPEED = 3.0
TURN = 120  # steps between turns
SPACING = 1.5


def _terrain(n: int) -> list[tuple[float, float]]:
    """Gentle hills under n characters (slopes below 20 degrees)."""
    width = n * SPACING + 20.0
    xs = np.arange(-10.0, width + 1e-9, 1.0)
    ys = 0.6 * np.sin(xs * 0.5) + 0.3 * np.sin(xs * 1.3)
    return [(float(x), float(y)) for x, y in zip(xs, ys, strict=True)]


def _scene(kind: str, n: int) -> Any:
    from kge import (
        BodyType,
        Capsule,
        Chain,
        CharacterBody,
        Collider,
        RigidBody,
        Transform,
        World,
    )
    from kge.systems.character import collider_shape

    def scene(world: World) -> None:
        hills = _terrain(n)
        world.spawn(Transform(), Collider(Chain(hills), friction=0.6))
        xs, ys = zip(*hills, strict=True)
        shape = Capsule(0.3, 0.9)
        for k in range(n):  # a little above the ground under each
            pose = Transform(k * SPACING, float(np.interp(k * SPACING, xs, ys)) + 1.0)
            if kind == "characters":
                world.spawn(pose, CharacterBody(shape))
            elif kind == "dynamic":
                world.spawn(pose, RigidBody(fixed_rotation=True),
                            Collider(collider_shape(shape, 0.0), friction=0.0, density=80.0))
            else:
                world.spawn(pose, RigidBody(type=BodyType.KINEMATIC),
                            Collider(collider_shape(shape), friction=0.0))

    return scene


class _World:
    """One of the three worlds and how its game code drives it each step."""

    def __init__(self, kind: str, n: int) -> None:
        from kge import (
            App,
            BehaviourPlugin,
            CharacterBody,
            CharacterPlugin,
            Physics,
            PhysicsPlugin,
            RigidBody,
        )

        self.kind = kind
        self.app = App(_scene(kind, n), headless=True,
                       plugins=[PhysicsPlugin(), CharacterPlugin(), BehaviourPlugin()])
        world = self.app.world
        ctype: type[Any] = CharacterBody if kind == "characters" else RigidBody
        found = sorted(world.query(ctype))
        self.entities = np.array([e for e, _ in found], dtype=np.int64)
        self.components: list[Any] = [c for _, (c,) in found]
        self.physics = world.resource(Physics)
        self.tick = 0

    def step(self) -> None:
        vx = SPEED if (self.tick // TURN) % 2 == 0 else -SPEED
        self.tick += 1
        if self.kind == "kinematic":
            v = np.zeros((len(self.entities), 2))
            v[:, 0] = vx
            self.physics.set_velocities(self.entities, v)
        else:  # the game's script: run, keep the fall
            for c in self.components:
                c.velocity = (vx, c.velocity[1])
        self.app.step()

    def quality(self) -> dict[str, float]:
        from kge import CharacterBody, Transform

        world = self.app.world
        if self.kind == "characters":
            standing = sum(world.get(int(e), CharacterBody).on_floor for e in self.entities)
            return {"standing": float(standing)}
        terrain = _terrain(len(self.entities))
        xs = np.array([p[0] for p in terrain])
        ys = np.array([p[1] for p in terrain])
        sink = 0.0
        for e in self.entities.tolist():
            t = world.get(e, Transform)
            ground = float(np.interp(t.x, xs, ys))
            sink = max(sink, ground - (t.y - 0.9))
        return {"deepest_sink_m": round(sink, 4)}

    def close(self) -> None:
        self.app.close()


def measure(n: int, frames: int = 120, warmup: int = 30, blocks: int = 6) -> dict[str, float]:
    """Median ms per fixed step of each world (and the ratio), measured interleaved."""
    worlds = {kind: _World(kind, n) for kind in ("characters", "dynamic", "kinematic")}
    try:
        for w in worlds.values():
            for _ in range(warmup):
                w.step()
        samples: dict[str, list[float]] = {k: [] for k in worlds}
        per_block = max(1, frames // blocks)
        for _ in range(blocks):
            for kind, w in worlds.items():
                for _ in range(per_block):
                    t0 = time.perf_counter()
                    w.step()
                    samples[kind].append(time.perf_counter() - t0)
        out: dict[str, float] = {"size": float(n)}
        for kind, values in samples.items():
            out[f"{kind}_ms"] = statistics.median(values) * 1e3
        out["ratio"] = out["characters_ms"] / out["dynamic_ms"]
        out["controller_ms"] = out["characters_ms"] - out["kinematic_ms"]
        for w in worlds.values():
            for key, value in w.quality().items():
                out[f"{w.kind}_{key}"] = value
        out["loadavg"] = os.getloadavg()[0]
        return out
    finally:
        for w in worlds.values():
            w.close()


def run_section(quick: bool, progress: Any) -> tuple[dict[str, float], str | None]:
    """The figures for ``kge bench`` (100 characters with --quick), or why they are missing."""
    n = 100 if quick else 1000
    progress(f"characters [{n} controllers beside {n} dynamic bodies]")
    try:
        return measure(n, frames=24 if quick else 120, warmup=10 if quick else 30,
                       blocks=2 if quick else 6), None
    except Exception as err:  # report, never fail the whole run
        return {}, f"characters skipped: {type(err).__name__}: {err}"


def targets(r: dict[str, float]) -> list[dict[str, Any]]:
    """The character controller's target beside the measured figure."""
    n = int(r.get("size", 0))
    value = r.get("ratio")
    return [{
        "target": f"{n:,} character controllers / {n:,} dynamic bodies, ms per step",
        "value": value, "goal": 2.0, "at_most": True, "unit": "",
        "met": None if value is None or math.isnan(value) else value <= 2.0,
    }]


def table(r: dict[str, float]) -> str:
    keys = ("size", "characters_ms", "dynamic_ms", "kinematic_ms", "controller_ms", "ratio",
            "characters_standing", "dynamic_deepest_sink_m", "loadavg")
    return "  ".join(f"{k} {r[k]:.4g}" for k in keys if k in r)


def markdown_lines(r: dict[str, float]) -> list[str]:
    n = int(r["size"])
    return ["", f"Character controllers: {n:,} capsules walking on hills, ms per fixed step "
            "(median, interleaved; `kinematic`: the same bodies moved with no collision "
            "handling):", "",
            "| N | characters | dynamic bodies | kinematic bodies | controller | characters / "
            "dynamic | standing | deepest dynamic sink (m) |",
            "|---:|---:|---:|---:|---:|---:|---:|---:|",
            f"| {n:,} | {r['characters_ms']:.2f} | {r['dynamic_ms']:.2f} | "
            f"{r['kinematic_ms']:.2f} | {r['controller_ms']:.2f} | {r['ratio']:.2f} | "
            f"{r.get('characters_standing', float('nan')):.0f} | "
            f"{r.get('dynamic_deepest_sink_m', float('nan')):.3f} |"]


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=(__doc__ or "").split("\n")[0])
    parser.add_argument("--size", type=int, default=1000)
    parser.add_argument("--frames", type=int, default=120)
    args = parser.parse_args(argv)
    print(table(measure(args.size, frames=args.frames)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
