"""The game-layer bad-input catalogue: sprites, animation, text, drawables, camera,
lights, particles, tweens, UI, audio and scenes.

Like :mod:`tests.reliability.catalogue` (the physics one), one list, :data:`CASES`,
drives both the test (``test_game_bad_input.py``) and the generated table of
``docs/reliability.md``. Each case is Python source run in a small headless game
(see :func:`build_game`); it must raise exactly ``error`` with a message matching
``names`` (the entity, component and field), leave every entity and component as it
was, and the game must then run two more frames with every pose, camera, particle
and tween row finite. To refresh the table after adding a case::

    .venv/bin/python -m tests.reliability.game_catalogue --write

The scene: ``hero`` (Transform, Sprite and Animator on the 64x32 ``sheet.png``),
``cam`` (Camera), ``fx`` (a ParticleEmitter), ``label`` (world Text), ``lamp``
(Light), ``box`` (a drawn Rect), ``root`` (a UI Panel) with ``ok`` (Button),
``volume`` (Slider), ``name`` (TextInput) and ``pick`` (Dropdown) in it, ``plain``
(Transform only) and ``dead`` (despawned); plus ``world``, ``app``, ``tweens``,
``audio``, ``clip`` (a good Clip) and ``level`` (a scene function taking ``number``).
"""

from __future__ import annotations

import math
import re
import shutil
import struct
import tempfile
import zlib
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

import kge
from kge.assets import AssetDecodeError, AssetNotFoundError, Assets
from kge.errors import ComponentTypeError, ValidationError

from .doctable import DOCS, Section, cell, main
from .harness import state_dump

SECTION = Section.named(DOCS / "reliability.md", "game-catalogue",
                        "tests/reliability/game_catalogue.py")


@dataclass(frozen=True, slots=True)
class Case:
    area: str  #: the part of the game layer
    name: str  #: what is wrong, in words
    call: str  #: the offending call (Python, run in the standard game)
    error: type[Exception]  #: the exact exception class expected
    names: str  #: a regex the message must contain (entity / component / field)


V = ValidationError
T = ComponentTypeError
BIG = "1e308"


def _fields(area: str, make: str, cases: list[tuple[str, str, type[Exception], str]]
            ) -> list[Case]:
    """Cases writing ``field = value`` into a live component (``make`` is its getter)."""
    return [
        Case(area, f"{make.split(',')[-1].strip(' )')}.{f} = {v}", f"{make}.{f} = {v}", e, n)
        for f, v, e, n in cases
    ]


def _bad_numbers(owner: str, entity: int, fields: list[str]) -> list[tuple[str, str, type, str]]:
    """NaN, infinity and a string in each float field."""
    out: list[tuple[str, str, type, str]] = []
    for f in fields:
        lead = rf"entity {entity}, {owner}\.{f}"
        out += [(f, "nan", V, lead), (f, "inf", V, lead), (f, "'1'", T, lead)]
    return out


SPRITE = [*_fields("sprite", "world.get(hero, Sprite)", [
    ("size", "(1e300, 1.0)", V, r"entity 1, Sprite\.size\[0\] must be <= "),
    ("size", "(1.0, 0.0)", V, r"entity 1, Sprite\.size\[1\] must be > 0"),
    ("size", "(nan, 1.0)", V, r"entity 1, Sprite\.size\[0\] must be finite"),
    ("anchor", "(1e6, 0.5)", V, r"entity 1, Sprite\.anchor must be fractions within"),
    ("anchor", "(0.5, nan)", V, r"entity 1, Sprite\.anchor\[1\] must be finite"),
    ("anchor", "'middle'", T, r"entity 1, Sprite\.anchor"),
    ("opacity", "300", V, r"entity 1, Sprite\.opacity"),
    ("opacity", "-1", V, r"entity 1, Sprite\.opacity"),
    ("tint", "(255, 0)", V, r"entity 1, Sprite\.tint"),
    ("tint", "(256, 0, 0)", V, r"entity 1, Sprite\.tint"),
    ("layer", "1.5", T, r"entity 1, Sprite\.layer"),
    ("image", "'missing.png'", AssetNotFoundError, r"entity 1, Sprite\.image"),
    ("image", "None", T, r"entity 1, Sprite\.image"),
    ("visible", "'yes'", T, r"entity 1, Sprite\.visible"),
    ("region", "(0, 0, -4, 4)", V, r"entity 1, Sprite\.region"),
    ("grid", "(0, 2)", V, r"entity 1, Sprite\.grid"),
]),
    Case("sprite", "spawned with a missing image", "world.spawn(Transform(), Sprite('nope.png'))",
         AssetNotFoundError, r"Sprite\.image"),
]

