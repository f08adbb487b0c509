"""Animated sprites on the GPU: frames packed in atlases, texture coordinates written in bulk.

Why: swapping a pyglet sprite's image is a Python call per sprite (pyglet's own
animated Sprite does one per frame change, through its clock). Here every frame
of every clip a world uses is packed once into an atlas *page* (a
:class:`pyglet.image.atlas.TextureAtlas`), so the animated sprites of a layer share
a texture and a vertex domain; each frame the texture coordinates of all of them
are gathered from a (frames x 4 flips, 12) table by the numpy state's shown frame
and written into the domain's ``tex_coords`` buffer with one assignment, the way
:mod:`kge.render.bulk` writes poses.

Pages grow and split: the first is 2048 pixels square; when a frame does not fit,
the next page is twice as big (up to the GPU's largest texture), so a 4096 x 3584
sprite sheet animates; a frame larger than the largest texture is refused with a
clear error. A sprite whose shown frame is on another page than its texture moves
to that page (it is synced again; frames of one clip usually share a page).

The animated sprite itself is the entity's :class:`~kge.render.sprites.SpriteStore`
sprite: :meth:`AtlasFrames.frame_region` is the store's ``frame_source``, so the
sprite is created on the atlas (its size, anchor, tint and layer still come from
the Sprite component). Frames of one animator share one pixel size.
"""

from __future__ import annotations

import os
import weakref
from typing import Any

import numpy as np
import pyglet

from kge.animation.clips import ClipState, ClipTable
from kge.animation.gif import gif_frames
from kge.components.animation import FrameRef
from kge.errors import KgeError, ValidationError
from kge.render.images import PixelImage

ATLAS_SIZE = 2048
#: the largest atlas page kge makes, pixels a side (also bounded by the GPU's limit)
MAX_ATLAS_SIZE = 16384
# vertex order of a pyglet sprite quad: bottom-left, bottom-right, top-right, top-left
_FLIPS = ([0, 1, 2, 3], [1, 0, 3, 2], [3, 2, 1, 0], [2, 3, 0, 1])


#: every live atlas, so a changed sprite sheet reaches them all (hot reload)
_ATLASES: weakref.WeakSet[AtlasFrames] = weakref.WeakSet()


