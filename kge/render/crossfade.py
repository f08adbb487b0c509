"""Cross-fades drawn: the outgoing clip's frame as a *ghost* sprite over the incoming one.

While an animator cross-fades (``Animator.play(name, fade=...)``, a ``Transition`` with
``fade``), its sprite shows the incoming clip at full opacity and a second sprite of
the same size, pose, tint, blend and layer shows the outgoing clip's frame on top with
opacity ``1 - weight``; for opaque pixels that is ``weight * new + (1 - weight) * old``.
The ghost lives in a child group drawn after the layer's sprites and is deleted when the
fade ends, so only entities fading right now cost anything; their vertices are copied
in bulk with numpy, as :mod:`kge.render.bulk` writes poses.
Nine-patch and repeating sprites cut without a ghost.
"""

from __future__ import annotations

from typing import Any

import numpy as np
import pyglet

from kge.animation.clips import ClipState
from kge.render.programs import KgeSprite

_ATTRS = ("position", "translate", "rotation", "scale")


class _Pair:
    """Ghosts in one vertex domain whose sprites share another: the index arrays of a copy."""

    __slots__ = ("at", "ghost", "ghost_vidx", "hi", "lo", "main", "main_vidx")

    def __init__(self, main: Any, ghost: Any, members: list[tuple[int, int, int]]) -> None:
        self.main, self.ghost = main, ghost
        self.at = np.array([m[0] for m in members], np.intp)  # positions in the fading rows
        quad = np.arange(4)
        self.main_vidx = (np.array([m[1] for m in members], np.intp)[:, None] + quad).ravel()
        self.ghost_vidx = (np.array([m[2] for m in members], np.intp)[:, None] + quad).ravel()
        self.lo, self.hi = int(self.ghost_vidx.min()), int(self.ghost_vidx.max()) + 1


def _array(domain: Any, name: str) -> tuple[Any, np.ndarray]:
    buf = domain.attrib_name_buffers[name]
    return buf, np.ctypeslib.as_array(buf.data).reshape(-1, buf.count)


class FadeGhosts:
    """entity -> its ghost sprite while the entity's animator cross-fades.

    The ghosts' vertices are written in bulk: for each (sprite domain, ghost domain)
    pair, one numpy gather per attribute copies the sprites' pose, the atlas gives the
    outgoing frames' texture coordinates and the colours get the faded alpha. Ghosts are
    made or dropped (the one per-entity Python step) only when the set of fading
    entities, their atlas pages or the sprites change.
    """

    def __init__(self, batch: Any) -> None:
        self.batch = batch
        self.ghosts: dict[int, tuple[Any, int]] = {}  # entity -> (ghost sprite, atlas page)
        self._groups: dict[int, Any] = {}  # id(parent group) -> the child drawn after it
        self._pairs: list[_Pair] = []
        self._key: tuple[bytes, bytes, int] | None = None

    def __len__(self) -> int:
        return len(self.ghosts)

    def _over(self, parent: Any) -> Any:
        group = self._groups.get(id(parent))
        if group is None or group.parent is not parent:
            group = self._groups[id(parent)] = pyglet.graphics.Group(order=1, parent=parent)
        return group

    def write(self, state: ClipState, store: Any, frames: Any) -> int:
        """Make, move and fade the ghosts of every row fading now; returns how many."""
        rows = np.flatnonzero(state.from_clip >= 0) if len(state) else np.zeros(0, np.intp)
        if not len(rows) and not self.ghosts:
            return 0
        table = frames.table
        src = table.frame_src[state.from_shown[rows]]
        pages = np.asarray(frames.page_of, np.intp)[src]
        entities = state.entity[rows]
        key = (entities.tobytes(), pages.tobytes(), int(store.version))
        if key != self._key:
            self._sync(entities, pages, src, store.sprites, frames)
            self._key = key
        if not self._pairs:
            return 0
        tc = frames.tc[src * 4 + table.variant[state.from_clip[rows]]].reshape(-1, 4, 3)
        total = state.fade_len[rows]
        fade = 1.0 - np.minimum(state.fade_t[rows] / np.where(total > 0, total, 1.0), 1.0)
        for pair in self._pairs:
            for name in _ATTRS:
                _, main = _array(pair.main, name)
                _, ghost = _array(pair.ghost, name)
                ghost[pair.ghost_vidx] = main[pair.main_vidx]
            _, ghost = _array(pair.ghost, "tex_coords")
            ghost[pair.ghost_vidx] = tc[pair.at].reshape(-1, 3)
            _, main = _array(pair.main, "colors")
            _, ghost = _array(pair.ghost, "colors")
            colors = main[pair.main_vidx].astype(np.float32)
            colors[:, 3] *= np.repeat(fade[pair.at], 4)
            ghost[pair.ghost_vidx] = np.rint(colors).astype(ghost.dtype)
            for name in (*_ATTRS, "tex_coords", "colors"):
                pair.ghost.attrib_name_buffers[name].invalidate_region(pair.lo, pair.hi - pair.lo)
        return sum(len(p.at) for p in self._pairs)

    def _sync(self, entities: np.ndarray, pages: np.ndarray, src: np.ndarray,
              sprites: dict[int, Any], frames: Any) -> None:  # fmt: skip
        """Ghosts for exactly the fading entities with quad sprites; the copy plan."""
        by_pair: dict[tuple[int, int], tuple[Any, Any, list[tuple[int, int, int]]]] = {}
        wanted: set[int] = set()
        for at, (entity, page, s) in enumerate(
            zip(entities.tolist(), pages.tolist(), src.tolist(), strict=True)
        ):
            ps = sprites.get(entity)
            vl = getattr(ps, "_vertex_list", None)
            if not isinstance(ps, KgeSprite) or vl is None:
                continue  # a nine-patch (or no sprite yet): it cuts
            ghost = self._ghost(entity, ps, frames, s, page)
            gl = ghost._vertex_list
            entry = by_pair.setdefault((id(vl.domain), id(gl.domain)), (vl.domain, gl.domain, []))
            entry[2].append((at, vl.start, gl.start))
            wanted.add(entity)
        for entity in [e for e in self.ghosts if e not in wanted]:
            self.ghosts.pop(entity)[0].delete()
        self._pairs = [_Pair(main, ghost, members) for main, ghost, members in by_pair.values()]
    def _ghost(self, entity: int, ps: Any, frames: Any, src: int, page: int) -> Any:
        found = self.ghosts.get(entity)
        parent = ps.group
        if found is not None:
            ghost, at = found
            if at == page and ghost.group is self._over(parent) and (
                ghost.program is ps.program and ghost.blend_mode == ps.blend_mode
            ):
                return ghost
            ghost.delete()
        region = frames.regions[src]
        image = frames.pages[page].texture.get_region(region.x, region.y, region.width,
                                                      region.height)  # fmt: skip
        src_f, dst_f = ps.blend_mode
        ghost = KgeSprite(image, batch=self.batch, group=self._over(parent), subpixel=True,
                          blend_src=src_f, blend_dest=dst_f, program=ps.program)  # fmt: skip
        self.ghosts[entity] = (ghost, page)
        return ghost

    def clear(self) -> None:
        for ghost, _ in self.ghosts.values():
            ghost.delete()
        self.ghosts.clear()
        self._pairs, self._key = [], None
