//! Backing up: the manoeuvre of a car-like vehicle with a reverse gear
//! ([`VehicleParams::v_reverse`] > 0), which [`crate::funnelling::manoeuvre`]
//! hands over to near the goal. Where the forward-only car follows the
//! shortest forward (Dubins) path, this one follows a Reeds–Shepp path
//! ([`crate::base::reeds_shepp`]): forward and backward segments, stopping
//! at every gear change (at rest the curvature bound `|ω| ≤ |v|/R_min`
//! holds the heading, so the car never turns at rest).
//!
//! The path ends on a straight run-in along β, as the forward manoeuvre's,
//! longer for a tight orientation tolerance ([`run_in`]), driven forwards into the goal or, for a halting goal,
//! backwards (the run-in then starts beyond the goal, along β: the car
//! backs into a bay). Of the Reeds–Shepp words to either run-in the one of
//! least cost is chosen (the shortest forward path, Dubins, is a candidate
//! too: it has no gear change): length plus [`VehicleParams::gear_cost`] per gear
//! change, the run-in's included, among the words whose path keeps out of
//! the position tolerance disk ([`clear_of`]): a path that cuts through
//! the disk would enter it at the wrong heading. Only when no word keeps
//! out (a start at the disk's rim) is the cheapest taken as it is.
//!
//! **Chosen by simulation.** Whenever a path is solved, the cheapest
//! word is only the first of a few paths tried ([`VARIANTS`]: a radius
//! closer to `R_min`, a shorter or longer run-in, setting off forwards or
//! backwards); each is followed in simulation with the very update and
//! seek step the world runs (`trial`, bounded by [`MAX_TRIAL_STEPS`]),
//! and the shortest drive that arrives entering the disk facing β is
//! taken. The word's cost is a poor guide near the goal: the pursuit lags
//! each change of curvature, so an arc close to a large disk can cut into
//! it, and a path radius with a margin or a long run-in lengthens every
//! path (tuned on seed 1: at rest, oriented on entry 98.6–99.0 % → 99.6–100 %
//! below 5 R_min, median path over the Reeds–Shepp shortest 1.27 → 1.09).
//! When no path enters oriented (a start at the rim of a large disk:
//! every word passes too close to it for the pursuit's lag), straight
//! stand-offs are tried ([`STANDOFFS`]): drive away from the goal first,
//! then manoeuvre. When none of these does either, the cheapest word is
//! followed as it is.
//!
//! Tracking is the forward manoeuvre's pure pursuit, with the aim point
//! behind the car while it backs (the heading aimed at is the bearing of
//! the aim point plus π), never past the next gear change (beyond it the
//! aim goes on along the segment's tangent); the speed brakes to rest at
//! every change, and the next segment begins once the car is at rest
//! within [`CUSP_REACH`] path radii of it.

use glam::Vec2;

use crate::base::angle::{diff, wrap};
use crate::base::dubins::DubinsPath;
use crate::base::minmax::MinMax;
use crate::base::reeds_shepp::{cheapest, Candidate, ReedsSheppPath, SEGMENTS};
use crate::base::trig;
use crate::base::vehicle::{VehicleParams, VehicleState};
use crate::funnelling::approach::{arrived, halting_speed, seen_from};
use crate::funnelling::goal::{Goal, Manoeuvre};
use crate::funnelling::seek::seek_step_committed;
use crate::funnelling::update::{Internals, Mode};

/// What the forward manoeuvre ([`crate::funnelling::manoeuvre`], which
/// calls this one) fixes for both: the path radius, the manoeuvre speed,
/// the run-in, the pure pursuit's lookahead and when a path is solved
/// again (both in path radii).
#[derive(Clone, Copy, Debug)]
pub struct Pursuit {
    /// Path radius, m.
    pub rho: f32,
    /// Manoeuvre speed, m/s.
    pub speed: f32,
    /// Run-in length, m.
    pub run_in: f32,
    /// Aim point, path radii ahead.
    pub lookahead: f32,
    /// Straying this many path radii solves a new path.
    pub replan: f32,
}

/// At rest this close to a gear change (path radii), the next segment
/// begins.
pub const CUSP_REACH: f32 = 0.1;
/// A word's path keeps this many path radii outside the position
/// tolerance (room for the pursuit's tracking error), when the start
/// allows it.
pub const DISK_MARGIN: f32 = 0.15;

