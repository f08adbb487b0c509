"""docs/animation.md's snippets marked runnable actually run (and their asserts hold)."""

import re
from pathlib import Path

import pytest

DOC = Path(__file__).resolve().parents[2] / "docs" / "animation.md"
BLOCKS = re.findall(r"<!-- runnable -->\n```python\n(.*?)```", DOC.read_text(), re.S)


def test_the_page_has_runnable_snippets() -> None:
    assert len(BLOCKS) >= 5


@pytest.mark.parametrize("code", BLOCKS, ids=[f"block{i}" for i in range(len(BLOCKS))])
def test_snippet_runs(code: str) -> None:
    exec(compile(code, "docs/animation.md", "exec"), {"__name__": "docs"})
