//! Time functions: sums of sines, blended or modulated by noise
//! (paper 004 §4, figures 128–139).
//!
//! Instead of random numbers, the command is a function of time
//! `t = step · dt`:
//!
//! `u(t) = E(t) · Σᵢ aᵢ · wᵢ(t) · sin(fᵢ·t + φᵢ)`
//!
//! where the optional envelope `E` is a noise sequence mapped to `[0, 1]`
//! (figures 134–136: `white/smooth/perlin_noise(t) · [0.5 sin t + 0.5 sin 50t]`)
//! and each term's weight `wᵢ` is 1, the blend noise `A(t)`, its complement
//! `1 − A(t)` (the paper's `A(t)·sin(10t) + (1 − A(t))·sin(t)`), or the
//! blend read backwards from a horizon, `A(T − t)` (figures 137–139:
//! `0.9·perlin(t)·sin t + 0.1·perlin(T − t)·sin 50t`). `u` is then scaled
//! by the controlled quantity's clamp like every other command, so sums
//! whose amplitudes add to more than 1 saturate at the clamp.

use serde::{Deserialize, Serialize};

use super::error::{finite, in_range_u, positive, WanderError};
use super::noise;
use crate::base::rng::Rng;
use crate::base::trig;

/// A noise sequence over steps, used as an envelope or a blend.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case", deny_unknown_fields)]
pub enum NoiseConfig {
    /// A fresh uniform value every step (empty struct variant so unknown
    /// fields are rejected).
    White {},
    /// Linearly interpolated white noise, a knot every `period` steps.
    Smooth {
        /// Steps per knot (≥ 1).
        period: u32,
    },
    /// Perlin noise with `period` steps per lattice cell.
    Perlin {
        /// Steps per cell (> 0).
        period: f32,
    },
}

impl NoiseConfig {
    /// Checks the period.
    pub fn validate(&self) -> Result<(), WanderError> {
        match self {
            Self::White {} => Ok(()),
            Self::Smooth { period } => in_range_u("noise.period", *period, 1, 1 << 20),
            Self::Perlin { period } => positive("noise.period", *period),
        }
    }
}

/// A built noise sequence (random access in the step, so it can be read
/// backwards for `A(T − t)`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct NoiseSeq {
    kind: u8,
    seed: u32,
    period: f32,
}

impl NoiseSeq {
    /// Builds `cfg` with a seed drawn from `rng`.
    pub fn new(cfg: &NoiseConfig, rng: &mut Rng) -> Result<Self, WanderError> {
        cfg.validate()?;
        let seed = rng.next_u32();
        Ok(match cfg {
            NoiseConfig::White {} => Self {
                kind: 0,
                seed,
                period: 1.0,
            },
            NoiseConfig::Smooth { period } => Self {
                kind: 1,
                seed,
                period: *period as f32,
            },
            NoiseConfig::Perlin { period } => Self {
                kind: 2,
                seed,
                period: *period,
            },
        })
    }

    /// The value at (possibly negative) step `s`, mapped to `[0, 1]`.
    #[inline]
    #[must_use]
    pub fn at(&self, s: i64) -> f32 {
        let v = match self.kind {
            0 => noise::white(self.seed, s as i32),
            1 => noise::smooth1(self.seed, s as f32 / self.period),
            _ => noise::perlin1(self.seed, s as f32 / self.period),
        };
        0.5 * (v + 1.0)
    }
}

/// How a sine term is weighted.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Weight {
    /// Weight 1.
    #[default]
    One,
    /// The blend noise `A(t)`.
    Blend,
    /// `1 − A(t)`.
    Complement,
    /// `A(T − t)`, `T = horizon`.
    BlendReversed,
}

/// The periodic function of a term. The paper prefers the sine (smooth,
/// bounded, constant frequency) and notes saw-tooth and square waves share
/// every property but smoothness (§4); all three have period 2π, range
/// `[-1, 1]`, and cross zero upwards at 0 like the sine.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Shape {
    /// `sin x`.
    #[default]
    Sine,
    /// Rising saw tooth: 0 at 0, 1 just before π, −1 at π.
    Saw,
    /// +1 on `(0, π)`, −1 on `(π, 2π)`.
    Square,
}

