"""``kge export [PROJECT]``: build a standalone copy of a game (see :mod:`kge.export`)."""

from __future__ import annotations

import argparse

from kge.export.build import ExportError, export, plan


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(
        prog="kge export",
        description="Build a standalone copy of a game project for this machine: one folder "
                    "(or one file) with the game, its assets and the Python runtime.")
    parser.add_argument("project", nargs="?", default=".",
                        help="the game project folder (default: the current one)")
    parser.add_argument("--out", help="where the build goes (default: PROJECT/dist)")
    parser.add_argument("--onefile", action="store_true",
                        help="one executable file instead of a folder")
    parser.add_argument("--name", help="the program's name (default: the project's name)")
    parser.add_argument("--dry-run", action="store_true",
                        help="say what would be built, build nothing")
    args = parser.parse_args(argv)
    try:
        if args.dry_run:
            p = plan(args.project, args.out, onefile=args.onefile, name=args.name)
            print(f"game {p.name}: package {p.package}, {len(p.data)} asset files")
            print(f"would build {p.executable}")
            return 0
        print(f"kge export: building {args.project} with PyInstaller (about a minute)...",
              flush=True)
        exe = export(args.project, args.out, onefile=args.onefile, name=args.name)
    except ExportError as err:
        print(f"kge export: {err}")
        return 1
    print(f"built {exe}")
    return 0
