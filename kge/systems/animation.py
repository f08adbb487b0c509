"""Animation systems and the plugin that installs them: sprite clips, tweens, camera shake.

===========================  ======================  ===================================
system                       stage, set              does
===========================  ======================  ===================================
``AnimationFrameStart``      INPUT, FIRST            clears the deprecated lists
``FixedTweens``              FIXED, PRE_PHYSICS      tweens of physics bodies: velocities
``ShakeRestore``             UPDATE, FIRST           takes last frame's shake offset off
``AnimationSystem``          UPDATE, ANIMATION       advances every Animator, events, hooks
``TweenSystem``              UPDATE, ANIMATION       every other tween (after the clips)
``ShakeApply``               LATE, CAMERA_EFFECTS    decays trauma, adds this frame's offset
===========================  ======================  ===================================

Everything runs on game time: the dt the App hands to the UPDATE stage is
scaled by ``time_scale``, zero while paused, one fixed step on ``single_step``,
so animations freeze, slow down and step with the game, headless or not.

Drawing: a render pass (``before``) packs frames into an atlas and writes every
animated sprite's texture coordinates in bulk (:mod:`kge.render.animation`),
imported only when the App first renders.
"""

from __future__ import annotations

import functools
from typing import Any

from kge.animation.clips import ClipState, ClipTable
from kge.animation.events import AnimationEvent, AnimationEvents, AnimationFinished, TweenFinished
from kge.animation.shake import decayed, offset
from kge.animation.tweens import TweenHandle, Tweens
from kge.components.animation import Animator
from kge.components.camera import Camera, active_camera, clamp_view
from kge.components.shake import CameraShake
from kge.components.tracked import bind, unbind, validate_writes
from kge.errors import MissingComponentError
from kge.plugin import Plugin
from kge.render.passes import Frame, passes_for
from kge.scene import Time
from kge.schedule import Stage, System, SystemSet
from kge.snapshot import carry_running
from kge.systems.animation_checks import check_frames
from kge.systems.behaviour import BehaviourRunner
from kge.world import World, deprecate_resource, stored_resource

deprecate_resource(
    AnimationEvents,
    "read world.events(AnimationEvent) (or AnimationFinished, TweenFinished), "
    "or the Behaviour hooks (on_animation_event...)",
)


