"""World metres -> pyglet: the one angle conversion and the camera's view matrix.

kge angles are radians counter-clockwise (maths, Box2D); pyglet's sprite and
shape shaders rotate by *clockwise degrees*. Every angle handed to pyglet goes
through :func:`to_pyglet_degrees`, so the sign flip lives in exactly one place.

Vertex data stays in metres; the camera is applied by the window's view matrix
(a scale by ``pixels_per_meter * zoom``, a turn by the camera's rotation and a
translation putting ``camera.center`` at the viewport's middle). Zooming,
panning or turning therefore rewrites no vertex.

>>> float(to_pyglet_degrees(3.141592653589793 / 2))
-90.0
>>> view_matrix((1.0, 0.0), 10.0, (100, 50))[12:14]
(40.0, 25.0)
>>> [round(v, 6) for v in view_matrix((0.0, 0.0), 1.0, (0, 0), 3.141592653589793 / 2)[:2]]
[0.0, -1.0]
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

Mat4Tuple = tuple[float, ...]


def to_pyglet_degrees(radians_ccw: Any) -> Any:
    """Radians counter-clockwise (kge) -> degrees clockwise (pyglet); scalars or arrays."""
    return np.negative(np.degrees(radians_ccw))


def view_matrix(
    center: tuple[float, float], scale: float, viewport: tuple[float, float],
    rotation: float = 0.0,
) -> Mat4Tuple:
    """Column-major 4x4: world metres -> viewport pixels for a camera at ``center``,
    turned ``rotation`` radians counter-clockwise (the world turns clockwise)."""
    k = float(scale)
    c, s = (math.cos(rotation), math.sin(rotation)) if rotation else (1.0, 0.0)
    a00, a01, a10, a11 = k * c, k * s, -k * s, k * c
    tx = viewport[0] / 2 - (a00 * center[0] + a01 * center[1])
    ty = viewport[1] / 2 - (a10 * center[0] + a11 * center[1])
    return (a00, a10, 0.0, 0.0, a01, a11, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, tx, ty, 0.0, 1.0)


def scaled(matrix: Mat4Tuple, factor: float) -> Mat4Tuple:
    """``matrix`` applied after a uniform scale by ``factor`` (font pixels -> metres)."""
    m = list(matrix)
    for i in range(8):
        m[i] *= factor
    return tuple(m)


IDENTITY: Mat4Tuple = (
    1.0,
    0.0,
    0.0,
    0.0,
    0.0,
    1.0,
    0.0,
    0.0,
    0.0,
    0.0,
    1.0,
    0.0,
    0.0,
    0.0,
    0.0,
    1.0,
)
