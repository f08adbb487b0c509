"""Imported first by the examples: run with a Python that has no kge (the system one
instead of the project's ``.venv``), an example says which Python to use instead of
``No module named 'kge'``."""

import sys
from importlib.util import find_spec

if find_spec("kge") is None:
    script = sys.argv[0] or "the example"
    sys.exit(
        f"{script}: this Python ({sys.executable}) has no kge. Run `make test` once in the "
        f"kge folder, then: .venv/bin/python {script}  (or `. .venv/bin/activate` first)"
    )
