"""Pure-data components. None of them holds a pymunk or pyglet object."""

from kge.components.audio import AudioListener, AudioSource, ImpactSound
from kge.components.behaviour import Behaviour, Script
from kge.components.name import Name
from kge.components.transform import Transform

__all__ = [
    "AudioListener",
    "AudioSource",
    "Behaviour",
    "ImpactSound",
    "Name",
    "Script",
    "Transform",
]
