//! Reeds–Shepp shortest paths: the shortest path between two oriented
//! points for a car that goes forwards *and backwards* with a minimum
//! turning radius (gear changes at rest, no turning at rest). Up to five
//! segments, arcs (L, R) and straights (S), each driven in one gear.
//!
//! The formulas are Reeds & Shepp (1990), "Optimal paths for a car that goes
//! both forwards and backwards", Pacific J. Math. 145(2), §8 (formulas
//! 8.1–8.11: CSC, CCC, CCCC, CCSC, CCSCC), with the two typos the paper is
//! known for corrected (8.3/8.4 and 8.11, as in OMPL's
//! `ReedsSheppStateSpace` by M. Moll, which we checked ours against when
//! writing it); the other 40 of the 48 words follow from the paper's three
//! symmetries (§7): *timeflip* `(x, y, φ) → (−x, y, −φ)` drives every
//! segment in the other gear, *reflect* `(x, −y, −φ)` swaps L and R, and
//! *backwards* (the path read from its end) reverses the segment order.
//!
//! Solved in constant time (a fixed list of closed forms) in f64 with the
//! crate's libm, as [`crate::base::dubins`] is and for the same reason:
//! the same bits natively and in wasm. Lengths and paths are returned in
//! f32. The tests integrate every candidate's segments back to the goal.
//! [`candidates`] lists every word with a solution, so a caller can
//! choose by its own cost (length plus a price per gear change,
//! [`cheapest`]).

use core::f64::consts::{FRAC_PI_2, PI, TAU};

use libm::{acos, asin, atan2, cos, sin, sqrt};

use glam::Vec2;
use serde::{Deserialize, Serialize};

/// Slack on the sign conditions of the base formulas (as OMPL's).
const ZERO: f64 = 10.0 * f64::EPSILON;

/// Angle wrapped to [−π, π] (C's `fmod`, then one turn: the paper's `mod`).
fn m2pi(x: f64) -> f64 {
    let v = x % TAU;
    if v < -PI {
        v + TAU
    } else if v > PI {
        v - TAU
    } else {
        v
    }
}

fn polar(x: f64, y: f64) -> (f64, f64) {
    (sqrt(x * x + y * y), atan2(y, x))
}

/// The paper's (τ, ω) of the CCCC words (§8, after 8.6).
fn tau_omega(u: f64, v: f64, xi: f64, eta: f64, phi: f64) -> (f64, f64) {
    let delta = m2pi(u - v);
    let a = sin(u) - sin(delta);
    let b = cos(u) - cos(delta) - 1.0;
    let t1 = atan2(eta * a - xi * b, xi * a + eta * b);
    let t2 = 2.0 * (cos(delta) - cos(v) - cos(u)) + 3.0;
    let tau = if t2 < 0.0 { m2pi(t1 + PI) } else { m2pi(t1) };
    (tau, m2pi(tau - u + v - phi))
}

/// 8.1: L⁺S⁺L⁺.
fn lp_sp_lp(x: f64, y: f64, phi: f64) -> Option<(f64, f64, f64)> {
    let (u, t) = polar(x - sin(phi), y - 1.0 + cos(phi));
    let v = m2pi(phi - t);
    (t >= -ZERO && v >= -ZERO).then_some((t, u, v))
}

/// 8.2: L⁺S⁺R⁺.
fn lp_sp_rp(x: f64, y: f64, phi: f64) -> Option<(f64, f64, f64)> {
    let (u1, t1) = polar(x + sin(phi), y - 1.0 - cos(phi));
    let u1 = u1 * u1;
    if u1 < 4.0 {
        return None;
    }
    let u = sqrt(u1 - 4.0);
    let t = m2pi(t1 + atan2(2.0, u));
    let v = m2pi(t - phi);
    (t >= -ZERO && v >= -ZERO).then_some((t, u, v))
}

/// 8.3 / 8.4 (corrected): L⁺R⁻L.
fn lp_rm_l(x: f64, y: f64, phi: f64) -> Option<(f64, f64, f64)> {
    let (u1, theta) = polar(x - sin(phi), y - 1.0 + cos(phi));
    if u1 > 4.0 {
        return None;
    }
    let u = -2.0 * asin(0.25 * u1);
    let t = m2pi(theta + 0.5 * u + PI);
    let v = m2pi(phi - t + u);
    (t >= -ZERO && u <= ZERO).then_some((t, u, v))
}

