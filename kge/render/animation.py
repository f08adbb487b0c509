"""Animated sprites on the GPU: frames packed in one atlas, texture coordinates written in bulk.

Why: swapping a pyglet sprite's image is a Python call per sprite (pyglet's own
animated Sprite does one per frame change, through its clock). Here every frame
of every clip a world uses is packed once into a :class:`pyglet.image.atlas.
TextureAtlas`, so all animated sprites of a layer share one texture and one
vertex domain; each frame the texture coordinates of all of them are gathered
from a (frames x 4 flips, 12) table by the numpy state's shown frame and
written into the domain's ``tex_coords`` buffer with one assignment, the way
:mod:`kge.render.bulk` writes poses.

The animated sprite itself is the entity's :class:`~kge.render.sprites.SpriteStore`
sprite: :meth:`AtlasFrames.frame_region` is the store's ``frame_source``, so the
sprite is created on the atlas (its size, anchor, tint and layer still come from
the Sprite component). Frames of one animator share one pixel size.
"""

from __future__ import annotations

from typing import Any

import numpy as np
import pyglet

from kge.animation.clips import ClipState, ClipTable
from kge.animation.gif import gif_frames
from kge.components.animation import FrameRef
from kge.errors import KgeError, ValidationError
from kge.render.images import PixelImage

ATLAS_SIZE = 2048
# vertex order of a pyglet sprite quad: bottom-left, bottom-right, top-right, top-left
_FLIPS = ([0, 1, 2, 3], [1, 0, 3, 2], [3, 2, 1, 0], [2, 3, 0, 1])


