"""UI images are looked up when a widget is spawned, added or given a new image.

A Button's icon, a UIImage, a Panel's or a Style's nine-patch naming a file that is not there
was found by the UI drawer at the first frame (``AssetNotFoundError`` from a draw,
or nothing at all headless). As for sprites, the file is looked up here (the asset
store's search, listing every place tried) and its header checked once per file;
decoding waits for the first draw.
"""

from __future__ import annotations

import functools
import os
from typing import Any

from kge.assets.store import assets_for
from kge.components.ui import Button, Panel, UIImage
from kge.components.ui_style import STATES, Style
from kge.errors import where
from kge.world import World

#: the UI components that name an image, and the field that names it
IMAGE_FIELDS: dict[type, str] = {Button: "image", Panel: "image", UIImage: "image"}


def _check_image(world: World, field: str, entity: int | None, component: Any) -> None:
    image = getattr(component, field)
    if isinstance(image, (str, os.PathLike)):
        owner = where(entity, type(component).__name__, field)
        assets_for(world).checked_image(image, owner=owner)


def _check_style(world: World, entity: int | None, style: Style, path: str = "Style") -> None:
    """A Style's nine-patch and those of its state variants (``Style.hover.image``)."""
    if isinstance(style.image, (str, os.PathLike)):
        owner = where(entity, path, "image")
        assets_for(world).checked_image(style.image, owner=owner)
    for state in STATES:
        variant = getattr(style, state)
        if variant is not None:
            _check_style(world, entity, variant, f"{path}.{state}")


def check_ui_images(world: World) -> None:
    """Refuse UI components naming a missing image at spawn, add and write (the UI
    plugin binds every UI component with the world's validators, so an ``image`` write
    is checked here too: the widgets list ``image`` in their ``_world_fields``)."""
    for ctype, field in IMAGE_FIELDS.items():
        world.validator(ctype, functools.partial(_check_image, world, field))
    world.validator(Style, functools.partial(_check_style, world))  # frozen: checked at add
