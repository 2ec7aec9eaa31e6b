//! Random vector fields on a sampled grid (paper 004 §3, figures 122–126).
//!
//! "It is impractical to generate a random vector for each pixel. Instead we
//! generate vectors for a sample grid and use interpolation": a field here
//! is a `cols × rows` grid of unit vectors `cell` world units apart,
//! bilinearly interpolated *as vectors* (so the result is continuous and the
//! ±π seam of angles causes no jump) and tiled periodically so an agent never
//! walks off it. The field's angle, divided by π, is the normalised command.
//!
//! The paper's two fixes are both here: a small random `jitter_deg` offset
//! against retracing a path in displacement mode, and switching between two
//! or three fields every `switch_every` steps against sinks. `bias: true`
//! turns the field into an influence instead of a command with the paper's
//! formula `u = r₁·field + (1 − r₁)·r₂`. The text defines "a random number"
//! as uniform on `[0, 1)`; `r₁` is that. For `r₂` our reading (the default,
//! [`BiasNoise::Signed`]) is a uniform *angle* on the same normalised range
//! `[-1, 1)` as the field: a bare `[0, 1)` number added to an angle turns
//! every agent to the left, which the text does not describe. The literal
//! `[0, 1)` stays selectable ([`BiasNoise::Unit`], `"bias_r2": "unit"`).

use glam::Vec2;
use serde::{Deserialize, Serialize};

use super::error::{in_range, in_range_u, WanderError};
use super::noise;
use crate::base::angle;
use crate::base::rng::Rng;
use crate::base::trig;

/// How grid vectors are drawn.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum FieldValues {
    /// Independent uniform angles per grid node (the paper's field).
    #[default]
    Uniform,
    /// Angles from 2D Perlin noise over the grid (spatially coherent
    /// "landscape" fields, paper §3 last paragraph).
    Perlin,
}

/// A vector-field source.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct FieldConfig {
    /// Grid columns (2–512).
    pub cols: u32,
    /// Grid rows (2–512).
    pub rows: u32,
    /// Distance between grid nodes, world units (> 0). Larger is smoother.
    pub cell: f32,
    /// How node vectors are drawn; default uniform.
    #[serde(default)]
    pub values: FieldValues,
    /// Number of independent fields cycled through (1–3), default 1.
    #[serde(default = "one")]
    pub count: u32,
    /// Steps between field switches; 0 (default) never switches.
    #[serde(default)]
    pub switch_every: u32,
    /// Uniform random offset added to the field angle, degrees in
    /// `[0, 180]`; default 0.
    #[serde(default)]
    pub jitter_deg: f32,
    /// Use the field only as a bias: `u = r₁·field + (1 − r₁)·r₂`.
    #[serde(default)]
    pub bias: bool,
    /// The range of `r₂` when `bias` is on: `signed` (default) or the
    /// text's literal `unit`. Left out of the JSON when it is the default,
    /// so configurations written before it existed read and write unchanged.
    #[serde(default, skip_serializing_if = "BiasNoise::is_default")]
    pub bias_r2: BiasNoise,
}

/// The range of `r₂` in the bias formula `u = r₁·field + (1 − r₁)·r₂`
/// (`u` and `field` normalised angles in `[-1, 1)`, module docs).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum BiasNoise {
    /// `r₂` uniform on `[-1, 1)`: a random angle of either sign (our reading).
    #[default]
    Signed,
    /// `r₂` uniform on `[0, 1)`, the text's "a random number" taken
    /// literally: the random part only ever turns left.
    Unit,
}

impl BiasNoise {
    fn is_default(&self) -> bool {
        *self == Self::default()
    }
}

fn one() -> u32 {
    1
}

impl FieldConfig {
    /// Checks grid size, spacing, count and jitter.
    pub fn validate(&self) -> Result<(), WanderError> {
        in_range_u("field.cols", self.cols, 2, 512)?;
        in_range_u("field.rows", self.rows, 2, 512)?;
        in_range("field.cell", self.cell, 1e-3, super::error::WORLD_LIMIT)?;
        in_range_u("field.count", self.count, 1, 3)?;
        in_range("field.jitter_deg", self.jitter_deg, 0.0, 180.0)
    }
}

/// A periodic grid of unit vectors with bilinear interpolation.
#[derive(Clone, Debug, PartialEq)]
pub struct VectorField {
    cols: u32,
    rows: u32,
    inv_cell: f32,
    nodes: Vec<Vec2>,
}

