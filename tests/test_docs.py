"""The one doc runner: every Python block of README.md and docs/*.md runs in the suite.

A block marked ``<!-- runnable -->`` runs on its own, in a fresh namespace; blocks
marked ``<!-- step -->`` run in order in one namespace per page, each continuing the
previous one as a reader pasting them would (a tutorial). Their asserts must hold.
Blocks marked ``<!-- test-file: NAME -->`` are whole test files, run in a fresh pytest by
``tests/testing/test_docs.py``. A Python block with no mark fails the suite unless its page is listed in
``NOT_YET_RUN`` with exactly that many unmarked blocks: the list only shrinks.
"""

from __future__ import annotations

import os
import re
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
PAGES = [ROOT / "README.md", *sorted((ROOT / "docs").glob("*.md"))]
BLOCK = re.compile(r"(?:<!-- (runnable|step|test-file)(?:: \S+)? -->\n)?```python\n(.*?)```", re.S)

#: pages whose older snippets are not run yet, with how many: convert them, never add
NOT_YET_RUN: dict[str, int] = {}


def _name(page: Path) -> str:
    return page.relative_to(ROOT).as_posix()


def _blocks(page: Path) -> list[tuple[str, str]]:
    return [(mark, code) for mark, code in BLOCK.findall(page.read_text())]


RUNNABLE = [
    pytest.param(page, code, id=f"{_name(page)}#{i}")
    for page in PAGES
    for i, (mark, code) in enumerate(_blocks(page))
    if mark == "runnable"
]
TUTORIALS = [
    pytest.param(page, id=_name(page))
    for page in PAGES
    if any(mark == "step" for mark, _ in _blocks(page))
]


def _run(code: str, filename: str, namespace: dict[str, object]) -> None:
    # a pybox2d page may install kge.box2d as ``Box2D``: leave sys.modules as found
    saved = {k: sys.modules.get(k) for k in ("Box2D", "Box2D.b2", "Box2D.Box2D")}
    cwd = os.getcwd()  # a snippet may change folder (into a temporary one, say)
    try:
        exec(compile(code, filename, "exec", dont_inherit=True), namespace)
    finally:
        os.chdir(cwd)
        for k, v in saved.items():
            if v is None:
                sys.modules.pop(k, None)
            else:
                sys.modules[k] = v


@pytest.mark.parametrize(("page", "code"), RUNNABLE)
def test_runnable_block(page: Path, code: str) -> None:
    _run(code, _name(page), {"__name__": "docs"})


@pytest.mark.parametrize("page", TUTORIALS)
def test_tutorial_steps_run_in_order(page: Path) -> None:
    namespace: dict[str, object] = {"__name__": "docs"}
    steps = [code for mark, code in _blocks(page) if mark == "step"]
    for number, code in enumerate(steps, 1):
        _run(code, f"{_name(page)} step {number}", namespace)


@pytest.mark.parametrize("page", PAGES, ids=_name)
def test_every_python_block_is_run(page: Path) -> None:
    unmarked = sum(1 for mark, _ in _blocks(page) if not mark)
    assert unmarked == NOT_YET_RUN.get(_name(page), 0), (
        f"{_name(page)} has {unmarked} Python blocks with no runnable, step or test-file mark"
    )


def test_the_pending_list_names_real_pages() -> None:
    names = {_name(p) for p in PAGES}
    assert set(NOT_YET_RUN) <= names


@pytest.mark.parametrize("page", PAGES, ids=_name)
def test_every_image_exists(page: Path) -> None:
    for image in re.findall(r"!\[[^\]]*\]\(([^)\s]+)\)", page.read_text()):
        if not image.startswith(("http://", "https://")):
            assert (page.parent / image).is_file(), f"{_name(page)}: {image}"
