"""``TilemapPlugin``: the world's map list and the pass that draws tile layers.

Loading is one call, :func:`kge.tilemap.load_map` (exported as ``kge.load_map``):
it needs no plugin to build entities and colliders (headless tests use it on a
bare World), but maps are only drawn in worlds with this plugin. The pass is
imported lazily, so a headless App that never renders never loads GL.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

from kge.errors import KgeError
from kge.plugin import Plugin
from kge.render.passes import passes_for
from kge.systems.tilemap_animation import TileAnimationSystem
from kge.tilemap.errors import TilemapError
from kge.tilemap.runtime import MapFiles, TileMaps, maps_in
from kge.world import World


class TilemapPlugin(Plugin):
    """Inserts the :class:`~kge.tilemap.TileMaps` resource, the tile animation clock
    (:mod:`kge.systems.tilemap_animation`) and the tile drawing pass."""

    def build(self, world: World) -> None:
        maps_in(world)
        world.add_system(TileAnimationSystem())
        if not world.has_resource(MapFiles):
            world.insert_resource(
                MapFiles(lambda name: map_file(world, name), lambda: asset_roots(world))
            )
        state: dict[str, Any] = {}

        def draw_maps(frame: Any) -> None:
            renderer = state.get("renderer")
            if renderer is None:
                from kge.render.tilemap import TilemapRenderer

                renderer = state["renderer"] = TilemapRenderer(world, lambda: _poses(world))
            renderer(frame)

        draw_maps.state = state  # type: ignore[attr-defined]  # tests read the renderer
        passes_for(world).add(draw_maps, phase="before", name="tilemap", after=["animation"])


def _poses(world: World) -> Any:
    """The world's pose table (what sprites are drawn from), once it renders."""
    from kge.systems.render import RenderSystem

    rs = world.get_system(RenderSystem)
    view = getattr(rs, "view", None) if rs is not None else None
    return getattr(view, "poses", None)


def map_file(world: World, name: str | Path) -> Path:
    """A map name as a file: an existing path as it is, else through the asset store.

    Tilesets and images inside the map are found relative to the map file itself.
    """
    p = Path(name)
    if p.is_absolute() or p.is_file():
        return p.resolve()  # relative to the working directory now, never later
    from kge.assets import assets_for

    try:
        found = assets_for(world).resolve(name, owner="load_map")
    except KgeError as exc:  # AssetNotFoundError lists every place searched
        raise TilemapError(f"map file {str(name)!r} not found: {exc}") from exc
    if found.path is None:
        raise TilemapError(
            f"map {str(name)!r} is inside a package archive ({found.where}); "
            "Tiled maps and their tilesets must be files on disk"
        )
    return found.path


def asset_roots(world: World) -> list[Path]:
    """The folders of the world's asset store: a map's files may be there too."""
    from kge.assets import DirLocation, assets_for

    return [loc.root for loc in assets_for(world).locations if isinstance(loc, DirLocation)]


__all__ = ["MapFiles", "TileMaps", "TilemapPlugin", "map_file"]
