"""Particles as numpy arrays owned by the particle system (no GL here).

* :mod:`kge.particles.pool`: one emitter's live particles (structure of arrays);
* :mod:`kge.particles.emitter`: emission bookkeeping and the ``Particles`` resource;
* :mod:`kge.particles.shapes`: where particles are born;
* :mod:`kge.particles.curves`: size / colour / alpha over life as lookup tables;
* :mod:`kge.particles.grid`: bulk collision with static colliders.

The systems live in :mod:`kge.systems.particles`, the drawing in
:mod:`kge.render.particles`.
"""

from kge.particles.emitter import EmitterState, Particles
from kge.particles.grid import StaticGrid
from kge.particles.pool import ParticlePool

__all__ = ["EmitterState", "ParticlePool", "Particles", "StaticGrid"]
