"""Scene transitions drawn by a fragment shader: ``Iris`` and your own ``ShaderTransition``.

Both are :class:`~kge.transitions.Transition` data (a duration, an ``ease``) that the
App plays like a :class:`~kge.transitions.Fade`; the renderer draws them over the frame
with a full-window quad whose fragment shader calls ::

    vec4 transition(sampler2D old_scene, vec2 uv, float progress)

``uv`` runs 0..1 across the window (bottom-left origin), ``old_scene`` is a picture of
the old scene's last frame (for transitions that take one), ``progress`` the eased
progress 0..1, and ``resolution`` (the window in pixels, ``vec2``) is declared for you.
The function returns straight (not premultiplied) RGBA, blended over the new scene.

``Iris(duration, color, center)`` closes a circle of ``color`` on ``center`` (0..1 of the
window), changes the scene when it is shut, and opens it again: the scene change of a
cartoon. A :class:`ShaderTransition` takes a picture of the old scene, changes the scene
at once and draws the picture through your shader as ``progress`` goes 0 -> 1 (a
dissolve, a pixelate, a page curl...); ``uniforms`` sets the shader's own uniforms,
checked against its declarations here. A shader that does not compile gives a
:class:`~kge.components.material.ShaderWarning` with the compiler's message at your
line, and the transition is drawn as a plain crossfade meanwhile.

>>> dissolve = ShaderTransition('''
... uniform float grain;
... vec4 transition(sampler2D old_scene, vec2 uv, float progress) {
...     float n = fract(sin(dot(floor(uv * resolution / grain), vec2(12.9898, 78.233))) * 43758.5);
...     return n < progress ? vec4(0.0) : texture(old_scene, uv);
... }''', duration=0.6, uniforms={"grain": 4.0})
>>> dissolve.needs_picture, dissolve.uniform_values()
(True, {'grain': 4.0})
>>> ShaderTransition("vec4 effect() { return vec4(1.0); }")
Traceback (most recent call last):
...
kge.errors.ValidationError: ShaderTransition.source must define vec4 transition(...) ...
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass, field
from typing import Any, ClassVar

from kge.components.material import UNIFORM_SIZES, declared_uniforms
from kge.errors import ComponentTypeError, ValidationError
from kge.transitions import Transition

_FUNCTION = re.compile(r"\bvec4\s+transition\s*\(")
_COMMENTS = re.compile(r"//[^\n]*|/\*.*?\*/", re.S)
#: uniforms kge declares in every transition shader
BUILTIN = frozenset({"resolution", "old_scene", "progress"})
SIGNATURE = "vec4 transition(sampler2D old_scene, vec2 uv, float progress)"


@dataclass(slots=True, frozen=True)
class Shaded(Transition):
    """Base of the transitions a fragment shader draws (see the module docstring)."""

    def glsl(self) -> str:
        """The GLSL source defining ``transition(...)`` (and its uniforms)."""
        raise NotImplementedError

    def uniform_values(self) -> dict[str, Any]:
        """The shader's own uniforms, by name."""
        return {}

    def progress(self, t: float, swapped: bool) -> float:
        """What the shader gets as ``progress`` at linear progress ``t``."""
        return self.curve(t)


@dataclass(slots=True, frozen=True)
class Iris(Shaded):
    """A circle of ``color`` closes on ``center`` (0..1 of the window), the scene changes,
    and it opens again on the new one."""

    duration: float = 0.8
    center: tuple[float, float] = (0.5, 0.5)

    def __post_init__(self) -> None:
        super(Iris, self).__post_init__()
        c = self.center
        if not isinstance(c, (tuple, list)) or len(c) != 2 or not all(
            isinstance(v, (int, float)) and not isinstance(v, bool) and 0.0 <= v <= 1.0
            for v in c
        ):
            raise ValidationError(
                f"Iris.center must be (x, y) fractions of the window in 0..1, got {c!r}"
            )
        object.__setattr__(self, "center", (float(c[0]), float(c[1])))

    def glsl(self) -> str:
        return """
uniform vec3 iris_color;
uniform vec2 iris_center;
vec4 transition(sampler2D old_scene, vec2 uv, float progress)
{
    vec2 p = (uv - iris_center) * resolution;
    vec2 far = max(iris_center, 1.0 - iris_center) * resolution;
    // shut (progress 1): the radius is below zero, so even the centre pixel is covered
    float radius = (1.0 - progress) * (length(far) + 2.0) - 1.5;
    float cover = clamp(length(p) - radius + 0.5, 0.0, 1.0);
    return vec4(iris_color, cover);
}
"""

    def uniform_values(self) -> dict[str, Any]:
        return {"iris_color": tuple(c / 255.0 for c in self.color), "iris_center": self.center}

    def progress(self, t: float, swapped: bool) -> float:
        """How shut the iris is: 0 -> 1 over the first half, 1 -> 0 over the second."""
        return self.curve(1.0 - abs(2.0 * t - 1.0))


def _check_uniforms(source: str, values: Any) -> dict[str, Any]:
    owner = "ShaderTransition.uniforms"
    if not isinstance(values, dict):
        raise ComponentTypeError(f"{owner} must be a dict of uniform name -> value")
    declared = declared_uniforms(source)
    out = {}
    for name, value in values.items():
        kind = declared.get(name)
        if kind is None:
            have = ", ".join(sorted(declared)) or "none"
            raise ValidationError(
                f"{owner}[{name!r}]: the shader declares no such uniform (it has: {have})"
            )
        size = UNIFORM_SIZES.get(kind, 0)
        items = list(value) if isinstance(value, (tuple, list)) else [value]
        if size == 0 or len(items) != size or not all(
            isinstance(v, (int, float)) and not isinstance(v, bool) and math.isfinite(v)
            for v in items
        ):
            raise ValidationError(f"{owner}[{name!r}]: the shader declares {kind}, got {value!r}")
        out[name] = value
    return out


@dataclass(slots=True, frozen=True, init=False)
class ShaderTransition(Shaded):
    """Your fragment shader draws the old scene's picture over the new scene while
    ``progress`` goes 0 -> 1 (see the module docstring)."""

    source: str = ""
    uniforms: dict[str, Any] = field(default_factory=dict, hash=False)
    name: str = "transition"

    needs_picture: ClassVar[bool] = True

    def __init__(
        self, source: str, duration: float = 0.6, *, uniforms: dict[str, Any] | None = None,
        ease: Any = None, color: tuple[int, int, int] = (0, 0, 0), name: str = "transition",
    ) -> None:
        for key, value in (("source", source), ("duration", duration), ("color", color),
                           ("ease", ease), ("name", name),
                           ("uniforms", {} if uniforms is None else uniforms)):  # fmt: skip
            object.__setattr__(self, key, value)
        self.__post_init__()

    def __post_init__(self) -> None:
        super(ShaderTransition, self).__post_init__()
        if not isinstance(self.source, str):
            raise ComponentTypeError(
                f"ShaderTransition.source must be GLSL text, got {type(self.source).__name__}"
            )
        if not _FUNCTION.search(_COMMENTS.sub("", self.source)):
            raise ValidationError(
                f"ShaderTransition.source must define vec4 transition(...) as {SIGNATURE}"
            )
        for name in declared_uniforms(self.source):
            if name in BUILTIN:
                raise ValidationError(
                    f"ShaderTransition {self.name!r}: uniform {name!r} is declared by kge; "
                    "remove it"
                )
        object.__setattr__(self, "uniforms", _check_uniforms(self.source, self.uniforms))

    def glsl(self) -> str:
        return self.source

    def uniform_values(self) -> dict[str, Any]:
        return dict(self.uniforms)
