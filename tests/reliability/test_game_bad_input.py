"""Game-layer bad input: a clear error at the call naming entity, component and field,
an unchanged world, and a game that runs on with every pose, camera, particle and
tween row finite.

The cases live in :mod:`tests.reliability.game_catalogue`, which also renders the
game-layer table of ``docs/reliability.md``; the last test keeps that table in sync.
"""

from __future__ import annotations

import pytest

from kge.errors import KgeError

from .game_catalogue import CASES, Case, doc_section, render_table, run_case


def test_the_catalogue_covers_every_area_of_the_game_layer() -> None:
    areas = {c.area for c in CASES}
    assert areas >= {"sprite", "animation", "camera", "text", "drawables", "lights",
                     "particles", "tweens", "ui", "audio", "scenes", "scene files", "media"}
    assert len(CASES) >= 300
    assert len({c.name for c in CASES}) == len(CASES)


@pytest.mark.parametrize("case", CASES, ids=[f"{c.area}: {c.name}" for c in CASES])
def test_game_bad_input_is_refused_and_changes_nothing(case: Case) -> None:
    err = run_case(case)
    assert isinstance(err, KgeError)
    assert isinstance(err, (ValueError, TypeError, KeyError, RuntimeError))


def test_the_game_doc_table_matches_the_cases() -> None:
    assert doc_section() == render_table(), (
        "docs/reliability.md is out of date: run "
        "`.venv/bin/python -m tests.reliability.game_catalogue --write`"
    )