impl VectorField {
    /// A field of random node vectors drawn from `rng`.
    #[must_use]
    pub fn random(cols: u32, rows: u32, cell: f32, values: FieldValues, rng: &mut Rng) -> Self {
        let seed = rng.next_u32();
        let n = (cols * rows) as usize;
        let mut nodes = Vec::with_capacity(n);
        for j in 0..rows {
            for i in 0..cols {
                let a = match values {
                    FieldValues::Uniform => {
                        rng.range(-core::f32::consts::PI, core::f32::consts::PI)
                    }
                    // Off-lattice samples (Perlin is 0 on its lattice).
                    FieldValues::Perlin => {
                        core::f32::consts::PI
                            * noise::perlin2(seed, i as f32 * 0.23 + 0.5, j as f32 * 0.23 + 0.5)
                    }
                };
                let (s, c) = trig::sin_cos(a);
                nodes.push(Vec2::new(c, s));
            }
        }
        Self {
            cols,
            rows,
            inv_cell: 1.0 / cell,
            nodes,
        }
    }

    /// The interpolated (not normalised) vector at world point `p`.
    /// Continuous in `p`, including across the periodic seams.
    #[must_use]
    pub fn vector_at(&self, p: Vec2) -> Vec2 {
        let g = p * self.inv_cell;
        let (fx, fy) = (g.x.floor(), g.y.floor());
        let (tx, ty) = (g.x - fx, g.y - fy);
        let i0 = (fx as i64).rem_euclid(i64::from(self.cols)) as u32;
        let j0 = (fy as i64).rem_euclid(i64::from(self.rows)) as u32;
        let i1 = (i0 + 1) % self.cols;
        let j1 = (j0 + 1) % self.rows;
        let at = |i: u32, j: u32| self.nodes[(j * self.cols + i) as usize];
        let a = at(i0, j0).lerp(at(i1, j0), tx);
        let b = at(i0, j1).lerp(at(i1, j1), tx);
        a.lerp(b, ty)
    }

    /// The field angle at `p`, radians in `[-π, π]`.
    #[inline]
    #[must_use]
    pub fn angle_at(&self, p: Vec2) -> f32 {
        let v = self.vector_at(p);
        trig::atan2(v.y, v.x)
    }
}

/// A built field source: one to three fields and the switching clock.
#[derive(Clone, Debug, PartialEq)]
pub struct FieldSource {
    fields: Vec<VectorField>,
    switch_every: u32,
    jitter: f32,
    bias: bool,
    bias_r2: BiasNoise,
}

impl FieldSource {
    /// Validates `cfg` and draws its fields from `rng`.
    pub fn new(cfg: &FieldConfig, rng: &mut Rng) -> Result<Self, WanderError> {
        cfg.validate()?;
        let fields = (0..cfg.count)
            .map(|_| VectorField::random(cfg.cols, cfg.rows, cfg.cell, cfg.values, rng))
            .collect();
        Ok(Self {
            fields,
            switch_every: cfg.switch_every,
            jitter: cfg.jitter_deg.to_radians(),
            bias: cfg.bias,
            bias_r2: cfg.bias_r2,
        })
    }

    /// The field active at `step` (fields cycle every `switch_every`).
    #[inline]
    #[must_use]
    pub fn active(&self, step: u32) -> &VectorField {
        let k = step
            .checked_div(self.switch_every)
            .map_or(0, |n| n as usize % self.fields.len());
        &self.fields[k]
    }

    /// Normalised command `u ∈ [-1, 1]` at position `pos` and `step`.
    #[inline]
    pub fn sample(&self, step: u32, pos: Vec2, rng: &mut Rng) -> f32 {
        let mut a = self.active(step).angle_at(pos);
        if self.jitter > 0.0 {
            a = angle::wrap(a + rng.range(-self.jitter, self.jitter));
        }
        let u = a * core::f32::consts::FRAC_1_PI;
        if self.bias {
            let r1 = rng.next_f32();
            // One draw either way, so the rest of the run keeps its stream.
            let r2 = match self.bias_r2 {
                BiasNoise::Signed => rng.range(-1.0, 1.0),
                BiasNoise::Unit => rng.next_f32(),
            };
            r1 * u + (1.0 - r1) * r2
        } else {
            u
        }
    }
}
