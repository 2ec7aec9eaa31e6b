//! Transition tables over angle ranges (paper 004 §6, figures 164–166).
//!
//! The steering angle lives in one of `n` ranges (edges in degrees). Each
//! step, the row of the current range gives the probabilities of the next
//! range; the paper's recipe is implemented literally: rows are turned into
//! cumulative rows once, a uniform `r` is drawn, the left-most cumulative
//! cell bigger than `r` is the new range, and the new angle is uniform in
//! it. The two-table variant first draws whether the angle changes at all
//! with a per-range `change_probability` (figure 165: 0.1, 0.2, 0.4;
//! figure 166: 1, 1, 0.1); if not, the angle is kept.
//!
//! The value is the commanded angle itself (degrees → radians), not a
//! normalised command: the table's ranges are what a user reasons about.
//! The control clamps still apply. Rows must sum to 1 within 1e-3 (the
//! paper's own cumulative example has a typo, "0.15 + 0.8 + 0.15"; we
//! reject such rows rather than guess).

use serde::{Deserialize, Serialize};

use super::error::{finite, in_range, in_range_u, WanderError};
use crate::base::rng::Rng;

/// A transition-table source.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct MarkovConfig {
    /// `n + 1` strictly increasing range edges, degrees (finite, n ≥ 1).
    pub edges_deg: Vec<f32>,
    /// `n × n` row-stochastic table: `table[i][j]` = P(next range j |
    /// current range i).
    pub table: Vec<Vec<f32>>,
    /// Optional per-range probability that the angle changes at all (the
    /// two-table variant), each in `[0, 1]`.
    #[serde(default)]
    pub change_probability: Option<Vec<f32>>,
    /// Range the chain starts in (its midpoint is the first angle);
    /// default 0.
    #[serde(default)]
    pub initial_range: u32,
    /// Read the table as a smooth 2D response curve (§6's smoothing,
    /// [`crate::wander::response`]) instead of a step function; at most
    /// 16 ranges. Default false (the paper's recipe).
    #[serde(default)]
    pub response_curve: bool,
}

impl MarkovConfig {
    /// Checks edges, the table's shape, entries and row sums, the change
    /// probabilities and the initial range.
    pub fn validate(&self) -> Result<(), WanderError> {
        if self.edges_deg.len() < 2 {
            return Err(WanderError::ShapeMismatch {
                what: "markov.edges_deg (at least)",
                expected: 2,
                found: self.edges_deg.len(),
            });
        }
        for e in &self.edges_deg {
            finite("markov.edges_deg[]", *e)?;
        }
        if self.edges_deg.windows(2).any(|w| w[1] <= w[0]) {
            return Err(WanderError::NotIncreasing {
                what: "markov.edges_deg",
            });
        }
        let n = self.edges_deg.len() - 1;
        if self.table.len() != n {
            return Err(WanderError::ShapeMismatch {
                what: "markov.table",
                expected: n,
                found: self.table.len(),
            });
        }
        for (i, row) in self.table.iter().enumerate() {
            if row.len() != n {
                return Err(WanderError::ShapeMismatch {
                    what: "markov.table[row]",
                    expected: n,
                    found: row.len(),
                });
            }
            for p in row {
                in_range("markov.table[][]", *p, 0.0, 1.0)?;
            }
            let sum: f32 = row.iter().sum();
            if (sum - 1.0).abs() > 1e-3 {
                return Err(WanderError::RowSum { row: i, sum });
            }
        }
        if let Some(c) = &self.change_probability {
            if c.len() != n {
                return Err(WanderError::ShapeMismatch {
                    what: "markov.change_probability",
                    expected: n,
                    found: c.len(),
                });
            }
            for p in c {
                in_range("markov.change_probability[]", *p, 0.0, 1.0)?;
            }
        }
        if self.response_curve && n > super::response::MAX_RANGES {
            return Err(WanderError::ShapeMismatch {
                what: "markov.table with response_curve (at most)",
                expected: super::response::MAX_RANGES,
                found: n,
            });
        }
        in_range_u("markov.initial_range", self.initial_range, 0, n as u32 - 1)
    }
}

/// A built chain: radians edges, flat cumulative table, current state.
#[derive(Clone, Debug, PartialEq)]
pub struct Markov {
    edges: Vec<f32>,
    cumulative: Vec<f32>,
    change: Option<Vec<f32>>,
    range: usize,
    value: f32,
    curve: Option<super::response::ResponseCurve>,
}

impl Markov {
    /// Validates `cfg` and builds the cumulative table.
    pub fn new(cfg: &MarkovConfig) -> Result<Self, WanderError> {
        cfg.validate()?;
        let n = cfg.table.len();
        let mut cumulative = Vec::with_capacity(n * n);
        for row in &cfg.table {
            let mut acc = 0.0;
            for p in row {
                acc += p;
                cumulative.push(acc);
            }
            // "In practice we don't need the last column": it is +∞ so
            // rounding can never leave `r` unmatched.
            if let Some(last) = cumulative.last_mut() {
                *last = f32::INFINITY;
            }
        }
        let edges: Vec<f32> = cfg.edges_deg.iter().map(|e| e.to_radians()).collect();
        let curve = cfg
            .response_curve
            .then(|| super::response::ResponseCurve::new(&edges, &cfg.table));
        let range = cfg.initial_range as usize;
        let value = 0.5 * (edges[range] + edges[range + 1]);
        Ok(Self {
            edges,
            cumulative,
            change: cfg.change_probability.clone(),
            range,
            value,
            curve,
        })
    }

    /// Number of ranges.
    #[must_use]
    pub fn ranges(&self) -> usize {
        self.edges.len() - 1
    }

    /// The current range index.
    #[must_use]
    pub fn range(&self) -> usize {
        self.range
    }

    /// One transition; returns the new angle (radians).
    #[inline]
    pub fn sample(&mut self, rng: &mut Rng) -> f32 {
        if let Some(c) = &self.change {
            if rng.next_f32() >= c[self.range] {
                return self.value;
            }
        }
        if let Some(curve) = &self.curve {
            self.value = curve.sample(self.value, rng);
            self.range = self
                .edges
                .windows(2)
                .position(|w| self.value < w[1])
                .unwrap_or(self.edges.len() - 2);
            return self.value;
        }
        let n = self.ranges();
        let r = rng.next_f32();
        let row = &self.cumulative[self.range * n..(self.range + 1) * n];
        let j = row.iter().position(|&c| r < c).unwrap_or(n - 1);
        self.range = j;
        self.value = rng.range(self.edges[j], self.edges[j + 1]);
        self.value
    }
}
