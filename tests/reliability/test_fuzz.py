"""CI run of the random-operation state machine (``KGE_FUZZ=long`` for the long run)."""

from __future__ import annotations

from hypothesis import settings

from .fuzz import PROFILE, PhysicsMachine

PhysicsMachine.TestCase.settings = settings.get_profile(PROFILE)
TestPhysicsMachine = PhysicsMachine.TestCase
