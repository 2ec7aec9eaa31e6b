//! The world's step on one thread against all the machine's threads
//! (`World::step` updates the agents on the current rayon pool), at
//! 10,000, 100,000 and 500,000 funnelling agents: the seeded random crowd
//! of the lab's performance runs (`World::spawn_random`, 16 oriented goals
//! each), no avoidance, path metrics on (a library world's default).
//!
//! Two measurements, both in the same run:
//! * criterion's groups `world_step_1_thread` and `world_step_all_threads`
//!   (throughput in agent updates per second);
//! * the speed-up, all threads over one: rounds of steps alternating
//!   between the two pools (1, N, N, 1, …), so a change in the shared
//!   machine's load during the run weighs on both alike; the median time
//!   per step of each. It is printed and, with `FIGURES_DIR` set, written
//!   as a timed record (`tests/common/figures.rs` documents the format)
//!   for the figures report.
//!
//! The two pools give the same bits (`tests/library.rs`), so only time is
//! compared. Run with
//! `FIGURES_DIR=target/figures cargo bench --bench parallel_step -- --warm-up-time 1 --measurement-time 3`.

use std::hint::black_box;
use std::time::{Duration, Instant};

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use rayon::{ThreadPool, ThreadPoolBuilder};
use steering::prelude::*;

#[path = "../tests/common/figures.rs"]
mod figures;

const SIZES: [usize; 3] = [10_000, 100_000, 500_000];

/// The random crowd's seed.
const SEED: u64 = 44;

/// The crowd of `n` agents, a second of steps in (every agent under way).
fn crowd(table: &EtaTable, n: usize) -> World {
    let mut w = World::new(VehicleParams::default(), FunnelConfig::default()).expect("defaults");
    w.spawn_random(n, SEED, 100.0, 1.3)
        .expect("within the bound");
    for _ in 0..60 {
        w.step(table).unwrap();
    }
    w
}

fn pool(threads: usize) -> ThreadPool {
    ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .expect("a thread pool")
}

fn bench(c: &mut Criterion) {
    let table = EtaTable::for_vehicle(&VehicleParams::default()).expect("the embedded table");
    let all = std::thread::available_parallelism().map_or(1, usize::from);
    let pools = [
        ("world_step_1_thread", pool(1)),
        ("world_step_all_threads", pool(all)),
    ];
    let mut figs = Vec::new();
    for n in SIZES {
        let world = crowd(&table, n);
        for (name, p) in &pools {
            let mut w = world.clone();
            let mut g = c.benchmark_group(*name);
            g.throughput(Throughput::Elements(n as u64));
            g.sample_size(10);
            g.bench_function(BenchmarkId::from_parameter(n), |b| {
                b.iter(|| {
                    p.install(|| w.step(&table)).unwrap();
                    black_box(w.agents()[0].state.pos);
                });
            });
            g.finish();
        }
        let [one, many] = alternating(&world, &table, [&pools[0].1, &pools[1].1]);
        let per = |d: Duration| d.as_secs_f64() * 1e9 / n as f64;
        println!(
            "{n} agents: 1 thread {:.1} ms/step ({:.0} ns/update), {all} threads {:.1} ms/step ({:.0} ns/update): {:.2}× faster",
            one.as_secs_f64() * 1e3,
            per(one),
            many.as_secs_f64() * 1e3,
            per(many),
            one.as_secs_f64() / many.as_secs_f64()
        );
        let k = n / 1000;
        figs.push(figures::Figure::new(
            &format!("world.step.{k}k.ns_per_update_1_thread"),
            &format!("ns per agent update, {n} random funnelling agents, one thread"),
            per(one),
            "ns",
            0,
        ));
        figs.push(figures::Figure::new(
            &format!("world.step.{k}k.ns_per_update_all_threads"),
            &format!("ns per agent update, {n} random funnelling agents, {all} threads"),
            per(many),
            "ns",
            0,
        ));
        figs.push(figures::Figure::new(
            &format!("world.step.{k}k.speedup"),
            &format!(
                "speed-up of World::step on {all} threads over one, {n} agents (median of alternating rounds)"
            ),
            one.as_secs_f64() / many.as_secs_f64(),
            "×",
            2,
        ));
    }
    if std::env::var_os("FIGURES_DIR").is_some() {
        figures::record(
            "benches/parallel_step.rs",
            "FIGURES_DIR=target/figures cargo bench --bench parallel_step",
            figures::Kind::Timed,
            &figures::Seeds {
                tuning: Vec::new(),
                report: vec![SEED],
            },
            &figs,
        );
    }
}

/// Median time per step on each pool, from rounds of steps alternating
/// between them (one world each, stepped on from `world`).
fn alternating(world: &World, table: &EtaTable, pools: [&ThreadPool; 2]) -> [Duration; 2] {
    const ROUNDS: usize = 6;
    let steps = (2_000_000 / world.agents().len()).clamp(2, 100);
    let mut worlds = [world.clone(), world.clone()];
    let mut times: [Vec<Duration>; 2] = [Vec::new(), Vec::new()];
    for round in 0..ROUNDS {
        for k in [round % 2, 1 - round % 2] {
            let w = &mut worlds[k];
            let t0 = Instant::now();
            pools[k].install(|| {
                for _ in 0..steps {
                    w.step(table).unwrap();
                }
            });
            times[k].push(t0.elapsed() / steps as u32);
        }
    }
    times.map(|mut t| {
        t.sort_unstable();
        t[t.len() / 2]
    })
}

criterion_group!(benches, bench);
criterion_main!(benches);