/// 8.7: L⁺R⁺ᵤL⁻ᵤR⁻.
fn lp_rup_lum_rm(x: f64, y: f64, phi: f64) -> Option<(f64, f64, f64)> {
    let (xi, eta) = (x + sin(phi), y - 1.0 - cos(phi));
    let rho = 0.25 * (2.0 + sqrt(xi * xi + eta * eta));
    if rho > 1.0 {
        return None;
    }
    let u = acos(rho);
    let (t, v) = tau_omega(u, -u, xi, eta, phi);
    (t >= -ZERO && v <= ZERO).then_some((t, u, v))
}

/// 8.8: L⁺R⁻ᵤL⁻ᵤR⁺.
fn lp_rum_lum_rp(x: f64, y: f64, phi: f64) -> Option<(f64, f64, f64)> {
    let (xi, eta) = (x + sin(phi), y - 1.0 - cos(phi));
    let rho = (20.0 - xi * xi - eta * eta) / 16.0;
    if !(0.0..=1.0).contains(&rho) {
        return None;
    }
    let u = -acos(rho);
    if u < -FRAC_PI_2 {
        return None;
    }
    let (t, v) = tau_omega(u, u, xi, eta, phi);
    (t >= -ZERO && v >= -ZERO).then_some((t, u, v))
}

/// 8.9: L⁺R⁻(π/2)S⁻L⁻.
fn lp_rm_sm_lm(x: f64, y: f64, phi: f64) -> Option<(f64, f64, f64)> {
    let (rho, theta) = polar(x - sin(phi), y - 1.0 + cos(phi));
    if rho < 2.0 {
        return None;
    }
    let r = sqrt(rho * rho - 4.0);
    let u = 2.0 - r;
    let t = m2pi(theta + atan2(r, -2.0));
    let v = m2pi(phi - FRAC_PI_2 - t);
    (t >= -ZERO && u <= ZERO && v <= ZERO).then_some((t, u, v))
}

/// 8.10: L⁺R⁻(π/2)S⁻R⁻.
fn lp_rm_sm_rm(x: f64, y: f64, phi: f64) -> Option<(f64, f64, f64)> {
    let (xi, eta) = (x + sin(phi), y - 1.0 - cos(phi));
    let (rho, theta) = polar(-eta, xi);
    if rho < 2.0 {
        return None;
    }
    let t = theta;
    let u = 2.0 - rho;
    let v = m2pi(t + FRAC_PI_2 - phi);
    (t >= -ZERO && u <= ZERO && v <= ZERO).then_some((t, u, v))
}

/// 8.11 (corrected): L⁺R⁻(π/2)S⁻L⁻(π/2)R⁺.
fn lp_rm_s_lm_rp(x: f64, y: f64, phi: f64) -> Option<(f64, f64, f64)> {
    let (xi, eta) = (x + sin(phi), y - 1.0 - cos(phi));
    let (rho, _) = polar(xi, eta);
    if rho < 2.0 {
        return None;
    }
    let u = 4.0 - sqrt(rho * rho - 4.0);
    if u > ZERO {
        return None;
    }
    let t = m2pi(atan2(
        (4.0 - u) * xi - 2.0 * eta,
        -2.0 * xi + (u - 4.0) * eta,
    ));
    let v = m2pi(t - phi);
    (t >= -ZERO && v >= -ZERO).then_some((t, u, v))
}

/// Steering of a segment: +1 left, −1 right, 0 straight.
type Steer = i8;

/// A base formula: (x, y, φ) to its (t, u, v), or `None` without a
/// solution of the family's signs.
type Formula = fn(f64, f64, f64) -> Option<(f64, f64, f64)>;

/// One base family: its formula, the steering of its segments (0 for
/// straight; unused segments are cut by `n`), and how (t, u, v) become the
/// signed segment lengths.
struct Family {
    solve: Formula,
    steer: [Steer; 5],
    n: usize,
    lens: fn(f64, f64, f64) -> [f64; 5],
    /// The family is not its own reverse: its backwards words are others.
    backwards: bool,
}

const H: f64 = FRAC_PI_2;