/// The paths simulated besides the manoeuvre's own when a path is solved
/// (`solve`): (path radius, run-in beyond `D_tol`), each a factor of the
/// manoeuvre's, and the gear to set off in (0: either).
pub const VARIANTS: [(f32, f32, f32); 10] = [
    (1.0, 1.0, 1.0),
    (1.0, 1.0, -1.0),
    (0.93, 1.0, 0.0),
    (1.0, 0.5, 0.0),
    (0.93, 0.5, 0.0),
    (0.93, 0.5, 1.0),
    (0.93, 0.5, -1.0),
    (1.0, 3.0, 0.0),
    (1.0, 6.0, 0.0),
    (1.0, 6.0, -1.0),
];
/// The straight stand-offs tried in turn, path radii, when no path of
/// the [`VARIANTS`] enters the disk facing β (a start at its rim: every
/// word passes too close to the disk for the pursuit's lag): drive
/// straight away from the goal first, then manoeuvre. Tuned on seed 1:
/// facing a disk of radius R_min from its rim, the way round it needs
/// two path radii.
pub const STANDOFFS: [f32; 4] = [0.5, 1.0, 2.0, 4.0];
/// A simulated entry counts as oriented within this share of `ε_tol`.
pub const TRIAL_EPS_SHARE: f32 = 0.9;
/// The most steps one simulated path may take.
pub const MAX_TRIAL_STEPS: u32 = 8192;

/// The straight run-in before the goal beyond the position tolerance, in
/// path radii, at the tightest orientation tolerance ([`run_in`]).
pub const RUN_IN_TIGHT: f32 = 1.0;
/// The same at the loosest.
pub const RUN_IN_LOOSE: f32 = 0.2;
/// The orientation tolerance, rad, at and below which the run-in is
/// [`RUN_IN_TIGHT`] (2°); above it shrinks as `ε_tol` grows.
pub const TIGHT_EPS: f32 = 0.035;

/// The straight run-in of the reversing manoeuvre, m: `D_tol` plus a
/// margin for the pursuit to settle on the line after the last arc, long
/// for a tight orientation tolerance, short for a loose one (tuned on
/// seed 1: at ε_tol = 2° a half path radius left a tenth of the entries
/// off, and a whole one made every path longer).
#[must_use]
pub fn run_in(g: &Goal, rho: f32) -> f32 {
    let k = (RUN_IN_TIGHT * TIGHT_EPS / g.eps_tol.at_least(1e-3)).clamp(RUN_IN_LOOSE, RUN_IN_TIGHT);
    g.d_tol + k * rho
}

/// Smallest distance from `q` to a segment from `pos` at heading `th`,
/// curvature `k`, signed length `l` (negative: backwards).
pub fn segment_distance(q: Vec2, pos: Vec2, th: f32, k: f32, l: f32) -> f32 {
    if k == 0.0 {
        let dir = trig::unit(th) * l;
        let along = ((q - pos).dot(dir) / dir.length_squared().at_least(1e-12)).clamp(0.0, 1.0);
        return (pos + dir * along - q).length();
    }
    let r = 1.0 / k;
    let centre = pos + Vec2::new(-trig::sin_cos(th).0, trig::sin_cos(th).1) * r;
    let sweep = k * l;
    let a0 = trig::atan2(pos.y - centre.y, pos.x - centre.x);
    let aq = trig::atan2(q.y - centre.y, q.x - centre.x);
    // How far round the arc's own direction the closest direction lies.
    let rel = wrap(aq - a0) * sweep.signum();
    let rel = if rel < 0.0 {
        rel + core::f32::consts::TAU
    } else {
        rel
    };
    if rel <= sweep.abs() {
        return ((q - centre).length() - r.abs()).abs();
    }
    let end = centre + trig::unit(a0 + sweep) * r.abs();
    (q - pos).length().at_most((q - end).length())
}

/// The smallest distance from `q` of the word `c` driven from `from` with
/// radius `rho`.
#[must_use]
pub fn clear_of(from: (f32, f32, f32), c: &Candidate, rho: f32, q: Vec2) -> f32 {
    let path = ReedsSheppPath::of(from, c, rho, 0.0, 1.0);
    let mut d = f32::INFINITY;
    for i in 0..5 {
        if path.len[i] > 0.0 {
            let (pos, th) = path.knots[i];
            let l = path.len[i] * path.gear[i];
            d = d.at_most(segment_distance(q, pos, th, path.kappa[i], l));
        }
    }
    d
}

