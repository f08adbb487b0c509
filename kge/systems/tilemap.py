"""``TilemapPlugin``: the world's map list and the pass that draws tile layers.

Loading is one call, :func:`kge.tilemap.load_map` (exported as ``kge.load_map``):
it needs no plugin to build entities and colliders (headless tests use it on a
bare World), but maps are only drawn in worlds with this plugin. The pass is
imported lazily, so a headless App that never renders never loads GL.
"""

from __future__ import annotations

from typing import Any

from kge.plugin import Plugin
from kge.render.passes import passes_for
from kge.tilemap.runtime import TileMaps, maps_in
from kge.world import World

#: before-pass order: maps upload their chunks before other game-layer passes
PASS_ORDER = -100


class TilemapPlugin(Plugin):
    """Inserts the :class:`~kge.tilemap.TileMaps` resource and the tile drawing pass."""

    def build(self, world: World) -> None:
        maps_in(world)
        state: dict[str, Any] = {}

        def draw_maps(frame: Any) -> None:
            renderer = state.get("renderer")
            if renderer is None:
                from kge.render.tilemap import TilemapRenderer

                renderer = state["renderer"] = TilemapRenderer(world)
            renderer(frame)

        draw_maps.state = state  # type: ignore[attr-defined]  # tests read the renderer
        passes_for(world).add(draw_maps, phase="before", order=PASS_ORDER)


__all__ = ["TileMaps", "TilemapPlugin"]
