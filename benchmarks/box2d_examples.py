"""pybox2d's testbed examples on pybox2d and on kge.box2d, in one run.

Every example of the installed pybox2d wheel runs headless through
``kge.box2d.testbed`` (the same framework stand-in for both engines) for
``frames`` frames, pressing each key its source handles (held 20 frames, one
every 40 frames from frame 60) and then space. A row gives, per engine, whether
it ran to the end and its seconds; then the frame rate ratio. Then the two
examples whose outcome the side-by-side tests compare: where the one-sided
platform's character is after 3 s, and where the breakable body's pieces rest.
Then sleep: each example left alone (no key pressed) for ``frames`` frames, how
many of its dynamic bodies are awake at the end and from which frame on all of
them slept, per engine (Box2D's rule: an island sleeps once every body in it
rested ``b2_timeToSleep``).

``python -m benchmarks.box2d_examples [FRAMES]`` prints the markdown kept in
``benchmarks/results/box2d_examples.md``.
"""

from __future__ import annotations

import contextlib
import io
import sys
import time
from typing import Any

from kge.box2d.testbed import examples
from kge.box2d.testbed.headless import HeadlessBackend
from kge.box2d.testbed.presses import Press


def presses(name: str) -> list[Press]:
    """Each key the example's source names (``Keys.K_*``), then space."""
    keys = [*examples.keys_handled(name), "SPACE"]
    return [Press(60 + 40 * i, key, hold=20) for i, key in enumerate(keys)]


def run(name: str, engine: str, frames: int, backend: Any = None) -> tuple[Any, float, str]:
    """(backend, seconds, error or "") of one example on one engine."""
    backend = backend or HeadlessBackend(frames, presses(name))
    started = time.perf_counter()
    try:
        with contextlib.redirect_stdout(io.StringIO()):
            examples.run(name, backend, engine)
    except Exception as e:  # reported in the table
        return backend, time.perf_counter() - started, f"{type(e).__name__}: {e}"
    return backend, time.perf_counter() - started, ""


class _Traced(HeadlessBackend):
    def run(self, test: Any) -> None:
        self.test = test
        for _ in range(self.frames):
            test.Frame()
            self.frames_run += 1


class _Sleep(HeadlessBackend):
    """Headless frames, counting the awake dynamic bodies after each."""

    def run(self, test: Any) -> None:
        self.test = test
        self.awake: list[int] = []
        for _ in range(self.frames):
            test.Frame()
            self.frames_run += 1
            self.awake.append(sum(1 for b in test.world.bodies if b.type == 2 and b.awake))


#: examples too slow for the sleep table on kge.box2d (minutes each), and ones whose
#: bodies keep moving by design on both engines (a motor turns, a tumbler spins)
SLEEP_SKIPPED = ("cloth", "liquid", "pyramid", "tiles", "tumbler", "vertical_stack")


def sleep_cell(name: str, engine: str, frames: int) -> str:
    """``awake of dynamic, asleep from frame F`` for one example left alone."""
    backend, _, error = run(name, engine, frames, _Sleep(frames, []))
    if error:
        return f"stopped: {error}"
    dynamic = sum(1 for b in backend.test.world.bodies if b.type == 2)
    if not dynamic:
        return "no dynamic body"
    last = max((i for i, n in enumerate(backend.awake) if n), default=-1)
    since = f", all asleep from frame {last + 1}" if last + 1 < frames else ""
    return f"{backend.awake[-1]} of {dynamic} awake{since}"


def sleep_rows(frames: int) -> list[str]:
    """The sleep table's rows: every example but :data:`SLEEP_SKIPPED`, both engines."""
    rows = []
    for name in examples.names():
        if name not in SLEEP_SKIPPED:
            rows.append(f"| {name} | {sleep_cell(name, 'pybox2d', frames)} | "
                        f"{sleep_cell(name, 'kge', frames)} |")
    return rows


def outcomes() -> list[str]:
    """The one-sided platform's character height and the breakable pieces' rest."""
    rows = []
    for engine in ("pybox2d", "kge"):
        backend, _, error = run("one_sided_platform", engine, 180, _Traced(180))
        body = backend.test.character.body
        rows.append(f"| one-sided platform, character y at 3 s | {engine} | "
                    f"{body.position.y:.3f} m{' ' + error if error else ''} |")
    for engine in ("pybox2d", "kge"):
        backend, _, error = run("breakable", engine, 240, _Traced(240))
        pieces = sorted((b.position.x, b.position.y) for b in backend.test.world.bodies
                        if b.type == 2)
        where = ", ".join(f"({x:.2f}, {y:.2f})" for x, y in pieces)
        rows.append(f"| breakable, pieces at 4 s | {engine} | {where} |")
    return rows


def table(frames: int = 600) -> str:
    lines = [f"pybox2d's testbed examples, {frames} frames each, headless, keys pressed:", "",
             "| example | pybox2d | kge.box2d | kge / pybox2d frame rate |", "|---|---|---|---|"]
    order = ("pybox2d", "kge")  # the columns'
    done = dict.fromkeys(order, 0)
    for name in examples.names():
        cells, seconds = [], {}
        for engine in order:
            backend, spent, error = run(name, engine, frames)
            ran = not error and backend.frames_run == frames
            done[engine] += ran
            seconds[engine] = spent
            cells.append(f"ran, {spent:.1f} s" if ran else f"stopped: {error}")
        ratio = seconds["pybox2d"] / seconds["kge"] if seconds["kge"] > 0 else 0.0
        lines.append(f"| {name} | {cells[0]} | {cells[1]} | {ratio:.2f}x |")
    lines += ["", f"ran to the end: pybox2d {done['pybox2d']}, kge.box2d {done['kge']} "
              f"of {len(examples.names())}", "",
              "| outcome | engine | value |", "|---|---|---|", *outcomes(), "",
              f"Sleep, {frames} frames with no key pressed (skipped: "
              f"{', '.join(SLEEP_SKIPPED)}):", "",
              "| example | pybox2d | kge.box2d |", "|---|---|---|", *sleep_rows(frames)]
    return "\n".join(lines)


if __name__ == "__main__":
    print(table(int(sys.argv[1]) if sys.argv[1:] else 600))
