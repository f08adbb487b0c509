"""pymunk adapter internals (bodies, shapes, filters, joints, events, queries, CCD).

Imported by :mod:`kge.systems.physics`; user code uses the components and the
``Physics`` resource instead.
"""
