"""docs/api.md lists every public name of kge (``kge.__all__``) exactly once, and each
name it lists exists."""

from __future__ import annotations

import re
from collections import Counter
from pathlib import Path

import kge

PAGE = Path(__file__).resolve().parents[2] / "docs" / "api.md"


def _table_names() -> list[str]:
    return re.findall(r"^\| `([A-Za-z_][A-Za-z0-9_]*)` \|", PAGE.read_text(), re.M)


def test_the_api_table_lists_every_public_name_once() -> None:
    names = _table_names()
    twice = sorted(n for n, k in Counter(names).items() if k > 1)
    assert twice == [], f"listed more than once in docs/api.md: {twice}"
    assert sorted(set(kge.__all__) - set(names)) == [], "public names missing from docs/api.md"
    assert sorted(set(names) - set(kge.__all__)) == [], "docs/api.md lists names kge lacks"


def test_every_public_name_resolves_and_all_has_no_duplicate() -> None:
    assert len(kge.__all__) == len(set(kge.__all__))
    for name in kge.__all__:
        assert getattr(kge, name) is not None, name