CLIPS = [
    Case("animation", "clip at 1e-9 fps", "Clip.grid('sheet.png', (4, 2), fps=1e-9)", V,
         r"Clip\.fps must be in"),
    Case("animation", "clip at 1e12 fps", "Clip.grid('sheet.png', (4, 2), fps=1e12)", V,
         r"Clip\.fps must be in"),
    Case("animation", "frame of 1e-300 s", "Clip.grid('sheet.png', (4, 2), duration=1e-300)", V,
         r"Clip\.duration must be in"),
    Case("animation", "frame of a year", "Clip.grid('sheet.png', (4, 2), duration=3.2e7)", V,
         r"Clip\.duration must be in"),
    Case("animation", "NaN frame duration", "Clip.grid('sheet.png', (2, 1), duration=[0.1, nan])",
         V, r"Clip\.duration\[1\] must be finite"),
    Case("animation", "clip speed 1e9", "Clip.grid('sheet.png', (4, 2), speed=1e9)", V,
         r"Clip\.speed must be <= 1000"),
    Case("animation", "clip speed 0", "Clip.grid('sheet.png', (4, 2), speed=0.0)", V,
         r"Clip\.speed must be > 0"),
    Case("animation", "a million-cell grid", "Clip.grid('sheet.png', (1000, 1000))", V,
         r"Clip\.grid 1000x1000 has 1,000,000 cells"),
    Case("animation", "a grid side past 65536", "Clip.grid('sheet.png', (70000, 1), frames=[0])",
         V, r"Clip\.grid must be at most 65536 cells a side"),
    Case("animation", "an endless frame list",
         "import itertools; Clip.grid('sheet.png', (4, 2), frames=itertools.repeat(0))", V,
         r"a clip has at most 10,000 frames"),
    Case("animation", "unknown loop mode", "Clip.grid('sheet.png', (4, 2), loop='bounce')", V,
         r"Clip\.loop"),
    Case("animation", "frame index past the grid", "FrameRef('sheet.png', grid=(4, 2), index=8)", V,
         r"FrameRef\.index: frame 8 is outside the 4x2 sheet"),
    Case("animation", "negative region size", "FrameRef('sheet.png', region=(0, 0, -1, 4))", V,
         r"FrameRef\.region\[2\] must be an int >= 1"),
    Case("animation", "region of floats", "FrameRef('sheet.png', region=(0, 0, 1.5, 4))", T,
         r"FrameRef\.region\[2\]"),
    Case("animation", "region of three numbers", "FrameRef('sheet.png', region=(0, 0, 4))", T,
         r"FrameRef\.region must be \(x, y, w, h\)"),
    Case("animation", "zero-column grid", "FrameRef('sheet.png', grid=(0, 2))", V,
         r"FrameRef\.grid\[0\] must be in 1\.\.65536"),
    Case("animation", "negative margin", "FrameRef('sheet.png', grid=(4, 2), margin=-1)", V,
         r"FrameRef\.margin must be an int >= 0"),
    Case("animation", "negative gif frame", "FrameRef('anim.gif', gif_frame=-1)", V,
         r"FrameRef\.gif_frame must be an int >= 0"),
    Case("animation", "frame of no image", "FrameRef(None)", T, r"FrameRef\.image must be"),
    Case("animation", "frame of an empty name", "FrameRef('')", T, r"FrameRef\.image must be"),
    Case("animation", "clip naming a missing image",
         "world.spawn(Transform(), Animator({'run': Clip.grid('gone.png', (2, 1))}))",
         AssetNotFoundError, r"Animator\.clips\)?\['run'\]\.frames\[0\]"),
    Case("animation", "grid finer than its image",
         "world.spawn(Transform(), Animator({'run': Clip.grid('sheet.png', (128, 1), "
         "frames=[0])}))", V, r"Animator\.clips\)?\['run'\]\.frames\[0\]"),
    Case("animation", "region outside its image",
         "world.spawn(Transform(), Animator({'r': Clip((FrameRef('sheet.png', "
         "region=(60, 0, 16, 16)),), (0.1,))}))", V, r"Animator\.clips\)?\['r'\]\.frames\[0\]"),
    Case("animation", "live clips write naming a missing image",
         "world.get(hero, Animator).clips = {'run': Clip.grid('gone.png', (2, 1))}",
         AssetNotFoundError, r"entity 1, Animator\.clips\)?\['run'\]"),
    Case("animation", "animator speed 1e9", "world.get(hero, Animator).speed = 1e9", V,
         r"entity 1, Animator\.speed must be <= 1000"),
    Case("animation", "animator speed NaN", "world.get(hero, Animator).speed = nan", V,
         r"entity 1, Animator\.speed must be finite"),
    Case("animation", "play a clip that is not there", "world.get(hero, Animator).current = 'fly'",
         V, r"entity 1, Animator\.current"),
    Case("animation", "queue a clip that is not there",
         "world.get(hero, Animator).queued = ['run', 'fly']", V,
         r"entity 1, Animator\.queued\[1\]"),
    Case("animation", "queue that is not a list", "world.get(hero, Animator).queued = 'run'", T,
         r"entity 1, Animator\.queued must be a list"),
    Case("animation", "transition to a missing clip",
         "world.get(hero, Animator).transitions = (kge.components.animation.Transition("
         "'*', 'fly'),)", V, r"entity 1, Animator\.transitions\[0\]\.dst"),
    Case("animation", "transitions that are not Transitions",
         "world.get(hero, Animator).transitions = ('run',)", T,
         r"entity 1, Animator\.transitions\[0\] must be a Transition"),
    Case("animation", "transitions of a number", "world.get(hero, Animator).transitions = 3", T,
         r"entity 1, Animator\.transitions must be a sequence"),
    Case("animation", "transition condition of a dict",
         "kge.components.animation.Transition('run', 'run', when={'fast': True})", T,
         r"Transition\.when must be a parameter name or None"),
    Case("animation", "transition to a clip of no name",
         "kge.components.animation.Transition('*', '')", T, r"Transition\.dst must be a clip"),
    Case("animation", "params that are not a dict", "world.get(hero, Animator).params = []", T,
         r"entity 1, Animator\.params must be a dict"),
    Case("animation", "playing as a string", "world.get(hero, Animator).playing = 'yes'", T,
         r"entity 1, Animator\.playing"),
    Case("animation", "clips of a string", "world.get(hero, Animator).clips = 'run'", V,
         r"entity 1, Animator\.clips"),
    Case("animation", "clip table without current", "world.get(hero, Animator).clips = {'x': clip}",
         V, r"entity 1, Animator\.clips"),
]

SHAKE = _fields("camera", "world.get(cam, CameraShake)", [
    ("max_offset", "(1e300, 1.0)", V, r"entity 2, CameraShake\.max_offset must be within"),
    ("max_offset", "(-1.0, 1.0)", V, r"entity 2, CameraShake\.max_offset\[0\] must be >= 0"),
    ("frequency", "1e300", V, r"entity 2, CameraShake\.frequency must be <= 10000 Hz"),
    ("frequency", "0.0", V, r"entity 2, CameraShake\.frequency must be > 0"),
    ("seed", "-1", V, r"entity 2, CameraShake\.seed must be in 0\.\.2\*\*32-1"),
    ("seed", "2**40", V, r"entity 2, CameraShake\.seed must be in 0\.\.2\*\*32-1"),
    ("trauma", "nan", V, r"entity 2, CameraShake\.trauma must be finite"),
    ("decay", "-1.0", V, r"entity 2, CameraShake\.decay must be >= 0"),
])

CAMERA = [*_fields("camera", "world.get(cam, Camera)", [
    ("center", f"({BIG}, 0.0)", V, r"entity 2, Camera\.center\[0\] must lie within 1e\+09 m"),
    ("center", "(nan, 0.0)", V, r"entity 2, Camera\.center\[0\] must be finite"),
    ("pixels_per_meter", "1e-9", V, r"entity 2, Camera\.pixels_per_meter must be in"),
    ("pixels_per_meter", "1e300", V, r"entity 2, Camera\.pixels_per_meter must be in"),
    ("pixels_per_meter", "0.0", V, r"entity 2, Camera\.pixels_per_meter must be > 0"),
    ("zoom", "0.0", V, r"entity 2, Camera\.zoom"),
    ("smoothing", "1e300", V, r"entity 2, Camera\.smoothing must be <= 1e\+06 s"),
    ("look_ahead", "1e300", V, r"entity 2, Camera\.look_ahead must be <= 1e\+06 s"),
    ("look_ahead", "-1.0", V, r"entity 2, Camera\.look_ahead must be >= 0"),
    ("dead_zone", f"({BIG}, 1.0)", V, r"entity 2, Camera\.dead_zone\[0\] must lie within"),
    ("bounds", f"(0.0, 0.0, {BIG}, 1.0)", V, r"entity 2, Camera\.bounds\[2\] must lie within"),
    ("bounds", "(1.0, 0.0, 0.0, 1.0)", V, r"entity 2, Camera\.bounds must have min < max"),
    ("bounds", "(0.0, 0.0, 1.0)", T, r"entity 2, Camera\.bounds must be"),
    ("follow", "999", V, r"entity 2, Camera\.follow: entity 999 does not exist"),
    ("follow", "dead", V, r"entity 2, Camera\.follow: entity 13 does not exist"),
    ("follow", "root", V, r"entity 2, Camera\.follow: entity 7 has no Transform"),
    ("follow", "-3", V, r"entity 2, Camera\.follow must be an entity id \(>= 0\)"),
    ("follow", "'hero'", T, r"entity 2, Camera\.follow must be an entity id"),
]),
    Case("camera", "camera spawned following nothing", "world.spawn(Camera(follow=999))", V,
         r"Camera\.follow: entity 999 does not exist"),
]

