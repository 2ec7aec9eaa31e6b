//! The seek controller of paper 000 §3 (docs/DESIGN.md §7) and the static-target
//! reach simulation that defines the η angle.
//!
//! Two controllers act each step. The angular one is a PD law on the
//! heading error, `ω̇ = Kp·α − Kd·ω`, where α is the angle from the forward
//! direction to the *heading direction*: the radial direction to the target
//! in plain seek mode, the modulated direction γ in funnelling
//! (crate::funnelling::funnel). The forward one tracks the desired speed, relaxed to
//! `v_dr = min(v_d, A/|ω|)` so that the normal acceleration stays bounded;
//! the vehicle model ([`VehicleParams::integrate`]) enforces every limit.

use crate::base::minmax::MinMax;
use glam::Vec2;

use crate::base::angle::{diff, wrap};
use crate::base::trig;
use crate::base::vehicle::{VehicleParams, VehicleState};

/// Commanded angular acceleration of the PD heading controller, towards
/// absolute heading `heading` (rad).
#[inline]
#[must_use]
pub fn angular_command(p: &VehicleParams, s: &VehicleState, heading: f32) -> f32 {
    pd(p, s, diff(heading, s.theta))
}

/// The PD law on a heading error `e`: `Kp·e − Kd·ω`.
#[inline]
fn pd(p: &VehicleParams, s: &VehicleState, e: f32) -> f32 {
    p.kp * e - p.kd * s.omega
}

/// One controller step towards absolute heading `heading` at desired
/// forward speed `desired_speed`.
#[inline]
pub fn seek_step(p: &VehicleParams, s: &mut VehicleState, heading: f32, desired_speed: f32) {
    let acc = angular_command(p, s, heading);
    p.integrate(s, acc, desired_speed);
}

/// Half-width of the band around the ±π seam of the heading error where
/// [`seek_step_committed`] keeps the current turn direction: 10°.
pub const TURN_COMMIT_WINDOW: f32 = 10.0 * core::f32::consts::PI / 180.0;

/// The heading error `e` (wrapped) with turn commitment: within
/// [`TURN_COMMIT_WINDOW`] of ±π, an error whose sign would reverse the
/// current rotation `omega` is taken the long way round (`e ± 2π`), so the
/// vehicle keeps turning the way it already turns.
///
/// Why: the PD law's wrapped error jumps by 2π at the seam. Plain seek
/// crosses it once and moves away, but a modulated heading (funnelling,
/// paper 000 §4) can hop across it from one update to the next, because η
/// itself flips sign for targets behind the vehicle; each hop reversed the
/// commanded turn, and in 23 of 10,000 random reach scenarios the vehicle
/// drove straight away from its target, turning neither way, for the
/// whole minute. With the commitment none does (`steer reach`).
#[inline]
#[must_use]
pub fn committed_error(e: f32, omega: f32) -> f32 {
    if e.abs() > core::f32::consts::PI - TURN_COMMIT_WINDOW && e * omega < 0.0 {
        e + core::f32::consts::TAU.copysign(omega)
    } else {
        e
    }
}

/// One controller step towards absolute heading `heading`, with turn
/// commitment near the seam ([`committed_error`]): the step of the
/// funnelling controllers, whose heading is modulated every update.
#[inline]
pub fn seek_step_committed(
    p: &VehicleParams,
    s: &mut VehicleState,
    heading: f32,
    desired_speed: f32,
) {
    let e = committed_error(diff(heading, s.theta), s.omega);
    p.integrate(s, pd(p, s, e), desired_speed);
}

/// [`seek_step_committed`] for a unicycle without a reverse gear
/// ([`VehicleParams::integrate_unicycle`]: `R_min` and `v_reverse` 0,
/// checked by the caller once for many steps); the same bits.
#[inline]
pub fn seek_step_committed_unicycle(
    p: &VehicleParams,
    s: &mut VehicleState,
    heading: f32,
    desired_speed: f32,
) {
    let e = committed_error(diff(heading, s.theta), s.omega);
    p.integrate_unicycle(s, pd(p, s, e), desired_speed);
}

/// One plain seek step towards the point `target`: the heading is the
/// instantaneous radial direction.
#[inline]
pub fn seek_point(p: &VehicleParams, s: &mut VehicleState, target: Vec2, desired_speed: f32) {
    let d = target - s.pos;
    let heading = trig::atan2(d.y, d.x);
    seek_step(p, s, heading, desired_speed);
}

