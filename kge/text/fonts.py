"""Which font families exist: registered files and the system's fonts (no GL, no pyglet).

kge asks the system's fontconfig (through ctypes, on Linux and BSD) whether a family
is installed, and keeps its own registry of font files added by the game
(:func:`register_file`, ``assets.font``). A family neither knows is reported with a
:class:`FontWarning` naming it (once per family), then drawn in the default family:
never a silent fallback.

>>> info = FONTS.register(b"not a font", "x.ttf")
Traceback (most recent call last):
...
kge.errors.ValidationError: x.ttf is not a TrueType/OpenType font (no name table)
"""

from __future__ import annotations

import ctypes
import ctypes.util
import functools
import os
import warnings
from collections.abc import Callable
from dataclasses import dataclass, field

from kge.errors import ValidationError
from kge.text.bitmap import BitmapFont
from kge.text.fontfile import FaceInfo, face_info

#: the suffixes of font files (a ``font`` value ending so is a file, not a family)
FONT_SUFFIXES = (".ttf", ".otf", ".ttc", ".otc")


class FontWarning(UserWarning):
    """A font family that is neither installed nor registered was asked for."""


def is_font_file(name: str) -> bool:
    """Whether a ``font`` value names a file (by its suffix) rather than a family."""
    return name.lower().endswith(FONT_SUFFIXES)


@dataclass(slots=True)
class RegisteredFace:
    """A face from a font file the game registered: its description and bytes."""

    info: FaceInfo
    data: bytes
    where: str


@dataclass(slots=True)
class FontRegistry:
    """Font files registered by the game, by family (one per process, like pyglet's)."""

    faces: dict[str, list[RegisteredFace]] = field(default_factory=dict)
    by_where: dict[str, RegisteredFace] = field(default_factory=dict)
    #: font file names as games write them (asset names) -> where the file was read
    names: dict[str, str] = field(default_factory=dict)
    warned: set[str] = field(default_factory=set)
    #: bitmap fonts by family name (:func:`register_bitmap_font`)
    bitmaps: dict[str, BitmapFont] = field(default_factory=dict)
    #: called with each newly registered face (the renderer hands it to its font engine)
    listeners: list[Callable[[RegisteredFace], None]] = field(default_factory=list)

    def register(self, data: bytes, where: str) -> FaceInfo:
        """Record the face in ``data`` (read from ``where``); returns what it is."""
        found = self.by_where.get(where)
        if found is not None and found.data == data:
            return found.info
        info = face_info(data)
        if info is None:
            raise ValidationError(f"{where} is not a TrueType/OpenType font (no name table)")
        face = RegisteredFace(info, data, where)
        self.by_where[where] = face
        family = self.faces.setdefault(info.family.lower(), [])
        family[:] = [f for f in family if f.where != where] + [face]
        for listener in self.listeners:
            listener(face)
        return info

    def register_bitmap(self, name: str, font: BitmapFont) -> None:
        """Make ``font`` usable as family ``name``."""
        if not isinstance(font, BitmapFont):
            raise ValidationError(f"register_bitmap_font: {font!r} is not a BitmapFont")
        if not isinstance(name, str) or not name.strip():
            raise ValidationError("register_bitmap_font: the family name must be a non-empty str")
        self.bitmaps[name.lower()] = font

    def bitmap(self, name: str) -> BitmapFont | None:
        return self.bitmaps.get(name.lower())

    def file(self, name: str) -> RegisteredFace | None:
        """The registered face of font file ``name`` (an asset name or a path)."""
        found = self.by_where.get(self.names.get(name, name))
        if found is None:
            tail = name.replace("\\", "/").lstrip("./")
            found = next((f for f in self.by_where.values() if f.where.endswith(tail)), None)
        return found

    def family(self, name: str) -> list[RegisteredFace]:
        """The registered faces of family ``name`` (any case)."""
        return self.faces.get(name.lower(), [])

    def known(self, name: str) -> bool:
        """Registered here or installed on the system (True when the system cannot say)."""
        if self.family(name) or self.bitmap(name) is not None:
            return True
        installed = system_has_family(name)
        return installed is None or installed

    def warn_missing(self, name: str, where: str = "", instead: str = "the default font") -> None:
        """The :class:`FontWarning` for family ``name``, once per family."""
        if name.lower() in self.warned:
            return
        self.warned.add(name.lower())
        at = f"{where}: " if where else ""
        warnings.warn(
            f"{at}font family {name!r} is neither installed nor registered "
            f"(register its file with assets.font(...) or kge.render.text.add_font_file); "
            f"drawing with {instead}",
            FontWarning,
            stacklevel=3,
        )


