//! The predicted seek path ("ghost"): where plain seek would take
//! the vehicle from its current state to a point, and the final direction
//! it would arrive with — the path whose end defines η (paper 000 §3,
//! Fig. 1c; paper 001 §3, Fig. 2).
//!
//! Why: the table stores only η, the angle between the initial radial
//! direction and the final tangential one. A reader who has not seen the
//! path behind that number cannot tell what η *is*, nor why Δη = β − (θ +
//! α + η) is the error funnelling corrects. The learn page and the lab's
//! overlay draw this path.
//!
//! Design: the path is not re-implemented. It is
//! [`simulate_reach_traced`], the very simulation the table generator runs
//! ([`crate::funnelling::table`]), with a visitor that keeps the positions; η and the
//! outcome are therefore bit-identical to the generator's for the same
//! inputs (`tests/ghost.rs`). The number of points is bounded: positions are
//! appended to a caller's buffer, and whenever `max_points` is reached every
//! other point is dropped and the keeping stride doubles, so a 200 s orbit
//! (12,000 steps) costs at most `max_points` points, evenly spaced in time,
//! and the arrival point is always the last one. Cost: one reach
//! simulation, at most `max_time / dt` seek steps (the early exit of a
//! straight approach makes far targets cheap); no allocation once the
//! buffer has its capacity.
//!
//! [`update_ghost`] draws the seek the controller's last update asked the
//! table about ([`Internals::aim_d`], `aim_alpha`, `v_query`): towards its
//! aim point (goal centre, entry point or relaxed point) at the queried
//! desired speed, and — where the table said unreachable — again at the
//! proactive fallback speed `v_dt` (paper 000 §3), which is the path the
//! stored η belongs to.

use glam::Vec2;

use crate::base::vehicle::{VehicleParams, VehicleState};
use crate::funnelling::goal::Goal;
use crate::funnelling::seek::{simulate_reach_traced, ReachLimits, ReachOutcome};
use crate::funnelling::table::lookup::EtaTable;
use crate::funnelling::update::Internals;

/// Fewest points a ghost may be asked to keep (start, a middle, the end).
pub const MIN_GHOST_POINTS: usize = 4;

/// What a predicted seek did; the points are in the caller's buffer.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Ghost {
    /// The seek reached the point (else it orbits or timed out).
    pub reached: bool,
    /// η, rad: final tangential direction minus the initial radial
    /// direction (NaN when not reached).
    pub eta: f32,
    /// The final tangential direction, world angle, rad (NaN when not
    /// reached): the initial radial direction + η.
    pub final_dir: f32,
    /// Simulated time to arrive, s (NaN when not reached).
    pub time: f32,
    /// Path length to the arrival, m (NaN when not reached).
    pub length: f32,
    /// The desired speed simulated, m/s.
    pub speed: f32,
    /// The point sought (world).
    pub target: Vec2,
    /// True when the seek at the queried speed did not arrive and this is
    /// the path at the table's proactive fallback speed `v_dt`.
    pub slowed: bool,
}

/// Appends positions to `out`, at most `max` of them, evenly spaced in
/// simulated time (the stride doubles when full).
struct Decimator<'a> {
    out: &'a mut Vec<Vec2>,
    start: usize,
    max: usize,
    stride: u32,
    count: u32,
}

impl Decimator<'_> {
    fn push(&mut self, p: Vec2) {
        if self.count % self.stride == 0 {
            if self.out.len() - self.start >= self.max - 1 {
                // Keep every other point (the first stays), double the stride.
                let mut k = 0;
                let start = self.start;
                self.out.retain(|_| {
                    k += 1;
                    k <= start || (k - start - 1) % 2 == 0
                });
                self.stride *= 2;
            }
            if self.count % self.stride == 0 {
                self.out.push(p);
            }
        }
        self.count += 1;
    }
}

