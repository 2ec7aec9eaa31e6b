//! Distributions of the random numbers that drive a wander (paper 004 §2).
//!
//! Every distribution produces a *normalised* value `u ∈ [-1, 1]` that the
//! control stage scales by the clamp of the controlled quantity (the paper's
//! `2·max·(random() − 0.5)`), so one distribution config works unchanged for
//! displacement, velocity or acceleration (paper figures 161–163 use one
//! curve for all three).
//!
//! Discrete angle sets (paper §2 "Discrete Distributions", figures 153–158)
//! are not a separate distribution here: they are the control stage's
//! `quantize_deg` snapping applied after *any* distribution, so "uniform +
//! quantize 90°" is the discrete set {0°, 90°, 180°, 270°} and "Perlin +
//! quantize" is the paper's discrete Perlin. See [`super::control`].

use serde::{Deserialize, Serialize};

use super::error::{finite, in_range, in_range_u, positive, WanderError};
use super::noise;
use crate::base::rng::Rng;

/// Which distribution a random source draws from.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case", deny_unknown_fields)]
pub enum DistributionConfig {
    /// Uniform on `[-1, 1)`: the paper's plain "random number". (An empty
    /// struct variant so that `deny_unknown_fields` also applies to it.)
    Uniform {},
    /// Smooth noise: a fresh uniform value every `period` steps, linearly
    /// interpolated in between (paper §2). `period = 1` is white noise.
    SmoothNoise {
        /// Steps between white-noise knots (≥ 1).
        period: u32,
    },
    /// Perlin gradient noise read at `step / period` (paper §2, figure 121).
    Perlin {
        /// Steps per lattice cell of the first octave (> 0).
        period: f32,
        /// Number of octaves (1–8), default 1.
        #[serde(default = "one_u32")]
        octaves: u32,
        /// Weight ratio between successive octaves (0–1], default 0.5.
        #[serde(default = "half")]
        persistence: f32,
    },
    /// A hand-drawn density curve on `[-1, 1]`, sampled by inverse CDF
    /// (paper §2 "Arbitrary Distributions", figures 161–163).
    Curve {
        /// `[u, density]` points, `u` strictly increasing within `[-1, 1]`,
        /// densities ≥ 0 and not all zero; the density is piecewise linear
        /// between points and zero outside. Need not be normalised.
        points: Vec<[f32; 2]>,
    },
}

fn one_u32() -> u32 {
    1
}
fn half() -> f32 {
    0.5
}

impl DistributionConfig {
    /// Checks every parameter; the typed error names the bad one.
    pub fn validate(&self) -> Result<(), WanderError> {
        match self {
            Self::Uniform {} => Ok(()),
            Self::SmoothNoise { period } => in_range_u("smooth_noise.period", *period, 1, 1 << 20),
            Self::Perlin {
                period,
                octaves,
                persistence,
            } => {
                positive("perlin.period", *period)?;
                in_range_u("perlin.octaves", *octaves, 1, 8)?;
                in_range("perlin.persistence", *persistence, f32::MIN_POSITIVE, 1.0)
            }
            Self::Curve { points } => Curve::new(points).map(|_| ()),
        }
    }
}

/// An inverse-CDF sampler for a piecewise-linear density (paper §2,
/// "Generating Random Numbers with an Arbitrary Distribution").
///
/// The cumulative areas are precomputed once; a draw is a binary search
/// plus the closed-form inverse of a quadratic, so it is exact (no
/// rejection, no lookup-table quantisation) and allocation-free.
#[derive(Clone, Debug, PartialEq)]
pub struct Curve {
    xs: Vec<f32>,
    ds: Vec<f32>,
    /// `cum[k]` = area left of `xs[k]`.
    cum: Vec<f32>,
}

