//! The keep-right rule in one agent's plan (the rule itself, its asks and
//! its state, is [`crate::avoidance::passing`]): the look ahead beyond
//! reach, the turn into the lane, the way sought taken as it is or ORCA's
//! velocity, turned right by an oncoming neighbour ahead, made the
//! unicycle's command.

use glam::{Vec2, Vec4};

use crate::avoidance::command::{unicycle, Command};
use crate::avoidance::neighbours::Neighbours;
use crate::avoidance::orca::{self, Lines};
use crate::avoidance::passing::{self, Passing};
use crate::avoidance::planning::{Agent, Pass, Way, DODGE_SPEED};
use crate::avoidance::stalled;
use crate::base::trig;

/// The share of [`AvoidanceConfig::bias_deg`](crate::avoidance::config::AvoidanceConfig::bias_deg) an agent keeps right by, at
/// least, while an oncoming neighbour is ahead (the full bias once it has
/// slowed to a stop).
pub const LANE_BIAS: f32 = 0.2;

impl Neighbours {
    /// The keep-right rule's look ahead beyond reach
    /// ([`passing::LOOK_AHEAD`]): the cells round a point further along
    /// the way, so that lanes form before the groups meet. Four at a time
    /// from the lanes (the asks fold by their maximum and the mates by
    /// "any": the order does not matter; the agent itself, at distance 0,
    /// asks nothing and is no mate, [`Passing::see4`]): scalar, one peer at
    /// a time, this scan costs more than the rest of the keep-right rule.
    /// Only the cells that meet the agent's far box ([`Passing::far_box`]:
    /// about 6 of the 9), when no other cell shares their buckets: the
    /// same neighbours seen.
    #[inline(always)]
    pub(crate) fn see_ahead(&self, pass: &Pass, a: &Agent, lane: &mut Passing) {
        let pos = a.peer.pos;
        let at = pos + a.seek.u * passing::LOOK_AHEAD;
        let (far, n_far) = if pass.far_trim && pos.abs().max_element() < passing::FAR_BOX_LIMIT {
            let [fx, fy] = self.grid.cell_of(at);
            let (lo, hi) = lane.far_box(pos, &pass.far_box);
            let ([x0, y0], [x1, y1]) = (self.grid.cell_of(lo), self.grid.cell_of(hi));
            let (x0, y0) = (x0.max(fx - 1), y0.max(fy - 1));
            let (x1, y1) = (x1.min(fx + 1), y1.min(fy + 1));
            self.grid.cell_runs(
                [x0, y0],
                (x1 - x0 + 1).max(0) as u32,
                (y1 - y0 + 1).max(0) as u32,
            )
        } else {
            self.grid.candidate_runs(at)
        };
        let (mx, my) = (Vec4::splat(pos.x), Vec4::splat(pos.y));
        // One length for the five (one bounds check).
        let n4 = self.lanes[0].len();
        let [lx, ly, lfx, lfy, lv] = self.lanes.each_ref().map(|l| &l[..n4]);
        for &(lo, hi) in &far[..n_far] {
            let (lo, hi) = (lo as usize, hi as usize);
            let mut c = lo;
            while c < hi {
                let in_run = Vec4::new(0.0, 1.0, 2.0, 3.0).cmplt(Vec4::splat((hi - c) as f32));
                lane.see_far4(
                    Vec4::from_slice(&lx[c..c + 4]) - mx,
                    Vec4::from_slice(&ly[c..c + 4]) - my,
                    Vec4::from_slice(&lfx[c..c + 4]),
                    Vec4::from_slice(&lfy[c..c + 4]),
                    Vec4::from_slice(&lv[c..c + 4]),
                    in_run,
                    &pass.far_box,
                );
                c += 4;
            }
        }
    }
}