/// Simulates plain seek from `start` towards the static `target` at desired
/// speed `v_d` (the table generator's simulation, [`simulate_reach_traced`])
/// and appends at most `max_points` positions of its path to `out` (start
/// first; on arrival, the crossing of the reach circle last). `max_points`
/// below [`MIN_GHOST_POINTS`] counts as that.
#[must_use]
pub fn seek_ghost(
    p: &VehicleParams,
    start: VehicleState,
    target: Vec2,
    v_d: f32,
    lim: &ReachLimits,
    max_points: usize,
    out: &mut Vec<Vec2>,
) -> Ghost {
    let first = out.len();
    let max = max_points.max(MIN_GHOST_POINTS);
    let mut last = None;
    let mut dec = Decimator {
        out,
        start: first,
        max,
        stride: 1,
        count: 0,
    };
    let outcome = simulate_reach_traced(p, start, target, v_d, lim, &mut |q| {
        last = Some(q);
        dec.push(q);
    });
    // The last position seen always ends the path.
    if let Some(q) = last {
        if out.last() != Some(&q) {
            if out.len() - first >= max {
                out.pop();
            }
            out.push(q);
        }
    }
    let d0 = target - start.pos;
    let radial0 = crate::base::trig::atan2(d0.y, d0.x);
    match outcome {
        ReachOutcome::Reached { eta, time, length } => Ghost {
            reached: true,
            eta,
            final_dir: crate::base::angle::wrap(radial0 + eta),
            time,
            length,
            speed: v_d,
            target,
            slowed: false,
        },
        ReachOutcome::Unreachable => Ghost {
            reached: false,
            eta: f32::NAN,
            final_dir: f32::NAN,
            time: f32::NAN,
            length: f32::NAN,
            speed: v_d,
            target,
            slowed: false,
        },
    }
}

/// The table's reach limits (what its η was simulated with).
#[must_use]
pub fn table_limits(table: &EtaTable) -> ReachLimits {
    let bp = table.params();
    ReachLimits {
        reach_radius: bp.reach_radius,
        orbit_turns: bp.orbit_turns,
        max_time: bp.max_time,
    }
}

/// The seek whose η an update used (`inter`, from the controller's plan of
/// state `s` towards goal `g`): towards the aim point it asked the table
/// about at the queried speed; when that does not arrive and the table
/// said unreachable, the path at the fallback speed `v_dt` instead
/// (`slowed`). An update that asked nothing (inside the tolerance, the
/// terminal pursuit) gets the seek towards the goal centre at its speed.
/// `out` is cleared first.
#[must_use]
pub fn update_ghost(
    table: &EtaTable,
    p: &VehicleParams,
    s: &VehicleState,
    inter: &Internals,
    g: &Goal,
    max_points: usize,
    out: &mut Vec<Vec2>,
) -> Ghost {
    let lim = table_limits(table);
    out.clear();
    let (target, v) = if inter.aim_d > 0.0 {
        let dir = s.theta + inter.aim_alpha;
        (
            s.pos + crate::base::trig::unit(dir) * inter.aim_d,
            inter.v_query,
        )
    } else {
        (g.pos, g.speed.max(table.axis(4)[0]))
    };
    let ghost = seek_ghost(p, *s, target, v, &lim, max_points, out);
    if ghost.reached || inter.reachable || inter.aim_d <= 0.0 || inter.v_dt <= 0.0 {
        return ghost;
    }
    out.clear();
    Ghost {
        slowed: true,
        ..seek_ghost(p, *s, target, inter.v_dt, &lim, max_points, out)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_orbit_keeps_at_most_max_points_evenly() {
        let p = VehicleParams::default();
        let s = VehicleState::new(Vec2::ZERO, 0.0, 2.0, 0.0);
        let mut out = Vec::new();
        let g = seek_ghost(
            &p,
            s,
            Vec2::new(0.0, 0.6),
            2.0,
            &ReachLimits::default(),
            64,
            &mut out,
        );
        assert!(!g.reached && g.eta.is_nan());
        assert!(out.len() <= 64 && out.len() >= 16, "{}", out.len());
        assert_eq!(out[0], Vec2::ZERO);
    }

    #[test]
    fn straight_ahead_ends_on_the_reach_circle() {
        let p = VehicleParams::default();
        let s = VehicleState::new(Vec2::ZERO, 0.0, 1.0, 0.0);
        let mut out = Vec::new();
        let g = seek_ghost(
            &p,
            s,
            Vec2::new(10.0, 0.0),
            1.3,
            &ReachLimits::default(),
            128,
            &mut out,
        );
        assert!(g.reached && g.eta.abs() < 1e-3);
        let end = *out.last().unwrap();
        assert!((end - Vec2::new(9.75, 0.0)).length() < 1e-3, "{end}");
    }
}
