"""Flat-coloured vertex lists in pyglet's shape shader, posed in bulk.

pyglet's shape shader takes, per vertex, a local ``position``, a
``translation`` and a clockwise ``rotation``: exactly a mesh in its entity's
frame plus the entity's pose. So each drawable (and each debug outline) is
built once, in local metres, and only its pose is written each frame, by a
:class:`~kge.render.bulk.BulkPoser`, like sprites.
"""

from __future__ import annotations

from typing import Any

import numpy as np
import pyglet
from pyglet import gl

from kge.render.bulk import BulkPoser
from kge.render.poses import PoseTable


class MeshGroup(pyglet.graphics.Group):
    """Binds the shape shader with alpha blending (one per parent group)."""

    def __init__(self, program: Any, parent: pyglet.graphics.Group) -> None:
        super().__init__(parent=parent)
        self.program = program

    def set_state(self) -> None:
        self.program.use()
        gl.glEnable(gl.GL_BLEND)
        gl.glBlendFunc(gl.GL_SRC_ALPHA, gl.GL_ONE_MINUS_SRC_ALPHA)

    def unset_state(self) -> None:
        gl.glDisable(gl.GL_BLEND)
        self.program.stop()

    def __eq__(self, other: object) -> bool:
        return (
            isinstance(other, MeshGroup)
            and other.program is self.program
            and other.parent == self.parent
        )

    def __hash__(self) -> int:
        return hash((id(self.program), self.parent))


def shape_program() -> Any:
    return pyglet.shapes.get_default_shader()


class MeshStore:
    """key -> one vertex list (triangles or lines) posed by an entity's pose row."""

    def __init__(self, batch: Any, poses: PoseTable) -> None:
        self.batch = batch
        self.poses = poses
        self.program = shape_program()
        self.poser = BulkPoser("translation", "rotation")
        self.lists: dict[Any, Any] = {}
        self._entity: dict[Any, int] = {}
        self._mesh_groups: dict[Any, MeshGroup] = {}

    def __len__(self) -> int:
        return len(self.lists)

    def group_for(self, parent: pyglet.graphics.Group) -> MeshGroup:
        g = self._mesh_groups.get(parent)
        if g is None:
            g = self._mesh_groups[parent] = MeshGroup(self.program, parent)
        return g

    def put(
        self,
        key: Any,
        entity: int,
        transform: Any,
        points: np.ndarray,
        color: tuple[int, int, int, int],
        parent: pyglet.graphics.Group,
        mode: int = gl.GL_TRIANGLES,
        posed: bool = True,
    ) -> Any:
        """(Re)build the vertex list of ``key`` from local ``points`` (n, 2)."""
        self.remove(key)
        n = len(points)
        if n == 0:
            return None
        vl = self.program.vertex_list(
            n,
            mode,
            self.batch,
            self.group_for(parent),
            position=("f", np.asarray(points, np.float32).ravel().tolist()),
            colors=("Bn", tuple(color) * n),
            translation=("f", (0.0, 0.0) * n),
            rotation=("f", (0.0,) * n),
            zposition=("f", (0.0,) * n),
        )
        self.lists[key] = vl
        if posed:
            row = self.poses.acquire(entity, transform)
            self._entity[key] = entity
            self.poser.add(key, vl, row)
        return vl

    def recolor(self, key: Any, color: tuple[int, int, int, int]) -> None:
        vl = self.lists.get(key)
        if vl is not None:
            vl.colors[:] = tuple(color) * vl.count

    def remove(self, key: Any) -> None:
        vl = self.lists.pop(key, None)
        if vl is None:
            return
        self.poser.remove(key)
        vl.delete()
        entity = self._entity.pop(key, None)
        if entity is not None:
            self.poses.release(entity)

    def clear(self) -> None:
        for k in list(self.lists):
            self.remove(k)
