//! Times the funnelling world's step per agent update natively, beside the wasm run.
//!
//! The workload is exactly the one `web/test/wasmnative.mjs` runs in the release wasm package
//! (`make bench-wasm-native` runs both and prints wasm / native): the
//! lab's performance world (`spawn_random`: N agents, seed, extent
//! √N·1.5 m, 1.3 m/s, 16 goals each), warmed up, then timed over rounds of
//! `steps` steps.
//!
//! `cargo run --release --example world_bench -- N STEPS ROUNDS` prints one
//! line per round, `ns_per_update <wall> cpu <process CPU time>` (CPU time:
//! Linux `CLOCK_PROCESS_CPUTIME_ID`, the clock of Node's
//! `process.cpuUsage`, so time preempted on a busy machine is not counted),
//! then `hash <hex>`: FNV-1a of the states' bits after the last round, so
//! the caller can check both sides did the same work. `--metrics` (or
//! `METRICS=1`) keeps the agents' path metrics, which the lab's page never
//! reads.

// clap is a native dev-dependency: under `wasm-pack test` (wasm32) this
// diagnostic is empty.
#![cfg_attr(target_arch = "wasm32", no_main)]
#![cfg(not(target_arch = "wasm32"))]
use std::time::Instant;

use clap::builder::FalseyValueParser;
use clap::Parser;

use steering::funnelling::config::FunnelConfig;
use steering::funnelling::table::lookup::EtaTable;
use steering::world::World;

#[path = "../benches/cpu_clock.rs"]
mod cpu_clock;

/// This process's CPU time in ns (0 where the clock is missing).
fn cpu_ns() -> u128 {
    cpu_clock::process_ns().unwrap_or(0)
}

/// The funnelling world's cost per agent update, natively.
#[derive(Parser)]
struct Args {
    /// Agents.
    #[arg(default_value_t = 10_000)]
    n: usize,
    /// Steps per round (and warm-up steps).
    #[arg(default_value_t = 30)]
    steps: usize,
    /// Timed rounds.
    #[arg(default_value_t = 5)]
    rounds: usize,
    /// Keep the agents' path metrics.
    #[arg(long, env = "METRICS", value_parser = FalseyValueParser::new())]
    metrics: bool,
}

fn main() {
    let Args {
        n,
        steps,
        rounds,
        metrics,
    } = Args::parse();
    let bytes = std::fs::read(concat!(env!("CARGO_MANIFEST_DIR"), "/tables/eta.bin"))
        .expect("tables/eta.bin");
    let table = EtaTable::from_bytes(&bytes).expect("a valid table");
    let mut w = World::new(table.params().vehicle, FunnelConfig::default()).expect("defaults");
    // As the page computes it (f64, then f32 at the binding).
    let extent = 10f64.max((n as f64).sqrt() * 1.5) as f32;
    w.spawn_random(n, 1, extent, 1.3).expect("room");
    // As the lab's page: it never reads the agents' path metrics
    // (`--metrics` keeps them, for a same-run comparison).
    w.set_metrics(metrics);
    for _ in 0..steps {
        w.step(&table).unwrap();
    }
    for _ in 0..rounds {
        let (t0, c0) = (Instant::now(), cpu_ns());
        for _ in 0..steps {
            w.step(&table).unwrap();
        }
        let per = (steps * n) as f64;
        let ns = t0.elapsed().as_nanos() as f64 / per;
        let cpu = (cpu_ns() - c0) as f64 / per;
        println!("ns_per_update {ns:.2} cpu {cpu:.2}");
    }
    let mut out = Vec::new();
    w.write_state(&mut out);
    let mut h: u32 = 0x811c_9dc5;
    for f in out.chunks_exact(steering::world::STATE_STRIDE) {
        for v in &f[..5] {
            for b in v.to_bits().to_le_bytes() {
                h = (h ^ u32::from(b)).wrapping_mul(0x0100_0193);
            }
        }
    }
    println!("hash {h:08x}");
}
