"""``HotReload``: what a running game watches, and what each kind of change does.

======================  ===============================================================
file                    on change
======================  ===============================================================
scene file, Tiled map   the scene is rebuilt from its setup and swapped in when that
                        succeeds (an error keeps the running world)
prefab file             every live instance gets the changed fields it does not
                        override (bodies keep their poses and velocities)
image, sprite sheet     textures are reloaded; sprites using them redraw
sound                   the decoded sound is dropped; the next play uses the new file
Python module           re-imported; scripts and systems switch to the new classes and
                        keep their state (see :mod:`kge.hotreload.modules`)
======================  ===============================================================

Errors are printed to the console and shown in the window until the file is fixed;
the game keeps running what it had.
"""

from __future__ import annotations

import os
import sys
from collections.abc import Iterable
from pathlib import Path
from typing import TYPE_CHECKING, Any

from kge.assets import loaders
from kge.assets.locate import DirLocation
from kge.assets.store import Assets, assets_for
from kge.components.behaviour import Behaviour
from kge.components.sprite import Sprite
from kge.components.ui import Button, Panel, UIImage
from kge.hotreload.modules import game_module, reload_module
from kge.hotreload.watcher import FileWatcher
from kge.scenefile import SceneFileError, SceneState, default_registry
from kge.scenefile.live import patch_prefab
from kge.world import World

if TYPE_CHECKING:
    from kge.host import Host

MAP_SUFFIXES = (".tmx", ".tsx", ".tmj", ".tsj", ".tx")


def _real(p: Any) -> Path:
    return Path(os.path.realpath(p))


