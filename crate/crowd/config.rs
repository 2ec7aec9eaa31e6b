//! Crowd configuration and the paper's test presets (paper 003, "Testing").
//!
//! Units: lengths in world units (the paper's pixels), time in simulation
//! steps (the paper's Processing frames; a front end running at 60 Hz does
//! one step per frame). Speeds are world units per step, forces/steering
//! world units per step per step.
//!
//! The paper gives no numbers for speeds, radii or the pathway's size, so
//! the presets use Reynolds/Shiffman-style values: max speed 3, prediction 25 and look-ahead 25 (Shiffman's path-following
//! example), boid radius 8, and a 640 × 400 rectangular pathway of radius
//! 24 — sized so 300 boids fill the band about as densely as hexagonal
//! packing at the separation distance allows (Test IV's "no free space").
//!
//! Reynolds' force limit: the paper's `craig_reynolds_seek` pseudocode has
//! none (steer = desired − velocity). The presets set `max_force` to
//! 2 × `max_speed`, which |desired − velocity| can never exceed, so the
//! limit never binds and the presets run the paper's seek. A binding limit
//! (Shiffman's ~0.1 × max speed, e.g. 0.3) makes Reynolds turn slowly and
//! lose speed in corners; then it no longer matches Parker 100 %
//! (measured with `crowd-metrics --set max_force=0.3`).
//!
//! Separation weight: the paper's literal sum (weight 1) flings boids at
//! max speed away from any neighbour whatever the seek, and pushes the 10 %
//! and 1 % seeks off Test IV's path; the presets use 0.05, chosen on the
//! preset's seed, under which Reynolds, 100 % and 10 % keep to the path as
//! in illustrations 13–15 (the 1 % seek still leaves it more often than the
//! text's illustration 16 suggests). `tests/fidelity_crowd.rs` sweeps the
//! weight; `crowd-metrics --set separation_weight=1` shows the literal rule.

use glam::Vec2;
use serde::{Deserialize, Serialize};

use crate::crowd::boid_seek::Seek;
use crate::crowd::error::{check_range, CrowdError};
use crate::crowd::path::Path;

/// Most boids a crowd accepts (keeps buffers within a browser's memory).
pub const MAX_BOIDS: usize = 1_000_000;

/// Most steps in a batch run's warm-up or measurement window (an unbounded
/// `measure_steps`, e.g. 4294967295, would run for hours with no output);
/// the paper presets use 1,500 + 6,000.
pub const MAX_RUN_STEPS: u32 = 1_000_000;

/// Most boid-steps in a batch run, `boids × (warmup_steps +
/// measure_steps)`: minutes of a native run, not hours.
pub const MAX_BOID_STEPS: u64 = 1_000_000_000;

/// Most points in a path.
pub const MAX_PATH_POINTS: usize = 100_000;

/// The path part of a [`CrowdConfig`].
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PathConfig {
    /// Polyline points `[x, y]`, world units, in travel order.
    pub points: Vec<[f32; 2]>,
    /// Path radius (half-width), world units, > 0.
    pub radius: f32,
    /// Whether the last point connects back to the first (a lap circuit).
    pub closed: bool,
}

impl PathConfig {
    /// Builds the validated [`Path`].
    ///
    /// # Errors
    /// See [`Path::new`].
    pub fn build(&self) -> Result<Path, CrowdError> {
        Path::new(
            self.points.iter().map(|p| Vec2::from_array(*p)).collect(),
            self.radius,
            self.closed,
        )
    }
}

/// Everything needed to start a crowd run; loadable from JSON
/// (`scenarios/crowd/*.json`).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CrowdConfig {
    /// Free-text label shown by front ends and tables.
    #[serde(default)]
    pub name: String,
    /// Seed of every random choice (spawns, traced boid).
    pub seed: u64,
    /// Number of boids, `0..=MAX_BOIDS`.
    pub boids: usize,
    /// Seek strategy (`{"kind": "reynolds"}` or
    /// `{"kind": "parker", "fraction": 0.1}`).
    pub seek: Seek,
    /// Whether separation is applied (off in Tests I–II, on in III–IV).
    pub separation: bool,
    /// Multiplier on the paper's separation sum, `[0, 10]`; 1 is the
    /// paper's literal rule.
    pub separation_weight: f32,
    /// Boid radius, world units, > 0; separation acts within two radii.
    pub boid_radius: f32,
    /// Speed limit, world units per step, > 0.
    pub max_speed: f32,
    /// Reynolds steering limit, world units per step², > 0 (Parker ignores it).
    pub max_force: f32,
    /// How far ahead the future position is predicted, world units, ≥ 0.
    pub predict_distance: f32,
    /// Target distance along the path beyond the normal point, world units, ≥ 0.
    pub lookahead: f32,
    /// Lateral spawn spread as a share of the path radius, `[0, 1]`.
    pub spawn_spread: f32,
    /// The pathway.
    pub path: PathConfig,
    /// Steps run before metrics start (settling), for batch runs.
    pub warmup_steps: u32,
    /// Steps over which metrics are collected, for batch runs.
    pub measure_steps: u32,
}

/// The paper's four test cases.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub enum PaperTest {
    /// 1 boid, no separation.
    I,
    /// 10 boids, no separation.
    II,
    /// 100 boids, separation.
    III,
    /// 300 boids, separation.
    IV,
}

