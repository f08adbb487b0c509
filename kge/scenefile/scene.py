"""``SceneFile``: a scene whose setup loads a scene file (``App("levels/one.scene.toml")``)."""

from __future__ import annotations

import os
from typing import TYPE_CHECKING, Any

from kge.scene import Scene
from kge.scenefile.load import load_scene

if TYPE_CHECKING:
    from kge.world import World


class SceneFile(Scene):
    """Load ``path`` into the scene's world; keyword arguments go to :func:`load_scene`."""

    def __init__(self, path: str | os.PathLike[str], **options: Any) -> None:
        self.path = os.fspath(path)
        self.options = options
        self.name = os.path.basename(self.path).split(".")[0] or "scene"

    def setup(self, world: World, **kwargs: Any) -> None:
        load_scene(world, self.path, **{**self.options, **kwargs})

    def __repr__(self) -> str:
        return f"<SceneFile {self.path!r}>"