impl Shape {
    /// The wave at `x` (radians).
    #[inline]
    #[must_use]
    pub fn eval(self, x: f32) -> f32 {
        let turns = x * core::f32::consts::FRAC_1_PI * 0.5;
        match self {
            Self::Sine => trig::sin(x),
            Self::Saw => 2.0 * (turns + 0.5 - (turns + 0.5).floor()) - 1.0,
            Self::Square => {
                if turns - turns.floor() < 0.5 {
                    1.0
                } else {
                    -1.0
                }
            }
        }
    }
}

/// One `a · w(t) · wave(f·t + φ)` term.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SineTerm {
    /// Amplitude `a` (finite).
    pub amplitude: f32,
    /// Angular frequency `f`, radians per unit of `t` (finite).
    pub frequency: f32,
    /// Phase `φ`, radians; default 0.
    #[serde(default)]
    pub phase: f32,
    /// Weight; default `one`.
    #[serde(default)]
    pub weight: Weight,
    /// Wave shape; default `sine`.
    #[serde(default)]
    pub shape: Shape,
}

/// A time-function source.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct TimeFnConfig {
    /// The sine terms (at least one).
    pub terms: Vec<SineTerm>,
    /// Increment of `t` per step (> 0), default 0.01.
    #[serde(default = "dt_default")]
    pub dt: f32,
    /// Optional envelope multiplying the whole sum.
    #[serde(default)]
    pub envelope: Option<NoiseConfig>,
    /// Blend noise `A`, required when a term is weighted by it.
    #[serde(default)]
    pub blend: Option<NoiseConfig>,
    /// Horizon `T` in steps for `blend_reversed`; default 100 000.
    #[serde(default = "horizon_default")]
    pub horizon: u32,
}

fn dt_default() -> f32 {
    0.01
}
fn horizon_default() -> u32 {
    100_000
}

impl TimeFnConfig {
    /// Checks the terms, `dt`, the noises, and that a blend exists when a
    /// term needs one.
    pub fn validate(&self) -> Result<(), WanderError> {
        if self.terms.is_empty() {
            return Err(WanderError::Empty {
                what: "time_function.terms",
            });
        }
        positive("time_function.dt", self.dt)?;
        let mut needs_blend = false;
        for t in &self.terms {
            finite("time_function.terms[].amplitude", t.amplitude)?;
            finite("time_function.terms[].frequency", t.frequency)?;
            finite("time_function.terms[].phase", t.phase)?;
            needs_blend |= t.weight != Weight::One;
        }
        if let Some(e) = &self.envelope {
            e.validate()?;
        }
        match &self.blend {
            Some(b) => b.validate(),
            None if needs_blend => Err(WanderError::Empty {
                what: "time_function.blend",
            }),
            None => Ok(()),
        }
    }
}

/// A built time function.
#[derive(Clone, Debug, PartialEq)]
pub struct TimeFn {
    terms: Vec<SineTerm>,
    dt: f32,
    envelope: Option<NoiseSeq>,
    blend: Option<NoiseSeq>,
    horizon: i64,
}

impl TimeFn {
    /// Validates `cfg` and seeds its noises from `rng`.
    pub fn new(cfg: &TimeFnConfig, rng: &mut Rng) -> Result<Self, WanderError> {
        cfg.validate()?;
        let envelope = cfg
            .envelope
            .as_ref()
            .map(|e| NoiseSeq::new(e, rng))
            .transpose()?;
        let blend = cfg
            .blend
            .as_ref()
            .map(|b| NoiseSeq::new(b, rng))
            .transpose()?;
        Ok(Self {
            terms: cfg.terms.clone(),
            dt: cfg.dt,
            envelope,
            blend,
            horizon: i64::from(cfg.horizon),
        })
    }

    /// `u(step · dt)`.
    #[must_use]
    pub fn value(&self, step: u32) -> f32 {
        let t = step as f32 * self.dt;
        let s = i64::from(step);
        let a = self.blend.map_or(1.0, |b| b.at(s));
        let mut sum = 0.0;
        for term in &self.terms {
            let w = match term.weight {
                Weight::One => 1.0,
                Weight::Blend => a,
                Weight::Complement => 1.0 - a,
                Weight::BlendReversed => self.blend.map_or(1.0, |b| b.at(self.horizon - s)),
            };
            sum += term.amplitude * w * term.shape.eval(term.frequency * t + term.phase);
        }
        self.envelope.map_or(sum, |e| e.at(s) * sum)
    }
}
