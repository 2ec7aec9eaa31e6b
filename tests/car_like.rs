//! Car-like vehicles: a minimum turning radius at every speed
//! (`minTurnRadius`, `|ω| ≤ v / R_min`), so no rotation at rest. The
//! limit holds in the integrator and is checked by the metrics, vehicle
//! files and tables carry it (a unicycle's key and bytes unchanged), and
//! near its goal the car-like vehicle arrives oriented by a Dubins
//! manoeuvre instead of pivoting: the envelope scaled to `R_min`, per
//! distance band, tuned on seed 1, reported on seed 2.
#![cfg(not(target_arch = "wasm32"))]

mod common;

use common::figures::{record, Figure, Kind, Seeds};

use std::sync::OnceLock;

use proptest::prelude::*;

use steering::base::metrics::percentile;
use steering::base::vehicle::{VehicleParams, VehicleState};
use steering::funnelling::controller::ControllerKind;
use steering::funnelling::table::format::TableError;
use steering::funnelling::table::lookup::EtaTable;
use steering::funnelling::table::spec::{TableSpec, DEFAULT_COUNTS};
use steering::funnelling::vehicle_file;
use steering::studies::car_like::{cells, pct, run_all, slow_start, summarise, text, BANDS};

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

proptest! {
    #![proptest_config(ProptestConfig::with_cases(300))]
    /// Whatever the commands, from any admissible state of any car-like
    /// vehicle, every limit holds after every step, `|ω| ≤ v/R_min` too.
    #[test]
    fn every_limit_holds_for_any_car_like_vehicle(
        r_min in 0.05f32..50.0,
        omega_accel in 0.5f32..20.0,
        accel in 0.2f32..10.0,
        v0 in 0.0f32..1.0,
        w0 in -1.0f32..1.0,
        seed in 0u64..1000,
    ) {
        let p = VehicleParams { r_min, omega_accel_max: omega_accel, accel_max: accel, ..VehicleParams::default() };
        let v = v0 * p.v_max;
        let mut s = VehicleState::new(glam::Vec2::ZERO, 0.0, v, w0 * p.omega_limit(v));
        prop_assert!(s.validate(&p).is_ok());
        let mut r = steering::base::rng::Rng::new(seed);
        for _ in 0..600 {
            let prev = s;
            p.integrate(&mut s, r.range(-1e4, 1e4), r.range(-1.0, 2.0 * p.v_max));
            prop_assert!(s.within_limits(&p), "{:?} -> {:?}", prev, s);
            prop_assert!((s.omega - prev.omega).abs() <= p.omega_accel_max * p.dt * 1.0001);
            prop_assert!((s.v - prev.v).abs() <= p.accel_max * p.dt * 1.0001);
        }
    }
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

/// The report seed (never tuned on: the parameters of
/// `crate::funnelling::manoeuvre` were chosen on seed 1) and its runs.
const REPORT_SEED: u64 = 2;
const REPORT_N: usize = 1500;

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
    let kind = match std::env::var("CAR_KIND").as_deref() {
        Ok("relaxed") => ControllerKind::Relaxed,
        _ => ControllerKind::Standard,
    };
    let runs = run_all(table(), &p, kind, seed, n);
    let bands = summarise(&runs, slow_start(&p));
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
    eprintln!("car_like, {kind:?}, seed {seed}, {n} runs: violations {violations}, pivot steps {pivots}, solves {solves} in {updates} updates (max {max_solves} per update)");
    eprint!("{}", text(&p, &runs));
    let mut all: Vec<f32> = bands
        .iter()
        .flat_map(|b| b.ratios.iter().copied())
        .collect();
    let cells = cells(&runs);
    for r in runs.iter().filter(|r| r.halting && !r.rest_ok).take(10) {
        eprintln!("  not at rest inside: {r:?}");
    }
    if seed != REPORT_SEED || n != REPORT_N || kind != ControllerKind::Standard {
        return;
    }
    let mut figs = vec![
        Figure::new(
            "car_like.d5-20.oriented_eps5.worst_cell",
            "oriented on entry, the worst cell (ε_tol ≥ 5° × D_tol, ≥ 10 entries) at D ≥ 5 R_min",
            cells.1,
            "%",
            1,
        ),
        Figure::new(
            "car_like.violations",
            "steps with a violated limit (|ω| ≤ v/R_min included), all runs",
            f64::from(violations),
            "steps",
            0,
        ),
        Figure::new(
            "car_like.pivots",
            "steps turning > 1° slower than 2 % of v_max, all runs",
            f64::from(pivots),
            "steps",
            0,
        ),
        Figure::new(
            "car_like.solves_per_update_max",
            "Dubins solves in one update, most",
            f64::from(max_solves),
            "",
            0,
        ),
        Figure::new(
            "car_like.solves_per_1000_updates",
            "Dubins solves per 1,000 updates",
            1000.0 * solves as f64 / updates.max(1) as f64,
            "",
            2,
        ),
        Figure::new(
            "car_like.length_ratio.median",
            "path length / Dubins shortest (R_min), all bands, median",
            f64::from(percentile(&mut all, 0.5)),
            "×",
            2,
        ),
        Figure::new(
            "car_like.length_ratio.p90",
            "path length / Dubins shortest (R_min), all bands, p90",
            f64::from(percentile(&mut all, 0.9)),
            "×",
            2,
        ),
    ];
    for (b, (lo, hi)) in bands.iter().zip(BANDS) {
        let key = format!("car_like.d{lo}-{hi}");
        let mut r = b.ratios.clone();
        figs.push(Figure::new(
            &format!("{key}.rest_ok"),
            &format!("halting runs at rest inside both tolerances, D {lo}–{hi} R_min"),
            pct(b.rest_ok, b.halting),
            "%",
            2,
        ));
        figs.push(Figure::new(
            &format!("{key}.oriented_eps5"),
            &format!("oriented on entry at ε_tol ≥ 5°, D {lo}–{hi} R_min"),
            pct(b.oriented_eps5.1, b.oriented_eps5.0),
            "%",
            1,
        ));
        figs.push(Figure::new(
            &format!("{key}.length_ratio.median"),
            &format!("path length / Dubins shortest (R_min), D {lo}–{hi} R_min, median"),
            f64::from(percentile(&mut r, 0.5)),
            "×",
            2,
        ));
        figs.push(Figure::new(
            &format!("{key}.length_ratio.p90"),
            &format!("path length / Dubins shortest (R_min), D {lo}–{hi} R_min, p90"),
            f64::from(percentile(&mut r, 0.9)),
            "×",
            2,
        ));
    }
    record(
        "tests/car_like.rs::car_like_arrives_oriented_without_pivoting",
        "cargo test --features cli,counters --test car_like car_like_arrives -- --nocapture",
        Kind::Deterministic,
        &Seeds {
            tuning: vec![1],
            report: vec![REPORT_SEED],
        },
        &figs,
    );
    assert_eq!(violations, 0);
    assert_eq!(pivots, 0);
    assert!(max_solves <= 1);
    for (b, (lo, hi)) in bands.iter().zip(BANDS) {
        assert!(pct(b.rest_ok, b.halting) >= 99.5, "D {lo}–{hi}: {b:?}");
        if lo >= 5.0 {
            assert!(
                b.oriented_eps5.0 >= 300 && pct(b.oriented_eps5.1, b.oriented_eps5.0) >= 95.0,
                "D {lo}–{hi}: {b:?}"
            );
        }
    }
    assert!(cells.1 >= 95.0, "{:?}", cells.0);
    assert!(percentile(&mut all, 0.5) <= 1.3);
}

