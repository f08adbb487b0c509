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


@pytest.mark.parametrize("page", sorted((README.parent / "benchmarks" / "results").glob("*.md")))
def test_results_files_link_inside_the_repository(page: Path) -> None:
    for target in re.findall(r"\]\(([^)#\s]+)", page.read_text()):
        if not target.startswith(("http://", "https://")):
            assert (page.parent / target).resolve().exists(), f"{page.name}: {target}"


@pytest.mark.parametrize("page", [README, *sorted((README.parent / "docs").glob("*.md"))])
def test_docs_teach_and_do_not_log(page: Path) -> None:
    """Dates with times, machine loads and issue numbers belong to benchmarks/results/
    and CHANGELOG.md, not to the pages that teach."""
    log = re.compile(r"[0-9]{2}:[0-9]{2} UTC|load average|load [0-9]\.[0-9]|issue [0-9]+")
    assert not log.findall(page.read_text()), page.name
