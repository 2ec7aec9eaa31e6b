//! What the envelope study measured, summarised: per-cell summaries, the
//! runs of every variant, the report and its parallel run.

use serde::Serialize;

use super::{EnvelopeStudy, GoalKind, RunRecord};
use crate::base::metrics::percentile;
#[cfg(not(target_arch = "wasm32"))]
use {
    super::{run, EnvScenario, Variant},
    crate::base::vehicle::VehicleParams,
    crate::funnelling::table::lookup::EtaTable,
};

/// Summary of a set of runs (a group, a cell).
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize)]
#[serde(rename_all = "camelCase")]
pub struct CellSummary {
    /// Runs.
    pub n: usize,
    /// Share entering the first disk.
    pub reach: f32,
    /// Runs that started inside the first disk.
    pub n_inside: usize,
    /// Share oriented on entry, of the runs that started outside.
    pub oriented: f32,
    /// Entry error median and p90, degrees (runs that entered).
    pub entry_err_deg: (f32, f32),
    /// Share of End_of_Steering declarations with both tolerances met.
    pub eos_ok: f32,
    /// Halting runs.
    pub n_halting: usize,
    /// Share of halting runs at rest inside both tolerances.
    pub rest_ok: f32,
    /// Share finishing every goal.
    pub finished: f32,
    /// Path length / Dubins, median and p90 (finished runs).
    pub length_ratio: (f32, f32),
    /// Steps with non-finite values, all runs.
    pub nan: u32,
    /// Steps with limit violations, all runs.
    pub violations: u32,
    /// Runs that never entered and were still moving at the limit.
    pub orbits: usize,
}

/// Summarises `runs`.
#[must_use]
pub fn summarise<'a>(runs: impl IntoIterator<Item = &'a RunRecord>) -> CellSummary {
    let runs: Vec<&RunRecord> = runs.into_iter().collect();
    let n = runs.len();
    let share = |k: usize, of: usize| {
        if of == 0 {
            f32::NAN
        } else {
            k as f32 / of as f32
        }
    };
    let outside: Vec<&&RunRecord> = runs.iter().filter(|r| !r.starts_inside).collect();
    let mut entry: Vec<f32> = outside
        .iter()
        .filter(|r| r.reached)
        .map(|r| r.entry_err_deg)
        .collect();
    let mut ratio: Vec<f32> = runs
        .iter()
        .filter(|r| r.finished && r.dubins > 1e-3)
        .map(|r| r.length / r.dubins)
        .collect();
    let halting: Vec<&&RunRecord> = runs.iter().filter(|r| r.halting).collect();
    let eos: u32 = runs.iter().map(|r| r.eos).sum();
    let eos_ok: u32 = runs.iter().map(|r| r.eos_ok).sum();
    CellSummary {
        n,
        reach: share(runs.iter().filter(|r| r.reached).count(), n),
        n_inside: n - outside.len(),
        oriented: share(
            outside.iter().filter(|r| r.oriented_on_entry).count(),
            outside.len(),
        ),
        entry_err_deg: (percentile(&mut entry, 0.5), percentile(&mut entry, 0.9)),
        eos_ok: share(eos_ok as usize, eos as usize),
        n_halting: halting.len(),
        rest_ok: share(halting.iter().filter(|r| r.rest_ok).count(), halting.len()),
        finished: share(runs.iter().filter(|r| r.finished).count(), n),
        length_ratio: (percentile(&mut ratio, 0.5), percentile(&mut ratio, 0.9)),
        nan: runs.iter().map(|r| r.nan).sum(),
        violations: runs.iter().map(|r| r.violations).sum(),
        orbits: runs.iter().filter(|r| r.orbit).count(),
    }
}

/// The runs of one variant on one group.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[serde(rename_all = "camelCase")]
pub struct GroupRuns {
    /// Family.
    pub kind: GoalKind,
    /// One record per scenario, in index order.
    pub runs: Vec<RunRecord>,
}

/// Everything one variant measured.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[serde(rename_all = "camelCase")]
pub struct VariantReport {
    /// Variant name.
    pub name: &'static str,
    /// Settings, as text.
    pub settings: String,
    /// Per group.
    pub groups: Vec<GroupRuns>,
}

impl VariantReport {
    /// Runs of `kind`'s group.
    #[must_use]
    pub fn runs(&self, kind: GoalKind) -> &[RunRecord] {
        self.groups
            .iter()
            .find(|g| g.kind == kind)
            .map_or(&[], |g| &g.runs)
    }
}

/// Missed runs kept per variant in the JSON (regenerate any of them with
/// [`EnvelopeStudy::scenario`] from the seed, group and index).
pub const MISSES_KEPT: usize = 5000;

/// The whole study's result.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[serde(rename_all = "camelCase")]
pub struct EnvelopeReport {
    /// Seed of the sample.
    pub seed: u64,
    /// Time limit per goal, s.
    pub max_time: f32,
    /// Per variant.
    pub variants: Vec<VariantReport>,
}

impl EnvelopeStudy {
    /// Runs every group for `variants` on rayon's pool (results do not
    /// depend on its size). Scenarios are
    /// sampled once and shared by the variants.
    #[cfg(not(target_arch = "wasm32"))]
    #[must_use]
    pub fn run_all(
        &self,
        table: &EtaTable,
        p: &VehicleParams,
        variants: &[Variant],
    ) -> EnvelopeReport {
        let scenarios: Vec<Vec<EnvScenario>> = GoalKind::ALL
            .iter()
            .map(|&k| (0..self.count(k)).map(|i| self.scenario(p, k, i)).collect())
            .collect();
        let jobs: Vec<(usize, &EnvScenario)> = (0..variants.len())
            .flat_map(|v| scenarios.iter().flatten().map(move |s| (v, s)))
            .collect();
        let records = crate::base::parallel::map_indices(jobs.len(), |j| {
            let (v, sc) = jobs[j];
            let mut r = run(
                table,
                p,
                &variants[v].controller,
                sc,
                self.max_time * self.scale.time(),
            );
            // Pedestrian-equivalent units, so the tables' cells match.
            r.d0 /= self.scale.length;
            // The sampled value's cell (a tolerance raised to the core's
            // minimum keeps its cell).
            let t = r.d_tol / self.scale.length;
            r.d_tol = super::D_TOLS
                .into_iter()
                .min_by(|a, b| (a / t).ln().abs().total_cmp(&(b / t).ln().abs()))
                .unwrap_or(t);
            r.speed /= self.scale.speed;
            r
        });
        let mut it = records.into_iter();
        let variants = variants
            .iter()
            .map(|v| VariantReport {
                name: v.name,
                settings: format!("{:?}", v.controller),
                groups: GoalKind::ALL
                    .iter()
                    .map(|&kind| GroupRuns {
                        kind,
                        runs: it.by_ref().take(self.count(kind)).collect(),
                    })
                    .collect(),
            })
            .collect();
        EnvelopeReport {
            seed: self.seed,
            max_time: self.max_time,
            variants,
        }
    }
}

/// A run that missed a target: started outside and not oriented on entry, an End_of_Steering
/// outside a tolerance, a halting rest outside one, not finished, NaN or a
/// violated limit.
#[must_use]
pub fn missed(r: &RunRecord) -> bool {
    (!r.starts_inside && !r.oriented_on_entry)
        || r.eos_ok < r.eos
        || !r.finished
        || (r.halting && !r.rest_ok)
        || r.nan > 0
        || r.violations > 0
}
