"""The runnable examples of docs/particles-lights.md run and their asserts hold."""

import re
from pathlib import Path

import pytest

PAGE = Path(__file__).resolve().parents[1] / "docs" / "particles-lights.md"
BLOCKS = re.findall(r"<!-- runnable -->\n```python\n(.*?)```", PAGE.read_text(), re.S)


def test_the_page_has_runnable_examples_and_its_images() -> None:
    assert len(BLOCKS) >= 3
    for image in re.findall(r"\]\((images/[^)]+)\)", PAGE.read_text()):
        assert (PAGE.parent / image).is_file(), image


@pytest.mark.parametrize("code", BLOCKS, ids=[f"block{i}" for i in range(len(BLOCKS))])
def test_page_example_runs(code: str) -> None:
    exec(compile(code, "particles-lights.md", "exec"), {"__name__": "docs"})
