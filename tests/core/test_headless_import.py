"""``import kge`` must stay headless: no pyglet GL, window or media modules."""

import subprocess
import sys


def test_import_kge_loads_no_pyglet_gl_window_or_media() -> None:
    code = (
        "import sys, kge, kge.components, kge.systems.behaviour\n"
        "try:\n    import kge.systems.physics\nexcept ImportError:\n    pass\n"
        "bad = sorted(m for m in sys.modules if m.split('.')[:2] in "
        "(['pyglet','gl'], ['pyglet','window'], ['pyglet','media']))\n"
        "print(','.join(bad))\n"
    )
    env = {"PATH": "/usr/bin:/bin"}  # no PYGLET_HEADLESS: a bare import must not need it
    out = subprocess.run(
        [sys.executable, "-c", code], capture_output=True, text=True, env=env, check=True
    )
    assert out.stdout.strip() == ""
