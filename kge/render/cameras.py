"""Drawing a world through its cameras: viewports, layers, render textures, post stacks.

For each enabled camera, in order (render-texture cameras first, so a sprite showing
one shows this frame's picture), :class:`CameraPasses` sets the camera's viewport,
projection and view matrix, lets the ``view`` passes run (the light map), and draws
the world's batch with only the camera's layers shown (:class:`ViewState.shows`).
A camera with a post stack draws into a texture first
(:class:`~kge.render.post.PostChain`). Screen-space text is drawn afterwards, once,
over the whole canvas.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import pyglet
from pyglet import gl

from kge.components.camera import FULL, Camera
from kge.components.resolution import Resolution
from kge.errors import ValidationError
from kge.render.canvas import Canvas
from kge.render.glutil import clear, drawing_into, new_texture
from kge.render.groups import SCREEN, ViewState
from kge.render.post import PostChain
from kge.render.programs import FrameUniforms
from kge.render.projection import Mat4Tuple, view_matrix

Rect = tuple[int, int, int, int]


@dataclass(slots=True)
class CameraView:
    """One camera's view this frame."""

    entity: int
    camera: Camera
    center: tuple[float, float]  #: drawn centre, metres (follow lag and snapping applied)
    size: tuple[float, float]  #: the view in screen (design) pixels
    matrix: Mat4Tuple  #: world metres -> view pixels
    view: tuple[float, float, float, float]  #: the world area seen (axis-aligned box)

    @property
    def pixels(self) -> float:
        """Screen pixels per metre."""
        return self.camera.scale


def make_view(entity: int, cam: Camera, center: tuple[float, float], canvas: Canvas,
              snap: bool) -> CameraView:  # fmt: skip
    """The view of ``cam`` centred on ``center`` (metres) over ``canvas``."""
    _, _, w, h = cam.rect(canvas.size)
    k = cam.scale
    if snap:  # the camera sits on whole screen pixels
        center = (round(center[0] * k) / k, round(center[1] * k) / k)
    probe = Camera(center=center, pixels_per_meter=cam.pixels_per_meter, zoom=cam.zoom,
                   rotation=cam.rotation)  # fmt: skip
    hw, hh = probe.half_extents((w, h))
    view = (center[0] - hw, center[1] - hh, center[0] + hw, center[1] + hh)
    return CameraView(entity, cam, center, (w, h), view_matrix(center, k, (w, h), cam.rotation),
                      view)  # fmt: skip


def union(views: list[CameraView]) -> tuple[float, float, float, float]:
    """The world box every view together sees (sprite culling)."""
    return (min(v.view[0] for v in views), min(v.view[1] for v in views),
            max(v.view[2] for v in views), max(v.view[3] for v in views))  # fmt: skip


def single(views: list[CameraView]) -> bool:
    """Whether the frame is one plain camera over the whole canvas (one batch draw)."""
    if len(views) != 1:
        return False
    cam = views[0].camera
    return cam.target is None and not cam.post and cam.viewport == FULL and cam.layers is None


def ortho(w: float, h: float) -> Any:
    return pyglet.math.Mat4.orthogonal_projection(0, w, 0, h, -255, 255)