/// When a simulated reach counts as arrived, and when it gives up.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ReachLimits {
    /// Arrival radius around the target, m. The default, 0.25 m, equals
    /// the default position tolerance: η then predicts the heading on
    /// *entering* the tolerance circle, which is what the funnel must get
    /// right (measured: with 0.1 m the arrival error was about twice as big).
    pub reach_radius: f32,
    /// Net heading rotation, in full turns, after which the vehicle is
    /// declared to orbit (paper 000 §3: "converge to an infinite orbital
    /// trajectory ... we consider the target as being unreachable").
    pub orbit_turns: f32,
    /// Hard cap on simulated time, s (a stalled vehicle never orbits).
    pub max_time: f32,
}

impl Default for ReachLimits {
    fn default() -> Self {
        Self {
            reach_radius: 0.25,
            orbit_turns: 1.0,
            max_time: 200.0,
        }
    }
}

/// Result of simulating the seek controller towards a static target.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ReachOutcome {
    /// Arrived within the reach radius.
    Reached {
        /// η: final tangential (heading) direction minus the initial radial
        /// direction, wrapped (paper 000 Fig. 1c).
        eta: f32,
        /// Time to arrive, s.
        time: f32,
        /// Path length, m.
        length: f32,
    },
    /// Orbiting (net rotation beyond the limit) or timed out.
    Unreachable,
}

/// Simulates plain seek from `start` towards the static `target` at desired
/// speed `v_d` until arrival, orbit or time-out. Cost is bounded by
/// `max_time / dt` steps: an orbit can never loop forever.
#[must_use]
pub fn simulate_reach(
    p: &VehicleParams,
    start: VehicleState,
    target: Vec2,
    v_d: f32,
    lim: &ReachLimits,
) -> ReachOutcome {
    simulate_reach_traced(p, start, target, v_d, lim, &mut |_| {})
}

