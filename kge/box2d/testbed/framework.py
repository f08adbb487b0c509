"""The testbed framework pybox2d's examples subclass: ``Framework``, ``Keys``, ``main``.

pybox2d's examples start with ``from Box2D.examples.framework import (Framework,
Keys, main)``, subclass ``Framework``, override ``Step``, ``Keyboard`` and the
contact callbacks, and end with ``main(TheirTest)``. This module is kge's
implementation of that contract, written to the behaviour pybox2d's testbed
documents: the world (gravity (0, -10), sleeping on), the destruction and
contact listeners, the per-step work of ``Step(settings)`` (time step from
``settings.hz``, pause and single step, debug-draw flags, warm starting /
continuous / sub-stepping switches, ``world.Step`` then ``ClearForces``, the
debug drawing, the bomb removed once asleep, the mouse joint, bomb aim line,
contact points and normals, statistics), picking with a mouse joint, the
slingshot and random bombs, the contact points gathered in ``PreSolve``, the
view (``viewCenter``, ``viewZoom``, ``ConvertScreenToWorld``), text
(``Print``, ``DrawStringAt``) and the testbed keys (z / x zoom, space bomb,
F1 menu, F2 single step, arrows pan, Home resets the view).

It runs on whichever ``Box2D`` is in ``sys.modules`` when it is loaded:
kge.box2d (``python -m kge.box2d.testbed``, or when nothing is), or the real
pybox2d for side-by-side comparisons (:mod:`kge.box2d.testbed.examples` loads
one copy per engine). How frames are shown and events arrive is the *backend*'s business
(:mod:`~kge.box2d.testbed.headless`, :mod:`~kge.box2d.testbed.window`):
``Framework.run()`` hands the test to :data:`backend`.
"""

from __future__ import annotations

import sys
from time import perf_counter
from typing import Any, ClassVar, Protocol

import kge.box2d
from kge.box2d.testbed.keys import Keys
from kge.box2d.testbed.settings import fwSettings

__all__ = ["Framework", "FrameworkBase", "Keys", "fwSettings", "main"]

#: the engine: whatever is installed as ``Box2D`` when this module loads (see the notes),
#: kge.box2d when nothing is
b2: Any = sys.modules.get("Box2D") or kge.box2d

#: pixels per metre, view centre (m) and screen size (px) a test starts with
START_ZOOM = 10.0
START_CENTER = (0.0, 20.0)
SCREEN = (640, 480)
#: the first text line's distance from the top, and the distance between lines (px)
TEXT_TOP, TEXT_LINE = 30, 15
ZOOM_LIMITS = (0.02, 50.0)


class Sink(Protocol):
    """Where :class:`TestbedDraw` sends a frame's primitives: screen pixels, y down from
    the top (what pybox2d's backends draw), radii and sizes in pixels."""

    def start(self) -> None: ...
    def end(self) -> None: ...
    def polygon(self, points: list[tuple[float, float]], color: Any, filled: bool) -> None: ...
    def circle(self, center: tuple[float, float], radius: float, color: Any,
               filled: bool) -> None: ...
    def segment(self, p1: tuple[float, float], p2: tuple[float, float], color: Any) -> None: ...
    def point(self, p: tuple[float, float], size: float, color: Any) -> None: ...


