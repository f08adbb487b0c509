"""pybox2d's testbed on kge.box2d: its examples (and tests of your own) run unmodified.

pybox2d's testbed examples subclass ``Framework`` from ``Box2D.examples.framework``.
This package is kge's stand-in for that framework and its backends:

* :mod:`~kge.box2d.testbed.framework`: ``Framework``, ``Keys``, ``main`` (kge's code,
  pybox2d's contract);
* :mod:`~kge.box2d.testbed.window`: a kge window (keys, mouse, text), or off screen;
* :mod:`~kge.box2d.testbed.headless`: fixed frames with scripted key presses
  (:mod:`~kge.box2d.testbed.presses`);
* :mod:`~kge.box2d.testbed.examples`: finds the examples in the installed pybox2d wheel
  and runs one with ``Box2D`` = kge.box2d (or the real pybox2d, to compare);
* ``python -m kge.box2d.testbed NAME``: the command line (see ``--help``).
"""