impl Curve {
    /// Builds the sampler; errors on an empty, non-increasing, out-of-range,
    /// negative, non-finite or all-zero curve.
    pub fn new(points: &[[f32; 2]]) -> Result<Self, WanderError> {
        if points.len() < 2 {
            return Err(WanderError::ShapeMismatch {
                what: "curve.points (at least)",
                expected: 2,
                found: points.len(),
            });
        }
        let mut cum = Vec::with_capacity(points.len());
        let mut area = 0.0f32;
        for (k, p) in points.iter().enumerate() {
            in_range("curve.points[].u", p[0], -1.0, 1.0)?;
            finite("curve.points[].density", p[1])?;
            if p[1] < 0.0 {
                return Err(WanderError::Range(crate::base::range::RangeError {
                    field: "curve.points[].density",
                    value: p[1],
                    min: 0.0,
                    max: f32::MAX,
                }));
            }
            if k > 0 {
                let q = points[k - 1];
                if p[0] <= q[0] {
                    return Err(WanderError::NotIncreasing {
                        what: "curve.points[].u",
                    });
                }
                area += 0.5 * (p[1] + q[1]) * (p[0] - q[0]);
            }
            cum.push(area);
        }
        if area <= 0.0 {
            return Err(WanderError::NotPositive {
                what: "curve area",
                value: area,
            });
        }
        Ok(Self {
            xs: points.iter().map(|p| p[0]).collect(),
            ds: points.iter().map(|p| p[1]).collect(),
            cum,
        })
    }

    /// The value whose CDF is `p ∈ [0, 1)`.
    #[must_use]
    pub fn inverse_cdf(&self, p: f32) -> f32 {
        let total = self.cum[self.cum.len() - 1];
        let a = p * total;
        // Segment k spans cum[k]..cum[k+1]; pick the last k with cum[k] <= a
        // among segments that have area.
        let k = self
            .cum
            .partition_point(|&c| c <= a)
            .clamp(1, self.cum.len() - 1)
            - 1;
        let (x0, x1) = (self.xs[k], self.xs[k + 1]);
        let (d0, d1) = (self.ds[k], self.ds[k + 1]);
        let w = x1 - x0;
        let slope = (d1 - d0) / w;
        let r = (a - self.cum[k]).max(0.0);
        // Solve d0·s + slope·s²/2 = r in the cancellation-free form.
        let disc = (d0 * d0 + 2.0 * slope * r).max(0.0);
        let denom = d0 + disc.sqrt();
        let s = if denom > 0.0 { 2.0 * r / denom } else { 0.0 };
        (x0 + s.min(w)).clamp(-1.0, 1.0)
    }

    /// One draw.
    #[inline]
    pub fn sample(&self, rng: &mut Rng) -> f32 {
        self.inverse_cdf(rng.next_f32())
    }
}

/// A built distribution, ready to draw per step.
#[derive(Clone, Debug, PartialEq)]
pub enum Sampler {
    /// See [`DistributionConfig::Uniform`].
    Uniform,
    /// See [`DistributionConfig::SmoothNoise`].
    Smooth {
        /// Noise seed (drawn from the wanderer's generator).
        seed: u32,
        /// Steps per knot.
        period: f32,
    },
    /// See [`DistributionConfig::Perlin`].
    Perlin {
        /// Noise seed.
        seed: u32,
        /// Steps per lattice cell.
        period: f32,
        /// Octaves.
        octaves: u32,
        /// Octave weight ratio.
        persistence: f32,
    },
    /// See [`DistributionConfig::Curve`].
    Curve(Curve),
}

impl Sampler {
    /// Validates `cfg` and builds it; noise seeds come from `rng`.
    pub fn new(cfg: &DistributionConfig, rng: &mut Rng) -> Result<Self, WanderError> {
        cfg.validate()?;
        Ok(match cfg {
            DistributionConfig::Uniform {} => Self::Uniform,
            DistributionConfig::SmoothNoise { period } => Self::Smooth {
                seed: rng.next_u32(),
                period: *period as f32,
            },
            DistributionConfig::Perlin {
                period,
                octaves,
                persistence,
            } => Self::Perlin {
                seed: rng.next_u32(),
                period: *period,
                octaves: *octaves,
                persistence: *persistence,
            },
            DistributionConfig::Curve { points } => Self::Curve(Curve::new(points)?),
        })
    }

    /// The value for simulation step `step`, in `[-1, 1]`. Noise
    /// distributions are indexed by the step (coherent in time); the others
    /// draw from `rng`.
    #[inline]
    pub fn sample(&self, step: u32, rng: &mut Rng) -> f32 {
        match self {
            Self::Uniform => rng.range(-1.0, 1.0),
            Self::Smooth { seed, period } => noise::smooth1(*seed, step as f32 / period),
            Self::Perlin {
                seed,
                period,
                octaves,
                persistence,
            } => noise::fbm1(*seed, step as f32 / period, *octaves, *persistence),
            Self::Curve(c) => c.sample(rng),
        }
    }
}
