"""Box2D collision filtering on top of pymunk's ShapeFilter.

pymunk rejects a pair when the shapes share a non-zero group or the category
and mask bits do not match, and it cannot *force* a collision. Box2D's rule is
different only for positive groups (same positive group: always collide), so:

* negative Box2D group ``g`` -> pymunk group ``-g`` (same negative group: never);
* group 0 -> categories and mask passed through;
* positive group -> the shape accepts everything in pymunk, and the exact Box2D
  rule runs once per new pair in the ``begin`` handler (:func:`should_collide`).

Verified against real Box2D 2.3.10 on 750 random pairs in pymunk-notes.md.

>>> to_pymunk(Filter(category_bits=2, mask_bits=5, group_index=-4))
ShapeFilter(group=4, categories=2, mask=5)
>>> to_pymunk(Filter(group_index=7)).mask == ALL
True
"""

from __future__ import annotations

from functools import lru_cache

import pymunk

from kge.components.filter import Filter

ALL = 0xFFFFFFFF


#: the filter a new pymunk shape has
DEFAULT_FILTER = pymunk.ShapeFilter()


@lru_cache(maxsize=256)
def to_pymunk(f: Filter) -> pymunk.ShapeFilter:
    """The pymunk filter that pre-screens pairs for Box2D filter ``f``.

    Cached: a game has a handful of distinct filters and spawns thousands of
    colliders with them (Filter and ShapeFilter are immutable).
    """
    if f.group_index > 0:
        return pymunk.ShapeFilter(group=0, categories=ALL, mask=ALL)
    group = -f.group_index if f.group_index < 0 else 0
    return pymunk.ShapeFilter(group=group, categories=f.category_bits, mask=f.mask_bits)


def needs_exact_check(a: Filter, b: Filter) -> bool:
    """True when pymunk's pre-screen may have let through a pair Box2D rejects."""
    return a.group_index > 0 or b.group_index > 0


def should_collide(a: Filter, b: Filter) -> bool:
    """Box2D's b2ContactFilter::ShouldCollide."""
    return a.collides_with(b)


def query_filter(f: Filter | None) -> pymunk.ShapeFilter:
    """A pymunk filter for space queries: ``f``'s mask against shape categories.

    Queries have no group of their own in kge unless ``f`` has a negative one.
    """
    if f is None:
        return pymunk.ShapeFilter()
    return pymunk.ShapeFilter(
        group=-f.group_index if f.group_index < 0 else 0,
        categories=f.category_bits,
        mask=f.mask_bits,
    )
