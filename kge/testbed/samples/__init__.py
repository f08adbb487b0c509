"""Every sample module; importing this package registers them all."""

from kge.testbed.samples import (  # noqa: F401
    animation,
    basics,
    bodies,
    box2d_api,
    collision,
    collision_module,
    determinism,
    joints,
    large,
    lights,
    materials,
    particles,
    queries,
    stacking,
    tilemaps,
    ui,
    ui_editor,
    ui_overlays,
    ui_scrolling,
    ui_world,
)
