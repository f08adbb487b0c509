"""docs/testing.md: each test file it shows runs green in a fresh pytest that finds kge's
plugin through its entry point; the golden workflow fails, writes, compares and updates."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

pytest_plugins = ["pytester"]

DOC = Path(__file__).resolve().parents[2] / "docs" / "testing.md"
FILES = re.findall(r"<!-- test-file: (\S+) -->\n```python\n(.*?)```", DOC.read_text(), re.S)


def test_the_doc_shows_test_files() -> None:
    assert [name for name, _ in FILES] == ["test_player.py", "test_bounce.py", "test_look.py"]


@pytest.mark.parametrize(("name", "code"), FILES[:2], ids=[n for n, _ in FILES[:2]])
def test_doc_test_file_passes(pytester: pytest.Pytester, name: str, code: str) -> None:
    pytester.makepyfile(**{name[:-3]: code})
    result = pytester.runpytest_subprocess("-q", "-p", "no:cacheprovider")
    result.assert_outcomes(passed=code.count("\ndef test_"))


def test_golden_workflow(pytester: pytest.Pytester) -> None:
    name, code = FILES[2]
    pytester.makepyfile(**{name[:-3]: code})
    first = pytester.runpytest_subprocess("-q", "-p", "no:cacheprovider")
    first.assert_outcomes(failed=1)  # no golden yet: written, and the run says so
    first.stdout.fnmatch_lines(["*no golden image at *sun.png: wrote it from this run*"])
    golden = pytester.path / "goldens" / "sun.png"
    assert golden.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    pytester.runpytest_subprocess("-q", "-p", "no:cacheprovider").assert_outcomes(passed=1)
    # the game changes colour: the comparison fails and shows this run's frame
    test_file = pytester.path / name
    test_file.write_text(code.replace("(255, 200, 0)", "(0, 120, 255)"))
    changed = pytester.runpytest_subprocess("-q", "-p", "no:cacheprovider")
    changed.assert_outcomes(failed=1)
    changed.stdout.fnmatch_lines(["*sun.png: *% of the pixels differ by more than 8*"])
    assert (pytester.path / "goldens" / "sun.actual.png").exists()
    # accepted on purpose: the goldens follow
    update = pytester.runpytest_subprocess("-q", "-p", "no:cacheprovider", "--kge-update-goldens")
    update.assert_outcomes(passed=1)
    pytester.runpytest_subprocess("-q", "-p", "no:cacheprovider").assert_outcomes(passed=1)
