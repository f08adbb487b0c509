"""Every sample module; importing this package registers them all."""

from kge.testbed.samples import (  # noqa: F401
    animation,
    basics,
    bodies,
    box2d_api,
    collision,
    collision_module,
    determinism,
    games,
    joints,
    large,
    lights,
    materials,
    particles,
    queries,
    stacking,
    tilemaps,
    ui,
)
