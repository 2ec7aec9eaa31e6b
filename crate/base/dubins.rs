//! Dubins shortest paths (Dubins 1957; cited by paper 000 §2): the shortest
//! C¹ path between two oriented points with a minimum turning radius, made
//! of arcs (L, R) and a straight (S) or three arcs. It is the geometric
//! lower bound against which funnelling paths are compared (docs/DESIGN.md §17).
//!
//! Formulas follow Shkel & Lumelsky (2001) in the frame where the start is
//! at the origin and the goal on the positive x axis at normalised distance
//! `d`; computed in f64 with libm, only lengths are returned. Each word is checked in
//! the tests by integrating its segments to the goal pose.

use core::f64::consts::TAU;

// The crate's libm, not std's f64 methods: natively std calls the host's C
// library, in wasm a port of musl's, and the two may round a last bit
// apart. One implementation on both targets keeps a planned path, and so
// a car-like agent's trajectory, bit-identical natively and in the
// browser. (`sqrt` and `rem_euclid` are exact in IEEE arithmetic.)
use libm::{acos, atan2, cos, sin};

use glam::Vec2;
use serde::{Deserialize, Serialize};

/// The six Dubins words.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Word {
    /// Left, straight, left.
    Lsl,
    /// Right, straight, right.
    Rsr,
    /// Left, straight, right.
    Lsr,
    /// Right, straight, left.
    Rsl,
    /// Right, left, right.
    Rlr,
    /// Left, right, left.
    Lrl,
}

/// All words, for iteration.
pub const WORDS: [Word; 6] = [
    Word::Lsl,
    Word::Rsr,
    Word::Lsr,
    Word::Rsl,
    Word::Rlr,
    Word::Lrl,
];

fn m2pi(x: f64) -> f64 {
    x.rem_euclid(TAU)
}

/// Normalised segment lengths (t, p, q) of `word` from heading `a` at the
/// origin to heading `b` at `(d, 0)`, with unit turning radius; `None` when
/// the word has no solution.
#[must_use]
pub fn segments(word: Word, a: f64, b: f64, d: f64) -> Option<(f64, f64, f64)> {
    let (sa, ca, sb, cb) = (sin(a), cos(a), sin(b), cos(b));
    let cab = cos(a - b);
    match word {
        Word::Lsl => {
            let p2 = 2.0 + d * d - 2.0 * cab + 2.0 * d * (sa - sb);
            if p2 < 0.0 {
                return None;
            }
            let th = atan2(cb - ca, d + sa - sb);
            Some((m2pi(th - a), p2.sqrt(), m2pi(b - th)))
        }
        Word::Rsr => {
            let p2 = 2.0 + d * d - 2.0 * cab + 2.0 * d * (sb - sa);
            if p2 < 0.0 {
                return None;
            }
            let th = atan2(ca - cb, d - sa + sb);
            Some((m2pi(a - th), p2.sqrt(), m2pi(th - b)))
        }
        Word::Lsr => {
            let p2 = -2.0 + d * d + 2.0 * cab + 2.0 * d * (sa + sb);
            if p2 < 0.0 {
                return None;
            }
            let p = p2.sqrt();
            let th = atan2(-ca - cb, d + sa + sb) - atan2(-2.0, p);
            Some((m2pi(th - a), p, m2pi(th - b)))
        }
        Word::Rsl => {
            let p2 = d * d - 2.0 + 2.0 * cab - 2.0 * d * (sa + sb);
            if p2 < 0.0 {
                return None;
            }
            let p = p2.sqrt();
            let th = atan2(ca + cb, d - sa - sb) - atan2(2.0, p);
            Some((m2pi(a - th), p, m2pi(b - th)))
        }
        Word::Rlr => {
            let tmp = (6.0 - d * d + 2.0 * cab + 2.0 * d * (sa - sb)) / 8.0;
            if tmp.abs() > 1.0 {
                return None;
            }
            let p = m2pi(TAU - acos(tmp));
            let t = m2pi(a - atan2(ca - cb, d - sa + sb) + p / 2.0);
            Some((t, p, m2pi(a - b - t + p)))
        }
        Word::Lrl => {
            let tmp = (6.0 - d * d + 2.0 * cab + 2.0 * d * (sb - sa)) / 8.0;
            if tmp.abs() > 1.0 {
                return None;
            }
            let p = m2pi(TAU - acos(tmp));
            let t = m2pi(-a - atan2(ca - cb, d + sa - sb) + p / 2.0);
            Some((t, p, m2pi(b - a - t + p)))
        }
    }
}

