"""The stats overlay: FPS, fixed-step time, bodies, contacts, sprites drawn, with
lighting on the light pass's share of the frame (:func:`light_note`), and the slowest
systems when per-system timings are on (F4, :mod:`kge.timings`).

FPS and step time are averaged over the last half second, so the numbers are
readable rather than flickering; in a window the label text is rebuilt at most
four times a second (glyph layout is not free). Headless Apps render only when
asked (tests, screenshots), so there every frame shows fresh numbers.
"""

from __future__ import annotations

import time
from collections import deque
from typing import Any

import pyglet

from kge.render.groups import OVERLAY_LAYER, SCREEN, Groups


class FrameClock:
    """Frame and fixed-step timings (kept even when the overlay is hidden)."""

    def __init__(self) -> None:
        self.frames: deque[float] = deque(maxlen=240)
        self.steps: deque[float] = deque(maxlen=240)

    def frame(self) -> None:
        self.frames.append(time.perf_counter())

    def step(self, seconds: float) -> None:
        self.steps.append(seconds)

    @property
    def fps(self) -> float:
        now = time.perf_counter()
        recent = [t for t in self.frames if now - t <= 0.5]
        if len(recent) < 2:
            return 0.0
        return (len(recent) - 1) / (recent[-1] - recent[0]) if recent[-1] > recent[0] else 0.0

    @property
    def step_ms(self) -> float:
        last = list(self.steps)[-30:]
        return 1000.0 * sum(last) / len(last) if last else 0.0


#: the share of the frame above which the overlay says the light pass dominates
LIGHTS_DOMINATE = 0.5


def light_note(light_ms: float, frame_ms: float) -> str:
    """The overlay's ``lights`` entry: the light pass's time per frame, and whether it
    takes more than half the frame (then fewer shadowed lights, smaller radii or a lower
    ``Lighting.resolution`` help most).

    >>> light_note(2.0, 10.0)
    '2.0 ms of 10.0'
    >>> light_note(7.5, 10.0)
    '7.5 ms of 10.0 (the light pass dominates the frame)'
    """
    text = f"{light_ms:.1f} ms of {frame_ms:.1f}"
    if frame_ms > 0.0 and light_ms > LIGHTS_DOMINATE * frame_ms:
        text += " (the light pass dominates the frame)"
    return text


class StatsOverlay:
    """A screen-space label at the top-left corner."""

    def __init__(self, batch: Any, groups: Groups) -> None:
        self.batch = batch
        self.groups = groups
        self.label: Any = None
        self.table: Any = None  #: the per-system timings, under the stats line
        self._last = 0.0
        self.text = ""
        self.table_text = ""

    def update(
        self, shown: bool, height: int, values: dict[str, Any], throttle: bool = True,
        lines: list[str] | None = None,
    ) -> None:
        """Show ``values`` at the top-left, and ``lines`` (the system timings) under them;
        ``throttle`` limits relayouts to 4 a second."""
        if not shown:
            self.clear()
            return
        self._table(height, lines or [], throttle)
        now = time.perf_counter()
        if self.label is None:
            self.label = pyglet.text.Label(
                "",
                font_size=11,
                color=(255, 255, 255, 230),
                anchor_x="left",
                anchor_y="top",
                batch=self.batch,
                group=self.groups.get(OVERLAY_LAYER + 1, SCREEN, 0),
            )
            self._last = 0.0
        self.label.position = (8.0, height - 8.0, 0.0)
        if not throttle or now - self._last >= 0.25:
            self._last = now
            self.text = "   ".join(f"{k} {v}" for k, v in values.items())
            self.label.text = self.text

    def _table(self, height: int, lines: list[str], throttle: bool) -> None:
        if not lines:
            if self.table is not None:
                self.table.delete()
                self.table = None
                self.table_text = ""
            return
        if self.table is None:
            self.table = pyglet.text.Label(
                "", font_name=["DejaVu Sans Mono", "Courier New", "monospace"], font_size=9,
                color=(255, 255, 255, 230), anchor_x="left", anchor_y="top", multiline=True,
                width=640, batch=self.batch, group=self.groups.get(OVERLAY_LAYER + 1, SCREEN, 0),
            )  # fmt: skip
        self.table.position = (8.0, height - 28.0, 0.0)
        text = "\n".join(lines)
        if text != self.table_text and (not throttle or time.perf_counter() - self._last >= 0.25):
            self.table_text = text
            self.table.text = text

    def clear(self) -> None:
        if self.label is not None:
            self.label.delete()
            self.label = None
        if self.table is not None:
            self.table.delete()
            self.table = None
            self.table_text = ""
