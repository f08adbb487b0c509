"""Assets: find a game's images, sounds and fonts by name, load each once.

Importing this package does not import pyglet; decoding does, on first use.
See :mod:`kge.assets.store` for how names are resolved and how a world finds
its store, and :mod:`kge.sound` for sounds generated in code.
"""

from kge.assets.errors import AssetDecodeError, AssetError, AssetNotFoundError, DecoderMissingError
from kge.assets.locate import DirLocation, Found, PackageLocation
from kge.assets.preload import AssetsLoaded, BackgroundPreload
from kge.assets.store import (
    Assets,
    FontAsset,
    Preload,
    assets_for,
    default_assets,
    set_default_assets,
)
from kge.sound import SoundData, SoundRef, melody, mix, silence, tone

__all__ = [
    "AssetDecodeError",
    "AssetError",
    "AssetNotFoundError",
    "Assets",
    "AssetsLoaded",
    "BackgroundPreload",
    "DecoderMissingError",
    "DirLocation",
    "FontAsset",
    "Found",
    "PackageLocation",
    "Preload",
    "SoundData",
    "SoundRef",
    "assets_for",
    "default_assets",
    "melody",
    "mix",
    "set_default_assets",
    "silence",
    "tone",
]
