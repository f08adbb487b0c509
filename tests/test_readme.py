"""The README and docs pages link only inside the repository (their code blocks run
through the shared doc runner, tests/test_docs.py)."""

import re
from pathlib import Path

import pytest

README = Path(__file__).resolve().parents[1] / "README.md"


@pytest.mark.parametrize("page", [README, *sorted((README.parent / "docs").glob("*.md"))])
def test_no_link_leaves_the_repository(page: Path) -> None:
    text = page.read_text()
    assert "../shared" not in text
    for target in re.findall(r"\]\(([^)#\s]+)", text):
        if not target.startswith(("http://", "https://")):
            path = (page.parent / target).resolve()
            assert path.exists(), target
            assert path.is_relative_to(README.parent), target
