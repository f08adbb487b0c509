"""Collision filtering data, exactly as Box2D's ``b2Filter``.

Two colliders collide when

* they share a non-zero ``group_index``: iff that group is positive;
* otherwise: iff ``(a.category_bits & b.mask_bits) and (b.category_bits & a.mask_bits)``.

Box2D uses 16 bits; kge accepts up to 32. A Filter is frozen: assign a new one
to ``collider.filter`` to refilter (it takes effect at the next step, ends the
contacts it forbids and wakes the body, like assigning ``fixture.filterData``).

>>> Filter(category_bits=0x2, mask_bits=0x1).collides_with(Filter())
True
>>> Filter(group_index=-3).collides_with(Filter(group_index=-3))
False
"""

from __future__ import annotations

from dataclasses import dataclass

from kge.errors import ValidationError
from kge.validate import integer

MAX_BITS = 0xFFFFFFFF


@dataclass(slots=True, frozen=True)
class Filter:
    """Category, mask and group of a collider (Box2D defaults)."""

    category_bits: int = 0x0001
    mask_bits: int = 0xFFFF
    group_index: int = 0

    def __post_init__(self) -> None:
        c, m, g = self.category_bits, self.mask_bits, self.group_index
        if (
            type(c) is int and type(m) is int and type(g) is int
            and 0 <= c <= MAX_BITS and 0 <= m <= MAX_BITS and -(2**31) <= g < 2**31
        ):
            return  # the common case: plain ints in range, nothing to convert
        for name in ("category_bits", "mask_bits"):
            v = integer(getattr(self, name), "Filter", name)
            if not 0 <= v <= MAX_BITS:
                raise ValidationError(f"Filter.{name} must be in [0, 0xFFFFFFFF], got {v!r}")
            object.__setattr__(self, name, v)
        g = integer(self.group_index, "Filter", "group_index")
        if not -(2**31) <= g < 2**31:
            raise ValidationError(f"Filter.group_index must fit in 32 bits, got {g!r}")
        object.__setattr__(self, "group_index", g)

    def collides_with(self, other: Filter) -> bool:
        """Box2D's b2ContactFilter::ShouldCollide rule for two filters."""
        if self.group_index == other.group_index and self.group_index != 0:
            return self.group_index > 0
        return bool(self.category_bits & other.mask_bits) and bool(
            other.category_bits & self.mask_bits
        )