TEXT = _fields("text", "world.get(label, Text)", [
    ("size", "1e6", V, r"entity 4, Text\.size must be in \(0, 1000\] points"),
    ("size", "0", V, r"entity 4, Text\.size"),
    ("size", "nan", V, r"entity 4, Text\.size must be finite"),
    ("offset", f"({BIG}, 0.0)", V, r"entity 4, Text\.offset must be within"),
    ("offset", "(0.0, inf)", V, r"entity 4, Text\.offset\[1\] must be finite"),
    ("anchor", "(0.5, 1e9)", V, r"entity 4, Text\.anchor must be fractions within"),
    ("text", "None", T, r"entity 4, Text\.text"),
    ("color", "(0, 0, 0, 300)", V, r"entity 4, Text\.color"),
    ("width", "1e300", V, r"entity 4, Text\.width"),
    ("max_lines", "-1", V, r"entity 4, Text\.max_lines"),
    ("align", "'middle'", V, r"entity 4, Text\.align"),
    ("overflow", "'spill'", V, r"entity 4, Text\.overflow"),
    ("opacity", "256", V, r"entity 4, Text\.opacity"),
    ("line_spacing", "nan", V, r"entity 4, Text\.line_spacing"),
    ("outline", "-1.0", V, r"entity 4, Text\.outline"),
    ("weight", "'heavyish'", V, r"entity 4, Text\.weight"),
])

DRAWN = [*_fields("drawables", "world.get(box, draw.Rect)", [
    ("width", "1e300", V, r"entity 6, Rect\.width must be <= "),
    ("width", "0.0", V, r"entity 6, Rect\.width must be > 0"),
    ("height", "nan", V, r"entity 6, Rect\.height must be finite"),
    ("thickness", "1e300", V, r"entity 6, Rect\.thickness must be <= "),
    ("offset", f"({BIG}, 0.0)", V, r"entity 6, Rect\.offset"),
    ("color", "(1, 2)", V, r"entity 6, Rect\.color"),
    ("filled", "1", T, r"entity 6, Rect\.filled"),
]),
    Case("drawables", "circle of radius 1e300", "draw.Circle(1e300)", V,
         r"Circle\.radius must be <= "),
    Case("drawables", "line to 1e300", "draw.Line((0.0, 0.0), (1e300, 0.0))", V, r"Line\.end"),
    Case("drawables", "triangle corner at NaN", "draw.Triangle((0, 0), (1, 0), (nan, 1))", V,
         r"Triangle\.c\[0\] must be finite"),
    Case("drawables", "polygon vertex at 1e300",
         "draw.Polygon([(0, 0), (1e300, 0), (0, 1)])", V, r"Polygon\.vertices\[1\] must lie within"),
    Case("drawables", "polygon of two points", "draw.Polygon([(0, 0), (1, 0)])", V,
         r"Polygon\.vertices needs at least 3 points"),
    Case("drawables", "circle of 2 segments", "draw.Circle(1.0, segments=2)", V,
         r"Circle\.segments"),
]

LIGHTS = _fields("lights", "world.get(lamp, Light)", [
    ("offset", f"({BIG}, 0.0)", V, r"entity 5, Light\.offset"),
    ("radius", "-1.0", V, r"entity 5, Light\.radius"),
    ("radius", "1e300", V, r"entity 5, Light\.radius"),
    ("intensity", "1e300", V, r"entity 5, Light\.intensity"),
    ("cone", "7.0", V, r"entity 5, Light\.cone"),
    ("softness", "2.0", V, r"entity 5, Light\.softness"),
    ("color", "(1, 2, 3, 4, 5)", V, r"entity 5, Light\.color"),
    *_bad_numbers("Light", 5, ["direction", "falloff"]),
])

EMITTER = _fields("particles", "world.get(fx, ParticleEmitter)", [
    ("rate", "-1.0", V, r"entity 3, ParticleEmitter\.rate"),
    ("rate", "1e300", V, r"entity 3, ParticleEmitter\.rate"),
    ("offset", f"({BIG}, 0.0)", V, r"entity 3, ParticleEmitter\.offset"),
    ("lifetime", "(2.0, 1.0)", V, r"entity 3, ParticleEmitter\.lifetime"),
    ("speed", f"(0.0, {BIG})", V, r"entity 3, ParticleEmitter\.speed"),
    ("acceleration", f"({BIG}, 0.0)", V, r"entity 3, ParticleEmitter\.acceleration"),
    ("max_particles", "-5", V, r"entity 3, ParticleEmitter\.max_particles"),
    ("max_particles", "10**9", V, r"entity 3, ParticleEmitter\.max_particles"),
    ("spread", "7.0", V, r"entity 3, ParticleEmitter\.spread"),
    ("size", "()", V, r"entity 3, ParticleEmitter\.size"),
    ("color", "('nope',)", T, r"entity 3, ParticleEmitter\.color"),
    ("blend", "'glow'", V, r"entity 3, ParticleEmitter\.blend"),  # 'screen' is a mode now
    ("space", "'galaxy'", V, r"entity 3, ParticleEmitter\.space"),
    ("seed", "-1", V, r"entity 3, ParticleEmitter\.seed"),
    ("shape", "'circle'", T, r"entity 3, ParticleEmitter\.shape"),
    *_bad_numbers("ParticleEmitter", 3, ["direction", "drag", "inherit_velocity", "prewarm",
                                        "bounciness"]),
])

