"""BulkPoser writes every member's pose into each of its vertices, whatever the layout.

Fake pyglet domains (ctypes buffers, as pyglet's are) so every layout the
poser distinguishes is checked value by value: a back-to-back block of equal
vertex counts with pose rows in order (a slice of the table) or permuted (a
gather), and mixed vertex counts (a per-vertex index).
"""

from __future__ import annotations

import ctypes
import math

import numpy as np
import pytest

from kge.render.bulk import BulkPoser

Z = 7.0  # the third component of ``translate``, which the poser must leave alone


class _Buffer:
    def __init__(self, count: int, vertices: int) -> None:
        self.count = count
        self.data = (ctypes.c_float * (count * vertices))()
        self.region: tuple[int, int] | None = None

    def invalidate_region(self, start: int, size: int) -> None:
        self.region = (start, size)

    def rows(self) -> np.ndarray:
        return np.ctypeslib.as_array(self.data).reshape(-1, self.count)


class _Domain:
    def __init__(self, vertices: int = 64) -> None:
        self.attrib_name_buffers = {
            "translate": _Buffer(3, vertices),
            "rotation": _Buffer(1, vertices),
            "scale": _Buffer(2, vertices),
        }
        self.attrib_name_buffers["translate"].rows()[:, 2] = Z


class _VertexList:
    def __init__(self, domain: _Domain, start: int, count: int) -> None:
        self.domain, self.start, self.count = domain, start, count


def _poses(n: int) -> np.ndarray:
    rng = np.random.default_rng(3)
    return np.column_stack([rng.uniform(-5, 5, n), rng.uniform(-5, 5, n), rng.uniform(-3, 3, n)])


def _check(
    domain: _Domain,
    lists: list[_VertexList],
    rows: list[int],
    poses: np.ndarray,
    scales: list[tuple[float, float]],
) -> None:
    bufs = domain.attrib_name_buffers
    for vl, row, scale in zip(lists, rows, scales, strict=True):
        span = slice(vl.start, vl.start + vl.count)
        x, y, angle = poses[row]
        np.testing.assert_array_equal(
            bufs["translate"].rows()[span], np.array([[x, y, Z]] * vl.count, dtype=np.float32)
        )
        np.testing.assert_array_equal(
            bufs["rotation"].rows()[span, 0], np.array([-math.degrees(angle)] * vl.count, dtype=np.float32)
        )
        np.testing.assert_array_equal(bufs["scale"].rows()[span], np.array([scale] * vl.count, dtype=np.float32))


@pytest.mark.parametrize("rows", [[0, 1, 2, 3], [3, 0, 2, 1]], ids=["slice", "gather"])
def test_a_block_of_sprites_gets_its_rows(rows):
    domain = _Domain()
    poser = BulkPoser("translate", "rotation", scale="scale")
    lists = [_VertexList(domain, 8 + 4 * i, 4) for i in range(4)]
    scales = [(1.0, 2.0), (0.5, 0.5), (-1.0, 1.0), (3.0, 0.25)]
    for i, (vl, row) in enumerate(zip(lists, rows, strict=True)):
        poser.add(i, vl, row, scales[i])
    poses = _poses(4)
    assert poser.write(poses) == 0
    _check(domain, lists, rows, poses, scales)
    assert domain.attrib_name_buffers["scale"].region == (8, 16)


def test_mixed_vertex_counts_use_the_per_vertex_index():
    domain = _Domain()
    poser = BulkPoser("translate", "rotation", scale="scale")
    lists = [_VertexList(domain, 0, 3), _VertexList(domain, 5, 6), _VertexList(domain, 20, 4)]
    rows = [2, 0, 1]
    for i, (vl, row) in enumerate(zip(lists, rows, strict=True)):
        poser.add(i, vl, row, (1.0, 1.0))
    poses = _poses(3)
    poser.write(poses)
    _check(domain, lists, rows, poses, [(1.0, 1.0)] * 3)


def test_members_outside_the_view_get_scale_zero():
    domain = _Domain()
    poser = BulkPoser("translate", "rotation", scale="scale")
    lists = [_VertexList(domain, 4 * i, 4) for i in range(2)]
    for i, vl in enumerate(lists):
        poser.add(i, vl, i, (2.0, 2.0), radius=0.5)
    poses = np.array([[0.0, 0.0, 0.0], [10.0, 0.0, 1.0]])
    assert poser.write(poses, view=(-1.0, -1.0, 1.0, 1.0)) == 1
    _check(domain, lists, [0, 1], poses, [(2.0, 2.0), (0.0, 0.0)])
