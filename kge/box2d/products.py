"""``b2Mul``, ``b2MulT`` and ``b2Mul22``: Box2D's overloaded products, chosen by argument type.

``b2Mul(A, B)`` applies A to B: a matrix, rotation or transform to a vector, or
composes two of the same kind. ``b2MulT`` applies the transpose (the inverse,
for rotations and transforms): it takes a world vector into A's frame.

>>> from kge.box2d.transform import b2Transform
>>> t = b2Transform()
>>> t.Set((1, 2), 0.0)
>>> b2Mul(t, (1, 0)), b2MulT(t, (2, 2))
(b2Vec2(2,2), b2Vec2(1,0))
"""

from __future__ import annotations

from typing import Any

from kge.box2d.matrix import b2Mat22, b2Mat33
from kge.box2d.transform import b2Rot, b2Transform, make_transform
from kge.box2d.vec import as_xy, b2Vec2
from kge.errors import ComponentTypeError


def _rot_vec(c: float, s: float, v: Any) -> b2Vec2:
    x, y = as_xy(v, "b2Mul", "v")
    return b2Vec2(c * x - s * y, s * x + c * y)


def b2Mul(A: Any, B: Any) -> Any:
    """``A * B`` for a b2Mat22, b2Mat33, b2Rot or b2Transform ``A`` (see the module notes)."""
    if isinstance(A, b2Mat22):
        return A * B
    if isinstance(A, b2Mat33):
        return A * B
    if isinstance(A, b2Rot):
        if isinstance(B, b2Rot):
            return b2Rot(A.angle + B.angle)
        return _rot_vec(A.c, A.s, B)
    if isinstance(A, b2Transform):
        if isinstance(B, b2Transform):
            p = A * B.position
            return make_transform(p.x, p.y, A.angle + B.angle)
        return A * B
    raise ComponentTypeError(f"b2Mul: cannot multiply {A!r} and {B!r}")


def b2MulT(A: Any, B: Any) -> Any:
    """``transpose(A) * B``: for rotations and transforms, B taken into A's frame."""
    if isinstance(A, b2Mat22):
        if isinstance(B, b2Mat22):
            c1, c2 = A.col1, A.col2
            return b2Mat22((c1.dot(B.col1), c2.dot(B.col1)), (c1.dot(B.col2), c2.dot(B.col2)))
        x, y = as_xy(B, "b2MulT", "v")
        return b2Vec2(A.col1.x * x + A.col1.y * y, A.col2.x * x + A.col2.y * y)
    if isinstance(A, b2Rot):
        if isinstance(B, b2Rot):
            return b2Rot(B.angle - A.angle)
        return _rot_vec(A.c, -A.s, B)
    if isinstance(A, b2Transform):
        if isinstance(B, b2Transform):
            d = B.position - A.position
            p = _rot_vec(A.q.c, -A.q.s, d)
            return make_transform(p.x, p.y, B.angle - A.angle)
        x, y = as_xy(B, "b2MulT", "v")
        return _rot_vec(A.q.c, -A.q.s, (x - A.position.x, y - A.position.y))
    raise ComponentTypeError(f"b2MulT: cannot multiply {A!r} and {B!r}")


def b2Mul22(A: b2Mat33, v: Any) -> b2Vec2:
    """The upper-left 2x2 block of ``A`` times the 2D vector ``v``."""
    if not isinstance(A, b2Mat33):
        raise ComponentTypeError(f"b2Mul22 needs a b2Mat33, got {A!r}")
    x, y = as_xy(v, "b2Mul22", "v")
    return b2Vec2(A.col1.x * x + A.col2.x * y, A.col1.y * x + A.col2.y * y)

