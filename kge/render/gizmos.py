"""Drawing immediate-mode debug shapes (:mod:`kge.debug.gizmos`) and text panels.

:class:`GizmoDrawer` takes the frame's segments as arrays and draws them in one
``glDrawArrays(GL_LINES)`` call through a stream buffer refilled each frame (a
debug view costs one upload, whatever the number of shapes), on top of the world
with the frame's camera. Text gizmos and :class:`TextPanel` (the console and the
live inspector) are pyglet labels kept between frames and re-laid out only when
their text changes.
"""

from __future__ import annotations

from typing import Any

import numpy as np
import pyglet
from pyglet import gl

from kge.render.glutil import Stream, per_context, program

_VERTEX = """#version 150 core
in vec2 position;
in vec4 color;
out vec4 v_color;
uniform WindowBlock
{
    mat4 projection;
    mat4 view;
} window;
void main()
{
    gl_Position = window.projection * window.view * vec4(position, 0.0, 1.0);
    v_color = color;
}
"""

_FRAGMENT = """#version 150 core
in vec4 v_color;
out vec4 final_color;
void main()
{
    final_color = v_color;
}
"""


def line_program() -> Any:
    return program("kge-gizmo-lines", _VERTEX, _FRAGMENT)


def line_vertices(segments: np.ndarray, colors: np.ndarray) -> np.ndarray:
    """(2n, 6) float32 rows x, y, r, g, b, a (colours 0..1) of n segments.

    >>> line_vertices(np.array([[0.0, 0.0, 1.0, 2.0]]), np.array([[255, 0, 0, 255]])).tolist()
    [[0.0, 0.0, 1.0, 0.0, 0.0, 1.0], [1.0, 2.0, 1.0, 0.0, 0.0, 1.0]]
    """
    n = len(segments)
    out = np.empty((2 * n, 6), np.float32)
    out[0::2, 0:2] = segments[:, 0:2]
    out[1::2, 0:2] = segments[:, 2:4]
    rgba = np.asarray(colors, np.float32) / 255.0
    out[0::2, 2:6] = rgba
    out[1::2, 2:6] = rgba
    return out


class GizmoDrawer:
    """Draws one world's gizmos each frame (an after-pass of the debug plugin)."""

    def __init__(self) -> None:
        self._labels: dict[tuple[Any, ...], list[Any]] = {}

    def draw(self, window: Any, world_view: Any, segments: np.ndarray, colors: np.ndarray,
             texts: list[Any], to_screen: Any) -> None:
        """Draw ``segments`` in world metres with ``world_view`` (metres -> pixels) and
        ``texts`` (world ones placed through ``to_screen``)."""
        if len(segments):
            prog = line_program()
            stream = per_context("kge-gizmo-stream",
                                 lambda: Stream(prog, [("position", 2), ("color", 4)]))
            stream.upload(line_vertices(segments, colors))
            window.view = pyglet.math.Mat4(*world_view)
            prog.use()
            gl.glEnable(gl.GL_BLEND)
            gl.glBlendFunc(gl.GL_SRC_ALPHA, gl.GL_ONE_MINUS_SRC_ALPHA)
            try:
                stream.draw(0, 2 * len(segments), gl.GL_LINES)
            finally:
                prog.stop()
                window.view = pyglet.math.Mat4()
        self._texts(texts, to_screen)

    def _texts(self, texts: list[Any], to_screen: Any) -> None:
        used: dict[tuple[Any, ...], int] = {}
        for t in texts:
            key = (t.text, t.size, t.color)
            pool = self._labels.setdefault(key, [])
            i = used.get(key, 0)
            used[key] = i + 1
            if i >= len(pool):
                pool.append(pyglet.text.Label(t.text, font_size=t.size, color=t.color,
                                              anchor_x="left", anchor_y="bottom"))  # fmt: skip
            label = pool[i]
            x, y = t.position if t.screen else to_screen(t.position)
            label.position = (float(x), float(y), 0.0)
            label.draw()
        for key in [k for k in self._labels if k not in used]:  # unused this frame: dropped
            for label in self._labels.pop(key):
                label.delete()

    def close(self) -> None:
        for pool in self._labels.values():
            for label in pool:
                label.delete()
        self._labels.clear()


class TextPanel:
    """A translucent box of monospaced lines in window pixels (console, inspector)."""

    def __init__(self, font_size: float = 10.0) -> None:
        self.font_size = font_size
        self._label: Any = None
        self._text: str | None = None
        self._box: Any = None

    def draw(self, lines: list[str], x: float, y: float, width: float, height: float,
             background: tuple[int, int, int, int] = (12, 14, 20, 215),
             color: tuple[int, int, int, int] = (225, 230, 240, 255), *,
             tail: bool = True) -> None:
        """Draw ``lines`` in the box whose bottom-left is (x, y): the last ones that fit
        (``tail``, a log), or the first ones."""
        if self._box is None:
            self._box = pyglet.shapes.Rectangle(x, y, width, height, color=background)
        box = self._box
        box.x, box.y, box.width, box.height = x, y, width, height
        box.color = background
        box.draw()
        line_height = self.font_size * 1.6
        fit = max(1, int((height - 8) // line_height))
        text = "\n".join(lines[-fit:] if tail else lines[:fit])
        if self._label is None:
            self._label = pyglet.text.Label(
                "", font_name=["DejaVu Sans Mono", "Courier New", "monospace"],
                font_size=self.font_size, color=color, multiline=True, width=int(width - 16),
                anchor_x="left", anchor_y="top",
            )  # fmt: skip
        label = self._label
        if text != self._text:
            self._text = text
            label.text = text
        label.width = int(max(width - 16, 16))
        label.position = (x + 8, y + height - 6, 0.0)
        label.color = color
        label.draw()

    def close(self) -> None:
        if self._label is not None:
            self._label.delete()
            self._label = None
        if self._box is not None:
            self._box.delete()
            self._box = None