#: the process's registry (pyglet's own font registry is process-wide too)
FONTS = FontRegistry()


def nearest_face(faces: list[RegisteredFace], weight: int, italic: bool) -> RegisteredFace:
    """The face closest to ``weight`` and slant: the slant first, then the weight (CSS rules).

    >>> light_italic = RegisteredFace(FaceInfo("F", "Light Italic", 300, True), b"", "a")
    >>> bold = RegisteredFace(FaceInfo("F", "Bold", 700, False), b"", "b")
    >>> nearest_face([light_italic, bold], 400, True).info.style
    'Light Italic'
    >>> nearest_face([light_italic, bold], 400, False).info.style
    'Bold'
    """
    return min(faces, key=lambda f: (f.info.italic != italic, abs(f.info.weight - weight)))


# -- the system's fonts through fontconfig ---------------------------------------------------
class _FcFontSet(ctypes.Structure):
    _fields_ = [("nfont", ctypes.c_int), ("sfont", ctypes.c_int),
                ("fonts", ctypes.POINTER(ctypes.c_void_p))]  # fmt: skip


_config: list[int] = []  # fontconfig's configuration, loaded once


@functools.cache
def _fontconfig() -> ctypes.CDLL | None:
    name = ctypes.util.find_library("fontconfig")
    if name is None:
        return None
    try:
        lib = ctypes.CDLL(name)
    except OSError:
        return None
    lib.FcInitLoadConfigAndFonts.restype = ctypes.c_void_p
    lib.FcPatternCreate.restype = ctypes.c_void_p
    lib.FcPatternAddString.argtypes = [ctypes.c_void_p, ctypes.c_char_p, ctypes.c_char_p]
    lib.FcObjectSetCreate.restype = ctypes.c_void_p
    lib.FcObjectSetAdd.argtypes = [ctypes.c_void_p, ctypes.c_char_p]
    lib.FcFontList.restype = ctypes.POINTER(_FcFontSet)
    lib.FcFontList.argtypes = [ctypes.c_void_p, ctypes.c_void_p, ctypes.c_void_p]
    lib.FcFontSetDestroy.argtypes = [ctypes.POINTER(_FcFontSet)]
    lib.FcPatternDestroy.argtypes = [ctypes.c_void_p]
    lib.FcObjectSetDestroy.argtypes = [ctypes.c_void_p]
    _config.append(lib.FcInitLoadConfigAndFonts())
    return lib


@functools.lru_cache(maxsize=256)
def system_has_family(name: str) -> bool | None:
    """Whether fontconfig knows family ``name``; None where there is no fontconfig."""
    if os.name == "nt":
        return None
    lib = _fontconfig()
    if lib is None:
        return None
    pattern = lib.FcPatternCreate()
    objects = lib.FcObjectSetCreate()
    try:
        lib.FcPatternAddString(pattern, b"family", name.encode("utf-8"))
        lib.FcObjectSetAdd(objects, b"family")
        found = lib.FcFontList(_config[0], pattern, objects)
        if not found:
            return False
        count = int(found.contents.nfont)
        lib.FcFontSetDestroy(found)
        return count > 0
    finally:
        lib.FcObjectSetDestroy(objects)
        lib.FcPatternDestroy(pattern)