PARTICLES = [
    *EMITTER,
    Case("particles", "emission circle of 1e300", "EmitCircle(1e300)", V,
         r"EmitCircle\.radius must be within"),
    Case("particles", "emission box of 1e300", "EmitBox(1.0, 1e300)", V,
         r"EmitBox\.height must be within"),
    Case("particles", "emission line to 1e300", "EmitLine((0.0, 0.0), (1e300, 0.0))", V,
         r"EmitLine\.end"),
    Case("particles", "burst at 1e300", "ParticleBurst(fx, 5, position=(1e300, 0.0))", V,
         r"ParticleBurst\.position"),
    Case("particles", "burst of a negative emitter", "ParticleBurst(-1, 5)", V,
         r"ParticleBurst\.emitter must be an entity id"),
    Case("particles", "burst event naming a missing emitter", "world.emit(ParticleBurst(999, 5))",
         V, r"ParticleBurst\.emitter: entity 999 does not exist"),
    Case("particles", "burst event naming a plain entity", "world.emit(ParticleBurst(plain, 5))",
         V, r"ParticleBurst\.emitter: entity 12 has no ParticleEmitter"),
    Case("particles", "BurstOnHit naming a missing emitter",
         "world.add(plain, BurstOnHit(999))", V,
         r"entity 12, BurstOnHit\.emitter: entity 999 does not exist"),
    Case("particles", "BurstOnHit naming a despawned emitter", "world.spawn(BurstOnHit(dead))", V,
         r"BurstOnHit\.emitter: entity 13 does not exist"),
    Case("particles", "burst through the resource at a missing emitter",
         "world.resource(Particles).burst(999, 5)", kge.EntityNotFoundError, r"999"),
    Case("particles", "positions of a missing emitter",
         "world.resource(Particles).positions(999)", kge.EntityNotFoundError, r"999"),
    Case("particles", "collision grid cell of 0", "world.resource(Particles).cell = 0.0", V,
         r"Particles\.cell must be > 0"),
    Case("particles", "collision grid cell of 1e300", "world.resource(Particles).cell = 1e300",
         V, r"Particles\.cell must be <= "),
]

TWEENS = [
    Case("tweens", "tween to 1e308", f"tweens.to(hero, Transform, 'x', {BIG}, 1.0)", V,
         r"entity 1.*Transform\.x"),
    Case("tweens", "tween to NaN", "tweens.to(hero, Transform, 'x', nan, 1.0)", V,
         r"target value must be finite"),
    Case("tweens", "tween to an int past float64", "tweens.to(hero, Transform, 'x', 10**400, 1.0)",
         V, r"target value must be finite"),
    Case("tweens", "tween starting at 1e308",
         f"tweens.to(hero, Transform, 'x', 1.0, 1.0, start={BIG})", V, r"start value"),
    Case("tweens", "tween of opacity to 300", "tweens.to(hero, Sprite, 'opacity', 300, 1.0)", V,
         r"out of the field's range.*Sprite\.opacity"),
    Case("tweens", "tween of zoom to 0", "tweens.to(cam, Camera, 'zoom', 0.0, 1.0)", V,
         r"out of the field's range.*Camera\.zoom"),
    Case("tweens", "tween of a text size to 1e6", "tweens.to(label, Text, 'size', 1e6, 1.0)", V,
         r"out of the field's range.*Text\.size"),
    Case("tweens", "tween of a light radius below 0",
         "tweens.to(lamp, Light, 'radius', -1.0, 1.0)", V, r"out of the field's range"),
    Case("tweens", "tween of a string field", "tweens.to(label, Text, 'text', 'b', 1.0)", V,
         r"not numeric"),
    Case("tweens", "tween of a missing field", "tweens.to(hero, Transform, 'z', 1.0, 1.0)", V,
         r"entity 1, Transform\.z"),
    Case("tweens", "tween of a component the entity lacks",
         "tweens.to(plain, Sprite, 'opacity', 10, 1.0)", V,
         r"entity 12 has no Sprite"),
    Case("tweens", "tween of a despawned entity", "tweens.to(dead, Transform, 'x', 1.0, 1.0)",
         V, r"entity 13 does not exist"),
    Case("tweens", "a billion repeats unrolled",
         "step_ = Tween(Transform, 'x', 1.0, 0.1); tweens.start(hero, TweenSequence(step_, "
         "repeat=10**9))", V, r"tween channels once its repeats are unrolled"),
    Case("tweens", "tween vector of the wrong size",
         "tweens.to(cam, Camera, 'center', (1.0, 2.0, 3.0), 1.0)", V, r"entity 2, Camera\.center: target value \(1\.0, 2\.0, 3\.0\) has 3 numbers"),
    Case("tweens", "tween of NaN duration", "Tween(Transform, 'x', 1.0, nan)", V,
         r"Tween\(Transform\.x\)\.duration must be finite"),
    Case("tweens", "tween of negative duration", "Tween(Transform, 'x', 1.0, -1.0)", V,
         r"Tween\(Transform\.x\)\.duration must be > 0"),
    Case("tweens", "tween of an unknown easing", "Tween(Transform, 'x', 1.0, 1.0, ease='wobbly')",
         V, r"ease"),
    Case("tweens", "tween of negative delay", "Tween(Transform, 'x', 1.0, 1.0, delay=-1.0)", V,
         r"Tween\(Transform\.x\)\.delay must be >= 0"),
    Case("tweens", "camera move tween past the view bound", "tweens.move_to((1e300, 0.0), 1.0)",
         V, r"Camera\.center"),
]

UI = [*_fields("ui", "world.get(volume, Slider)", [
    ("min", f"-{BIG}", V, r"entity 9, Slider"),
    ("value", "nan", V, r"entity 9, Slider\.value"),
    ("step", "-1.0", V, r"entity 9, Slider\.step"),
]), *_fields("ui", "world.get(name, TextInput)", [
    ("max_length", "-1", V, r"entity 10, TextInput\.max_length"),
    ("caret", "99", V, r"entity 10, TextInput\.caret"),
    ("text", "5", T, r"entity 10, TextInput\.text"),
]), *_fields("ui", "world.get(ok, UINode)", [
    ("offset", f"({BIG}, 0.0)", V, r"entity 8, UINode\.offset"),
    ("padding", BIG, V, r"entity 8, UINode\.padding"),
    ("spacing", BIG, V, r"entity 8, UINode\.spacing"),
    ("width", BIG, V, r"entity 8, UINode\.width"),
    ("parent", "ok", V, r"entity 8, UINode\.parent"),
    ("parent", "999", V, r"entity 8, UINode\.parent"),
    ("anchor", "'middle'", V, r"entity 8, UINode\.anchor"),
    ("layout", "'grid3d'", V, r"entity 8, UINode\.layout"),
    ("columns", "0", V, r"entity 8, UINode\.columns"),
]), *_fields("ui", "world.get(ok, Button)", [
    ("image", "'missing.png'", AssetNotFoundError, r"entity 8, Button\.image"),
    ("disabled", "'no'", T, r"entity 8, Button\.disabled"),
]), *_fields("ui", "world.get(root, Panel)", [
    ("image", "'missing.png'", AssetNotFoundError, r"entity 7, Panel\.image"),
    ("border", "-1.0", V, r"entity 7, Panel\.border"),
]), *_fields("ui", "world.get(pick, Dropdown)", [
    ("selected", "7", V, r"entity 11, Dropdown\.selected"),
]),
    Case("ui", "UIImage of a missing file", "world.spawn(UINode(), UIImage('missing.png'))",
         AssetNotFoundError, r"UIImage\.image"),
    Case("ui", "Button with a missing icon", "world.spawn(UINode(), Button('x', image='no.png'))",
         AssetNotFoundError, r"Button\.image"),
    Case("ui", "slider over 1e308 either side", f"Slider(-{BIG}, {BIG})", V, r"Slider"),
    Case("ui", "theme padding of 1e308", f"Theme(padding={BIG})", V,
         r"Theme\.padding must be <= 1e\+07 pixels"),
    Case("ui", "theme font of a million points", "Theme(font_size=1e6)", V,
         r"Theme\.font_size must be <= 1000 points"),
    Case("ui", "UI node under a missing parent", "world.spawn(UINode(parent=999))", V,
         r"UINode\.parent"),
]

