//! Counts the instructions of a world step with and without avoidance (under callgrind).
//!
//! A deterministic cost for a loaded machine: run under callgrind and
//! difference two step counts, e.g.
//!
//! ```sh
//! cargo build --release --example avoid_icount
//! for n in 20 40; do valgrind --tool=callgrind --callgrind-out-file=/dev/null \
//!   target/release/examples/avoid_icount orca $n 2>&1 | grep Collected; done
//! ```
//! `off`, `separation` or `orca`, N steps after 60 unmeasured ones, on the
//! world of `benches/avoidance.rs` (32 × 32 agents on a 1.6 m lattice,
//! about 11 neighbours each): instructions per agent update =
//! (count(40) − count(20)) / (20 · 1,024). An optional third argument
//! sets `maxNeighbours` (a change of behaviour, to measure its cost).

// clap is a native dev-dependency: under `wasm-pack test` (wasm32) this
// diagnostic is empty.
#![cfg_attr(target_arch = "wasm32", no_main)]
#![cfg(not(target_arch = "wasm32"))]

use clap::Parser;
use std::hint::black_box;
use steering::avoidance::config::AvoidanceMethod;
use steering::funnelling::table::lookup::EtaTable;

#[path = "../benches/avoid_world.rs"]
mod avoid_world;

/// Steps of the avoidance benchmark's lattice world, for callgrind.
#[derive(Parser)]
struct Args {
    /// Avoidance method.
    #[arg(default_value = "orca", value_parser = ["off", "separation", "orca"])]
    what: String,
    /// Measured steps (after 60 unmeasured ones).
    #[arg(default_value_t = 20)]
    n: usize,
    /// `maxNeighbours` (default: the method's).
    max_neighbours: Option<u32>,
}

fn main() {
    let Args {
        what,
        n,
        max_neighbours,
    } = Args::parse();
    let method = match what.as_str() {
        "off" => AvoidanceMethod::Off,
        "separation" => AvoidanceMethod::Separation,
        _ => AvoidanceMethod::Orca,
    };
    let table = EtaTable::from_bytes(&std::fs::read("tables/eta.bin").unwrap())
        .expect("tables/eta.bin (run from the repository root)");
    let mut w = avoid_world::world(32, method);
    if let Some(k) = max_neighbours {
        let mut cfg = steering::avoidance::config::AvoidanceConfig::with_method(method);
        cfg.max_neighbours = k;
        w.set_avoidance(cfg, Vec::new()).unwrap();
    }
    for _ in 0..60 + n {
        w.step(&table).unwrap();
    }
    black_box(&w);
}