const FAMILIES: [Family; 8] = [
    Family {
        solve: lp_sp_lp,
        steer: [1, 0, 1, 0, 0],
        n: 3,
        lens: |t, u, v| [t, u, v, 0.0, 0.0],
        backwards: false,
    },
    Family {
        solve: lp_sp_rp,
        steer: [1, 0, -1, 0, 0],
        n: 3,
        lens: |t, u, v| [t, u, v, 0.0, 0.0],
        backwards: false,
    },
    Family {
        solve: lp_rm_l,
        steer: [1, -1, 1, 0, 0],
        n: 3,
        lens: |t, u, v| [t, u, v, 0.0, 0.0],
        backwards: true,
    },
    Family {
        solve: lp_rup_lum_rm,
        steer: [1, -1, 1, -1, 0],
        n: 4,
        lens: |t, u, v| [t, u, -u, v, 0.0],
        backwards: false,
    },
    Family {
        solve: lp_rum_lum_rp,
        steer: [1, -1, 1, -1, 0],
        n: 4,
        lens: |t, u, v| [t, u, u, v, 0.0],
        backwards: false,
    },
    Family {
        solve: lp_rm_sm_lm,
        steer: [1, -1, 0, 1, 0],
        n: 4,
        lens: |t, u, v| [t, -H, u, v, 0.0],
        backwards: true,
    },
    Family {
        solve: lp_rm_sm_rm,
        steer: [1, -1, 0, -1, 0],
        n: 4,
        lens: |t, u, v| [t, -H, u, v, 0.0],
        backwards: true,
    },
    Family {
        solve: lp_rm_s_lm_rp,
        steer: [1, -1, 0, 1, -1],
        n: 5,
        lens: |t, u, v| [t, -H, u, -H, v],
        backwards: false,
    },
];

/// One word's solution in the unit-radius frame of the start: the
/// steering and the signed length (negative: backwards) of up to five
/// segments.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Candidate {
    /// Steering of each segment: +1 left, −1 right, 0 straight.
    pub steer: [i8; 5],
    /// Signed length of each segment, radii (0 for an unused one).
    pub len: [f64; 5],
}

impl Candidate {
    /// Total length, radii.
    #[must_use]
    pub fn length(&self) -> f64 {
        self.len.iter().map(|l| l.abs()).sum()
    }

    /// The gear of the first and the last segment driven (+1 forwards,
    /// −1 backwards; +1 for an empty path) and the gear changes between.
    #[must_use]
    pub fn gears(&self) -> (f32, f32, u32) {
        let mut first = 0.0;
        let mut last = 0.0;
        let mut changes = 0;
        for &l in &self.len {
            if l.abs() <= 1e-9 {
                continue;
            }
            let g = if l < 0.0 { -1.0 } else { 1.0 };
            if last != 0.0 && g != last {
                changes += 1;
            }
            if first == 0.0 {
                first = g;
            }
            last = g;
        }
        if first == 0.0 {
            (1.0, 1.0, 0)
        } else {
            (first, last, changes)
        }
    }
}

/// Every word with a solution from the origin at heading 0 to `(x, y)`
/// at heading `phi`, unit radius: the eight base families under the
/// paper's symmetries (at most 48; `f` is called once per candidate, in a
/// fixed order).
pub fn candidates(x: f64, y: f64, phi: f64, mut f: impl FnMut(Candidate)) {
    let (sp, cp) = (sin(phi), cos(phi));
    let (xb, yb) = (x * cp + y * sp, x * sp - y * cp);
    for fam in &FAMILIES {
        for back in [false, true] {
            if back && !fam.backwards {
                continue;
            }
            let (x0, y0) = if back { (xb, yb) } else { (x, y) };
            for (flip, refl) in [(false, false), (true, false), (false, true), (true, true)] {
                let xi = if flip { -x0 } else { x0 };
                let yi = if refl { -y0 } else { y0 };
                let pi = if flip != refl { -phi } else { phi };
                let Some((t, u, v)) = (fam.solve)(xi, yi, pi) else {
                    continue;
                };
                let mut len = (fam.lens)(t, u, v);
                let mut steer = fam.steer;
                if flip {
                    len = len.map(|l| -l);
                }
                if refl {
                    steer = steer.map(|s| -s);
                }
                if back {
                    len[..fam.n].reverse();
                    steer[..fam.n].reverse();
                }
                if len.iter().all(|l| l.is_finite()) {
                    f(Candidate { steer, len });
                }
            }
        }
    }
}