/// The normalised frame of a query: the radius in f64 (at least 1e-6), the
/// distance `d` in radii and the start and goal headings `a`, `b` measured
/// from the start→goal direction.
fn frame(start: (f32, f32, f32), goal: (f32, f32, f32), rho: f32) -> (f64, f64, f64, f64) {
    let rho = f64::from(rho.max(1e-6));
    let dx = f64::from(goal.0 - start.0);
    let dy = f64::from(goal.1 - start.1);
    let d = (dx * dx + dy * dy).sqrt() / rho;
    let phi = if d > 0.0 { atan2(dy, dx) } else { 0.0 };
    (
        rho,
        d,
        m2pi(f64::from(start.2) - phi),
        m2pi(f64::from(goal.2) - phi),
    )
}

/// Length of the shortest Dubins path from `(x0, y0, θ0)` to `(x1, y1, θ1)`
/// with minimum turning radius `rho` (> 0), in the units of the input.
#[must_use]
pub fn shortest_length(start: (f32, f32, f32), goal: (f32, f32, f32), rho: f32) -> f32 {
    let (rho, d, a, b) = frame(start, goal, rho);
    let best = WORDS
        .iter()
        .filter_map(|&w| segments(w, a, b, d))
        .map(|(t, p, q)| t + p + q)
        .fold(f64::INFINITY, f64::min);
    (best * rho) as f32
}

/// The turn of each segment of `word`: +1 left, −1 right, 0 straight.
#[must_use]
pub fn turns(word: Word) -> [f32; 3] {
    match word {
        Word::Lsl => [1.0, 0.0, 1.0],
        Word::Rsr => [-1.0, 0.0, -1.0],
        Word::Lsr => [1.0, 0.0, -1.0],
        Word::Rsl => [-1.0, 0.0, 1.0],
        Word::Rlr => [-1.0, 1.0, -1.0],
        Word::Lrl => [1.0, -1.0, 1.0],
    }
}

/// One shortest Dubins path, kept to be followed: the start pose, the
/// signed curvature of each of its three segments and their lengths in
/// metres. Solved once in constant time ([`DubinsPath::shortest`]: six
/// closed forms), sampled in constant time ([`DubinsPath::at`]: at most
/// three segments). Beyond its end the path goes on straight along the
/// goal heading, so a follower aiming ahead of the end is led onto it.
///
/// The solve runs in f64 with libm (the same code on every target) and is
/// rounded to f32; the sampling uses only [`crate::base::trig`]; so
/// following it is bit-identical natively and in wasm.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "camelCase")]
pub struct DubinsPath {
    /// Start position, m.
    pub start: Vec2,
    /// Start heading, rad.
    pub theta: f32,
    /// Signed curvature of each segment (±1/ρ or 0), 1/m.
    pub kappa: [f32; 3],
    /// Length of each segment, m.
    pub len: [f32; 3],
    /// Position and heading where each segment starts (the first is the
    /// start pose), so a sample advances along one segment only.
    pub knots: [(Vec2, f32); 3],
}

impl DubinsPath {
    /// The shortest forward path from `start` (x, y, θ) to `goal` with
    /// turning radius `rho` (> 0); `None` only for a degenerate input
    /// (non-finite).
    #[must_use]
    pub fn shortest(start: (f32, f32, f32), goal: (f32, f32, f32), rho: f32) -> Option<Self> {
        let (r, d, a, b) = frame(start, goal, rho);
        let (word, (t, p, q)) = WORDS
            .iter()
            .filter_map(|&w| segments(w, a, b, d).map(|s| (w, s)))
            .filter(|(_, (t, p, q))| (t + p + q).is_finite())
            .min_by(|x, y| (x.1 .0 + x.1 .1 + x.1 .2).total_cmp(&(y.1 .0 + y.1 .1 + y.1 .2)))?;
        Some(Self::of_solution(word, (t, p, q), r, start))
    }

    /// The path of `word` from `start` (x, y, θ) to `goal` with turning
    /// radius `rho` (> 0), not necessarily the shortest; `None` when the
    /// word has no solution.
    #[must_use]
    pub fn of_word(
        word: Word,
        start: (f32, f32, f32),
        goal: (f32, f32, f32),
        rho: f32,
    ) -> Option<Self> {
        let (r, d, a, b) = frame(start, goal, rho);
        let (t, p, q) = segments(word, a, b, d).filter(|(t, p, q)| (t + p + q).is_finite())?;
        Some(Self::of_solution(word, (t, p, q), r, start))
    }

