"""Drawing the screen-space UI (an after-pass: over the world, in window pixels).

:class:`UIDrawer` keeps the pyglet objects of every widget (anti-aliased shapes,
labels, sprites) in one batch and *syncs* an entity's objects only when something
about it changed: one of its components was written, its box moved, or its look
changed (hover, focus, press). A frame where nothing changed draws the batch and
does nothing else, so an unchanged HUD costs one draw call per depth level.

Draw order: parents under children (a depth level per nesting level, eight parts
per level), open dropdown lists and tooltips over everything, dialogs above the
rest of the UI. Scroll views clip their content with a scissor; text fields and
lists clip their own text. Each widget kind's drawing is in
:mod:`kge.render.ui_widgets` and :mod:`kge.render.ui_lists`.
"""

from __future__ import annotations

from typing import Any

import pyglet

from kge.components.transform import Transform
from kge.host import Host
from kge.render.passes import Frame
from kge.render.setup import renderer_for
from kge.render.textures import TextureCache
from kge.render.ui_parts import ClipGroup
from kge.render.ui_shapes import ShapeGroup, ShapeStore
from kge.render.ui_text import PygletMeasure, TextStore
from kge.ui.current import current_layout
from kge.ui.layout import Box, Layout
from kge.ui.measure import Font, elide, visible
from kge.ui.settings import UISettings
from kge.ui.sizing import Sizer
from kge.ui.state import UIState
from kge.ui.style import Look
from kge.world import World

Color = tuple[int, ...]  #: RGBA (themes and components always hold four channels)
LEVEL = 16  #: draw orders per nesting level
TOP = 1_000_000  #: open dropdown lists, tooltips, drag ghosts
OVERLAY = -1  #: the pseudo-entity owning tooltips and drag ghosts


class Canvas:
    """Draws one entity's parts (keys are scoped to it; see :class:`UIDrawer`)."""

    def __init__(self, drawer: UIDrawer, e: int, box: Box, z: int) -> None:
        self.d, self.e, self.box, self.z = drawer, e, box, z
        self.own_box: Box | None = None

    # -- clipping ----------------------------------------------------------------------------------
    def clip_to(self, box: Box) -> None:
        """Parts drawn with ``own=True`` are cut to ``box`` (and to the scroll views around)."""
        self.own_box = box

    def _clip(self, own: bool) -> Any:
        return self.d.own_clip(self.e, self.own_box) if own else self.d.layout_clip(self.e)

    # -- parts ------------------------------------------------------------------------------------
    def rect(self, part: Any, b: Box, color: Color, dz: int = 0, radius: float = 0.0,
             border: float = 0.0, edge: Color = (0, 0, 0, 0), corners: Any = None,
             own: bool = False, z: int | None = None) -> None:  # fmt: skip
        if b.w <= 0 or b.h <= 0 or (color[3] == 0 and (border <= 0 or edge[3] == 0)
                                    and corners is None):  # fmt: skip
            return
        key = (self.e, part)
        self.d.used.add(key)
        g = self.d.group("s", self.z + dz if z is None else z, self._clip(own))
        self.d.shapes.box(key, g, b.x, b.y, b.w, b.h, color, radius, border, edge, corners)

    def line(self, part: Any, a: tuple[float, float], b: tuple[float, float], width: float,
             color: Color, dz: int = 0, own: bool = False,
             z: int | None = None) -> None:  # fmt: skip
        key = (self.e, part)
        self.d.used.add(key)
        g = self.d.group("s", self.z + dz if z is None else z, self._clip(own))
        self.d.shapes.stroke(key, g, a, b, width, color)

    def label(self, part: Any, text: str, x: float, baseline: float, font: Font, color: Color,
              dz: int = 4, anchor: str = "left", own: bool = False,
              z: int | None = None) -> None:  # fmt: skip
        if not text:
            return
        key = (self.e, part)
        self.d.used.add(key)
        g = self.d.group("t", self.z + dz if z is None else z, self._clip(own))
        self.d.texts.put(key, g, text, x, baseline, font, color, anchor)

    def line_of_text(self, part: Any, text: str, b: Box, font: Font, color: Color,
                     align: str = "center", dz: int = 4, own: bool = False,
                     z: int | None = None) -> None:  # fmt: skip
        """One line in ``b``, centred vertically, cut with an ellipsis to the box's width."""
        m = self.d.measure
        shown = elide(m, visible(text), font, b.w)
        lh, asc = m.line_height(font), m.ascent(font)
        baseline = b.center[1] + lh / 2 - asc
        x = {"left": b.x, "center": b.center[0], "right": b.right}[align]
        self.label(part, shown, x, baseline, font, color, dz, align, own, z)

    def image(self, part: Any, image: Any, b: Box, dz: int = 2, tint: Color = (255, 255, 255, 255),
              own: bool = False, z: int | None = None) -> None:  # fmt: skip
        if b.w <= 0 or b.h <= 0:
            return
        key = (self.e, part)
        self.d.used.add(key)
        g = self.d.group("i", self.z + dz if z is None else z, self._clip(own))
        self.d.sprite(key, g, image, b, tint)