/// The start→goal query in the start's frame, in radii: (x, y, φ).
fn frame(start: (f32, f32, f32), goal: (f32, f32, f32), rho: f64) -> (f64, f64, f64) {
    let dx = f64::from(goal.0) - f64::from(start.0);
    let dy = f64::from(goal.1) - f64::from(start.1);
    let th = f64::from(start.2);
    let (s, c) = (sin(th), cos(th));
    (
        (c * dx + s * dy) / rho,
        (-s * dx + c * dy) / rho,
        f64::from(goal.2) - th,
    )
}

/// Length of the shortest Reeds–Shepp path from `(x0, y0, θ0)` to `(x1, y1,
/// θ1)` with minimum turning radius `rho` (> 0), in the units of the input.
#[must_use]
pub fn shortest_length(start: (f32, f32, f32), goal: (f32, f32, f32), rho: f32) -> f32 {
    let r = f64::from(rho.max(1e-6));
    let (x, y, phi) = frame(start, goal, r);
    let mut best = f64::INFINITY;
    candidates(x, y, phi, |c| best = best.min(c.length()));
    (best * r) as f32
}

/// Most segments a kept path has: a word's five and a straight run-in.
pub const SEGMENTS: usize = 6;

/// One Reeds–Shepp path kept to be followed: the start pose and, per
/// segment, its signed curvature (heading change per metre driven in the
/// segment's gear, ±1/ρ or 0), its length in metres and its gear (+1
/// forwards, −1 backwards). Beyond its end the path goes on straight
/// along the final heading in the final gear. Sampled in constant time
/// with [`crate::base::trig`] only, so following it is bit-identical
/// natively and in wasm (as [`crate::base::dubins::DubinsPath`]).
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "camelCase")]
pub struct ReedsSheppPath {
    /// Start position, m.
    pub start: Vec2,
    /// Start heading, rad.
    pub theta: f32,
    /// Signed curvature of each segment, 1/m.
    pub kappa: [f32; SEGMENTS],
    /// Length of each segment, m (0 for none).
    pub len: [f32; SEGMENTS],
    /// Gear of each segment: +1 forwards, −1 backwards.
    pub gear: [f32; SEGMENTS],
    /// Position and heading where each segment starts.
    pub knots: [(Vec2, f32); SEGMENTS],
}

impl ReedsSheppPath {
    /// The path of `c` (unit radius, in the frame of `start`) with radius
    /// `rho`, then a straight of `run_in` metres in gear `run_gear`.
    #[must_use]
    pub fn of(start: (f32, f32, f32), c: &Candidate, rho: f32, run_in: f32, run_gear: f32) -> Self {
        let mut kappa = [0.0; SEGMENTS];
        let mut len = [0.0; SEGMENTS];
        let mut gear = [1.0; SEGMENTS];
        for i in 0..5 {
            let l = c.len[i];
            len[i] = (l.abs() * f64::from(rho)) as f32;
            gear[i] = if l < 0.0 { -1.0 } else { 1.0 };
            kappa[i] = f32::from(c.steer[i]) / rho;
        }
        len[5] = run_in;
        gear[5] = run_gear;
        Self::from_segments(Vec2::new(start.0, start.1), start.2, kappa, len, gear)
    }

    /// The path from `start` at heading `theta` through the given segments.
    #[must_use]
    pub fn from_segments(
        start: Vec2,
        theta: f32,
        kappa: [f32; SEGMENTS],
        len: [f32; SEGMENTS],
        gear: [f32; SEGMENTS],
    ) -> Self {
        let mut knots = [(start, theta); SEGMENTS];
        for i in 1..SEGMENTS {
            let (p, t) = knots[i - 1];
            knots[i] = advance(p, t, kappa[i - 1], len[i - 1] * gear[i - 1]);
        }
        Self {
            start,
            theta,
            kappa,
            len,
            gear,
            knots,
        }
    }

    /// Never set (a forward-only vehicle's manoeuvre).
    #[must_use]
    #[allow(clippy::trivially_copy_pass_by_ref)]
    pub fn is_unused(&self) -> bool {
        *self == Self::default()
    }

