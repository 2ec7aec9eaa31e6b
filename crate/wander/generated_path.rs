//! Generated paths followed by the agent (paper 004 §7).
//!
//! "It is sometimes easier to steer towards a generated path than to control
//! the steering directly": the path is generated once from the seed (so it
//! can be saved, replayed or sent over a network) and the agent follows it
//! at constant speed by turning towards a point `lookahead` world units
//! ahead of its closest point on the path, the turn clamped by the velocity
//! clamp. Two generators from the paper:
//!
//! - fractal subdivision: start from one segment and repeatedly insert
//!   either one random point near each midpoint, or two points near the
//!   thirds on opposite sides of the segment; offsets are perpendicular and
//!   proportional to the segment length (`roughness`);
//! - a circle with sines: `r(t) = k + Σᵢ rᵢ·sin(2ⁱ t)`, `i = 0, 1, 2...`
//!   (the paper's `r₁ sin t + r₂ sin 2t + r₃ sin 4t + …`), closed.
//!
//! An open (fractal) path is followed back and forth: at an end the agent
//! turns round, which is what a user watching a gallery expects rather than
//! circling the end point forever.

use glam::Vec2;
use serde::{Deserialize, Serialize};

use super::error::{finite, in_range, in_range_u, positive, WanderError, WORLD_LIMIT};
use super::time_fn::Shape;
use crate::base::rng::Rng;
use crate::base::trig;

/// Most points a generated path may have.
pub const MAX_POINTS: u64 = 200_000;

/// Where the fractal inserts points.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Subdivision {
    /// One random point near each midpoint (doubles the segments).
    Midpoint,
    /// Two points near 1/3 and 2/3, on opposite sides (triples them).
    Thirds,
}

/// A path generator.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case", deny_unknown_fields)]
pub enum PathConfig {
    /// Fractal subdivision of the segment `start → end`.
    Fractal {
        /// First point.
        start: [f32; 2],
        /// Last point.
        end: [f32; 2],
        /// Subdivision rounds (1–16; total points ≤ 200 000).
        depth: u32,
        /// Largest perpendicular offset as a fraction of the segment
        /// length, in `[0, 1]`.
        roughness: f32,
        /// Insertion rule.
        rule: Subdivision,
    },
    /// `r(t) = k + Σ rᵢ sin(2ⁱ t)` around `center`.
    Circle {
        /// Centre.
        center: [f32; 2],
        /// Base radius `k` (> Σ|rᵢ| so the radius stays positive).
        radius: f32,
        /// The `rᵢ`; with `random_coefficients` they are bounds and each
        /// `rᵢ` is drawn uniformly in `[-|rᵢ|, |rᵢ|]`.
        coefficients: Vec<f32>,
        /// Draw the coefficients from the seed; default false.
        #[serde(default)]
        random_coefficients: bool,
        /// Points around the circle (8–100 000), default 720.
        #[serde(default = "samples_default")]
        samples: u32,
        /// Wave added to the circle: sine (default), or the saw-tooth and
        /// square waves the paper also suggests (§7).
        #[serde(default)]
        shape: Shape,
    },
}

fn samples_default() -> u32 {
    720
}

