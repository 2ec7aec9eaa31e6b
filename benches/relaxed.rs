//! Paper 001 Table 1 analogue: ns per control update (plan + one seek
//! step), standard vs relaxed funnelling, for small (0.1 m, 1°) and large
//! (2.5 m, 15°) tolerances, measured side by side in one run; the relaxed
//! controller aiming at the entry point (default) and with the paper's
//! ring arc, with its cheap arc-end η and with the full multilinear one.
//!
//! `cargo bench --bench relaxed -- --warm-up-time 1 --measurement-time 2`
//! Criterion times each controller over a mix of goal parameters; then a
//! plain timing loop gives the [min, max] over 16 goal-parameter bins
//! (centre distance 1.5, 4, 10, 25 m × β offset 0°, 60°, 120°, 180° from the
//! bearing; 256 random bearings and (v, ω) per bin), as in Table 1.
//! With `FIGURES_DIR` set, Table 1's two claims, each in the paper's
//! reading and ours, are written as timed records for the figures report
//! (`tests/common/figures.rs` documents the format).

use std::hint::black_box;
use std::time::Instant;

use criterion::{criterion_group, Criterion};
use steering::base::vehicle::{VehicleParams, VehicleState};
use steering::funnelling::config::FunnelConfig;
use steering::funnelling::controller::Controller;
use steering::funnelling::goal::{FunnelMemory, Goal};
use steering::funnelling::relaxed::{EndEta, RelaxedAim, RelaxedConfig, RelaxedInternals};
use steering::funnelling::table::lookup::EtaTable;
use steering::funnelling::update::Update;
use steering::studies::cost::{
    table1_bins, TABLE1_LARGE, TABLE1_LARGE_CLAIM, TABLE1_SMALL, TABLE1_SMALL_CLAIM,
};

#[path = "../tests/common/figures.rs"]
mod figures;

fn table() -> EtaTable {
    EtaTable::for_vehicle(&VehicleParams::default()).unwrap()
}

/// The first 64 cases of each Table 1 bin.
fn mixed(tol: (f32, f32)) -> Vec<(VehicleState, Goal)> {
    table1_bins(tol)
        .into_iter()
        .flat_map(|b| b.into_iter().take(64))
        .collect()
}

#[inline]
fn update(t: &EtaTable, p: &VehicleParams, c: &Controller, case: &(VehicleState, Goal)) {
    let mut s = case.0;
    let mut mem = FunnelMemory::default();
    let mut ri = RelaxedInternals::default();
    let mut u = Update {
        table: t,
        params: p,
        state: &mut s,
        goal: black_box(&case.1),
        memory: &mut mem,
    };
    black_box(c.step(&mut u, &mut ri));
    black_box(&s);
}

const TOLS: [(&str, (f32, f32)); 2] = [("small", TABLE1_SMALL), ("large", TABLE1_LARGE)];

