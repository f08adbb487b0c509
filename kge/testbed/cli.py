"""``kge testbed`` (also ``python -m kge testbed`` and the README's demo command).

* ``kge testbed --list``: one sample per line, its command-line name first;
* ``kge testbed --headless --sample NAME --frames N --screenshot FILE``: run one sample;
* ``kge testbed`` with a display: the interactive testbed window;
* ``kge testbed`` without a display (or ``--showcase``): run every sample for a few
  simulated seconds, print a summary per sample and write one PNG contact sheet.
"""

from __future__ import annotations

import argparse
import sys
import time
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from kge.app import App, has_display
from kge.testbed.registry import Sample, all_samples, get_sample


@dataclass(slots=True)
class RunSummary:
    """What one headless run of a sample did."""

    name: str
    bodies: int
    asleep: int
    steps: int
    ms_per_step: float

    def line(self) -> str:
        return (
            f"{self.name:<24} bodies {self.bodies:5d}  asleep {self.asleep:5d}  "
            f"steps {self.steps:4d}  {self.ms_per_step:7.3f} ms/step"
        )


def make_app(s: Sample, size: tuple[int, int] = (640, 400), **kwargs: Any) -> App:
    """A headless App running sample ``s`` (with its camera, when rendering)."""
    return App(s.setup, headless=True, size=size, **kwargs)


def summarize(s: Sample, app: App, steps: int, seconds: float) -> RunSummary:
    from kge.components.rigidbody import BodyType, RigidBody

    bodies = [rb for _, (rb,) in app.world.query(RigidBody) if rb.type is not BodyType.STATIC]
    asleep = sum(1 for rb in bodies if not rb.awake)
    return RunSummary(s.slug, len(bodies), asleep, steps, 1000.0 * seconds / max(steps, 1))


def run_one(s: Sample, frames: int, screenshot: str | None = None,
            size: tuple[int, int] = (640, 400)) -> RunSummary:
    """Run ``s`` headless for ``frames`` fixed steps (optionally saving the last frame)."""
    app = make_app(s, size)
    start = time.perf_counter()
    app.step(frames)
    elapsed = time.perf_counter() - start
    if screenshot:
        from kge.testbed.showcase import frame_sample

        frame_sample(app, s)
        app.screenshot(screenshot)
    summary = summarize(s, app, frames, elapsed)
    app.close()
    return summary


def showcase(seconds: float, sheet: str, size: tuple[int, int] = (640, 400)) -> int:
    """Run every sample headless, print summaries and write the contact sheet."""
    from kge.testbed.showcase import contact_sheet, frame_sample, grab

    frames = max(1, round(seconds * 60))
    tiles = []
    samples = all_samples()
    print(f"kge testbed: {len(samples)} samples, {seconds:g} s of simulated time each")
    for i, s in enumerate(samples, 1):
        app = make_app(s, size)
        start = time.perf_counter()
        app.step(frames)
        summary = summarize(s, app, frames, time.perf_counter() - start)
        frame_sample(app, s)
        tiles.append(grab(app))
        app.close()
        print(f"[{i:2d}/{len(samples)}] {summary.line()}", flush=True)
    contact_sheet(tiles, sheet)
    print(f"contact sheet: {sheet}")
    return 0


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="kge testbed", description=__doc__.split("\n")[0])
    parser.add_argument("--list", action="store_true", help="list the samples and exit")
    parser.add_argument("--sample", help="run this sample (see --list)")
    parser.add_argument("--frames", type=int, default=None,
                        help="headless: fixed steps to run (default 180); window: close after N")
    parser.add_argument("--screenshot", help="write a PNG of the last frame")
    parser.add_argument("--headless", action="store_true", help="never open a window")
    parser.add_argument("--showcase", action="store_true", help="run every sample headless")
    parser.add_argument("--seconds", type=float, default=3.0, help="showcase: seconds per sample")
    parser.add_argument("--sheet", default="out/testbed-contact-sheet.png",
                        help="showcase: where to write the contact sheet")
    args = parser.parse_args(argv)

    if args.list:
        for s in all_samples():
            print(f"{s.slug}\t{s.category}\t{s.help}")
        return 0
    headless = args.headless or not has_display()
    if args.sample:
        try:
            s = get_sample(args.sample)
        except KeyError as err:
            print(err.args[0], file=sys.stderr)
            return 2
        if headless:
            print(run_one(s, args.frames or 180, args.screenshot).line())
            if args.screenshot:
                print(f"screenshot: {args.screenshot}")
            return 0
        from kge.testbed.app import run_testbed

        return run_testbed(start=s.slug, frames=args.frames, screenshot=args.screenshot)
    if headless or args.showcase:
        Path(args.sheet).parent.mkdir(parents=True, exist_ok=True)
        return showcase(args.seconds, args.sheet)
    from kge.testbed.app import run_testbed

    return run_testbed(frames=args.frames, screenshot=args.screenshot)


if __name__ == "__main__":
    sys.exit(main())
