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
from pyglet import gl

from kge.components.camera import Camera
from kge.components.camera import cameras as camera_list
from kge.components.debug import DebugDraw
from kge.components.drawables import DRAWABLE_TYPES
from kge.components.lights import Lighting
from kge.components.material import Material
from kge.components.rigidbody import RigidBody
from kge.components.sprite import Sprite
from kge.components.text import Text
from kge.components.tracked import bind, unbind
from kge.components.transform import Transform
from kge.host import Host
from kge.physics.events import ContactBegin, ContactEnd
from kge.physics.resource import Physics
from kge.render.cameras import (
    CameraPasses,
    CameraView,
    letterbox,
    make_view,
    ortho,
    single,
    text_scales,
    union,
)
from kge.render.canvas import Canvas, IntegerCanvas, canvas_of
from kge.render.debugdraw import DebugDrawer
from kge.render.geometry import drawable_triangles
from kge.render.glutil import drawing_into
from kge.render.groups import WORLD, Groups, ViewState
from kge.render.meshes import MeshStore
from kge.render.passes import Frame, RenderPasses
from kge.render.passtime import PassTimer
from kge.render.poses import PoseTable
from kge.render.programs import FrameUniforms
from kge.render.setup import Renderer, ensure_renderer
from kge.render.sprites import SpriteStore
from kge.render.stats import StatsOverlay, light_note
from kge.render.text.store import TextStore
from kge.render.textures import TextureCache

