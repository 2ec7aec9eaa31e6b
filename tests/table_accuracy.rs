//! Interpolation accuracy of the committed η table against direct seek
//! simulations at 10,000 random off-grid queries inside the sampled ranges
//! (targets: median < 0.5°, p95 < 2°; reachability agreement ≥ 98 %).
//!
//! Two samplings of the same box, both reported (README "Figures"):
//! - **uniform** over every axis, the plain reading of "random queries
//!   inside the sampled ranges": the acceptance figure;
//! - **near-weighted**, log-uniform in distance, which puts a third of the
//!   queries closer than 2 m. Within about two turning radii η is not a
//!   smooth function: a path that just misses the 0.25 m arrival circle
//!   loops round and arrives from elsewhere, so η jumps (by 70° between
//!   v_c = 1.525 and 1.575 m/s in `near_eta_jumps_where_the_path_grazes_the_arrival_circle`),
//!   and no interpolation on a fixed grid follows a jump. Its tail is
//!   reported and locked, not held to the 2° target.
#![cfg(not(target_arch = "wasm32"))]

use glam::Vec2;
use steering::base::angle::diff;
use steering::base::rng::Rng;
use steering::base::vehicle::{VehicleParams, VehicleState};
use steering::funnelling::seek::{simulate_reach, ReachLimits, ReachOutcome};
use steering::funnelling::table::lookup::EtaTable;

fn percentile(v: &mut [f32], q: f32) -> f32 {
    v.sort_by(f32::total_cmp);
    v[((v.len() - 1) as f32 * q).round() as usize]
}

fn table() -> EtaTable {
    let path = std::env::var("ETA_TABLE")
        .unwrap_or_else(|_| concat!(env!("CARGO_MANIFEST_DIR"), "/tables/eta.bin").to_string());
    EtaTable::from_bytes(&std::fs::read(path).unwrap()).unwrap()
}

fn limits(t: &EtaTable) -> ReachLimits {
    let bp = t.params();
    ReachLimits {
        reach_radius: bp.reach_radius,
        orbit_turns: bp.orbit_turns,
        max_time: bp.max_time,
    }
}

/// Errors (degrees) and distances of 10,000 reachable queries, and the
/// share of all queries whose reachability flag agrees with simulation.
struct Sample {
    errors: Vec<f32>,
    distances: Vec<f32>,
    agreement: f64,
}

impl Sample {
    fn run(table: &EtaTable, seed: u64, near_weighted: bool) -> Self {
        let p = VehicleParams::default();
        table.check_params(&p).unwrap();
        let lim = limits(table);
        let (dmin, dmax) = (table.distances()[0], *table.distances().last().unwrap());
        let vd_min = table.axis(4)[0];
        let mut rng = Rng::new(seed);
        let (mut errors, mut distances) = (Vec::new(), Vec::new());
        let (mut queries, mut agree) = (0usize, 0usize);
        while errors.len() < 10_000 {
            queries += 1;
            let u = rng.next_f32();
            let d = if near_weighted {
                dmin * (dmax / dmin).powf(u)
            } else {
                dmin + (dmax - dmin) * u
            };
            let a = rng.range(-std::f32::consts::PI, std::f32::consts::PI);
            let v = rng.range(0.0, p.v_max);
            let w = rng.range(-1.0, 1.0) * p.omega_limit(v);
            let vd = rng.range(vd_min, p.v_max);
            let out = simulate_reach(
                &p,
                VehicleState::new(Vec2::ZERO, 0.0, v, w),
                steering::base::trig::unit(a) * d,
                vd,
                &lim,
            );
            let lk = table.lookup(d, a, w, v, vd);
            agree += usize::from(matches!(out, ReachOutcome::Reached { .. }) == lk.reachable);
            if let (ReachOutcome::Reached { eta, .. }, true) = (out, lk.reachable) {
                errors.push(diff(lk.eta, eta).abs().to_degrees());
                distances.push(d);
            }
        }
        Self {
            errors,
            distances,
            agreement: agree as f64 / queries as f64,
        }
    }

