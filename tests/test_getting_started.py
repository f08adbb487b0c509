"""docs/getting-started.md: every step runs as written, in order, in one namespace
(each step continues the previous one, as a reader pasting them would)."""

import re
from pathlib import Path

DOC = Path(__file__).resolve().parents[1] / "docs" / "getting-started.md"
STEPS = re.findall(r"<!-- step -->\n```python\n(.*?)```", DOC.read_text(), re.S)


def test_every_step_runs_in_order() -> None:
    text = DOC.read_text()
    assert len(STEPS) == 6
    assert len(re.findall(r"```python\n", text)) == len(STEPS)  # no step is left untested
    namespace: dict[str, object] = {"__name__": "getting_started"}
    for number, code in enumerate(STEPS, 1):
        exec(compile(code, f"getting-started step {number}", "exec"), namespace)