    /// The path of `word` whose segments are `(t, p, q)` turning radii
    /// `r` long, from `start` (x, y, θ).
    fn of_solution(word: Word, (t, p, q): (f64, f64, f64), r: f64, start: (f32, f32, f32)) -> Self {
        let k = (1.0 / r) as f32;
        let tn = turns(word);
        Self::from_segments(
            Vec2::new(start.0, start.1),
            start.2,
            [tn[0] * k, tn[1] * k, tn[2] * k],
            [(t * r) as f32, (p * r) as f32, (q * r) as f32],
        )
    }

    /// The path from `start` at heading `theta` through three segments of
    /// curvature `kappa` and length `len` (a zero length for none).
    #[must_use]
    pub fn from_segments(start: Vec2, theta: f32, kappa: [f32; 3], len: [f32; 3]) -> Self {
        let mut knots = [(start, theta); 3];
        for i in 1..3 {
            let (p, t) = knots[i - 1];
            knots[i] = advance(p, t, kappa[i - 1], len[i - 1]);
        }
        Self {
            start,
            theta,
            kappa,
            len,
            knots,
        }
    }

    /// Total length, m.
    #[must_use]
    pub fn length(&self) -> f32 {
        self.len[0] + self.len[1] + self.len[2]
    }

    /// The straight distance ahead at arc length `s`: what is left of the
    /// straight segment `s` lies on (unbounded past the end, where the
    /// path goes on straight), 0 on an arc.
    #[must_use]
    pub fn straight_ahead(&self, s: f32) -> f32 {
        let mut end = 0.0;
        for i in 0..3 {
            end += self.len[i];
            if s < end {
                return if self.kappa[i] == 0.0 { end - s } else { 0.0 };
            }
        }
        f32::INFINITY
    }

    /// Position, heading and curvature at arc length `s` (clamped below
    /// at 0; past the end, straight on along the final heading).
    #[must_use]
    pub fn at(&self, s: f32) -> (Vec2, f32, f32) {
        let mut left = s.max(0.0);
        for i in 0..3 {
            if left <= self.len[i] {
                let (pos, th) = self.knots[i];
                let (p, t) = advance(pos, th, self.kappa[i], left);
                return (p, t, self.kappa[i]);
            }
            left -= self.len[i];
        }
        let (pos, th) = self.knots[2];
        let (end, th) = advance(pos, th, self.kappa[2], self.len[2]);
        (end + crate::base::trig::unit(th) * left, th, 0.0)
    }
}

