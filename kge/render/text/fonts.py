"""Font faces for text: family + weight + slant to a face, its em metrics and its glyphs.

:class:`FontBook` (one per process, :data:`BOOK`) resolves a style to a chain of faces
(the face asked for, then fallbacks for the characters it lacks):

* a font *file* name (``"fonts/Brand-LightItalic.ttf"``) is that file's face, whatever
  its weight and slant;
* a family registered from files (``assets.font``, :func:`add_font_file`) picks its
  nearest face: the slant first, then the closest weight (a family whose only file
  is a Light Italic draws Light Italic, never another family);
* a bitmap font registered by name is its cells;
* otherwise the system's fonts (fontconfig): an unknown family is reported with a
  :class:`~kge.text.fonts.FontWarning` naming it, then drawn in the default family.

Metrics come straight from FreeType in font units (advances, kerning, ascent,
descent, line height), so layout is independent of the pixel size it is drawn at;
glyph images come from pyglet fonts loaded at the raster size.
"""

from __future__ import annotations

import ctypes
import io
from collections.abc import Sequence
from typing import Any

import pyglet

from kge.text.bitmap import BitmapFace, BitmapFont
from kge.text.fonts import FONTS, RegisteredFace, is_font_file, nearest_face, system_has_family
from kge.text.layout import Face

#: families tried, in order, for characters the chosen face lacks (those installed)
FALLBACK_FAMILIES = [
    "DejaVu Sans", "Noto Sans", "Noto Sans CJK SC", "Noto Sans CJK JP", "Noto Sans Symbols",
    "Noto Sans Symbols2", "Noto Color Emoji", "Noto Emoji", "Liberation Sans", "FreeSans",
    "Arial Unicode MS", "Segoe UI Symbol", "Segoe UI Emoji", "Apple Color Emoji",
]  # fmt: skip
#: pyglet's weight names by CSS weight
_WEIGHT_NAMES = ((100, "thin"), (200, "extralight"), (300, "light"), (350, "semilight"),
                 (400, "normal"), (500, "medium"), (600, "semibold"), (700, "bold"),
                 (800, "extrabold"), (900, "black"))  # fmt: skip
#: largest glyph em rasterised, pixels (bigger text is drawn scaled up from it)
MAX_RASTER_EM = 512.0


def weight_name(weight: int) -> str:
    """pyglet's name for the weight nearest ``weight``."""
    return min(_WEIGHT_NAMES, key=lambda p: abs(p[0] - weight))[1]


class _FT:
    """The FreeType calls pyglet does not bind (advances and kerning in font units)."""

    lib: Any = None

    @classmethod
    def get(cls) -> Any:
        if cls.lib is None:
            from pyglet.font import freetype_lib

            lib = freetype_lib._libfreetype
            lib.FT_Get_Advance.argtypes = [ctypes.c_void_p, ctypes.c_uint, ctypes.c_int32,
                                           ctypes.POINTER(ctypes.c_long)]  # fmt: skip
            lib.FT_Get_Advance.restype = ctypes.c_int
            lib.FT_Get_Char_Index.argtypes = [ctypes.c_void_p, ctypes.c_ulong]
            lib.FT_Get_Char_Index.restype = ctypes.c_uint
            cls.lib = lib
        return cls.lib


_FT_LOAD_NO_SCALE = 1
_FT_KERNING_UNSCALED = 2
_FT_FACE_FLAG_KERNING = 1 << 6