class HotReload:
    """One per App (a resource of each of its worlds): the watcher and the reload rules."""

    def __init__(self, app: Host, modules: Iterable[str] = ()) -> None:
        self.app = app
        self.watcher = FileWatcher()
        self.modules = list(modules)
        #: file -> the error it has now (shown until the file reloads cleanly)
        self.errors: dict[Path, str] = {}
        #: what each reload did, newest last (tests and the editor's console read it)
        self.log: list[str] = []
        self._tracked: set[int] = set()

    # -- what to watch --------------------------------------------------------------------
    def track(self, world: World) -> None:
        """Watch the files ``world`` was made from (called on its first frame)."""
        if id(world) in self._tracked:
            return
        self._tracked.add(id(world))
        files: set[Path] = set()
        state = world.try_resource(SceneState)
        if state is not None:
            files.update(state.files)
            if state.source is not None:
                files.add(_real(state.source))
        from kge.tilemap.runtime import TileMaps

        maps = world.try_resource(TileMaps)
        for tmap in maps.maps if maps is not None else ():
            files.add(_real(tmap.path))
        store = assets_for(world)
        for _, (sprite,) in world.query(Sprite):
            found = _file_of(store, sprite.image)
            if found is not None:
                files.add(found)
        modules = {type(b.script).__module__ for _, (b,) in world.query(Behaviour)}
        modules |= {type(s).__module__ for s in world.schedule.systems()}
        modules |= {getattr(c, "__module__", "") for c in _registered_scripts()}
        modules |= set(self.modules)
        for name in modules:
            mod = sys.modules.get(name)
            if game_module(mod) and mod is not None and mod.__file__:
                files.add(_real(mod.__file__))
        self.watcher.watch(files)
        self.watcher.watch_trees(
            [loc.root for loc in store.locations if isinstance(loc, DirLocation)],
            (*loaders.IMAGE_SUFFIXES, *loaders.SOUND_SUFFIXES, *MAP_SUFFIXES),
        )

    def worlds(self) -> list[World]:
        return list(getattr(self.app, "visible_worlds", lambda: [])())

    # -- applying --------------------------------------------------------------------------
    def apply(self) -> list[str]:
        """Reload what changed since the last frame (on the main thread, between steps)."""
        changed = self.watcher.drain()
        done: list[str] = []
        for path in sorted(changed):
            try:
                done += self._apply_one(path)
            except Exception as exc:  # a reload must never take the game down
                self.fail(path, f"{path}: {type(exc).__name__}: {exc}")
        return done

    def _apply_one(self, path: Path) -> list[str]:
        suffix = path.suffix.lower()
        worlds = self.worlds()
        if suffix == ".py":
            self.errors.pop(path, None)
            switched = reload_module(path, worlds, lambda m: self.fail(path, m))
            if path not in self.errors:
                self.ok(path, f"reloaded {path.name}: {len(switched)} scripts and systems "
                        "switched")
            return switched
        top = worlds[-1] if worlds else None
        state = None if top is None else top.try_resource(SceneState)
        is_source = state is not None and state.source is not None and _real(
            state.source) == path
        if is_source or (suffix in MAP_SUFFIXES and self._map_of(top, path)):
            return self._reload_scene(path)
        done: list[str] = []
        if any(path in (w.try_resource(SceneState) or SceneState()).files for w in worlds):
            for world in worlds:
                try:
                    done += patch_prefab(world, path)
                except SceneFileError as exc:
                    self.fail(path, str(exc))
                    return []
            self.ok(path, f"reloaded prefab {path.name}: {len(done)} fields changed")
            return done
        if suffix in loaders.IMAGE_SUFFIXES:
            return self._reload_image(path, worlds)
        if suffix in loaders.SOUND_SUFFIXES:
            for world in worlds:
                assets_for(world).forget(path)
            self.ok(path, f"reloaded sound {path.name}")
            return [str(path)]
        if suffix in MAP_SUFFIXES and top is not None:
            return self._reload_scene(path)
        return []

    def _map_of(self, world: World | None, path: Path) -> bool:
        from kge.tilemap.runtime import TileMaps

        maps = None if world is None else world.try_resource(TileMaps)
        return any(_real(m.path) == path for m in (maps.maps if maps is not None else ()))

    def _reload_scene(self, path: Path) -> list[str]:
        reload = getattr(self.app, "reload_scene", None)
        if reload is None:
            return []
        try:
            reload()
        except Exception as exc:
            self.fail(path, str(exc) if isinstance(exc, SceneFileError) else
                      f"{path}: {type(exc).__name__}: {exc}")
            return []
        self._tracked.clear()
        self.ok(path, f"reloaded scene ({path.name})")
        return [str(path)]

    def _reload_image(self, path: Path, worlds: list[World]) -> list[str]:
        from kge.render.textures import forget_file

        for world in worlds:
            assets_for(world).forget(path)
        names = set(forget_file(str(path)))
        touched = []
        for world in worlds:
            store = assets_for(world)
            for ctype in (Sprite, UIImage, Panel, Button):
                for e, (comp,) in world.query(ctype):
                    image = getattr(comp, "image", None)
                    if image in names or _file_of(store, image) == path:
                        comp.image = image  # a write: the renderer redraws it
                        touched.append(f"entity {e} {ctype.__name__}")
        from kge.render.animation import redraw_file

        frames = redraw_file(str(path))  # animated sprites: their atlas frames, in place
        self.ok(path, f"reloaded image {path.name}: {len(touched)} drawables, "
                f"{frames} animation frames")
        return touched

    # -- messages ----------------------------------------------------------------------------
    def fail(self, path: Path, message: str) -> None:
        self.errors[path] = message
        self.log.append(f"error: {message}")
        print(f"kge hot reload: {message}", file=sys.stderr)

    def ok(self, path: Path, message: str) -> None:
        self.errors.pop(path, None)
        self.log.append(message)

    def stop(self) -> None:
        self.watcher.stop()


def _file_of(store: Assets, image: Any) -> Path | None:
    if not isinstance(image, str):
        return None
    if os.path.isabs(image):
        return _real(image)
    found = store.find(image)
    return None if found is None or found.path is None else _real(found.path)


def _registered_scripts() -> list[type]:
    reg = default_registry()
    return [c for n in reg.script_names() if (c := reg.script(n)) is not None]