    /// What is left of the straight segment at arc length `s` (unbounded
    /// past the end, where the path goes on straight), 0 on an arc.
    #[must_use]
    pub fn straight_ahead(&self, s: f32) -> f32 {
        let (i, from) = self.segment(s);
        if self.kappa[i] != 0.0 {
            return 0.0;
        }
        if i == SEGMENTS - 1 || self.len[i + 1..].iter().all(|l| *l == 0.0) {
            return f32::INFINITY;
        }
        from + self.len[i] - s
    }

    /// Total length driven, m.
    #[must_use]
    pub fn length(&self) -> f32 {
        self.len.iter().sum()
    }

    /// The segment driven at arc length `s` (the last for `s` beyond the
    /// end) and the arc length where it starts.
    fn segment(&self, s: f32) -> (usize, f32) {
        let mut from = 0.0;
        let mut last = 0;
        for i in 0..SEGMENTS {
            if self.len[i] > 0.0 {
                if s < from + self.len[i] {
                    return (i, from);
                }
                last = i;
            }
            from += self.len[i];
        }
        (last, from - self.len[last])
    }

    /// The gear driven at arc length `s`.
    #[must_use]
    pub fn gear_at(&self, s: f32) -> f32 {
        self.gear[self.segment(s).0]
    }

    /// Arc length of the next gear change after `s` (where the vehicle
    /// must be at rest), or the path's end when there is none.
    #[must_use]
    pub fn next_change(&self, s: f32) -> f32 {
        let (i, from) = self.segment(s);
        let g = self.gear[i];
        let mut end = from;
        for j in i..SEGMENTS {
            if self.len[j] > 0.0 && self.gear[j] != g {
                return end;
            }
            end += self.len[j];
        }
        end
    }

    /// Gear changes along the whole path.
    #[must_use]
    pub fn changes(&self) -> u32 {
        let mut last = 0.0;
        let mut n = 0;
        for i in 0..SEGMENTS {
            if self.len[i] > 0.0 {
                n += u32::from(last != 0.0 && self.gear[i] != last);
                last = self.gear[i];
            }
        }
        n
    }

    /// Position, heading, curvature and gear at arc length `s` (clamped
    /// below at 0; past the end, straight on in the final gear).
    #[must_use]
    pub fn at(&self, s: f32) -> (Vec2, f32, f32, f32) {
        let s = s.max(0.0);
        let (i, from) = self.segment(s);
        let (pos, th) = self.knots[i];
        let l = s - from;
        if l <= self.len[i] {
            let (p, t) = advance(pos, th, self.kappa[i], l * self.gear[i]);
            return (p, t, self.kappa[i], self.gear[i]);
        }
        let (end, th) = advance(pos, th, self.kappa[i], self.len[i] * self.gear[i]);
        let more = (l - self.len[i]) * self.gear[i];
        (
            end + crate::base::trig::unit(th) * more,
            th,
            0.0,
            self.gear[i],
        )
    }
}

/// Moves the signed distance `l` (negative: backwards) along a segment of
/// curvature `k` from `pos` at heading `th`.
fn advance(pos: Vec2, th: f32, k: f32, l: f32) -> (Vec2, f32) {
    if k == 0.0 {
        return (pos + crate::base::trig::unit(th) * l, th);
    }
    let th1 = th + k * l;
    let (s0, c0) = crate::base::trig::sin_cos(th);
    let (s1, c1) = crate::base::trig::sin_cos(th1);
    (pos + Vec2::new(s1 - s0, c0 - c1) / k, th1)
}

