//! Car-like vehicles: a minimum turning radius at every speed
//! (`minTurnRadius`, `|ω| ≤ v / R_min`), so no rotation at rest. The
//! limit holds in the integrator and is checked by the metrics, vehicle
//! files and tables carry it (a unicycle's key and bytes unchanged), and
//! near its goal the car-like vehicle arrives oriented by a Dubins
//! manoeuvre instead of pivoting: the envelope scaled to `R_min`, per
//! distance band, tuned on seed 1, reported on seed 2.
#![cfg(not(target_arch = "wasm32"))]

mod common;

use std::sync::OnceLock;

use steering::base::metrics::percentile;
use steering::base::vehicle::{VehicleParams, VehicleState};
use steering::funnelling::table::format::TableError;
use steering::funnelling::table::lookup::EtaTable;
use steering::funnelling::table::spec::{TableSpec, DEFAULT_COUNTS};
use steering::funnelling::vehicle_file;
use steering::studies::car_like::{run_all, CarRun, BANDS};

fn car_like() -> VehicleParams {
    vehicle_file::reference("car_like").unwrap().vehicle
}

/// The car-like table's sample counts: the default layout (the
/// car-like table builds in about the car's time).
const COUNTS: [usize; 5] = DEFAULT_COUNTS;

fn table() -> &'static EtaTable {
    static T: OnceLock<EtaTable> = OnceLock::new();
    T.get_or_init(|| {
        let t0 = std::time::Instant::now();
        let t = TableSpec::for_vehicle(car_like(), COUNTS)
            .unwrap()
            .generate()
            .unwrap();
        eprintln!(
            "car_like table: {} entries in {:.1?}",
            t.len(),
            t0.elapsed()
        );
        t
    })
}

#[test]
fn the_curvature_bound_holds_at_every_step_and_at_rest_nothing_turns() {
    let p = car_like();
    assert_eq!(p.r_min, 5.0);
    let mut s = VehicleState::default();
    for i in 0..20_000 {
        let a = if (i / 37) % 2 == 0 { 1e6 } else { -1e6 };
        let vd = if (i / 211) % 3 == 0 { 0.0 } else { 100.0 };
        let prev = s;
        p.integrate(&mut s, a, vd);
        assert!(s.within_limits(&p), "{i}: {s:?}");
        assert!(
            s.omega.abs() <= s.v / p.r_min * (1.0 + 1e-5) + 1e-6,
            "{s:?}"
        );
        assert!((s.v - prev.v).abs() <= p.accel_max * p.dt * 1.0001);
        assert!((s.omega - prev.omega).abs() <= p.omega_accel_max * p.dt * 1.0001);
    }
    // At rest a full angular command turns nothing.
    let mut s = VehicleState::default();
    for _ in 0..100 {
        p.integrate(&mut s, 1e6, 0.0);
    }
    assert_eq!((s.omega, s.theta), (0.0, 0.0));
    // A state turning tighter than R_min is refused, the field named.
    let bad = VehicleState::new(glam::Vec2::ZERO, 0.0, 1.0, 0.5);
    let e = bad.validate(&p).unwrap_err().to_string();
    assert!(e.contains("minTurnRadius"), "{e}");
}

