"""``Shader`` and ``Material``: your own GLSL for a drawable, with uniforms tweens animate.

A :class:`Shader` is a fragment of GLSL defining one function, in the style of
LÖVE's pixel effects::

    uniform float glow;                     // your uniforms: set them in Material.uniforms
    vec4 effect(vec4 color, sampler2D tex, vec2 uv, vec2 world)
    {
        return texture(tex, uv) * color * (1.0 + glow);
    }

``color`` is the drawable's colour (a sprite's tint and opacity, a shape's colour, a
particle's), ``tex`` its texture (a white pixel for shapes), ``uv`` the texture
coordinate (a shape's position in its own frame, metres; 0..1 across a particle),
``world`` the pixel's position in the world (metres). ``time`` (game seconds) is
declared for you. Return straight (not premultiplied) RGBA: kge blends it with the
drawable's ``blend`` mode.

A :class:`Material` on an entity with a Sprite, a shape drawable or a particle
emitter draws it with that shader and these ``uniforms``. Uniform values are checked
against the shader's declarations at the call (a ``vec3`` needs three numbers); a
shader that does not compile gives a :class:`ShaderWarning` with the compiler's
message at *your* line number, and the drawable is drawn with the plain material
meanwhile: the game keeps running. Uniforms are tweenable by a dotted name:
``Tween(Material, "uniforms.glow", 1.0, 0.5)``. Set one with ``material.set(name,
value)`` or replace them all with ``material.uniforms = {...}`` (both checked).

>>> glow = Shader('''
... uniform float glow;
... uniform vec3 tint;
... vec4 effect(vec4 color, sampler2D tex, vec2 uv, vec2 world) {
...     return texture(tex, uv) * color * vec4(tint * (1.0 + glow), 1.0);
... }''', name="glow")
>>> glow.uniforms
{'glow': 'float', 'tint': 'vec3'}
>>> m = Material(glow, {"glow": 0.5, "tint": (1.0, 0.8, 0.6)})
>>> m.set("tint", (1, 2))
Traceback (most recent call last):
...
kge.errors.ValidationError: Material.uniforms['tint']: the shader declares vec3, got (1, 2)
>>> Material(glow, {"shine": 1.0})
Traceback (most recent call last):
...
kge.errors.ValidationError: Material.uniforms['shine']: shader 'glow' declares no such uniform ...
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass, field
from typing import Any, ClassVar

from kge.components.tracked import Check, Tracked
from kge.errors import ComponentTypeError, ValidationError

#: GLSL uniform types a Material can set, and how many numbers each takes
UNIFORM_SIZES = {
    "float": 1, "int": 1, "bool": 1, "vec2": 2, "vec3": 3, "vec4": 4,
    "ivec2": 2, "ivec3": 3, "ivec4": 4, "mat2": 4, "mat3": 9, "mat4": 16, "sampler2D": 0,
}  # fmt: skip
#: declared by kge for every material shader (do not declare them again)
BUILTIN_UNIFORMS = frozenset({"time", "kge_texture"})
_UNIFORM = re.compile(
    r"^\s*uniform\s+(?:(?:lowp|mediump|highp)\s+)?(\w+)\s+(\w+)\s*(\[[^\]]*\])?\s*;", re.M
)
_EFFECT = re.compile(r"\bvec4\s+effect\s*\(")
_COMMENTS = re.compile(r"//[^\n]*|/\*.*?\*/", re.S)


class ShaderWarning(UserWarning):
    """A material or post-processing shader did not compile (the plain one is drawn)."""


def declared_uniforms(source: str) -> dict[str, str]:
    """``{name: glsl type}`` of the ``uniform`` declarations in ``source`` (no arrays)."""
    code = _COMMENTS.sub(lambda m: "\n" * m.group(0).count("\n"), source)
    return {m.group(2): m.group(1) for m in _UNIFORM.finditer(code) if not m.group(3)}


@dataclass(slots=True, frozen=True)
class Shader:
    """GLSL source defining ``vec4 effect(...)`` (see the module docstring)."""

    source: str
    name: str = "shader"
    #: ``{name: glsl type}`` of the uniforms it declares (read from the source)
    uniforms: dict[str, str] = field(default_factory=dict, init=False, compare=False, repr=False)

    def __post_init__(self) -> None:
        if not isinstance(self.source, str):
            raise ComponentTypeError(f"Shader.source must be GLSL text, got {self.source!r}")
        if not isinstance(self.name, str) or not self.name:
            raise ValidationError(f"Shader.name must be a non-empty str, got {self.name!r}")
        code = _COMMENTS.sub("", self.source)
        if not _EFFECT.search(code):
            raise ValidationError(
                f"shader {self.name!r} must define vec4 effect(vec4 color, sampler2D tex, "
                "vec2 uv, vec2 world) (see kge.components.material)"
            )
        found = declared_uniforms(self.source)
        for name, kind in found.items():
            if name in BUILTIN_UNIFORMS:
                raise ValidationError(
                    f"shader {self.name!r}: uniform {name!r} is declared by kge; remove it"
                )
            if kind not in UNIFORM_SIZES:
                raise ValidationError(
                    f"shader {self.name!r}: uniform {name} has type {kind}, which a Material "
                    f"cannot set (use one of {', '.join(UNIFORM_SIZES)})"
                )
        object.__setattr__(self, "uniforms", found)

    def __hash__(self) -> int:
        return hash((self.source, self.name))


def uniform_value(shader: Shader, name: str, value: Any, owner: str = "Material") -> Any:
    """``value`` checked against the type ``shader`` declares for uniform ``name``."""
    label = f"{owner}.uniforms[{name!r}]"
    kind = shader.uniforms.get(name)
    if kind is None:
        have = ", ".join(sorted(shader.uniforms)) or "none"
        raise ValidationError(
            f"{label}: shader {shader.name!r} declares no such uniform (it has: {have})"
        )
    size = UNIFORM_SIZES[kind]
    if size == 0:  # a texture: an image value, resolved when drawn
        if value is None or isinstance(value, (int, float, bool, tuple, list)):
            raise ValidationError(f"{label}: the shader declares sampler2D: give an image")
        return value
    items = list(value) if isinstance(value, (tuple, list)) else [value]
    ok = len(items) == size and all(
        isinstance(v, (int, float)) and not (isinstance(v, bool) and kind != "bool")
        and math.isfinite(float(v)) for v in items
    )  # fmt: skip
    if not ok:
        raise ValidationError(f"{label}: the shader declares {kind}, got {value!r}")
    if kind in ("int", "bool") or kind.startswith("ivec"):
        if not all(float(v).is_integer() for v in items):
            raise ValidationError(f"{label}: the shader declares {kind}: whole numbers only")
        items = [int(v) for v in items]
    else:
        items = [float(v) for v in items]
    return items[0] if size == 1 else tuple(items)


def _shader(value: Any, owner: str, field: str) -> Shader:
    if not isinstance(value, Shader):
        raise ComponentTypeError(f"{owner}.{field} must be a Shader, got {value!r}")
    return value


def _uniforms(value: Any, owner: str, field: str) -> dict[str, Any]:
    if not isinstance(value, dict) or not all(isinstance(k, str) for k in value):
        raise ComponentTypeError(f"{owner}.{field} must be a dict of uniform name -> value")
    return dict(value)


@dataclass(slots=True)
class Material(Tracked):
    """Draw this entity's Sprite, shape or particles with ``shader`` and ``uniforms``."""

    _checks: ClassVar[dict[str, Check]] = {"shader": _shader, "uniforms": _uniforms}

    shader: Shader
    uniforms: dict[str, Any] = field(default_factory=dict)

    def set(self, name: str, value: Any) -> None:
        """Set uniform ``name`` (checked against the shader's declaration)."""
        self.uniforms[name] = uniform_value(self.shader, name, value, self._owner())

    # -- tweens: "uniforms.NAME" reads and writes one uniform ----------------------------
    @classmethod
    def tweenable(cls, name: str) -> bool:
        return name.startswith("uniforms.") and len(name) > len("uniforms.")

    def __getattr__(self, name: str) -> Any:
        if name.startswith("uniforms."):
            key = name[len("uniforms.") :]
            try:
                return self.uniforms[key]
            except KeyError:
                raise AttributeError(f"Material has no uniform {key!r} set") from None
        raise AttributeError(name)

    def __setattr__(self, name: str, value: Any) -> None:
        if name.startswith("uniforms."):
            self.set(name[len("uniforms.") :], value)  # read at draw time: nothing to sync
            return
        if name == "uniforms":  # the shader is set first (field order)
            value = _uniforms(value, self._owner(), name)
            value = {k: uniform_value(self.shader, k, v, self._owner()) for k, v in value.items()}
        elif name == "shader" and isinstance(value, Shader):
            try:
                current = dict(self.uniforms)
            except AttributeError:  # inside __init__
                current = {}
            for k, v in current.items():
                uniform_value(value, k, v, self._owner())
        Tracked.__setattr__(self, name, value)
