"""``Box2D.b2``: pybox2d's short names (``world``, ``polygonShape``, ``staticBody``...).

Every ``b2Name`` of :mod:`kge.box2d` is here as ``name`` with a lower-case first
letter, and every ``b2_constant`` as ``constant``, the aliases pybox2d makes.
They are the same objects (``b2.polygonShape is b2PolygonShape``), so
``type(shape) is circleShape`` tests work.

>>> from kge.box2d import b2
>>> b2.polygonShape.__name__, b2.staticBody
('b2PolygonShape', 0)
"""

from __future__ import annotations

from typing import Any

from kge.box2d import api as _full


def _aliases() -> dict[str, Any]:
    out: dict[str, Any] = {}
    for name, value in vars(_full).items():
        if name.startswith("b2_"):
            out[name[3:]] = value
        elif name.startswith("b2") and len(name) > 2 and name[2].isupper():
            out[name[2].lower() + name[3:]] = value
        if name.startswith("b2") or name.startswith("e_"):
            out[name] = value
    return out


globals().update(_aliases())


def __getattr__(name: str) -> Any:  # names added to kge.box2d after this import
    aliases = _aliases()
    if name in aliases:
        return aliases[name]
    raise AttributeError(f"module 'Box2D.b2' has no attribute {name!r}")