AUDIO = [
    Case("audio", "pitch 100", "AudioSource('beep.wav', pitch=100.0)", V,
         r"AudioSource\.pitch must be in \(0, 8\]"),
    Case("audio", "min distance past max", "world.get(hero, AudioSource).min_distance = 50.0", V,
         r"entity 1, AudioSource\.max_distance \(30\.0\) must be greater than min_distance"),
    Case("audio", "max distance below min", "world.get(hero, AudioSource).max_distance = 0.5", V,
         r"entity 1, AudioSource\.max_distance \(0\.5\) must be greater"),
    Case("audio", "NaN distance", "world.get(hero, AudioSource).max_distance = nan", V,
         r"entity 1, AudioSource\.max_distance must be finite"),
    Case("audio", "impact threshold past the top speed",
         "world.get(hero, ImpactSound).hit_threshold = 20.0", V,
         r"entity 1, ImpactSound\.max_speed \(10\.0\) must be >= hit_threshold \(20\.0\)"),
    Case("audio", "impact top speed below the threshold",
         "world.get(hero, ImpactSound).max_speed = 0.5", V, r"entity 1, ImpactSound\.max_speed"),
    Case("audio", "play at pitch 0", "audio.play('beep.wav', pitch=0.0)", V,
         r"audio\.play\.pitch must be > 0"),
    Case("audio", "play at pitch 1e9", "audio.play('beep.wav', pitch=1e9)", V,
         r"audio\.play\.pitch must be in"),
    Case("audio", "play with loop='yes'", "audio.play('beep.wav', loop='yes')", T,
         r"audio\.play\.loop"),
    Case("audio", "play at 1e308 m", f"audio.play('beep.wav', position=({BIG}, 0.0))", V,
         r"audio\.play\.position"),
    Case("audio", "play with min distance past max",
         "audio.play('beep.wav', position=(1.0, 0.0), min_distance=5.0, max_distance=2.0)", V,
         r"audio\.play\.max_distance \(2\.0\) must be greater"),
    Case("audio", "music fading 1e300 s", "audio.play_music('beep.wav', fade=1e300)", V,
         r"audio\.play_music\.fade must be <= "),
    Case("audio", "music stop fade NaN", "audio.stop_music(nan)", V,
         r"audio\.stop_music\.fade must be finite"),
    Case("audio", "volume 2", "audio.play('beep.wav', volume=2.0)", V, r"audio\.play\.volume"),
    Case("audio", "play a missing file", "audio.play('nope.wav')", AssetNotFoundError, r"nope"),
]

SCENES = [
    Case("scenes", "push with a misspelt keyword", "app.push_scene(level, numbr=2)", T,
         r"scene level: setup\(world.*number.*\) does not take numbr=2"),
    Case("scenes", "replace with a misspelt keyword", "app.replace_scene(level, numbr=2)", T,
         r"scene level: setup\(world.*number.*\) does not take numbr=2"),
    Case("scenes", "push run_below without overlay", "app.push_scene(level, run_below=True)", V,
         r"run_below=True\) needs overlay=True"),
    Case("scenes", "replace with a transition that is not one",
         "app.replace_scene(level, transition='fade')", T,
         r"replace_scene: transition must be a Transition"),
    Case("scenes", "a class that is not a scene", "app.push_scene(int)", T, r"a scene must be"),
    Case("scenes", "a scene of None", "app.push_scene(None)", T, r"a scene must be"),
    Case("scenes", "fade of NaN seconds", "Fade(nan)", V, r"Fade\.duration"),
    Case("scenes", "fade colour of booleans", "Fade(0.5, color=(True, 0, 0))", V, r"Fade\.color"),
    Case("scenes", "fade colour of a string", "Fade(0.5, color='black')", T, r"Fade\.color"),
    Case("scenes", "input map with an unknown key",
         "kge.InputMap(world.resource(Input)).load_data({'action': {}})", V,
         r"unknown keys \['action'\]"),
    Case("scenes", "input map file that is not text",
         "p = root_dir / 'bind.json'; p.write_bytes(b'\\xff\\xfe'); "
         "kge.InputMap(world.resource(Input)).load(p)", V, r"bind\.json: cannot read"),
    Case("scenes", "rumble strength NaN", "kge.Gamepad(0, 'pad').rumble(nan)", V,
         r"Gamepad\.rumble\.weak"),
]

#: hostile media files in the game's asset folder (see :func:`_assets_dir`)
BAD_IMAGES = {
    "truncated.png": r"not a readable image \(OSError: Truncated File Read\)",
    "empty.png": r"an empty file \(0 bytes\)",
    "zero-size.png": "not an image",
    "huge.png": "an image larger than kge.assets.headers allows",
    "wide.png": r"an image of 20000 x 1 pixels is larger",
    "not-an-image.png": "not an image",
}
BAD_WAVS = {
    "truncated.wav": "a WAV whose format chunk is cut short",
    "empty.wav": r"not a WAV file \(no RIFF/WAVE header\)",
    "bits7.wav": "a WAV of 7-bit samples",
    "claims-4gib.wav": "a WAV claiming 4,294,967,280 bytes of samples",
    "no-data.wav": "a WAV with no data chunk",
    "rate-0.wav": "a WAV at 0 Hz",
}
D = AssetDecodeError
MEDIA = [
    *(Case("media", f"sprite of {name}", f"world.spawn(Transform(), Sprite({name!r}))", D,
           rf"Sprite\.image: asset '{name}' .* could not be loaded: {why}")
      for name, why in BAD_IMAGES.items()),
    *(Case("media", f"live sprite image write of {name}",
           f"world.get(hero, Sprite).image = {name!r}", D,
           rf"entity 1, Sprite\.image: asset '{name}' .* {why}")
      for name, why in list(BAD_IMAGES.items())[:3]),
    *(Case("media", f"button icon {name}", f"world.spawn(UINode(), Button('x', image={name!r}))",
           D, rf"Button\.image: asset '{name}' .* {why}")
      for name, why in list(BAD_IMAGES.items())[:3]),
    Case("media", "UIImage of a truncated PNG", "world.spawn(UINode(), UIImage('truncated.png'))",
         D, r"UIImage\.image: asset 'truncated\.png'"),
    Case("media", "panel of a 0 x 0 PNG", "world.get(root, Panel).image = 'zero-size.png'", D,
         r"entity 7, Panel\.image: asset 'zero-size\.png'"),
    Case("media", "animator frames of a truncated sheet",
         "world.spawn(Transform(), Animator({'r': Clip.grid('truncated.png', (2, 1))}))", D,
         r"Animator\.clips\['r'\]\.frames\[0\]: asset 'truncated\.png'"),
    *(Case("media", f"sound source of {name}", f"world.spawn(Transform(), AudioSource({name!r}))",
           D, rf"AudioSource\.sound: asset '{name}' .* could not be loaded: {why}")
      for name, why in BAD_WAVS.items()),
    *(Case("media", f"play {name}", f"audio.play({name!r})", D,
           rf"audio\.play: asset '{name}' .* {why}")
      for name, why in BAD_WAVS.items()),
    Case("media", "music of a 7-bit WAV", "audio.play_music('bits7.wav')", D,
         r"asset 'bits7\.wav' .* a WAV of 7-bit samples"),
    Case("media", "impact sound of a WAV claiming 4 GiB",
         "world.add(plain, ImpactSound('claims-4gib.wav'))", D,
         r"entity 12, ImpactSound\.sound: asset 'claims-4gib\.wav'"),
    Case("media", "empty SoundData", "SoundData(b'', 8000)", V,
         r"SoundData\.samples is empty"),
]

