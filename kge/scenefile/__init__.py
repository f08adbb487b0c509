"""Scene, prefab and save files: a text format that never runs code (docs/scene-files.md).

* :func:`load_scene` / :func:`save_scene`: a level in a ``.scene.toml`` file; any
  world (or some of its entities) saves back, and save, load, save is byte-identical.
* :func:`instantiate` / :func:`save_prefab`: entity templates (a car, a ragdoll) in
  ``.prefab.toml`` files, placed many times with per-instance overrides.
* :func:`save_game` / :func:`load_game`: game saves with every field and id, restored
  by ``app.restore(load_game(path))``.
* :func:`register_type` / :func:`register_script`: the game's own types, the only
  names besides kge's that a file may use.
"""

from kge.scenefile.codec import LIMITS, Limits
from kge.scenefile.default import default_registry, register_script, register_type
from kge.scenefile.errors import SceneFileError, Where
from kge.scenefile.load import (
    instantiate,
    load_scene,
    load_scene_text,
    resolve_file,
    scene_state,
)
from kge.scenefile.migrate import FORMAT, migration
from kge.scenefile.registry import TypeInfo, TypeRegistry
from kge.scenefile.save import dumps, save_game, save_prefab, save_scene
from kge.scenefile.saves import SavedGame, load_game
from kge.scenefile.scene import SceneFile
from kge.scenefile.state import Instance, SceneState

__all__ = [
    "FORMAT",
    "LIMITS",
    "Instance",
    "Limits",
    "SavedGame",
    "SceneFile",
    "SceneFileError",
    "SceneState",
    "TypeInfo",
    "TypeRegistry",
    "Where",
    "default_registry",
    "dumps",
    "instantiate",
    "load_game",
    "load_scene",
    "load_scene_text",
    "migration",
    "register_script",
    "register_type",
    "resolve_file",
    "save_game",
    "save_prefab",
    "save_scene",
    "scene_state",
]
