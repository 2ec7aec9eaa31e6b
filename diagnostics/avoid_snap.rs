//! Prints ASCII snapshots of an avoidance benchmark run (ORCA).
//!
//! Every agent is a
//! glyph of its heading (`>` `<` `^` `v`; upper-case letters at rest), and
//! the obstacles are `#`.
//!
//! `cargo run --release --example avoid_snap -- corridor 1001 2.0`
//! (benchmark, seed, seconds between snapshots).

// clap is a native dev-dependency: under `wasm-pack test` (wasm32) this
// diagnostic is empty.
#![cfg_attr(target_arch = "wasm32", no_main)]
#![cfg(not(target_arch = "wasm32"))]

use clap::Parser;
use steering::avoidance::config::AvoidanceMethod;
use steering::funnelling::table::lookup::EtaTable;
use steering::studies::avoidance::Bench;

/// ASCII snapshots of an avoidance benchmark run (ORCA).
#[derive(Parser)]
struct Args {
    /// Benchmark (the snapshot's frame fits these two).
    #[arg(default_value = "corridor", value_parser = ["corridor", "doorway"])]
    which: String,
    /// Seed.
    #[arg(default_value_t = 1000)]
    seed: u64,
    /// Seconds between snapshots.
    #[arg(default_value_t = 2.0)]
    every: f32,
    /// Last snapshot, s.
    #[arg(default_value_t = 60.0)]
    t_end: f32,
}

fn main() {
    let Args {
        which,
        seed,
        every,
        t_end,
    } = Args::parse();
    let bytes = std::fs::read("tables/eta.bin").expect("run from the repository root");
    let table = EtaTable::from_bytes(&bytes).expect("tables/eta.bin loads");
    let bench = match which.as_str() {
        "doorway" => Bench::Doorway,
        _ => Bench::Corridor,
    };
    let sc = bench.scenario(seed, AvoidanceMethod::Orca);
    let mut w = sc.world().expect("benchmark scenarios are valid");
    w.plan(&table).unwrap();
    let (x0, x1, y0, y1, cell) = (-8.0f32, 8.0f32, -3.0f32, 3.0f32, 0.25f32);
    let cols = ((x1 - x0) / cell) as usize;
    let rows = ((y1 - y0) / cell) as usize;
    let every_steps = (every / w.params().dt).round() as u32;
    for step in 0..sc.steps() {
        w.step(&table).unwrap();
        if step % every_steps != 0 || step as f32 * w.params().dt > t_end {
            continue;
        }
        let mut g = vec![vec![' '; cols]; rows];
        for (r, row) in g.iter_mut().enumerate() {
            for (c, ch) in row.iter_mut().enumerate() {
                let p = glam::Vec2::new(x0 + (c as f32 + 0.5) * cell, y1 - (r as f32 + 0.5) * cell);
                if w.obstacles()
                    .iter()
                    .any(|o| o.distance_normal(p).0.abs() <= cell * 0.5 + 1e-3)
                {
                    *ch = '#';
                }
            }
        }
        let mut done = 0;
        for (i, a) in w.agents().iter().enumerate() {
            if a.done() {
                done += 1;
            }
            let p = a.state.pos;
            let c = ((p.x - x0) / cell).floor();
            let r = ((y1 - p.y) / cell).floor();
            if c < 0.0 || r < 0.0 || c as usize >= cols || r as usize >= rows {
                continue;
            }
            let th = a.state.theta.to_degrees();
            let k = if (-45.0..45.0).contains(&th) {
                0
            } else if (45.0..135.0).contains(&th) {
                1
            } else if (-135.0..-45.0).contains(&th) {
                2
            } else {
                3
            };
            let rest = a.state.v < 0.05;
            // First half of the agents (the corridor's group from the left): > ^ v <,
            // at rest @; the others e n s w, at rest upper case.
            let mark = if i < w.agents().len() / 2 {
                if rest {
                    '@'
                } else {
                    ['>', '^', 'v', '<'][k]
                }
            } else if rest {
                ['E', 'N', 'S', 'W'][k]
            } else {
                ['e', 'n', 's', 'w'][k]
            };
            g[r as usize][c as usize] = mark;
        }
        println!("t = {:.1} s, done {done}", step as f32 * w.params().dt);
        for row in g {
            println!("|{}|", row.into_iter().collect::<String>());
        }
    }
}
