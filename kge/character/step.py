"""One fixed step of every character: intent, collide-and-slide, contacts, pushes.

In order, for all characters at once:

1. **intent** (platformers): the jump button's press is buffered, a jump starts when
   standing (or within the coyote time of it), releasing early cuts a rising jump,
   gravity acts when not standing, and a standing character is carried by its floor
   (the floor body's motion over the step, rotation included);
2. dynamic bodies pressing into a character push it (their approach speed times
   their share of the two masses);
3. **move**: collide-and-slide (:mod:`kge.character.mover`), then a step up onto a
   ledge that blocked a standing character, then a snap down to the floor for a
   character that stood and is not rising;
4. **contacts** where it ends: the floor under it (the most upward-facing floor it
   touches), the walls and ceilings that blocked it, landings;
5. **pushes**: dynamic bodies it walked into get the impulse that gives them its
   speed along the push, at most ``push_force`` times the step; a dynamic floor
   carries its weight.

One-way platforms are met only by characters above them at the start of the step
(not overlapping, on the side ``OneWayPlatform.up`` faces); ``drop_through``
ignores the ones under its feet until it has fallen clear of them.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from kge.character import planes
from kge.character.batch import Batch
from kge.character.bodies import Bodies
from kge.character.contacts import CHARACTER, MARGIN, SKIN, Pairs, build
from kge.character.mover import (
    CAST_TOLERANCE,
    Blocks,
    slide,
    snap_down,
    step_up,
    touching,
    walkable,
)
from kge.character.obstacles import DYNAMIC, KINEMATIC, Obstacles
from kge.character.state import CharacterState

#: a one-way platform is met while the character overlaps it by less than this (m)
ONE_WAY_DEPTH = 1e-3


@dataclass(slots=True)
class Result:
    """What one step did to each character (rows as in the batch)."""

    pos: np.ndarray
    velocity: np.ndarray
    on_floor: np.ndarray
    on_wall: np.ndarray
    on_ceiling: np.ndarray
    floor_normal: np.ndarray
    wall_normal: np.ndarray
    ceiling_normal: np.ndarray
    floor_collider: np.ndarray
    wall_collider: np.ndarray
    floor_velocity: np.ndarray
    jumped: np.ndarray
    landed: np.ndarray
    hard_landing: np.ndarray
    landing_speed: np.ndarray
    #: impulses for dynamic bodies: (body entities, impulses (n, 2), points (n, 2))
    impulses: tuple[np.ndarray, np.ndarray, np.ndarray]


def _dot(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    return np.einsum("nd,nd->n", a, b)


def _first_per_row(rows: np.ndarray, *keys: np.ndarray) -> np.ndarray:
    """Index of the first item of each distinct row after sorting by ``keys`` (last key
    most significant, as np.lexsort), one per row."""
    order = np.lexsort((*keys, rows))
    r = rows[order]
    first = np.ones(len(r), bool)
    first[1:] = r[1:] != r[:-1]
    return order[first]


class Stepper:
    """Runs :func:`advance` for one world (its state persists across steps)."""

    def __init__(self) -> None:
        self.state = CharacterState()
        self.dt = 1.0 / 60.0
        #: the state rows of the last batch advanced
        self.slots = np.zeros(0, np.int64)

    def advance(self, batch: Batch, colliders: np.ndarray, obstacles: Obstacles, bodies: Bodies,
                gravity: tuple[float, float], dt: float, max_translation: float,
                physics: object) -> Result:
        state = self.state
        self.dt = dt
        slots = self.slots = state.rows(batch.entity)
        c = len(batch)
        up = batch.up
        plat = batch.platformer
        was_floor = state["on_floor"][slots] & plat
        floor_body = state["floor_body"][slots]
        v = batch.velocity.copy()
        g = np.array(gravity, dtype=np.float64)

        # -- pairs within reach of anything this step can do -----------------------------
        carry = np.zeros((c, 2))
        riding = np.flatnonzero(was_floor & (floor_body >= 0))
        if len(riding):
            carry[riding], _ = bodies.motion(floor_body[riding], batch.pos[riding])
        speed = (np.hypot(v[:, 0], v[:, 1]) + batch.jump_speed
                 + float(np.hypot(*g)) * np.abs(batch.gravity_scale) * dt)
        others = float(np.abs(bodies.velocity[:, :2]).max(initial=0.0))  # dynamic bodies
        reach = (speed + 2.0 * others) * dt + np.hypot(carry[:, 0], carry[:, 1])
        reach += np.maximum(batch.step, batch.snap) + SKIN + MARGIN
        pairs = build(batch, obstacles.static, obstacles.moving, reach, colliders)
        self._one_way(batch, pairs, bodies)
        fresh = np.flatnonzero(state.fresh & plat)
        if len(fresh):  # a character spawned standing on something stands from its first step
            was_floor, floor_body = self._first_floor(batch, pairs, bodies, fresh, was_floor,
                                                      floor_body, carry)

        # -- 1. intent -------------------------------------------------------------------
        pressed = batch.jump & ~state["jump_held"][slots]
        buffer = np.where(pressed, batch.buffer, np.maximum(state["buffer"][slots] - dt, 0.0))
        air = state["air_time"][slots]
        jumped_before = state["jumped"][slots]
        grounded = was_floor | ((air <= batch.coyote) & ~jumped_before)
        do_jump = plat & (batch.jump_speed > 0.0) & grounded & (pressed | (buffer > 0.0))
        floor_v = np.stack([state["floor_vx"][slots], state["floor_vy"][slots]], axis=1)
        if do_jump.any():
            vu = _dot(v, up)
            carried = np.where(was_floor[:, None], floor_v, 0.0)
            jump_v = v - vu[:, None] * up + batch.jump_speed[:, None] * up + carried
            v = np.where(do_jump[:, None], jump_v, v)
        buffer[do_jump] = 0.0
        rising = state["rising"][slots] | do_jump
        vu = _dot(v, up)
        cut = plat & rising & ~batch.jump & (vu > 0.0) & ~do_jump
        v -= ((1.0 - batch.jump_cut) * np.where(cut, vu, 0.0))[:, None] * up
        rising = rising & ~cut & (_dot(v, up) > 0.0)
        airborne = plat & (~was_floor | do_jump | (_dot(v, up) > 1e-12))
        v[airborne] += (g[None, :] * batch.gravity_scale[airborne, None]) * dt
        standing = plat & ~airborne
        into = np.minimum(_dot(v, up), 0.0)
        v[standing] -= into[standing, None] * up[standing]
        delta = v * dt
        delta[standing] += carry[standing]
        step_ok = standing & (batch.step > 0.0)

        # -- 2. dynamic bodies pushing in ----------------------------------------------------
        shove = self._pushed(batch, pairs, bodies, v, physics)
        if shove is not None:
            v += shove
            delta += shove * dt
        # Box2D's cap on a step's move, as for every body
        length = np.hypot(delta[:, 0], delta[:, 1])
        over = length > max_translation
        if over.any():
            delta[over] *= (max_translation / length[over])[:, None]

        # -- 3. move ------------------------------------------------------------------------
        rows = np.arange(c)
        blocks = Blocks()
        end = slide(batch, pairs, rows, batch.pos, delta, batch.slides, blocks)
        b_row, b_n, b_q, b_pair, b_at = blocks.arrays()
        b_up = _dot(b_n, up[b_row])
        b_solid = pairs.kind[b_pair] != CHARACTER
        b_floor = walkable(batch, b_row, b_at, b_n, b_q)
        b_ceiling = plat[b_row] & (b_up <= -batch.floor_cos[b_row])
        b_wall = b_solid & ~b_floor & ~b_ceiling
        climb = np.zeros(c, bool)
        # a wall in the way, or the edge of a step too steep to roll up quickly: try
        # stepping up onto it
        ledge = b_wall | (b_floor & (b_up < batch.floor_cos[b_row]))
        climb[b_row[ledge & b_solid & (_dot(b_n, delta[b_row]) < 0.0)]] = True
        climb &= step_ok
        if climb.any():
            r = np.flatnonzero(climb)
            end[r], _ = step_up(batch, pairs, r, batch.pos[r], delta[r], end[r])
        # down onto the floor: a standing character follows it down slopes and steps (up
        # to snap_length), and any falling one that ends within the contact margin of a
        # floor settles on it, so nothing stands a hair above its floor
        settle = SKIN + MARGIN
        drop = np.where(standing, np.maximum(batch.snap, settle), 0.0)
        drop = np.where(plat & ~standing & (_dot(v, up) <= 0.0), settle, drop)

        # -- 4. contacts where it ends --------------------------------------------------------
        t_idx, t_at, t_sd, t_n, t_pt = touching(batch, pairs, rows, end)
        on = walkable(batch, t_at, end[t_at], t_n, t_pt) & (pairs.kind[t_idx] != CHARACTER)
        resting = np.zeros(c, bool)  # already on a floor at the separation kept
        resting[t_at[on & (t_sd <= pairs.target[t_idx] + CAST_TOLERANCE)]] = True
        r = np.flatnonzero((drop > 0.0) & ~resting)
        if len(r):
            end[r], snapped = snap_down(batch, pairs, r, end[r], drop[r])
            r = r[snapped]
            if len(r):  # their contacts, where they are now
                keep = ~np.isin(t_at, r)
                n_idx, n_at, n_sd, n_n, n_pt = touching(batch, pairs, r, end[r])
                t_idx = np.concatenate([t_idx[keep], n_idx])
                t_at = np.concatenate([t_at[keep], r[n_at]])
                t_sd = np.concatenate([t_sd[keep], n_sd])
                t_n = np.concatenate([t_n[keep], n_n])
                t_pt = np.concatenate([t_pt[keep], n_pt])
        t_up = _dot(t_n, up[t_at])
        is_floor = walkable(batch, t_at, end[t_at], t_n, t_pt) & (pairs.kind[t_idx] != CHARACTER)
        on_floor = np.zeros(c, bool)
        floor_normal = np.zeros((c, 2))
        floor_collider = np.full(c, -1, np.int64)
        new_floor_body = np.full(c, -1, np.int64)
        floor_velocity = np.zeros((c, 2))
        floor_point = np.zeros((c, 2))
        f = np.flatnonzero(is_floor)
        if len(f):
            best = f[_first_per_row(t_at[f], t_sd[f], -t_up[f])]
            fr = t_at[best]
            on_floor[fr] = True
            floor_normal[fr] = t_n[best]
            floor_collider[fr] = pairs.collider[t_idx[best]]
            floor_point[fr] = t_pt[best]
            moving = pairs.kind[t_idx[best]] != 0
            mr = fr[moving]
            new_floor_body[mr] = pairs.body[t_idx[best][moving]]
            if len(mr):
                _, floor_velocity[mr] = bodies.motion(new_floor_body[mr], t_pt[best][moving])
        on_wall = np.zeros(c, bool)
        on_ceiling = np.zeros(c, bool)
        wall_normal = np.zeros((c, 2))
        ceiling_normal = np.zeros((c, 2))
        wall_collider = np.full(c, -1, np.int64)
        for mask, flag, normal, which in ((b_wall, on_wall, wall_normal, wall_collider),
                                          (b_ceiling & b_solid, on_ceiling, ceiling_normal, None)):
            k = np.flatnonzero(mask)
            if len(k):
                last = k[_first_per_row(b_row[k], -np.arange(len(k)))]
                flag[b_row[last]] = True
                normal[b_row[last]] = b_n[last]
                if which is not None:
                    which[b_row[last]] = pairs.collider[b_pair[last]]

        # a platformer keeps its sideways speed landing on a slope (the floor takes what
        # falls into it, along up) and gains no upward speed from a steep slope it runs
        # into (that takes the sideways part, as an upright wall)
        clip_n = b_n.copy()
        clip_n[b_floor] = up[b_row[b_floor]]
        steep = b_wall & plat[b_row] & (b_up > 1e-9)
        if steep.any():
            side = b_n[steep] - b_up[steep, None] * up[b_row[steep]]
            clip_n[steep] = side / np.hypot(side[:, 0], side[:, 1])[:, None]
        out = planes.clip(v, clip_n[b_solid], b_row[b_solid])
        out[np.abs(out) < 1e-12] = 0.0  # what clipping leaves of a speed into a surface
        out_up = _dot(out, up)
        sink = on_floor & (out_up < 0.0)
        out[sink] -= out_up[sink, None] * up[sink]
        jumped = do_jump
        landed = on_floor & ~was_floor
        landing_speed = np.where(landed, np.maximum(-_dot(v, up), 0.0), 0.0)
        hard = landed & (landing_speed >= batch.hard_speed)

        # -- 5. pushes ---------------------------------------------------------------------------
        impulses = self._push(batch, pairs, bodies, v, t_idx, t_at, t_n, t_pt, on_floor,
                              floor_point, new_floor_body, g, dt, physics)

        # -- remember -------------------------------------------------------------------------
        self._forget_passed(batch, pairs, end)
        state["on_floor"][slots] = on_floor
        state["air_time"][slots] = np.where(on_floor, 0.0, air + dt)
        state["buffer"][slots] = buffer
        state["jump_held"][slots] = batch.jump
        state["rising"][slots] = rising & ~on_floor
        state["jumped"][slots] = (jumped_before | do_jump) & ~(on_floor & ~do_jump)
        state["floor_body"][slots] = new_floor_body
        state["floor_collider"][slots] = floor_collider
        state["floor_vx"][slots] = floor_velocity[:, 0]
        state["floor_vy"][slots] = floor_velocity[:, 1]
        return Result(end, out, on_floor, on_wall, on_ceiling, floor_normal, wall_normal,
                      ceiling_normal, floor_collider, wall_collider, floor_velocity, jumped,
                      landed, hard,
                      landing_speed, impulses)

    def _first_floor(self, batch: Batch, pairs: Pairs, bodies: Bodies, rows: np.ndarray,
                     was_floor: np.ndarray, floor_body: np.ndarray, carry: np.ndarray
                     ) -> tuple[np.ndarray, np.ndarray]:
        """New characters touching a floor where they are stand on it (and ride it)."""
        t_idx, t_at, t_sd, t_n, t_pt = touching(batch, pairs, rows, batch.pos[rows])
        on = walkable(batch, rows[t_at], batch.pos[rows[t_at]], t_n, t_pt) & (
            pairs.kind[t_idx] != CHARACTER
        )
        f = np.flatnonzero(on)
        if len(f) == 0:
            return was_floor, floor_body
        best = f[_first_per_row(t_at[f], t_sd[f])]
        r = rows[t_at[best]]
        was_floor = was_floor.copy()
        floor_body = floor_body.copy()
        was_floor[r] = True
        moving = pairs.kind[t_idx[best]] != 0
        floor_body[r[moving]] = pairs.body[t_idx[best][moving]]
        if moving.any():
            carry[r[moving]], _ = bodies.motion(floor_body[r[moving]], batch.pos[r[moving]])
        return was_floor, floor_body

    # -- one-way platforms ------------------------------------------------------------------------
    def _one_way(self, batch: Batch, pairs: Pairs, bodies: Bodies) -> None:
        """Switch off the one-way pairs a character is not above (or drops through)."""
        oneway = np.flatnonzero(~np.isnan(pairs.oneway[:, 0]))
        if len(oneway) == 0:
            return
        rows = pairs.char[oneway]
        pos = batch.pos[rows]
        # a kinematic platform is placed where the step leaves it: compare the character
        # with it as it is now, i.e. moved by the platform's own motion
        kin = pairs.kind[oneway] == KINEMATIC
        if kin.any():
            shift, _ = bodies.motion(pairs.body[oneway[kin]], pos[kin])
            pos = pos.copy()
            pos[kin] += shift
        sd, n, _ = pairs.measure(batch, oneway, pos)
        up = pairs.oneway[oneway, :2]
        above = (sd > -ONE_WAY_DEPTH) & (_dot(n, up) >= pairs.oneway[oneway, 2])
        passing = self.state.passing
        ents = batch.entity[rows]
        dropping = batch.drop[rows] & batch.platformer[rows]
        for k in np.flatnonzero(dropping & (sd < pairs.target[oneway] + MARGIN)).tolist():
            passing.setdefault(int(ents[k]), set()).add(int(pairs.collider[oneway[k]]))
        if passing:
            through = np.array([int(col) in passing.get(int(e), ())
                                for e, col in zip(ents, pairs.collider[oneway], strict=True)])
            above &= ~through
        pairs.live[oneway] = above & ~dropping

    def _forget_passed(self, batch: Batch, pairs: Pairs, end: np.ndarray) -> None:
        """Characters clear of a platform they dropped through may land on it again."""
        passing = self.state.passing
        if not passing:
            return
        row_of = {int(e): k for k, e in enumerate(batch.entity.tolist())}
        for e in list(passing):
            k = row_of.get(e)
            if k is None:
                del passing[e]
                continue
            idx = np.arange(pairs.first[k], pairs.first[k] + pairs.count[k])
            idx = idx[np.isin(pairs.collider[idx], list(passing[e]))]
            still: set[int] = set()
            if len(idx):
                sd, _, _ = pairs.measure(batch, idx, np.repeat(end[k:k + 1], len(idx), 0))
                still = {int(col) for col in pairs.collider[idx][sd < pairs.target[idx] + MARGIN]}
            if still:
                passing[e] = still
            else:
                del passing[e]

    # -- pushes ---------------------------------------------------------------------------------
    def _pushed(self, batch: Batch, pairs: Pairs, bodies: Bodies, v: np.ndarray,
                physics: object) -> np.ndarray | None:
        """Velocity given to each character by dynamic bodies moving into it."""
        dyn = np.flatnonzero((pairs.kind == DYNAMIC) & pairs.live)
        if len(dyn) == 0:
            return None
        rows = pairs.char[dyn]
        movable = np.isfinite(batch.mass[rows])
        dyn, rows = dyn[movable], rows[movable]
        if len(dyn) == 0:
            return None
        sd, n, point = pairs.measure(batch, dyn, batch.pos[rows])
        _, vb = bodies.motion(pairs.body[dyn], point)
        approach = _dot(vb - v[rows], n)
        # touching, or closing in fast enough to meet it within this step
        go = (approach > 0.0) & (sd - pairs.target[dyn] < approach * self.dt + MARGIN)
        if not go.any():
            return None
        dyn, rows, n, approach = dyn[go], rows[go], n[go], approach[go]
        mb = np.array([physics.mass_data(int(e)).mass  # type: ignore[attr-defined]
                       for e in pairs.body[dyn].tolist()])
        share = mb / (mb + batch.mass[rows])
        out = np.zeros((len(batch), 2))
        np.add.at(out, rows, (share * approach)[:, None] * n)
        return out

    def _push(self, batch: Batch, pairs: Pairs, bodies: Bodies, v: np.ndarray,
              t_idx: np.ndarray, t_at: np.ndarray, t_n: np.ndarray, t_pt: np.ndarray,
              on_floor: np.ndarray, floor_point: np.ndarray, floor_body: np.ndarray,
              g: np.ndarray, dt: float, physics: object
              ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        ents: list[np.ndarray] = []
        imps: list[np.ndarray] = []
        pts: list[np.ndarray] = []
        dyn = (pairs.kind[t_idx] == DYNAMIC) & (batch.push_force[t_at] > 0.0)
        if dyn.any():
            idx, rows, n, pt = t_idx[dyn], t_at[dyn], t_n[dyn], t_pt[dyn]
            bodies_e = pairs.body[idx]
            _, vb = bodies.motion(bodies_e, pt)
            approach = _dot(v[rows] - vb, -n)  # how fast it walks into the body
            go = approach > 0.0
            if go.any():
                idx, rows, n, pt, bodies_e = idx[go], rows[go], n[go], pt[go], bodies_e[go]
                approach = approach[go]
                eff = np.array([_effective_mass(physics, int(e), p, -nn, bodies)
                                for e, p, nn in zip(bodies_e.tolist(), pt, n, strict=True)])
                j = np.minimum(eff * approach, batch.push_force[rows] * dt)
                ents.append(bodies_e)
                imps.append(-n * j[:, None])
                pts.append(pt)
        weight = on_floor & (floor_body >= 0) & np.isfinite(batch.mass) & batch.platformer
        if weight.any():
            r = np.flatnonzero(weight)
            dynamic = bodies.kind_of(floor_body[r]) == DYNAMIC
            r = r[dynamic]
            if len(r):
                ents.append(floor_body[r])
                imps.append((batch.mass[r] * batch.gravity_scale[r] * dt)[:, None] * g[None, :])
                pts.append(floor_point[r])
        if not ents:
            z = np.zeros(0, np.int64)
            return z, np.zeros((0, 2)), np.zeros((0, 2))
        return np.concatenate(ents), np.concatenate(imps), np.concatenate(pts)


def _effective_mass(physics: object, e: int, point: np.ndarray, direction: np.ndarray,
                    bodies: Bodies) -> float:
    """The mass a push along ``direction`` at ``point`` meets (Box2D's normal mass)."""
    md = physics.mass_data(e)  # type: ignore[attr-defined]
    if md.mass <= 0.0:
        return 0.0
    cx, cy = bodies.center_world(e)
    rx, ry = point[0] - cx, point[1] - cy
    rn = rx * direction[1] - ry * direction[0]
    inv = 1.0 / md.mass + (rn * rn / md.inertia if md.inertia > 0.0 and math.isfinite(
        md.inertia) else 0.0)
    return 1.0 / inv