/// The shortest forward (Dubins) path from `from` to `to` as a word.
fn forward_word(from: (f32, f32, f32), to: (f32, f32, f32), rho: f32) -> Option<Candidate> {
    let d = DubinsPath::shortest(from, to, rho)?;
    let mut c = Candidate {
        steer: [0; 5],
        len: [0.0; 5],
    };
    for i in 0..3 {
        c.steer[i] = if d.kappa[i] > 0.0 {
            1
        } else if d.kappa[i] < 0.0 {
            -1
        } else {
            0
        };
        c.len[i] = f64::from(d.len[i]) / f64::from(rho);
    }
    Some(c)
}

/// The cheapest admissible path from the vehicle's pose to the goal
/// through a run-in of length `run`, with path radius `rho` (module docs),
/// setting off in gear `first` (1 forwards, −1 backwards, 0 either), of
/// words of at most `most` segments.
fn cheapest_path(
    p: &VehicleParams,
    s: &VehicleState,
    g: &Goal,
    rho: f32,
    run: f32,
    first: f32,
    most: usize,
) -> ReedsSheppPath {
    let from = (s.pos.x, s.pos.y, s.theta);
    let d0 = (s.pos - g.pos).length();
    let keep = g.d_tol + (DISK_MARGIN * rho).at_most(0.5 * (d0 - g.d_tol).at_least(0.0));
    let gears: &[f32] = if g.halting { &[1.0, -1.0] } else { &[1.0] };
    let mut best: Option<(f64, Candidate, f32)> = None;
    let mut loose: Option<(f64, Candidate, f32)> = None;
    for &gear in gears {
        let start = g.pos - trig::unit(g.beta) * (run * gear);
        let to = (start.x, start.y, g.beta);
        let change =
            |c: &Candidate| f64::from(p.gear_cost) * f64::from(u8::from(c.gears().1 != gear));
        // The shortest forward path too: no gear change, where the
        // Reeds–Shepp words (each arc at most a half turn) all have one.
        let sets_off = |c: &Candidate| {
            (first == 0.0 || c.gears().0 == first)
                && c.len.iter().filter(|l| **l != 0.0).count() <= most
        };
        if let Some(c) = forward_word(from, to, rho).filter(|_| first >= 0.0) {
            let cost = c.length() * f64::from(rho) + change(&c);
            if best.is_none_or(|b| cost < b.0) && clear_of(from, &c, rho, g.pos) >= keep {
                best = Some((cost, c, gear));
            }
        }
        let bound = best.map_or(f64::INFINITY, |b| b.0);
        if let Some((c, cost)) = cheapest(from, to, rho, p.gear_cost, |c, cost| {
            cost + change(c) < bound && sets_off(c) && clear_of(from, c, rho, g.pos) >= keep
        }) {
            best = Some((cost + change(&c), c, gear));
        }
        if let Some((c, cost)) = cheapest(from, to, rho, p.gear_cost, |c, _| sets_off(c)) {
            let cost = cost + change(&c);
            if loose.is_none_or(|l| cost < l.0) {
                loose = Some((cost, c, gear));
            }
        }
    }
    match best.or(loose) {
        Some((_, c, gear)) => ReedsSheppPath::of(from, &c, rho, run, gear),
        None => ReedsSheppPath::from_segments(s.pos, s.theta, [0.0; 6], [0.0; 6], [1.0; 6]),
    }
}

/// A path that first drives `len` straight away from the goal (forwards
/// when its centre lies behind the vehicle, else backwards), then the
/// cheapest path from there with the manoeuvre's radius and run-in, of
/// words of at most four segments (the stand-off takes the fifth of
/// [`SEGMENTS`]' six, the run-in the last).
fn standoff_path(
    p: &VehicleParams,
    s: &VehicleState,
    g: &Goal,
    k: &Pursuit,
    len: f32,
) -> ReedsSheppPath {
    let gear = if (g.pos - s.pos).dot(s.forward()) > 0.0 {
        -1.0
    } else {
        1.0
    };
    let from = VehicleState {
        pos: s.pos + s.forward() * (gear * len),
        ..*s
    };
    let rest = cheapest_path(p, &from, g, k.rho, k.run_in, 0.0, 4);
    let mut kappa = [0.0; SEGMENTS];
    let mut lens = [0.0; SEGMENTS];
    let mut gears = [1.0; SEGMENTS];
    lens[0] = len;
    gears[0] = gear;
    let kept = (0..SEGMENTS).filter(|&i| rest.len[i] > 0.0);
    for (j, i) in (1..SEGMENTS).zip(kept) {
        kappa[j] = rest.kappa[i];
        lens[j] = rest.len[i];
        gears[j] = rest.gear[i];
    }
    ReedsSheppPath::from_segments(s.pos, s.theta, kappa, lens, gears)
}

