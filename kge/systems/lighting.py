"""``LightingPlugin``: lights, shadows from colliders, and the light map pass.

The plugin inserts the :class:`~kge.components.lights.Lighting` resource (unless
the scene already did), keeps the static occluder cache fresh (collider and body
hooks) and registers a before-pass (:mod:`kge.render.passes`) that renders the
light map; pyglet is imported only when a frame is drawn. Lighting needs no
system of its own: lights and shadows are computed from the components each
drawn frame, so they follow game time through the poses they are drawn at.
"""

from __future__ import annotations

import os
from typing import Any

from kge.components.collider import Collider
from kge.components.lights import DirectionalLight, Light, Lighting, ShadowCaster
from kge.components.rigidbody import RigidBody
from kge.components.tracked import validate_writes
from kge.errors import where
from kge.lighting.occluders import Occluders
from kge.plugin import Plugin
from kge.render.passes import passes_for
from kge.schedule import Stage, System, SystemSet
from kge.snapshot import keep_resource
from kge.world import World

keep_resource(Lighting)  # scene settings: snapshots carry the ambient light


class LightingPlugin(Plugin):
    """2D lights with shadows cast by colliders. See the module docstring.

    A world without a ``Lighting`` resource is drawn unlit, so having the plugin
    in the default set changes no existing game: insert ``Lighting(ambient=...)``
    to light a scene, and toggle ``Lighting.enabled`` to switch it off and on.
    """

    def build(self, world: World) -> None:
        world.validator(Light, _check_cookie(world))  # a missing cookie file: at the call
        validate_writes(world, Light)  # a bad write names its entity
        validate_writes(world, ShadowCaster)
        occluders = world.try_resource(Occluders) or world.insert_resource(Occluders())

        def changed(entity: int, comp: Any) -> None:
            occluders.dirty = True

        for ctype in (Collider, RigidBody, ShadowCaster):
            world.on_add(ctype, changed)
            world.on_remove(ctype, changed)
        holder: dict[str, Any] = {}

        def draw(frame: Any) -> None:
            lighting = world.try_resource(Lighting)
            lm = holder.get("map")
            if lighting is None or not lighting.enabled:
                if lm is not None:  # switched off: remove the multiply from the batch
                    lm.draw(frame, Lighting(enabled=False))
                return
            from kge.render.lighting import LightMap
            from kge.systems.render import RenderSystem

            rs = world.get_system(RenderSystem)
            view = rs.view if rs is not None else None
            if lm is None or lm.batch is not frame.batch:
                if lm is not None:
                    lm.close()
                textures = view.textures if view is not None else None
                lm = holder["map"] = LightMap(world, frame.batch, frame.groups, occluders,
                                              textures)  # fmt: skip
            lm.draw(frame, lighting, view.sprites.normals if view is not None else None)

        passes_for(world).add(draw, phase="view", name="lighting")
        world.add_system(_LightMapOwner(holder))


def _check_cookie(world: World) -> Any:
    """A Light whose ``texture`` names a file that is missing or cannot load is refused
    at spawn and write (as a Sprite's image), not at the first lit frame."""

    def check(entity: int | None, light: Light) -> None:
        if isinstance(light.texture, (str, os.PathLike)):
            from kge.assets.store import assets_for

            assets_for(world).checked_image(light.texture,
                                            owner=where(entity, "Light", "texture"))

    return check


class _LightMapOwner(System):
    """Frees the world's light map when the world closes (its GL objects belong to one
    window's context, so they are deleted there and then, not by the garbage collector)."""

    stage = Stage.RENDER
    in_set = SystemSet.LAST

    def __init__(self, holder: dict[str, Any]) -> None:
        self.holder = holder

    def process(self, dt: float) -> None:
        """Nothing per frame: the light map is drawn by the render pass."""

    def detach(self) -> None:
        lm = self.holder.pop("map", None)
        if lm is not None:
            lm.close()


__all__ = ["DirectionalLight", "Light", "Lighting", "LightingPlugin", "ShadowCaster"]
