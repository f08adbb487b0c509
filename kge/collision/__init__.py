"""kge.collision: Box2D's collision module on kge shapes, with no World.

The pybox2d manual says shapes "may be used independently of physics"; this
package is that part of Box2D 2.3 on kge's own shapes
(:class:`~kge.components.shapes.Circle`, ``Box``, ``Polygon``, ``Edge`` and the
segments of a ``Chain``). Every function takes a shape in its body-local
coordinates plus a *pose* ``(x, y, angle)`` (or a :class:`Pose` or a
``Transform``), so one frozen shape serves any number of places:

* is a point inside? :func:`test_point` (``b2Shape::TestPoint``)
* where does a ray hit? :func:`ray_cast` -> :class:`RayCastOutput` (``RayCast``)
* its bounding box: :func:`aabb` -> :class:`AABB` (``ComputeAABB``)
* mass, inertia, centre: :func:`mass_data` (``ComputeMass``)
* closest points: :func:`distance` -> :class:`DistanceOutput` (``b2Distance``, GJK);
  do they touch at all: :func:`overlap` (``b2TestOverlap``)
* first contact of two motions: :func:`time_of_impact` with :class:`Sweep`
  (``b2TimeOfImpact``)
* how two shapes touch: :func:`collide` -> :class:`Manifold` (``b2Collide*`` and
  ``b2WorldManifold``); which points are new, kept or gone: :func:`point_states`
  (``b2GetPointStates``)
* many boxes at once: :class:`DynamicTree` (``b2DynamicTree``)

Each module explains its algorithm; ``docs/collision.md`` has the guide, the
tolerances against measured pybox2d answers and the few places kge differs.

>>> import math
>>> from kge.components.shapes import Box, Circle
>>> from kge import collision
>>> collision.test_point(Box(1.0, 0.5), (0.0, 0.0, math.pi / 2), (0.0, 0.9))
True
>>> round(collision.distance(Circle(0.5), (0, 0, 0), Circle(0.5), (3, 0, 0)).distance, 6)
2.0
"""

from kge.collision.collide import collide
from kge.collision.distance import DistanceOutput, SimplexCache, distance, overlap
from kge.collision.geometry import POLYGON_RADIUS, child_count
from kge.collision.manifold import ContactId, Manifold, ManifoldPoint, point_states
from kge.collision.pose import Pose
from kge.collision.shape_queries import AABB, RayCastOutput, aabb, mass_data, ray_cast, test_point
from kge.collision.toi import Sweep, TOIOutput, time_of_impact
from kge.collision.tree import AABB_EXTENSION, AABB_MULTIPLIER, DynamicTree

__all__ = [
    "AABB",
    "AABB_EXTENSION",
    "AABB_MULTIPLIER",
    "POLYGON_RADIUS",
    "ContactId",
    "DistanceOutput",
    "DynamicTree",
    "Manifold",
    "ManifoldPoint",
    "Pose",
    "RayCastOutput",
    "SimplexCache",
    "Sweep",
    "TOIOutput",
    "aabb",
    "child_count",
    "collide",
    "distance",
    "mass_data",
    "overlap",
    "point_states",
    "ray_cast",
    "test_point",
    "time_of_impact",
]