/// Ours (defaults, then the paper arc variants), then like for like the
/// paper's literal standard controller against its literal relaxed one
/// (Table 1's "relaxed about 50 % cheaper" is against that).
fn controllers() -> [(&'static str, Controller); 6] {
    let f = FunnelConfig::default();
    let lit = steering::studies::envelope::literal_config();
    let lit_rel = steering::studies::envelope::literal_relaxed_config();
    let paper = RelaxedConfig {
        aim: RelaxedAim::PaperArc,
        ..Default::default()
    };
    [
        ("standard", Controller::Standard(f)),
        (
            "relaxed_entry",
            Controller::Relaxed(f, RelaxedConfig::default()),
        ),
        ("relaxed_paper_arc", Controller::Relaxed(f, paper)),
        (
            "relaxed_paper_arc_multilinear_ends",
            Controller::Relaxed(
                f,
                RelaxedConfig {
                    end_eta: EndEta::Multilinear,
                    ..paper
                },
            ),
        ),
        ("standard_literal", Controller::Standard(lit)),
        ("relaxed_literal", Controller::Relaxed(lit, lit_rel)),
    ]
}

fn bench(c: &mut Criterion) {
    let p = VehicleParams::default();
    let t = table();
    let mut g = c.benchmark_group("relaxed");
    for (tn, tol) in TOLS {
        let cases = mixed(tol);
        for (cn, ctl) in controllers() {
            g.bench_function(format!("{cn}_{tn}"), |b| {
                let mut k = 0usize;
                b.iter(|| {
                    k = (k + 1) % cases.len();
                    update(&t, &p, &ctl, &cases[k]);
                });
            });
        }
    }
    g.finish();
}

/// Table 1: [min, max] over the bins of the mean ns per update.
fn table1() {
    let p = VehicleParams::default();
    let t = table();
    let n = 100_000usize;
    println!(
        "\nTable 1 analogue (ns per update, [min, max] over 16 goal-parameter bins; same run):"
    );
    println!("| controller | small tolerances (0.1 m, 1°) | large tolerances (2.5 m, 15°) |");
    println!("|---|---|---|");
    let mut means = [[0.0f64; 2]; 6];
    let mut rows = Vec::new();
    for (ci, (cn, ctl)) in controllers().iter().enumerate() {
        let mut cells = Vec::new();
        for (ti, (_, tol)) in TOLS.iter().enumerate() {
            let (mut lo, mut hi, mut sum) = (f64::INFINITY, 0.0f64, 0.0);
            for cases in table1_bins(*tol) {
                let t0 = Instant::now();
                for k in 0..n {
                    update(&t, &p, ctl, &cases[k & 255]);
                }
                let ns = t0.elapsed().as_secs_f64() * 1e9 / n as f64;
                lo = lo.min(ns);
                hi = hi.max(ns);
                sum += ns;
            }
            means[ci][ti] = sum / 16.0;
            cells.push(format!("[{lo:.0}, {hi:.0}] (mean {:.0})", sum / 16.0));
        }
        rows.push(format!("| {cn} | {} | {} |", cells[0], cells[1]));
    }
    for r in rows {
        println!("{r}");
    }
    println!(
        "mean cost / standard: entry aim small {:.2}, large {:.2}; paper arc small {:.2}, large {:.2}; paper arc with multilinear ends small {:.2}, large {:.2}",
        means[1][0] / means[0][0],
        means[1][1] / means[0][1],
        means[2][0] / means[0][0],
        means[2][1] / means[0][1],
        means[3][0] / means[0][0],
        means[3][1] / means[0][1]
    );
    println!(
        "like for like, the paper's literal controllers: relaxed / standard small {:.2}, large {:.2} (paper: about equal, and about 0.5 for large tolerances)",
        means[5][0] / means[4][0],
        means[5][1] / means[4][1]
    );
    record(&means);
}

/// Table 1's claims as timed records: relaxed / standard mean time per
/// update, ours (rows 1 / 0 of [`controllers`]) and the paper's literal
/// controllers (rows 5 / 4), at each tolerance.
fn record(means: &[[f64; 2]; 6]) {
    let claims = [
        ("small_tolerances_cost_alike", TABLE1_SMALL_CLAIM, "about 1"),
        (
            "large_tolerances_relaxed_cheaper",
            TABLE1_LARGE_CLAIM,
            "about 0.5",
        ),
    ];
    for (ti, ((size, _), (name, claim, paper))) in TOLS.iter().zip(claims).enumerate() {
        for (reading, (std, rel), who) in [
            ("ours", (0, 1), "the default controllers (entry aim)"),
            ("paper", (4, 5), "the paper's literal controllers"),
        ] {
            let what = format!(
                "001 Table 1, {reading} reading ({who}): relaxed / standard mean time per update over the 16 bins × 256 cases (paper {paper}: {claim})"
            );
            figures::record_timed(
                "relaxed",
                &format!("p001_table1_{name}_{reading}"),
                &[figures::Figure::new(
                    &format!("p001.table1.{size}.{reading}.time_ratio"),
                    &what,
                    means[rel][ti] / means[std][ti],
                    "×",
                    2,
                )],
            );
        }
    }
}

criterion_group!(benches, bench);

fn main() {
    benches();
    // Not under `cargo test --all-targets` (criterion's test mode runs each
    // piece once; the same-run ratios are a benchmark's, minutes long).
    if std::env::args().any(|a| a == "--bench") {
        table1();
    }
    Criterion::default().configure_from_args().final_summary();
}