@carry_running
class Animations:
    """Every Animator of a world as numpy rows (a resource): what the systems and the
    renderer share, and what game code can ask (``frame(entity)``, ``clip(entity)``)."""

    def __init__(self, world: World) -> None:
        self.world = world
        self.state = ClipState(ClipTable())
        self._compacted_at = self._table_at = -1
        #: entity -> (clip, time, finished, fresh) from a snapshot, applied at the next sync
        self._carried: dict[int, tuple[str, float, bool, bool]] = {}
        self.dirty: set[int] = set()
        self._new: list[int] = []
        self._serials: dict[int, int] = {}
        self._conditional: set[int] = set()
        #: called with an entity whose sprite must be re-made (added/removed Animator)
        self.redraw: Any = None
        world.on_add(Animator, self._added)
        world.on_remove(Animator, self._removed)

    def _added(self, entity: int, anim: Animator) -> None:
        bind(anim, entity, self.dirty)
        self.dirty.add(entity)
        if entity not in self.state.rows:
            self._new.append(entity)
        self._serials.pop(entity, None)
        if self.redraw is not None:
            self.redraw(entity)

    def _removed(self, entity: int, anim: Animator) -> None:
        unbind(anim, self.dirty)
        self.dirty.discard(entity)
        if entity in self._new:
            self._new.remove(entity)
        self.state.remove(entity)
        self._serials.pop(entity, None)
        self._conditional.discard(entity)
        if self.redraw is not None:
            self.redraw(entity)

    # -- reading ------------------------------------------------------------------------
    def frame(self, entity: int) -> int:
        """The frame (index inside its clip) ``entity`` shows now."""
        self.sync()
        return self.state.local_frame(self._row(entity))

    def clip(self, entity: int) -> str:
        """The name of the clip ``entity`` plays."""
        return str(self.world.get(entity, Animator).current)

    def finished(self, entity: int) -> bool:
        """True once a ``once``/``hold`` clip has ended (or the animator was stopped)."""
        self.sync()
        return bool(self.state.finished[self._row(entity)])

    def _row(self, entity: int) -> int:
        row = self.state.rows.get(entity)
        if row is None:
            self.sync()  # spawned since the last frame
            row = self.state.rows.get(entity)
        if row is None:
            raise MissingComponentError(f"entity {entity} has no Animator component")
        return row

    # -- syncing from the components --------------------------------------------------------
    @property
    def table(self) -> ClipTable:
        """The clips the animators play (replaced when it is compacted)."""
        return self.state.table

    def sync(self) -> None:
        if self._new:
            self.state.add_many(self._new)
            self._new.clear()
        if self.dirty:
            for entity in sorted(self.dirty):
                self._sync_one(entity)
            self.dirty.clear()
        self.table.ensure()  # clips first played since the last frame (play() of a new one)
        if self._carried:
            self._continue_carried()
        if self.state.version != self._compacted_at or self.table.version != self._table_at:
            self.state.compact()  # rows or clips came or went: drop clips nobody plays
            self.table.ensure()
            self._compacted_at, self._table_at = self.state.version, self.table.version

    # -- snapshots (kge.snapshot.carry_running) ------------------------------------------
    def export_running(self) -> dict[int, tuple[str, float, bool, bool]]:
        """Each animator's clip and where it is in it."""
        self.sync()
        state, out = self.state, {}
        for entity, row in state.rows.items():
            anim = self.world.try_get(entity, Animator)
            if anim is not None:
                out[entity] = (str(anim.current), float(state.time[row]),
                               bool(state.finished[row]), bool(state.fresh[row]))  # fmt: skip
        return out

    def import_running(self, carried: dict[int, tuple[str, float, bool, bool]]) -> None:
        """Animators of a restored world go on from where they were (at the next sync)."""
        self._carried = dict(carried)

    def _continue_carried(self) -> None:
        state = self.state
        for entity, (clip, time, finished, fresh) in sorted(self._carried.items()):
            row = state.rows.get(entity)
            anim = self.world.try_get(entity, Animator)
            if row is None or anim is None or str(anim.current) != clip:
                continue  # gone, or playing another clip since: it starts afresh
            state.seek(row, time)
            state.finished[row] = finished
            state.fresh[row] = fresh
        self._carried.clear()

    def _sync_one(self, entity: int) -> None:
        anim = self.world.try_get(entity, Animator)
        row = self.state.rows.get(entity)
        if anim is None or row is None:
            return
        state = self.state
        slot = self.table.register(anim.clips[str(anim.current)]).slot
        state.speed[row] = anim.speed
        state.playing[row] = anim.playing
        if self._serials.get(entity) != anim.serial or state.clip[row] != slot:
            state.start(row, slot, stopped=anim.stopped)
            self._serials[entity] = anim.serial
        if any(tr.when is not None for tr in anim.transitions):
            self._conditional.add(entity)
        else:
            self._conditional.discard(entity)

    def _conditions(self) -> None:
        """Conditional transitions: switch clips whose parameter is set (entity order)."""
        for entity in sorted(self._conditional):
            anim = self.world.try_get(entity, Animator)
            if anim is None:
                continue
            for tr in anim.transitions:
                if (
                    tr.when is not None
                    and tr.src in ("*", anim.current)
                    and anim.current != tr.dst
                    and tr.holds(anim.params)
                ):
                    anim.play(tr.dst)
                    self._sync_one(entity)
                    break

    def _after_end(self, entity: int, anim: Animator) -> None:
        """A clip ended: follow an end transition, else the queue."""
        for tr in anim.transitions:
            if tr.when is None and tr.src in ("*", anim.current):
                anim.play(tr.dst)
                break
        else:
            if not anim.queued:
                return
            nxt = anim.queued.pop(0)
            rest = list(anim.queued)
            anim.play(nxt)
            anim.queued.extend(rest)
        self._sync_one(entity)


