"""Hot reload: scene, prefab, map, image, sound and Python files take effect while the
game runs (docs/editor.md). ``kge.run`` turns it on with a window; tests and tools add
:class:`HotReloadPlugin` themselves."""

from kge.hotreload.plugin import HotReloadPlugin, HotReloadSystem
from kge.hotreload.reloader import HotReload
from kge.hotreload.watcher import FileWatcher

__all__ = ["FileWatcher", "HotReload", "HotReloadPlugin", "HotReloadSystem"]
