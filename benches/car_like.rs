//! Cost per update of a car-like vehicle (minimum turning radius, the
//! Dubins manoeuvre near its goal) against the unicycle's funnelling, in
//! the same run: the car-like reference vehicle and the car (the same
//! limits, a unicycle), each with its own η table, on the same scenarios
//! (`steering::studies::car_like::scenario`, seed 3). 64 agents drive
//! to their goals; each iteration steps one of them one update, and an
//! agent that has arrived starts again, so the cost is the average over
//! whole approaches: funnelling far, and for the car-like vehicle the
//! manoeuvre near the goal with its Dubins solves.
//!
//! `cargo bench --bench car_like` (add `-- --warm-up-time 1
//! --measurement-time 2` for a quick run). Criterion times each; then a
//! plain loop times both in turn, seven rounds, and prints the ratio of
//! the minima.

use std::hint::black_box;
use std::time::Instant;

use criterion::{criterion_group, Criterion};
use steering::base::vehicle::{VehicleParams, VehicleState};
use steering::funnelling::config::FunnelConfig;
use steering::funnelling::controller::ControllerKind;
use steering::funnelling::goal::{FunnelMemory, Goal};
use steering::funnelling::relaxed::{RelaxedConfig, RelaxedInternals};
use steering::funnelling::table::lookup::EtaTable;
use steering::funnelling::table::spec::{TableSpec, DEFAULT_COUNTS};
use steering::funnelling::update::{Mode, Update};
use steering::funnelling::vehicle_file;
use steering::studies::car_like::scenario;

const AGENTS: usize = 64;

/// One vehicle's agents on their way.
struct Fleet {
    p: VehicleParams,
    t: EtaTable,
    starts: Vec<(VehicleState, Goal)>,
    now: Vec<(VehicleState, FunnelMemory)>,
    funnel: FunnelConfig,
    relaxed: RelaxedConfig,
}

impl Fleet {
    fn new(name: &str) -> Self {
        let p = vehicle_file::reference(name).unwrap().vehicle;
        let car_like = vehicle_file::reference("car_like").unwrap().vehicle;
        let t = TableSpec::for_vehicle(p, DEFAULT_COUNTS)
            .unwrap()
            .generate()
            .unwrap();
        let starts: Vec<_> = (0..AGENTS).map(|i| scenario(&car_like, 3, i)).collect();
        let now = starts
            .iter()
            .map(|(s, _)| (*s, FunnelMemory::default()))
            .collect();
        Self {
            p,
            t,
            starts,
            now,
            funnel: FunnelConfig::default(),
            relaxed: RelaxedConfig::default(),
        }
    }

    fn update(&mut self, k: usize) {
        let i = k % AGENTS;
        let goal = self.starts[i].1;
        let (s, m) = &mut self.now[i];
        let mut ri = RelaxedInternals::default();
        let out = ControllerKind::Standard.step(
            &self.funnel,
            &self.relaxed,
            &mut Update {
                table: &self.t,
                params: &self.p,
                state: s,
                goal: black_box(&goal),
                memory: m,
            },
            &mut ri,
        );
        if out.mode == Mode::EndOfSteering {
            self.now[i] = (self.starts[i].0, FunnelMemory::default());
        }
        black_box(out);
    }
}

fn bench(c: &mut Criterion) {
    let mut g = c.benchmark_group("car_like");
    for name in ["car", "car_like"] {
        let mut f = Fleet::new(name);
        g.bench_function(format!("update {name}"), |b| {
            let mut k = 0usize;
            b.iter(|| {
                k += 1;
                f.update(k);
            });
        });
    }
    g.finish();
}

/// Same-run ratio from interleaved rounds.
fn ratio() {
    let mut car = Fleet::new("car");
    let mut like = Fleet::new("car_like");
    let n = 400_000;
    let time = |f: &mut Fleet| {
        let t0 = Instant::now();
        for k in 0..n {
            f.update(k);
        }
        t0.elapsed().as_secs_f64() * 1e9 / n as f64
    };
    let (mut a, mut b) = (f64::INFINITY, f64::INFINITY);
    for _ in 0..7 {
        a = a.min(time(&mut car));
        b = b.min(time(&mut like));
    }
    println!(
        "same-run ratio: update of the car-like vehicle (manoeuvre near the goal) / the car's funnelling (unicycle): {b:.1} / {a:.1} ns = {:.2}",
        b / a
    );
}

criterion_group!(benches, bench);

fn main() {
    benches();
    // Not under `cargo test --all-targets` (criterion's test mode runs each
    // piece once; the same-run ratios are a benchmark's, minutes long).
    if std::env::args().any(|a| a == "--bench") {
        ratio();
    }
    Criterion::default().configure_from_args().final_summary();
}