class AtlasFrames:
    """The atlas of one world's animation frames and the bulk texture-coordinate writer."""

    @property
    def table(self) -> ClipTable:
        """The state's clip table (a new one after each compaction; sources keep ids)."""
        return self.state.table

    def __init__(
        self, world: Any, table: ClipTable, state: ClipState, sprites: Any, sync: Any = None
    ) -> None:
        self.world = world
        #: brings ``state`` up to date with the components (new animators get rows)
        self.sync = sync
        self.state = state
        self.sprites = sprites
        self.atlas = pyglet.image.atlas.TextureAtlas(ATLAS_SIZE, ATLAS_SIZE)
        tex = self.atlas.texture
        from pyglet import gl

        gl.glBindTexture(tex.target, tex.id)
        gl.glTexParameteri(tex.target, gl.GL_TEXTURE_MAG_FILTER, gl.GL_NEAREST)
        gl.glTexParameteri(tex.target, gl.GL_TEXTURE_MIN_FILTER, gl.GL_NEAREST)
        self.regions: list[Any] = []
        self.tc = np.zeros((0, 12), np.float32)
        self._images: dict[Any, Any] = {}
        self._key: tuple[int, int, int] | None = None
        self._domains: list[tuple[Any, np.ndarray, np.ndarray, tuple[int, int] | None]] = []

    # -- packing ------------------------------------------------------------------------
    def _source_image(self, ref: FrameRef) -> Any:
        """pyglet ImageData of the frame's pixels (whole images decoded once)."""
        img = ref.image
        key: Any
        if ref.gif_frame is not None:
            key = ("gif", img)
            frames = self._images.get(key)
            if frames is None:
                from kge.assets import assets_for

                frames = self._images[key] = gif_frames(assets_for(self.world).bytes(img))
            if ref.gif_frame >= len(frames):
                raise ValidationError(
                    f"GIF {img!r} has {len(frames)} frames, not {ref.gif_frame + 1}"
                )
            arr = frames[ref.gif_frame]
            h, w = arr.shape[:2]
            return pyglet.image.ImageData(w, h, "RGBA", arr.tobytes())
        key = img if isinstance(img, (str, PixelImage)) else ("object", id(img))
        whole = self._images.get(key)
        if whole is None:
            if isinstance(img, PixelImage):
                whole = pyglet.image.ImageData(img.width, img.height, "RGBA", img.pixels)
            elif isinstance(img, str):
                from kge.assets import assets_for

                whole = assets_for(self.world).image(img)
            elif hasattr(img, "get_image_data"):
                whole = img
            else:
                raise ValidationError(
                    f"cannot draw {img!r}: not an asset name, PixelImage or image"
                )
            whole = whole.get_image_data()
            self._images[key] = whole
        x, y, w, h = ref.rect(whole.width, whole.height)
        return whole.get_region(x, y, w, h).get_image_data()

    def pack(self) -> None:
        """Put every registered frame source not yet in the atlas into it."""
        sources = self.table.sources
        start = len(self.regions)
        if start == len(sources):
            return
        rows: list[np.ndarray] = []
        for ref in sources[start:]:
            try:
                image = self._source_image(ref)
                if max(image.width, image.height) + 2 > ATLAS_SIZE:  # the 1 px border
                    raise ValidationError(
                        f"{image.width}x{image.height} pixels is larger than the animation "
                        f"atlas ({ATLAS_SIZE}x{ATLAS_SIZE}); "
                        "split it into smaller frames or draw it as a plain Sprite"
                    )
                region = self.atlas.add(image, border=1)
            except pyglet.image.atlas.AllocatorException as exc:
                raise KgeError(
                    f"the animation atlas ({ATLAS_SIZE}x{ATLAS_SIZE}) is full: too many distinct "
                    "frames in one scene"
                ) from exc
            except (KgeError, OSError) as exc:
                raise ValidationError(f"animation frame {ref!r}: {exc}") from exc
            self.regions.append(region)
            corners = np.asarray(region.tex_coords, np.float32).reshape(4, 3)
            rows.extend(corners[order].ravel() for order in _FLIPS)
        self.tc = np.concatenate([self.tc, np.array(rows, np.float32).reshape(-1, 12)])

    def frame_region(self, entity: int) -> tuple[Any, tuple[int, int, int, int]] | None:
        """The store's ``frame_source``: the atlas texture and the entity's current frame."""
        if self.sync is not None:
            self.sync()
        row = self.state.rows.get(entity)
        if row is None:
            return None
        self.pack()
        src = int(self.table.frame_src[self.state.shown[row]])
        r = self.regions[src]
        return self.atlas.texture, (r.x, r.y, r.width, r.height)

    # -- bulk write -----------------------------------------------------------------------
    def _rebuild(self) -> None:
        """Group the animated sprites by vertex domain, sorted by vertex start."""
        by_domain: dict[int, tuple[Any, list[tuple[int, int]]]] = {}
        atlas_id = self.atlas.texture.id
        for entity, row in self.state.rows.items():
            ps = self.sprites.sprites.get(entity)
            if ps is None or ps._texture.id != atlas_id:
                continue
            vl = ps._vertex_list
            by_domain.setdefault(id(vl.domain), (vl.domain, []))[1].append((vl.start, row))
        self._domains = []
        for domain, members in by_domain.values():
            members.sort()
            starts = np.array([m[0] for m in members], np.intp)
            rows = np.array([m[1] for m in members], np.intp)
            lo = int(starts[0])
            block = (lo, lo + 4 * len(starts)) if np.array_equal(
                starts, lo + 4 * np.arange(len(starts))
            ) else None
            vidx = (starts[:, None] + np.arange(4)).ravel()
            self._domains.append((domain, rows, vidx, block))

    def write(self) -> int:
        """Write every animated sprite's frame into its vertex buffer; returns sprites written."""
        self.pack()
        key = (self.state.version, self.sprites.version, self.table.version)
        if key != self._key:
            self._rebuild()
            self._key = key
        if not self._domains:
            return 0
        table, state = self.table, self.state
        tc_row = table.frame_src[state.shown] * 4 + table.variant[state.clip]
        written = 0
        for domain, rows, vidx, block in self._domains:
            buf = domain.attrib_name_buffers["tex_coords"]
            arr = np.ctypeslib.as_array(buf.data).reshape(-1, 3)
            values = self.tc[tc_row[rows]].reshape(-1, 3)
            if block is not None:
                arr[block[0] : block[1]] = values
                buf.invalidate_region(block[0], block[1] - block[0])
            else:
                arr[vidx] = values
                buf.invalidate_region(int(vidx.min()), int(vidx.max()) + 1 - int(vidx.min()))
            written += len(rows)
        return written