/// The candidate of least cost from `start` to `goal` with radius `rho`,
/// a gear change costing `gear_cost` metres; `admit` may refuse a
/// candidate (given its path in metres without a run-in). `None` when
/// every candidate is refused or the input is not finite.
pub fn cheapest(
    start: (f32, f32, f32),
    goal: (f32, f32, f32),
    rho: f32,
    gear_cost: f32,
    mut admit: impl FnMut(&Candidate, f64) -> bool,
) -> Option<(Candidate, f64)> {
    let r = f64::from(rho.max(1e-6));
    let (x, y, phi) = frame(start, goal, r);
    let mut best: Option<(Candidate, f64)> = None;
    candidates(x, y, phi, |c| {
        let cost = c.length() * r + f64::from(gear_cost) * f64::from(c.gears().2);
        if best.is_none_or(|(_, b)| cost < b) && admit(&c, cost) {
            best = Some((c, cost));
        }
    });
    best
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Integrates a candidate's segments from the origin at heading 0.
    fn endpoint(c: &Candidate) -> (f64, f64, f64) {
        let (mut x, mut y, mut th) = (0.0f64, 0.0f64, 0.0f64);
        for (s, l) in c.steer.iter().zip(c.len) {
            match s {
                1 => {
                    x += (th + l).sin() - th.sin();
                    y += -(th + l).cos() + th.cos();
                    th += l;
                }
                -1 => {
                    x += -(th - l).sin() + th.sin();
                    y += (th - l).cos() - th.cos();
                    th -= l;
                }
                _ => {
                    x += l * th.cos();
                    y += l * th.sin();
                }
            }
        }
        (x, y, th)
    }

    #[test]
    fn every_candidate_ends_at_the_goal_pose() {
        let mut r = crate::base::rng::Rng::new(7);
        let mut solved = 0;
        for _ in 0..3000 {
            let x = f64::from(r.range(-8.0, 8.0));
            let y = f64::from(r.range(-8.0, 8.0));
            let phi = f64::from(r.range(-3.1, 3.1));
            candidates(x, y, phi, |c| {
                let (ex, ey, eth) = endpoint(&c);
                assert!((ex - x).abs() < 1e-6 && (ey - y).abs() < 1e-6, "{c:?}");
                assert!(m2pi(eth - phi).abs() < 1e-6, "{c:?}");
                solved += 1;
            });
        }
        assert!(solved > 3000 * 5, "{solved}");
    }

    #[test]
    fn a_kept_path_ends_at_the_goal_and_never_beats_nor_loses_to_dubins_wrongly() {
        let mut r = crate::base::rng::Rng::new(11);
        for _ in 0..2000 {
            let st = (r.range(-5.0, 5.0), r.range(-5.0, 5.0), r.range(-3.1, 3.1));
            let g = (r.range(-9.0, 9.0), r.range(-9.0, 9.0), r.range(-3.1, 3.1));
            let rho = r.range(0.5, 4.0);
            let (c, _) = cheapest(st, g, rho, 0.0, |_, _| true).unwrap();
            let path = ReedsSheppPath::of(st, &c, rho, 0.0, 1.0);
            let (p, th, _, _) = path.at(path.length());
            assert!(
                (p - Vec2::new(g.0, g.1)).length() < 1e-3 * (1.0 + rho),
                "{p} {g:?}"
            );
            assert!(crate::base::angle::diff(th, g.2).abs() < 1e-3);
            let l = shortest_length(st, g, rho);
            assert!((path.length() - l).abs() < 1e-3 * l.max(1.0));
            // Backing never makes a path longer than the forward one.
            assert!(l <= crate::base::dubins::shortest_length(st, g, rho) + 1e-3);
        }
    }

    #[test]
    fn known_lengths_and_gears() {
        // Straight behind: back up the distance, one gear, no change.
        let (c, _) = cheapest((0.0, 0.0, 0.0), (-3.0, 0.0, 0.0), 1.0, 0.0, |_, _| true).unwrap();
        assert!((c.length() - 3.0).abs() < 1e-9);
        assert_eq!(c.gears(), (-1.0, -1.0, 0));
        let p = ReedsSheppPath::of((0.0, 0.0, 0.0), &c, 1.0, 0.0, -1.0);
        assert_eq!(p.gear_at(1.0), -1.0);
        assert!((p.at(1.0).0 - Vec2::new(-1.0, 0.0)).length() < 1e-6);
        // A price per gear change chooses fewer changes, at a length.
        let mut r = crate::base::rng::Rng::new(13);
        let mut fewer = 0;
        for _ in 0..1000 {
            let goal = (r.range(-3.0, 3.0), r.range(-3.0, 3.0), r.range(-3.1, 3.1));
            let (free, _) = cheapest((0.0, 0.0, 0.0), goal, 1.0, 0.0, |_, _| true).unwrap();
            let (dear, _) = cheapest((0.0, 0.0, 0.0), goal, 1.0, 100.0, |_, _| true).unwrap();
            assert!(dear.gears().2 <= free.gears().2, "{free:?} {dear:?}");
            assert!(dear.length() >= free.length() - 1e-9);
            fewer += usize::from(dear.gears().2 < free.gears().2);
        }
        assert!(fewer > 10, "{fewer}");
    }
}
