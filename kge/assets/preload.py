"""Preloading lists of assets: a few per frame (:class:`Preload`), or decoded on
background threads and finished on the main thread (:class:`BackgroundPreload`).

``Assets.preload(names, background=True)`` returns a :class:`BackgroundPreload`.
Worker threads read the files and decode them at once (Pillow for images, soundfile
for sounds, plain reads for fonts, tile maps and other files: the slow parts, which
release the GIL); :meth:`BackgroundPreload.step`, called each frame on the main
thread, turns the decoded assets into pyglet objects in the order given and caches
them, within its time budget, never waiting for a worker. GL textures are still made
on the main thread, at an image's first draw.

``progress`` (0..1) counts assets finished on the main thread, ``decoded`` those the
workers are done with. Failures are collected in ``failed`` as with
:class:`Preload`, and :meth:`finish` raises one error naming them.

>>> import tempfile, pathlib
>>> from kge.assets.store import Assets
>>> root = pathlib.Path(tempfile.mkdtemp())
>>> _ = (root / "level.txt").write_bytes(b"1 2 3")
>>> job = Assets(root, anchor=root).preload(["level.txt", "missing.txt"], background=True)
>>> job.wait()                  # a test waits for the workers; a game keeps drawing
>>> job.step(budget=float("inf")), job.progress, job.result("level.txt"), sorted(job.failed)
(2, 1.0, b'1 2 3', ['missing.txt'])
"""

from __future__ import annotations

import os
import time
from collections.abc import Iterable
from concurrent.futures import Future, ThreadPoolExecutor, wait
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

from kge.assets import loaders
from kge.assets.errors import AssetDecodeError, AssetError
from kge.assets.locate import Found, normalize_name
from kge.errors import ValidationError

if TYPE_CHECKING:
    from kge.assets.store import Assets

#: worker threads per background preload (decoders release the GIL while they work)
WORKERS = 2


@dataclass(frozen=True, slots=True)
class AssetsLoaded:
    """A preload finished (the loading screen emits it into its world): how many assets
    were queued and loaded, and the names that failed."""

    queued: int
    loaded: int
    failed: tuple[str, ...] = ()


@dataclass(frozen=True, slots=True)
class Decoded:
    """An asset decoded by :func:`decode` (on any thread), for :meth:`Assets.adopt`."""

    found: Found
    kind: str  #: "image", "sound", "font" or "bytes"
    value: Any


def decode(store: Assets, name: str | os.PathLike[str]) -> Decoded:
    """Find and decode ``name`` without touching pyglet: Pillow for images, soundfile for
    sounds, a file read for fonts and other files (tile maps, levels). Worker threads call
    it; :meth:`Assets.adopt` finishes the job on the main thread."""
    found = store.resolve(name)
    suffix = found.suffix
    if suffix in loaders.IMAGE_SUFFIXES:
        return Decoded(found, "image", loaders.decode_image(found))
    try:
        data = found.read_bytes()
    except OSError as exc:
        raise AssetDecodeError(found.name, found.where, f"unreadable: {exc}") from exc
    if suffix in loaders.SOUND_SUFFIXES:
        from kge.assets.sounds import decode as decode_sound

        return Decoded(found, "sound", decode_sound(data, found.name, found.where))
    return Decoded(found, "font" if suffix in loaders.FONT_SUFFIXES else "bytes", data)


