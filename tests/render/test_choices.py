"""Rendering's choices are enums; their strings still work one release, with a warning."""

from __future__ import annotations

import pytest

from kge import (
    Blend,
    Resolution,
    ScaleMode,
    Sprite,
    Text,
    TextAlign,
    TextOverflow,
    TextStyle,
    TextureFilter,
    TextureWrap,
    VerticalAlign,
)
from kge.components.drawables import Rect
from kge.errors import ValidationError

CASES = [
    (lambda v: Sprite("a.png", blend=v), "blend", "add", Blend.ADDITIVE),
    (lambda v: Sprite("a.png", filter=v), "filter", "linear", TextureFilter.LINEAR),
    (lambda v: Sprite("a.png", wrap=v), "wrap", "mirror", TextureWrap.MIRROR),
    (lambda v: Rect(1.0, 1.0, blend=v), "blend", "screen", Blend.SCREEN),
    (lambda v: Text("t", align=v), "align", "justify", TextAlign.JUSTIFY),
    (lambda v: TextStyle(valign=v), "valign", "bottom", VerticalAlign.BOTTOM),
    (lambda v: TextStyle(overflow=v), "overflow", "ellipsis", TextOverflow.ELLIPSIS),
    (lambda v: Resolution(320, 180, mode=v), "mode", "integer", ScaleMode.INTEGER),
]


@pytest.mark.parametrize(("make", "field", "old", "member"), CASES)
def test_a_choice_takes_its_enum_and_still_its_string(make, field, old, member) -> None:
    import warnings

    with warnings.catch_warnings():
        warnings.simplefilter("error")
        assert getattr(make(member), field) is member  # the enum: no warning
    with pytest.warns(DeprecationWarning, match=f"is now {type(member).__name__}.{member.name}"):
        assert getattr(make(old), field) is member
    with pytest.raises(ValidationError, match=f"{field} must be one of"):
        make("sideways")
