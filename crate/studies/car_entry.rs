//! Whether a car-like vehicle without a reverse gear can still enter its
//! position tolerance disk facing β: the sampled search behind the car-like
//! study's deciding test of an unavoidable wrong-heading entry
//! ([`crate::studies::car_like::entry_unavoidable`]).
//!
//! The vehicle is modelled as at least as able as it is: forward paths
//! whose curvature changes at once (no angular acceleration), of radius
//! `R_min` once it is slow enough for it. A moving start first brakes
//! (`accel_max`) along a lead-in, full lock either side or straight,
//! whose turn tightens as it slows (pieces at the radius of each one's
//! start speed; [`LEAD_PIECES`]), down to the fastest speed whose radius
//! is `R_min`. From there the
//! search tries, for every entry pose sampled on the disk's rim
//! ([`ENTRY_POINTS`] points × [`ENTRY_HEADINGS`] headings within β ± ε_tol,
//! pointing inwards), the six Dubins words of radius `R_min`, and then the
//! same after a straight or full-lock detour ([`DETOURS`]); an entry is
//! possible when one path reaches its pose without entering the disk
//! before. The answer is sampled, not exact: an entry window narrower
//! than the samples is missed, and a moving start's lead-in is one of
//! three; the study counts the runs it calls
//! unavoidable that the controller entered oriented anyway, the check
//! that the test does not excuse what is possible.

use core::f32::consts::{PI, TAU};

use glam::Vec2;

use crate::base::angle::diff;
use crate::base::dubins::{DubinsPath, Word, WORDS};
use crate::base::trig;
use crate::base::vehicle::{VehicleParams, VehicleState};
use crate::funnelling::approach::braking_distance;
use crate::funnelling::goal::Goal;
use crate::funnelling::reverse::segment_distance;

/// Entry points sampled evenly on the disk's rim.
pub const ENTRY_POINTS: usize = 72;
/// Entry headings sampled, shares of ε_tol about β.
pub const ENTRY_HEADINGS: [f32; 5] = [-0.9, -0.45, 0.0, 0.45, 0.9];
/// The lead-ins' sides: full lock left, right, straight.
pub const LEAD_SIDES: [f32; 3] = [1.0, -1.0, 0.0];
/// Pieces of a lead-in, each at the radius of its start speed.
pub const LEAD_PIECES: usize = 6;
/// Detours tried before the Dubins words when none reaches an entry
/// directly: (curvature in `1/R_min`, length in `R_min`).
pub const DETOURS: [(f32, f32); 8] = [
    (0.0, 1.0),
    (0.0, 2.0),
    (0.0, 4.0),
    (1.0, 0.5 * PI),
    (-1.0, 0.5 * PI),
    (1.0, PI),
    (-1.0, PI),
    (0.0, 8.0),
];

/// Whether some forward path of the module's model enters the disk of
/// `g` facing β within ε_tol from `s` (a start inside: true).
#[must_use]
pub fn oriented_entry_possible(p: &VehicleParams, s: &VehicleState, g: &Goal) -> bool {
    if (s.pos - g.pos).length() < g.d_tol {
        return true;
    }
    let r = p.r_min;
    'lead: for side in LEAD_SIDES {
        let (mut pos, mut th) = (s.pos, s.theta);
        for (k, l) in lead_in(p, s.v.max(0.0), side) {
            let piece = DubinsPath::from_segments(pos, th, [k, 0.0, 0.0], [l, 0.0, 0.0]);
            if let Some(t) = first_entry(&piece, g, r) {
                if diff(g.beta, t).abs() < g.eps_tol {
                    return true;
                }
                continue 'lead;
            }
            (pos, th, _) = piece.at(l);
        }
        if reaches(pos, th, r, g) {
            return true;
        }
        for (kd, ld) in DETOURS {
            let detour = DubinsPath::from_segments(pos, th, [kd / r, 0.0, 0.0], [ld * r, 0.0, 0.0]);
            if let Some(t) = first_entry(&detour, g, r) {
                if diff(g.beta, t).abs() < g.eps_tol {
                    return true;
                }
                continue;
            }
            let (q, t, _) = detour.at(ld * r);
            if reaches(q, t, r, g) {
                return true;
            }
        }
        if s.v <= slow_enough(p) {
            // At rest or slow, no lead-in: the sides are the same.
            break;
        }
    }
    false
}

/// The fastest speed whose turning radius is `R_min`.
fn slow_enough(p: &VehicleParams) -> f32 {
    (p.omega_max * p.r_min).min((p.normal_accel_max * p.r_min).sqrt())
}

