//! Lists where avoidance benchmark agents first get stuck (the study's deadlocks).
//!
//! For each seed, every agent the moment it has been unfinished
//! and slower than 0.05 m/s for 10 s (the study's deadlock rule), with
//! its goal, mode and the agents within 1.5 m.
//!
//! `cargo run --release --example avoid_stuck -- corridor 1000 20`
//! (benchmark `corridor` | `doorway` | `circle32` | `circle100`, first
//! seed, seeds). Tune seeds are 1000–1019; the report seeds 0–99.

// clap is a native dev-dependency: under `wasm-pack test` (wasm32) this
// diagnostic is empty.
#![cfg_attr(target_arch = "wasm32", no_main)]
#![cfg(not(target_arch = "wasm32"))]

#[path = "common/bench_arg.rs"]
mod bench_arg;
use clap::Parser;
use steering::avoidance::config::AvoidanceMethod;
use steering::funnelling::table::lookup::EtaTable;

/// Where avoidance benchmark agents first get stuck.
#[derive(Parser)]
struct Args {
    /// Benchmark.
    #[arg(value_enum, default_value_t = bench_arg::BenchArg::Corridor)]
    bench: bench_arg::BenchArg,
    /// First seed.
    #[arg(default_value_t = 1000)]
    s0: u64,
    /// Seeds.
    #[arg(default_value_t = 20)]
    n: u64,
}

fn main() {
    let Args { bench, s0, n } = Args::parse();
    let bytes = std::fs::read("tables/eta.bin").expect("run from the repository root");
    let table = EtaTable::from_bytes(&bytes).expect("tables/eta.bin loads");
    let bench = bench.bench();
    for seed in s0..s0 + n {
        let sc = bench.scenario(seed, AvoidanceMethod::Orca);
        let mut w = sc.world().expect("benchmark scenarios are valid");
        w.plan(&table).unwrap();
        let mut slow = vec![0.0f32; w.agents().len()];
        let mut reported = vec![false; w.agents().len()];
        for step in 0..sc.steps() {
            w.step(&table).unwrap();
            for (i, a) in w.agents().iter().enumerate() {
                if !a.done() && a.state.v < 0.05 {
                    slow[i] += w.params().dt;
                } else {
                    slow[i] = 0.0;
                }
                if slow[i] < 10.0 || reported[i] {
                    continue;
                }
                reported[i] = true;
                let g = a.goal_now;
                let mut near = String::new();
                for (j, b) in w.agents().iter().enumerate() {
                    let d = (b.state.pos - a.state.pos).length();
                    if j != i && d < 1.5 {
                        near += &format!(
                            " [{j} d={d:.2} done={} v={:.2} θ={:.0}°]",
                            b.done(),
                            b.state.v,
                            b.state.theta.to_degrees()
                        );
                    }
                }
                println!(
                    "seed {seed} t={:.1} s agent {i} at ({:.2}, {:.2}) θ={:.0}° goal #{} ({:.1}, {:.1}) D={:.2} {:?}{near}",
                    step as f32 * w.params().dt,
                    a.state.pos.x,
                    a.state.pos.y,
                    a.state.theta.to_degrees(),
                    a.current,
                    g.pos.x,
                    g.pos.y,
                    (g.pos - a.state.pos).length(),
                    a.internals.mode
                );
            }
        }
    }
}
