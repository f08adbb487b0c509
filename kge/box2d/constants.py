"""Box2D 2.3's constants as pybox2d exposes them (``b2_pi``, body types, point states...).

Tolerances are the engine's own: kge's physics settings use the same values
(``PhysicsSettings.collision_slop`` is b2_linearSlop, ``polygon_radius`` is
b2_polygonRadius, ``time_to_sleep`` is b2_timeToSleep).
"""

from __future__ import annotations

import math

b2_pi = math.pi
b2_epsilon = 1.1920928955078125e-07
b2_maxFloat = 3.4028234663852886e38
b2_maxManifoldPoints = 2
b2_maxPolygonVertices = 16
b2_aabbExtension = 0.1
b2_aabbMultiplier = 2.0
b2_linearSlop = 0.005
b2_angularSlop = 2.0 / 180.0 * b2_pi
b2_polygonRadius = 2.0 * b2_linearSlop
b2_maxSubSteps = 8
b2_maxTOIContacts = 32
b2_velocityThreshold = 1.0
b2_maxLinearCorrection = 0.2
b2_maxAngularCorrection = 8.0 / 180.0 * b2_pi
b2_maxTranslation = 2.0
b2_maxTranslationSquared = b2_maxTranslation * b2_maxTranslation
b2_maxRotation = 0.5 * b2_pi
b2_maxRotationSquared = b2_maxRotation * b2_maxRotation
b2_baumgarte = 0.2
b2_toiBaugarte = 0.75
b2_timeToSleep = 0.5
b2_linearSleepTolerance = 0.01
b2_angularSleepTolerance = 2.0 / 180.0 * b2_pi

# body types (b2BodyType)
b2_staticBody = 0
b2_kinematicBody = 1
b2_dynamicBody = 2

# point states (b2GetPointStates)
b2_nullState = 0
b2_addState = 1
b2_persistState = 2
b2_removeState = 3

# joint types (b2JointType)
e_unknownJoint = 0
e_revoluteJoint = 1
e_prismaticJoint = 2
e_distanceJoint = 3
e_pulleyJoint = 4
e_mouseJoint = 5
e_gearJoint = 6
e_wheelJoint = 7
e_weldJoint = 8
e_frictionJoint = 9
e_ropeJoint = 10
e_motorJoint = 11

b2_version = (2, 3, 1)
b2_version_string = "2.3.1 (kge.box2d)"

# b2Globals' statistics of Box2D's time of impact (the most iterations one call needed):
# pybox2d exposes them; kge's time of impact does not count its iterations, so they stay 0
b2_toiMaxIters = 0
b2_toiMaxRootIters = 0
