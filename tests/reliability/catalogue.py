"""The bad-input catalogue: every case, the call that makes it, and the error it gets.

One list, :data:`CASES`, drives both the test (``test_bad_input.py``) and the table
in ``docs/reliability.md``: the table is rendered from the cases by running them,
and a test fails when the document differs from what the cases produce now. To
refresh the table after adding a case::

    .venv/bin/python -m tests.reliability.catalogue --write

Each case's ``call`` is Python source run against a small standard scene (see
:func:`build_scene`): ``ground`` (static box), ``a`` and ``b`` (dynamic boxes
resting on it, ``a`` with ``contact_hooks=True``), ``plain`` (an entity with a
Transform only), ``hinge`` (a RevoluteJoint a-b), ``rod`` (a DistanceJoint a-b)
and ``dead`` (a despawned body), plus ``world``, ``physics``, ``assets`` and
``step()``.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import kge
from kge.assets import AssetNotFoundError, Assets
from kge.errors import (
    ComponentTypeError,
    EntityNotFoundError,
    HookSignatureError,
    MissingComponentError,
    MissingResourceError,
    ValidationError,
    WorldLockedError,
)
from kge.snapshot import SnapshotError

from .doctable import DOCS, Section, cell, main
from .harness import PhysicsWorld

DOC = DOCS / "reliability.md"
SECTION = Section.named(DOC, "catalogue", "tests/reliability/catalogue.py")


@dataclass(frozen=True, slots=True)
class Case:
    name: str  #: what is wrong, in words
    call: str  #: the offending call (Python, run in the standard scene)
    error: type[Exception]  #: the exact exception class expected
    names: str  #: a regex the message must contain (entity / component / field)
    in_step: bool = False  #: the error surfaces from step(): compare structure, not bytes
    setup: str = ""  #: run before the "before" state is taken (not part of the call)


V = ValidationError
T = ComponentTypeError
REG17 = "[(math.cos(k * math.tau / 17), math.sin(k * math.tau / 17)) for k in range(17)]"

CASES: list[Case] = [
    # -- shapes -----------------------------------------------------------------------
    Case("non-convex polygon", "Polygon([(0, 0), (4, 0), (4, 4), (2, 1), (0, 4)])", V,
         r"Polygon\.vertices must be convex"),
    Case("clockwise polygon", "Polygon([(0, 0), (0, 1), (1, 0)])", V,
         r"Polygon\.vertices must be counter-clockwise"),
    Case("collinear polygon", "Polygon([(0, 0), (1, 1), (2, 2)])", V, r"Polygon has zero area"),
    Case("17-vertex polygon", f"Polygon({REG17})", V, r"Polygon\.vertices must have 3\.\.16"),
    Case("2-vertex polygon", "Polygon([(0, 0), (1, 0)])", V, r"Polygon\.vertices must have"),
    Case("duplicate polygon vertices", "Polygon([(0, 0), (1, 0), (1, 0), (0, 1)])", V,
         r"Polygon\.vertices 1 and 2 coincide"),
    Case("NaN polygon vertex", "Polygon([(0, 0), (1, 0), (nan, 1)])", V,
         r"Polygon\.vertices\[2\]\[0\] must be finite"),
    Case("zero radius", "Circle(0.0)", V, r"Circle\.radius must be > 0"),
    Case("negative radius", "Circle(-1.0)", V, r"Circle\.radius must be > 0"),
    Case("zero half extent", "Box(0.0, 1.0)", V, r"Box\.half_width must be > 0"),
    Case("negative half extent", "Box(1.0, -0.5)", V, r"Box\.half_height must be > 0"),
    Case("half extent below the slop", "Box(0.001, 1.0)", V, r"Box\.half_width must be >="),
    Case("infinite box angle", "Box(1.0, 1.0, angle=inf)", V, r"Box\.angle must be finite"),
    Case("zero-length edge", "Edge((1, 1), (1, 1))", V, r"Edge has zero length"),
    Case("box too large (mass would overflow)", "Box(1e200, 1.0)", V,
         r"Box\.half_width must be <= 1e\+06 m"),
    Case("polygon vertex too far out", "Polygon([(0, 0), (1e300, 0), (0, 1)])", V,
         r"Polygon\.vertices\[1\] must lie within 1e\+06 m"),
    Case("2-point chain loop", "Chain([(0, 0), (1, 0)], loop=True)", V,
         r"Chain\.vertices needs at least 3"),
    # -- collider, body, transform, filter --------------------------------------------
    Case("negative density", "world.get(a, Collider).density = -1.0", V,
         r"entity 2, Collider\.density must be >= 0"),
    Case("NaN density", "Collider(Circle(1.0), density=nan)", V,
         r"Collider\.density must be finite"),
    Case("density whose mass overflows", "world.get(a, Collider).density = 1e300", V,
         r"entity 2, Collider\.density must be <= 1e\+12 kg/m\^2"),
    Case("density so small joints overflow", "Collider(Circle(1.0), density=1e-300)", V,
         r"Collider\.density must be 0 \(massless\) or >= 1e-06 kg/m\^2"),
    Case("negative friction", "world.get(b, Collider).friction = -0.1", V,
         r"entity 3, Collider\.friction must be >= 0"),
    Case("shape that is not a shape", "Collider('circle')", T, r"Collider\.shape must be one of"),
    Case("shape class instead of instance", "world.get(a, Collider).shape = Circle", T,
         r"entity 2, Collider\.shape must be one of"),
    Case("collider on a missing body", "world.spawn(Collider(Circle(1.0), body=999))", V,
         r"Collider\.body: body entity 999 does not exist"),
    Case("collider on an entity without body", "world.add(plain, Collider(Circle(1.0), body=plain))",
         V, r"entity 4, Collider\.body: entity 4 has no RigidBody"),
    Case("zero mass", "world.get(a, RigidBody).mass = 0.0", V,
         r"entity 2, RigidBody\.mass must be > 0"),
    Case("negative mass", "RigidBody(mass=-2.0)", V, r"RigidBody\.mass must be > 0"),
    Case("mass whose inertia overflows", "world.get(b, RigidBody).mass = 1e300", V,
         r"entity 3, RigidBody\.mass must be <= 1e\+24 kg"),
    Case("mass so small joints overflow", "world.get(b, RigidBody).mass = 1e-300", V,
         r"entity 3, RigidBody\.mass must be >= 1e-06 kg"),
    Case("NaN position", "world.get(a, Transform).x = nan", V,
         r"entity 2, Transform\.x must be finite"),
    Case("infinite position", "world.spawn(Transform(0.0, inf), RigidBody())", V,
         r"Transform\.y must be finite"),
    Case("NaN angle", "world.get(b, Transform).angle = nan", V,
         r"entity 3, Transform\.angle must be finite"),
    Case("infinite velocity", "world.get(a, RigidBody).velocity = (inf, 0.0)", V,
         r"entity 2, RigidBody\.velocity\[0\] must be finite"),
    Case("NaN angular velocity", "world.get(b, RigidBody).angular_velocity = nan", V,
         r"entity 3, RigidBody\.angular_velocity must be finite"),
    Case("velocity of the wrong shape", "world.get(a, RigidBody).velocity = (1.0, 2.0, 3.0)", V,
         r"entity 2, RigidBody\.velocity must be an \(x, y\) pair"),
    Case("negative damping", "world.get(a, RigidBody).linear_damping = -0.5", V,
         r"entity 2, RigidBody\.linear_damping must be >= 0"),
    Case("unknown body type", "world.get(a, RigidBody).type = 'wobbly'", T,
         r"entity 2, RigidBody\.type must be a BodyType"),
    Case("non-bool flag", "world.get(a, RigidBody).enabled = 1", T,
         r"entity 2, RigidBody\.enabled must be True or False"),
    Case("category bits out of range", "Filter(category_bits=2**32)", V,
         r"Filter\.category_bits must be in \[0, 0xFFFFFFFF\]"),
    Case("negative mask bits", "Filter(mask_bits=-1)", V, r"Filter\.mask_bits must be in"),
    Case("group index out of range", "Filter(group_index=2**31)", V,
         r"Filter\.group_index must fit in 32 bits"),
    Case("filter that is not a Filter", "world.get(a, Collider).filter = 0x0002", T,
         r"entity 2, Collider\.filter must be a Filter"),
    # -- forces -------------------------------------------------------------------------
    Case("NaN force", "physics.apply_force(a, (nan, 0.0))", V,
         r"entity 2, Physics\.apply_force\.force\[0\] must be finite"),
    Case("NaN force point", "physics.apply_force(a, (1.0, 0.0), point=(0.0, nan))", V,
         r"entity 2, Physics\.apply_force\.point\[1\] must be finite"),
    Case("infinite torque", "physics.apply_torque(a, inf)", V,
         r"entity 2, Physics\.apply_torque\.torque must be finite"),
    Case("NaN linear impulse", "physics.apply_linear_impulse(b, (0.0, nan))", V,
         r"entity 3, Physics\.apply_linear_impulse\.impulse\[1\] must be finite"),
    Case("infinite angular impulse", "physics.apply_angular_impulse(b, -inf)", V,
         r"entity 3, Physics\.apply_angular_impulse\.impulse must be finite"),
    Case("force on an entity without body", "physics.apply_force(plain, (1.0, 0.0))", V,
         r"entity 4 has no body"),
    Case("force on a despawned entity", "physics.apply_force(dead, (1.0, 0.0))",
         EntityNotFoundError, r"entity 7 does not exist"),
    Case("impulse whose lever arm overflows",
         "physics.apply_linear_impulse(a, (1e308, 1e308), point=(1e300, 0.0))", V,
         r"entity 2, Physics\.apply_linear_impulse: the resulting velocity would not be finite"),
    Case("NaN gravity", "physics.settings.gravity = (nan, -10.0)", V,
         r"PhysicsSettings\.gravity\[0\] must be finite"),
    Case("NaN ray end", "physics.raycast((0.0, 5.0), (nan, -5.0))", V,
         r"raycast\.p2\[0\] must be finite"),
    Case("inverted query box", "physics.query_aabb((1.0, 1.0), (0.0, 0.0))", V,
         r"lower \(1\.0, 1\.0\) must not exceed upper"),
    # -- joints -------------------------------------------------------------------------
    Case("joint to a missing entity", "world.spawn(RevoluteJoint(a, 999, anchor=(0, 0)))", V,
         r"RevoluteJoint\.body_b: body entity 999 does not exist"),
    Case("joint to a despawned entity", "world.spawn(DistanceJoint(dead, b))", V,
         r"DistanceJoint\.body_a: body entity 7 does not exist"),
    Case("joint to an entity without body", "world.spawn(WeldJoint(a, plain))", V,
         r"WeldJoint\.body_b: entity 4 has no RigidBody or Collider"),
    Case("joint of a body to itself", "world.spawn(DistanceJoint(a, a))", V,
         r"DistanceJoint: body_a and body_b are both entity 2"),
    Case("joint body that is not an id", "RevoluteJoint('a', b)", T,
         r"RevoluteJoint\.body_a must be an entity id"),
    Case("gear on a non-revolute joint", "world.spawn(GearJoint(hinge, rod))", V,
         r"GearJoint\.joint_b: entity 6 must hold a RevoluteJoint or PrismaticJoint"),
    Case("gear naming a missing joint", "world.spawn(GearJoint(hinge, 999))", V,
         r"GearJoint\.joint_b: joint entity 999 does not exist"),
    Case("gear naming a body, not a joint", "world.spawn(GearJoint(a, hinge))", V,
         r"GearJoint\.joint_a: entity 2 must hold a RevoluteJoint"),
    Case("gear of two joints that move one body", "world.spawn(GearJoint(hinge, hinge2))", V,
         r"GearJoint\.joint_b: joints 5 and \d+ both move entity 3 \(their body_b\)",
         setup="hinge2 = world.spawn(RevoluteJoint(a, b, anchor=(0.0, 1.0)))"),
    Case("gear of a joint with itself", "GearJoint(hinge, hinge)", V,
         r"GearJoint\.joint_b must differ from joint_a"),
    Case("gear ratio zero", "GearJoint(hinge, 8, ratio=0.0)", V, r"GearJoint\.ratio must not be 0"),
    Case("angle limits lower > upper", "RevoluteJoint(a, b, lower_angle=1.0, upper_angle=-1.0)", V,
         r"RevoluteJoint\.upper_angle must be >= lower_angle"),
    Case("live limit write lower > upper", "world.get(hinge, RevoluteJoint).lower_angle = 2.0", V,
         r"entity 5, RevoluteJoint\.lower_angle must be <= upper_angle"),
    Case("translation limits lower > upper",
         "PrismaticJoint(a, b, lower_translation=2.0, upper_translation=1.0)", V,
         r"PrismaticJoint\.upper_translation must be >= lower_translation"),
    Case("length limits min > max", "DistanceJoint(a, b, min_length=3.0, max_length=1.0)", V,
         r"DistanceJoint\.max_length must be >= min_length"),
    Case("negative motor torque", "world.get(hinge, RevoluteJoint).max_motor_torque = -1.0", V,
         r"entity 5, RevoluteJoint\.max_motor_torque must be >= 0"),
    Case("NaN motor speed", "world.get(hinge, RevoluteJoint).motor_speed = nan", V,
         r"entity 5, RevoluteJoint\.motor_speed must be finite"),
    Case("zero axis", "PrismaticJoint(a, b, local_axis_a=(0.0, 0.0))", V,
         r"PrismaticJoint\.local_axis_a must be a non-zero direction"),
    Case("negative spring frequency", "world.get(rod, DistanceJoint).frequency_hz = -2.0", V,
         r"entity 6, DistanceJoint\.frequency_hz must be >= 0"),
    Case("pulley ratio zero", "PulleyJoint(a, b, ratio=0.0)", V, r"PulleyJoint\.ratio must be > 0"),
    # -- ECS misuse ---------------------------------------------------------------------
    Case("component class instead of instance", "world.spawn(Transform)", T,
         r"expected a component instance, got the class Transform"),
    Case("None as a component", "world.add(a, None)", T,
         r"entity 2: expected a component instance, got NoneType"),
    Case("two components of one type", "world.spawn(Transform(), Transform())", T,
         r"two Transform components"),
    Case("entity id that is not an int", "world.get('a', Transform)", T,
         r"world\.get\(\): entity must be an int id"),
    Case("despawning twice", "world.despawn(b)", EntityNotFoundError,
         r"world\.despawn\(\): entity 3 was despawned", setup="world.despawn(b)"),
    Case("despawning a flushed entity", "world.despawn(dead)", EntityNotFoundError,
         r"world\.despawn\(\): entity 7 does not exist"),
    Case("add to a despawned entity", "world.add(dead, Name('x'))", EntityNotFoundError,
         r"world\.add\(\): entity 7 does not exist"),
    Case("get from a despawned entity", "world.get(dead, Transform)", EntityNotFoundError,
         r"world\.get\(\): entity 7 does not exist"),
    Case("remove a missing component", "world.remove(plain, RigidBody)", MissingComponentError,
         r"entity 4 has no RigidBody component"),
    Case("missing resource", "world.resource(Camera)", MissingResourceError,
         r"has no Camera resource"),
    Case("spawn inside pre-solve", "physics.on_pre_solve(spawn_in_hook); step()",
         WorldLockedError, r"world\.spawn\(\) inside a physics callback", in_step=True),
    Case("despawn inside pre-solve", "physics.on_pre_solve(despawn_in_hook); step()",
         WorldLockedError, r"world\.despawn\(\) inside a physics callback", in_step=True),
    Case("add inside the contact filter", "physics.contact_filter = add_in_filter; "
         "world.get(b, Transform).y = 3.0; step(); world.get(b, Transform).y = 0.5; step()",
         WorldLockedError, r"world\.add\(\) inside a physics callback", in_step=True),
    Case("hook with wrong parameters", "Behaviour(BadHook())", HookSignatureError,
         r"on_update"),
    Case("unknown asset path", "assets.bytes('no/such/sprite.png')", AssetNotFoundError,
         r"asset 'no/such/sprite\.png' not found"),
    Case("garbage snapshot", "World.restore(b'not a snapshot')", SnapshotError,
         r"not a kge snapshot"),
    Case("zero solver iterations", "PhysicsSettings(iterations=0)", V,
         r"PhysicsSettings\.iterations must be >= 1"),
    # -- one instance, one entity (issue 15, class 5) ------------------------------------
    Case("one component instance on two entities", "world.spawn(world.get(a, Transform))", V,
         r"world\.spawn\(\): this Transform instance already is a component of entity 2"),
    Case("adding another entity's component", "world.add(plain, world.get(b, RigidBody))", V,
         r"world\.add\(\): entity 4: this RigidBody instance already is a component of entity 3"),
    Case("two joints spawned on one entity",
         "world.spawn(RevoluteJoint(a, b, anchor=(0.0, 0.0)), DistanceJoint(a, b))", T,
         r"RevoluteJoint and DistanceJoint are both joints; an entity holds one joint"),
    Case("a second joint added to a joint entity", "world.add(hinge, DistanceJoint(a, b))", T,
         r"world\.add\(\): entity 5: RevoluteJoint and DistanceJoint are both joints"),
    # -- time and API inputs (issue 15, class 7) ----------------------------------------
    Case("NaN frame time", "App(headless=True).advance(nan)", V,
         r"App\.advance\.frame_dt must be finite, got nan"),
    Case("step count as a string", "App(headless=True).step('3')", T,
         r"App\.step\.n must be an int, got str '3'"),
    Case("negative step count", "App(headless=True).step(-1)", V, r"App\.step\.n must be >= 0"),
    Case("time scale as a string", "app = App(headless=True); app.time_scale = 'fast'", T,
         r"App\.time_scale must be a number, got str 'fast'"),
    Case("paused as a string", "app = App(headless=True); app.paused = 'no'", T,
         r"App\.paused must be True or False"),
    Case("NaN accumulator", "App(headless=True).timestep.accumulator = nan", V,
         r"FixedTimestep\.accumulator must be finite"),
    Case("int beyond a float", "Transform(x=10**400)", V,
         r"Transform\.x must be finite, got an int of 1329 bits"),
    Case("huge int velocity write", "world.get(a, RigidBody).velocity = (10**400, 0)", V,
         r"entity 2, RigidBody\.velocity\[0\] must be finite, got an int"),
    Case("component type as a string", "world.get(a, 'Transform')", T,
         r"world\.get\(\): the component type must be a class, got str 'Transform'"),
    Case("query by a string", "world.query(Transform, 'RigidBody')", T,
         r"world\.query\(\): the component type must be a class"),
    Case("velocity as a set", "world.get(a, RigidBody).velocity = {1.0, 2.0}", T,
         r"entity 2, RigidBody\.velocity must be an \(x, y\) pair, got set"),
    Case("entity id that is a list", "world.exists([a])", T,
         r"world\.exists\(\): entity must be an int id, got list"),
    Case("resource type as a string", "world.resource('Camera')", T,
         r"world\.resource\(\): the component type must be a class, got str"),
    Case("a set as a component", "world.add(a, {1, 2})", T,
         r"entity 2: expected a component instance, got set"),
    Case("a function as a component", "world.spawn(Transform(), print)", T,
         r"expected a component instance, got builtin_function_or_method"),
    Case("substeps beyond reason", "physics.settings.substeps = 10**19", V,
         r"PhysicsSettings\.substeps must be <= 1000"),
    Case("replacing a Behaviour's script", "Behaviour(Script()).script = 5", T,
         r"Behaviour\.script cannot be replaced"),
    Case("joint of the ground to the ground",
         "world.spawn(RevoluteJoint(None, None, anchor=(0.0, 0.0)))", V,
         r"RevoluteJoint: body_a and body_b are both None \(the ground\)"),
    Case("behaviour of a number", "Behaviour(5)", T,
         r"Behaviour\.script must define a hook .* got int 5"),
    Case("NaN mouse move", "Input().move_mouse(nan, 10.0)", V,
         r"Input\.move_mouse\.x must be finite"),
    Case("mouse button at a 3-tuple", "Input().mouse_down(at=(1.0, 2.0, 3.0))", V,
         r"Input\.mouse_down\.at must be an \(x, y\) pair"),
    Case("self-intersecting star polygon",
         "Polygon([(0.0, 1.0), (-0.588, -0.809), (0.951, 0.309), (-0.951, 0.309), "
         "(0.588, -0.809)])", V,
         r"Polygon\.vertices must outline a simple convex polygon: .* winds 2 times"),
    # -- extreme finite values (issue 15, class 6) --------------------------------------
    Case("teleport beyond the world bound", "world.get(b, Transform).x = 1e160", V,
         r"entity 3, Transform\.x must lie within 1e\+07 m of the origin"),
    Case("joint anchor beyond the world bound",
         "world.get(hinge, RevoluteJoint).local_anchor_a = (1e8, 0.0)", V,
         r"entity 5, RevoluteJoint\.local_anchor_a must lie within 1e\+07 m"),
    Case("motor joint offset beyond the world bound", "MotorJoint(a, b, linear_offset=(1e300, 0.0))",
         V, r"MotorJoint\.linear_offset must lie within 1e\+07 m"),
    Case("mouse target beyond the world bound", "MouseJoint(None, a, target=(0.0, -1e160))", V,
         r"MouseJoint\.target must lie within 1e\+07 m"),
    Case("spring frequency too high", "world.get(rod, DistanceJoint).frequency_hz = 1e300", V,
         r"entity 6, DistanceJoint\.frequency_hz must be <= 1e\+06 Hz"),
    Case("polygon skin of metres", "physics.settings.polygon_radius = 5.0", V,
         r"PhysicsSettings\.polygon_radius must be <= 1 m"),
    Case("per-step translation cap too high", "physics.settings.max_translation = 1e300", V,
         r"PhysicsSettings\.max_translation must be <= 1000 m"),
    Case("NaN friction written in pre-solve", "physics.on_pre_solve(nan_friction); step()", V,
         r"contact 1-2, PreSolve\.friction must be finite, got nan", in_step=True),
    Case("string written to PreSolve.enabled", "physics.on_pre_solve(text_enabled); step()", T,
         r"contact 1-2, PreSolve\.enabled must be True or False", in_step=True),
    # -- restores (issue 15, class 2) ------------------------------------------------------
    Case("snapshot holding a NaN position", "World.restore(bad)", SnapshotError,
         r"snapshot entity 2, Transform: Transform\.x must be finite, got nan",
         setup="import pickle; d = pickle.loads(world.snapshot()); "
               "object.__setattr__(d['entities'][a][0], 'x', nan); "
               "from kge.snapshot import seal; bad = seal(d)"),
    Case("snapshot of a collider on a missing body",
         "App(lambda w: None, headless=True).restore(bad)", SnapshotError,
         r"snapshot entity 2: entity 2, Collider\.body: body entity 999 does not exist",
         setup="import pickle; d = pickle.loads(world.snapshot()); "
               "c = [c for c in d['entities'][a] if type(c) is Collider][0]; "
               "object.__setattr__(c, 'body', 999); from kge.snapshot import seal; bad = seal(d)"),
    Case("snapshot bytes not signed in this process (a file, another process)",
         "World.restore(bad)", SnapshotError, r"not a kge snapshot taken in this process",
         setup="import pickle; bad = pickle.dumps(pickle.loads(world.snapshot()))"),
    # -- callbacks (issue 15, class 8) --------------------------------------------------
    Case("closing the world inside pre-solve", "physics.on_pre_solve(close_in_hook); step()",
         WorldLockedError, r"world\.close\(\) inside a physics callback", in_step=True),
    # -- live writes of entity references (issue 15, class 4) ----------------------------
    Case("live joint body write to a missing entity", "world.get(hinge, RevoluteJoint).body_b = 999",
         V, r"entity 5, RevoluteJoint\.body_b: body entity 999 does not exist"),
    Case("live joint body write to a despawned entity", "world.get(rod, DistanceJoint).body_a = dead",
         V, r"entity 6, DistanceJoint\.body_a: body entity 7 does not exist"),
    Case("live joint body write to an entity without body",
         "world.get(rod, DistanceJoint).body_b = plain", V,
         r"entity 6, DistanceJoint\.body_b: entity 4 has no RigidBody or Collider"),
    Case("live joint body write making both bodies one", "world.get(hinge, RevoluteJoint).body_b = a",
         V, r"entity 5, RevoluteJoint: body_a and body_b are both entity 2"),
    Case("live joint body write of a string", "world.get(hinge, RevoluteJoint).body_a = 'a'", T,
         r"entity 5, RevoluteJoint\.body_a must be an entity id"),
    Case("live NaN write to a listener's pan width", "AudioListener(2.0).pan_width = nan", V,
         r"AudioListener\.pan_width must be finite, got nan"),
    Case("live Collider.body write to a missing entity", "world.get(ground, Collider).body = dead",
         V, r"entity 1, Collider\.body: body entity 7 does not exist"),
    Case("live Collider.body write to an entity without body",
         "world.get(ground, Collider).body = plain", V,
         r"entity 1, Collider\.body: entity 4 has no RigidBody"),
    Case("live gear write naming a distance joint", "world.get(gear, GearJoint).joint_b = rod", V,
         r"entity 9, GearJoint\.joint_b: entity 6 must hold a RevoluteJoint or PrismaticJoint",
         setup="hinge2 = world.spawn(RevoluteJoint(None, a, anchor=(0.0, 0.5))); "
               "gear = world.spawn(GearJoint(hinge, hinge2))"),
    Case("live gear write naming a missing joint", "world.get(gear, GearJoint).joint_a = 999", V,
         r"entity 9, GearJoint\.joint_a: joint entity 999 does not exist",
         setup="hinge2 = world.spawn(RevoluteJoint(None, a, anchor=(0.0, 0.5))); "
               "gear = world.spawn(GearJoint(hinge, hinge2))"),
]


class BadHook(kge.Script):
    def on_update(self) -> None:  # missing dt
        pass


@dataclass
class Scene:
    pw: PhysicsWorld
    ns: dict[str, Any]


def build_scene() -> Scene:
    """The standard scene every case runs against (ids 1..7, one step taken)."""
    from kge import (
        Box,
        Circle,
        Collider,
        DistanceJoint,
        RevoluteJoint,
        RigidBody,
        Transform,
    )

    pw = PhysicsWorld(name="catalogue")  # a fixed name: messages may quote it
    w = pw.world
    ground = w.spawn(Transform(0.0, -1.0), Collider(Box(10.0, 1.0)))
    a = w.spawn(Transform(0.0, 0.5), RigidBody(), Collider(Box(0.5, 0.5), contact_hooks=True))
    b = w.spawn(Transform(2.0, 0.5), RigidBody(), Collider(Box(0.5, 0.5)))
    plain = w.spawn(Transform(5.0, 5.0))
    hinge = w.spawn(RevoluteJoint(a, b, anchor=(1.0, 0.5)))
    rod = w.spawn(DistanceJoint(a, b))
    dead = w.spawn(Transform(-3.0, 3.0), RigidBody(), Collider(Circle(0.2)))
    w.despawn(dead)
    pw.step()
    ns: dict[str, Any] = {name: getattr(kge, name) for name in kge.__all__}
    ns.update(
        math=math, nan=math.nan, inf=math.inf, world=w, physics=pw.physics, step=pw.step,
        assets=Assets(anchor=Path(__file__).parent), ground=ground, a=a, b=b, plain=plain,
        hinge=hinge, rod=rod, dead=dead, BadHook=BadHook,
        spawn_in_hook=lambda contact: w.spawn(Transform()),
        despawn_in_hook=lambda contact: w.despawn(b),
        nan_friction=lambda contact: setattr(contact, "friction", math.nan),
        close_in_hook=lambda contact: w.close(),
        text_enabled=lambda contact: setattr(contact, "enabled", "no"),
        add_in_filter=lambda ca, cb: w.add(plain, kge.Name("x")) is None,  # type: ignore[func-returns-value]
    )
    return Scene(pw, ns)


def structure(pw: PhysicsWorld) -> dict[int, tuple[str, ...]]:
    w = pw.world
    return {e: tuple(sorted(type(c).__name__ for c in w.components(e))) for e in w.entities()}


def _control(case: Case) -> tuple[dict[int, tuple[str, ...]], dict[str, int]]:
    """Structure and pymunk counts of the scene after ``setup`` and two steps, no call."""
    from .harness import space_counts

    scene = build_scene()
    try:
        exec(case.setup, scene.ns)
        scene.pw.step(2)
        return structure(scene.pw), space_counts(scene.pw.sim)
    finally:
        scene.pw.close()


def run_case(case: Case) -> BaseException:
    """Run ``case`` in a fresh scene; assert the error and that nothing changed.

    "Nothing changed" is checked twice: right after the call (every entity and
    component byte for byte, or the entity/component structure when the error
    comes out of a step, plus the pymunk object counts), and two steps later
    against a control run of the same scene without the call, so no half-applied
    change surfaces at the next step either. Returns the exception.
    """
    from .harness import space_counts, state_dump

    scene = build_scene()
    pw, ns = scene.pw, scene.ns
    try:
        exec(case.setup, ns)
        before = state_dump(pw.world)
        shape = structure(pw)
        counts = space_counts(pw.sim)
        try:
            exec(case.call, ns)
        except Exception as exc:  # checked below
            err: BaseException = exc
        else:
            raise AssertionError(f"{case.name}: {case.call} raised nothing")
        assert type(err) is case.error, f"{case.name}: got {type(err).__name__}: {err}"
        assert re.search(case.names, str(err)), f"{case.name}: message {str(err)!r}"
        pw.physics.remove_hook(ns["spawn_in_hook"])
        pw.physics.remove_hook(ns["despawn_in_hook"])
        pw.physics.remove_hook(ns["nan_friction"])
        pw.physics.remove_hook(ns["close_in_hook"])
        pw.physics.remove_hook(ns["text_enabled"])
        pw.physics.contact_filter = None
        if case.in_step:
            assert structure(pw) == shape, f"{case.name}: entities/components changed"
        else:
            assert state_dump(pw.world) == before, f"{case.name}: the world changed"
            assert space_counts(pw.sim) == counts, f"{case.name}: pymunk objects changed"
        pw.step(2 if not case.in_step else 1)
        later = (structure(pw), space_counts(pw.sim))
        assert later == _control(case), f"{case.name}: the next steps differ from a clean run"
        return err
    finally:
        pw.close()


def render_table() -> str:
    """The markdown table of every case, with the message each one gets now."""
    lines = [
        "| # | case | call | error | message |",
        "|---|---|---|---|---|",
    ]
    for i, case in enumerate(CASES, 1):
        err = run_case(case)
        msg = str(err).splitlines()[0]
        call = case.call if not case.setup else f"{case.setup}; {case.call}"
        lines.append(
            f"| {i} | {case.name} | `{cell(call)}` | `{type(err).__name__}` | {cell(msg)} |"
        )
    return "\n".join(lines) + "\n"


def doc_section() -> str:
    return SECTION.read()


if __name__ == "__main__":
    main(SECTION, render_table)
