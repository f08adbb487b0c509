"""The default plugin set: what ``App(scene)`` is made of when ``plugins=`` is left out.

=====================  =================================================================
``BehaviourPlugin``    Behaviour scripts: input hooks, fixed/update/late hooks, coroutines
``PhysicsPlugin``      Box2D-style physics on pymunk, contact events, joints, queries
``CharacterPlugin``    characters that collide and slide (``CharacterBody``), in the fixed step
``AudioPlugin``        sounds and music on pyglet (loaded on the first sound)
``RenderPlugin``       camera follow; the window and drawing on the first ``app.render()``
``AnimationPlugin``    sprite clips (Animator), tweens, camera shake
``ParticlesPlugin``    particle emitters: numpy particles, bursts on hits, drawn per layer
``LightingPlugin``     2D lights and a light map, shadows cast by colliders
``UIPlugin``           screen-space widgets, layout, focus, UI events (drawn on top)
``TilemapPlugin``      Tiled maps loaded with ``kge.load_map`` are drawn (chunked, culled)
``DebugPlugin``        gizmos, the in-game console, the live inspector, system timings
=====================  =================================================================

Each plugin lives beside the systems it installs (``kge/systems/``); this module
only lists them, and imports each when the list is asked for, so an App built from
a chosen list never imports the others. Game-layer plugins join this list as they
land.
"""

from __future__ import annotations

from kge.plugin import Plugin


def default_plugins() -> list[Plugin]:
    """A fresh instance of every default plugin, in build order."""
    from kge.debug.plugin import DebugPlugin
    from kge.systems.animation import AnimationPlugin
    from kge.systems.audio import AudioPlugin
    from kge.systems.behaviour import BehaviourPlugin
    from kge.systems.character import CharacterPlugin
    from kge.systems.lighting import LightingPlugin
    from kge.systems.particles import ParticlesPlugin
    from kge.systems.physics import PhysicsPlugin
    from kge.systems.render import RenderPlugin
    from kge.systems.tilemap import TilemapPlugin
    from kge.systems.ui import UIPlugin

    return [
        BehaviourPlugin(),
        PhysicsPlugin(),
        CharacterPlugin(),
        AudioPlugin(),
        RenderPlugin(),
        AnimationPlugin(),
        ParticlesPlugin(),
        LightingPlugin(),
        UIPlugin(),
        TilemapPlugin(),
        DebugPlugin(),
    ]
