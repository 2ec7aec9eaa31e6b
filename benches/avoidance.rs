//! Cost per agent update with avoidance vs without (target: ORCA ≤ 3×
//! the avoidance-free update at about 10 neighbours, same run).
//!
//! Agents on a square lattice of 1.6 m (π·3²/1.6² ≈ 11 within the 3 m
//! neighbour reach), each funnelling to a seeded oriented target 20–30 m
//! away in any direction, so paths cross everywhere and ORCA is active for
//! most agents. The world restarts every 300 steps (5 s: the density stays
//! near the lattice's); restarting is not timed. 1,000 and 4,000 agents:
//! a flat cost per agent shows the grid search is not quadratic.
//! Throughput is per agent (ns per agent update = 1e9 / elements/s).
//!
//! Run with `cargo bench --bench avoidance -- --warm-up-time 1 --measurement-time 3`.
//! After criterion's groups it prints the same-run ratio ORCA / off at
//! both sizes: off and ORCA rounds interleaved (a whole 300-step restart
//! cycle each, thread CPU time), the best round of each kept, so a load
//! that comes and goes during the run weighs on both alike. The ratio
//! alone: a filter that matches no group, e.g. `<bench binary> --bench
//! same-run`.

use std::time::{Duration, Instant};

use criterion::{BenchmarkId, Criterion, Throughput};
use steering::avoidance::config::AvoidanceMethod;
use steering::funnelling::table::lookup::EtaTable;

#[path = "avoid_world.rs"]
mod avoid_world;
use avoid_world::world;
#[path = "cpu_clock.rs"]
mod cpu_clock;

fn bench(c: &mut Criterion) {
    let table = EtaTable::from_bytes(include_bytes!("../tables/eta.bin")).unwrap();
    let mut g = c.benchmark_group("avoid_step");
    for side in [32usize, 64] {
        let n = side * side;
        g.throughput(Throughput::Elements(n as u64));
        for m in [
            AvoidanceMethod::Off,
            AvoidanceMethod::Separation,
            AvoidanceMethod::Orca,
        ] {
            let w0 = world(side, m);
            g.bench_with_input(BenchmarkId::new(m.name(), n), &w0, |b, w0| {
                b.iter_custom(|iters| {
                    let mut total = Duration::ZERO;
                    let mut w = w0.clone();
                    let mut k = 0;
                    for _ in 0..iters {
                        if k == 300 {
                            w = w0.clone();
                            k = 0;
                        }
                        let t = Instant::now();
                        w.step(&table).unwrap();
                        total += t.elapsed();
                        k += 1;
                    }
                    total
                });
            });
        }
    }
    g.finish();
}

/// Steps of one restart cycle (as in [`bench`]).
const CYCLE: usize = 300;

/// ns per agent update over one restart cycle from `w0` (thread CPU time;
/// wall time without that clock). The clone is not timed.
fn cycle_ns(w0: &steering::world::World, table: &EtaTable) -> f64 {
    let mut w = w0.clone();
    let (t0, w_0) = (cpu_clock::thread_ns(), Instant::now());
    for _ in 0..CYCLE {
        w.step(table).unwrap();
    }
    let ns = match (t0, cpu_clock::thread_ns()) {
        (Some(a), Some(b)) => (b - a) as f64,
        _ => w_0.elapsed().as_secs_f64() * 1e9,
    };
    std::hint::black_box(&w);
    ns / (CYCLE * w0.agents().len()) as f64
}

/// Same-run ratio ORCA / off: rounds interleaved, the best of each kept.
fn ratio() {
    let table = EtaTable::from_bytes(include_bytes!("../tables/eta.bin")).unwrap();
    for (side, rounds) in [(32usize, 9), (64, 5)] {
        let off = world(side, AvoidanceMethod::Off);
        let orca = world(side, AvoidanceMethod::Orca);
        let (mut best_off, mut best_orca) = (f64::INFINITY, f64::INFINITY);
        for _ in 0..rounds {
            best_off = best_off.min(cycle_ns(&off, &table));
            best_orca = best_orca.min(cycle_ns(&orca, &table));
        }
        println!(
            "same-run ratio ({} agents, best of {rounds} interleaved {CYCLE}-step cycles): ORCA / off {best_orca:.1} / {best_off:.1} ns per agent update = {:.2}",
            side * side,
            best_orca / best_off
        );
    }
}

fn main() {
    let mut c = Criterion::default().configure_from_args();
    bench(&mut c);
    // Not under `cargo test --benches` (criterion's test mode).
    if std::env::args().any(|a| a == "--bench") {
        ratio();
    }
    c.final_summary();
}
