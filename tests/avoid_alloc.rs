//! An avoidance step (ORCA) allocates nothing once its buffers have grown
//! (the avoider's scratch lives in fixed arrays and reused buffers):
//! counted with a global allocator that tallies allocations made by this
//! test's own thread, on the cost benchmark's lattice world and on the
//! doorway preset (obstacles).
#![cfg(not(target_arch = "wasm32"))]

use steering::avoidance::config::AvoidanceMethod;
use steering::funnelling::table::lookup::EtaTable;
use steering::world::scenario::Scenario;

mod common;

#[path = "../benches/avoid_world.rs"]
mod avoid_world;

#[global_allocator]
static GLOBAL: common::CountingAlloc = common::CountingAlloc;

#[test]
fn avoidance_steps_do_not_allocate_once_grown() {
    let table = EtaTable::from_bytes(include_bytes!("../tables/eta.bin")).unwrap();
    let lattice = avoid_world::world(16, AvoidanceMethod::Orca);
    let sc = Scenario::from_json(include_str!("../scenarios/avoid_doorway.json")).unwrap();
    let doorway = sc.world().unwrap();
    for (name, mut w) in [("lattice", lattice), ("doorway", doorway)] {
        // The first steps grow the buffers (the densest candidate set
        // sizes the candidate buffers).
        for _ in 0..5 {
            w.step(&table).unwrap();
        }
        let ((), n) = common::allocations(|| {
            for _ in 0..600 {
                w.step(&table).unwrap();
            }
        });
        assert_eq!(n, 0, "{name}: allocations during avoidance steps");
    }
}