/// The lead-in of a start at speed `v` on `side` (+1 full lock left, −1
/// right, 0 straight): [`LEAD_PIECES`] pieces (curvature, length)
/// braking at `accel_max` to [`slow_enough`], each at the radius of the
/// speed it begins with (so the turn tightens as the vehicle slows); none
/// for a start no faster than that.
fn lead_in(p: &VehicleParams, v: f32, side: f32) -> Vec<(f32, f32)> {
    let slow = slow_enough(p);
    if v <= slow {
        return Vec::new();
    }
    let (v2, s2) = (v * v, slow * slow);
    (0..LEAD_PIECES)
        .map(|i| {
            let at = |j: usize| (v2 - (v2 - s2) * j as f32 / LEAD_PIECES as f32).sqrt();
            let (a, b) = (at(i), at(i + 1));
            let l = braking_distance(p, a) - braking_distance(p, b);
            (side / p.min_turn_radius(a).max(p.r_min), l)
        })
        .collect()
}

/// The heading at which `path` (its first segment) first enters the disk
/// of `g`, traced in steps of at most a quarter of `D_tol` and 2 % of
/// `radius`; `None` when it keeps out.
fn first_entry(path: &DubinsPath, g: &Goal, radius: f32) -> Option<f32> {
    let l = path.len[0];
    if l <= 0.0 {
        return None;
    }
    let (pos, th) = path.knots[0];
    if segment_distance(g.pos, pos, th, path.kappa[0], l) >= g.d_tol {
        return None;
    }
    let h = (0.25 * g.d_tol).min(0.02 * radius).max(1e-4);
    let steps = (l / h).ceil() as u32;
    (1..=steps).find_map(|i| {
        let (q, t, _) = path.at((i as f32 * h).min(l));
        ((q - g.pos).length() < g.d_tol).then_some(t)
    })
}

/// Whether a Dubins word of radius `r` from the pose (`pos`, `th`) ends on
/// a sampled entry pose of `g` without entering the disk before.
fn reaches(pos: Vec2, th: f32, r: f32, g: &Goal) -> bool {
    for j in 0..ENTRY_POINTS {
        let phi = TAU * j as f32 / ENTRY_POINTS as f32;
        let at = g.pos + trig::unit(phi) * g.d_tol;
        for share in ENTRY_HEADINGS {
            let h = g.beta + share * g.eps_tol;
            // Pointing inwards: the heading within a right angle of the
            // direction to the centre.
            if diff(h, phi + PI).abs() >= 0.5 * PI {
                continue;
            }
            if WORDS.iter().any(|&w| clear_word(w, pos, th, at, h, r, g)) {
                return true;
            }
        }
    }
    false
}

/// Word `w` of radius `r` from (`pos`, `th`) to (`at`, `h`), when it
/// exists and keeps out of the disk but for its last thousandth of `r`.
fn clear_word(w: Word, pos: Vec2, th: f32, at: Vec2, h: f32, r: f32, g: &Goal) -> bool {
    let Some(path) = DubinsPath::of_word(w, (pos.x, pos.y, th), (at.x, at.y, h), r) else {
        return false;
    };
    let end = path.length() - 1e-3 * r;
    let mut from = 0.0;
    for ((&len, &(q0, t0)), &k) in path.len.iter().zip(&path.knots).zip(&path.kappa) {
        let l = len.min(end - from);
        if l > 0.0 && segment_distance(g.pos, q0, t0, k, l) < g.d_tol * (1.0 - 1e-4) {
            return false;
        }
        from += len;
    }
    true
}

#[cfg(test)]
mod tests {
    use super::*;

    fn car() -> VehicleParams {
        VehicleParams {
            r_min: 5.0,
            ..VehicleParams::default()
        }
    }

    fn goal(d_tol: f32, beta: f32) -> Goal {
        Goal {
            pos: Vec2::new(10.0, 0.0),
            beta,
            d_tol,
            eps_tol: 5f32.to_radians(),
            ..Goal::default()
        }
    }

    #[test]
    fn far_at_rest_any_heading_is_possible() {
        let s = VehicleState::new(Vec2::new(-40.0, 0.0), 0.0, 0.0, 0.0);
        for beta in [0.0, 1.5, PI, -2.0] {
            assert!(oriented_entry_possible(&car(), &s, &goal(2.5, beta)));
        }
    }

    #[test]
    fn at_rest_at_the_rim_facing_into_a_large_disk_is_not() {
        // A disk of radius R_min, the car at rest a tenth of a metre off
        // its rim facing its centre, β the other way: every forward path
        // enters at once, far from β.
        let s = VehicleState::new(Vec2::new(4.9, 0.0), 0.0, 0.0, 0.0);
        assert!(!oriented_entry_possible(&car(), &s, &goal(5.0, PI)));
        // Facing β already: possible.
        assert!(oriented_entry_possible(&car(), &s, &goal(5.0, 0.0)));
    }
}
