"""Audio internals: handles, the mixer, positional math and the ``Audio`` resource.

Nothing here imports ``pyglet.media`` at import time; the mixer loads it when
the first sound plays. Games use :class:`~kge.audio.resource.Audio` (through
``world.resource(Audio)``) and the components in :mod:`kge.components.audio`;
:mod:`kge.systems.audio` ties them to a world.
"""

from kge.audio.handle import SoundHandle
from kge.audio.mixer import Mixer
from kge.audio.resource import Audio
from kge.audio.spatial import pan_and_gain

__all__ = ["Audio", "Mixer", "SoundHandle", "pan_and_gain"]