class FreeTypeFace:
    """A pyglet FreeType font's face, in em units (the :class:`~kge.text.layout.Face` protocol)."""

    def __init__(self, font: Any, load: tuple[Any, str, bool]) -> None:
        self.font = font  # keeps the FreeType face alive
        self.load_args = load  #: (name, weight name, italic) that load this face in pyglet
        self.name = str(font.name)
        self._ft = font.face.ft_face
        rec = self._ft.contents
        upem = float(rec.units_per_EM) or 0.0
        self._upem = upem
        if upem > 0:
            self.ascent = rec.ascender / upem
            self.descent = rec.descender / upem
            self.line_height = max(rec.height / upem, self.ascent - self.descent)
        else:  # a bitmap-only face: pyglet's pixel metrics at its size
            px = font.size * 4.0 / 3.0
            self.ascent, self.descent = font.ascent / px, font.descent / px
            self.line_height = self.ascent - self.descent
        self._kerning = bool(rec.face_flags & _FT_FACE_FLAG_KERNING) and upem > 0
        self._index: dict[str, int] = {}
        self._advance: dict[str, float] = {}
        self._raster: dict[float, Any] = {}

    def _gid(self, ch: str) -> int:
        gid = self._index.get(ch)
        if gid is None:
            gid = self._index[ch] = int(_FT.get().FT_Get_Char_Index(self._ft, ord(ch)))
        return gid

    def has(self, ch: str) -> bool:
        return self._gid(ch) != 0

    def advance(self, ch: str) -> float:
        adv = self._advance.get(ch)
        if adv is None:
            if self._upem > 0:
                units = ctypes.c_long()
                _FT.get().FT_Get_Advance(self._ft, self._gid(ch), _FT_LOAD_NO_SCALE, units)
                adv = units.value / self._upem
            else:
                glyph = self.raster_font(self.font.size * 4.0 / 3.0)[0].get_glyphs(ch)[0][0]
                adv = glyph.advance / (self.font.size * 4.0 / 3.0)
            self._advance[ch] = adv
        return adv

    def kerning(self, left: str, right: str) -> float:
        if not self._kerning or not left or not right:
            return 0.0
        from pyglet.font.freetype_lib import FT_Get_Kerning, FT_Vector

        v = FT_Vector()
        FT_Get_Kerning(self._ft, self._gid(left), self._gid(right), _FT_KERNING_UNSCALED, v)
        return float(v.x) / self._upem

    def raster_font(self, pixel_size: float) -> tuple[Any, float]:
        """The pyglet font of this face near ``pixel_size`` pixels per em (glyph images),
        and the factor from its glyphs to ``pixel_size`` (1 but for huge sizes)."""
        px = max(round(min(pixel_size, MAX_RASTER_EM) * 4) / 4, 0.25)
        k = 1.0 if pixel_size <= MAX_RASTER_EM else pixel_size / px
        font = self._raster.get(px)
        if font is None:
            name, weight, italic = self.load_args
            font = pyglet.font.load(name, px * 0.75, weight=weight, italic=italic)
            # big glyphs: an atlas of a few, not pyglet's 100 (a 500 px em would ask 128 MB)
            font.glyph_fit = max(4, min(100, int((2048 / (px * 1.3 + 2)) ** 2)))
            if len(self._raster) > 24:  # zooming through many sizes: keep the cache small
                self._raster.clear()
            self._raster[px] = font
        return font, k


