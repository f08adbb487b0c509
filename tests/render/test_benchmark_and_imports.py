"""The render benchmark runs at a small size; the core never imports pyglet's GL side."""

from __future__ import annotations

import subprocess
import sys

from benchmarks.render_sync import VARIANTS, measure


def test_render_sync_benchmark_reports_every_variant():
    result = measure(50, repeats=2)
    assert set(result) == set(VARIANTS)
    assert all(v > 0 for v in result.values())  # reported, never asserted against a target


def test_render_components_and_systems_stay_headless():
    code = (
        "import sys, kge\n"
        "import kge.components.sprite, kge.components.drawables, kge.components.text\n"
        "import kge.components.camera, kge.components.debug, kge.systems.render\n"
        "import kge.render.images, kge.render.geometry, kge.render.poses, kge.render.projection\n"
        "bad = [m for m in ('pyglet.gl', 'pyglet.window', 'pyglet.media') if m in sys.modules]\n"
        "print(bad)\n"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == "[]"


def test_docs_screenshot_script_still_runs(tmp_path):
    import importlib.util
    from pathlib import Path

    script = Path(__file__).resolve().parents[2] / "docs" / "rendering_screenshot.py"
    spec = importlib.util.spec_from_file_location("rendering_screenshot", script)
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    out = module.main(tmp_path / "shot.png")
    assert out.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