class CameraPasses:
    """Per-camera drawing state of one world: post chains and render textures."""

    def __init__(self, state: ViewState, textures: Any) -> None:
        self.state = state
        self.textures = textures
        self.chains: dict[int, PostChain] = {}
        self.targets: dict[str, Any] = {}
        self._sizes: dict[str, tuple[int, int]] = {}

    # -- render textures ---------------------------------------------------------------------
    def target(self, name: str, cams: list[tuple[int, Camera]], canvas: tuple[int, int]) -> Any:
        """The texture camera ``target=name`` draws into (made at its size on first use)."""
        cam = next((c for _, c in cams if c.target == name), None)
        if cam is None:
            raise ValidationError(f"RenderTexture({name!r}): no enabled camera has target={name!r}")
        _, _, w, h = cam.rect(canvas)
        size = (max(1, round(w)), max(1, round(h)))
        tex = self.targets.get(name)
        if tex is None or self._sizes.get(name) != size:
            if tex is not None:
                tex.delete()
            tex = self.targets[name] = new_texture(*size)
            self._sizes[name] = size
        return tex

    # -- one camera -------------------------------------------------------------------------------
    def draw(self, v: CameraView, canvas: Canvas, first: bool, background: tuple[int, ...],
             scene: Any, cams: list[tuple[int, Camera]]) -> None:  # fmt: skip
        """Draw ``v``'s camera: ``scene(v, rect)`` draws the world into the bound target."""
        cam = v.camera
        if cam.target is not None:
            tex = self.target(cam.target, cams, canvas.size)
            with drawing_into(tex):
                clear(_color(cam.background) if cam.background else (0.0, 0.0, 0.0, 0.0))
                self._through_post(v, (0, 0, tex.width, tex.height), canvas, None, scene)
            return
        rect = canvas.sub_rect(cam.viewport)
        fill: tuple[int, ...] | None = cam.background
        if fill is None and first and cam.post:
            fill = (*background[:3], 255)
        self._through_post(v, rect, canvas, fill, scene)

    def _through_post(self, v: CameraView, rect: Rect, canvas: Canvas,
                      fill: tuple[int, ...] | None, scene: Any) -> None:  # fmt: skip
        cam = v.camera
        if not cam.post:
            if fill is not None:
                _clear_rect(rect, _color(fill))
            scene(v, rect)
            return
        chain = self.chains.get(v.entity)
        if chain is None:
            chain = self.chains[v.entity] = PostChain()
        buf = chain.begin((rect[2], rect[3]))
        with drawing_into(buf, rect[2], rect[3]):
            clear(_color(fill) if fill is not None else (0.0, 0.0, 0.0, 0.0))
            scene(v, (0, 0, rect[2], rect[3]))
        rows = v.size[1]
        chain.finish(cam.post, rect, rows, self.textures)

    def scene_pass(self, window: Any, v: CameraView, rect: Rect, snap: bool) -> None:
        """Set up the GL state of a camera pass over ``rect`` (framebuffer pixels)."""
        st = self.state
        gl.glViewport(*rect)
        gl.glEnable(gl.GL_SCISSOR_TEST)
        gl.glScissor(*rect)
        st.scissor = rect
        window.projection = ortho(*v.size)
        st.matrices[0] = st.matrices[1] = v.matrix
        layers = v.camera.layers
        if layers is None:
            st.shows = _world_spaces
        else:
            st.shows = lambda layer, space: space != SCREEN and layer in layers
        FrameUniforms.snap = (1.0 / v.camera.scale) if snap else 0.0

    def screen_pass(self, window: Any, canvas: Canvas) -> None:
        """Set up the screen-space pass (HUD text) over the whole canvas."""
        st = self.state
        gl.glViewport(*canvas.rect)
        gl.glEnable(gl.GL_SCISSOR_TEST)
        gl.glScissor(*canvas.rect)
        st.scissor = canvas.rect
        window.projection = ortho(*canvas.size)
        st.shows = _screen_only
        FrameUniforms.snap = 0.0

    def end(self) -> None:
        self.state.shows = None
        gl.glDisable(gl.GL_SCISSOR_TEST)

    def forget(self, keep: set[int]) -> None:
        """Free the post chains of cameras gone or without a stack."""
        for entity in [e for e in self.chains if e not in keep]:
            self.chains.pop(entity).close()

    def close(self) -> None:
        for chain in self.chains.values():
            chain.close()
        self.chains.clear()
        for tex in self.targets.values():
            tex.delete()
        self.targets.clear()


def _world_spaces(layer: int, space: int) -> bool:
    return space != SCREEN


def _screen_only(layer: int, space: int) -> bool:
    return space == SCREEN


def _color(c: tuple[int, ...]) -> tuple[float, float, float, float]:
    a = c[3] / 255.0 if len(c) > 3 else 1.0
    return (c[0] / 255.0 * a, c[1] / 255.0 * a, c[2] / 255.0 * a, a)


def _clear_rect(rect: Rect, color: tuple[float, float, float, float]) -> None:
    gl.glEnable(gl.GL_SCISSOR_TEST)
    gl.glScissor(*rect)
    clear(color)
    gl.glDisable(gl.GL_SCISSOR_TEST)


def letterbox(canvas: Canvas, background: tuple[int, ...], window: bool = False) -> None:
    """Clear for a frame: bars colour around the canvas, the background inside it.

    In integer mode the canvas is a texture of its own: ``window=True`` clears the
    window around it (bars only), else the texture (background).
    """
    res: Resolution | None = canvas.resolution
    if res is not None and canvas.integer and window:
        gl.glViewport(0, 0, *canvas.framebuffer)
        clear(_color((*res.bars, 255)))
    elif res is not None and not canvas.integer:
        gl.glViewport(0, 0, *canvas.framebuffer)
        clear(_color((*res.bars, 255)))
        _clear_rect(canvas.rect, _color((*background[:3], 255)))
    else:
        clear(_color((*background[:3], 255)))


def text_scales(cams: list[Camera], canvas: Canvas) -> tuple[float, float]:
    """(world text, screen text) raster scales: framebuffer pixels per text pixel (the
    largest any camera shows world text at)."""
    world = 0.0
    for cam in cams:
        px = 1.0 if cam.target is not None else canvas.pixel_scale
        world = max(world, cam.zoom * px)
    return (world or 1.0, canvas.pixel_scale)
