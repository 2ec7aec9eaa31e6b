//! Counts the instructions of a seek step, a table lookup or a funnelling update (under callgrind).
//!
//! A deterministic cost for a loaded machine: run under callgrind and
//! difference two iteration counts to get instructions per call, e.g.
//!
//! ```sh
//! cargo build --release --example icount
//! for n in 20000 40000; do valgrind --tool=callgrind --callgrind-out-file=/dev/null \
//!   target/release/examples/icount funnel $n 2>&1 | grep Collected; done
//! ```
//! `seek`, `seek_like` (from the funnelling update's states), `lookup` or `funnel` (default funnelling update), N iterations.

// clap is a native dev-dependency: under `wasm-pack test` (wasm32) this
// diagnostic is empty.
#![cfg_attr(target_arch = "wasm32", no_main)]
#![cfg(not(target_arch = "wasm32"))]

use clap::Parser;
use glam::Vec2;
use std::hint::black_box;
use steering::base::rng::Rng;
use steering::base::vehicle::{VehicleParams, VehicleState};
use steering::funnelling::config::FunnelConfig;
use steering::funnelling::goal::{FunnelMemory, Goal};
use steering::funnelling::seek::seek_point;
use steering::funnelling::table::lookup::EtaTable;
use steering::funnelling::update::Update;

/// Calls of one piece, for callgrind.
#[derive(Parser)]
struct Args {
    /// The piece.
    #[arg(default_value = "funnel", value_parser = ["seek", "seek_like", "lookup", "funnel"])]
    what: String,
    /// Iterations.
    #[arg(default_value_t = 10_000)]
    n: usize,
}

fn main() {
    let Args { what, n } = Args::parse();
    let t = EtaTable::from_bytes(&std::fs::read("tables/eta.bin").unwrap())
        .expect("tables/eta.bin (run from the repository root)");
    let p = black_box(VehicleParams::default());
    let mut r = Rng::new(9);
    let qs: Vec<[f32; 6]> = (0..1024)
        .map(|_| {
            let v = r.range(0.0, 2.0);
            [
                r.range(1.0, 30.0),
                r.range(-3.1, 3.1),
                r.range(-1.0, 1.0) * p.omega_limit(v),
                v,
                r.range(0.3, 2.0),
                r.range(-3.1, 3.1),
            ]
        })
        .collect();
    let cfg = black_box(FunnelConfig::default());
    let mut s = VehicleState::new(Vec2::ZERO, 0.0, 1.0, 0.0);
    for i in 0..n {
        let q = qs[i & 1023];
        match what.as_str() {
            "seek" => {
                let tg = s.pos + Vec2::from_angle(q[1]) * q[0];
                seek_point(&p, &mut s, black_box(tg), 1.3);
            }
            // The seek step on the funnelling update's inputs (a fresh
            // state, the same goal; `benches/core.rs`'s like-for-like seek).
            "seek_like" => {
                let mut st = VehicleState::new(Vec2::ZERO, black_box(0.0), q[3], q[2]);
                let tg = Vec2::from_angle(q[1]) * q[0];
                seek_point(&p, &mut st, black_box(tg), black_box(1.3));
                black_box(st);
            }
            "lookup" => {
                black_box(t.lookup(black_box(q[0]), q[1], q[2], q[3], q[4]));
            }
            _ => {
                let mut st = VehicleState::new(Vec2::ZERO, black_box(0.0), q[3], q[2]);
                let g = Goal {
                    pos: Vec2::from_angle(q[1]) * q[0],
                    beta: q[5],
                    ..Default::default()
                };
                black_box(cfg.step(&mut Update {
                    table: &t,
                    params: &p,
                    state: &mut st,
                    goal: &g,
                    memory: &mut FunnelMemory::default(),
                }));
                // The moved state is the update's result too: without this
                // the integrator and θ's sin/cos are dead code and drop out
                // of the count.
                black_box(st);
            }
        }
    }
    black_box(s);
}
