"""World metres -> pyglet: the one angle conversion and the camera's view matrix.

kge angles are radians counter-clockwise (maths, Box2D); pyglet's sprite and
shape shaders rotate by *clockwise degrees*. Every angle handed to pyglet goes
through :func:`to_pyglet_degrees`, so the sign flip lives in exactly one place.

Vertex data stays in metres; the camera is applied by the window's view matrix
(a scale by ``pixels_per_meter * zoom`` and a translation putting
``camera.center`` at the window's middle). Zooming or panning therefore
rewrites no vertex.

>>> float(to_pyglet_degrees(3.141592653589793 / 2))
-90.0
>>> view_matrix((1.0, 0.0), 10.0, (100, 50))[12:14]
(40.0, 25.0)
"""

from __future__ import annotations

from typing import Any

import numpy as np

Mat4Tuple = tuple[float, ...]


def to_pyglet_degrees(radians_ccw: Any) -> Any:
    """Radians counter-clockwise (kge) -> degrees clockwise (pyglet); scalars or arrays."""
    return np.negative(np.degrees(radians_ccw))


def view_matrix(
    center: tuple[float, float], scale: float, viewport: tuple[float, float]
) -> Mat4Tuple:
    """Column-major 4x4: world metres -> window pixels for a camera at ``center``."""
    k = float(scale)
    tx = viewport[0] / 2 - k * center[0]
    ty = viewport[1] / 2 - k * center[1]
    return (k, 0.0, 0.0, 0.0, 0.0, k, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, tx, ty, 0.0, 1.0)


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
