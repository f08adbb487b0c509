"""Continuous collision for pymunk: Box2D's speed caps and time-of-impact sweeps.

pymunk moves every body by ``v*dt`` and only then looks for overlaps, so a
body that travels further than its own thickness in one step can jump clean
over a thin wall (tunnelling). Box2D 2.3 prevents that with two rules, which
this module reproduces:

* **speed caps**: a body moves at most ``max_translation`` (2 m) and rotates at
  most ``max_rotation`` (pi/2) per fixed step, and the *clamped velocity is
  kept* (120 m/s and 94.25 rad/s at 60 Hz);
* **time of impact**: a dynamic body never passes through static or kinematic
  geometry, and a ``bullet`` body never passes through dynamic bodies either.
  Ordinary dynamic bodies may tunnel through each other, as in Box2D (that is
  what the bullet flag is for).

How: :class:`ContinuousCollision` reads every body's pose and velocity once
per step with ``pymunk.batch`` (about 0.5 ms for 20,000 bodies), clamps the few
that exceed the caps, and *arms* a swept integrator - a pymunk
``position_func`` - only on tracked dynamic bodies that move more than
``threshold`` times their core radius per substep *and* have something they
could hit within reach, on the neighbours such a body could launch, and on
bodies a fast kinematic body is about to sweep over. All other bodies keep
pymunk's C integrator, so a scene of slow bodies pays nothing but the read.
"Within reach" is answered by a numpy index of the static and kinematic
shapes (the only ones that stop a non-bullet), which screens all fast bodies
in one vectorised pass: a swinging chain far from any wall costs no shape
walk at all, and a bullet in open air a couple of box queries per step. The
rows that pass hold everything the body and the neighbours it could launch
can reach, so their later questions ("anything within my reach?") are a few
Python comparisons on those rows, not another pass over the table; a table
of thousands of rows (a tile map) is searched by a window of rows sorted by
left edge instead of a full pass (:mod:`kge.physics.ccd.sorted_boxes`).

An armed body, at each substep whose motion is still fast, is capped again
(collisions inside a step can exceed the caps) and sweeps its shapes along
the motion against the candidate shapes in its swept bounding box: circles as
swept circles, polygons as their vertices plus an inscribed circle, all
shrunk by ``margin`` so that surfaces it already rests on are never "hit";
a spinning body's points follow their arcs as short chords. At the earliest
impact it stops (its shapes then overlap by about ``margin``) and keeps its
velocity; pymunk's contact solver, which runs right after in the same
substep, resolves the contact (bounce, friction, events) as for any other.
A small *guard* circle deep inside each shape catches the rare body that the
solver fails to stop at a contact the world accepted (crushed by others, or
spinning into a wall): it is held for that substep and its approach removed.

The sweep honours everything that decides whether two colliders touch: same
body, sensors, Box2D filtering and one-way platforms (read from the space's
:class:`~kge.physics.shape_table.ShapeTable`), joints without
``collide_bodies``, an optional ``pair_filter`` (the world's contact filter)
and, for the guard, the contacts pymunk actually accepted in the last substep
(pre-solve hooks). Moving
obstacles (kinematic bodies, and dynamic ones for bullets) are swept against
in their own frame; a kinematic one carries what it hits along for the rest
of the substep (never through static geometry), so a fast paddle pushes a
ball instead of passing over it.

>>> import math, pymunk
>>> space = pymunk.Space()
>>> wall = pymunk.Poly(space.static_body, [(5, -2), (5.1, -2), (5.1, 2), (5, 2)], radius=0.01)
>>> ball = pymunk.Body()
>>> shot = pymunk.Circle(ball, 0.05)
>>> shot.density = 1.0
>>> space.add(wall, ball, shot)
>>> ball.velocity = (500.0, 0.0)
>>> ccd = ContinuousCollision(space)
>>> ccd.track(ball)
>>> for _ in range(5):
...     armed = ccd.before_step(1 / 60)
...     space.step(1 / 60)
...     ccd.after_step(1 / 60)
>>> round(ball.velocity.x, 6) <= 120.0, ball.position.x < 5.0
(True, True)
"""

from kge.physics.ccd.manager import ContinuousCollision, PairFilter

__all__ = ["ContinuousCollision", "PairFilter"]
