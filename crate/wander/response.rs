//! The 2D response curve of paper 004 §6: "We can smooth out the results
//! by using a 2D response curve, but this can be tricky. Also, we need to
//! specify many values to get the 2D distribution we want."
//!
//! Problem: a transition table over angle ranges is a step function twice
//! over: the next angle's distribution jumps when the current angle
//! crosses a range edge (14.9° and 15.1° get rows 0.9 / 0.15 apart), and
//! within a range every angle is equally likely.
//!
//! Design: the same `n × n` table read as samples of a smooth density
//! `p(next | current)`, so no more values need specifying. Each row `i`
//! is a density over the next angle, piecewise linear through
//! `table[i][j] / width_j` at the range midpoints, flat to the outer
//! edges; the row used for a current angle blends the two rows whose
//! midpoints enclose it, linearly (flat beyond the first and last
//! midpoints). A draw inverts the blended density's cumulative
//! distribution exactly: one trapezoid per segment, a quadratic inside it.
//! Cost: O(n) per draw, no allocation (n + 1 segments, at most 17 for the
//! 16 ranges a table may have).
//!
//! Measured (`tests/fidelity.rs`, `p004_sec6_response_curve_smooths_the_table`):
//! P(next < 15°) for a current angle of 14.9° against 15.1° differs by
//! 0.75 with the paper's table and under 0.01 with the curve.

use crate::base::rng::Rng;

/// Ranges a response curve accepts (segments are kept on the stack).
pub const MAX_RANGES: usize = 16;

/// A transition table read as a smooth 2D response curve (module docs).
#[derive(Clone, Debug, PartialEq)]
pub struct ResponseCurve {
    /// Range edges, radians (`n + 1`, increasing).
    edges: Vec<f32>,
    /// Row densities at the range midpoints, per radian (`n × n`).
    density: Vec<f32>,
    /// Range midpoints, radians.
    mids: Vec<f32>,
}

impl ResponseCurve {
    /// From validated edges (radians) and a row-stochastic table with at
    /// most [`MAX_RANGES`] ranges (checked by the caller's validation).
    #[must_use]
    pub fn new(edges: &[f32], table: &[Vec<f32>]) -> Self {
        let n = edges.len() - 1;
        let mids: Vec<f32> = (0..n).map(|j| 0.5 * (edges[j] + edges[j + 1])).collect();
        let density = table
            .iter()
            .flat_map(|row| (0..n).map(move |j| row[j] / (edges[j + 1] - edges[j])))
            .collect();
        Self {
            edges: edges.to_vec(),
            density,
            mids,
        }
    }

    /// The blended density at the `n` midpoints for `current` (radians).
    fn row(&self, current: f32, out: &mut [f32; MAX_RANGES]) {
        let n = self.mids.len();
        let (i, t) = match self.mids.iter().position(|&m| current < m) {
            None => (n - 1, 0.0),
            Some(0) => (0, 0.0),
            Some(k) => (
                k - 1,
                (current - self.mids[k - 1]) / (self.mids[k] - self.mids[k - 1]),
            ),
        };
        let k = (i + 1).min(n - 1);
        for (j, o) in out.iter_mut().enumerate().take(n) {
            *o = (1.0 - t) * self.density[i * n + j] + t * self.density[k * n + j];
        }
    }

    /// `P(next < x | current)`: for tests and the gallery's explanation.
    #[must_use]
    pub fn cdf(&self, current: f32, x: f32) -> f32 {
        let mut f = [0.0f32; MAX_RANGES];
        self.row(current, &mut f);
        let (mut acc, mut total) = (0.0f32, 0.0f32);
        self.segments(&f, |a, b, fa, fb| {
            let area = 0.5 * (fa + fb) * (b - a);
            total += area;
            if x >= b {
                acc += area;
            } else if x > a {
                let fx = fa + (fb - fa) * (x - a) / (b - a);
                acc += 0.5 * (fa + fx) * (x - a);
            }
        });
        if total > 0.0 {
            acc / total
        } else {
            0.0
        }
    }

    /// Visits the `n + 1` linear segments `(a, b, f(a), f(b))` of a row.
    fn segments(&self, f: &[f32; MAX_RANGES], mut visit: impl FnMut(f32, f32, f32, f32)) {
        let n = self.mids.len();
        visit(self.edges[0], self.mids[0], f[0], f[0]);
        for j in 0..n - 1 {
            visit(self.mids[j], self.mids[j + 1], f[j], f[j + 1]);
        }
        visit(self.mids[n - 1], self.edges[n], f[n - 1], f[n - 1]);
    }

    /// Draws the next angle (radians) given the current one.
    #[inline]
    pub fn sample(&self, current: f32, rng: &mut Rng) -> f32 {
        let mut f = [0.0f32; MAX_RANGES];
        self.row(current, &mut f);
        let mut total = 0.0f32;
        self.segments(&f, |a, b, fa, fb| total += 0.5 * (fa + fb) * (b - a));
        let mut target = rng.next_f32() * total;
        let mut out = None;
        self.segments(&f, |a, b, fa, fb| {
            if out.is_some() {
                return;
            }
            let area = 0.5 * (fa + fb) * (b - a);
            if target > area {
                target -= area;
                return;
            }
            // Solve ∫_a^x f = target with f linear: ½·s·u² + fa·u = target.
            let s = (fb - fa) / (b - a);
            let u = if s.abs() < 1e-12 {
                if fa > 0.0 {
                    target / fa
                } else {
                    0.0
                }
            } else {
                (-fa + (fa * fa + 2.0 * s * target).max(0.0).sqrt()) / s
            };
            out = Some((a + u).clamp(a, b));
        });
        out.unwrap_or(self.edges[self.edges.len() - 1])
    }
}
