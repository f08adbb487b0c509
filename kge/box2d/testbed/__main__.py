"""``python -m kge.box2d.testbed NAME``: a pybox2d testbed example, unmodified, on kge.box2d.

With a display the example opens in a window (its keys, the mouse, the testbed's
own keys: z / x zoom, space launches a bomb, arrows pan, Esc quits). Without
one, or with ``--headless``, it steps ``--frames`` frames (600) and prints a
summary. ``--keys 120:b,300:w/60`` presses keys at given frames (and holds them).
pybox2d's testbed options (``--hz 30``, ``--drawAABBs``, ``--no-drawStats``...)
are accepted; ``--engine pybox2d`` runs the same example on the real pybox2d.
"""

from __future__ import annotations

import argparse
import sys
from typing import Any

from kge.box2d.testbed import examples, settings
from kge.box2d.testbed.backends import HEADLESS_FRAMES
from kge.box2d.testbed.presses import parse_presses


def parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(
        prog="python -m kge.box2d.testbed",
        description="Run one of pybox2d's testbed examples unmodified on kge.box2d.")
    p.add_argument("name", nargs="?", help="an example's name (see --list) or a .py file")
    p.add_argument("--list", action="store_true", help="list the examples and exit")
    p.add_argument("--headless", action="store_true",
                   help="step without a window even when there is a display")
    p.add_argument("--frames", type=int, default=None,
                   help=f"frames to run (headless default {HEADLESS_FRAMES}; window: until closed)")
    p.add_argument("--keys", default="", help="scripted presses: FRAME:KEY[/HOLD],...")
    p.add_argument("--screenshot", default=None, help="save the last frame as a PNG")
    p.add_argument("--engine", choices=examples.ENGINES, default="kge",
                   help="kge (kge.box2d, the default) or pybox2d (the real one)")
    settings.options(p.add_argument_group("pybox2d testbed settings"))
    return p


def main(argv: list[str] | None = None) -> int:
    args = parser().parse_args(sys.argv[1:] if argv is None else argv)
    if args.list or not args.name:
        found = examples.names()
        if not found:
            print("pybox2d's examples come from its wheel: pip install 'box2d>=2.3.10,<2.4'",
                  file=sys.stderr)
            return 1 if args.list else 2
        print("\n".join(found))
        return 0
    try:
        presses = parse_presses(args.keys)
    except (KeyError, ValueError) as e:
        print(f"--keys: {e}", file=sys.stderr)
        return 2
    backend = make_backend(args, presses)
    try:
        examples.run(args.name, backend, args.engine, apply=args)
    except (FileNotFoundError, ModuleNotFoundError) as e:  # no such example; no pybox2d
        print(e, file=sys.stderr)
        return 2
    report(args.name, backend)
    return 0


def make_backend(args: argparse.Namespace, presses: list[Any]) -> Any:
    from kge.platform import has_display

    if args.headless or not has_display():
        if args.screenshot:
            from kge.box2d.testbed.window import WindowBackend

            return WindowBackend(args.frames or HEADLESS_FRAMES, presses, args.screenshot,
                                 headless=True)
        from kge.box2d.testbed.headless import HeadlessBackend

        return HeadlessBackend(args.frames or HEADLESS_FRAMES, presses)
    from kge.box2d.testbed.window import WindowBackend

    return WindowBackend(args.frames, presses, args.screenshot)


def report(name: str, backend: Any) -> None:
    """One line for a headless run: frames, bodies (awake), joints, contacts, the last text."""
    test = getattr(backend, "test", None)
    frames = getattr(backend, "frames_run", None)
    if test is None or frames is None:
        return
    world = test.world
    awake = sum(1 for b in world.bodies if b.awake)
    print(f"{name}: {frames} frames in {backend.seconds:.1f} s; {world.bodyCount} bodies "
          f"({awake} awake), {world.jointCount} joints, {world.contactCount} contacts")
    for _x, _y, text, _color in test.text:
        print(f"  {text}")


if __name__ == "__main__":
    raise SystemExit(main())
