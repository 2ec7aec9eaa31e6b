//! Classifies the deadlock each corridor agent is in (ORCA).
//!
//! Every agent the moment it has been unfinished and slower than 0.05 m/s for
//! 10 s (the study's rule, as `avoid_stuck.rs`), classified by where it
//! stands and what holds it, and whether it finished by the end of the run.
//!
//! `cargo run --release --example avoid_kinds -- 1000 100 [-v]`
//! (first seed, seeds; `-v` one line per agent).
//!
//! Kinds, first match wins (the group from the left goes +x and keeps to
//! y < 0, its lane; the other goes −x and keeps to y > 0):
//! - `finished`: an arrived agent within 0.9 m (a jam at the goals);
//! - `outside`: beyond the corridor's ends (|x| > 6.3 m);
//! - `wall-wrong-lane`: within 0.55 m of a wall, on the other group's side;
//! - `wall-own-lane`: within 0.55 m of a wall, on its own side;
//! - `mid-jam`: the rest (inside the corridor, away from the walls).

// clap is a native dev-dependency: under `wasm-pack test` (wasm32) this
// diagnostic is empty.
#![cfg_attr(target_arch = "wasm32", no_main)]
#![cfg(not(target_arch = "wasm32"))]

use clap::Parser;
use steering::avoidance::config::AvoidanceMethod;
use steering::funnelling::table::lookup::EtaTable;
use steering::studies::avoidance::Bench;

const KINDS: [&str; 5] = [
    "finished",
    "outside",
    "wall-wrong-lane",
    "wall-own-lane",
    "mid-jam",
];

/// What kind of deadlock each corridor agent is in (ORCA).
#[derive(Parser)]
struct Args {
    /// First seed.
    #[arg(default_value_t = 1000)]
    s0: u64,
    /// Seeds.
    #[arg(default_value_t = 100)]
    n: u64,
    /// One line per deadlocked agent.
    #[arg(short)]
    verbose: bool,
}

fn main() {
    let Args { s0, n, verbose } = Args::parse();
    let bytes = std::fs::read("tables/eta.bin").expect("run from the repository root");
    let table = EtaTable::from_bytes(&bytes).expect("tables/eta.bin loads");
    // [kind][finished later?] agents; first stuck agent of a run by kind.
    let mut agents = [[0usize; 2]; 5];
    let mut first = [0usize; 5];
    let mut runs = 0;
    for seed in s0..s0 + n {
        let sc = Bench::Corridor.scenario(seed, AvoidanceMethod::Orca);
        let mut w = sc.world().expect("benchmark scenarios are valid");
        w.plan(&table).unwrap();
        let half = w.agents().len() / 2;
        let mut slow = vec![0.0f32; w.agents().len()];
        let mut turn = vec![0.0f32; w.agents().len()];
        let mut kind: Vec<Option<usize>> = vec![None; w.agents().len()];
        let mut order = Vec::new();
        for step in 0..sc.steps() {
            w.step(&table).unwrap();
            for (i, a) in w.agents().iter().enumerate() {
                if !a.done() && a.state.v < 0.05 {
                    slow[i] += w.params().dt;
                    turn[i] += a.state.omega.abs() * w.params().dt;
                } else {
                    slow[i] = 0.0;
                    turn[i] = 0.0;
                }
                if slow[i] < 10.0 || kind[i].is_some() {
                    continue;
                }
                let p = a.state.pos;
                let near_done = w
                    .agents()
                    .iter()
                    .enumerate()
                    .any(|(j, b)| j != i && b.done() && (b.state.pos - p).length() < 0.9);
                let dir = if i < half { 1.0 } else { -1.0 };
                let k = if near_done {
                    0
                } else if p.x.abs() > 6.3 {
                    1
                } else if p.y.abs() > 2.0 - 0.55 {
                    if p.y * dir > 0.0 {
                        2
                    } else {
                        3
                    }
                } else {
                    4
                };
                kind[i] = Some(k);
                order.push(i);
                if verbose {
                    println!(
                        "seed {seed} t={:.1} agent {i} at ({:.2}, {:.2}) θ={:.0}° {} turned {:.0}° in 10 s, ω={:.2}",
                        step as f32 * w.params().dt,
                        p.x,
                        p.y,
                        a.state.theta.to_degrees(),
                        KINDS[k],
                        turn[i].to_degrees(),
                        a.state.omega
                    );
                }
            }
        }
        if let Some(&i0) = order.first() {
            runs += 1;
            first[kind[i0].unwrap_or(4)] += 1;
        }
        for (i, k) in kind.iter().enumerate() {
            if let Some(k) = *k {
                agents[k][usize::from(w.agents()[i].done())] += 1;
            }
        }
    }
    let total: usize = agents.iter().map(|a| a[0] + a[1]).sum();
    println!(
        "corridor, ORCA, seeds {s0}–{}: {total} deadlocked agents in {runs} runs",
        s0 + n - 1
    );
    println!("| kind | agents (never finish / finish later) | runs whose first stuck agent is this kind |");
    println!("|---|---|---|");
    for (k, name) in KINDS.iter().enumerate() {
        println!(
            "| {name} | {} ({} / {}) | {} |",
            agents[k][0] + agents[k][1],
            agents[k][0],
            agents[k][1],
            first[k]
        );
    }
}