impl PaperTest {
    /// All four, in order.
    pub const ALL: [PaperTest; 4] = [PaperTest::I, PaperTest::II, PaperTest::III, PaperTest::IV];

    /// Boid count of the test.
    #[must_use]
    pub fn boids(self) -> usize {
        match self {
            PaperTest::I => 1,
            PaperTest::II => 10,
            PaperTest::III => 100,
            PaperTest::IV => 300,
        }
    }

    /// Whether the test uses separation.
    #[must_use]
    pub fn separation(self) -> bool {
        matches!(self, PaperTest::III | PaperTest::IV)
    }

    /// 1-based number (Test I = 1).
    #[must_use]
    pub fn number(self) -> u32 {
        match self {
            PaperTest::I => 1,
            PaperTest::II => 2,
            PaperTest::III => 3,
            PaperTest::IV => 4,
        }
    }
}

/// File-name tag of a seek variant: `reynolds`, `parker100`, `parker10`,
/// `parker1`, `parker0.1`.
#[must_use]
pub fn seek_tag(seek: &Seek) -> String {
    match *seek {
        Seek::Reynolds => "reynolds".to_owned(),
        Seek::Parker { fraction } => format!("parker{}", fraction * 100.0),
    }
}

impl CrowdConfig {
    /// The preset for one of the paper's tests with one seek variant, on
    /// the closed rectangular pathway (see module docs for the values).
    #[must_use]
    pub fn paper(test: PaperTest, seek: Seek) -> Self {
        let (w, h) = (640.0f32, 400.0f32);
        Self {
            name: format!(
                "Test {} ({} boids) — {}",
                test.number(),
                test.boids(),
                seek.label()
            ),
            seed: u64::from(test.number()),
            boids: test.boids(),
            seek,
            separation: test.separation(),
            separation_weight: 0.05,
            boid_radius: 8.0,
            max_speed: 3.0,
            max_force: 6.0,
            predict_distance: 25.0,
            lookahead: 25.0,
            spawn_spread: 0.8,
            path: PathConfig {
                points: vec![
                    [-w / 2.0, -h / 2.0],
                    [w / 2.0, -h / 2.0],
                    [w / 2.0, h / 2.0],
                    [-w / 2.0, h / 2.0],
                ],
                radius: 24.0,
                closed: true,
            },
            warmup_steps: 1500,
            measure_steps: 6000,
        }
    }

    /// All 20 paper presets (Tests I–IV × [`Seek::PAPER_VARIANTS`]), in the
    /// order of `scenarios/crowd/` and the metrics table, e.g. for a menu.
    #[must_use]
    pub fn paper_presets() -> Vec<Self> {
        PaperTest::ALL
            .iter()
            .flat_map(|&t| Seek::PAPER_VARIANTS.iter().map(move |&s| Self::paper(t, s)))
            .collect()
    }

    /// Parses and validates JSON.
    ///
    /// # Errors
    /// [`CrowdError::Json`] for malformed JSON or unknown fields, else see
    /// [`CrowdConfig::validate`].
    pub fn from_json(text: &str) -> Result<Self, CrowdError> {
        let c: Self = crate::base::field_error::from_str(text)
            .map_err(|e| CrowdError::Json(e.to_string()))?;
        c.validate()?;
        Ok(c)
    }

    /// Pretty JSON (the format of `scenarios/crowd/`).
    #[must_use]
    pub fn to_json(&self) -> String {
        serde_json::to_string_pretty(self).unwrap_or_default()
    }

    /// Checks every field (ranges in the field docs) and the path.
    ///
    /// # Errors
    /// The first offending field.
    pub fn validate(&self) -> Result<(), CrowdError> {
        check_range("boids", self.boids as f32, 0.0, MAX_BOIDS as f32)?;
        self.seek.validate()?;
        check_range("separation_weight", self.separation_weight, 0.0, 10.0)?;
        check_range("boid_radius", self.boid_radius, 1e-3, 1e5)?;
        check_range("max_speed", self.max_speed, 1e-6, 1e5)?;
        check_range("max_force", self.max_force, 1e-6, 1e5)?;
        check_range("predict_distance", self.predict_distance, 0.0, 1e6)?;
        check_range("lookahead", self.lookahead, 0.0, 1e6)?;
        check_range("spawn_spread", self.spawn_spread, 0.0, 1.0)?;
        let max_steps = MAX_RUN_STEPS as f32;
        check_range("warmup_steps", self.warmup_steps as f32, 0.0, max_steps)?;
        check_range("measure_steps", self.measure_steps as f32, 0.0, max_steps)?;
        check_range(
            "path.points (count)",
            self.path.points.len() as f32,
            0.0,
            MAX_PATH_POINTS as f32,
        )?;
        self.path.build()?;
        Ok(())
    }

    /// Checks that a batch run ([`crate::crowd::world::Crowd::run_measured`], the
    /// `crowd-metrics` table) stays under [`MAX_BOID_STEPS`]; an
    /// interactive crowd (the page) steps as long as it is shown.
    ///
    /// # Errors
    /// `boids × (warmup_steps + measure_steps)` out of range.
    pub fn check_batch(&self) -> Result<(), CrowdError> {
        let work =
            self.boids as f64 * (f64::from(self.warmup_steps) + f64::from(self.measure_steps));
        check_range(
            "boids × (warmup_steps + measure_steps)",
            work as f32,
            0.0,
            MAX_BOID_STEPS as f32,
        )
    }
}
