"""One registry of sample scenes, shared by the testbed, the tests and the benchmarks.

A sample is a setup function registered once with a category and a name::

    @sample("Stacking", "Pyramid", help="A 10-row pyramid of boxes that must stand.")
    def pyramid(world: World, rows: int = 10) -> None:
        ...

The testbed lists samples by category, the test suite runs every one of them
headless (and asserts the physical claim a sample declares with ``@s.claim``),
and the benchmarks build the same geometry at larger sizes through the keyword
arguments. Keeping one definition is what stops the three from drifting apart.

The registry knows no sample by name: the sample modules fill it when they are
imported, and importing :mod:`kge.testbed` imports them all (``kge.testbed.samples``).
A game can register its own samples the same way.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

from kge.world import World

Setup = Callable[..., None]
Claim = Callable[[Any], None]  # receives the App after the sample has run


@dataclass(slots=True)
class Sample:
    """A registered sample scene."""

    category: str
    name: str
    setup: Setup
    help: str = ""
    keys: dict[str, str] = field(default_factory=dict)
    #: centre x, y and zoom; None: the testbed fits the camera to what the sample built
    camera: tuple[float, float, float] | None = None
    claims: list[Claim] = field(default_factory=list)
    #: the Name of an entity the testbed camera follows (a car, a walker)
    follow: str | None = None

    @property
    def slug(self) -> str:
        """The command-line name: lower case, words joined by dashes."""
        return self.name.lower().replace(" ", "-").replace("/", "-")

    def claim(self, check: Claim) -> Claim:
        """Register a check of the sample's physical claim (used by the tests)."""
        self.claims.append(check)
        return check

    def __call__(self, world: World, **kwargs: Any) -> None:
        self.setup(world, **kwargs)


_SAMPLES: dict[str, Sample] = {}


def sample(
    category: str,
    name: str,
    *,
    help: str = "",
    keys: dict[str, str] | None = None,
    camera: tuple[float, float, float] | None = None,
    follow: str | None = None,
) -> Callable[[Setup], Sample]:
    """Decorator registering ``setup`` as a sample; returns the :class:`Sample`."""

    def register(setup: Setup) -> Sample:
        s = Sample(category, name, setup, help, dict(keys or {}), camera, follow=follow)
        old = _SAMPLES.get(s.slug)
        # The same function registered again (its module run with ``python -m`` after
        # the package imported it) replaces itself; two different samples may not
        # share a name.
        if old is not None and old.setup.__qualname__ != setup.__qualname__:
            raise ValueError(f"two samples are named {name!r}")
        _SAMPLES[s.slug] = s
        return s

    return register


def all_samples() -> list[Sample]:
    """Every registered sample, ordered by category then name."""
    return sorted(_SAMPLES.values(), key=lambda s: (s.category, s.name))


def get_sample(name: str) -> Sample:
    """A registered sample by slug or by name (case-insensitive)."""
    key = name.lower().replace(" ", "-")
    if key in _SAMPLES:
        return _SAMPLES[key]
    known = ", ".join(sorted(_SAMPLES))
    raise KeyError(f"no sample named {name!r}; known samples: {known}")
