"""docs/box2d.md's runnable examples run (and their asserts hold)."""

import re
import sys
from pathlib import Path

import pytest

DOC = Path(__file__).resolve().parents[2] / "docs" / "box2d.md"
BLOCKS = re.findall(r"<!-- runnable -->\n```python\n(.*?)```", DOC.read_text(), re.S)


def test_the_page_has_runnable_examples() -> None:
    assert len(BLOCKS) >= 2


@pytest.mark.parametrize("code", BLOCKS, ids=[f"block{i}" for i in range(len(BLOCKS))])
def test_doc_example_runs(code: str) -> None:
    saved = {k: sys.modules.get(k) for k in ("Box2D", "Box2D.b2", "Box2D.Box2D")}
    try:
        exec(compile(code, "docs/box2d.md", "exec"), {"__name__": "doc"})
    finally:
        for k, v in saved.items():
            if v is None:
                sys.modules.pop(k, None)
            else:
                sys.modules[k] = v
