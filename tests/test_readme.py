"""The README's examples marked runnable actually run (and their asserts hold)."""

import re
from pathlib import Path

import pytest

README = Path(__file__).resolve().parents[1] / "README.md"
TEXT = README.read_text()
BLOCKS = re.findall(r"<!-- runnable -->\n```python\n(.*?)```", TEXT, re.S)


def test_the_readme_has_runnable_examples() -> None:
    assert len(BLOCKS) >= 5


def test_every_python_block_of_the_readme_is_run() -> None:
    # a snippet a reader copies must run as written: none may opt out of the test
    assert len(re.findall(r"```python\n", TEXT)) == len(BLOCKS)


@pytest.mark.parametrize("page", [README, *sorted((README.parent / "docs").glob("*.md"))])
def test_no_link_leaves_the_repository(page: Path) -> None:
    text = page.read_text()
    assert "../shared" not in text
    for target in re.findall(r"\]\(([^)#\s]+)", text):
        if not target.startswith(("http://", "https://")):
            path = (page.parent / target).resolve()
            assert path.exists(), target
            assert path.is_relative_to(README.parent), target


@pytest.mark.parametrize("code", BLOCKS, ids=[f"block{i}" for i in range(len(BLOCKS))])
def test_readme_example_runs(code: str) -> None:
    exec(compile(code, "README.md", "exec"), {"__name__": "readme"})