impl PathConfig {
    /// Checks every parameter and the size of the result.
    pub fn validate(&self) -> Result<(), WanderError> {
        match self {
            Self::Fractal {
                start,
                end,
                depth,
                roughness,
                rule,
            } => {
                for v in start.iter().chain(end) {
                    in_range("path.start/end", *v, -WORLD_LIMIT, WORLD_LIMIT)?;
                }
                if start == end {
                    return Err(WanderError::NotPositive {
                        what: "path length",
                        value: 0.0,
                    });
                }
                in_range_u("path.depth", *depth, 1, 16)?;
                in_range("path.roughness", *roughness, 0.0, 1.0)?;
                let per = match rule {
                    Subdivision::Midpoint => 2u64,
                    Subdivision::Thirds => 3,
                };
                let points = per.saturating_pow(*depth).saturating_add(1);
                if points > MAX_POINTS {
                    return Err(WanderError::TooLarge {
                        what: "path points",
                        value: points,
                        max: MAX_POINTS,
                    });
                }
                Ok(())
            }
            Self::Circle {
                center,
                radius,
                coefficients,
                samples,
                ..
            } => {
                in_range("path.center", center[0], -WORLD_LIMIT, WORLD_LIMIT)?;
                in_range("path.center", center[1], -WORLD_LIMIT, WORLD_LIMIT)?;
                positive("path.radius", *radius)?;
                in_range("path.radius", *radius, 0.0, WORLD_LIMIT)?;
                let mut sum = 0.0;
                for c in coefficients {
                    finite("path.coefficients[]", *c)?;
                    sum += c.abs();
                }
                if sum >= *radius {
                    return Err(WanderError::Range(crate::base::range::RangeError {
                        field: "path.coefficients (sum of |rᵢ|)",
                        value: sum,
                        min: 0.0,
                        max: *radius,
                    }));
                }
                in_range_u("path.samples", *samples, 8, 100_000)
            }
        }
    }

    /// Whether the generated path is closed.
    #[must_use]
    pub fn closed(&self) -> bool {
        matches!(self, Self::Circle { .. })
    }

    /// Generates the points (validated; randomness from `rng`).
    pub fn generate(&self, rng: &mut Rng) -> Result<Vec<Vec2>, WanderError> {
        self.validate()?;
        Ok(match self {
            Self::Fractal {
                start,
                end,
                depth,
                roughness,
                rule,
            } => {
                let mut pts = vec![Vec2::from(*start), Vec2::from(*end)];
                for _ in 0..*depth {
                    pts = subdivide(&pts, *rule, *roughness, rng);
                }
                pts
            }
            Self::Circle {
                center,
                radius,
                coefficients,
                random_coefficients,
                samples,
                shape,
            } => {
                let r: Vec<f32> = coefficients
                    .iter()
                    .map(|c| {
                        if *random_coefficients {
                            rng.range(-c.abs(), c.abs())
                        } else {
                            *c
                        }
                    })
                    .collect();
                let c = Vec2::from(*center);
                (0..*samples)
                    .map(|j| {
                        let t = core::f32::consts::TAU * j as f32 / *samples as f32;
                        let mut rad = *radius;
                        let mut f = 1.0;
                        for ri in &r {
                            rad += ri * shape.eval(f * t);
                            f *= 2.0;
                        }
                        let (s, co) = trig::sin_cos(t);
                        c + rad * Vec2::new(co, s)
                    })
                    .collect()
            }
        })
    }
}

/// One round of fractal subdivision.
fn subdivide(pts: &[Vec2], rule: Subdivision, roughness: f32, rng: &mut Rng) -> Vec<Vec2> {
    let mut out = Vec::with_capacity(pts.len() * 3);
    for w in pts.windows(2) {
        let (a, b) = (w[0], w[1]);
        let d = b - a;
        let n = d.perp() * roughness;
        out.push(a);
        match rule {
            Subdivision::Midpoint => out.push(a + 0.5 * d + rng.range(-1.0, 1.0) * n),
            Subdivision::Thirds => {
                let side = if rng.next_u32() & 1 == 0 { 1.0 } else { -1.0 };
                out.push(a + d / 3.0 + side * rng.next_f32() * n);
                out.push(a + 2.0 * d / 3.0 - side * rng.next_f32() * n);
            }
        }
    }
    out.push(pts[pts.len() - 1]);
    out
}

/// Checks a look-ahead distance: positive and at most the world limit.
pub fn validate_lookahead(lookahead: f32) -> Result<(), WanderError> {
    positive("path.lookahead", lookahead)?;
    in_range("path.lookahead", lookahead, 0.0, WORLD_LIMIT)
}

/// Follows a polyline with a look-ahead target.
#[derive(Clone, Debug, PartialEq)]
pub struct PathFollower {
    points: Vec<Vec2>,
    /// Flat `[x0, y0, x1, y1, …]` copy for drawing.
    flat: Vec<f32>,
    /// Arc length at each point (for a closed path, one extra entry: the
    /// closing segment back to the first point).
    arc: Vec<f32>,
    closed: bool,
    lookahead: f32,
    segment: usize,
    dir: f32,
}