_TRACKED: tuple[type, ...] = (Sprite, Text, Material, *DRAWABLE_TYPES)


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
        self.timer = PassTimer()  # the light pass's share, while the overlay is shown
        self.cameras = CameraPasses(self.state, self.textures)
        self.integer = IntegerCanvas()
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
        material = w.try_get(entity, Material)
        sp = w.try_get(entity, Sprite)
        if sp is None:
            self.sprites.remove(entity)
        else:
            self.sprites.sync(entity, sp, t, ppm, material)
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
                prog = None
                if material is not None:
                    prog, parent = self.meshes.material_group(key, material, self.textures, parent)
                self.meshes.put(key, entity, t, drawable_triangles(d), d.color, parent,
                                blend=d.blend, program=prog)  # fmt: skip

    def sync(self, ppm: float) -> None:
        if ppm != self._ppm:
            if self._ppm is not None:  # default sprite sizes depend on pixels_per_meter
                self.dirty.update(self.sprites.sprites)
                self.dirty.update(self.labels.labels)
            self._ppm = ppm
        # sprites whose material changed since they joined a shared group: drawn alone now
        self.dirty.update(self.sprites.shared.diverged())
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
    def _views(self, cams: list[tuple[int, Camera]], canvas: Canvas, poses: Any,
               snap: bool) -> list[CameraView]:  # fmt: skip
        views = []
        for entity, cam in cams:
            center = cam.center
            if cam.follow is not None:  # follow what is drawn, not the un-blended pose
                row = self.poses.row_of.get(cam.follow)
                if row is not None:
                    lag = poses[row, :2] - self.poses.last_live[row, :2]
                    center = (center[0] + float(lag[0]), center[1] + float(lag[1]))
            # inside the bounds as drawn: the lag, or a first frame before the camera
            # system ran, never shows past them
            center = cam.clamped(center, canvas.size)
            views.append(make_view(entity, cam, center, canvas, snap))
        return views

    def draw(self, alpha: float) -> None:
        r = self.renderer
        window = r.window
        window.switch_to()
        canvas = canvas_of(self.world, window)
        cams = camera_list(self.world)
        if not cams:
            cams = [(-1, self.camera())]
        primary = next((c for _, c in cams if c.target is None), cams[0][1])
        ppm = primary.pixels_per_meter
        res = canvas.resolution
        snap = res is not None and res.snap
        self.labels.rescale(*text_scales([c for _, c in cams], canvas))
        self.textures.render_textures = lambda name: self.cameras.target(name, cams, canvas.size)
        self.sync(ppm)
        settings = self.world.try_resource(DebugDraw)
        if settings is not None:
            self.debug.sync(settings)
        elif self.debug.meshes.lists:
            self.debug.clear()
        poses = self.poses.blend(alpha)
        views = self._views(cams, canvas, poses, snap)
        seen = union(views)
        self.culled = self.sprites.poser.write(poses, seen)
        self.sprites.normals.poser.write(poses, seen)
        self.meshes.poser.write(poses)
        self.labels.poser.write(poses)
        if settings is not None:
            self.debug.update(settings, poses, self._game_time())
            self.debug.meshes.poser.write(poses)
        shown = settings is not None and settings.stats
        self.timer.start(shown)
        self.stats.update(
            shown, canvas.size[1], self.stat_values() if shown else {},
            throttle=not self.app.headless,
            lines=self.timing_lines() if shown and settings is not None and settings.timings
            else None,
        )  # fmt: skip
        FrameUniforms.time = self._game_time()
        passes = self.world.try_resource(RenderPasses)
        main = next((v for v in views if v.camera is primary), views[0])
        base = self._frame(alpha, main, seen, poses, canvas)
        if passes is not None:
            for before in passes.before():
                before(base)
        if canvas.integer:
            with drawing_into(self.integer.target(canvas.size)):
                self._draw_canvas(canvas, views, cams, passes, alpha, poses, base)
            if r.clear:
                letterbox(canvas, self.app.background, window=True)
            self.integer.present(canvas)
        else:
            self._draw_canvas(canvas, views, cams, passes, alpha, poses, base)
        gl.glViewport(0, 0, *canvas.framebuffer)  # what screenshots and transitions expect
        window.projection = ortho(window.width, window.height)
        window.view = pyglet.math.Mat4()
        self.cameras.forget({v.entity for v in views if v.camera.post})
        self.timer.finish()
        r.clock.frame()

    def _frame(self, alpha: float, v: CameraView, view: Any, poses: Any, canvas: Canvas,
               rect: tuple[int, int, int, int] | None = None) -> Frame:  # fmt: skip
        cam = v.camera
        return Frame(
            alpha, cam, v.center, cam.scale, (round(v.size[0]), round(v.size[1])), view,
            v.matrix, self._game_time(), self.batch, self.groups, poses, self.poses.row_of,
            rect or canvas.rect, canvas.pixel_scale, cam.rotation,
        )  # fmt: skip

    def _draw_canvas(self, canvas: Canvas, views: list[CameraView],
                     cams: list[tuple[int, Camera]], passes: RenderPasses | None, alpha: float,
                     poses: Any, base: Frame) -> None:  # fmt: skip
        window = self.renderer.window
        if self.renderer.clear:
            letterbox(canvas, self.app.background)
        snap = canvas.resolution is not None and canvas.resolution.snap
        view_passes = (list(zip(passes.names("view"), passes.view(), strict=True))
                       if passes is not None else [])  # fmt: skip

        def scene(v: CameraView, rect: tuple[int, int, int, int]) -> None:
            self.cameras.scene_pass(window, v, rect, snap)
            frame = self._frame(alpha, v, v.view, poses, canvas, rect)
            for name, view_pass in view_passes:
                self.timer.run(name, view_pass, frame)
            self.cameras.scene_pass(window, v, rect, snap)  # a pass may have moved GL state
            self.batch.draw()

        if single(views) and not canvas.integer and canvas.resolution is None:
            v = views[0]  # the common case: one camera over the window, one batch draw
            self.cameras.scene_pass(window, v, canvas.rect, snap)
            self.state.shows = None
            frame = self._frame(alpha, v, v.view, poses, canvas)
            for name, view_pass in view_passes:
                self.timer.run(name, view_pass, frame)
            self.cameras.scene_pass(window, v, canvas.rect, snap)
            self.state.shows = None
            gl.glDisable(gl.GL_SCISSOR_TEST)
            self.batch.draw()
        else:
            first = True
            for v in views:
                self.cameras.draw(v, canvas, first and v.camera.target is None,
                                  self.app.background, scene, cams)  # fmt: skip
                if v.camera.target is None:
                    first = False
            self.cameras.screen_pass(window, canvas)
            self.batch.draw()
        self.cameras.end()
        if passes is not None:
            gl.glViewport(*canvas.rect)
            window.projection = ortho(*canvas.size)
            window.view = pyglet.math.Mat4()
            after = Frame(
                alpha, base.camera, base.center, base.scale, canvas.size, base.view,
                base.world_matrix, base.time, self.batch, self.groups, poses, self.poses.row_of,
                canvas.rect, canvas.pixel_scale, base.rotation,
            )  # fmt: skip
            for after_pass in passes.after():
                after_pass(after)

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
        lighting = self.world.try_resource(Lighting)
        if lighting is not None and lighting.enabled and self.timer.frame_ms > 0.0:
            values["lights"] = light_note(self.timer.ms("lighting"), self.timer.frame_ms)
        return values

    def timing_lines(self, top: int = 10) -> list[str]:
        """The slowest systems of the world, one line each (the stats overlay's table)."""
        timings = self.world.schedule.timings
        if timings is None:
            return ["system timings are off (F4)"]
        rows = timings.rows(top)
        lines = [f"{'systems':<6} {f'{timings.frame_ms():.2f} ms/frame':<24} "
                 f"{'avg ms':>8} {'peak ms':>8}"]  # fmt: skip
        lines += [f"{r.stage:<6} {r.name:<24.24} {r.average:8.3f} {r.peak:8.3f}" for r in rows]
        return lines

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
        self.cameras.close()
        self.integer.close()
        self.textures.clear()
