"""Bad input: a clear error at the call, naming what is wrong, and an unchanged world.

The cases live in :mod:`tests.reliability.catalogue`, which also renders the
table of ``docs/reliability.md``; the last test keeps that table in sync.
"""

from __future__ import annotations

import pytest

from kge.errors import KgeError

from .catalogue import CASES, Case, doc_section, render_table, run_case


def test_the_catalogue_has_at_least_forty_kinds() -> None:
    assert len(CASES) >= 40
    assert len({c.name for c in CASES}) == len(CASES)


@pytest.mark.parametrize("case", CASES, ids=[c.name for c in CASES])
def test_bad_input_is_refused_and_changes_nothing(case: Case) -> None:
    err = run_case(case)
    assert isinstance(err, KgeError)
    assert isinstance(err, (ValueError, TypeError, KeyError, RuntimeError))


def test_the_doc_table_matches_the_cases() -> None:
    assert doc_section() == render_table(), (
        "docs/reliability.md is out of date: run "
        "`.venv/bin/python -m tests.reliability.catalogue --write`"
    )
