"""Everything one world draws: its batch, stores, camera and debug view.

:class:`WorldView` is what :class:`kge.systems.render.RenderSystem` delegates
to. Components are mirrored lazily: hooks only note *which* entities changed
(adds, removes and tracked writes of Sprite, Text and the shape drawables),
and :meth:`WorldView.draw` reconciles just those before drawing. Moving
things costs one numpy pass per vertex domain (see :mod:`kge.render.bulk`).
"""

from __future__ import annotations

import time
from typing import Any

import pyglet

from kge.components.camera import Camera
from kge.components.debug import DebugDraw
from kge.components.drawables import DRAWABLE_TYPES
from kge.components.rigidbody import RigidBody
from kge.components.sprite import Sprite
from kge.components.text import Text
from kge.components.tracked import bind, unbind
from kge.components.transform import Transform
from kge.host import Host
from kge.physics.events import ContactBegin, ContactEnd
from kge.physics.resource import Physics
from kge.render.debugdraw import DebugDrawer
from kge.render.geometry import drawable_triangles
from kge.render.groups import WORLD, Groups, ViewState
from kge.render.meshes import MeshStore
from kge.render.passes import Frame, RenderPasses
from kge.render.poses import PoseTable
from kge.render.projection import view_matrix
from kge.render.setup import Renderer, ensure_renderer
from kge.render.sprites import SpriteStore
from kge.render.stats import StatsOverlay
from kge.render.text.store import TextStore
from kge.render.textures import TextureCache

_TRACKED: tuple[type, ...] = (Sprite, Text, *DRAWABLE_TYPES)


