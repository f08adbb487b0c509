"""A virtual X display for the real-window tests (Xvfb), typed into by xdotool.

Needs the Debian packages xvfb and xdotool (``tools/bootstrap.sh`` installs them); a
test using these helpers installs nothing and fails, naming them, when they are absent.
"""

from __future__ import annotations

import os
import shutil
import subprocess
from collections.abc import Iterator
from contextlib import contextmanager

import pytest


def need(tool: str) -> str:
    """The path of ``tool``, or a test failure saying how to install it."""
    path = shutil.which(tool)
    if path is None:
        pytest.fail(
            f"{tool} is not installed: run tools/bootstrap.sh (Debian packages xvfb, xdotool)"
        )
    return path


def xdo(display: str, *args: str) -> str:
    """Run xdotool on ``display``; its output, stripped."""
    out = subprocess.run([need("xdotool"), *args], env={**os.environ, "DISPLAY": display},
                         capture_output=True, text=True, timeout=30, check=True)  # fmt: skip
    return out.stdout.strip()


@contextmanager
def virtual_display(screen: str = "800x600x24") -> Iterator[tuple[str, dict[str, str]]]:
    """Start Xvfb on a free display; yield it and an environment for a windowed child
    (no headless switches, the silent audio driver). The server stops on exit."""
    xvfb = need("Xvfb")
    need("xdotool")
    read, write = os.pipe()
    server = subprocess.Popen(
        [xvfb, "-displayfd", str(write), "-screen", "0", screen, "-nolisten", "tcp"],
        pass_fds=(write,), stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
    )  # fmt: skip
    os.close(write)
    try:
        number = b""
        while not number.endswith(b"\n"):
            chunk = os.read(read, 16)
            assert chunk, "Xvfb exited before reporting its display"
            number += chunk
        display = f":{number.decode().strip()}"
        env = {k: v for k, v in os.environ.items() if k not in ("PYGLET_HEADLESS", "KGE_HEADLESS")}
        env.update(DISPLAY=display, PYGLET_AUDIO="silent")
        yield display, env
    finally:
        server.terminate()
        server.wait(timeout=10)
        os.close(read)
