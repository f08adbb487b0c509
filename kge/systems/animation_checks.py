"""An Animator's frames are checked when it is spawned, added or given new clips.

Without this, a clip naming a missing image, a sheet grid too fine for its image or
a region outside it was found by the renderer at the first frame drawn (or never,
headless). Here each frame's image is looked up in the world's asset store, its
header checked and its size read (:meth:`kge.assets.Assets.checked_image`: nothing
is decoded), and the frame's rectangle computed from it, so the error comes from the
call that made the animator, naming the entity, the clip and the frame.

The store caches each file's size and good frames of image files are remembered, so a
thousand animators sharing one sheet read its header once and cost a set lookup per
frame afterwards.
"""

from __future__ import annotations

import os
from typing import Any

from kge.assets.store import assets_for
from kge.components.animation import Animator, FrameRef
from kge.errors import KgeError, ValidationError, where
from kge.world import World

#: frames larger than this (pixels a side) cannot go into the animation atlas
MAX_FRAME_PIXELS = 2048


class FrameSizes:
    """Frames already found good (a world resource, filled as animators arrive)."""

    def __init__(self) -> None:
        #: frames of image files already found good (their number is bounded by the
        #: files and their grids; frames of images made in code are not kept)
        self.good: set[FrameRef] = set()


def _image_size(world: World, image: Any, owner: str) -> tuple[int, int] | None:
    if hasattr(image, "width") and hasattr(image, "height"):  # an image made in code
        return int(image.width), int(image.height)
    if not isinstance(image, (str, os.PathLike)):
        return None
    return assets_for(world).checked_image(image, owner=owner)  # header read once per file


def check_frames(world: World, entity: int | None, anim: Animator) -> None:
    """Refuse an Animator whose clips name a missing image or a frame that does not fit."""
    sizes = world.try_resource(FrameSizes) or world.insert_resource(FrameSizes())
    seen: set[FrameRef] = set()
    for name, clip in anim.clips.items():
        for i, ref in enumerate(clip.frames):
            if ref in seen or ref in sizes.good:
                continue
            seen.add(ref)
            owner = f"{where(entity, 'Animator', 'clips')}[{name!r}].frames[{i}]"
            size = _image_size(world, ref.image, owner)
            if size is None or ref.gif_frame is not None:
                continue
            try:
                _, _, w, h = ref.rect(*size)
            except KgeError as exc:
                raise ValidationError(f"{owner}: {exc}") from None
            if w > MAX_FRAME_PIXELS or h > MAX_FRAME_PIXELS:
                raise ValidationError(
                    f"{owner}: a {w}x{h} frame is larger than the animation atlas allows "
                    f"({MAX_FRAME_PIXELS} pixels a side)"
                )
            if isinstance(ref.image, str):
                sizes.good.add(ref)
