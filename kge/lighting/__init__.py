"""Light and shadow geometry with numpy (no GL here).

* :mod:`kge.lighting.occluders`: the colliders that block light, as world-space edges;
* :mod:`kge.lighting.shadows`: shadow quads for many lights at once (extruded edges).

The plugin lives in :mod:`kge.systems.lighting`, the light map in
:mod:`kge.render.lighting`.
"""

from kge.lighting.occluders import Occluders
from kge.lighting.shadows import shadow_quads

__all__ = ["Occluders", "shadow_quads"]
