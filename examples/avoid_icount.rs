//! Deterministic cost of a world step with and without avoidance (issue
//! 18), for a loaded machine: run under callgrind and difference two step
//! counts, e.g.
//!
//! ```sh
//! cargo build --release --example avoid_icount
//! for n in 20 40; do valgrind --tool=callgrind --callgrind-out-file=/dev/null \
//!   target/release/examples/avoid_icount orca $n 2>&1 | grep Collected; done
//! ```
//! `off`, `separation` or `orca`, N steps after 60 unmeasured ones, on the
//! world of `benches/avoidance.rs` (32 × 32 agents on a 1.6 m lattice,
//! about 11 neighbours each): instructions per agent update =
//! (count(40) − count(20)) / (20 · 1,024).

use glam::Vec2;
use std::hint::black_box;
use steering::avoidance::{AvoidanceConfig, AvoidanceMethod};
use steering::funnel::{FunnelConfig, Goal};
use steering::rng::Rng;
use steering::table::EtaTable;
use steering::vehicle::{VehicleParams, VehicleState};
use steering::world::{GoalMotion, GoalSpec, SwitchRule, World};

fn main() {
    let what = std::env::args().nth(1).unwrap_or_else(|| "orca".into());
    let n: usize = std::env::args()
        .nth(2)
        .and_then(|s| s.parse().ok())
        .unwrap_or(20);
    let method = match what.as_str() {
        "off" => AvoidanceMethod::Off,
        "separation" => AvoidanceMethod::Separation,
        _ => AvoidanceMethod::Orca,
    };
    let table = EtaTable::from_bytes(&std::fs::read("tables/eta.bin").unwrap())
        .expect("tables/eta.bin (run from the repository root)");
    let side = 32;
    let p = VehicleParams::default();
    let mut w = World::new(p, FunnelConfig::default()).unwrap();
    w.set_avoidance(AvoidanceConfig::with_method(method), Vec::new())
        .unwrap();
    let mut rng = Rng::new(18);
    for i in 0..side * side {
        let pos = Vec2::new((i % side) as f32, (i / side) as f32) * 1.6;
        let a = rng.range(-3.1, 3.1);
        let d = rng.range(20.0, 30.0);
        let goal = Goal {
            pos: pos + steering::trig::unit(a) * d,
            beta: rng.range(-3.1, 3.1),
            d_tol: 0.3,
            eps_tol: 10f32.to_radians(),
            speed: 1.3,
            halting: true,
            vel: Vec2::ZERO,
        };
        let spec = GoalSpec {
            goal,
            motion: GoalMotion::Static,
            switch: SwitchRule::EndOfSteering,
        };
        w.add_agent(VehicleState::new(pos, a, 1.0, 0.0), vec![spec])
            .unwrap();
    }
    for _ in 0..60 + n {
        w.step(&table);
    }
    black_box(&w);
}