def animations(world: World) -> Animations:
    """The world's :class:`Animations`, created on first use."""
    found = world.try_resource(Animations)
    if found is None:
        found = world.insert_resource(Animations(world))
    return found


def tweens_of(world: World) -> Tweens:
    """The world's :class:`~kge.animation.tweens.Tweens`, created on first use."""
    found = world.try_resource(Tweens)
    if found is None:
        found = world.insert_resource(Tweens(world))
    return found


def events_of(world: World) -> AnimationEvents:
    """The deprecated per-frame lists (kept filled for one release)."""
    found = stored_resource(world, AnimationEvents)
    if found is None:
        found = world.insert_resource(AnimationEvents())
    return found


def _hook(world: World, entity: int | None, name: str, event: Any) -> None:
    runner = world.try_resource(BehaviourRunner)
    if runner is not None and entity is not None:
        runner.call_one(entity, name, event)


class AnimationFrameStart(System):
    """Clears the deprecated ``AnimationEvents`` lists (first thing in a frame)."""

    stage = Stage.INPUT
    in_set = SystemSet.FIRST

    def process(self, dt: float) -> None:
        events_of(self.world).clear()


class AnimationSystem(System):
    """Advances every Animator with numpy, then delivers frame and end events."""

    stage = Stage.UPDATE
    in_set = SystemSet.ANIMATION

    def attach(self, world: World) -> None:
        super().attach(world)
        self.anims = animations(world)
        self.events = events_of(world)

    def process(self, dt: float) -> None:
        anims = self.anims
        anims.sync()
        anims._conditions()
        state = anims.state
        if not len(state):
            return
        crossings = state.advance(dt)
        world = self.world
        for row, _slot, name, frame in crossings.events:
            entity = int(state.entity[row])
            anim = world.try_get(entity, Animator)
            clip = str(anim.current) if anim is not None else ""
            ev = AnimationEvent(entity, clip, name, frame)
            self.events.frame.append(ev)
            world.emit(ev)
            _hook(world, entity, "on_animation_event", ev)
        ended = sorted(int(state.entity[r]) for r in crossings.finished.tolist())
        for entity in ended:
            anim = world.try_get(entity, Animator)
            if anim is None:
                continue
            fin = AnimationFinished(entity, str(anim.current))
            self.events.finished.append(fin)
            world.emit(fin)
            _hook(world, entity, "on_animation_end", fin)
            anims._after_end(entity, anim)


def _finished(world: World, handles: list[TweenHandle]) -> None:
    events = events_of(world)
    for h in handles:
        ev = TweenFinished(h.entity, h, h.name)
        events.tweens.append(ev)
        world.emit(ev)
        _hook(world, h.entity, "on_tween_end", ev)


class TweenSystem(System):
    """Advances every tween not driving a physics body (game time, once per frame)."""

    stage = Stage.UPDATE
    in_set = SystemSet.ANIMATION
    after = (AnimationSystem,)

    def attach(self, world: World) -> None:
        super().attach(world)
        self.tweens = tweens_of(world)

    def process(self, dt: float) -> None:
        _finished(self.world, self.tweens.advance(dt, fixed=False))


class FixedTweens(System):
    """Advances tweens of physics bodies' Transforms in the fixed step, before physics."""

    stage = Stage.FIXED
    in_set = SystemSet.PRE_PHYSICS

    def attach(self, world: World) -> None:
        super().attach(world)
        self.tweens = tweens_of(world)

    def process(self, dt: float) -> None:
        if self.tweens.stop_next or len(self.tweens.g_ids):
            _finished(self.world, self.tweens.advance(dt, fixed=True))


def _shake_of(world: World, cam: Camera) -> CameraShake | None:
    for _, (c, s) in world.query(Camera, CameraShake):
        if c is cam:
            return s
    found: CameraShake | None = world.try_resource(CameraShake)
    return found