/// Simulates following `path` from `s` with the update and the committed
/// seek step a world runs, to the arrival: the distance driven, or `None`
/// when the vehicle enters the disk at the wrong heading or has not
/// arrived after `max` steps.
fn trial(
    p: &VehicleParams,
    mut s: VehicleState,
    g: &Goal,
    k: &Pursuit,
    path: ReedsSheppPath,
    max: u32,
) -> Option<f32> {
    let mut m = Manoeuvre {
        active: true,
        rs: path,
        goal: g.pos,
        beta: g.beta,
        ..Manoeuvre::default()
    };
    let mut inside = (s.pos - g.pos).length() < g.d_tol;
    let mut length = 0.0;
    for _ in 0..max {
        if arrived(p, &s, g, (g.pos - s.pos).length()) {
            return Some(length);
        }
        let out = step(p, &s, g, &mut m, k, Internals::default(), false);
        let before = s.pos;
        seek_step_committed(p, &mut s, out.gamma, out.v_dt);
        length += (s.pos - before).length();
        if !inside && (g.pos - s.pos).length() < g.d_tol {
            inside = true;
            if diff(g.beta, s.theta).abs() >= TRIAL_EPS_SHARE * g.eps_tol {
                return None;
            }
        }
    }
    None
}

/// Solves the path from the vehicle's pose to the goal (module docs):
/// with `simulate`, the shortest simulated of the [`VARIANTS`] that
/// arrives entering the disk facing β, else (or when none does) the
/// cheapest path with the manoeuvre's own radius and run-in.
fn solve(
    m: &mut Manoeuvre,
    p: &VehicleParams,
    s: &VehicleState,
    g: &Goal,
    k: &Pursuit,
    simulate: bool,
) {
    let mut path = cheapest_path(p, s, g, k.rho, k.run_in, 0.0, 5);
    if simulate {
        let max = trial_steps(p, s, g, k);
        let mut best = trial(p, *s, g, k, path, max);
        for (radius, run, first) in VARIANTS {
            let rho = k.rho * radius;
            let run = g.d_tol + (k.run_in - g.d_tol) * run;
            let other = cheapest_path(p, s, g, rho, run, first, 5);
            if other == path {
                continue;
            }
            if let Some(l) = trial(p, *s, g, k, other, max) {
                if best.is_none_or(|b| l < b) {
                    best = Some(l);
                    path = other;
                }
            }
        }
        // Only when every path above enters askew (a start at the rim):
        // standing off first.
        for len in STANDOFFS {
            if best.is_some() {
                break;
            }
            let other = standoff_path(p, s, g, k, len * k.rho);
            best = trial(p, *s, g, k, other, max);
            if best.is_some() {
                path = other;
            }
        }
    }
    m.rs = path;
    m.s = 0.0;
    m.goal = g.pos;
    m.beta = g.beta;
    m.solves = m.solves.saturating_add(1);
    m.active = true;
}

/// The steps a trial may take: twice the time to drive the straight
/// line to the goal and round a full circle at the manoeuvre speed, at
/// most [`MAX_TRIAL_STEPS`].
fn trial_steps(p: &VehicleParams, s: &VehicleState, g: &Goal, k: &Pursuit) -> u32 {
    let far = (s.pos - g.pos).length() + core::f32::consts::TAU * k.rho;
    let t = 2.0 * far / k.speed.at_most(p.v_reverse).at_least(1e-3) + 2.0 * s.v.abs() / p.accel_max;
    ((t / p.dt) as u32).clamp(1, MAX_TRIAL_STEPS)
}

/// Advances the arc length reached to the vehicle's projection on the path
/// (along the direction of travel), never backwards, never past the next
/// gear change, and never further than the vehicle can have gone since the
/// last update plus a margin.
fn progress(m: &mut Manoeuvre, s: &VehicleState, rho: f32, dt: f32) -> Vec2 {
    let s0 = m.s;
    let cusp = m.rs.next_change(s0);
    let mut s_max = s0 + s.v.abs() * dt + 0.1 * rho;
    if cusp < m.rs.length() {
        s_max = s_max.at_most(cusp).at_least(s0);
    }
    let mut at = s0;
    for _ in 0..2 {
        let (q, th, _, gear) = m.rs.at(at);
        at = (at + (s.pos - q).dot(trig::unit(th)) * gear).clamp(s0, s_max);
    }
    m.s = at;
    m.rs.at(at).0
}

