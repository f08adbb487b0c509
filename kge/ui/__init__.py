"""Screen-space UI logic that needs no window: layout, theme, events, interaction.

The components live in :mod:`kge.components.ui`; the plugin and its systems in
:mod:`kge.systems.ui`; drawing in :mod:`kge.render.ui`. See ``docs/ui-scenes-input.md``.
"""

from kge.ui.events import ButtonClicked, FocusChanged, TextSubmitted, UIEvents, ValueChanged
from kge.ui.layout import Box, compute_layout
from kge.ui.theme import DEFAULT_THEME, Theme

__all__ = [
    "DEFAULT_THEME",
    "Box",
    "ButtonClicked",
    "FocusChanged",
    "TextSubmitted",
    "Theme",
    "UIEvents",
    "ValueChanged",
    "compute_layout",
]
