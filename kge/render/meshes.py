"""Flat-coloured vertex lists in pyglet's shape layout, posed in bulk.

pyglet's shape layout takes, per vertex, a local ``position``, a ``translation``
and a clockwise ``rotation``: exactly a mesh in its entity's frame plus the
entity's pose. So each drawable (and each debug outline) is built once, in local
metres, and only its pose is written each frame, by a
:class:`~kge.render.bulk.BulkPoser`, like sprites. They are drawn with kge's shape
program (:mod:`kge.render.programs`): blend modes and materials.
"""

from __future__ import annotations

from typing import Any

import numpy as np
import pyglet
from pyglet import gl

from kge.components.blend import Blend
from kge.render.bulk import BulkPoser
from kge.render.glutil import per_context
from kge.render.poses import PoseTable
from kge.render.programs import (
    MaterialGroup,
    apply_frame_uniforms,
    default_program,
    material_program,
    set_blend,
)


class MeshGroup(pyglet.graphics.Group):
    """Binds a shape program with a blend mode (one per parent group, program and blend)."""

    def __init__(
        self, program: Any, parent: pyglet.graphics.Group, blend: Blend = Blend.ALPHA
    ) -> None:
        super().__init__(parent=parent)
        self.program = program
        self.blend = blend

    def set_state(self) -> None:
        self.program.use()
        apply_frame_uniforms(self.program)
        white = _white_texture()
        gl.glActiveTexture(gl.GL_TEXTURE0)
        gl.glBindTexture(white.target, white.id)
        set_blend(self.blend)

    def unset_state(self) -> None:
        gl.glDisable(gl.GL_BLEND)
        self.program.stop()

    def __eq__(self, other: object) -> bool:
        return (
            isinstance(other, MeshGroup)
            and other.program is self.program
            and other.parent == self.parent
            and other.blend == self.blend
        )

    def __hash__(self) -> int:
        return hash((id(self.program), self.parent, self.blend))


def shape_program() -> Any:
    return default_program("shape")


def _white_texture() -> Any:
    return per_context("kge-white", lambda: pyglet.image.ImageData(
        1, 1, "RGBA", b"\xff\xff\xff\xff").get_texture())  # fmt: skip


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
        self._materials: dict[Any, MaterialGroup] = {}

    def __len__(self) -> int:
        return len(self.lists)

    def group_for(self, parent: pyglet.graphics.Group, blend: Blend = Blend.ALPHA,
                  program: Any = None) -> MeshGroup:  # fmt: skip
        prog = program or self.program
        key = (parent, blend, id(prog))
        g = self._mesh_groups.get(key)
        if g is None:
            g = self._mesh_groups[key] = MeshGroup(prog, parent, blend)
        return g

    def material_group(self, key: Any, material: Any, textures: Any,
                       parent: pyglet.graphics.Group) -> tuple[Any, Any]:  # fmt: skip
        """(program, group) of a shape drawn with ``material`` (the default when its
        shader does not compile)."""
        prog = material_program(material.shader, "shape")
        if prog is None:
            self._materials.pop(key, None)
            return self.program, parent
        g = self._materials.get(key)
        if g is None or g.material is not material or g.parent is not parent:
            g = self._materials[key] = MaterialGroup(material, prog, textures, parent)
        return prog, g

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
        blend: Blend = Blend.ALPHA,
        program: Any = None,
    ) -> Any:
        """(Re)build the vertex list of ``key`` from local ``points`` (n, 2)."""
        self.remove(key)
        n = len(points)
        if n == 0:
            return None
        prog = program or self.program
        vl = prog.vertex_list(
            n,
            mode,
            self.batch,
            self.group_for(parent, blend, prog),
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