#: more hostile calls, by area (the second probe of the game layer)
MORE = [
    Case("particles", "emission circle of NaN radius", "EmitCircle(nan)", V,
         r"EmitCircle\.radius must be finite"),
    Case("particles", "burst of a negative count", "ParticleBurst(fx, -3)", V,
         r"ParticleBurst\.count must be in 0\.\.1000000"),
    Case("particles", "burst of a billion particles", "ParticleBurst(fx, 10**9)", V,
         r"ParticleBurst\.count must be in 0\.\.1000000"),
    Case("particles", "burst direction NaN", "ParticleBurst(fx, 5, direction=nan)", V,
         r"ParticleBurst\.direction must be finite"),
    Case("particles", "attractor strength 1e308",
         "world.spawn(Transform(), ParticleAttractor(strength=1e308))", V,
         r"ParticleAttractor\.strength must be within"),
    Case("particles", "attractor radius below 0",
         "world.spawn(Transform(), ParticleAttractor(radius=-1.0))", V,
         r"ParticleAttractor\.radius must be > 0"),
    *_fields("particles", "world.get(fx, ParticleEmitter)", [
        ("spin", "(2.0, 1.0)", V, r"entity 3, ParticleEmitter\.spin must be \(low, high\)"),
        ("duration", "-1.0", V, r"entity 3, ParticleEmitter\.duration must be > 0"),
        ("burst", "-1", V, r"entity 3, ParticleEmitter\.burst must be in"),
        ("rate_per_meter", "nan", V, r"entity 3, ParticleEmitter\.rate_per_meter"),
    ]),
    *_fields("lights", "world.get(lamp, Light)", [
        ("color", "(256, 0, 0)", V, r"entity 5, Light\.color\[0\] must be an int in 0\.\.255"),
        ("shadow_softness", "-1.0", V, r"entity 5, Light\.shadow_softness must be >= 0"),
        ("height", "nan", V, r"entity 5, Light\.height must be finite"),
        ("enabled", "'yes'", T, r"entity 5, Light\.enabled must be True or False"),
        ("texture", "'missing.png'", AssetNotFoundError, r"entity 5, Light\.texture"),
    ]),
    Case("lights", "light spawned with a missing cookie",
         "world.spawn(Transform(), Light(texture='nope.png'))", AssetNotFoundError,
         r"Light\.texture: .*nope\.png"),
    Case("lights", "light cookie of a truncated PNG",
         "world.get(lamp, Light).texture = 'truncated.png'", AssetDecodeError,
         r"entity 5, Light\.texture"),
    Case("lights", "ambient light of 1e308", "kge.Lighting(ambient=(1e308, 0, 0))", T,
         r"Lighting\.ambient\[0\] must be an int in 0\.\.255"),
    Case("tweens", "tween speed NaN",
         "h = tweens.to(hero, Transform, 'x', 1.0, 1.0); h.speed = nan", V,
         r"speed must be finite"),
    Case("tweens", "tween repeat of -2", "Tween(Transform, 'x', 1.0, 1.0, repeat=-2)", V,
         r"Tween\(Transform\.x\)\.repeat must be >= 0, or -1 for forever"),
    Case("tweens", "sequence step that is not a tween",
         "TweenSequence(Tween(Transform, 'x', 1.0, 1.0), 5)", T,
         r"TweenSequence step 1 must be a Tween"),
    Case("tweens", "tween of a component instance, not its class",
         "tweens.to(hero, Transform(), 'x', 1.0, 1.0)", T,
         r"Tween\.component must be a component class"),
    Case("tweens", "zoom tween to infinity", "tweens.zoom_to(inf, 1.0)", V,
         r"entity 2, Camera\.zoom: target value must be finite"),
    Case("ui", "progress bar value NaN", "world.spawn(UINode(), ProgressBar(nan))", V,
         r"ProgressBar\.value must be finite"),
    Case("ui", "dropdown with no options selecting 0",
         "world.spawn(UINode(), Dropdown([], selected=0))", V,
         r"Dropdown\.selected 0 is not an index of its 0 options"),
    Case("ui", "focus on an entity that is not UI", "kge.focus(world, plain)", V,
         r"focus: entity 12 is not a UI node"),
    *_fields("ui", "world.get(ok, UINode)", [
        ("height", "-5", V, r"entity 8, UINode\.height must be >= 0 pixels"),
        ("width", "'200%%%'", V, r"entity 8, UINode\.width must be >= 0 pixels"),
    ]),
    *_fields("ui", "world.get(volume, Slider)", [
        ("step", "nan", V, r"entity 9, Slider\.step must be finite"),
    ]),
    *_fields("ui", "world.get(name, TextInput)", [
        ("caret", "-2", V, r"entity 10, TextInput\.caret"),
    ]),
    Case("scenes", "pop of the only scene", "app.pop_scene()", kge.SceneStackError,
         r"pop_scene\(\) would leave the App with no scene"),
    Case("scenes", "crossfade of negative seconds", "Crossfade(-1.0)", V,
         r"Crossfade\.duration must be a positive number"),
    Case("scenes", "push of a scene file that is not there",
         "app.push_scene(root_dir / 'nope.scene.toml')", kge.SceneFileError,
         r"nope\.scene\.toml: cannot read"),
    Case("scenes", "push with overlay='yes'", "app.push_scene(level, overlay='yes')", T,
         r"push_scene\.overlay must be True or False"),
]

