"""kge.collision: Box2D's collision module on kge shapes, no World needed."""

from kge.collision.collide import collide
from kge.collision.distance import DistanceOutput, SimplexCache, distance
from kge.collision.geometry import POLYGON_RADIUS, child_count
from kge.collision.manifold import ContactId, Manifold, ManifoldPoint
from kge.collision.pose import Pose
from kge.collision.shape_queries import AABB, RayCastOutput, aabb, mass_data, ray_cast, test_point
from kge.collision.toi import Sweep, TOIOutput, time_of_impact

__all__ = [
    "AABB",
    "POLYGON_RADIUS",
    "ContactId",
    "DistanceOutput",
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
    "ray_cast",
    "test_point",
    "time_of_impact",
]
