"""Text layout measured as boxes, with a made-up monospaced face (no fonts, no GL).

Every glyph of :class:`MonoSource` is 0.5 em wide and lines are 1.2 em, so at 12 pt
(16 px) a glyph is 8 px and a line 19.2 px: boxes are exact numbers.
"""

from __future__ import annotations

import pytest

from kge.components.text import Text, TextAlign, TextOverflow, TextStyle, VerticalAlign
from kge.errors import ValidationError
from kge.text.layout import MonoFace, MonoSource, layout
from kge.text.markup import Span, parse, spans_of

GLYPH, LINE = 8.0, 19.2


def lay(text: str, markup: bool = False, source: MonoSource | None = None, **style):
    style.setdefault("size", 12)
    st = TextStyle(markup=markup, **style)
    return layout(spans_of(text, markup), st, source or MonoSource())


def texts(out):
    return [ln.text for ln in out.lines]


def test_newlines_end_lines_and_draw_nothing():
    out = lay("ab\ncd\n\ne")
    assert texts(out) == ["ab", "cd", "", "e"]
    assert out.height == pytest.approx(4 * LINE)
    assert all(g.char not in "\n\r" for g in out.glyphs)
    assert [g.char for g in lay("\r\n\t\x07x\u200d").glyphs] == ["x"]  # no box for controls


def test_wrapping_breaks_at_spaces_and_hangs_trailing_spaces():
    out = lay("aaa bbb ccc", width=8 * GLYPH)
    assert texts(out) == ["aaa bbb", "ccc"]
    assert out.lines[0].width == 7 * GLYPH and out.width == 8 * GLYPH
    assert max(g.x for g in out.glyphs) < out.width


def test_a_word_longer_than_the_line_breaks_between_letters():
    assert texts(lay("abcdefghij", width=4 * GLYPH)) == ["abcd", "efgh", "ij"]


def test_hyphens_and_cjk_are_break_opportunities():
    assert texts(lay("well-known", width=6 * GLYPH)) == ["well-", "known"]
    assert texts(lay("日本語の文章", width=4 * GLYPH)) == ["日本語の", "文章"]


def test_no_wrap_keeps_one_line_per_paragraph():
    out = lay("aaa bbb ccc", width=3 * GLYPH, wrap=False)
    assert texts(out) == ["aaa bbb ccc"]


@pytest.mark.parametrize(("align", "x"), [(TextAlign.LEFT, 0.0), (TextAlign.CENTER, 2 * GLYPH), (TextAlign.RIGHT, 4 * GLYPH)])
def test_alignment_places_each_line_in_the_box(align, x):
    out = lay("ab\nabcdef", width=6 * GLYPH, align=align)
    assert out.lines[0].x == pytest.approx(x)
    assert out.lines[1].x == pytest.approx(0.0)
    first = [g.x for g in out.glyphs if g.baseline == out.lines[0].baseline]
    assert first[0] == pytest.approx(x)


def test_justify_stretches_wrapped_lines_but_not_the_last():
    out = lay("a b c dd eee", width=9 * GLYPH, align=TextAlign.JUSTIFY)
    assert texts(out) == ["a b c dd", "eee"]
    assert out.lines[0].width == pytest.approx(9 * GLYPH)  # 3 gaps share the extra glyph
    d = [g.x for g in out.glyphs if g.char == "d"]
    assert d[0] == pytest.approx(6 * GLYPH + GLYPH)
    assert out.lines[-1].width == pytest.approx(3 * GLYPH)


def test_line_spacing_scales_the_line_boxes():
    one, two = lay("a\nb\nc"), lay("a\nb\nc", line_spacing=2.0)
    assert two.height == pytest.approx(2 * one.height)
    gaps = [two.lines[i].baseline - two.lines[i + 1].baseline for i in range(2)]
    assert gaps == pytest.approx([2 * LINE, 2 * LINE])


def test_letter_spacing_widens_every_advance():
    assert lay("abcd", letter_spacing=2.0).lines[0].width == pytest.approx(4 * GLYPH + 4 * 2.0)


def test_boxes_scale_exactly_with_the_font_size():
    small, big = lay("hello world ok", size=12, width=60), lay("hello world ok", size=24, width=120)
    assert texts(small) == texts(big)
    assert big.height == pytest.approx(2 * small.height)


def test_clip_keeps_whole_lines_that_fit_the_height():
    out = lay("a\nb\nc\nd", height=2.5 * LINE, overflow=TextOverflow.CLIP)
    assert texts(out) == ["a", "b"] and out.truncated
    assert out.height == pytest.approx(2.5 * LINE)
    visible = lay("a\nb\nc\nd", height=2.5 * LINE)
    assert texts(visible) == ["a", "b", "c", "d"] and not visible.truncated