/// Moves `l` along a segment of curvature `k` from `pos` at heading `th`.
fn advance(pos: Vec2, th: f32, k: f32, l: f32) -> (Vec2, f32) {
    if k == 0.0 {
        return (pos + crate::base::trig::unit(th) * l, th);
    }
    let th1 = th + k * l;
    let (s0, c0) = crate::base::trig::sin_cos(th);
    let (s1, c1) = crate::base::trig::sin_cos(th1);
    (pos + Vec2::new(s1 - s0, c0 - c1) / k, th1)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Integrates a word's segments from the origin at heading `a`.
    fn endpoint(w: Word, a: f64, (t, p, q): (f64, f64, f64)) -> (f64, f64, f64) {
        let kinds: [char; 3] = match w {
            Word::Lsl => ['L', 'S', 'L'],
            Word::Rsr => ['R', 'S', 'R'],
            Word::Lsr => ['L', 'S', 'R'],
            Word::Rsl => ['R', 'S', 'L'],
            Word::Rlr => ['R', 'L', 'R'],
            Word::Lrl => ['L', 'R', 'L'],
        };
        let (mut x, mut y, mut th) = (0.0f64, 0.0f64, a);
        for (k, len) in kinds.iter().zip([t, p, q]) {
            match k {
                'L' => {
                    x += (th + len).sin() - th.sin();
                    y += -(th + len).cos() + th.cos();
                    th += len;
                }
                'R' => {
                    x += -(th - len).sin() + th.sin();
                    y += (th - len).cos() - th.cos();
                    th -= len;
                }
                _ => {
                    x += len * th.cos();
                    y += len * th.sin();
                }
            }
        }
        (x, y, th)
    }

    #[test]
    fn a_path_of_any_word_ends_at_the_goal_pose() {
        let (from, to, rho) = ((1.0, -2.0, 0.3), (4.0, 3.0, -2.0), 1.5);
        let mut n = 0;
        for w in WORDS {
            if let Some(path) = DubinsPath::of_word(w, from, to, rho) {
                n += 1;
                let (q, th, _) = path.at(path.length());
                assert!((q - Vec2::new(to.0, to.1)).length() < 1e-4, "{w:?}: {q:?}");
                assert!(
                    crate::base::angle::diff(th, to.2).abs() < 1e-4,
                    "{w:?}: {th}"
                );
            }
        }
        assert!(n >= 4, "{n}");
    }

    #[test]
    fn every_word_solution_ends_at_the_goal_pose() {
        let mut r = crate::base::rng::Rng::new(3);
        let mut solved = 0;
        for _ in 0..2000 {
            let a = f64::from(r.range(0.0, core::f32::consts::TAU));
            let b = f64::from(r.range(0.0, core::f32::consts::TAU));
            let d = f64::from(r.range(0.0, 6.0));
            for w in WORDS {
                if let Some(seg) = segments(w, a, b, d) {
                    let (x, y, th) = endpoint(w, a, seg);
                    assert!(
                        (x - d).abs() < 1e-6 && y.abs() < 1e-6,
                        "{w:?} {a} {b} {d}: ({x}, {y})"
                    );
                    assert!(
                        (m2pi(th - b) + 1e-9) % TAU < 1e-6 || (TAU - m2pi(th - b)) < 1e-6,
                        "{w:?} heading"
                    );
                    solved += 1;
                }
            }
        }
        assert!(solved > 6000);
    }

    #[test]
    fn a_kept_path_ends_at_the_goal_pose_and_has_the_shortest_length() {
        let mut r = crate::base::rng::Rng::new(5);
        for _ in 0..2000 {
            let g = (
                r.range(-20.0, 20.0),
                r.range(-20.0, 20.0),
                r.range(-3.1, 3.1),
            );
            let st = (r.range(-5.0, 5.0), r.range(-5.0, 5.0), r.range(-3.1, 3.1));
            let rho = r.range(0.5, 6.0);
            let path = DubinsPath::shortest(st, g, rho).unwrap();
            let (p, th, _) = path.at(path.length());
            assert!(
                (p - Vec2::new(g.0, g.1)).length() < 1e-3 * (1.0 + rho),
                "{p} {g:?}"
            );
            assert!(crate::base::angle::diff(th, g.2).abs() < 1e-3);
            assert!(
                (path.length() - shortest_length(st, g, rho)).abs() < 1e-3 * path.length().max(1.0)
            );
            // Beyond the end: straight on along the goal heading.
            let (q, _, k) = path.at(path.length() + 2.0);
            assert!((q - p - crate::base::trig::unit(th) * 2.0).length() < 1e-3);
            assert_eq!(k, 0.0);
        }
    }

    #[test]
    fn known_lengths() {
        // Straight ahead: the distance.
        assert!((shortest_length((0.0, 0.0, 0.0), (10.0, 0.0, 0.0), 1.0) - 10.0).abs() < 1e-4);
        // A half turn to the point beside: π·ρ.
        let l = shortest_length((0.0, 0.0, 0.0), (0.0, 2.0, core::f32::consts::PI), 1.0);
        assert!((l - core::f32::consts::PI).abs() < 1e-4, "{l}");
        // Reversing in place is impossible: a full teardrop, longer than 2π·ρ... not
        // exactly: same point, opposite heading, needs > π·ρ and ≤ (2 + π)ρ·something.
        let l = shortest_length((0.0, 0.0, 0.0), (0.0, 0.0, core::f32::consts::PI), 1.0);
        assert!(l > 3.0 && l < 8.0, "{l}");
        // Scale invariance.
        let a = shortest_length((0.0, 0.0, 0.3), (4.0, 1.0, 2.0), 1.0);
        let b = shortest_length((0.0, 0.0, 0.3), (8.0, 2.0, 2.0), 2.0);
        assert!((2.0 * a - b).abs() < 1e-3);
        // Never shorter than the straight distance.
        let l = shortest_length((0.0, 0.0, 2.0), (5.0, -3.0, -1.0), 0.7);
        assert!(l >= 34f32.sqrt());
    }
}