class Preload:
    """Loads a list of assets in small slices so a loading screen can draw between them.

    ``step()`` loads until its time budget is spent; ``loaded`` and ``queued``
    (and ``progress`` in 0..1) drive a progress bar. Failures do not stop the
    rest: they are collected in ``failed``, and :meth:`finish` raises one
    :class:`AssetError` listing them all.

    >>> import tempfile, pathlib
    >>> from kge.assets.store import Assets
    >>> root = pathlib.Path(tempfile.mkdtemp())
    >>> _ = (root / "level.txt").write_bytes(b"1 2 3")
    >>> job = Assets(root, anchor=root).preload(["level.txt", "missing.txt"])
    >>> job.step(max_items=1), job.loaded, job.queued, job.done
    (1, 1, 2, False)
    >>> job.step(), job.progress, sorted(job.failed)
    (1, 1.0, ['missing.txt'])
    """

    def __init__(self, store: Assets, names: Iterable[str | os.PathLike[str]]) -> None:
        self.store = store
        self._pending = [normalize_name(n) for n in names]
        self._pending.reverse()  # pop() from the end keeps the given order
        self.queued = len(self._pending)
        self.loaded = 0
        self.failed: dict[str, AssetError] = {}

    @property
    def done(self) -> bool:
        return not self._pending

    @property
    def progress(self) -> float:
        """Fraction of the queue processed (loaded or failed), 1.0 when empty."""
        if self.queued == 0:
            return 1.0
        return (self.loaded + len(self.failed)) / self.queued

    def step(self, budget: float = 1.0 / 120.0, max_items: int | None = None) -> int:
        """Load queued assets for about ``budget`` seconds (at least one); return the count."""
        start = time.perf_counter()
        count = 0
        while not self.done:
            if max_items is not None and count >= max_items:
                break
            if count and time.perf_counter() - start >= budget:
                break
            name = self._ready()
            if name is None:
                break
            try:
                self._load(name)
            except AssetError as exc:
                self.failed[name] = exc
            else:
                self.loaded += 1
            count += 1
        return count

    def event(self) -> AssetsLoaded:
        """This preload's :class:`AssetsLoaded` event (what it loaded and what failed)."""
        return AssetsLoaded(self.queued, self.loaded, tuple(self.failed))

    def _ready(self) -> str | None:
        """The next name to load now (None: none is ready yet)."""
        return self._pending.pop()

    def _load(self, name: str) -> None:
        self.store.load(name)

    def finish(self) -> None:
        """Load everything left; raise one error naming every asset that failed."""
        while not self.done:
            self.step(budget=float("inf"))
        if self.failed:
            details = "\n".join(f"* {exc}" for exc in self.failed.values())
            raise AssetError(f"{len(self.failed)} of {self.queued} assets failed:\n{details}")


class BackgroundPreload(Preload):
    """A :class:`~kge.assets.store.Preload` whose decoding runs on worker threads."""

    def __init__(
        self, store: Assets, names: Iterable[str | os.PathLike[str]], workers: int = WORKERS
    ) -> None:
        super().__init__(store, names)
        if isinstance(workers, bool) or not isinstance(workers, int) or workers < 1:
            raise ValidationError(
                f"BackgroundPreload: workers must be an int >= 1, got {workers!r}"
            )
        order = list(reversed(self._pending))
        self._pending.clear()
        self._results: dict[str, Any] = {}
        pool = ThreadPoolExecutor(max_workers=workers, thread_name_prefix="kge-assets")
        self._jobs: list[tuple[str, Future[Decoded]]] = [
            (name, pool.submit(decode, store, name)) for name in order
        ]
        pool.shutdown(wait=False)  # the queued decodes still run; the threads then end
        self._next = 0

    @property
    def done(self) -> bool:
        return self._next >= len(self._jobs)

    @property
    def decoded(self) -> int:
        """How many assets the workers have finished decoding (or failed on)."""
        return sum(1 for _, job in self._jobs if job.done())

    def wait(self, timeout: float | None = None) -> None:
        """Block until every decode is done (tests; or a game with nothing to draw)."""
        wait([job for _, job in self._jobs], timeout=timeout)

    def result(self, name: str | os.PathLike[str]) -> Any:
        """What loading ``name`` gave (an image, sound, font, or a file's bytes)."""
        key = normalize_name(name)
        if key not in self._results:
            state = "failed" if key in self.failed else "is not loaded yet"
            raise ValidationError(f"BackgroundPreload.result: {key!r} {state}")
        return self._results[key]

    def _ready(self) -> str | None:
        name, job = self._jobs[self._next]
        if not job.done():
            return None  # never wait for a worker inside a frame
        self._next += 1
        return name

    def _load(self, name: str) -> None:
        decoded = self._jobs[self._next - 1][1].result()  # re-raises the worker's error
        self._results[name] = self.store.adopt(decoded)

    def finish(self) -> None:
        self.wait()
        super().finish()