class TestbedDraw(b2.b2DrawExtended):
    """The framework's debug renderer: Box2D (and the examples) hand it screen pixels, as
    pybox2d's backends get them, and it passes them to its :class:`Sink` (kge drawables in
    a window, a record when headless)."""

    __test__ = False  # not a pytest class

    def __init__(self, test: Framework, sink: Sink, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.test = test
        self.sink = sink
        self.flipX = False
        self.flipY = True
        self.convertVertices = True
        self.axisScale = 10.0  # pixels of a drawn contact normal

    def to_world(self, p: Any) -> tuple[float, float]:
        """The world point of screen pixel ``p`` (the inverse of ``to_screen``)."""
        x, y = float(p[0]), float(p[1])
        if self.flipX:
            x = self.screenSize[0] - x
        if self.flipY:
            y = self.screenSize[1] - y
        return ((x + self.offset[0]) / self.zoom, (y + self.offset[1]) / self.zoom)

    def StartDraw(self) -> None:
        test = self.test
        self.zoom = test.viewZoom
        self.center = test.viewCenter
        self.offset = test.viewOffset
        self.screenSize = test.screenSize
        self.sink.start()

    def EndDraw(self) -> None:
        self.sink.end()

    def DrawPoint(self, p: Any, size: float, color: Any) -> None:
        self.sink.point((p[0], p[1]), float(size), color)

    def DrawAABB(self, aabb: Any, color: Any) -> None:
        lo, hi = aabb.lowerBound, aabb.upperBound
        corners = [self.to_screen(c) for c in ((lo[0], lo[1]), (hi[0], lo[1]),
                                               (hi[0], hi[1]), (lo[0], hi[1]))]
        self.sink.polygon(corners, color, False)

    def DrawSegment(self, p1: Any, p2: Any, color: Any) -> None:
        self.sink.segment((p1[0], p1[1]), (p2[0], p2[1]), color)

    def DrawTransform(self, xf: Any) -> None:
        p = (float(xf.position[0]), float(xf.position[1]))
        x_axis, y_axis = xf.R.col1, xf.R.col2
        scale = 0.4  # m
        start = self.to_screen(p)
        for axis, color in ((x_axis, (1.0, 0.0, 0.0)), (y_axis, (0.0, 1.0, 0.0))):
            end = self.to_screen((p[0] + scale * axis[0], p[1] + scale * axis[1]))
            self.sink.segment(start, end, color)

    def DrawCircle(self, center: Any, radius: float, color: Any,
                   drawwidth: int = 1) -> None:
        self.sink.circle((center[0], center[1]), radius * self.zoom, color, False)

    def DrawSolidCircle(self, center: Any, radius: float, axis: Any, color: Any) -> None:
        c, r = (center[0], center[1]), radius * self.zoom
        self.sink.circle(c, r, color, True)
        # the radius line along the body's axis (screen y points down)
        self.sink.segment(c, (c[0] + r * axis[0], c[1] - r * axis[1]), color)

    def DrawPolygon(self, vertices: Any, color: Any) -> None:
        self.sink.polygon([(v[0], v[1]) for v in vertices], color, False)

    def DrawSolidPolygon(self, vertices: Any, color: Any) -> None:
        self.sink.polygon([(v[0], v[1]) for v in vertices], color, True)


class fwDestructionListener(b2.b2DestructionListener):
    """Tells the test when a joint or fixture goes with its body."""

    def __init__(self, test: FrameworkBase, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.test = test

    def SayGoodbye(self, obj: Any) -> None:
        if isinstance(obj, b2.b2Joint):
            if self.test.mouseJoint == obj:
                self.test.mouseJoint = None
            else:
                self.test.JointDestroyed(obj)
        elif isinstance(obj, b2.b2Fixture):
            self.test.FixtureDestroyed(obj)


class fwQueryCallback(b2.b2QueryCallback):
    """Finds the dynamic fixture under a point (for picking)."""

    def __init__(self, p: Any) -> None:
        super().__init__()
        self.point = p
        self.fixture: Any = None

    def ReportFixture(self, fixture: Any) -> bool:
        if fixture.body.type == b2.b2_dynamicBody and fixture.TestPoint(self.point):
            self.fixture = fixture
            return False  # found: stop
        return True


class FrameworkBase(b2.b2ContactListener):
    """The testbed's physics side: a world, its listeners and the per-step work."""

    name = "None"
    description: str | None = None
    TEXTLINE_START = TEXT_TOP
    colors: ClassVar[dict[str, Any]] = {
        "mouse_point": b2.b2Color(0, 1, 0),
        "bomb_center": b2.b2Color(0, 0, 1.0),
        "bomb_line": b2.b2Color(0, 1.0, 1.0),
        "joint_line": b2.b2Color(0.8, 0.8, 0.8),
        "contact_add": b2.b2Color(0.3, 0.95, 0.3),
        "contact_persist": b2.b2Color(0.3, 0.3, 0.95),
        "contact_normal": b2.b2Color(0.4, 0.9, 0.4),
    }

    def __init__(self) -> None:
        super().__init__()
        self.points: list[dict[str, Any]] = []
        self.settings = fwSettings
        self.bomb: Any = None
        self.mouseJoint: Any = None
        self.bombSpawning = False
        self.bombSpawnPoint: Any = None
        self.mouseWorld: Any = None
        self.using_contacts = False
        self.stepCount = 0
        self.renderer: Any = None
        self.world = b2.b2World(gravity=(0, -10), doSleep=True)
        self.destructionListener = fwDestructionListener(test=self)
        self.world.destructionListener = self.destructionListener
        self.world.contactListener = self
        self.t_steps: list[float] = []
        self.t_draws: list[float] = []
        self.fps = 0.0

    # -- the step ------------------------------------------------------------------------
    def Step(self, settings: Any) -> None:
        """One physics step and its drawing (call it from your ``Step``)."""
        self.stepCount += 1
        time_step = 1.0 / settings.hz if settings.hz > 0.0 else 0.0
        if settings.pause:
            if settings.singleStep:
                settings.singleStep = False
            else:
                time_step = 0.0
            self.Print("****PAUSED****", (200, 0, 0))
        renderer = self.renderer
        if renderer is not None:
            renderer.flags = dict(
                drawShapes=settings.drawShapes, drawJoints=settings.drawJoints,
                drawAABBs=settings.drawAABBs, drawPairs=settings.drawPairs,
                drawCOMs=settings.drawCOMs,
                convertVertices=isinstance(renderer, b2.b2DrawExtended))
        world = self.world
        world.warmStarting = settings.enableWarmStarting
        world.continuousPhysics = settings.enableContinuous
        world.subStepping = settings.enableSubStepping
        self.points = []
        started = perf_counter()
        world.Step(time_step, settings.velocityIterations, settings.positionIterations)
        world.ClearForces()
        step_time = perf_counter() - started

        started = perf_counter()
        if renderer is not None:
            renderer.StartDraw()
        world.DrawDebugData()
        if self.bomb is not None and not self.bomb.awake:  # a bomb at rest goes away
            world.DestroyBody(self.bomb)
            self.bomb = None
        if renderer is not None:
            self._draw_extras(renderer, settings)
            renderer.EndDraw()
            self._statistics(settings, step_time, perf_counter() - started)

    def _draw_extras(self, renderer: Any, settings: Any) -> None:
        """The mouse joint, the bomb's aim, contact points and normals."""
        size = settings.pointSize
        if self.mouseJoint is not None:
            p1 = renderer.to_screen(self.mouseJoint.anchorB)
            p2 = renderer.to_screen(self.mouseJoint.target)
            renderer.DrawPoint(p1, size, self.colors["mouse_point"])
            renderer.DrawPoint(p2, size, self.colors["mouse_point"])
            renderer.DrawSegment(p1, p2, self.colors["joint_line"])
        if self.bombSpawning:
            start = renderer.to_screen(self.bombSpawnPoint)
            renderer.DrawPoint(start, size, self.colors["bomb_center"])
            renderer.DrawSegment(start, renderer.to_screen(self.mouseWorld),
                                 self.colors["bomb_line"])
        if self.settings.drawContactPoints:
            for point in self.points:
                kind = {b2.b2_addState: "contact_add", b2.b2_persistState: "contact_persist"}
                if point["state"] in kind:
                    renderer.DrawPoint(renderer.to_screen(point["position"]), size,
                                       self.colors[kind[point["state"]]])
        if settings.drawContactNormals:
            for point in self.points:
                p1 = renderer.to_screen(point["position"])
                n = point["normal"]
                p2 = (p1[0] + renderer.axisScale * n[0], p1[1] + renderer.axisScale * n[1])
                renderer.DrawSegment(p1, p2, self.colors["contact_normal"])

    def _statistics(self, settings: Any, step_time: float, draw_time: float) -> None:
        for times, spent in ((self.t_steps, step_time), (self.t_draws, draw_time)):
            times.append(1.0 / max(spent, b2.b2_epsilon))
            del times[:-2]
        if settings.drawFPS:
            self.Print(f"Combined FPS {int(self.fps)}")
        if settings.drawStats:
            w = self.world
            self.Print(f"bodies={w.bodyCount} contacts={w.contactCount} "
                       f"joints={w.jointCount} proxies={w.proxyCount}")
            self.Print(f"hz {int(settings.hz)} vel/pos iterations "
                       f"{settings.velocityIterations}/{settings.positionIterations}")
            self.Print(f"Potential draw rate: {sum(self.t_draws) / len(self.t_draws):.2f} fps "
                       f"Step rate: {sum(self.t_steps) / len(self.t_steps):.2f} Hz")

    def SimulationLoop(self) -> None:
        """One frame: the test's name and description, then its ``Step``."""
        self.textLine = self.TEXTLINE_START
        self.Print(self.name, (127, 127, 255))
        for line in (self.description or "").split("\n") if self.description else ():
            self.Print(line, (127, 255, 127))
        self.Step(self.settings)

    # -- mouse, bombs --------------------------------------------------------------------
    def ShiftMouseDown(self, p: Any) -> None:
        """Left button with shift: start aiming a bomb (unless dragging a body)."""
        self.mouseWorld = p
        if self.mouseJoint is None:
            self.SpawnBomb(p)

    def MouseDown(self, p: Any) -> None:
        """Left button: grab the dynamic body under ``p`` with a mouse joint."""
        if self.mouseJoint is not None:
            return
        aabb = b2.b2AABB(lowerBound=(p[0] - 0.001, p[1] - 0.001),
                         upperBound=(p[0] + 0.001, p[1] + 0.001))
        query = fwQueryCallback(p)
        self.world.QueryAABB(query, aabb)
        if query.fixture is not None:
            body = query.fixture.body
            self.mouseJoint = self.world.CreateMouseJoint(
                bodyA=self.groundbody, bodyB=body, target=p, maxForce=1000.0 * body.mass)
            body.awake = True

    def MouseUp(self, p: Any) -> None:
        if self.mouseJoint is not None:
            self.world.DestroyJoint(self.mouseJoint)
            self.mouseJoint = None
        if self.bombSpawning:
            self.CompleteBombSpawn(p)

    def MouseMove(self, p: Any) -> None:
        self.mouseWorld = p
        if self.mouseJoint is not None:
            self.mouseJoint.target = p

    def SpawnBomb(self, worldPt: Any) -> None:
        self.bombSpawnPoint = b2.b2Vec2(worldPt[0], worldPt[1])
        self.bombSpawning = True

    def CompleteBombSpawn(self, p: Any) -> None:
        """Launch the aimed bomb: faster the longer the drag (30 m/s per metre)."""
        if not self.bombSpawning:
            return
        start = self.bombSpawnPoint
        self.LaunchBomb(start, b2.b2Vec2(30.0 * (start[0] - p[0]), 30.0 * (start[1] - p[1])))
        self.bombSpawning = False

    def LaunchBomb(self, position: Any, velocity: Any) -> None:
        """A heavy 0.3 m ball from ``position`` at ``velocity`` (replaces the last bomb)."""
        if self.bomb is not None:
            self.world.DestroyBody(self.bomb)
            self.bomb = None
        self.bomb = self.world.CreateDynamicBody(
            allowSleep=True, position=position, linearVelocity=velocity,
            fixtures=b2.b2FixtureDef(shape=b2.b2CircleShape(radius=0.3), density=20,
                                     restitution=0.1))

    def LaunchRandomBomb(self) -> None:
        """A bomb from a random point 30 m up, thrown down towards the middle."""
        p = b2.b2Vec2(b2.b2Random(-15.0, 15.0), 30.0)
        self.LaunchBomb(p, -5.0 * p)

    # -- contacts ------------------------------------------------------------------------
    def PreSolve(self, contact: Any, old_manifold: Any) -> None:
        """Gather the new and persisting contact points (when drawn or ``using_contacts``)."""
        settings = self.settings
        if not (settings.drawContactPoints or settings.drawContactNormals
                or self.using_contacts):
            return
        if len(self.points) > settings.maxContactPoints:
            return
        manifold = contact.manifold
        if manifold.pointCount == 0:
            return
        _, state2 = b2.b2GetPointStates(old_manifold, manifold)
        if not state2:
            return
        world_manifold = contact.worldManifold
        for i, state in enumerate(state2):
            self.points.append(dict(fixtureA=contact.fixtureA, fixtureB=contact.fixtureB,
                                    position=world_manifold.points[i],
                                    normal=world_manifold.normal.copy(), state=state))

    # BeginContact, EndContact and PostSolve are b2ContactListener's (they do nothing): a
    # test overrides them. Not defining them here keeps kge.box2d from hooking every
    # contact's post-solve for tests that do not listen.

    def FixtureDestroyed(self, fixture: Any) -> None:
        """A fixture went away with its body."""

    def JointDestroyed(self, joint: Any) -> None:
        """A joint went away with one of its bodies."""

    def Keyboard(self, key: int) -> None:
        """A key (``Keys.K_*``) was pressed."""

    def KeyboardUp(self, key: int) -> None:
        """A key was released."""

    # -- the renderer's side (Framework implements them) ----------------------------------
    def ConvertScreenToWorld(self, x: float, y: float) -> Any:
        raise NotImplementedError

    def DrawStringAt(self, x: float, y: float, str: str,
                     color: Any = (229, 153, 153, 255)) -> None:
        raise NotImplementedError

    def Print(self, str: str, color: Any = (229, 153, 153, 255)) -> None:
        raise NotImplementedError


class Framework(FrameworkBase):
    """What examples subclass: :class:`FrameworkBase` with a view, text and the testbed's
    keys; :meth:`run` hands the test to the backend (a window, or headless)."""

    def __init__(self) -> None:
        super().__init__()
        self.screenSize = b2.b2Vec2(*SCREEN)
        self._viewZoom = START_ZOOM
        self.viewCenter = START_CENTER
        self.textLine = TEXT_TOP
        #: this frame's text: (x, y from the top, text, colour)
        self.text: list[tuple[float, float, str, Any]] = []
        self.held: set[int] = set()
        self.sink: Sink = current_backend().sink(self)
        self.renderer = TestbedDraw(self, self.sink)
        self.world.renderer = self.renderer
        self.groundbody = self.world.CreateBody()

    # -- the view ------------------------------------------------------------------------
    @property
    def viewZoom(self) -> float:
        """Pixels per metre."""
        return self._viewZoom

    @viewZoom.setter
    def viewZoom(self, zoom: float) -> None:
        center = self.viewCenter
        self._viewZoom = float(zoom)
        self.viewCenter = center

    @property
    def viewCenter(self) -> Any:
        """The world point at the middle of the screen."""
        return b2.b2Vec2(self._center[0], self._center[1])

    @viewCenter.setter
    def viewCenter(self, value: Any) -> None:
        self._center = (float(value[0]), float(value[1]))

    @property
    def viewOffset(self) -> Any:
        """The world-to-screen offset (pixels): ``centre * zoom - screen / 2``."""
        z = self._viewZoom
        return b2.b2Vec2(self._center[0] * z - self.screenSize[0] / 2,
                         self._center[1] * z - self.screenSize[1] / 2)

    def setCenter(self, value: Any) -> None:
        self.viewCenter = value

    def setZoom(self, zoom: float) -> None:
        self.viewZoom = zoom

    def ConvertScreenToWorld(self, x: float, y: float) -> Any:
        """The world point at screen pixel (x, y), y down from the top."""
        offset, z = self.viewOffset, self._viewZoom
        return b2.b2Vec2((x + offset[0]) / z, (self.screenSize[1] - y + offset[1]) / z)

    # -- text ----------------------------------------------------------------------------
    def DrawStringAt(self, x: float, y: float, str: str,
                     color: Any = (229, 153, 153, 255)) -> None:
        self.text.append((float(x), float(y), str, color))

    def Print(self, str: str, color: Any = (229, 153, 153, 255)) -> None:
        self.text.append((5.0, float(self.textLine), str, color))
        self.textLine += TEXT_LINE

    def SimulationLoop(self) -> None:
        self.text = []
        super().SimulationLoop()

    # -- keys ----------------------------------------------------------------------------
    def KeyDown(self, key: int) -> None:
        """A key went down: the testbed's own keys, else the test's ``Keyboard``."""
        self.held.add(key)
        if key == Keys.K_z:
            self.viewZoom = min(1.1 * self.viewZoom, ZOOM_LIMITS[1])
        elif key == Keys.K_x:
            self.viewZoom = max(0.9 * self.viewZoom, ZOOM_LIMITS[0])
        elif key == Keys.K_SPACE:
            self.LaunchRandomBomb()
        elif key == Keys.K_F1:
            self.settings.drawMenu = not self.settings.drawMenu
        elif key == Keys.K_F2:
            self.settings.singleStep = True
        else:
            self.Keyboard(key)

    def KeyUp(self, key: int) -> None:
        self.held.discard(key)
        self.KeyboardUp(key)

    def CheckKeys(self) -> None:
        """Keys acting while held: arrows pan half a metre a frame, Home resets the view."""
        held, (cx, cy) = self.held, self._center
        if Keys.K_LEFT in held:
            cx -= 0.5
        elif Keys.K_RIGHT in held:
            cx += 0.5
        if Keys.K_UP in held:
            cy += 0.5
        elif Keys.K_DOWN in held:
            cy -= 0.5
        self._center = (cx, cy)
        if Keys.K_HOME in held:
            self._viewZoom = 1.0
            self.viewCenter = START_CENTER

    def Frame(self) -> None:
        """One frame as a backend runs it: held keys, then the simulation loop."""
        self.CheckKeys()
        self.SimulationLoop()

    def run(self) -> None:
        """Run the test until the backend stops (the window closes, the steps are done)."""
        current_backend().run(self)
        self.world.contactListener = None
        self.world.destructionListener = None
        self.world.renderer = None


class Backend(Protocol):
    """Shows a running test and feeds it events: a window, or headless steps."""

    def sink(self, test: Framework) -> Sink: ...
    def run(self, test: Framework) -> None: ...


#: the backend ``Framework.run()`` uses; the runner sets it (None: pick one on first use)
backend: Backend | None = None


def current_backend() -> Backend:
    """:data:`backend`, or (first use) a window when there is a display, else headless."""
    global backend
    if backend is None:
        from kge.box2d.testbed.backends import default_backend

        backend = default_backend()
    return backend


def main(test_class: type[Framework]) -> None:
    """Build ``test_class`` and run it (``fwSettings.onlyInit``: build only)."""
    print(f"Loading {test_class.name}...")
    test = test_class()
    if fwSettings.onlyInit:
        return
    test.run()