/// The way sought after the keep-right turn, and whether it turned: the
/// asks folded ([`Passing::settle`]), the way turned right where an
/// unfinished agent not walled is asked to and the turned way is clear of
/// walls; turning into its lane with a mate beside it on that side, it
/// drops back to merge behind it ([`Passing::merge_factor`]).
#[inline(always)]
pub(crate) fn lane_way(a: &Agent, lane: &mut Passing, lines: &Lines) -> (Way, bool) {
    lane.settle();
    let u_lane = lane.turn(a.seek.u);
    let turned = a.unfinished
        && !a.walled
        && lane.active()
        && lines.obstacles_admit(u_lane * a.s_pref.max(DODGE_SPEED), 0.0);
    if !turned {
        return (a.seek, false);
    }
    let f = lane.merge_factor();
    let way = Way {
        heading: trig::atan2(u_lane.y, u_lane.x),
        speed: a.s_pref * f,
        u: u_lane,
        v: lane.turn(a.seek.v) * f,
    };
    (way, true)
}

/// True when the agent takes the way sought as it is: not walled, no
/// oncoming neighbour ahead (then it keeps right at once, before the pair
/// is blocked, so that lanes form before a jam does), within the vehicle's
/// speed, admitted by every half-plane, and its present heading clear of
/// walls at that speed ([`present_heading_clear`]).
#[inline(always)]
pub(crate) fn way_admitted(
    pass: &Pass,
    a: &Agent,
    way: &Way,
    oncoming: bool,
    lines: &Lines,
) -> bool {
    !a.walled
        && !oncoming
        && way.speed <= pass.p.v_max
        && lines.admits(way.v, 0.0)
        && present_heading_clear(lines, a.peer.fwd, way.speed)
}

/// ORCA's velocity for a way not admitted, as the unicycle's command: the
/// velocity sought turned right by an oncoming neighbour ahead (at least
/// [`LANE_BIAS`] of [`AvoidanceConfig::bias_deg`](crate::avoidance::config::AvoidanceConfig::bias_deg), the more the slower the
/// agent goes than its way asks: none at full speed), unless that runs
/// into a wall; the linear program's nearest admissible velocity, no
/// faster than the way asks; then [`unicycle`].
#[inline(always)]
pub(crate) fn solve_keep_right(
    pass: &Pass,
    a: &Agent,
    way: &Way,
    oncoming: bool,
    lines: &Lines,
) -> Command {
    let slow = if oncoming {
        (1.0 - a.state.v / way.speed.max(0.1)).clamp(LANE_BIAS, 1.0)
    } else {
        0.0
    };
    let v_seek = if slow > 0.0 {
        // Not into a wall ([`crate::avoidance::stalled`]).
        stalled::bias_clear_of_walls(
            lines,
            way.v,
            way.v
                .rotate(trig::unit(-pass.cfg.bias_deg.to_radians() * slow)),
            DODGE_SPEED,
        )
    } else {
        way.v
    };
    // Never faster than the way asks (at least DODGE_SPEED, so an agent
    // at rest can step aside): a vehicle that must brake within its
    // acceleration limit cannot afford ORCA's habit of speeding up to pass
    // in front.
    let cap = way.speed.max(DODGE_SPEED).min(pass.p.v_max);
    let v = orca::solve(lines, cap, v_seek);
    Command {
        walls: lines.obstacle_count() > 0,
        ..unicycle(a.state, a.peer.fwd, way.heading, way.v, v, lines, cap)
    }
}

/// True when the vehicle, still moving along its present heading `forward`
/// while it turns to the funnel's, may speed up to `speed` without running
/// into an obstacle. The funnel's own command sets a heading to turn to and
/// a speed, not a velocity: an agent facing a wall whose funnel asks to
/// turn round at full speed would accelerate into the wall while it
/// turns, closer than its radius. Without obstacles in reach: always (the
/// same bits).
#[inline]
fn present_heading_clear(lines: &Lines, forward: Vec2, speed: f32) -> bool {
    lines.obstacle_count() == 0 || lines.obstacles_admit(forward * speed, 0.0)
}
