"""How each widget is drawn: panels, labels, rich text, buttons, toggles, sliders, bars,
images, spin boxes, colour pickers, dialogs, focus rings, tooltips and drag ghosts.

Every painter draws one entity's parts on a :class:`~kge.render.ui.Canvas` from its
resolved look (:mod:`kge.ui.style`) and the shared geometry (:mod:`kge.ui.geometry`).
Lists, trees, tabs and text fields are in :mod:`kge.render.ui_lists`.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from kge.components.ui import (
    Button,
    ColorPicker,
    Dialog,
    DropTarget,
    Label,
    Panel,
    ProgressBar,
    RichText,
    Slider,
    SpinBox,
    Toggle,
    Tooltip,
    UIImage,
)
from kge.components.ui_widgets import hsv_to_rgb
from kge.render import ui_lists
from kge.render.ui_glyphs import check_mark, checker
from kge.render.ui_parts import nine_patch
from kge.ui import geometry as geo
from kge.ui.layout import Box
from kge.ui.measure import elide, visible, width
from kge.ui.style import Look

if TYPE_CHECKING:
    from kge.render.ui import Canvas, UIDrawer

Color = tuple[int, ...]  #: RGBA (themes and components always hold four channels)
CLEAR: Color = (0, 0, 0, 0)


def kind_of(w: Any) -> str:
    return type(w).__name__ if w is not None else "Panel"


def paint(d: UIDrawer, c: Canvas, w: Any) -> None:
    """Draw entity ``c.e``: its panel, its widget, its focus ring, scrollbars, highlights."""
    world, st = d.world, d.state
    e = c.e
    dialog = world.try_get(e, Dialog)
    if dialog is not None:
        _dialog(d, c, dialog)
    panel = world.try_get(e, Panel)
    if panel is not None and dialog is None:
        _panel(d, c, panel)
    state = st.state_of(e) if w is not None else "normal"
    if w is not None:
        lk = d.look(e, kind_of(w), state)
        painter = PAINTERS.get(type(w))
        if painter is not None:
            painter(d, c, w, lk)
        if st.focused == e and not isinstance(w, (Label, RichText, ProgressBar, UIImage)):
            _ring(d, c, lk)
    if e in d.layout.scroll:
        ui_lists.scrollbars(d, c)
    if st.drag is not None and st.drag.over == e and world.try_get(e, DropTarget) is not None:
        th = d.sizer.theme if d.sizer else None
        accent = th.accent if th else (46, 196, 182, 255)
        c.rect("drop", c.box, CLEAR, 7, 6 * d.layout.scale, 2 * d.layout.scale, accent)


def _ring(d: UIDrawer, c: Canvas, lk: Look) -> None:
    assert d.sizer is not None
    th = d.sizer.theme
    fw = th.focus_width * d.layout.scale
    c.rect("focus", c.box.inset(-fw - 1), CLEAR, 1, lk.radius + fw + 1, fw, th.focus)


def _panel(d: UIDrawer, c: Canvas, p: Panel) -> None:
    own = d.sizer.styles.get(c.e) if d.sizer else None
    lk = d.look(c.e, "Panel", "normal")
    image = p.image or lk.image
    if image:
        tint = p.color or (255, 255, 255, 255)
        for i, (region, part) in enumerate(nine_patch(d.textures.texture(image), c.box,
                                                      p.border * d.layout.scale)):  # fmt: skip
            c.image(("nine", i), region, part, 0, tint)
        return
    color = p.color or lk.background
    radius = lk.radius if own is not None and own.radius is not None else p.radius * d.layout.scale
    opaque = len(color) == 3 or color[3] == 255  # a border under a see-through panel shows
    border = lk.border_width if opaque else 0.0
    c.rect("panel", c.box, _rgba(color), 0, radius, border, lk.border)


def _rgba(color: Any) -> Color:
    return (color[0], color[1], color[2], color[3] if len(color) > 3 else 255)


def _dialog(d: UIDrawer, c: Canvas, dialog: Dialog) -> None:
    assert d.sizer is not None
    lk = d.look(c.e, "Dialog", "normal")
    if dialog.modal:
        w, h = d.layout.size
        c.rect("scrim", Box(0, 0, w, h), d.sizer.theme.scrim, -2)
    c.rect("panel", c.box, lk.background, 0, lk.radius, lk.border_width, lk.border)
    bar = d.sizer.title_bar(c.e, dialog.title)
    if bar:
        title = Box(c.box.x, c.box.top - bar - lk.padding, c.box.w, bar + lk.padding)
        inset = max(lk.border_width, 1.0)
        c.rect("titlebar", Box(title.x + inset, title.y, title.w - 2 * inset, title.h - inset),
               d.sizer.theme.button, 1, max(lk.radius - inset, 0.0))  # fmt: skip
        c.line_of_text("title", dialog.title, title.inset(lk.padding / 2), _bold(lk), lk.text,
                       "left")  # fmt: skip


def _bold(lk: Look) -> Any:
    from kge.ui.measure import Font

    return Font(lk.font.name, lk.font.size, True, lk.font.italic)


# -- text ---------------------------------------------------------------------------------------
def _label(d: UIDrawer, c: Canvas, w: Label, lk: Look) -> None:
    assert d.sizer is not None
    font = d.sizer.label_font(c.e, w)
    lines = d.sizer.label_lines(c.e, w, c.box.w if w.wrap else None)
    m = d.measure
    lh, asc = m.line_height(font), m.ascent(font)
    block = lh * len(lines)
    top = c.box.center[1] + block / 2
    overflow = block > c.box.h + 1
    if overflow:
        c.clip_to(c.box)
    color = _rgba(w.color) if w.color else lk.text
    for i, text in enumerate(lines):
        line_top = top - i * lh
        if line_top - lh > c.box.top or line_top < c.box.y:
            continue  # a line wholly outside the box is not drawn
        shown = elide(m, text, font, c.box.w + 0.5)
        x = {"left": c.box.x, "center": c.box.center[0], "right": c.box.right}[w.align]
        c.label(("line", i), shown, x, line_top - asc, font, color, 4, w.align, own=overflow)


def _rich(d: UIDrawer, c: Canvas, w: RichText, lk: Look) -> None:
    assert d.sizer is not None
    lines = d.sizer.rich_lines(c.e, w, c.box.w)
    heights = d.sizer.rich_line_heights(c.e, w, lines)
    m = d.measure
    c.clip_to(c.box)
    base = _rgba(w.color) if w.color else lk.text
    top = c.box.top
    k = 0
    for line, h in zip(lines, heights, strict=True):
        if top < c.box.y:
            break
        lw = sum(width(m, t, f) for t, _, f in line)
        x = {"left": c.box.x, "center": c.box.center[0] - lw / 2,
             "right": c.box.right - lw}[w.align]  # fmt: skip
        asc = max((m.ascent(f) for _, _, f in line), default=0.0)
        for text, run, font in line:
            if text.strip():
                c.label(("run", k), text, x, top - asc, font, run.color or base, 4, own=True)
                k += 1
            x += width(m, text, font)
        top -= h


# -- buttons, toggles, sliders ---------------------------------------------------------------------
def _button(d: UIDrawer, c: Canvas, w: Button, lk: Look) -> None:
    b = c.box
    if lk.image:
        for i, (region, part) in enumerate(nine_patch(d.textures.texture(lk.image), b,
                                                      lk.image_border)):  # fmt: skip
            c.image(("nine", i), region, part, 2)
    else:
        c.rect("fill", b, lk.background, 2, lk.radius, lk.border_width, lk.border)
    inner = b.inset(lk.padding)
    if w.image is not None:
        side = max(min(inner.h, inner.w), 0.0)
        x = inner.x if w.text else b.center[0] - side / 2
        c.image("icon", w.image, Box(x, b.center[1] - side / 2, side, side), 3)
        if w.text:
            gap = 6 * d.layout.scale
            inner = Box(x + side + gap, inner.y, max(inner.right - x - side - gap, 0.0), inner.h)
    if w.text:
        c.line_of_text("text", w.text, Box(inner.x, b.y, inner.w, b.h), lk.font, lk.text,
                       "center" if w.image is None else "left")  # fmt: skip


def _toggle(d: UIDrawer, c: Canvas, w: Toggle, lk: Look) -> None:
    b = c.box
    side = min(b.h, d.measure.line_height(lk.font))
    square = Box(b.x, b.center[1] - side / 2, side, side)
    c.rect("box", square, lk.background, 2, min(lk.radius * 0.6, side / 3), lk.border_width,
           lk.border)  # fmt: skip
    if w.value:
        check_mark(c, square, lk.accent)
    gap = 8 * d.layout.scale
    text = Box(square.right + gap, b.y, max(b.right - square.right - gap, 0.0), b.h)
    c.line_of_text("text", w.text, text, lk.font, lk.text, "left")


def _slider(d: UIDrawer, c: Canvas, w: Slider, lk: Look) -> None:
    track, r = geo.slider_track(c.box)
    c.rect("track", track, lk.background, 2, track.h / 2)
    t = w.fraction
    c.rect("fill", Box(track.x, track.y, track.w * t, track.h), lk.accent, 3, track.h / 2)
    cx, cy = track.x + track.w * t, c.box.center[1]
    c.rect("knob", Box(cx - r, cy - r, 2 * r, 2 * r), lk.text, 4, r)


def _progress(d: UIDrawer, c: Canvas, w: ProgressBar, lk: Look) -> None:
    b = c.box
    r = min(lk.radius, b.h / 2)
    c.rect("track", b, lk.background, 2, r)
    c.rect("fill", Box(b.x, b.y, b.w * w.fraction, b.h), _rgba(w.color) if w.color else lk.accent,
           3, r)  # fmt: skip


def _image(d: UIDrawer, c: Canvas, w: UIImage, lk: Look) -> None:
    c.image("img", w.image, c.box, 2, _rgba(w.tint))


def _spin(d: UIDrawer, c: Canvas, w: SpinBox, lk: Look) -> None:
    assert d.sizer is not None
    th = d.sizer.theme
    minus, field, plus = geo.spin_parts(c.box)
    c.rect("field", c.box, lk.background, 2, lk.radius, lk.border_width, lk.border)
    for name, part in (("minus", minus), ("plus", plus)):
        c.rect(name, part.inset(3 * d.layout.scale), th.button, 3, max(lk.radius - 3, 0.0))
        cx, cy = part.center
        k = part.h * 0.18
        c.line((name, "h"), (cx - k, cy), (cx + k, cy), max(k * 0.35, 1.5), lk.text, 4)
        if name == "plus":
            c.line((name, "v"), (cx, cy - k), (cx, cy + k), max(k * 0.35, 1.5), lk.text, 4)
    ui_lists.spin_text(d, c, w, lk, field)


def _picker(d: UIDrawer, c: Canvas, w: ColorPicker, lk: Look) -> None:
    from kge.ui.controls import PICKER_PARTS

    hsv = d.state.picker.get(c.e)
    from kge.components.ui_widgets import rgb_to_hsv

    h, s, v = rgb_to_hsv(w.color) if hsv is None or hsv_to_rgb(*hsv[:3]) != tuple(
        w.color[:3]) else hsv[:3]  # fmt: skip
    active = int(hsv[3]) if hsv is not None else 0
    parts = geo.picker_parts(c.box, w.alpha)
    sv, hue = parts["sv"], parts["hue"]
    pure = (*hsv_to_rgb(h, 1.0, 1.0), 255)
    white, black, none = (255, 255, 255, 255), (0, 0, 0, 255), (0, 0, 0, 0)
    c.rect("sv", sv, white, 2, corners=(white, pure, pure, white))
    c.rect("sv_dark", sv, black, 3, corners=(black, black, none, none))
    for i in range(6):
        seg = Box(hue.x, hue.y + hue.h * i / 6, hue.w, hue.h / 6 + 0.5)
        lo, hi = (*hsv_to_rgb(i / 6, 1, 1), 255), (*hsv_to_rgb((i + 1) / 6, 1, 1), 255)
        c.rect(("hue", i), seg, lo, 2, corners=(lo, lo, hi, hi))
    rgb = w.color[:3]
    if "alpha" in parts:
        a = parts["alpha"]
        checker(c, "achk", a)
        c.rect("alpha", a, (*rgb, 255), 3, corners=((*rgb, 0), (*rgb, 0), (*rgb, 255), (*rgb, 255)))
        ay = a.y + a.h * (w.color[3] if len(w.color) > 3 else 255) / 255
        c.rect("amark", Box(a.x - 2, ay - 2, a.w + 4, 4), white, 5, 2, 1, black)
    sw = parts["swatch"]
    checker(c, "schk", sw)
    c.rect("swatch", sw, _rgba(w.color), 3, min(lk.radius, sw.h / 2))
    mx, my = sv.x + sv.w * s, sv.y + sv.h * v
    rr = max(5 * d.layout.scale, 3)
    c.rect("svmark", Box(mx - rr, my - rr, 2 * rr, 2 * rr), CLEAR, 5, rr, 2, white)
    hy = hue.y + hue.h * h
    c.rect("hmark", Box(hue.x - 2, hy - 2, hue.w + 4, 4), white, 5, 2, 1, black)
    if d.state.focused == c.e and d.sizer is not None:
        name = PICKER_PARTS[active]
        target = {"hue": hue, "sv_s": sv, "sv_v": sv}.get(name, parts.get("alpha", sv))
        c.rect("active", target.inset(-3), CLEAR, 6, 3, 2, d.sizer.theme.focus)


PAINTERS: dict[type, Any] = {
    Label: _label, RichText: _rich, Button: _button, Toggle: _toggle, Slider: _slider,
    ProgressBar: _progress, UIImage: _image, SpinBox: _spin, ColorPicker: _picker,
    **ui_lists.PAINTERS,
}  # fmt: skip


# -- overlay: tooltips and drag ghosts -------------------------------------------------------------
def paint_overlay(d: UIDrawer, c: Canvas) -> None:
    st = d.state
    assert d.sizer is not None
    lay = d.layout
    W, H = lay.size
    tip = st.tip
    if tip.shown and tip.entity is not None and tip.entity in lay.boxes:
        t = d.world.try_get(tip.entity, Tooltip)
        if t is not None and t.text:
            lk = d.look(tip.entity, "Tooltip", "normal")
            text = visible(t.text)
            tw = min(width(d.measure, text, lk.font), W * 0.6)
            lh = d.measure.line_height(lk.font)
            bw, bh = tw + 2 * lk.padding, lh + lk.padding
            x = min(max(tip.at[0] + 12, 2.0), W - bw - 2)
            y = tip.at[1] - 20 - bh
            if y < 2:
                y = tip.at[1] + 20
            b = Box(x, min(y, H - bh - 2), bw, bh)
            c.rect("tip", b, lk.background, 20, lk.radius, lk.border_width, lk.border)
            c.line_of_text("tiptext", text, b.inset(lk.padding / 2), lk.font, lk.text, "center",
                           dz=21)  # fmt: skip
    drag = st.drag
    if drag is not None and drag.started:
        lk = d.look(drag.source, "Button", "normal")
        text = drag.label or "…"
        tw = min(width(d.measure, text, lk.font), 300 * lay.scale)
        lh = d.measure.line_height(lk.font)
        b = Box(drag.at[0] + 10, drag.at[1] - lh - 10, tw + 2 * lk.padding, lh + lk.padding)
        color = (*lk.background[:3], 200)
        c.rect("ghost", b, color, 30, lk.radius, lk.border_width or 1, d.sizer.theme.accent)
        c.line_of_text("ghosttext", text, b, lk.font, lk.text, "center", dz=31)
