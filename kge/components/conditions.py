"""Animator transition conditions: a parameter test written as text, never evaluated.

``when`` of an animator :class:`~kge.components.animation.Transition` is one or more
clauses joined by ``and``:

=====================  ==============================================
``"grounded"``         the parameter is truthy
``"not grounded"``     the parameter is falsy (or unset)
``"speed > 0.1"``      a comparison: ``<``, ``<=``, ``>``, ``>=``, ``==``, ``!=``
                       with a number, ``true`` / ``false`` or a word
``"a and b > 2"``      every clause holds
=====================  ==============================================

A comparison with an unset or non-numeric parameter is false (``<`` and friends);
nothing is raised while the game runs. A malformed condition is refused when the
Transition is made.

>>> met("speed > 0.1 and not hurt", {"speed": 0.5})
True
>>> met("state == jump", {"state": "fall"})
False
>>> parse("speed >> 2")
Traceback (most recent call last):
...
kge.errors.ValidationError: Transition.when: 'speed >> 2' is not a condition ...
"""

from __future__ import annotations

import math
import operator
import re
from collections.abc import Callable, Mapping
from functools import lru_cache
from typing import Any

from kge.errors import ValidationError

_OPS: dict[str, Callable[[Any, Any], bool]] = {
    "<=": operator.le, ">=": operator.ge, "==": operator.eq, "!=": operator.ne,
    "<": operator.lt, ">": operator.gt,
}  # fmt: skip
_CLAUSE = re.compile(
    r"^\s*(?:(?P<not>not)\s+(?P<neg>[A-Za-z_]\w*)"
    r"|(?P<name>[A-Za-z_]\w*)\s*(?:(?P<op><=|>=|==|!=|<|>)\s*(?P<value>[^\s<>=!]+))?)\s*$"
)

Clause = tuple[str, str, Any]  # (name, op or "truthy" / "not", value)


def _literal(text: str) -> Any:
    low = text.lower()
    if low in ("true", "false"):
        return low == "true"
    try:
        v = float(text)
    except ValueError:
        return text.strip("'\"")
    if not math.isfinite(v):
        raise ValueError(text)
    return v


@lru_cache(maxsize=1024)
def parse(condition: str) -> tuple[Clause, ...]:
    """The clauses of ``condition``; a ValidationError naming it when malformed."""
    if not isinstance(condition, str) or not condition.strip():
        raise ValidationError(f"Transition.when: a condition must be non-empty text, "
                              f"got {condition!r}")  # fmt: skip
    out = []
    for part in re.split(r"\s+and\s+", condition.strip()):
        m = _CLAUSE.match(part)
        try:
            if m is None or m["name"] in ("not", "and", "or"):
                raise ValueError(part)
            if m["not"]:
                out.append((m["neg"], "not", None))
            elif m["op"]:
                out.append((m["name"], m["op"], _literal(m["value"])))
            else:
                out.append((m["name"], "truthy", None))
        except ValueError:
            raise ValidationError(
                f"Transition.when: {condition!r} is not a condition (write 'moving', "
                "'not grounded', 'speed > 0.1', 'state == jump', joined by 'and')"
            ) from None
    return tuple(out)


def met(condition: str, params: Mapping[str, Any]) -> bool:
    """Does ``condition`` hold for the animator's ``params``?"""
    for name, op, value in parse(condition):
        got = params.get(name)
        if op == "truthy":
            ok = bool(got)
        elif op == "not":
            ok = not got
        elif op in ("==", "!="):
            if isinstance(value, float) and isinstance(got, int | float):
                got = float(got)
            ok = _OPS[op](got, value)
        else:
            try:
                ok = isinstance(got, int | float) and isinstance(value, float) and bool(
                    _OPS[op](float(got), value)
                )
            except TypeError:
                ok = False
        if not ok:
            return False
    return True
