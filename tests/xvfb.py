"""A virtual X display for the real-window tests (Xvfb), typed into by xdotool.

Needs the Debian packages xvfb and xdotool (``tools/bootstrap.sh`` installs them); a
test using these helpers installs nothing and fails, naming them, when they are absent.
"""

from __future__ import annotations

import ctypes
import ctypes.util
import json
import os
import selectors
import shutil
import subprocess
import time
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from typing import Any

import pytest

#: seconds to wait for any one report (a busy machine is slow, never wrong)
TIMEOUT = 60.0


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


class _ClientMessage(ctypes.Structure):
    """Xlib's XClientMessageEvent, padded to the size of an XEvent (24 longs)."""

    _fields_ = [
        ("type", ctypes.c_int), ("serial", ctypes.c_ulong), ("send_event", ctypes.c_int),
        ("display", ctypes.c_void_p), ("window", ctypes.c_ulong),
        ("message_type", ctypes.c_ulong), ("format", ctypes.c_int),
        ("data", ctypes.c_long * 5), ("pad", ctypes.c_long * 12),
    ]  # fmt: skip


def close_window(display: str, window: str) -> None:
    """What a window manager's close button sends: a WM_DELETE_WINDOW request to
    ``window`` (the client decides; xdotool's windowclose would destroy it instead)."""
    path = ctypes.util.find_library("X11")
    assert path, "libX11 is not installed"
    x11 = ctypes.CDLL(path)
    x11.XOpenDisplay.restype = ctypes.c_void_p
    x11.XOpenDisplay.argtypes = [ctypes.c_char_p]
    x11.XInternAtom.restype = ctypes.c_ulong
    x11.XInternAtom.argtypes = [ctypes.c_void_p, ctypes.c_char_p, ctypes.c_int]
    x11.XSendEvent.argtypes = [ctypes.c_void_p, ctypes.c_ulong, ctypes.c_int, ctypes.c_long,
                               ctypes.c_void_p]  # fmt: skip
    x11.XFlush.argtypes = x11.XCloseDisplay.argtypes = [ctypes.c_void_p]
    dpy = x11.XOpenDisplay(display.encode())
    assert dpy, f"cannot open the X display {display}"
    try:
        ev = _ClientMessage(type=33, send_event=1, display=dpy, window=int(window), format=32)
        ev.message_type = x11.XInternAtom(dpy, b"WM_PROTOCOLS", 0)
        ev.data[0] = x11.XInternAtom(dpy, b"WM_DELETE_WINDOW", 0)
        assert x11.XSendEvent(dpy, int(window), 0, 0, ctypes.byref(ev)), "XSendEvent failed"
        x11.XFlush(dpy)
    finally:
        x11.XCloseDisplay(dpy)


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


class Reports:
    """A windowed child's reports, one JSON object per line of its stdout, read as they
    come: a test waits for the report it expects before its next input (never a fixed
    sleep). Lines that are not JSON objects (the child's own output) are kept in
    ``text``."""

    def __init__(self, proc: subprocess.Popen[bytes]) -> None:
        assert proc.stdout is not None
        self.proc, self.stream = proc, proc.stdout
        self.sel = selectors.DefaultSelector()
        self.sel.register(self.stream, selectors.EVENT_READ)
        self.buf = b""
        self.seen: list[dict[str, Any]] = []
        self.text: list[str] = []

    def _take_lines(self, want: Callable[[dict[str, Any]], object]) -> dict[str, Any] | None:
        while b"\n" in self.buf:
            line, self.buf = self.buf.split(b"\n", 1)
            try:
                got = json.loads(line)
            except ValueError:
                got = None
            if not isinstance(got, dict):
                self.text.append(line.decode(errors="replace"))
                continue
            self.seen.append(got)
            if want(got):
                return got
        return None

    def wait(self, want: Callable[[dict[str, Any]], object], what: str) -> dict[str, Any]:
        """The first report (from now on) for which ``want`` is true."""
        deadline = time.monotonic() + TIMEOUT
        while True:
            got = self._take_lines(want)
            if got is not None:
                return got
            left = deadline - time.monotonic()
            if left <= 0 or (self.proc.poll() is not None and not self.sel.select(0)):
                raise AssertionError(f"the app never reported {what}; it said {self.seen}")
            if self.sel.select(timeout=left):
                chunk = os.read(self.stream.fileno(), 4096)
                if not chunk:
                    raise AssertionError(f"the app exited before {what}; it said {self.seen}")
                self.buf += chunk

    def rest(self) -> list[str]:
        """Read to the end of the child's output (call once it exits); the text lines."""
        self.buf += self.stream.read()
        self._take_lines(lambda _: False)
        return self.text