def redraw_file(path: str) -> int:
    """The image file ``path`` changed: every atlas draws the frames cut from it again
    (see :meth:`AtlasFrames.redraw_file`); how many frames were redrawn."""
    return sum(atlas.redraw_file(path) for atlas in list(_ATLASES))


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
        self.pages: list[Any] = []
        self.atlas = self._new_page(ATLAS_SIZE)
        #: ``fn(entities)``: sync these sprites again (their frame moved to another page)
        self.migrate: Any = None
        self.regions: list[Any] = []
        self.page_of: list[int] = []
        self.tc = np.zeros((0, 12), np.float32)
        self._images: dict[Any, Any] = {}
        self._key: tuple[int, int, int] | None = None
        self._domains: list[tuple[Any, np.ndarray, np.ndarray, tuple[int, int] | None, int,
                                  np.ndarray]] = []
        _ATLASES.add(self)

    # -- packing ------------------------------------------------------------------------
    @staticmethod
    def largest() -> int:
        from pyglet import gl

        found = gl.GLint()
        gl.glGetIntegerv(gl.GL_MAX_TEXTURE_SIZE, found)
        return min(int(found.value), MAX_ATLAS_SIZE)

    def _new_page(self, size: int) -> Any:
        from pyglet import gl

        atlas = pyglet.image.atlas.TextureAtlas(size, size)
        tex = atlas.texture
        gl.glBindTexture(tex.target, tex.id)
        gl.glTexParameteri(tex.target, gl.GL_TEXTURE_MAG_FILTER, gl.GL_NEAREST)
        gl.glTexParameteri(tex.target, gl.GL_TEXTURE_MIN_FILTER, gl.GL_NEAREST)
        self.pages.append(atlas)
        return atlas

    def _place(self, image: Any) -> tuple[Any, int]:
        """Put ``image`` in the last page, or in a new, bigger one; (region, page)."""
        try:
            return self.atlas.add(image, border=1), len(self.pages) - 1
        except pyglet.image.atlas.AllocatorException:
            pass
        largest = self.largest()
        need = max(image.width, image.height) + 2
        if need > largest:
            raise KgeError(
                f"an animation frame of {image.width}x{image.height} pixels is larger than "
                f"the largest texture this GPU makes ({largest}x{largest}): cut the sheet "
                "into smaller frames"
            )
        size = min(largest, max(self.atlas.texture.width * 2, 1 << (need - 1).bit_length()))
        self.atlas = self._new_page(size)
        return self.atlas.add(image, border=1), len(self.pages) - 1

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
                region, page = self._place(image)
            except (KgeError, OSError) as exc:
                raise ValidationError(f"animation frame {ref!r}: {exc}") from exc
            self.regions.append(region)
            self.page_of.append(page)
            corners = np.asarray(region.tex_coords, np.float32).reshape(4, 3)
            rows.extend(corners[order].ravel() for order in _FLIPS)
        self.tc = np.concatenate([self.tc, np.array(rows, np.float32).reshape(-1, 12)])

    def redraw_file(self, path: str) -> int:
        """Draw the packed frames cut from the image file ``path`` again, from its pixels
        now: in place when a frame keeps its size (else in a new atlas slot), so every
        animator keeps its clip, frame and time. All frames are cut before any is drawn:
        a sheet that no longer holds them is refused and the old frames stay."""
        from kge.assets import assets_for

        target = os.path.realpath(path)
        store = assets_for(self.world)

        def from_file(image: Any) -> bool:
            if not isinstance(image, str):
                return False
            found = store.find(image)
            where = image if found is None or found.path is None else found.path
            return os.path.realpath(where) == target

        sources = self.table.sources[: len(self.regions)]
        hit = [i for i, ref in enumerate(sources) if from_file(ref.image)]
        if not hit:
            return 0
        names = {sources[i].image for i in hit}
        stale = {k: v for k, v in self._images.items()
                 if k in names or (isinstance(k, tuple) and k[0] == "gif" and k[1] in names)}
        for k in stale:
            del self._images[k]
        try:
            images = [self._source_image(sources[i]) for i in hit]
        except (KgeError, OSError) as exc:
            self._images.update(stale)
            raise ValidationError(f"sprite sheet {path}: {exc}") from exc
        for i, image in zip(hit, images, strict=True):
            region = self.regions[i]
            if (image.width, image.height) == (region.width, region.height):
                region.blit_into(image, 0, 0, 0)
                continue
            region, self.page_of[i] = self._place(image)
            self.regions[i] = region
            corners = np.asarray(region.tex_coords, np.float32).reshape(4, 3)
            self.tc[4 * i : 4 * i + 4] = [corners[order].ravel() for order in _FLIPS]
        self._key = None  # a frame may have moved to another page
        return len(hit)

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
        return self.pages[self.page_of[src]].texture, (r.x, r.y, r.width, r.height)

    # -- bulk write -----------------------------------------------------------------------
    def _rebuild(self) -> None:
        """Group the animated sprites by vertex domain, sorted by vertex start."""
        by_domain: dict[int, tuple[Any, int, list[tuple[int, int, int]]]] = {}
        page_ids = {atlas.texture.id: i for i, atlas in enumerate(self.pages)}
        for entity, row in self.state.rows.items():
            ps = self.sprites.sprites.get(entity)
            page = page_ids.get(ps._texture.id) if ps is not None else None
            if page is None:
                continue
            vl = ps._vertex_list
            entry = by_domain.setdefault(id(vl.domain), (vl.domain, page, []))
            entry[2].append((vl.start, row, entity))
        self._domains = []
        for domain, page, members in by_domain.values():
            members.sort()
            starts = np.array([m[0] for m in members], np.intp)
            rows = np.array([m[1] for m in members], np.intp)
            entities = np.array([m[2] for m in members], np.intp)
            lo = int(starts[0])
            block = (lo, lo + 4 * len(starts)) if np.array_equal(
                starts, lo + 4 * np.arange(len(starts))
            ) else None
            vidx = (starts[:, None] + np.arange(4)).ravel()
            self._domains.append((domain, rows, vidx, block, page, entities))

    def write(self, retry: bool = True) -> int:
        """Write every animated sprite's frame into its vertex buffer; returns sprites written."""
        self.pack()
        key = (self.state.version, self.sprites.version, self.table.version)
        if key != self._key:
            self._rebuild()
            self._key = key
        if not self._domains:
            return 0
        table, state = self.table, self.state
        src = table.frame_src[state.shown]
        tc_row = src * 4 + table.variant[state.clip]
        if len(self.pages) > 1 and retry:  # a sprite showing another page's frame moves there
            pages = np.asarray(self.page_of, np.intp)[src]
            away = [ents[pages[rows] != page] for _, rows, _, _, page, ents in self._domains]
            moving = np.concatenate(away) if away else np.zeros(0, np.intp)
            if len(moving) and self.migrate is not None:
                self.migrate([int(e) for e in moving])
                self._key = None
                return self.write(retry=False)
        written = 0
        for domain, rows, vidx, block, _, _ in self._domains:
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