class WorldView:
    """The pyglet mirror of one world."""

    def __init__(self, world: Any) -> None:
        self.world = world
        self.app = world.resource(Host)
        self.renderer: Renderer = ensure_renderer(self.app)
        self.batch = pyglet.graphics.Batch()
        self.state = ViewState(self.renderer.window)
        self.groups = Groups(self.state)
        self.poses = PoseTable()
        self.textures = TextureCache(world)
        self.sprites = SpriteStore(self.batch, self.groups, self.textures, self.poses)
        self.meshes = MeshStore(self.batch, self.poses)
        self.labels = TextStore(self.batch, self.groups, self.poses, self.textures)
        self.debug = DebugDrawer(world, self.batch, self.groups, self.poses)
        self.stats = StatsOverlay(self.batch, self.groups)
        self.dirty: set[int] = set()
        self.closed = False
        self.culled = 0
        self._touching: set[tuple[int, int]] = set()
        self._ppm: float | None = None
        for ctype in _TRACKED:
            world.on_add(ctype, self._added)
            world.on_remove(ctype, self._removed)
            for entity, (comp,) in world.query(ctype):
                self._added(entity, comp)
        world.on_add(Transform, self._transform_changed)
        world.on_remove(Transform, self._transform_removed)

    # -- change notes (no GL work in hooks) ----------------------------------------------
    def _added(self, entity: int, comp: Any) -> None:
        if self.closed:
            return
        bind(comp, entity, self.dirty)
        self.dirty.add(entity)

    def _removed(self, entity: int, comp: Any) -> None:
        if self.closed:
            return
        unbind(comp)
        self.dirty.add(entity)

    def _transform_changed(self, entity: int, t: Transform) -> None:
        if not self.closed:
            self.poses.set_transform(entity, t)

    def _transform_removed(self, entity: int, t: Transform) -> None:
        if not self.closed:
            self.poses.set_transform(entity, None)

    # -- camera ----------------------------------------------------------------------------
    def camera(self) -> Camera:
        """The active camera: lowest entity id with a Camera, else the Camera resource."""
        from kge.components.camera import active_camera

        cam = active_camera(self.world)
        if cam is None:
            cam = self.world.insert_resource(Camera())
        return cam

    # -- reconcile ---------------------------------------------------------------------------
    def _reconcile(self, entity: int, ppm: float) -> None:
        w = self.world
        t = w.try_get(entity, Transform)
        sp = w.try_get(entity, Sprite)
        if sp is None:
            self.sprites.remove(entity)
        else:
            self.sprites.sync(entity, sp, t, ppm)
        tx = w.try_get(entity, Text)
        if tx is None:
            self.labels.remove(entity)
        else:
            self.labels.sync(entity, tx, t, ppm)
        for dtype in DRAWABLE_TYPES:
            key = (dtype, entity)
            d = w.try_get(entity, dtype)
            if d is None or not d.visible:
                self.meshes.remove(key)
            else:
                parent = self.groups.get(d.layer, WORLD, d.order)
                self.meshes.put(key, entity, t, drawable_triangles(d), d.color, parent)

    def sync(self, ppm: float) -> None:
        if ppm != self._ppm:
            if self._ppm is not None:  # default sprite sizes depend on pixels_per_meter
                self.dirty.update(self.sprites.sprites)
                self.dirty.update(self.labels.labels)
            self._ppm = ppm
        if self.dirty:
            todo = sorted(self.dirty)
            self.dirty.clear()
            for i, entity in enumerate(todo):
                try:
                    self._reconcile(entity, ppm)
                except Exception:
                    # keep this entity and the rest pending: fixing the component retries it
                    self.dirty.update(todo[i:])
                    raise

    # -- drawing --------------------------------------------------------------------------------
    def draw(self, alpha: float) -> None:
        r = self.renderer
        r.begin_frame(self.app.background)
        cam = self.camera()
        ppm = cam.pixels_per_meter
        self.labels.rescale(cam.zoom, 1.0)
        self.sync(ppm)
        settings = self.world.try_resource(DebugDraw)
        if settings is not None:
            self.debug.sync(settings)
        elif self.debug.meshes.lists:
            self.debug.clear()
        poses = self.poses.blend(alpha)
        viewport = r.size
        center = cam.center
        if cam.follow is not None:  # follow what is drawn, not the un-blended pose
            row = self.poses.row_of.get(cam.follow)
            if row is not None:
                lag = poses[row, :2] - self.poses.last_live[row, :2]
                center = (center[0] + float(lag[0]), center[1] + float(lag[1]))
                # the lag must not carry the view past the bounds: a strip of clear
                # colour showed at a map's edge while a bounded follow camera started
                center = cam.clamped(center, viewport)
        world_view = view_matrix(center, cam.scale, viewport)
        self.state.matrices[WORLD] = world_view
        hw, hh = viewport[0] / (2 * cam.scale), viewport[1] / (2 * cam.scale)
        view = (center[0] - hw, center[1] - hh, center[0] + hw, center[1] + hh)
        self.culled = self.sprites.poser.write(poses, view)
        self.meshes.poser.write(poses)
        self.labels.poser.write(poses)
        if settings is not None:
            self.debug.update(settings, poses, self._game_time())
            self.debug.meshes.poser.write(poses)
        shown = settings is not None and settings.stats
        self.stats.update(
            shown, viewport[1], self.stat_values() if shown else {}, throttle=not self.app.headless
        )
        passes = self.world.try_resource(RenderPasses)
        if passes is None:
            self.batch.draw()
        else:
            frame = Frame(
                alpha, cam, center, cam.scale, viewport, view, world_view, self._game_time(),
                self.batch, self.groups, poses, self.poses.row_of,
            )  # fmt: skip
            for before in passes.before():
                before(frame)
            self.batch.draw()
            for after in passes.after():
                after(frame)
        r.clock.frame()

    def _game_time(self) -> float:
        from kge.scene import Time

        t = self.world.try_resource(Time)
        return float(t.fixed_elapsed) if t is not None else time.perf_counter()

    def stat_values(self) -> dict[str, Any]:
        clock = self.renderer.clock
        values: dict[str, Any] = {
            "FPS": f"{clock.fps:.0f}" if clock.fps > 0 else "-",  # headless: no frame rate
            "step": f"{clock.step_ms:.2f} ms",
        }
        values["bodies"] = len(self.world.query(RigidBody))
        values["contacts"] = len(self._touching)
        values["sprites"] = f"{len(self.sprites) - self.culled}/{len(self.sprites)}"
        return values

    # -- fixed-step hooks ----------------------------------------------------------------------
    def after_step(self, seconds: float) -> None:
        """Called by RenderStepRecorder after every fixed step."""
        self.poses.record()
        physics = self.world.try_resource(Physics)
        if physics is not None:
            self.poses.adopt(*physics.poses())
        self.renderer.clock.step(seconds)
        self.debug.record_contacts(self._game_time())
        self._count_contacts()

    def _count_contacts(self) -> None:
        """Touching collider pairs, kept from begin/end events (no per-contact query)."""
        pairs = self._touching
        world = self.world
        for c in world.events(ContactBegin):  # this step's (RenderStepRecorder runs last)
            pairs.add((c.collider_a, c.collider_b))
        for c in world.events(ContactEnd):
            pairs.discard((c.collider_a, c.collider_b))
            pairs.discard((c.collider_b, c.collider_a))

    def close(self) -> None:
        self.closed = True
        self.sprites.clear()
        self.meshes.clear()
        self.labels.clear()
        self.debug.clear()
        self.stats.clear()
        self.textures.clear()
