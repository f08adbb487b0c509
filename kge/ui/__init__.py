"""Screen-space UI logic that needs no window: layout, theme, events, interaction.

The components live in :mod:`kge.components.ui`; the plugin and its systems in
:mod:`kge.systems.ui`; drawing in :mod:`kge.render.ui`. See ``docs/ui.md``.
"""

from kge.ui.events import (
    ButtonClicked,
    DialogClosed,
    DragCancelled,
    DragStarted,
    Dropped,
    FocusChanged,
    ItemActivated,
    ItemToggled,
    TextSubmitted,
    TreeDrop,
    UIEvents,
    ValueChanged,
)
from kge.ui.layout import Box, compute_layout
from kge.ui.settings import UISettings
from kge.ui.theme import DEFAULT_THEME, Theme

__all__ = [
    "DEFAULT_THEME",
    "Box",
    "ButtonClicked",
    "DialogClosed",
    "DragCancelled",
    "DragStarted",
    "Dropped",
    "FocusChanged",
    "ItemActivated",
    "ItemToggled",
    "TextSubmitted",
    "Theme",
    "TreeDrop",
    "UIEvents",
    "UISettings",
    "ValueChanged",
    "compute_layout",
]
