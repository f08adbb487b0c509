"""A dynamic AABB tree usable on its own (Box2D's b2DynamicTree).

The tree answers "which of my boxes overlap this box / this ray?" in about
log(n) box tests instead of n. Each *proxy* is a leaf holding a **fat** AABB:
the box you insert, grown by :data:`AABB_EXTENSION` (0.1 m) on every side.
Moving a proxy whose new box still fits in its fat box costs nothing
(:meth:`DynamicTree.move` returns False); only when it leaves it is the leaf
re-inserted, with a new fat box stretched :data:`AABB_MULTIPLIER` (2) times the
``displacement`` in the direction of motion, so a steadily moving object
re-inserts rarely. Queries therefore report proxies whose *fat* box overlaps:
a superset of the exact answer, which the caller narrows with exact tests
(:mod:`kge.collision.shape_queries`).

Insertion walks down choosing the child whose box grows least (Box2D's
surface-area heuristic on perimeters); removals and insertions rebalance with
AVL rotations so the height stays about log2(n).

The protocols are Box2D's:

* :meth:`DynamicTree.query` calls ``callback(proxy_id)`` for each overlapping
  leaf; return ``False`` to stop early (any other value, None included,
  continues, as in kge's physics queries). It returns the proxies visited;
* :meth:`DynamicTree.ray_cast` calls ``callback(p1, p2, max_fraction,
  proxy_id)`` for each leaf the (clipped) ray's fat-box test passes. The
  callback returns ``0`` to stop, a positive fraction to clip the ray there
  (the closest hit so far), or a negative value to ignore that proxy.

>>> tree = DynamicTree()
>>> a = tree.insert(((0.0, 0.0), (1.0, 1.0)), "crate")
>>> b = tree.insert(((5.0, 0.0), (6.0, 1.0)), "barrel")
>>> tree.fat_aabb(a)
AABB(lower=(-0.1, -0.1), upper=(1.1, 1.1))
>>> sorted(tree.user_data(p) for p in tree.query(((0.5, 0.5), (5.5, 0.6))))
['barrel', 'crate']
>>> tree.query(((2.0, 0.0), (3.0, 1.0)))  # between them
[]
>>> tree.move(a, ((0.05, 0.0), (1.05, 1.0)), (0.05, 0.0))  # still inside its fat box
False
>>> tree.move(a, ((3.0, 0.0), (4.0, 1.0)), (3.0, 0.0))
True
>>> tree.fat_aabb(a)
AABB(lower=(2.9, -0.1), upper=(10.1, 1.1))
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

from kge.collision.pose import point
from kge.collision.shape_queries import AABB, aabb_of
from kge.errors import ComponentTypeError, ValidationError
from kge.validate import finite

Vec2 = tuple[float, float]

#: Box2D's b2_aabbExtension: the fat margin around every inserted box (metres)
AABB_EXTENSION = 0.1
#: Box2D's b2_aabbMultiplier: how far ahead of a move the fat box stretches
AABB_MULTIPLIER = 2.0
NULL = -1

RayCallback = Callable[[Vec2, Vec2, float, int], Any]


def _box(value: Any, field: str) -> AABB:
    if isinstance(value, AABB):
        return value
    if isinstance(value, (str, bytes)) or not hasattr(value, "__len__") or len(value) != 2:
        raise ValidationError(f"{field} must be an AABB or a (lower, upper) pair, got {value!r}")
    return aabb_of(value[0], value[1], field)


Box4 = tuple[float, float, float, float]  # (lower x, lower y, upper x, upper y)


def _union(a: Box4, b: Box4) -> Box4:
    return (min(a[0], b[0]), min(a[1], b[1]), max(a[2], b[2]), max(a[3], b[3]))


def _perimeter(b: Box4) -> float:
    return 2.0 * ((b[2] - b[0]) + (b[3] - b[1]))


def _contains(outer: Box4, inner: Box4) -> bool:
    return (outer[0] <= inner[0] and outer[1] <= inner[1]
            and inner[2] <= outer[2] and inner[3] <= outer[3])


class DynamicTree:
    """Fat AABBs with user data in a balanced binary tree; ids are small ints, reused.

    Nodes live in flat lists indexed by id (boxes as 4-tuples), which keeps a
    query's inner loop to a few list reads per node.
    """

    __slots__ = ("_aabb", "_child1", "_child2", "_data", "_free", "_height", "_parent",
                 "_proxies", "_root")

    def __init__(self) -> None:
        self._aabb: list[Box4] = []
        self._parent: list[int] = []
        self._child1: list[int] = []
        self._child2: list[int] = []
        self._height: list[int] = []  # leaf 0, free -1
        self._data: list[Any] = []
        self._free: list[int] = []
        self._root = NULL
        self._proxies = 0

    # ----------------------------------------------------------------------------- public

    def __len__(self) -> int:
        """The number of proxies (leaves)."""
        return self._proxies

    def insert(self, box: Any, user_data: Any = None) -> int:
        """Add a proxy for ``box`` (fattened by 0.1 m); returns its id (b2 CreateProxy)."""
        b = _box(box, "box")
        node = self._allocate()
        e = AABB_EXTENSION
        self._aabb[node] = (b.lower[0] - e, b.lower[1] - e, b.upper[0] + e, b.upper[1] + e)
        self._data[node] = user_data
        self._height[node] = 0
        self._insert_leaf(node)
        self._proxies += 1
        return node

    def remove(self, proxy_id: Any) -> None:
        """Remove a proxy (b2 DestroyProxy); its id may be reused by a later insert."""
        node = self._leaf(proxy_id)
        self._remove_leaf(node)
        self._release(node)
        self._proxies -= 1

    def move(self, proxy_id: Any, box: Any, displacement: Any = (0.0, 0.0)) -> bool:
        """Move a proxy to ``box``; True if it had to be re-inserted (b2 MoveProxy).

        Nothing happens while ``box`` stays inside the proxy's fat box. Otherwise
        the new fat box is ``box`` grown by 0.1 m and stretched by twice
        ``displacement`` (the motion since the last move) ahead of it.
        """
        node = self._leaf(proxy_id)
        b = _box(box, "box")
        dx, dy = point(displacement, "displacement")
        if _contains(self._aabb[node], (b.lower[0], b.lower[1], b.upper[0], b.upper[1])):
            return False
        self._remove_leaf(node)
        e = AABB_EXTENSION
        lx, ly, ux, uy = b.lower[0] - e, b.lower[1] - e, b.upper[0] + e, b.upper[1] + e
        dx, dy = AABB_MULTIPLIER * dx, AABB_MULTIPLIER * dy
        if dx < 0.0:
            lx += dx
        else:
            ux += dx
        if dy < 0.0:
            ly += dy
        else:
            uy += dy
        self._aabb[node] = (lx, ly, ux, uy)
        self._insert_leaf(node)
        return True

    def fat_aabb(self, proxy_id: Any) -> AABB:
        lx, ly, ux, uy = self._aabb[self._leaf(proxy_id)]
        return AABB((lx, ly), (ux, uy))

    def user_data(self, proxy_id: Any) -> Any:
        return self._data[self._leaf(proxy_id)]

    def query(self, box: Any, callback: Callable[[int], Any] | None = None) -> list[int]:
        """Proxies whose fat box overlaps ``box`` (touching counts), in tree order.

        With ``callback(proxy_id)``, each is passed to it as found; returning
        ``False`` stops the query. The returned list holds those visited.
        """
        q = _box(box, "box")
        qlx, qly, qux, quy = q.lower[0], q.lower[1], q.upper[0], q.upper[1]
        found: list[int] = []
        stack = [self._root]
        aabbs, c1, c2, height = self._aabb, self._child1, self._child2, self._height
        while stack:
            node = stack.pop()
            if node == NULL:
                continue
            lx, ly, ux, uy = aabbs[node]
            if qlx > ux or qly > uy or lx > qux or ly > quy:
                continue
            if height[node] == 0:
                found.append(node)
                if callback is not None and callback(node) is False:
                    break
            else:
                stack.append(c1[node])
                stack.append(c2[node])
        return found

    def pairs(self, proxies: Any = None) -> list[tuple[int, int]]:
        """Pairs of proxies whose fat boxes overlap, each once as (smaller id, larger id).

        This is Box2D's broad phase (``b2BroadPhase::UpdatePairs``): pass the
        proxies that moved since the last call (``move`` returned True for them,
        or they are new) to get only the pairs involving them, the candidates
        for exact tests; None checks every proxy. Sorted.
        """
        if proxies is None:
            movers = [i for i, h in enumerate(self._height) if h == 0]
        else:
            movers = [self._leaf(p) for p in proxies]
        found: set[tuple[int, int]] = set()
        for a in movers:
            lx, ly, ux, uy = self._aabb[a]
            for b in self.query(AABB((lx, ly), (ux, uy))):
                if b != a:
                    found.add((a, b) if a < b else (b, a))
        return sorted(found)

    def ray_cast(self, p1: Any, p2: Any, callback: RayCallback, max_fraction: Any = 1.0) -> None:
        """Walk the leaves a ray may hit, clipping it by the callback's answers (b2 RayCast).

        ``callback(p1, p2, max_fraction, proxy_id)`` returns 0 to stop, a
        positive fraction to clip the ray, or a negative value to skip the proxy.
        """
        a, b = point(p1, "p1"), point(p2, "p2")
        limit = finite(max_fraction, "", "max_fraction")
        if a == b:
            raise ValidationError(f"ray_cast needs p1 != p2 (a zero-length ray), got {a!r} twice")
        if not callable(callback):
            raise ComponentTypeError(f"ray_cast callback must be callable, got {callback!r}")
        dx, dy = b[0] - a[0], b[1] - a[1]
        length = (dx * dx + dy * dy) ** 0.5
        vx, vy = -dy / length, dx / length  # perpendicular to the ray
        avx, avy = abs(vx), abs(vy)
        seg = self._segment_box(a, dx, dy, limit)
        stack = [self._root]
        while stack:
            node = stack.pop()
            if node == NULL:
                continue
            lx, ly, ux, uy = self._aabb[node]
            if seg[0] > ux or seg[1] > uy or lx > seg[2] or ly > seg[3]:
                continue
            cx, cy = 0.5 * (lx + ux), 0.5 * (ly + uy)
            hx, hy = 0.5 * (ux - lx), 0.5 * (uy - ly)
            if abs(vx * (a[0] - cx) + vy * (a[1] - cy)) - (avx * hx + avy * hy) > 0.0:
                continue  # the ray's line misses the box
            if self._height[node] == 0:
                value = finite(callback(a, b, limit, node), "ray_cast callback", "return value")
                if value == 0.0:
                    return
                if value > 0.0:
                    limit = value
                    seg = self._segment_box(a, dx, dy, limit)
            else:
                stack.append(self._child1[node])
                stack.append(self._child2[node])

    @property
    def height(self) -> int:
        """Height of the root (0 for one proxy or none)."""
        return 0 if self._root == NULL else self._height[self._root]

    @property
    def max_balance(self) -> int:
        """Largest height difference between two siblings (Box2D keeps it <= 1)."""
        worst = 0
        for node, h in enumerate(self._height):
            if h > 0:
                worst = max(worst, abs(self._height[self._child2[node]]
                                       - self._height[self._child1[node]]))
        return worst

    @property
    def area_ratio(self) -> float:
        """Sum of all node perimeters over the root's (Box2D's tree quality measure)."""
        if self._root == NULL:
            return 0.0
        total = sum(_perimeter(self._aabb[i]) for i, h in enumerate(self._height) if h >= 0)
        return total / _perimeter(self._aabb[self._root])

    def validate(self) -> None:
        """Check the structure (parents, heights, enclosing boxes); raises AssertionError."""
        if self._root != NULL:
            assert self._parent[self._root] == NULL
            self._validate(self._root)
        leaves = sum(1 for h in self._height if h == 0)
        assert leaves == self._proxies, (leaves, self._proxies)

    # ---------------------------------------------------------------------------- private

    @staticmethod
    def _segment_box(a: Vec2, dx: float, dy: float, t: float) -> Box4:
        bx, by = a[0] + t * dx, a[1] + t * dy
        return (min(a[0], bx), min(a[1], by), max(a[0], bx), max(a[1], by))

    def _validate(self, node: int) -> None:
        if self._height[node] == 0:
            return
        c1, c2 = self._child1[node], self._child2[node]
        assert self._parent[c1] == node and self._parent[c2] == node
        assert self._height[node] == 1 + max(self._height[c1], self._height[c2])
        assert _contains(self._aabb[node], self._aabb[c1])
        assert _contains(self._aabb[node], self._aabb[c2])
        self._validate(c1)
        self._validate(c2)

    def _leaf(self, proxy_id: Any) -> int:
        if type(proxy_id) is not int:
            raise ComponentTypeError(f"proxy id must be an int, got {proxy_id!r}")
        if not 0 <= proxy_id < len(self._height) or self._height[proxy_id] != 0:
            raise ValidationError(f"proxy id {proxy_id} is not in this tree")
        return proxy_id

    def _allocate(self) -> int:
        if self._free:
            node = self._free.pop()
        else:
            node = len(self._height)
            self._aabb.append((0.0, 0.0, 0.0, 0.0))
            self._parent.append(NULL)
            self._child1.append(NULL)
            self._child2.append(NULL)
            self._height.append(-1)
            self._data.append(None)
        self._parent[node] = self._child1[node] = self._child2[node] = NULL
        self._height[node] = 0
        self._data[node] = None
        return node

    def _release(self, node: int) -> None:
        self._height[node] = -1
        self._data[node] = None
        self._free.append(node)

    def _insert_leaf(self, leaf: int) -> None:
        if self._root == NULL:
            self._root = leaf
            self._parent[leaf] = NULL
            return
        box = self._aabb[leaf]
        index = self._root
        while self._height[index] > 0:  # descend to the cheapest sibling
            area = _perimeter(self._aabb[index])
            combined = _perimeter(_union(self._aabb[index], box))
            cost = 2.0 * combined
            inheritance = 2.0 * (combined - area)
            costs = []
            for child in (self._child1[index], self._child2[index]):
                grown = _perimeter(_union(box, self._aabb[child]))
                if self._height[child] > 0:
                    grown -= _perimeter(self._aabb[child])
                costs.append(grown + inheritance)
            if cost < costs[0] and cost < costs[1]:
                break
            index = self._child1[index] if costs[0] < costs[1] else self._child2[index]
        sibling = index
        old_parent = self._parent[sibling]
        new_parent = self._allocate()
        self._height[new_parent] = self._height[sibling] + 1
        self._parent[new_parent] = old_parent
        self._aabb[new_parent] = _union(box, self._aabb[sibling])
        if old_parent != NULL:
            if self._child1[old_parent] == sibling:
                self._child1[old_parent] = new_parent
            else:
                self._child2[old_parent] = new_parent
        else:
            self._root = new_parent
        self._child1[new_parent], self._child2[new_parent] = sibling, leaf
        self._parent[sibling] = self._parent[leaf] = new_parent
        self._refit(self._parent[leaf])

    def _refit(self, index: int) -> None:
        """Rebalance and recompute heights and boxes from ``index`` up to the root."""
        while index != NULL:
            index = self._balance(index)
            c1, c2 = self._child1[index], self._child2[index]
            self._height[index] = 1 + max(self._height[c1], self._height[c2])
            self._aabb[index] = _union(self._aabb[c1], self._aabb[c2])
            index = self._parent[index]

    def _remove_leaf(self, leaf: int) -> None:
        if leaf == self._root:
            self._root = NULL
            return
        parent = self._parent[leaf]
        grand = self._parent[parent]
        sibling = self._child2[parent] if self._child1[parent] == leaf else self._child1[parent]
        if grand != NULL:
            if self._child1[grand] == parent:
                self._child1[grand] = sibling
            else:
                self._child2[grand] = sibling
            self._parent[sibling] = grand
            self._release(parent)
            self._refit(grand)
        else:
            self._root = sibling
            self._parent[sibling] = NULL
            self._release(parent)

    def _balance(self, a: int) -> int:
        """Rotate ``a``'s taller child up if the heights differ by more than one (AVL)."""
        if self._height[a] < 2:
            return a
        b, c = self._child1[a], self._child2[a]
        diff = self._height[c] - self._height[b]
        if diff > 1:
            return self._rotate(a, c, b, second=False)
        if diff < -1:
            return self._rotate(a, b, c, second=True)
        return a

    def _rotate(self, a: int, up: int, other: int, second: bool) -> int:
        """Make ``up`` (a child of ``a``) the parent of ``a``; ``other`` is a's other child."""
        f, g = self._child1[up], self._child2[up]
        self._child1[up] = a
        self._parent[up] = self._parent[a]
        self._parent[a] = up
        pa = self._parent[up]
        if pa != NULL:
            if self._child1[pa] == a:
                self._child1[pa] = up
            else:
                self._child2[pa] = up
        else:
            self._root = up
        # the taller grandchild stays under ``up``; the shorter one moves to ``a``
        keep, give = (f, g) if self._height[f] > self._height[g] else (g, f)
        self._child2[up] = keep
        if second:
            self._child1[a] = give
        else:
            self._child2[a] = give
        self._parent[give] = a
        self._aabb[a] = _union(self._aabb[other], self._aabb[give])
        self._aabb[up] = _union(self._aabb[a], self._aabb[keep])
        self._height[a] = 1 + max(self._height[other], self._height[give])
        self._height[up] = 1 + max(self._height[a], self._height[keep])
        return up