def test_ellipsis_ends_the_last_line_that_fits():
    out = lay("one two three four five six", width=9 * GLYPH, max_lines=2, overflow=TextOverflow.ELLIPSIS)
    assert len(out.lines) == 2 and out.truncated
    assert out.lines[1].text.endswith("\u2026")
    assert all(ln.width <= 9 * GLYPH + 1e-6 for ln in out.lines)


def test_ellipsis_shortens_unwrapped_lines_to_the_width():
    out = lay("a very long single line", width=10 * GLYPH, wrap=False, overflow=TextOverflow.ELLIPSIS)
    assert out.lines[0].text == "a very lo\u2026" and out.lines[0].width <= 10 * GLYPH


def test_ellipsis_falls_back_to_dots_when_the_face_lacks_the_glyph():
    src = MonoSource()
    src.face = MonoFace(missing="\u2026")
    out = lay("abcdefghijk", source=src, width=6 * GLYPH, wrap=False, overflow=TextOverflow.ELLIPSIS)
    assert out.lines[0].text == "abc..."


def test_shrink_lowers_the_size_until_the_text_fits():
    out = lay("make this fit", width=10 * GLYPH, height=LINE, overflow=TextOverflow.SHRINK)
    assert out.scale < 1.0 and len(out.lines) == 1
    assert out.lines[0].width <= 10 * GLYPH + 1e-6
    assert out.lines[0].width > 9 * GLYPH  # the largest size that fits, not any smaller one
    assert lay("fits", width=10 * GLYPH, overflow=TextOverflow.SHRINK).scale == 1.0


def test_valign_places_the_block_in_a_taller_box():
    top = lay("a", height=100.0)
    bottom = lay("a", height=100.0, valign=VerticalAlign.BOTTOM)
    assert top.lines[0].y == pytest.approx(100.0 - LINE)
    assert bottom.lines[0].y == pytest.approx(0.0)


def test_fallback_faces_draw_what_the_first_lacks():
    class Two(MonoSource):
        def __init__(self):
            super().__init__()
            self.first, self.second = MonoFace(missing="é"), MonoFace(width=1.0)

        def faces(self, family, weight, italic):
            return (self.first, self.second)

    src = Two()
    out = lay("eé", source=src)
    assert [g.face for g in out.glyphs] == [src.first, src.second]
    assert out.lines[0].width == pytest.approx(GLYPH + 2 * GLYPH)


def test_markup_spans_change_size_colour_weight_and_icons():
    out = lay("a[size=24]b[/size][color=red]c[/color][img=10x10]x.png[/img]", markup=True)
    a, b, c, icon = out.glyphs
    assert b.size == 2 * a.size and c.color == (230, 40, 40, 255)
    assert icon.icon == ("x.png", 10.0, 10.0) and icon.char == ""
    assert [s.weight for s in parse("[b]x[/b][weight=light]y[/weight]")] == [700, 300]
    assert parse("[i]x[/i]")[0].italic is True


@pytest.mark.parametrize("bad", ["[b]x", "[/b]", "[b]x[/i][/b]", "[color=nope]x[/color]",
                                 "[size=0]x[/size]", "[img]x", "[wobble]x[/wobble]",
                                 "[img=big]x[/img]"])
def test_bad_markup_is_refused_naming_the_tag(bad):
    with pytest.raises(ValidationError, match="markup"):
        parse(bad)


def test_styles_refuse_bad_values_at_the_call():
    for bad in ({"size": 1e6}, {"size": 0}, {"align": "middle"}, {"overflow": "scroll"},
                {"weight": "heavyish"}, {"outline": -1}, {"max_lines": 0}, {"width": -5.0},
                {"line_spacing": 0.0}, {"shadow": (500, 0)}):
        with pytest.raises(ValidationError):
            TextStyle(**bad)
        with pytest.raises(ValidationError):
            Text("x", **bad)
    t = Text("x")
    with pytest.raises(ValidationError, match="Text.size"):
        t.size = float("inf")
    assert t.size == 16.0


def test_text_value_still_works_with_a_deprecation_warning():
    t = Text("old")
    with pytest.warns(DeprecationWarning, match="Text.text"):
        assert t.value == "old"
    with pytest.warns(DeprecationWarning) as record:
        t.value = "new"
    assert t.text == "new" and record[0].filename == __file__


def test_world_text_box_is_in_metres():
    st = Text("x", width=2.0, height=1.0).style(box_scale=64.0)
    assert (st.width, st.height) == (128.0, 64.0)


def test_spans_of_plain_text_is_one_span():
    assert spans_of("[b]", False) == [Span("[b]")]
