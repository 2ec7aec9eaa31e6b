//! ORCA's command for one planning agent: the obstacles' half-planes, the
//! keep-right rule completed, the neighbours' half-planes with right of
//! way by progress ([`PRIORITY_GAP`], [`PRIORITY_MARGIN`]), then the way
//! sought as it is or the linear program's velocity.

use glam::{BVec4A, Mat4, Vec2, Vec4};

use crate::avoidance::command::Command;
use crate::avoidance::keep_right::{lane_way, solve_keep_right, way_admitted};
use crate::avoidance::neighbours::{Nearest, Neighbours};
use crate::avoidance::orca::{self, Lines};
use crate::avoidance::passing::{Passing, ONCOMING_COS};
use crate::avoidance::planning::{Agent, Pass};
use crate::avoidance::stalled::STUCK_SPEED;

/// How much nearer its goal an agent must be than a neighbour, m, to have
/// the right of way over it. Much wider, the right of way goes nearly by
/// index, and agents level at the doorway jam.
pub const PRIORITY_GAP: f32 = 0.25;

/// The clearance, m, beyond the two bodies that an agent with the right of
/// way keeps from the neighbour yielding to it.
pub const PRIORITY_MARGIN: f32 = 0.15;

impl Neighbours {
    /// ORCA's command: the keep-right rule completed (the look-ahead scan,
    /// the turn into the lane), the neighbours' half-planes added, then
    /// the way sought taken as it is when every half-plane admits it, or
    /// else the linear program's velocity turned into the unicycle's
    /// heading and speed.
    #[inline(always)]
    pub(crate) fn orca_command(
        &self,
        pass: &Pass,
        a: &Agent,
        lane: &mut Passing,
        near: &Nearest,
        lines: &mut Lines,
    ) -> Command {
        if a.passing && lane.far_may_ask(&pass.far_box) {
            self.see_ahead(pass, a, lane);
        }
        let (way, turned) = lane_way(a, lane, lines);
        let oncoming = self.push_agent_lines(pass, a, way.u, near, lines);
        if way_admitted(pass, a, &way, oncoming, lines) {
            Command {
                heading: way.heading,
                speed: way.speed,
                active: turned,
                walls: false,
            }
        } else {
            solve_keep_right(pass, a, &way, oncoming, lines)
        }
    }