#[test]
fn vehicle_files_keys_and_table_bytes_carry_the_radius() {
    for (text, field) in [
        (r#"{"minTurnRadius": -1}"#, "minTurnRadius"),
        (r#"{"minTurnRadius": 1e9}"#, "minTurnRadius"),
        (r#"{"minTurnRadius": NaN}"#, "minTurnRadius"),
        (
            r#"{"vehicle": {"minTurnRadius": "tight"}}"#,
            "minTurnRadius",
        ),
    ] {
        let e = vehicle_file::parse(text).unwrap_err();
        assert!(e.contains(field), "{text}: {e}");
    }
    // The unicycle serialises without the field; the car-like one with it.
    let j = serde_json::to_string(&VehicleParams::default()).unwrap();
    assert!(!j.contains("minTurnRadius"), "{j}");
    let j = serde_json::to_string(&car_like()).unwrap();
    assert!(j.contains("\"minTurnRadius\":5.0"), "{j}");
    // Keys: the car-like key differs from the car's; a small table
    // round-trips through bytes (format version 2) and refuses another R_min.
    let car = vehicle_file::reference("car").unwrap().vehicle;
    let counts = [4, 12, 3, 3, 3];
    let a = TableSpec::with_counts(car, counts);
    let b = TableSpec::with_counts(car_like(), counts);
    assert_ne!(a.key(), b.key());
    let t = b.generate().unwrap();
    let bytes = t.to_bytes();
    assert_eq!(u32::from_le_bytes(bytes[8..12].try_into().unwrap()), 2);
    let back = EtaTable::from_bytes(&bytes).unwrap();
    assert_eq!(back.key(), b.key());
    assert_eq!(back.params().vehicle.r_min, 5.0);
    back.check_params(&car_like()).unwrap();
    assert!(matches!(
        back.check_params(&car),
        Err(TableError::ParamsMismatch {
            field: "minTurnRadius",
            ..
        })
    ));
    let unicycle = a.generate().unwrap().to_bytes();
    assert_eq!(u32::from_le_bytes(unicycle[8..12].try_into().unwrap()), 1);
}

/// Per-band summary of a seed's runs.
#[derive(Debug, Default)]
struct Band {
    runs: usize,
    reached: usize,
    halting: usize,
    rest_ok: usize,
    entries: usize,
    oriented: usize,
    oriented_far5: (usize, usize),
    ratios: Vec<f32>,
    ratios_speed: Vec<f32>,
}

fn summarise(runs: &[CarRun]) -> Vec<Band> {
    let mut bands: Vec<Band> = BANDS.iter().map(|_| Band::default()).collect();
    for r in runs {
        let k = BANDS
            .iter()
            .position(|(lo, hi)| r.d0 >= lo * 0.999 && r.d0 < *hi)
            .unwrap_or(BANDS.len() - 1);
        let b = &mut bands[k];
        b.runs += 1;
        b.reached += usize::from(r.reached || r.starts_inside);
        if r.halting {
            b.halting += 1;
            b.rest_ok += usize::from(r.rest_ok);
        }
        if r.reached && !r.starts_inside {
            b.entries += 1;
            b.oriented += usize::from(r.oriented_on_entry);
            if r.eps_tol_deg >= 4.9 {
                b.oriented_far5.0 += 1;
                b.oriented_far5.1 += usize::from(r.oriented_on_entry);
            }
        }
        if r.finished && r.dubins > 0.0 {
            b.ratios.push(r.length / r.dubins);
            b.ratios_speed.push(r.length / r.dubins_at_speed);
        }
    }
    bands
}

fn pct(a: usize, b: usize) -> f64 {
    100.0 * a as f64 / b.max(1) as f64
}

#[test]
fn car_like_arrives_oriented_without_pivoting() {
    let seed: u64 = std::env::var("CAR_SEED")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(2);
    let n: usize = std::env::var("CAR_N")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(1500);
    let p = car_like();
    let runs = run_all(table(), &p, seed, n);
    let bands = summarise(&runs);
    let violations: u32 = runs.iter().map(|r| r.violations).sum();
    let pivots: u32 = runs.iter().map(|r| r.pivots).sum();
    let max_solves = runs
        .iter()
        .map(|r| r.max_solves_per_update)
        .max()
        .unwrap_or(0);
    let (solves, updates) = runs.iter().fold((0u64, 0u64), |(s, u), r| {
        (s + u64::from(r.solves), u + u64::from(r.updates))
    });
    eprintln!("car_like, seed {seed}, {n} runs: violations {violations}, pivot steps {pivots}, solves {solves} in {updates} updates (max {max_solves} per update)");
    for (b, (lo, hi)) in bands.iter().zip(BANDS) {
        let mut r = b.ratios.clone();
        let mut rs = b.ratios_speed.clone();
        eprintln!(
            "D {lo}–{hi} R_min: {} runs, reach {:.2} %, rest ok {:.2} % of {}, oriented on entry {:.1} % of {} ({:.1} % of {} at ε ≥ 5°), length/Dubins(R_min) median {:.2} p90 {:.2}, /Dubins(speed) median {:.2} p90 {:.2}",
            b.runs,
            pct(b.reached, b.runs),
            pct(b.rest_ok, b.halting),
            b.halting,
            pct(b.oriented, b.entries),
            b.entries,
            pct(b.oriented_far5.1, b.oriented_far5.0),
            b.oriented_far5.0,
            percentile(&mut r, 0.5),
            percentile(&mut r, 0.9),
            percentile(&mut rs, 0.5),
            percentile(&mut rs, 0.9),
        );
    }
    for r in runs.iter().filter(|r| r.halting && !r.rest_ok).take(10) {
        eprintln!("  not at rest inside: {r:?}");
    }
    assert_eq!(violations, 0);
    assert!(max_solves <= 1);
}

#[test]
fn zz_trace() {
    let Ok(i) = std::env::var("CAR_TRACE").map(|s| s.parse::<usize>().unwrap()) else {
        return;
    };
    let p = car_like();
    let (start, g) = steering::studies::car_like::scenario(&p, 1, i);
    eprintln!("{start:?} {g:?}");
    let mut w = steering::world::World::new(p, Default::default()).unwrap();
    w.add_agent(
        start,
        vec![steering::world::goals::GoalSpec {
            goal: g,
            motion: steering::world::goals::GoalMotion::Static,
            switch: steering::world::goals::SwitchRule::EndOfSteering,
        }],
    )
    .unwrap();
    for k in 0..6000 {
        w.step(table());
        let a = &w.agents[0];
        if k % 60 == 0 {
            let m = &a.memory.manoeuvre;
            eprintln!("{k} pos {:.1} {:.1} th {:.2} v {:.2} w {:.3} mode {:?} d {:.2} vdt {:.2} act {} s {:.1} len {:.1} solves {}", a.state.pos.x, a.state.pos.y, a.state.theta, a.state.v, a.state.omega, a.internals.mode, a.internals.d, a.internals.v_dt, m.active, m.s, m.path.length(), m.solves);
        }
    }
}