/// The reversing manoeuvre's update: solve a path when needed, then the
/// pure-pursuit heading and the signed speed along it.
pub fn follow(
    p: &VehicleParams,
    s: &VehicleState,
    g: &Goal,
    m: &mut Manoeuvre,
    k: &Pursuit,
    out: Internals,
) -> Internals {
    step(p, s, g, m, k, out, true)
}

/// [`follow`]; a path solved meanwhile is chosen by simulation when
/// `simulate` (never inside a simulation).
fn step(
    p: &VehicleParams,
    s: &VehicleState,
    g: &Goal,
    m: &mut Manoeuvre,
    k: &Pursuit,
    mut out: Internals,
    simulate: bool,
) -> Internals {
    let moved =
        (g.pos - m.goal).length() > 0.1 * g.d_tol || diff(g.beta, m.beta).abs() > 0.1 * g.eps_tol;
    let (rho, vm) = (k.rho, k.speed);
    let fresh = !m.active || moved || m.rs.is_unused();
    if fresh {
        solve(m, p, s, g, k, simulate);
    }
    let on_path = progress(m, s, rho, p.dt);
    let len = m.rs.length();
    let at_rest = s.v.abs() < 0.05 * vm;
    let stopped = at_rest && m.s > len - 0.05 * rho;
    let strayed = (s.pos - on_path).length() > k.replan * rho;
    if !fresh && (strayed || stopped || m.s > len + rho) {
        solve(m, p, s, g, k, simulate);
    }
    // A gear change reached at rest: the next segment begins.
    let cusp = m.rs.next_change(m.s);
    if cusp < len && cusp - m.s < CUSP_REACH * rho && at_rest {
        m.s = cusp;
    }
    let gear = m.rs.gear_at(m.s);
    let cusp = m.rs.next_change(m.s);
    let ahead = m.s + k.lookahead * rho;
    let aim = if cusp < len && ahead > cusp {
        let (q, th, _, _) = m.rs.at(cusp);
        q + trig::unit(th) * (gear * (ahead - cusp))
    } else {
        m.rs.at(ahead).0
    };
    let (_, bearing, _) = seen_from(s, aim);
    let gamma = if gear < 0.0 {
        wrap(bearing + core::f32::consts::PI)
    } else {
        bearing
    };
    let mut straight = m.rs.straight_ahead(m.s);
    if cusp < len {
        straight = straight.at_most(cusp - m.s);
    }
    let mut v = vm.at_least(
        g.speed
            .at_most((vm * vm + 2.0 * 0.8 * p.accel_max * straight).sqrt()),
    );
    if cusp < len {
        v = v.at_most(halting_speed(p, cusp - m.s));
    }
    if g.halting {
        v = v.at_most(halting_speed(p, (len - m.s).at_least(0.0)));
    }
    if gear < 0.0 {
        v = v.at_most(p.v_reverse);
    }
    out.mode = Mode::OrientationOnly;
    out.delta_eta = diff(g.beta, s.theta);
    out.gamma = gamma;
    out.v_dt = gear * v;
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn distance_to_an_arc_and_a_line() {
        // The unit left turn from the origin heading +x: a quarter circle
        // about (0, 1) to (1, 1).
        let q = Vec2::new(0.0, 1.0);
        let k = 1.0;
        let h = core::f32::consts::FRAC_PI_2;
        let d = segment_distance(q, Vec2::ZERO, 0.0, k, h);
        assert!((d - 1.0).abs() < 1e-5, "{d}");
        // The far side of the circle: the arc's nearest end.
        let d = segment_distance(Vec2::new(-1.0, 1.0), Vec2::ZERO, 0.0, k, h);
        assert!((d - 2f32.sqrt()).abs() < 1e-5, "{d}");
        // Backing along the same circle: the other quarter.
        let d = segment_distance(Vec2::new(-1.0, 1.0), Vec2::ZERO, 0.0, k, -h);
        assert!(d.abs() < 1e-5, "{d}");
        // A line driven backwards.
        let d = segment_distance(Vec2::new(-2.0, 1.0), Vec2::ZERO, 0.0, 0.0, -3.0);
        assert!((d - 1.0).abs() < 1e-5, "{d}");
    }
}
