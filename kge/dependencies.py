"""Fail early, and kindly, when kge is imported by a Python that lacks its dependencies.

The usual case is the system Python run in a checkout (``python -m kge testbed``)
instead of the virtual environment ``make test`` made: rather than a bare
``No module named 'esper'`` from deep inside the package, the error says which
Python it was and what to use instead.
"""

from __future__ import annotations

import sys
from importlib.util import find_spec

REQUIRED = ("esper", "numpy", "pymunk", "pyglet", "soundfile")

for _name in REQUIRED:
    if find_spec(_name) is None:
        raise ModuleNotFoundError(
            f"kge needs {_name}, which this Python ({sys.executable}) does not have: "
            "use the virtual environment `make test` made (.venv/bin/python, or "
            "`. .venv/bin/activate`), or `pip install -e path/to/kge`",
            name=_name,
        )
