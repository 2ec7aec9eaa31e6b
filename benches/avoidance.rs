//! Cost per agent update with avoidance vs without (issue 18 target: ORCA
//! ≤ 3× the avoidance-free update at about 10 neighbours, same run).
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

use std::time::{Duration, Instant};

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use steering::avoidance::AvoidanceMethod;
use steering::table::EtaTable;

#[path = "avoid_world.rs"]
mod avoid_world;
use avoid_world::world;

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
                        w.step(&table);
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

criterion_group!(benches, bench);
criterion_main!(benches);