    /// Median, p95 and p99 of the errors with `lo <= D < hi`.
    fn stats(&self, lo: f32, hi: f32) -> (usize, f32, f32, f32) {
        let mut e: Vec<f32> = self
            .errors
            .iter()
            .zip(&self.distances)
            .filter(|(_, &d)| d >= lo && d < hi)
            .map(|(e, _)| *e)
            .collect();
        let n = e.len();
        (
            n,
            percentile(&mut e, 0.5),
            percentile(&mut e, 0.95),
            percentile(&mut e, 0.99),
        )
    }

    fn report(&self, name: &str) -> (f32, f32, f32) {
        let (_, med, p95, p99) = self.stats(0.0, f32::INFINITY);
        eprintln!(
            "η accuracy, {name}, {} reachable off-grid queries: median {med:.3}°, p95 {p95:.3}°, p99 {p99:.3}°; reachability agreement {:.2} %",
            self.errors.len(),
            100.0 * self.agreement
        );
        for (lo, hi) in [
            (0.5, 1.0),
            (1.0, 2.0),
            (2.0, 4.0),
            (4.0, 8.0),
            (8.0, 16.0),
            (16.0, 33.0),
        ] {
            let (n, m, q, r) = self.stats(lo, hi);
            if n > 20 {
                eprintln!("  D in [{lo}, {hi}) m: {n:5} queries, median {m:.2}°, p95 {q:.2}°, p99 {r:.2}°");
            }
        }
        (med, p95, p99)
    }
}

#[test]
fn interpolated_eta_matches_direct_simulation_uniformly_over_the_table() {
    let s = Sample::run(&table(), 2024, false);
    let (med, p95, p99) = s.report("uniform");
    // Measured: median 0.07°, p95 1.2°, p99 5.6°; agreement 99.8 %.
    assert!(med < 0.5, "median {med}");
    assert!(p95 < 2.0, "p95 {p95}");
    assert!(p99 < 8.0, "p99 {p99}");
    assert!(s.agreement >= 0.98, "agreement {}", s.agreement);
}

#[test]
fn near_weighted_accuracy_is_locked() {
    let s = Sample::run(&table(), 2024, true);
    let (med, p95, p99) = s.report("near-weighted (log-uniform D)");
    // Measured: median 0.21°, p95 4.6°, p99 17°; agreement 99.3 %.
    assert!(med < 0.5, "median {med}");
    assert!(p95 < 5.5, "p95 {p95}");
    assert!(p99 < 25.0, "p99 {p99}");
    assert!(s.agreement >= 0.98, "agreement {}", s.agreement);
    // From 4 m on (1.5 turning radii at full speed; grazing loops become
    // rare) the near-weighted sample meets the 2° target too.
    let (_, _, far95, _) = s.stats(4.0, f32::INFINITY);
    assert!(far95 < 2.0, "p95 beyond 4 m {far95}");
}

/// Why the near tail exists: η along the current-speed axis for a target
/// 0.59 m away at 33.5°, by direct simulation. Below about 1.53 m/s the
/// path enters the arrival circle on its first pass; above, it grazes past
/// and loops round, and η jumps by tens of degrees within a few cm/s — a
/// discontinuity inside one table cell (the v_c samples there are 0.25 m/s
/// apart).
#[test]
fn near_eta_jumps_where_the_path_grazes_the_arrival_circle() {
    let t = table();
    let p = VehicleParams::default();
    let lim = limits(&t);
    let eta_at = |v: f32| {
        let w = -0.19 * p.omega_limit(v);
        match simulate_reach(
            &p,
            VehicleState::new(Vec2::ZERO, 0.0, v, w),
            steering::base::trig::unit(33.5f32.to_radians()) * 0.59,
            0.35,
            &lim,
        ) {
            ReachOutcome::Reached { eta, .. } => eta.to_degrees(),
            ReachOutcome::Unreachable => panic!("unreachable at v = {v}"),
        }
    };
    let (below, above) = (eta_at(1.525), eta_at(1.575));
    eprintln!("η at v_c = 1.525 m/s: {below:.1}°, at 1.575 m/s: {above:.1}°");
    assert!(below.abs() < 5.0 && above > 50.0, "{below} {above}");
}
