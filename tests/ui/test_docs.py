"""The runnable blocks of docs/ui-scenes-input.md run (and their asserts hold)."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

DOC = Path(__file__).resolve().parents[2] / "docs" / "ui-scenes-input.md"
BLOCKS = re.findall(r"<!-- runnable -->\n```python\n(.*?)```", DOC.read_text(), re.S)


def test_the_page_has_runnable_examples_and_its_images_exist() -> None:
    assert len(BLOCKS) >= 6
    for image in re.findall(r"\]\((images/[^)]+)\)", DOC.read_text()):
        assert (DOC.parent / image).is_file(), image


@pytest.mark.parametrize("code", BLOCKS, ids=[f"block{i}" for i in range(len(BLOCKS))])
def test_doc_example_runs(code: str) -> None:
    exec(compile(code, str(DOC), "exec"), {"__name__": "docs"})
