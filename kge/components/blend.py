"""``Blend``: how a drawable's colour combines with what is already drawn.

One choice for sprites, shapes, text-free drawables and particles:

* ``ALPHA``: covers what is behind, by its opacity (the default);
* ``ADDITIVE``: adds its colour (fire, sparks, glows, light shafts);
* ``MULTIPLY``: darkens by its colour (shade, stains, tinted glass);
* ``SCREEN``: lightens softly, never past white (haze, mist);
* ``PREMULTIPLIED``: as ``ALPHA``, for images whose colour is already multiplied by
  their alpha.

Each member equals its string (``Blend.ADDITIVE == "additive"``); ``"add"`` is read
as ``ADDITIVE``.

>>> Blend("add") is Blend.ADDITIVE
True
>>> [m.value for m in Blend]
['alpha', 'additive', 'multiply', 'screen', 'premultiplied']
"""

from __future__ import annotations

from enum import StrEnum


class Blend(StrEnum):
    """How a drawable is drawn over what is behind it (see the module docstring)."""

    ALPHA = "alpha"  #: ordinary transparency
    ADDITIVE = "additive"  #: colours add up (fire, sparks, glows)
    MULTIPLY = "multiply"  #: darkens by the colour (shade, tinted glass)
    SCREEN = "screen"  #: lightens softly (haze)
    PREMULTIPLIED = "premultiplied"  #: alpha blending of premultiplied images

    @classmethod
    def _missing_(cls, value: object) -> Blend | None:
        return cls.ADDITIVE if value == "add" else None