#: hostile scene and prefab files in the game's asset folder (see :func:`_assets_dir`),
#: with what the message must say
_HEAD = 'format = 1\nkind = "scene"\n[[entity]]\nid = "a"\n'
BAD_SCENE_FILES: dict[str, tuple[str, str]] = {
    "format-99.scene.toml": ('format = 99\nkind = "scene"\n',
                             r":1: format 99 was written by a newer kge"),
    "kind-exe.scene.toml": ('format = 1\nkind = "exe"\n', r":2: kind must be one of"),
    "not-toml.scene.toml": ('format = 1\nkind = "scene"\n[[entity]\n', r":3: not valid TOML"),
    "binary.scene.toml": ("\x00\x01\x02\udcff", r"not UTF-8 text"),
    "unknown-component.scene.toml": (_HEAD + "[entity.Rocket]\n",
                                     r"entity 'a', Rocket: unknown component 'Rocket'"),
    "code-component.scene.toml": (_HEAD + '[entity."os.system"]\n',
                                  r"unknown component 'os\.system'"),
    "code-shape.scene.toml": (
        _HEAD + '[entity.Collider]\nshape = { type = "subprocess.Popen", args = ["ls"] }\n',
        r"entity 'a', Collider\.shape: unknown value type 'subprocess\.Popen'"),
    "code-script.scene.toml": (_HEAD + '[entity.Behaviour]\nscript = "os.system"\n',
                               r"entity 'a', Behaviour\.script: unknown script 'os\.system'"),
    "nan-pose.scene.toml": (_HEAD + "[entity.Transform]\nx = nan\n",
                            r"entity 'a', Transform\.x: nan is not a finite number"),
    "inf-velocity.scene.toml": (_HEAD + "[entity.RigidBody]\nvelocity = [inf, 0.0]\n",
                                r"entity 'a', RigidBody\.velocity: inf is not a finite"),
    "unknown-field.scene.toml": (_HEAD + "[entity.Transform]\nz = 1.0\n",
                                 r"entity 'a', Transform\.z: Transform has no field 'z'"),
    "string-pose.scene.toml": (_HEAD + '[entity.Transform]\nx = "left"\n',
                               r"entity 'a', Transform\.x: must be a number"),
    "duplicate-id.scene.toml": (_HEAD + '[[entity]]\nid = "a"\n',
                                r"two entities have the id 'a'"),
    "missing-reference.scene.toml": (
        _HEAD + '[entity.RevoluteJoint]\nbody_b = "ghost"\nanchor = [0.0, 0.0]\n',
        r"RevoluteJoint\.body_b: names entity 'ghost', which is not in this file"),
    "image-outside.scene.toml": (
        _HEAD + '[entity.Sprite]\nimage = "../../../../../../etc/passwd"\n',
        r"Sprite\.image: asset path '\.\./\.\./\.\./\.\./\.\./\.\./etc/passwd' leads outside"),
    "image-absolute.scene.toml": (_HEAD + '[entity.Sprite]\nimage = "/etc/hostname"\n',
                                  r"Sprite\.image: asset path '/etc/hostname' is absolute"),
    "prefab-outside.scene.toml": (_HEAD + 'prefab = "../../../../../../dev/zero"\n',
                                  r"prefab path '\.\./\.\./\.\./\.\./\.\./\.\./dev/zero' leads"),
    "deep-nesting.scene.toml": (_HEAD + "[entity.Transform]\nx = " + "[" * 400 + "]" * 400
                                + "\n", r"Transform\.x: nested deeper than 24 levels"),
    "5000-vertices.scene.toml": (
        _HEAD + '[entity.Collider]\nshape = { type = "Polygon", vertices = ['
        + ", ".join(["[0.0, 0.0]"] * 5000) + "] }\n",
        r"Collider\.shape: Polygon\.vertices must have 3\.\.16 vertices, got 5000"),
    "negative-radius.scene.toml": (
        _HEAD + '[entity.Collider]\nshape = { type = "Circle", radius = -1.0 }\n',
        r"Collider\.shape: Circle\.radius must be > 0"),
    "unknown-resource.scene.toml": ('format = 1\nkind = "scene"\n[resources.Launcher]\nx = 1\n',
                                    r"unknown resource 'Launcher'"),
    "infinite-gravity.scene.toml": (
        'format = 1\nkind = "scene"\n[resources.PhysicsSettings]\ngravity = [0.0, -inf]\n',
        r"PhysicsSettings\.gravity: -inf is not a finite number"),
    "scene-as-prefab.prefab.toml": (_HEAD, r"a scene file, not a prefab"),
    "prefab-of-itself.prefab.toml": (
        'format = 1\nkind = "prefab"\n[[entity]]\nid = "a"\n'
        'prefab = "prefab-of-itself.prefab.toml"\n', r"prefab cycle"),
    "nan-emitter.prefab.toml": (
        'format = 1\nkind = "prefab"\n[[entity]]\nid = "a"\n[entity.ParticleEmitter]\n'
        "rate = nan\n", r"entity 'a', ParticleEmitter\.rate: nan is not a finite number"),
}


def _load_call(name: str) -> str:
    if name.endswith(".prefab.toml"):
        return f"kge.instantiate(world, root_dir / '{name}', at=(0.0, 0.0))"
    return f"kge.load_scene(world, root_dir / '{name}')"


SCENE_FILES = [
    Case("scene files", name, _load_call(name), kge.SceneFileError,
         re.escape(name) + r".*" + rx)
    for name, (_, rx) in BAD_SCENE_FILES.items()
]

CASES: list[Case] = [
    *SPRITE, *CLIPS, *SHAKE, *CAMERA, *TEXT, *DRAWN, *LIGHTS, *PARTICLES, *TWEENS, *UI,
    *AUDIO, *SCENES, *MEDIA, *MORE, *SCENE_FILES,
]


@dataclass
class Game:
    app: kge.App
    ns: dict[str, Any]
    root: Path  #: the game's asset folder (removed after the case)


def _assets_dir() -> Path:
    from kge.sound import tone
    from kge.testing import write_png

    root = Path(tempfile.mkdtemp(prefix="kge-game-catalogue-"))
    pixels = np.zeros((32, 64, 4), np.uint8)
    pixels[..., 0] = np.arange(64, dtype=np.uint8)[None, :] * 4
    pixels[..., 3] = 255
    write_png(pixels, root / "sheet.png")
    wav = tone(440, 0.05, rate=8000).to_wav()
    (root / "beep.wav").write_bytes(wav)
    _hostile_media(root, (root / "sheet.png").read_bytes(), wav)
    for name, (text, _) in BAD_SCENE_FILES.items():
        (root / name).write_bytes(text.encode("utf-8", "surrogateescape"))
    return root


