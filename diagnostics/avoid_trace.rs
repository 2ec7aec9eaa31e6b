//! Traces one agent of an avoidance benchmark run, step by step.
//!
//! Per step: pose, the funnel's (γ, v_dt) and the avoidance's command.
//!
//! `cargo run --release --example avoid_trace -- corridor 1008 0 18 24 0.2`
//! (benchmark, seed, agent, from s, to s, every s).

// clap is a native dev-dependency: under `wasm-pack test` (wasm32) this
// diagnostic is empty.
#![cfg_attr(target_arch = "wasm32", no_main)]
#![cfg(not(target_arch = "wasm32"))]

#[path = "common/bench_arg.rs"]
mod bench_arg;
use clap::Parser;
use steering::avoidance::config::AvoidanceMethod;
use steering::funnelling::table::lookup::EtaTable;

/// One agent of an avoidance benchmark run, step by step.
#[derive(Parser)]
struct Args {
    /// Benchmark.
    #[arg(value_enum, default_value_t = bench_arg::BenchArg::Corridor)]
    bench: bench_arg::BenchArg,
    /// Seed.
    #[arg(default_value_t = 1000)]
    seed: u64,
    /// Agent.
    #[arg(default_value_t = 0)]
    i: usize,
    /// From, s.
    #[arg(default_value_t = 0.0)]
    t0: f32,
    /// To, s.
    #[arg(default_value_t = 30.0)]
    t1: f32,
    /// Every, s.
    #[arg(default_value_t = 0.2)]
    every: f32,
}

fn main() {
    let Args {
        bench,
        seed,
        i,
        t0,
        t1,
        every,
    } = Args::parse();
    let bench = bench.bench();
    let bytes = std::fs::read("tables/eta.bin").expect("run from the repository root");
    let table = EtaTable::from_bytes(&bytes).expect("tables/eta.bin loads");
    let sc = bench.scenario(seed, AvoidanceMethod::Orca);
    let mut w = sc.world().expect("benchmark scenarios are valid");
    w.plan(&table).unwrap();
    let every = (every / w.params().dt).round().max(1.0) as u32;
    for step in 0..sc.steps() {
        w.step(&table).unwrap();
        let t = (step + 1) as f32 * w.params().dt;
        for (k, a) in w.agents().iter().enumerate() {
            for o in w.obstacles() {
                let d = o.distance_normal(a.state.pos).0;
                if d < sc.avoidance.radius {
                    println!("t={t:.2} agent {k} touches an obstacle: {d:.3} m");
                }
            }
        }
        if t < t0 || t > t1 || step % every != 0 {
            continue;
        }
        let a = &w.agents()[i];
        let c = w.avoider().commands[i];
        println!(
            "t={t:.2} pos=({:.2},{:.2}) θ={:.0}° v={:.2} ω={:.2} γ={:.0}° v_dt={:.2} {:?} cmd θ={:.0}° v={:.2} active={} walls={}",
            a.state.pos.x,
            a.state.pos.y,
            a.state.theta.to_degrees(),
            a.state.v,
            a.state.omega,
            a.internals.gamma.to_degrees(),
            a.internals.v_dt,
            a.internals.mode,
            c.heading.to_degrees(),
            c.speed,
            c.active,
            c.walls
        );
    }
}