class UIDrawer:
    """The pyglet side of one world's UI (see the module docstring)."""

    def __init__(self, world: World) -> None:
        self.world = world
        self.batch = pyglet.graphics.Batch()
        self.shapes = ShapeStore(self.batch)
        self.texts = TextStore(self.batch)
        self.sprites: dict[Any, Any] = {}
        self.textures = TextureCache(world)  # asset names, PixelImages, pyglet images
        self.groups: dict[tuple[Any, ...], Any] = {}
        self.clips: dict[Any, ClipGroup] = {}
        self.owned: dict[int, set[Any]] = {}
        self.drawn: dict[int, tuple[Any, ...]] = {}
        self.used: set[Any] = set()
        self.layout = Layout()
        self.state: UIState = world.resource(UIState)
        self.sizer: Sizer | None = None
        self.measure: Any = None
        self.version = -1
        self.key: tuple[Any, ...] = ()
        self.blink = -1
        self.fb_scale = 1.0
        self.syncs = 0  #: entities synced (a counter the benchmarks and tests read)

    # -- groups ------------------------------------------------------------------------------------
    def layout_clip(self, e: int) -> ClipGroup | None:
        """The clip group of the scroll view ``e`` is inside, or None."""
        lay = self.layout
        if e not in lay.clip:
            return None
        owner = lay.parent.get(e)
        while owner is not None and owner not in lay.scroll:
            owner = lay.parent.get(owner)
        if owner is None:
            return None
        view = lay.scroll[owner].viewport.intersect(lay.clip.get(owner))
        order = 2 * (lay.depth[owner] * LEVEL + LEVEL - 1)  # after the view's own parts
        return self._clip_group(("view", owner), view, order, self.layout_clip(owner))

    def own_clip(self, e: int, box: Box | None) -> ClipGroup | None:
        outer = self.layout_clip(e)
        if box is None:
            return outer
        cut = box.intersect(self.layout.clip.get(e))
        # after the entity's background parts (up to +2), before its clipped ones (+3 on)
        order = 2 * (self.layout.depth.get(e, 0) * LEVEL + 2) + 1
        return self._clip_group(("own", e), cut, order, outer)

    def _clip_group(self, key: Any, box: Box, order: int, parent: Any) -> ClipGroup:
        g = self.clips.get(key)
        if g is None or g.parent is not parent or g.order != order:
            g = self.clips[key] = ClipGroup(order=order, parent=parent)
        g.box = (box.x, box.y, box.w, box.h)
        g.scale = self.fb_scale
        return g

    def group(self, kind: str, z: int, clip: Any) -> Any:
        key = (kind, z, id(clip) if clip is not None else None)
        g = self.groups.get(key)
        if g is None or (clip is not None and g.parent is not clip):
            order = 2 * z + (1 if kind == "t" else 0)
            if kind == "s":
                g = ShapeGroup(order, clip)
            else:
                g = pyglet.graphics.Group(order=order, parent=clip)
            self.groups[key] = g
        return g

    def sprite(self, key: Any, group: Any, image: Any, b: Box, tint: Color) -> None:
        img = self.textures.texture(image) if not hasattr(image, "get_texture") or isinstance(
            image, str) else image  # fmt: skip
        spr = self.sprites.get(key)
        if spr is not None and spr.group is not group:
            spr.delete()
            spr = None
        if spr is None:
            spr = self.sprites[key] = pyglet.sprite.Sprite(img, batch=self.batch, group=group)
        if spr.image is not img:
            spr.image = img
        spr.update(x=b.x, y=b.y, scale_x=b.w / max(img.width, 1), scale_y=b.h / max(img.height, 1))
        if tuple(spr.color) != tuple(tint):
            spr.color = tint

    def _forget(self, gone: set[int]) -> None:
        """Drop the clip groups of nodes that left the layout, and the groups under them."""
        dropped = [k for k in self.clips if k[1] in gone]
        if not dropped:
            return
        ids = {id(self.clips.pop(k)) for k in dropped}
        for key in [k for k in self.groups if k[2] in ids]:
            del self.groups[key]

    def _delete(self, key: Any) -> None:
        self.shapes.delete(key)
        self.texts.delete(key)
        spr = self.sprites.pop(key, None)
        if spr is not None:
            spr.delete()

    # -- syncing -----------------------------------------------------------------------------------
    def look(self, e: int, kind: str, state: str) -> Look:
        assert self.sizer is not None
        return self.sizer.look(e, kind, state)

    def sync(self, e: int) -> None:
        """Rebuild entity ``e``'s parts (deleting the ones it no longer draws)."""
        from kge.render.ui_widgets import paint

        lay = self.layout
        self.used = set()
        if e in lay.boxes:
            canvas = Canvas(self, e, lay.boxes[e], lay.depth[e] * LEVEL)
            paint(self, canvas, lay.widget.get(e))
        old = self.owned.get(e, set())
        for key in old - self.used:
            self._delete(key)
        if self.used:
            self.owned[e] = self.used
        else:
            self.owned.pop(e, None)
        self.syncs += 1

    def _signature(self, e: int) -> tuple[Any, ...]:
        lay = self.layout
        return (lay.boxes.get(e), lay.depth.get(e), lay.clip.get(e))

    def draw(self, frame: Frame) -> None:
        world, state = self.world, self.state
        host = world.try_resource(Host)
        renderer = renderer_for(host) if host is not None else None
        if renderer is not None:
            window = renderer.window
            fw, _ = window.get_framebuffer_size()
            self.fb_scale = fw / max(window.width, 1)
            state.store.attach(window)
            settings = world.try_resource(UISettings)
            extra = float(getattr(window, "scale", 1.0)) / self.fb_scale
            if settings is not None and abs(extra - settings.dpi) > 1e-6 and 0.25 <= extra <= 8:
                settings.dpi = extra
        if not isinstance(state.measure, PygletMeasure):
            state.measure = PygletMeasure()
        self.measure = state.measure
        # laid out for the App's window size, as the input handling sees it (a headless App
        # resized after its first frame draws into its first buffer: the UI is cut, not moved)
        size = host.size if host is not None else frame.viewport
        lay = current_layout(world, size, self._to_screen(frame))
        self.layout, self.sizer = lay, lay.sizer
        todo = set(state.redraw)
        state.redraw.clear()
        key = (lay.size, lay.scale, id(self.sizer.theme) if self.sizer else None, self.fb_scale)
        if key != self.key:
            todo |= set(lay.order) | set(self.owned)
            self.key = key
        elif lay.version != self.version:
            for e in lay.order:
                if self._signature(e) != self.drawn.get(e):
                    todo.add(e)
            todo |= set(self.owned) - set(lay.boxes)
        self.version = lay.version
        blink = int(state.time * 2.0) % 2
        if blink != self.blink:
            self.blink = blink
            if state.focused is not None:
                todo.add(state.focused)
        gone = set()
        for e in sorted(todo, key=lambda k: lay.depth.get(k, 0)):
            self.sync(e)
            if e in lay.boxes:
                self.drawn[e] = self._signature(e)
            else:
                self.drawn.pop(e, None)
                gone.add(e)
        if gone:
            self._forget(gone)
        if state.drag is not None or state.tip.shown or OVERLAY in self.owned:
            from kge.render.ui_widgets import paint_overlay

            self.used = set()
            paint_overlay(self, Canvas(self, OVERLAY, Box(0, 0, *lay.size), TOP))
            for k in self.owned.get(OVERLAY, set()) - self.used:
                self._delete(k)
            self.owned[OVERLAY] = self.used
        if renderer is None:
            return
        window = renderer.window
        saved, window.view = window.view, pyglet.math.Mat4()  # window pixels
        try:
            self.batch.draw()
        finally:
            window.view = saved

    def _to_screen(self, frame: Frame) -> Any:
        world = self.world

        def to_screen(entity: int, offset: tuple[float, float]) -> tuple[float, float] | None:
            pose = frame.pose(entity)
            if pose is None:
                t = world.try_get(entity, Transform) if world.exists(entity) else None
                if t is None:
                    return None
                pose = (t.x, t.y, t.angle)
            return frame.world_to_screen((pose[0] + offset[0], pose[1] + offset[1]))

        return to_screen

    def close(self) -> None:
        self.shapes.clear()
        self.texts.clear()
        for spr in self.sprites.values():
            spr.delete()
        self.sprites.clear()
        self.owned.clear()
        self.drawn.clear()


def drawer_for(world: World) -> UIDrawer:
    d = world.try_resource(UIDrawer)
    if d is None:
        d = world.insert_resource(UIDrawer(world))
    return d


def draw_ui(frame: Frame, world: World) -> None:
    """The UI plugin's after-pass."""
    drawer_for(world).draw(frame)
