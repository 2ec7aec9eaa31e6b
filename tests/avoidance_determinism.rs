//! Avoidance worlds, same trajectory bits — natively and in WebAssembly
//! (an optimisation of the avoidance pass is bit-identical, or it is a
//! change of behaviour and re-records these hashes).
//!
//! The golden values hash the raw f32 bits of every agent's state at every
//! step of the avoidance presets (ORCA: circle swap N = 32, corridor,
//! doorway with its walls, Fig. 8; separation: the corridor) and of the
//! cost benchmark's lattice world (`benches/avoid_world.rs`, 16 × 16
//! agents, about 11 neighbours each: the k-nearest selection, ties on the
//! lattice included). They pin every ORCA rule in force: the keep-right
//! and the merge behind a mate (`avoidance/passing.rs`), agents at rest
//! seeking their goal's direction with no keep-right bias into a wall
//! (`avoidance/stalled.rs`), patience (`avoidance/patience.rs`), the heading
//! search's `trig` cosine, and plans every other step (the default
//! `AvoidanceConfig::replan_every` 2; the lattice also planning every
//! step). Separation does not keep right: its hash pins the separation
//! pass alone. No proptest and no file I/O, so it also runs under
//! `wasm-pack test --headless --chrome`.

#[cfg(target_arch = "wasm32")]
wasm_bindgen_test::wasm_bindgen_test_configure!(run_in_browser);

use steering::avoidance::{config::AvoidanceConfig, config::AvoidanceMethod};
use steering::funnelling::table::lookup::EtaTable;
use steering::world::scenario::Scenario;

mod common;
use common::world_hash;

#[path = "../benches/avoid_world.rs"]
mod avoid_world;

static TABLE: &[u8] = include_bytes!("../tables/eta.bin");

/// Preset, method override (`None`: the preset's own), steps, golden hash.
const PRESETS: [(&str, &str, Option<AvoidanceMethod>, u32, u64); 5] = [
    (
        "avoid_circle32",
        include_str!("../scenarios/avoid_circle32.json"),
        None,
        1200,
        0xf0c8_9e87_5c4b_a2ac,
    ),
    (
        "avoid_corridor",
        include_str!("../scenarios/avoid_corridor.json"),
        None,
        1200,
        0x8c2f_082e_6ac9_a877,
    ),
    (
        "avoid_doorway",
        include_str!("../scenarios/avoid_doorway.json"),
        None,
        1200,
        DOORWAY,
    ),
    (
        "avoid_fig8",
        include_str!("../scenarios/avoid_fig8.json"),
        None,
        900,
        0xa74a_c626_daae_000f,
    ),
    (
        "avoid_corridor separation",
        include_str!("../scenarios/avoid_corridor.json"),
        Some(AvoidanceMethod::Separation),
        600,
        0x6dd5_dcac_e95a_9356,
    ),
];

/// The doorway's golden hash. Agents stuck at the door's walls run
/// `unicycle`'s heading search, which takes `steering::base::trig`'s cosine:
/// `f32::cos`, the platform's libm, gives other bits in wasm32.
const DOORWAY: u64 = 0xc135_74cd_328a_4ce0;

/// The lattice world's golden hash (ORCA, 16 × 16 agents, 300 steps).
const LATTICE: u64 = 0x2e84_3d7b_146e_2ba5;

/// The same with every agent planning every step (`replanEvery` 1), so the
/// every-step reading, not the default, stays pinned too.
const LATTICE_EVERY_STEP: u64 = 0x2413_6082_0d54_be21;

#[test]
#[cfg_attr(target_arch = "wasm32", wasm_bindgen_test::wasm_bindgen_test)]
fn avoidance_presets_match_golden_hashes() {
    let table = EtaTable::from_bytes(TABLE).expect("committed table loads");
    let got: Vec<(&str, u64)> = PRESETS
        .iter()
        .map(|(name, json, method, steps, _)| {
            let mut sc = Scenario::from_json(json).expect("preset parses and validates");
            if let Some(m) = method {
                sc.avoidance.method = *m;
            }
            let mut w = sc.world().expect("preset builds a world");
            (*name, world_hash(&table, &mut w, *steps))
        })
        .collect();
    for ((name, h), (_, _, _, _, golden)) in got.iter().zip(PRESETS) {
        assert_eq!(*h, golden, "preset {name}: got {h:#018x}; all: {got:#x?}");
    }
}

#[test]
#[cfg_attr(target_arch = "wasm32", wasm_bindgen_test::wasm_bindgen_test)]
fn the_cost_benchmark_lattice_matches_its_golden_hash() {
    let table = EtaTable::from_bytes(TABLE).expect("committed table loads");
    let mut w = avoid_world::world(16, AvoidanceMethod::Orca);
    let h = world_hash(&table, &mut w, 300);
    assert_eq!(h, LATTICE, "lattice: got {h:#018x}");
    let mut w = avoid_world::world(16, AvoidanceMethod::Orca);
    let cfg = AvoidanceConfig {
        replan_every: 1,
        ..AvoidanceConfig::with_method(AvoidanceMethod::Orca)
    };
    w.set_avoidance(cfg, Vec::new()).unwrap();
    let h = world_hash(&table, &mut w, 300);
    assert_eq!(h, LATTICE_EVERY_STEP, "lattice, every step: got {h:#018x}");
}
