"""Headless EGL fixtures shared with the render tests (same pooled window size)."""

from __future__ import annotations

from tests.render.conftest import BG, SIZE, bbox, make_app, mask, pixels

__all__ = ["BG", "SIZE", "bbox", "make_app", "mask", "pixels"]