/// [`simulate_reach`], telling `visit` every position the simulated
/// vehicle passes: the start, each step's, and on arrival the point where
/// the path crosses the reach circle (interpolated like the heading, or the
/// end of the straight run the early exit skips). The one simulation behind
/// both the η table ([`crate::funnelling::table`]) and the predicted seek path the
/// pages draw ([`crate::funnelling::ghost`]); with a no-op `visit` it is
/// `simulate_reach` itself (the call is generic and inlined).
pub fn simulate_reach_traced(
    p: &VehicleParams,
    start: VehicleState,
    target: Vec2,
    v_d: f32,
    lim: &ReachLimits,
    visit: &mut impl FnMut(Vec2),
) -> ReachOutcome {
    let mut s = start;
    let d0 = target - s.pos;
    let radial0 = trig::atan2(d0.y, d0.x);
    let r2 = lim.reach_radius * lim.reach_radius;
    let max_steps = (lim.max_time / p.dt) as u32;
    let orbit = lim.orbit_turns * core::f32::consts::TAU;
    let mut turned = 0.0f32;
    let mut length = 0.0f32;
    let mut prev: Option<(f32, f32, Vec2)> = None; // (distance, heading, position) one step back
    for step in 0..max_steps {
        let d = target - s.pos;
        let dist2 = d.length_squared();
        if dist2 <= r2 {
            // Interpolate the heading at the exact crossing of the reach
            // circle, so η does not jitter with the step phase.
            let dist = dist2.sqrt();
            let theta = match prev {
                Some((d0, th0, p0)) if d0 > dist => {
                    let f = ((d0 - lim.reach_radius) / (d0 - dist)).clamp(0.0, 1.0);
                    visit(p0.lerp(s.pos, f));
                    th0 + f * diff(s.theta, th0)
                }
                _ => s.theta,
            };
            return ReachOutcome::Reached {
                eta: wrap(theta - radial0),
                time: step as f32 * p.dt,
                length,
            };
        }
        let dist = dist2.sqrt();
        visit(s.pos);
        let bearing = trig::atan2(d.y, d.x);
        // Steady straight approach: heading on the target, no rotation. The
        // rest of the path is a straight line ending with this bearing, so
        // η is known now (saves most of the cost of far targets).
        if dist > 4.0 * lim.reach_radius
            && s.omega.abs() < 1e-3
            && diff(bearing, s.theta).abs() < 1e-3
        {
            let rest = (dist - lim.reach_radius) / s.v.at_least(1e-3);
            visit(s.pos + d * ((dist - lim.reach_radius) / dist));
            return ReachOutcome::Reached {
                eta: wrap(bearing - radial0),
                time: step as f32 * p.dt + rest,
                length: length + dist - lim.reach_radius,
            };
        }
        prev = Some((dist, s.theta, s.pos));
        let th0 = s.theta;
        let p0 = s.pos;
        seek_step(p, &mut s, bearing, v_d);
        turned += diff(s.theta, th0);
        length += (s.pos - p0).length();
        if turned.abs() > orbit {
            return ReachOutcome::Unreachable;
        }
    }
    ReachOutcome::Unreachable
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn target_straight_ahead_is_reached_with_zero_eta() {
        let p = VehicleParams::default();
        let s = VehicleState::new(Vec2::ZERO, 0.0, 1.0, 0.0);
        match simulate_reach(&p, s, Vec2::new(10.0, 0.0), 1.3, &ReachLimits::default()) {
            ReachOutcome::Reached { eta, time, length } => {
                assert!(eta.abs() < 1e-3, "eta {eta}");
                assert!((length - 9.75).abs() < 0.05, "length {length}");
                // The early exit estimates the remaining time at the current speed.
                assert!(time > 7.0 && time < 10.0, "time {time}");
            }
            ReachOutcome::Unreachable => panic!("unreachable"),
        }
    }

    #[test]
    fn target_inside_the_turning_circle_at_speed_is_an_orbit_not_a_hang() {
        let p = VehicleParams::default();
        // Fast, with the target just beside the vehicle: it circles.
        let s = VehicleState::new(Vec2::ZERO, 0.0, 2.0, 0.0);
        let out = simulate_reach(&p, s, Vec2::new(0.0, 0.6), 2.0, &ReachLimits::default());
        assert_eq!(out, ReachOutcome::Unreachable);
        // Slowly, the same target is reachable.
        let s = VehicleState::new(Vec2::ZERO, 0.0, 0.0, 0.0);
        let out = simulate_reach(&p, s, Vec2::new(0.0, 0.6), 0.25, &ReachLimits::default());
        assert!(matches!(out, ReachOutcome::Reached { .. }), "{out:?}");
    }

    #[test]
    fn committed_error_keeps_the_turn_direction_only_near_the_seam() {
        use core::f32::consts::{PI, TAU};
        let near = PI - 0.5 * TURN_COMMIT_WINDOW;
        // Turning left (ω > 0), target just across the seam on the right:
        // keep turning left, the long way round.
        assert!((committed_error(-near, 0.5) - (TAU - near)).abs() < 1e-6);
        assert!((committed_error(near, -0.5) - (near - TAU)).abs() < 1e-6);
        // Already turning that way, far from the seam, or not turning:
        // the plain error.
        assert_eq!(committed_error(-near, -0.5), -near);
        assert_eq!(committed_error(-2.0, 0.5), -2.0);
        assert_eq!(committed_error(-near, 0.0), -near);
    }

    #[test]
    fn mirror_symmetry_eta_alpha_omega() {
        // η(α, ω) = −η(−α, −ω): the controller is left/right symmetric.
        let p = VehicleParams::default();
        let lim = ReachLimits::default();
        for &(x, y, w) in &[
            (3.0f32, 2.0f32, 0.5f32),
            (-1.0, 2.0, -0.3),
            (0.5, -4.0, 0.0),
        ] {
            let a = simulate_reach(
                &p,
                VehicleState::new(Vec2::ZERO, 0.0, 1.0, w),
                Vec2::new(x, y),
                1.3,
                &lim,
            );
            let b = simulate_reach(
                &p,
                VehicleState::new(Vec2::ZERO, 0.0, 1.0, -w),
                Vec2::new(x, -y),
                1.3,
                &lim,
            );
            match (a, b) {
                (ReachOutcome::Reached { eta: ea, .. }, ReachOutcome::Reached { eta: eb, .. }) => {
                    assert!((ea + eb).abs() < 1e-3, "{ea} vs {eb}");
                }
                other => panic!("{other:?}"),
            }
        }
    }
}
