"""Render fixtures for the debug tools' pixel tests."""

from ..render.conftest import make_app

__all__ = ["make_app"]
