"""Tiled's tile animations played by kge.animation's numpy clips, on game time.

Why not a ticker of its own: kge.animation already keeps every animator's
time and frame in flat arrays and advances them all in one numpy pass
(:class:`~kge.animation.clips.ClipState`), with the game-time rules (pause,
``time_scale``, single step) handled once by the schedule's UPDATE dt. A tile
animation is just such a clip: its frames are the tiles' pixels (a
:class:`~kge.components.animation.FrameRef` into the tileset image) and its
durations Tiled's. Each map gets one clip table and one row per *animated
gid* (every tile of that gid shows the same frame, as in Tiled), so the cost
per frame is one ``advance`` per map, whatever the map's size.

After each pass :attr:`kge.tilemap.TileMap.shown` maps every animated gid to
the gid of the frame it shows; the tile renderer rebuilds a visible chunk
when one of its animated tiles changed frame.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from kge.animation.clips import ClipState, ClipTable
from kge.components.animation import Clip, FrameRef
from kge.schedule import Stage, System, SystemSet
from kge.systems.animation import AnimationSystem, TweenSystem
from kge.tilemap.model import GidTable
from kge.tilemap.runtime import TileMaps


@dataclass(slots=True)
class MapClips:
    """One map's tile clips: a clip table, one playing row per animated gid."""

    state: ClipState
    gids: np.ndarray  #: the animated gid of each row
    source_gid: np.ndarray  #: the table's frame source id -> the tile gid it shows

    @classmethod
    def of(cls, tiles: GidTable) -> MapClips:
        table = ClipTable()
        state = ClipState(table)
        gids = sorted(tiles.animations)
        state.add_many(gids)  # row i is gids[i] (the "entity" of a row is its gid)
        source_gid: dict[int, int] = {}
        for row, g in enumerate(gids):
            frames, ends = tiles.animations[g]
            durations = np.diff(np.concatenate([[0.0], ends]))
            refs = tuple(_frame_ref(tiles, int(f)) for f in frames.tolist())
            info = table.register(Clip(refs, tuple(durations.tolist())))
            for ref, f in zip(refs, frames.tolist(), strict=True):
                source_gid[table.source_id(ref)] = int(f)
            state.start(row, info.slot)
        state.playing[:] = True
        lookup = np.zeros(len(table.sources), np.int64)
        for sid, f in source_gid.items():
            lookup[sid] = f
        return cls(state, np.array(gids, np.int64), lookup)

    def advance(self, dt: float) -> np.ndarray:
        """Move every tile clip by ``dt`` seconds; the gid each row shows now."""
        self.state.advance(dt)
        return self.source_gid[self.state.table.frame_src[self.state.shown]]


def _frame_ref(tiles: GidTable, gid: int) -> FrameRef:
    x, y, w, h = (int(v) for v in tiles.rect[gid])
    return FrameRef(str(tiles.images[int(tiles.image[gid])]), region=(x, y, w, h))


class TileAnimationSystem(System):
    """Advances the tile clips of every loaded map on the UPDATE stage's game time."""

    stage = Stage.UPDATE
    in_set = SystemSet.ANIMATION
    after = (AnimationSystem,)
    before = (TweenSystem,)

    def process(self, dt: float) -> None:
        maps = self.world.try_resource(TileMaps)
        for tmap in maps.maps if maps is not None else ():
            if not tmap.data.tiles.animations:
                continue
            clips = tmap.clock
            if clips is None:  # kept on the map: snapshots carry it, so a restore goes on
                clips = tmap.clock = MapClips.of(tmap.data.tiles)
            tmap.shown[clips.gids] = clips.advance(dt)