/// The car-like car with a reverse gear: backing at up to 5 m/s (a third
/// of its forward top speed), a gear change worth `GEAR_COST` R_min of
/// path (chosen on seed 1).
fn car_like_reverse() -> VehicleParams {
    let p = car_like();
    VehicleParams {
        v_reverse: 5.0,
        gear_cost: GEAR_COST * p.r_min,
        ..p
    }
}

/// What a gear change is worth, in `R_min` of path (tuned on seed 1).
const GEAR_COST: f32 = 0.5;
/// Runs per start kind of the reverse study.
const REVERSE_N: usize = 1500;

#[test]
fn car_like_with_reverse_backs_up_where_shorter() {
    use steering::studies::car_like::{full_lock_askew, run_all_from, scenario, text_reverse};
    let seed: u64 = std::env::var("CAR_SEED")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(REPORT_SEED);
    let n: usize = std::env::var("CAR_N")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(REVERSE_N);
    let kind = ControllerKind::Standard;
    let mut figs = Vec::new();
    let mut checks = Vec::new();
    for (gear, p) in [("forward", car_like()), ("reverse", car_like_reverse())] {
        for (start, rest) in [("moving", false), ("rest", true)] {
            let runs = run_all_from(table(), &p, kind, seed, n, rest);
            eprintln!("car_like {gear}, starts {start}, seed {seed}, {n} runs:");
            eprint!("{}", text_reverse(&runs));
            // The deciding test excuses nothing the controller managed;
            // and the runs the full-lock test alone would excuse besides.
            let excused_yet_oriented = runs
                .iter()
                .filter(|r| r.unavoidable && r.reached && !r.starts_inside && r.oriented_on_entry)
                .count();
            let lock_only = runs
                .iter()
                .filter(|r| {
                    let (mut s, g) = scenario(&p, seed, r.index);
                    if rest {
                        s.v = 0.0;
                        s.omega = 0.0;
                    }
                    r.reached && !r.starts_inside && !r.unavoidable && full_lock_askew(&p, &s, &g)
                })
                .count();
            eprintln!("  unavoidable yet entered oriented: {excused_yet_oriented}; possible by the deciding test, unavoidable by the full-lock test alone: {lock_only}");
            for r in runs
                .iter()
                .filter(|r| r.reached && !r.starts_inside && !r.oriented_on_entry && !r.unavoidable)
                .take(8)
            {
                eprintln!("  unoriented, avoidable: {r:?}");
            }
            let bands = summarise(&runs, 0.0);
            let violations: u32 = runs.iter().map(|r| r.violations).sum();
            let pivots: u32 = runs.iter().map(|r| r.pivots).sum();
            checks.push((
                gear,
                rest,
                violations + pivots,
                excused_yet_oriented,
                bands.clone(),
            ));
            let key = format!("car_like.{gear}.{start}");
            for (b, (lo, hi)) in bands.iter().zip(BANDS) {
                let k = format!("{key}.d{lo}-{hi}");
                let mut rs = b.ratios_rs.clone();
                let what = format!(
                    "{gear} gear{}, starts {start}, D {lo}–{hi} R_min",
                    if gear == "reverse" { " too" } else { " only" }
                );
                figs.push(Figure::new(
                    &format!("{k}.oriented"),
                    &format!("oriented on entry, {what}"),
                    pct(b.oriented, b.entries),
                    "%",
                    1,
                ));
                let test = if gear == "reverse" {
                    "both full-lock arcs enter the disk outside β ± ε_tol within the braking distance"
                } else {
                    "no forward path of radius R_min, after braking on a tightening full-lock or straight lead-in, reaches an entry pose sampled on the rim within β ± ε_tol without entering the disk before"
                };
                figs.push(Figure::new(
                    &format!("{k}.unavoidable"),
                    &format!("entries where a wrong heading was unavoidable ({test}), {what}"),
                    b.unavoidable as f64,
                    "runs",
                    0,
                ));
                figs.push(Figure::new(
                    &format!("{k}.oriented_possible"),
                    &format!("oriented on entry where possible, {what}"),
                    pct(b.oriented_possible.1, b.oriented_possible.0),
                    "%",
                    1,
                ));
                figs.push(Figure::new(
                    &format!("{k}.rest_ok"),
                    &format!("halting runs at rest inside both tolerances, {what}"),
                    pct(b.rest_ok, b.halting),
                    "%",
                    1,
                ));
                figs.push(Figure::new(
                    &format!("{k}.length_over_rs.median"),
                    &format!("path length / Reeds–Shepp shortest (R_min), median, {what}"),
                    f64::from(percentile(&mut rs, 0.5)),
                    "×",
                    2,
                ));
            }
            figs.push(Figure::new(
                &format!("{key}.unavoidable_yet_oriented"),
                &format!("entries the deciding test calls unavoidable that entered oriented anyway, {gear}, starts {start}"),
                excused_yet_oriented as f64,
                "runs",
                0,
            ));
            figs.push(Figure::new(
                &format!("{key}.violations"),
                &format!("steps with a violated limit, {gear}, starts {start}"),
                f64::from(violations),
                "steps",
                0,
            ));
            figs.push(Figure::new(
                &format!("{key}.pivots"),
                &format!("steps turning > 1° slower than 2 % of v_max, {gear}, starts {start}"),
                f64::from(pivots),
                "steps",
                0,
            ));
        }
    }
    if seed != REPORT_SEED || n != REVERSE_N {
        return;
    }
    record(
        "tests/car_like.rs::car_like_with_reverse_backs_up_where_shorter",
        "cargo test --release --features cli,counters --test car_like car_like_with_reverse -- --nocapture",
        Kind::Deterministic,
        &Seeds {
            tuning: vec![1],
            report: vec![REPORT_SEED],
        },
        &figs,
    );
    for (gear, rest, violations_pivots, excused, bands) in checks {
        assert_eq!(violations_pivots, 0, "{gear} rest {rest}");
        assert_eq!(excused, 0, "{gear} rest {rest}");
        for (b, (lo, hi)) in bands.iter().zip(BANDS) {
            assert!(
                pct(b.rest_ok, b.halting) >= 99.5,
                "{gear} D {lo}–{hi}: {b:?}"
            );
            assert!(
                pct(b.oriented_possible.1, b.oriented_possible.0) >= 95.0,
                "{gear} rest {rest} D {lo}–{hi}: {b:?}"
            );
            if gear == "reverse" && rest {
                // Every start at rest enters oriented (a start at the rim
                // of a large disk stands off first), median path within
                // 1.2× the Reeds–Shepp shortest (seed 2: 1.05–1.10).
                let mut rs = b.ratios_rs.clone();
                assert_eq!(b.oriented, b.entries, "D {lo}–{hi}: {b:?}");
                assert!(percentile(&mut rs, 0.5) <= 1.2, "D {lo}–{hi}");
            }
        }
    }
}

