"""Where the installed pybox2d wheel keeps its own tests and testbed examples.

pybox2d 2.3.10's wheel (the ``box2d`` distribution) ships ``Box2D/tests`` and
``Box2D/examples``. kge runs them unmodified against kge.box2d (its test suite,
``python -m kge.box2d.testbed``) and finds them through the distribution's
metadata, without importing pybox2d: nothing of pybox2d is copied into kge.
"""

from __future__ import annotations

from importlib import metadata
from pathlib import Path

#: the distribution that installs ``import Box2D`` (pybox2d)
DISTRIBUTION = "box2d"


def pybox2d_dir(part: str) -> Path | None:
    """The installed wheel's ``Box2D/<part>`` directory, or None when pybox2d (with that
    directory) is not installed."""
    try:
        dist = metadata.distribution(DISTRIBUTION)
    except metadata.PackageNotFoundError:
        return None
    path = Path(str(dist.locate_file(f"Box2D/{part}")))
    return path if path.is_dir() else None


def pybox2d_version() -> str | None:
    """The installed pybox2d's version ("2.3.10"), or None."""
    try:
        return metadata.version(DISTRIBUTION)
    except metadata.PackageNotFoundError:
        return None
