"""``HotReloadPlugin``: reload changed files while the game runs (``kge.run`` turns it on
when it opens a window; add it yourself for other Apps)."""

from __future__ import annotations

from collections.abc import Iterable
from typing import TYPE_CHECKING, Any

from kge.hotreload.reloader import HotReload
from kge.plugin import Plugin
from kge.schedule import Stage, System, SystemSet

if TYPE_CHECKING:
    from kge.host import Host
    from kge.world import World


class HotReloadSystem(System):
    """First thing of every frame's update: start watching the world, apply changes."""

    stage = Stage.UPDATE
    in_set = SystemSet.FIRST

    def __init__(self, reloader: HotReload) -> None:
        self.reloader = reloader

    def process(self, dt: float) -> None:
        self.reloader.track(self.world)
        if self.reloader.watcher.pending():
            self.reloader.apply()


class HotReloadPlugin(Plugin):
    """Watches the scene, prefab, map, image, sound and Python files the game runs on.

    ``modules``: extra module names to watch (the modules of Behaviour scripts,
    systems and registered scripts are watched anyway).
    """

    def __init__(self, modules: Iterable[str] = ()) -> None:
        self.modules = list(modules)
        self.reloader: HotReload | None = None

    def build_app(self, app: Host) -> None:
        self.reloader = HotReload(app, self.modules)

    def build(self, world: World) -> None:
        reloader = self.reloader
        if reloader is None:  # a world built without an App: watch nothing
            return
        world.insert_resource(reloader)
        world.add_system(HotReloadSystem(reloader))
        from kge.render.passes import passes_for

        passes_for(world).add(_overlay(reloader), phase="after", name="hot_reload", after=["ui"])

    def cleanup(self, app: Host) -> None:
        if self.reloader is not None:
            self.reloader.stop()


def _overlay(reloader: HotReload) -> Any:
    """An after-pass drawing the current reload errors over the game (red, top left)."""
    cache: dict[str, Any] = {}

    def draw(frame: Any) -> None:
        text = "\n".join(reloader.errors.values())
        if not text:
            cache.clear()
            return
        label = cache.get(text)
        if label is None:
            import pyglet

            cache.clear()
            label = cache[text] = pyglet.text.Label(
                f"hot reload: {text}", font_size=12, color=(255, 90, 90, 255), multiline=True,
                width=max(200, frame.viewport[0] - 20), anchor_x="left", anchor_y="top",
            )
        label.position = (10.0, frame.viewport[1] - 10.0, 0.0)
        label.draw()

    return draw
