"""pymunk's, Chipmunk's and esper's private layers are named in their doors only.

The doors are ``kge/physics/cp/`` (pymunk and Chipmunk) and ``kge/esper_door.py``.
Anywhere else in ``kge/``, code, comments and docstrings alike, none of these may
appear: ``_chipmunk``, ``pymunk._util``, a private pymunk field read off an object
that is not ``self`` (``x._body``, ``x._shape``, ``x._space``, ``x._h``,
``x._shapes``, ``x._constraint(s)``, ``x._arbiter``, ``x._hashid``,
``x._float_arr``...), or esper's module globals (``esper._...``, ``._entities``).
Attributes of kge's own classes (``self._body``) are kge's and stay allowed.
"""

from __future__ import annotations

import re
from pathlib import Path

import pytest

KGE = Path(__file__).resolve().parents[2] / "kge"
DOORS = (KGE / "physics" / "cp", KGE / "esper_door.py")

_PYMUNK_FIELDS = (
    "_body|_shape|_space|_h|_shapes|_constraint|_constraints|_arbiter|_hashid"
    "|_removed_shapes|_remove_later|_float_arr|_int_arr|_static_body|_bodies_to_check"
)
PRIVATE = re.compile(
    r"_chipmunk\b"
    r"|pymunk\._util\b"
    rf"|(?<![\w.])(?!self\.(?:{_PYMUNK_FIELDS})\b)[A-Za-z_][\w.\]\[)]*\.(?:{_PYMUNK_FIELDS})\b"
    r"|\besper\._\w"
    r"|\._entities\b"
)


def _in_door(path: Path) -> bool:
    return any(path == door or door in path.parents for door in DOORS)


def private_uses(root: Path = KGE) -> list[str]:
    """``path:line: text`` for every private name outside the doors under ``root``."""
    found = []
    for path in sorted(root.rglob("*.py")):
        if _in_door(path):
            continue
        for number, line in enumerate(path.read_text(encoding="utf-8").splitlines(), 1):
            if PRIVATE.search(line):
                found.append(f"{path.relative_to(root.parent)}:{number}: {line.strip()}")
    return found


def test_no_private_layer_outside_the_doors() -> None:
    assert private_uses() == []


@pytest.mark.parametrize(
    "line",
    [
        "from pymunk._chipmunk import lib",
        "    cp = body._body",
        "    cp = rec.body._body",
        "    cp = bodies[k]._body",
        "    ca = self.frame._body",
        "    if shape._space() is not space:",
        "    s.__dict__['x'] = seg._h",
        "    for s in body._shapes:",
        "    n = shape._hashid",
        "    table = esper._entities",
        "    esper._entity_count = itertools.count()",
        "    from pymunk._util import _dead_ref",
        "    cs = [h.pivot._constraint for h in handles]",
    ],
)
def test_each_private_name_is_caught(line: str, tmp_path: Path) -> None:
    (tmp_path / "planted.py").write_text(f"def f():\n{line}\n")
    assert len(private_uses(tmp_path)) == 1


@pytest.mark.parametrize(
    "line",
    [
        "    self._body = body",
        "    body = self._body(e, col)",
        "    cp = body_handle(body)",
        "    LIMITS.max_entities = 5",
        "    if not self._world._locked:",
    ],
)
def test_kge_own_names_pass(line: str, tmp_path: Path) -> None:
    (tmp_path / "fine.py").write_text(f"def f():\n{line}\n")
    assert private_uses(tmp_path) == []
