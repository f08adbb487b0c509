"""``FileWatcher``: the files a running game depends on, watched by ``watchfiles``.

``watchfiles`` (the OS's own change notifications through Rust's ``notify``; no
polling by hand) runs in a daemon thread over the folders of the watched files.
Changes are collected until the game's next frame takes them with :meth:`drain`,
so reloading always happens on the main thread, between frames. Tests wait for
the watcher's event itself (:meth:`wait_ready`, :meth:`wait_for`), never a sleep.
"""

from __future__ import annotations

import os
import threading
from collections.abc import Iterable
from pathlib import Path


class FileWatcher:
    """Watches files (by their folders) and collects the ones that changed."""

    def __init__(self, debounce_ms: int = 30) -> None:
        self.debounce_ms = debounce_ms
        self._files: set[Path] = set()
        self._dirs: set[Path] = set()
        #: folders whose files of these suffixes count, at any depth (asset folders)
        self._trees: dict[Path, tuple[str, ...]] = {}
        self._changed: set[Path] = set()
        self._cond = threading.Condition()
        self._stop: threading.Event | None = None
        self._thread: threading.Thread | None = None
        self._ready = False
        self.error: BaseException | None = None  #: what stopped the thread, if anything

    @property
    def files(self) -> frozenset[Path]:
        return frozenset(self._files)

    def watch(self, paths: Iterable[str | os.PathLike[str]]) -> None:
        """Watch these files too (the watcher restarts when a new folder joins)."""
        new_dirs = False
        with self._cond:
            for p in paths:
                real = Path(os.path.realpath(p))
                self._files.add(real)
                if real.parent not in self._dirs and real.parent.is_dir():
                    self._dirs.add(real.parent)
                    new_dirs = True
        if new_dirs:
            self._restart()

    def watch_trees(self, roots: Iterable[str | os.PathLike[str]], suffixes: tuple[str, ...]
                    ) -> None:
        """Watch every file with one of ``suffixes`` anywhere under ``roots``."""
        new = False
        with self._cond:
            for r in roots:
                real = Path(os.path.realpath(r))
                if real.is_dir() and self._trees.get(real) != suffixes:
                    self._trees[real] = suffixes
                    new = True
        if new:
            self._restart()

    def _counts(self, real: Path) -> bool:
        if real in self._files:
            return True
        suffix = real.suffix.lower()
        return any(suffix in sufs and real.is_relative_to(root)
                   for root, sufs in self._trees.items())

    def _restart(self) -> None:
        self.stop()
        stop = threading.Event()
        self._stop = stop
        self._ready = False
        dirs = sorted(self._dirs - {d for d in self._dirs for t in self._trees
                                     if d.is_relative_to(t)})
        self._thread = threading.Thread(
            target=self._run, args=(dirs, stop), name="kge-hot-reload", daemon=True
        )
        self._thread.start()

    def _run(self, dirs: list[Path], stop: threading.Event) -> None:
        import watchfiles

        trees = sorted(self._trees)
        try:
            for changes in watchfiles.watch(
                *dirs, *trees, stop_event=stop, debounce=self.debounce_ms, step=10,
                rust_timeout=200, yield_on_timeout=True, recursive=True, raise_interrupt=False,
            ):
                with self._cond:
                    self._ready = True  # the first yield: the OS watches are in place
                    for _, raw in changes:
                        real = Path(os.path.realpath(raw))
                        if self._counts(real):
                            self._changed.add(real)
                    self._cond.notify_all()
        except BaseException as exc:  # a folder removed under the watcher, say
            with self._cond:
                self.error = exc
                self._cond.notify_all()

    def drain(self) -> set[Path]:
        """The files changed since the last drain."""
        with self._cond:
            out, self._changed = self._changed, set()
        return out

    def pending(self) -> bool:
        with self._cond:
            return bool(self._changed)

    def wait_ready(self, timeout: float = 10.0) -> bool:
        """Block until the OS watches are in place (tests, before writing a file)."""
        with self._cond:
            return self._cond.wait_for(lambda: self._ready or self.error is not None, timeout)

    def wait_for(self, path: str | os.PathLike[str], timeout: float = 10.0) -> bool:
        """Block until a change of ``path`` has been seen (tests)."""
        real = Path(os.path.realpath(path))
        with self._cond:
            return self._cond.wait_for(lambda: real in self._changed or self.error is not None,
                                       timeout)

    def stop(self) -> None:
        """Stop the thread (the App's cleanup calls this)."""
        if self._stop is not None:
            self._stop.set()
        if self._thread is not None:
            self._thread.join(timeout=5.0)
        self._thread = None
        self._stop = None
