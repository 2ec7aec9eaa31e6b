//! What a vehicle's table is worth: the measures each reference
//! vehicle is reported with, in the vehicle's own units (distances in
//! turning radii `R = v_max / min(ω_max, A/v_max)`, speeds in fractions of
//! `v_max`), so one set of targets serves every vehicle.
//!
//! - [`accuracy`]: interpolated η against the direct seek simulation that
//!   defines it (paper 000 §3), at random off-grid queries uniform over the
//!   table's box with `D ≥ 4 R` (the turn-in region closer than that has
//!   η jumps no fixed grid follows: `tests/table_accuracy.rs`); median and
//!   p95 of the error over queries both call reachable, and the share of
//!   all queries whose reachability the table gets right.
//! - [`oriented_far`]: from an
//!   [`EnvelopeStudy`](crate::studies::envelope::EnvelopeStudy) scaled to the vehicle,
//!   reach over every static run and oriented entries of the runs with
//!   `D ≥ 5 R` at ε_tol 5°.
//!
//! Targets: median ≤ 0.2°, p95 ≤ 2°, reach ≥ 99.5 %, oriented
//! ≥ 95 %. `steer envelope --vehicle FILE` prints them; `tests/
//! vehicle_study.rs` asserts a fast slice.

use core::f32::consts::PI;

use glam::Vec2;
use serde::Serialize;

use crate::base::angle::diff;
use crate::base::metrics::percentile;
use crate::base::rng::Rng;
use crate::base::vehicle::{VehicleParams, VehicleState};
use crate::funnelling::seek::{simulate_reach, ReachLimits, ReachOutcome};
use crate::funnelling::table::lookup::EtaTable;
use crate::funnelling::table::spec::turn_radius;
use crate::studies::envelope::report::VariantReport;
use crate::studies::envelope::GoalKind;

/// Interpolation accuracy of a table.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
#[serde(rename_all = "camelCase")]
pub struct Accuracy {
    /// Queries drawn.
    pub queries: usize,
    /// Queries reachable both by simulation and by the table.
    pub both_reachable: usize,
    /// Median |η_table − η_sim|, degrees.
    pub median_deg: f32,
    /// p95, degrees.
    pub p95_deg: f32,
    /// Share of queries whose reachability the table gets right.
    pub agreement: f32,
}

/// [`accuracy`]'s query `i` of `seed`: (D, α, ω, v_c, v_d).
fn query(table: &EtaTable, p: &VehicleParams, seed: u64, i: usize, d_min: f32) -> [f32; 5] {
    let mut r = Rng::with_stream(seed, i as u64);
    let dmax = *table.distances().last().unwrap_or(&d_min);
    let d = r.range(d_min, dmax);
    let a = r.range(-PI, PI);
    let v = r.range(0.0, p.v_max);
    let w = r.range(-1.0, 1.0) * p.omega_limit(v);
    let vd = r.range(table.axis(4)[0], p.v_max);
    [d, a, w, v, vd]
}

/// Interpolated η against direct simulation at `n` queries with
/// `D ≥ d_min_radii · R` (see the module documentation), seeded.
#[must_use]
pub fn accuracy(
    table: &EtaTable,
    p: &VehicleParams,
    n: usize,
    seed: u64,
    d_min_radii: f32,
) -> Accuracy {
    let bp = table.params();
    let lim = ReachLimits {
        reach_radius: bp.reach_radius,
        orbit_turns: bp.orbit_turns,
        max_time: bp.max_time,
    };
    let d_min = d_min_radii * turn_radius(p);
    let out = crate::base::parallel::map_indices(n, |i| {
        let [d, a, w, v, vd] = query(table, p, seed, i, d_min);
        let sim = simulate_reach(
            p,
            VehicleState::new(Vec2::ZERO, 0.0, v, w),
            crate::base::trig::unit(a) * d,
            vd,
            &lim,
        );
        let lk = table.lookup(d, a, w, v, vd);
        let reached = matches!(sim, ReachOutcome::Reached { .. });
        let err = match (sim, lk.reachable) {
            (ReachOutcome::Reached { eta, .. }, true) => Some(diff(lk.eta, eta).abs().to_degrees()),
            _ => None,
        };
        (reached == lk.reachable, err)
    });
    let agree = out.iter().filter(|o| o.0).count();
    let mut errs: Vec<f32> = out.iter().filter_map(|o| o.1).collect();
    Accuracy {
        queries: n,
        both_reachable: errs.len(),
        median_deg: percentile(&mut errs, 0.5),
        p95_deg: percentile(&mut errs, 0.95),
        agreement: agree as f32 / n.max(1) as f32,
    }
}

/// Reach and far oriented entries of one variant of a scaled envelope
/// study.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
#[serde(rename_all = "camelCase")]
pub struct Arrival {
    /// Static runs.
    pub runs: usize,
    /// Share entering the goal's disk.
    pub reach: f32,
    /// Static runs with D ≥ 5 R at ε_tol 5° that started outside.
    pub far_runs: usize,
    /// Their share oriented on entry.
    pub far_oriented: f32,
}

/// [`Arrival`] of `report`'s static group. The records are in
/// pedestrian-equivalent units ([`super::envelope::EnvelopeStudy::scale`]),
/// where 5 turning radii are 5 × the pedestrian's 2.67 m.
#[must_use]
pub fn oriented_far(report: &VariantReport) -> Arrival {
    let runs = report.runs(GoalKind::Static);
    let five_r = 5.0 * turn_radius(&VehicleParams::default());
    let far: Vec<_> = runs
        .iter()
        .filter(|r| r.d0 >= five_r && r.eps_tol_deg == 5.0 && !r.starts_inside)
        .collect();
    let share = |k: usize, n: usize| k as f32 / n.max(1) as f32;
    Arrival {
        runs: runs.len(),
        reach: share(runs.iter().filter(|r| r.reached).count(), runs.len()),
        far_runs: far.len(),
        far_oriented: share(
            far.iter().filter(|r| r.oriented_on_entry).count(),
            far.len(),
        ),
    }
}