#[test]
fn the_reverse_parking_preset_backs_into_the_bay() {
    let text = include_str!("../scenarios/car_like_reverse_parking.json");
    let sc = steering::world::scenario::Scenario::from_json(text).unwrap();
    assert_eq!(sc.vehicle.v_reverse, 5.0);
    table().check_params(&sc.vehicle).unwrap();
    let mut w = sc.world().unwrap();
    let (mut backing, mut forward, mut pivots) = (0u32, 0u32, 0u32);
    for _ in 0..sc.steps() {
        let prev = w.agents()[0].state;
        w.step(table()).unwrap();
        let s = w.agents()[0].state;
        backing += u32::from(s.v < 0.0);
        forward += u32::from(s.v > 0.0);
        if steering::base::angle::diff(s.theta, prev.theta).abs() > 1f32.to_radians()
            && prev.v.abs() < 0.02 * sc.vehicle.v_max
        {
            pivots += 1;
        }
    }
    let a = &w.agents()[0];
    eprintln!(
        "reverse parking: backing {backing} steps, forward {forward}, finished at {:?}, at {:?}",
        a.finished_at, a.state
    );
    assert!(a.done(), "{:?}", a.state);
    assert_eq!(a.metrics.violations, 0);
    assert_eq!(pivots, 0);
    assert!(backing > forward, "backing {backing}, forward {forward}");
    let g = a.goal_now;
    assert!((a.state.pos - g.pos).length() < g.d_tol && a.state.v == 0.0);
    assert!(steering::base::angle::diff(g.beta, a.state.theta).abs() < g.eps_tol);
}
