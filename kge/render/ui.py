"""Drawing the screen-space UI (an after-pass: over the world, in window pixels).

:class:`UIDrawer` keeps one pyglet object per (entity, part) — rounded rectangles,
labels, sprites — and updates them in place each frame from the layout and the
widget components, so text is laid out again only when it changes. Draw order is
the layout's (parents under children), each part in its own ordered group; open
dropdown lists go on top of everything; scroll lists clip their rows with a scissor.
"""

from __future__ import annotations

from typing import Any

import pyglet

from kge.components.ui import (
    Button,
    Dropdown,
    Label,
    Panel,
    ProgressBar,
    ScrollList,
    Slider,
    TextInput,
    Toggle,
    UIImage,
)
from kge.host import Host
from kge.render.passes import Frame
from kge.render.setup import renderer_for
from kge.render.textures import TextureCache
from kge.render.ui_parts import ClipGroup, nine_patch
from kge.ui.interact import UIState, dropdown_rows, list_rows
from kge.ui.layout import Box, compute_layout
from kge.ui.theme import DEFAULT_THEME, Theme
from kge.world import World

Color = Any  # RGB or RGBA tuples
_TOP = 1_000_000  # z of open dropdown lists


class UIDrawer:
    """The pyglet side of one world's UI."""

    def __init__(self, world: World) -> None:
        self.world = world
        self.batch = pyglet.graphics.Batch()
        self.items: dict[tuple[Any, ...], Any] = {}
        self.used: set[tuple[Any, ...]] = set()
        self.groups: dict[int, Any] = {}
        self.clips: dict[int, ClipGroup] = {}
        self.theme: Theme = DEFAULT_THEME
        self.time = 0.0
        self.textures = TextureCache(world)  # asset names, PixelImages, pyglet images

    # -- cached primitives -------------------------------------------------------------------
    def group(self, z: int, clip: int | None = None) -> Any:
        if clip is not None:
            return self.clips[clip].child(z)
        g = self.groups.get(z)
        if g is None:
            g = self.groups[z] = pyglet.graphics.Group(order=z)
        return g

    def _get(self, key: tuple[Any, ...], make: Any) -> Any:
        self.used.add(key)
        obj = self.items.get(key)
        if obj is None:
            obj = self.items[key] = make()
        return obj

    def rect(self, key: tuple[Any, ...], box: Box, color: Color, z: int, radius: float = 0.0,
             clip: int | None = None) -> None:  # fmt: skip
        if box.w < 1 or box.h < 1 or color[3] == 0:
            return
        r = min(radius, box.w / 2, box.h / 2)
        g = self.group(z, clip)

        def make() -> Any:
            if r >= 1:
                return pyglet.shapes.RoundedRectangle(
                    box.x,
                    box.y,
                    box.w,
                    box.h,
                    r,
                    segments=6,
                    color=color,
                    batch=self.batch,
                    group=g,
                )
            return pyglet.shapes.Rectangle(
                box.x, box.y, box.w, box.h, color=color, batch=self.batch, group=g
            )

        shape = self._get((*key, "rect", round(r), z, clip), make)
        if (shape.x, shape.y, shape.width, shape.height) != (box.x, box.y, box.w, box.h):
            shape.x, shape.y = box.x, box.y
            shape.width, shape.height = box.w, box.h
        if tuple(shape.color) != color:
            shape.color = color

    def text(
        self,
        key: tuple[Any, ...],
        value: str,
        x: float,
        y: float,
        color: Color,
        z: int,
        size: float | None = None,
        anchor_x: Any = "center",
        clip: int | None = None,
    ) -> Any:
        size = size or self.theme.font_size
        g = self.group(z, clip)

        def make() -> Any:
            return pyglet.text.Label(
                value, font_name=self.theme.font_name, font_size=size, color=color, x=x, y=y,
                anchor_x=anchor_x, anchor_y="center", batch=self.batch, group=g,
            )  # fmt: skip

        label = self._get((*key, "text", size, anchor_x, z, clip), make)
        if label.text != value:
            label.text = value
        if (label.x, label.y) != (x, y):
            label.position = (x, y, 0)
        if tuple(label.color) != color:
            label.color = color
        return label

    def sprite(self, key: tuple[Any, ...], image: Any, box: Box, z: int, tint: Color) -> None:
        g = self.group(z)
        spr = self._get((*key, "sprite", z),
                        lambda: pyglet.sprite.Sprite(image, batch=self.batch, group=g))  # fmt: skip
        if spr.image is not image:
            spr.image = image
        spr.update(x=box.x, y=box.y, scale_x=box.w / max(image.width, 1),
                   scale_y=box.h / max(image.height, 1))  # fmt: skip
        spr.color = tint

    # -- frame -----------------------------------------------------------------------------------
    def draw(self, frame: Frame) -> None:
        world = self.world
        state = world.try_resource(UIState)
        if state is None:
            return
        self.theme = world.try_resource(Theme) or DEFAULT_THEME
        self.time = frame.time
        self.used = set()
        lay = compute_layout(world, frame.viewport, self.theme)
        state.layout = lay
        for e in lay.order:
            # one group per nesting level and part, not per widget: siblings share a
            # level, so a grid of 200 buttons is a handful of draw calls
            self.widget(e, lay.boxes[e], lay.widget.get(e), state, lay.depth[e] * 8)
        for key in [k for k in self.items if k not in self.used]:
            self.items.pop(key).delete()
        renderer = renderer_for(world.resource(Host))
        if renderer is None:
            return
        window = renderer.window
        fw, _ = window.get_framebuffer_size()
        for clip in self.clips.values():
            clip.scale = fw / max(window.width, 1)
        saved, window.view = window.view, pyglet.math.Mat4()  # window pixels
        try:
            self.batch.draw()
        finally:
            window.view = saved

    # -- widgets ---------------------------------------------------------------------------------
    def widget(self, e: int, box: Box, w: Any, state: UIState, z: int) -> None:
        th = self.theme
        panel = self.world.try_get(e, Panel)
        if panel is not None:
            self.panel(e, box, panel, z)
        if w is None:
            return
        look = state.state_of(e)
        focused = state.focused == e
        if focused and not isinstance(w, (Label, ProgressBar, UIImage, TextInput)):
            self.rect(
                (e, "focus"), box.inset(-th.focus_width), th.focus, z, th.radius + th.focus_width
            )
        muted = th.text_disabled if look == "disabled" else th.text
        if isinstance(w, Label):
            ax = w.align
            x = {"left": box.x, "center": box.center[0], "right": box.right}[ax]
            self.text((e,), w.text, x, box.center[1], w.color or th.text, z + 1, w.size, ax)
        elif isinstance(w, Button):
            fill = {"normal": th.button, "focused": th.button, "hover": th.button_hover,
                    "pressed": th.button_pressed, "disabled": th.button_disabled}[look]  # fmt: skip
            self.rect((e, "fill"), box, fill, z + 1, th.radius)
            if w.image:
                img = self.textures.texture(w.image)
                side = min(box.h - 2 * th.padding, box.w - 2 * th.padding)
                x = box.x + th.padding if w.text else box.center[0] - side / 2
                self.sprite((e, "img"), img, Box(x, box.center[1] - side / 2, side, side), z + 2,
                            (255, 255, 255, 255))  # fmt: skip
            if w.text:
                self.text((e,), w.text, box.center[0], box.center[1], muted, z + 3)
        elif isinstance(w, Toggle):
            side = min(box.h, 28.0)
            square = Box(box.x, box.center[1] - side / 2, side, side)
            hover = look in ("hover", "pressed")
            self.rect((e, "box"), square, th.button_hover if hover else th.field, z + 1, 5)
            if w.value:
                self.rect((e, "tick"), square.inset(side * 0.22), th.accent, z + 2, 3)
            self.text((e,), w.text, square.right + 8, box.center[1], muted, z + 3, anchor_x="left")
        elif isinstance(w, Slider):
            self.slider(e, box, w, look, z)
        elif isinstance(w, ProgressBar):
            self.rect((e, "track"), box, th.track, z + 1, min(th.radius, box.h / 2))
            bar = Box(box.x, box.y, box.w * w.fraction, box.h)
            self.rect((e, "fill"), bar, w.color or th.accent, z + 2, min(th.radius, box.h / 2))
        elif isinstance(w, TextInput):
            self.text_input(e, box, w, focused, z)
        elif isinstance(w, Dropdown):
            self.dropdown(e, box, w, look, z)
        elif isinstance(w, ScrollList):
            self.scroll_list(e, box, w, z)
        elif isinstance(w, UIImage):
            self.sprite((e,), self.textures.texture(w.image), box, z + 1, w.tint)

    def panel(self, e: int, box: Box, p: Panel, z: int) -> None:
        th = self.theme
        if p.image:
            img = self.textures.texture(p.image)
            for i, (region, part) in enumerate(nine_patch(img, box, p.border)):
                self.sprite((e, "nine", i), region, part, z, p.color or (255, 255, 255, 255))
            return
        color = p.color or th.panel
        if len(color) == 3 or color[3] == 255:  # a border under a see-through panel would show
            self.rect((e, "border"), box, th.panel_border, z, p.radius)
            box = box.inset(1)
        self.rect((e, "panel"), box, color, z, p.radius)

    def slider(self, e: int, box: Box, w: Slider, look: str, z: int) -> None:
        th = self.theme
        knob = box.h / 2
        th_h = max(box.h / 4, 3.0)
        track = Box(box.x + knob, box.center[1] - th_h / 2, box.w - 2 * knob, th_h)
        self.rect((e, "track"), track, th.track, z + 1, th_h / 2)
        span = w.max - w.min
        t = 0.0 if span <= 0 else (w.value - w.min) / span
        fill = Box(track.x, track.y, track.w * t, track.h)
        self.rect(
            (e, "fill"),
            fill,
            th.text_disabled if look == "disabled" else th.accent,
            z + 2,
            th_h / 2,
        )
        cx = track.x + track.w * t
        r = knob - 2
        color = th.button_pressed if look == "pressed" else th.text
        self.rect((e, "knob"), Box(cx - r, box.center[1] - r, 2 * r, 2 * r), color, z + 3, r)

    def text_input(self, e: int, box: Box, w: TextInput, focused: bool, z: int) -> None:
        th = self.theme
        self.rect((e, "edge"), box, th.focus if focused else th.panel_border, z + 1, th.radius)
        self.rect((e, "field"), box.inset(2), th.field, z + 2, max(th.radius - 2, 0))
        x0, cy = box.x + th.padding, box.center[1]
        shown = w.text or w.placeholder
        color = th.text if w.text else th.text_muted
        self.text((e,), shown, x0, cy, color, z + 4, anchor_x="left")
        if not focused or w.disabled:
            return
        fs = th.font_size

        def x_at(i: int) -> float:
            if not w.text or i == 0:
                return x0
            probe = self.text(
                (e, "probe"), w.text[:i], -10_000, 0, (0, 0, 0, 0), z, anchor_x="left"
            )
            return x0 + probe.content_width

        sel = w.selection
        if sel is not None:
            a, b = x_at(sel[0]), x_at(sel[1])
            self.rect((e, "sel"), Box(a, cy - fs * 0.75, b - a, fs * 1.5), th.selection, z + 3)
        if int(self.time * 2.0) % 2 == 0:  # blink on game time (deterministic headless)
            cx = x_at(w.caret)
            self.rect((e, "caret"), Box(cx, cy - fs * 0.7, 2, fs * 1.4), th.text, z + 5)

    def dropdown(self, e: int, box: Box, w: Dropdown, look: str, z: int) -> None:
        th = self.theme
        fill = th.button_hover if look in ("hover", "pressed") else th.button
        self.rect((e, "fill"), box, fill, z + 1, th.radius)
        self.text(
            (e,), w.value or "", box.x + th.padding, box.center[1], th.text, z + 2, anchor_x="left"
        )
        self.text((e, "arrow"), "v", box.right - th.padding, box.center[1], th.text_muted, z + 2,
                  anchor_x="right")  # fmt: skip
        if not w.open:
            return
        for i, row in enumerate(dropdown_rows(box, len(w.options))):
            color = th.button_pressed if i == w.selected else th.panel
            self.rect((e, "opt", i), row, th.panel_border, _TOP)
            self.rect((e, "optbg", i), row.inset(1), color, _TOP + 1)
            self.text((e, "opt", i), w.options[i], row.x + th.padding, row.center[1], th.text,
                      _TOP + 2, anchor_x="left")  # fmt: skip

    def scroll_list(self, e: int, box: Box, w: ScrollList, z: int) -> None:
        th = self.theme
        self.rect((e, "bg"), box, th.field, z + 1, th.radius)
        clip = self.clips.get(e)
        if clip is None:
            clip = self.clips[e] = ClipGroup(order=z + 2)
        clip.box = (box.x, box.y, box.w, box.h)
        for i, row in list_rows(w, box, th):
            if i == w.selected:
                self.rect((e, "sel", i), row, th.selection, 0, clip=e)
            self.text((e, "row", i), w.items[i], row.x + th.padding, row.center[1], th.text, 1,
                      anchor_x="left", clip=e)  # fmt: skip

    def close(self) -> None:
        for obj in self.items.values():
            obj.delete()
        self.items.clear()


def drawer_for(world: World) -> UIDrawer:
    d = world.try_resource(UIDrawer)
    if d is None:
        d = world.insert_resource(UIDrawer(world))
    return d


def draw_ui(frame: Frame, world: World) -> None:
    """The UI plugin's after-pass."""
    drawer_for(world).draw(frame)