def _png(width: int, height: int) -> bytes:
    """A PNG of just its header (IHDR, IEND) claiming ``width`` x ``height``."""
    def chunk(kind: bytes, data: bytes) -> bytes:
        return struct.pack(">I", len(data)) + kind + data + struct.pack(
            ">I", zlib.crc32(kind + data))

    ihdr = struct.pack(">IIBBBBB", width, height, 8, 6, 0, 0, 0)
    return b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", ihdr) + chunk(b"IEND", b"")


def _hostile_media(root: Path, png: bytes, wav: bytes) -> None:
    """The files of :data:`BAD_IMAGES` and :data:`BAD_WAVS`."""
    files = {
        "truncated.png": png[: len(png) // 2], "empty.png": b"", "zero-size.png": _png(0, 0),
        "huge.png": _png(100_000, 100_000), "wide.png": _png(20_000, 1),
        "not-an-image.png": b"#!/bin/sh\necho hi\n",
        "truncated.wav": wav[:30], "empty.wav": b"",
        "bits7.wav": wav[:34] + struct.pack("<H", 7) + wav[36:],
        "claims-4gib.wav": wav[:40] + struct.pack("<I", 0xFFFFFFF0) + wav[44:],
        "no-data.wav": wav[:36], "rate-0.wav": wav[:24] + struct.pack("<I", 0) + wav[28:],
    }  # fmt: skip
    for name, data in files.items():
        (root / name).write_bytes(data)


def build_game() -> Game:
    """The standard game every case runs against (ids 1..12, two frames run)."""
    from kge import (
        Animator,
        Button,
        Camera,
        CameraShake,
        Clip,
        Dropdown,
        ImpactSound,
        Light,
        Panel,
        ParticleEmitter,
        Slider,
        Sprite,
        Text,
        TextInput,
        Transform,
        UINode,
        draw,
    )  # fmt: skip
    from kge.components.audio import AudioSource

    root_dir = _assets_dir()
    ids: dict[str, int] = {}

    def setup(world: kge.World) -> None:
        world.insert_resource(Assets(root_dir, anchor=root_dir))
        clip = Clip.grid("sheet.png", (4, 2), fps=10)
        ids["hero"] = world.spawn(
            Transform(0.0, 0.0), Sprite("sheet.png"), Animator({"run": clip}),
            AudioSource("beep.wav"), ImpactSound("beep.wav"),
        )  # fmt: skip
        ids["cam"] = world.spawn(Camera(), CameraShake())
        ids["fx"] = world.spawn(Transform(1.0, 0.0), ParticleEmitter(rate=50.0, seed=1))
        ids["label"] = world.spawn(Transform(0.0, 1.0), Text("hi"))
        ids["lamp"] = world.spawn(Transform(2.0, 0.0), Light())
        ids["box"] = world.spawn(Transform(-2.0, 0.0), draw.Rect(1.0, 1.0))
        ids["root"] = world.spawn(UINode(width=300, height=200, layout="column"), Panel())
        ids["ok"] = world.spawn(UINode(parent=ids["root"]), Button("ok"))
        ids["volume"] = world.spawn(UINode(parent=ids["root"]), Slider(0.0, 1.0, 0.5))
        ids["name"] = world.spawn(UINode(parent=ids["root"]), TextInput("abc"))
        ids["pick"] = world.spawn(UINode(parent=ids["root"]), Dropdown(["a", "b"]))
        ids["plain"] = world.spawn(Transform(5.0, 5.0))
        ids["dead"] = world.spawn(Transform(-3.0, 3.0))
        world.despawn(ids["dead"])

    app = kge.App(setup, headless=True)
    app.step(2)
    world = app.world

    def level(world: kge.World, number: int = 1) -> None:
        del world, number

    ns: dict[str, Any] = {name: getattr(kge, name) for name in kge.__all__}
    ns.update(ids)
    ns.update(
        kge=kge, math=math, nan=math.nan, inf=math.inf, world=world, app=app,
        tweens=world.resource(kge.Tweens), audio=world.resource(kge.Audio),
        clip=Clip.grid("sheet.png", (4, 2), fps=10), level=level, root_dir=root_dir,
        AudioSource=AudioSource, Input=kge.Input, SoundData=kge.SoundData,
    )
    return Game(app, ns, root_dir)


def _finite_state(world: kge.World) -> None:
    """Every pose, camera, particle row and tween row of ``world`` is finite."""
    from kge import Camera, Particles, Transform, Tweens

    for e, (t,) in world.query(Transform):
        assert all(math.isfinite(v) for v in (t.x, t.y, t.angle)), f"entity {e}: {t}"
    for e, (cam,) in world.query(Camera):
        assert all(math.isfinite(v) for v in cam.center), f"entity {e}: {cam}"
    for e, st in world.resource(Particles).states.items():
        n = st.pool.count
        for name in ("pos", "vel", "angle"):
            arr = getattr(st.pool, name, None)
            if arr is not None:
                assert np.isfinite(arr[:n]).all(), f"emitter {e}: {name} not finite"
    tw = world.resource(Tweens)
    rows = tw.rows
    assert np.isfinite(tw.v_start[:rows]).all() and np.isfinite(tw.v_end[:rows]).all()


def run_case(case: Case) -> BaseException:
    """Run ``case`` in a fresh game; assert the error, that nothing changed, and that the
    game runs on with finite state. Returns the exception."""
    game = build_game()
    app, ns = game.app, game.ns
    try:
        world = app.world
        before = state_dump(world)
        try:
            exec(case.call, ns)
        except Exception as exc:  # checked below
            err: BaseException = exc
        else:
            raise AssertionError(f"{case.name}: {case.call} raised nothing")
        assert type(err) is case.error, f"{case.name}: got {type(err).__name__}: {err}"
        assert re.search(case.names, str(err)), f"{case.name}: message {str(err)!r}"
        assert state_dump(world) == before, f"{case.name}: the world changed"
        app.step(2)
        _finite_state(app.world)
        return err
    finally:
        app.close()
        shutil.rmtree(game.root, ignore_errors=True)


def render_table() -> str:
    """The markdown table of every case, with the message each one gets now."""
    lines = ["| # | area | case | call | error | message |", "|---|---|---|---|---|---|"]
    for i, case in enumerate(CASES, 1):
        err = run_case(case)
        msg = re.sub(r"\S*kge-game-catalogue-[^/\s]*", "<assets>", str(err).splitlines()[0])
        lines.append(
            f"| {i} | {case.area} | {cell(case.name)} | `{cell(case.call)}` | "
            f"`{type(err).__name__}` | {cell(msg)} |"
        )
    return "\n".join(lines) + "\n"


def doc_section() -> str:
    return SECTION.read()


if __name__ == "__main__":
    main(SECTION, render_table)
