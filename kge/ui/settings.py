"""``UISettings``: how big the UI is drawn (resolution, high DPI, the player's choice) and
how big its text is (accessibility). One object serves every scene of an App (the UI
plugin puts the same one in each world), so a settings menu changes them all.

UINode pixel values are *design* pixels. The layout multiplies them by
:meth:`UISettings.factor`: the player's ``scale`` times, when ``design_size`` is
set, the fit of that design resolution in the window (a menu made for 1280 x 720
fills a 2560 x 1440 window the same way), times the display's extra DPI scale when
the window reports one (``dpi``, set by the renderer). ``text_scale`` multiplies
font sizes only, on top of that: layouts with ``"auto"`` sizes grow to fit.

>>> s = UISettings(design_size=(1280, 720))
>>> s.factor((2560, 1440)), s.factor((1280, 1440))
(2.0, 1.0)
>>> UISettings(scale=0)
Traceback (most recent call last):
...
kge.errors.ValidationError: UISettings.scale must be in [0.25, 8], got 0.0
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from kge.errors import ValidationError
from kge.validate import finite, vec2


def _ranged(value: Any, name: str, lo: float, hi: float) -> float:
    v = finite(value, "UISettings", name)
    if not lo <= v <= hi:
        raise ValidationError(f"UISettings.{name} must be in [{lo:g}, {hi:g}], got {v!r}")
    return v


@dataclass(slots=True)
class UISettings:
    """The UI scale and text scale of a world (a resource the UI plugin inserts)."""

    scale: float = 1.0  #: the player's "UI size"
    text_scale: float = 1.0  #: multiplies every font size (accessibility)
    design_size: tuple[float, float] | None = None  #: fit this resolution into the window
    dpi: float = 1.0  #: the display's extra scale (set by the renderer from the window)

    def __setattr__(self, name: str, value: Any) -> None:
        if name in ("scale", "text_scale") or name == "dpi":
            value = _ranged(value, name, 0.25, 8.0)
        elif name == "design_size" and value is not None:
            w, h = vec2(value, "UISettings", name)
            if not (1.0 <= w <= 1e5 and 1.0 <= h <= 1e5):
                raise ValidationError(
                    f"UISettings.design_size must be two sizes in 1..1e5 pixels, got {value!r}"
                )
            value = (w, h)
        object.__setattr__(self, name, value)

    def factor(self, window: tuple[float, float]) -> float:
        """Design pixels -> window pixels for a window of this size."""
        k = self.scale * self.dpi
        if self.design_size is not None:
            fit = min(window[0] / self.design_size[0], window[1] / self.design_size[1])
            k *= min(max(fit, 0.05), 20.0)
        return k