class ShakeRestore(System):
    """Takes last frame's shake offset off the camera before this frame's updates."""

    stage = Stage.UPDATE
    in_set = SystemSet.FIRST
    applied: tuple[Camera, tuple[float, float]] | None = None

    def process(self, dt: float) -> None:
        if self.applied is not None:
            cam, (ox, oy) = self.applied
            cx, cy = cam.center
            cam.center = (cx - ox, cy - oy)
            self.applied = None


class ShakeApply(System):
    """Decays trauma and adds this frame's shake offset to the active camera (LATE)."""

    stage = Stage.LATE
    in_set = SystemSet.CAMERA_EFFECTS

    def process(self, dt: float) -> None:
        world = self.world
        cam = active_camera(world)
        shake = _shake_of(world, cam) if cam is not None else world.try_resource(CameraShake)
        if shake is None or shake.trauma <= 0.0:
            return
        time = world.try_resource(Time)
        now = time.elapsed if time is not None else 0.0
        ox, oy = offset(shake.trauma, now, shake.max_offset, shake.frequency, shake.seed)
        shake.trauma = decayed(shake.trauma, shake.decay, dt)
        if cam is None:  # nothing to move (no camera yet): the trauma still decays
            return
        cx, cy = cam.center
        cam.center = (clamp_view(cx + ox), clamp_view(cy + oy))  # near the view bound
        ox, oy = cam.center[0] - cx, cam.center[1] - cy
        restore = world.get_system(ShakeRestore)
        if restore is not None:
            restore.applied = (cam, (ox, oy))


def shake(world: World, amount: float) -> CameraShake:
    """Add ``amount`` trauma to the active camera's shake (creating a CameraShake resource)."""
    cam = active_camera(world)
    found = _shake_of(world, cam) if cam is not None else world.try_resource(CameraShake)
    if found is None:
        found = world.insert_resource(CameraShake())
    found.add(amount)
    return found


class _AtlasPass:
    """The render pass: animated sprites drawn from the atlas (GL loaded only here)."""

    def __init__(self, world: World, anims: Animations) -> None:
        self.world = world
        self.anims = anims
        self.frames: Any = None
        self.current: Frame | None = None

    def __call__(self, frame: Frame) -> None:
        from kge.systems.render import RenderSystem

        rs = self.world.get_system(RenderSystem)
        if rs is None:
            return
        view = rs.view
        self.anims.sync()
        if self.frames is None:
            from kge.render.animation import AtlasFrames

            self.frames = AtlasFrames(
                self.world, self.anims.table, self.anims.state, view.sprites, self.anims.sync
            )
            view.sprites.frame_source = self.frames.frame_region
            self.anims.redraw = view.dirty.add
            self.frames.migrate = self._migrate
            # sprites made before the atlas existed move onto it now
            known = [e for e in self.anims.state.rows if e in view.sprites.sprites]
            if known:
                view.dirty.update(known)
                view.sync(frame.camera.pixels_per_meter)
                frame.poses = view.poses.blend(frame.alpha)
                view.sprites.poser.write(frame.poses, frame.view)
        self.current = frame
        self.frames.write()

    def _migrate(self, entities: list[int]) -> None:
        """Sync these sprites now: onto the atlas page of the frame they show."""
        from kge.systems.render import RenderSystem

        rs, frame = self.world.get_system(RenderSystem), self.current
        if rs is None or frame is None:
            return
        rs.view.dirty.update(entities)
        rs.view.sync(frame.camera.pixels_per_meter)
        rs.view.sprites.poser.write(frame.poses, frame.view)


class AnimationPlugin(Plugin):
    """Sprite animation (Animator + clips), tweens and camera shake. See the module docstring."""

    def build(self, world: World) -> None:
        anims = animations(world)
        tweens_of(world)
        events_of(world)
        for system in (
            AnimationFrameStart(), FixedTweens(), ShakeRestore(), AnimationSystem(),
            TweenSystem(), ShakeApply(),
        ):  # fmt: skip
            world.add_system(system)
        passes_for(world).add(_AtlasPass(world, anims), phase="before", name="animation")
        world.validator(Animator, functools.partial(check_frames, world))
        validate_writes(world, Animator)
        validate_writes(world, CameraShake)  # a bad write names its entity
