//! Dumps every agent of an avoidance benchmark run (ORCA) at given times.
//!
//! Per agent: pose, speed, goal, done, the command.
//!
//! `cargo run --release --example avoid_dump -- corridor 1015 12 20`
//! (benchmark, seed, times in s).

// clap is a native dev-dependency: under `wasm-pack test` (wasm32) this
// diagnostic is empty.
#![cfg_attr(target_arch = "wasm32", no_main)]
#![cfg(not(target_arch = "wasm32"))]

#[path = "common/bench_arg.rs"]
mod bench_arg;
use clap::Parser;
use steering::avoidance::config::AvoidanceMethod;
use steering::funnelling::table::lookup::EtaTable;

/// All agents of an avoidance benchmark run (ORCA) at given times.
#[derive(Parser)]
struct Args {
    /// Benchmark.
    #[arg(value_enum, default_value_t = bench_arg::BenchArg::Corridor)]
    bench: bench_arg::BenchArg,
    /// Seed.
    #[arg(default_value_t = 1000)]
    seed: u64,
    /// Times to print, s.
    times: Vec<f32>,
}

fn main() {
    let Args { bench, seed, times } = Args::parse();
    let bench = bench.bench();
    let bytes = std::fs::read("tables/eta.bin").expect("run from the repository root");
    let table = EtaTable::from_bytes(&bytes).expect("tables/eta.bin loads");
    let sc = bench.scenario(seed, AvoidanceMethod::Orca);
    let mut w = sc.world().expect("benchmark scenarios are valid");
    w.plan(&table).unwrap();
    for step in 0..sc.steps() {
        w.step(&table).unwrap();
        let t = (step + 1) as f32 * w.params().dt;
        if !times.iter().any(|&x| (x - t).abs() < 0.5 * w.params().dt) {
            continue;
        }
        println!("t={t:.2}");
        for (i, a) in w.agents().iter().enumerate() {
            let c = w.avoider().commands[i];
            println!(
                "  {i:2} ({:6.2},{:6.2}) θ={:4.0}° v={:.2} goal=({:.1},{:.1}) done={} γ={:4.0}° v_dt={:.2} cmd θ={:4.0}° v={:.2}",
                a.state.pos.x,
                a.state.pos.y,
                a.state.theta.to_degrees(),
                a.state.v,
                a.goal_now.pos.x,
                a.goal_now.pos.y,
                a.done(),
                a.internals.gamma.to_degrees(),
                a.internals.v_dt,
                c.heading.to_degrees(),
                c.speed
            );
        }
    }
}
