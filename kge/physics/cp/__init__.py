"""The door: the only code in kge that touches pymunk's and Chipmunk's private layer.

pymunk 7.3 is kge's physics backend through its public API, plus a private layer
some hot paths need: Chipmunk's C functions (:mod:`.capi`), the private fields that
hold each object's C struct and relations (:mod:`.handles`), pymunk's batch buffers
(:mod:`.bulk`), the contact callbacks that skip pymunk's per-call wrapper
(:mod:`.collisions`) and the chain-segment fast path that builds and re-initialises
pymunk shapes itself (:mod:`.static_bulk`). Everything of that layer kge uses is
named here and pinned, function by function, to pymunk's public behaviour in
``tests/physics/test_door.py``; ``tests/architecture/test_door_only.py`` fails when
a private name appears anywhere else in kge. A pymunk upgrade touches this package
only: see "The door to pymunk" in docs/architecture.md for what to check.
"""

from kge.physics.cp.capi import FUNCTIONS, ffi, lib
from kge.physics.cp.handles import (
    arbiter_handle,
    body_constraints,
    body_handle,
    body_shapes,
    constraint_handle,
    shape_body,
    shape_handle,
    shape_hashid,
    shape_space,
    space_handle,
)

__all__ = [
    "FUNCTIONS",
    "arbiter_handle",
    "body_constraints",
    "body_handle",
    "body_shapes",
    "constraint_handle",
    "ffi",
    "lib",
    "shape_body",
    "shape_handle",
    "shape_hashid",
    "shape_space",
    "space_handle",
]