impl PathFollower {
    /// Generates the path and prepares the follower.
    pub fn new(cfg: &PathConfig, lookahead: f32, rng: &mut Rng) -> Result<Self, WanderError> {
        validate_lookahead(lookahead)?;
        let points = cfg.generate(rng)?;
        let closed = cfg.closed();
        let segs = if closed {
            points.len()
        } else {
            points.len() - 1
        };
        let mut arc = Vec::with_capacity(segs + 1);
        arc.push(0.0);
        for k in 0..segs {
            let (a, b) = (points[k], points[(k + 1) % points.len()]);
            arc.push(arc[k] + a.distance(b));
        }
        let flat = points.iter().flat_map(|p| [p.x, p.y]).collect();
        Ok(Self {
            points,
            flat,
            arc,
            closed,
            lookahead,
            segment: 0,
            dir: 1.0,
        })
    }

    /// The path's points, flat `[x0, y0, x1, y1, …]`.
    #[must_use]
    pub fn flat(&self) -> &[f32] {
        &self.flat
    }

    /// First point and the heading of the first segment (where the agent
    /// starts).
    #[must_use]
    pub fn start_pose(&self) -> (Vec2, f32) {
        let d = self.points[1] - self.points[0];
        (self.points[0], trig::atan2(d.y, d.x))
    }

    fn segments(&self) -> usize {
        self.arc.len() - 1
    }

    fn seg_end(&self, k: usize) -> (Vec2, Vec2) {
        (self.points[k], self.points[(k + 1) % self.points.len()])
    }

    /// The point at arc length `s` (wrapped on a closed path, clamped on
    /// an open one), searching from the current segment.
    fn point_at(&self, s: f32) -> Vec2 {
        let total = self.arc[self.segments()];
        let s = if self.closed {
            s.rem_euclid(total)
        } else {
            s.clamp(0.0, total)
        };
        let k = self
            .arc
            .partition_point(|&a| a <= s)
            .clamp(1, self.segments())
            - 1;
        let (a, b) = self.seg_end(k);
        let len = self.arc[k + 1] - self.arc[k];
        if len <= 0.0 {
            return a;
        }
        a.lerp(b, (s - self.arc[k]) / len)
    }

    /// The turn (radians) that points the agent at the look-ahead target.
    pub fn sample(&mut self, pos: Vec2, heading: f32) -> f32 {
        // Closest point among a window of segments around the current one,
        // mostly ahead in the direction of travel: O(1) per step, and it
        // cannot jump to a far part of the path that happens to pass nearby.
        const BEHIND: i64 = 3;
        const AHEAD: i64 = 8;
        let n = self.segments();
        let (mut best_d, mut best_k, mut best_t) = (f32::INFINITY, self.segment, 0.0);
        for off in -BEHIND..=AHEAD {
            let off = if self.dir > 0.0 { off } else { -off };
            let k = self.segment as i64 + off;
            let k = if self.closed {
                k.rem_euclid(n as i64) as usize
            } else if k < 0 || k >= n as i64 {
                continue;
            } else {
                k as usize
            };
            let (a, b) = self.seg_end(k);
            let ab = b - a;
            let l2 = ab.length_squared();
            let t = if l2 > 0.0 {
                ((pos - a).dot(ab) / l2).clamp(0.0, 1.0)
            } else {
                0.0
            };
            let d = pos.distance_squared(a + t * ab);
            if d < best_d {
                (best_d, best_k, best_t) = (d, k, t);
            }
        }
        self.segment = best_k;
        let s = self.arc[best_k] + best_t * (self.arc[best_k + 1] - self.arc[best_k]);
        if !self.closed {
            let total = self.arc[n];
            if self.dir > 0.0 && s + self.lookahead >= total {
                self.dir = -1.0;
            } else if self.dir < 0.0 && s - self.lookahead <= 0.0 {
                self.dir = 1.0;
            }
        }
        let target = self.point_at(s + self.dir * self.lookahead);
        let d = target - pos;
        crate::base::angle::diff(trig::atan2(d.y, d.x), heading)
    }
}