    /// Adds the half-planes of the k nearest neighbours to `lines`, four
    /// at a time, every test a lane mask (their outcomes flip from
    /// neighbour to neighbour: as branches they are mispredicted about
    /// every other time). Read from their records (positions and headings
    /// transposed), past the k-th the k-th again (masked). Returns whether
    /// one of them is oncoming ahead along `u_seek`, the way the agent
    /// seeks.
    #[inline(always)]
    fn push_agent_lines(
        &self,
        pass: &Pass,
        a: &Agent,
        u_seek: Vec2,
        near: &Nearest,
        lines: &mut Lines,
    ) -> bool {
        let (cfg, me, pos) = (pass.cfg, &a.peer, a.state.pos);
        let (near, k) = (&near.near, near.k);
        let record = |c: usize| &self.peers[near[c.min(k - 1)].1 as usize];
        let mut oncoming = BVec4A::FALSE;
        let v_me = me.fwd * me.v;
        // A pair's combined reach: with the right of way, the bodies'
        // clearance plus a sliver; otherwise the whole margin (both less
        // for an agent out of patience).
        let reach_ahead = 2.0 * cfg.radius + PRIORITY_MARGIN.min(2.0 * a.margin);
        let reach_yield = 2.0 * (cfg.radius + a.margin);
        let (inv_h, inv_dt) = (1.0 / cfg.horizon, 1.0 / pass.p.dt);
        let splat = Vec4::splat;
        let moving = BVec4A::splat(me.v >= STUCK_SPEED);
        let mut c = 0;
        while c < k {
            let q = [record(c), record(c + 1), record(c + 2), record(c + 3)];
            let t = Mat4::from_cols(q[0].head(), q[1].head(), q[2].head(), q[3].head()).transpose();
            let (qx, qy, fx, fy) = (t.x_axis, t.y_axis, t.z_axis, t.w_axis);
            let qv = Vec4::new(q[0].v, q[1].v, q[2].v, q[3].v);
            let prio = Vec4::new(q[0].prio, q[1].prio, q[2].prio, q[3].prio);
            // The tie direction, +y when i < j, else −y (the scalar
            // `-Vec2::Y`: x is −0), by its sign bit.
            let after = q.map(|q| u32::from(q.index <= me.index) << 31);
            let tie_x = Vec4::from_array(after.map(f32::from_bits));
            let tie_y = Vec4::from_array(after.map(|a| f32::from_bits(0x3f80_0000 | a)));
            let valid = (splat(c as f32) + Vec4::new(0.0, 1.0, 2.0, 3.0)).cmplt(splat(k as f32));
            let (rx, ry) = (qx - splat(pos.x), qy - splat(pos.y));
            // Oncoming and ahead along the way the agent will seek (its
            // goal's direction when walled, not the funnel's γ it then
            // ignores: judged along γ, a neighbour beside the way flips in
            // and out of "ahead" step after step at a doorway's wall end,
            // and the keep-right turn with it, so that at rest the velocity
            // sought swings between the gap and the wall).
            let opposed = (fx * splat(u_seek.x) + fy * splat(u_seek.y)).cmplt(splat(ONCOMING_COS));
            oncoming |=
                valid & opposed & (rx * splat(u_seek.x) + ry * splat(u_seek.y)).cmpgt(Vec4::ZERO);
            let opposed = (fx * splat(me.fwd.x) + fy * splat(me.fwd.y)).cmplt(splat(ONCOMING_COS));
            let before = tie_y.cmpgt(Vec4::ZERO);
            // Reciprocity assumes the neighbour takes half the avoidance;
            // a forward-only neighbour at rest cannot step back, so an
            // agent closing on it takes all.
            let share = Vec4::select(qv.cmplt(splat(STUCK_SPEED)) & moving, Vec4::ONE, splat(0.5));
            // Right of way: the agent clearly nearer its goal keeps only
            // the bodies' distance (plus a sliver) from the other, which
            // keeps the whole margin; the pair still never overlaps, and
            // where the margins leave no room (a doorway, a jam) the one
            // ahead gets through instead of both waiting. Within the gap
            // (two agents level at a doorway, both waiting for the other)
            // the lower index goes first. No priority given (NaN): nobody
            // is ahead.
            let pa = me.prio;
            let ahead = splat(pa + PRIORITY_GAP).cmplt(prio)
                | (before & splat(pa).cmple(prio + splat(PRIORITY_GAP)));
            let keep_right = opposed
                & (rx * splat(me.fwd.x) + ry * splat(me.fwd.y)).cmpgt(Vec4::ZERO)
                & ((splat(pos.x) - qx) * fx + (splat(pos.y) - qy) * fy).cmpgt(Vec4::ZERO);
            let pairs = orca::Pairs4 {
                pn: (qx, qy),
                vn: (fx * qv, fy * qv),
                r: Vec4::select(ahead, splat(reach_ahead), splat(reach_yield)),
                share,
                tie: (tie_x, tie_y),
                keep_right,
            };
            lines.push_agents4(&orca::agent_lines4(pos, v_me, &pairs, inv_h, inv_dt), k - c);
            c += 4;
        }
        oncoming.any()
    }
}

/// Adds the half-planes of the obstacles in reach of an agent at `pos`
/// keeping `margin` to `lines`.
#[inline(always)]
pub(crate) fn push_obstacle_lines(pass: &Pass, pos: Vec2, margin: f32, lines: &mut Lines) {
    let cfg = pass.cfg;
    for o in pass.obstacles {
        let (dist, nrm) = o.distance_normal(pos);
        if dist - pass.r < cfg.reach {
            lines.push_obstacle(orca::obstacle_line(
                nrm,
                dist,
                cfg.radius + margin,
                cfg.obstacle_horizon,
                pass.p.dt,
            ));
        }
    }
}