class FontBook:
    """Style -> chain of faces (see the module docstring)."""

    def __init__(self) -> None:
        self._chains: dict[tuple[Any, ...], tuple[Face, ...]] = {}
        self._faces: dict[tuple[Any, ...], Face] = {}
        self._pyglet_keys: dict[str, list[tuple[str, str, bool]]] = {}
        self._fallbacks: list[Face] | None = None
        self._default: FreeTypeFace | None = None
        self.fallback_families = FALLBACK_FAMILIES
        FONTS.listeners.append(self._added)
        for faces in list(FONTS.faces.values()):
            for face in faces:
                self._added(face)

    # -- registering files with pyglet -------------------------------------------------------
    def _added(self, face: RegisteredFace) -> None:
        """Hand a registered face to pyglet and note the key pyglet stores it under."""
        from pyglet.font import freetype

        store = getattr(getattr(freetype, "FreeTypeFont", None), "_memory_faces", None)
        known = set(store._dict) if store is not None else set()
        pyglet.font.add_file(io.BytesIO(face.data))
        if store is not None:
            new = sorted(set(store._dict) - known)
            if new:
                self._pyglet_keys[face.where] = new
        self._chains.clear()
        self._faces = {k: v for k, v in self._faces.items() if k[0] != "file"}

    def _load(self, name: str | None, weight: str, italic: bool) -> FreeTypeFace:
        key = ("load", name, weight, italic)
        face = self._faces.get(key)
        if face is None:
            font = pyglet.font.load(name, 12, weight=weight, italic=italic)
            face = self._faces[key] = FreeTypeFace(font, (name, weight, italic))
        assert isinstance(face, FreeTypeFace)
        return face

    def _registered(self, reg: RegisteredFace) -> FreeTypeFace:
        keys = self._pyglet_keys.get(reg.where)
        if keys:  # exactly the memory face pyglet made from this file
            name, weight, italic = keys[0]
            return self._load(name, weight, italic)
        return self._load(reg.info.family, weight_name(reg.info.weight), reg.info.italic)

    # -- resolving -----------------------------------------------------------------------------
    def default_face(self) -> FreeTypeFace:
        if self._default is None:
            self._default = self._load(None, "normal", False)
        return self._default

    def primary(self, family: str | None, weight: int, italic: bool, where: str = "") -> Face:
        """The face drawing text of this style (see the module docstring)."""
        if family is None:
            return self._load(None, weight_name(weight), italic)
        if is_font_file(family):
            reg = FONTS.file(family)
            if reg is not None:
                return self._registered(reg)
            FONTS.warn_missing(family, where, f"{self.default_face().name!r}")
            return self._load(None, weight_name(weight), italic)
        bitmap = FONTS.bitmap(family)
        if bitmap is not None:
            key = ("bitmap", family.lower(), id(bitmap))
            face = self._faces.get(key)
            if face is None:
                face = self._faces[key] = BitmapFace(bitmap)
            return face
        registered = FONTS.family(family)
        if registered:
            return self._registered(nearest_face(registered, weight, italic))
        installed = system_has_family(family)
        if installed is None:
            installed = bool(pyglet.font.have_font(family))
        if not installed:
            FONTS.warn_missing(family, where, f"{self.default_face().name!r}")
            return self._load(None, weight_name(weight), italic)
        return self._load(family, weight_name(weight), italic)

    def fallbacks(self) -> list[Face]:
        if self._fallbacks is None:
            self._fallbacks = [
                self._load(name, "normal", False)
                for name in self.fallback_families
                if system_has_family(name) or (system_has_family(name) is None
                                               and pyglet.font.have_font(name))
            ]  # fmt: skip
        return self._fallbacks

    def chain(
        self, family: str | None, weight: int, italic: bool, where: str = ""
    ) -> tuple[Face, ...]:
        """The face for this style, then the installed fallbacks (each face once)."""
        key = (family, weight, italic)
        found = self._chains.get(key)
        if found is None:
            first = self.primary(family, weight, italic, where)
            rest = [f for f in self.fallbacks() if f is not first]
            if not isinstance(first, BitmapFace) and not rest:
                rest = [self.default_face()] if self.default_face() is not first else []
            found = self._chains[key] = (first, *rest)
        return found


#: images usable by name in ``[img]name[/img]`` markup (``register_icon``)
ICONS: dict[str, Any] = {}

_book: FontBook | None = None


def book() -> FontBook:
    """The process's :class:`FontBook` (pyglet's font registry is process-wide)."""
    global _book
    if _book is None:
        _book = FontBook()
    return _book


class WorldFaces:
    """A :class:`~kge.text.layout.FaceSource` for one world: the book's faces, and inline
    images and bitmap sheets from the world's asset store."""

    def __init__(self, textures: Any, where: str = "") -> None:
        self.textures = textures
        self.where = where

    def faces(self, family: str | None, weight: int, italic: bool) -> Sequence[Face]:
        return book().chain(family, weight, italic, self.where)

    def icon(self, name: str) -> Any:
        """The texture of inline image ``name``: a registered icon, else an asset."""
        return self.textures.texture(ICONS.get(name, name), filter="linear")

    def icon_size(self, name: str) -> tuple[float, float] | None:
        tex = self.icon(name)
        return (float(tex.width), float(tex.height))

    def bitmap_texture(self, font: BitmapFont) -> Any:
        return self.textures.texture(font.image, filter="nearest")
