"""Text of the UI on pyglet: the measure that asks the real font, and labels kept per key.

:class:`PygletMeasure` answers :class:`kge.ui.measure.TextMeasure` with pyglet's own
glyph advances and font metrics, so text is laid out, hit and drawn with the same
numbers (pyglet lays a label out as the sum of its glyphs' advances). It is the one
place that would switch to a richer text engine's measuring.

:class:`TextStore` keeps one ``pyglet.text.Label`` per key, placed at a baseline,
and touches it only when its text, place, colour or font changed.
"""

from __future__ import annotations

from typing import Any, Literal

import pyglet

from kge.ui.measure import Advances, Font, is_control

Color = tuple[int, ...]
_ANCHORS: dict[str, Literal["left", "center", "right"]] = {
    "left": "left", "center": "center", "right": "right",
}  # fmt: skip


class PygletMeasure:
    """Advances and metrics from pyglet's fonts (see the module docstring)."""

    def __init__(self) -> None:
        self._fonts: dict[Font, Any] = {}
        self._advances: dict[Font, Advances] = {}

    def font(self, font: Font) -> Any:
        got = self._fonts.get(font)
        if got is None:
            got = self._fonts[font] = pyglet.font.load(
                font.name, font.size, weight="bold" if font.bold else "normal", italic=font.italic
            )
        return got

    def advances(self, font: Font) -> Advances:
        got = self._advances.get(font)
        if got is None:
            pyglet_font = self.font(font)

            def advance(ch: str) -> float:
                if is_control(ch):
                    return 0.0
                return float(sum(g.advance for g in pyglet_font.get_glyphs(ch)[0]))

            got = self._advances[font] = Advances(advance)
        return got

    def line_height(self, font: Font) -> float:
        f = self.font(font)
        return float(f.ascent - f.descent)

    def ascent(self, font: Font) -> float:
        return float(self.font(font).ascent)


class TextStore:
    """One label per key, drawn at a baseline (see the module docstring)."""

    def __init__(self, batch: Any) -> None:
        self.batch = batch
        self.labels: dict[Any, Any] = {}
        self.meta: dict[Any, tuple[Any, Font, str]] = {}

    def put(self, key: Any, group: Any, text: str, x: float, baseline: float, font: Font,
            color: Color, anchor_x: str = "left") -> None:  # fmt: skip
        label = self.labels.get(key)
        meta = (group, font, anchor_x)
        if label is not None and self.meta[key] != meta:
            label.delete()
            label = None
        if label is None:
            label = pyglet.text.Label(
                text, x=x, y=baseline, font_name=font.name, font_size=font.size,
                weight="bold" if font.bold else "normal", italic=font.italic,
                color=(color[0], color[1], color[2], color[3]), anchor_x=_ANCHORS[anchor_x],
                anchor_y="baseline", batch=self.batch, group=group,
            )  # fmt: skip
            self.labels[key] = label
            self.meta[key] = meta
            return
        if label.text != text:
            label.text = text
        if (label.x, label.y) != (x, baseline):
            label.position = (x, baseline, 0)
        if tuple(label.color) != tuple(color):
            label.color = color

    def delete(self, key: Any) -> None:
        label = self.labels.pop(key, None)
        if label is not None:
            label.delete()
            self.meta.pop(key, None)

    def clear(self) -> None:
        for label in self.labels.values():
            label.delete()
        self.labels.clear()
        self.meta.clear()
