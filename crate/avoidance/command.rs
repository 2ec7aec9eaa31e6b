//! What one agent is told to do this step ([`Command`]), and a velocity
//! turned into it ([`unicycle`]): a forward-only unicycle moves along its
//! heading, not along the velocity avoidance asks for, so the command is
//! chosen among the headings and speeds every half-plane admits.

use glam::Vec2;

use crate::avoidance::orca::{ray_cap, Lines};
use crate::avoidance::stalled::STUCK_SPEED;
use crate::base::trig;
use crate::base::vehicle::VehicleState;

/// What one agent is told to do this step.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Command {
    /// Heading for the seek step, rad.
    pub heading: f32,
    /// Desired speed, m/s.
    pub speed: f32,
    /// True when the avoidance changed the funnel's (γ, v_dt).
    pub active: bool,
    /// An obstacle was in reach: the step keeps the agent's turn near the
    /// ±π seam (`world::avoid_step`'s turn commitment).
    pub walls: bool,
}

/// Headings sampled each side of the current one by [`unicycle`].
pub const HEADING_SAMPLES: usize = 12;

/// The forward-only unicycle's answer: it chooses among the admissible
/// headings and speeds. When ORCA's velocity `v_orca` is at least
/// [`STUCK_SPEED`], the heading command is its direction and the speed its
/// projection on the present heading, no more than that ray admits.
/// Otherwise (a crowd packed at the contact distance leaves ORCA nearly no
/// velocity) the headings are searched: candidates are the ORCA velocity's direction
/// (`v_orca`), the current heading and [`HEADING_SAMPLES`] headings every
/// 15° each side of it; along each, the speed nearest the sought velocity
/// `v_seek` that every half-plane admits (a 1D linear program). The
/// candidate nearest `v_seek` wins (ties: the smaller turn). It contains
/// ORCA's own answer, so it is never worse than ORCA's velocity; it still
/// finds a way out where ORCA's velocity is nearly zero (a crowd packed at
/// the contact distance) and a ray away from the packing is free.
///
/// The heading command is the winner's; the speed command is the speed the
/// winner asks for, scaled by the cosine of the turn still to make, and no
/// more than the current heading's own ray admits: the vehicle moves along
/// its present heading while it turns.
#[must_use]
pub fn unicycle(
    s: &VehicleState,
    forward: Vec2,
    h_pref: f32,
    v_seek: Vec2,
    v_orca: Vec2,
    lines: &Lines,
    v_max: f32,
) -> Command {
    let along = ray_cap(lines, forward, v_max);
    if v_orca.length() >= STUCK_SPEED {
        // ORCA found a way: turn to it, move along the present heading at
        // its projection, as far as that ray is admissible.
        return Command {
            heading: trig::atan2(v_orca.y, v_orca.x),
            speed: v_orca.dot(forward).max(0.0).min(along),
            active: true,
            walls: false,
        };
    }
    if v_seek.length_squared() < 1e-6 {
        // Nothing sought (the funnel turns the agent in place, or it rests):
        // turning on the spot is always admissible.
        return Command {
            heading: h_pref,
            speed: 0.0,
            active: true,
            walls: false,
        };
    }
    let step = 15f32.to_radians();
    let turn_step = trig::unit(step);
    let mut best = (f32::INFINITY, 0.0f32, s.theta, 0.0f32); // cost, |turn|, heading, speed
    let mut consider = |h: f32, u: Vec2, turn: f32, along: Option<f32>| {
        // A ray facing away from `v_seek` gets speed 0 whatever its cap
        // (the clamp's lower bound): its lines are not read.
        let d = v_seek.dot(u);
        let cap = if d > 0.0 {
            along.unwrap_or_else(|| ray_cap(lines, u, v_max))
        } else {
            f32::INFINITY
        };
        let sp = d.clamp(0.0, cap);
        let cost = (u * sp - v_seek).length_squared();
        if cost < best.0 - 1e-9 || (cost <= best.0 + 1e-9 && turn < best.1) {
            best = (cost, turn, h, sp);
        }
    };
    if v_orca.length_squared() > 1e-6 {
        let h = trig::atan2(v_orca.y, v_orca.x);
        consider(
            h,
            v_orca.normalize(),
            crate::base::angle::diff(h, s.theta).abs(),
            None,
        );
    }
    consider(s.theta, forward, 0.0, Some(along));
    // The samples by successive rotations of the present heading (no
    // sine or cosine per sample).
    let (mut left, mut right) = (forward, forward);
    for k in 1..=HEADING_SAMPLES {
        let d = step * k as f32;
        left = turn_step.rotate(left);
        right = Vec2::new(turn_step.x, -turn_step.y).rotate(right);
        consider(crate::base::angle::wrap(s.theta + d), left, d, None);
        consider(crate::base::angle::wrap(s.theta - d), right, d, None);
    }
    let (_, turn, heading, sp) = best;
    if !best.0.is_finite() {
        // No ray is admissible: brake, turning to the funnel's heading.
        return Command {
            heading: h_pref,
            speed: 0.0,
            active: true,
            walls: false,
        };
    }
    Command {
        heading,
        // `trig`, not `f32::cos` (the platform's libm): the same bits
        // natively and in wasm.
        speed: (sp * trig::sin_cos(turn).1.max(0.0)).min(along),
        active: true,
        walls: false,
    }
}
