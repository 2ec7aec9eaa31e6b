//! Same scenario, same trajectory — natively and in WebAssembly (docs/DESIGN.md
//! §5; the lab replays exactly what `steer run` computes).
//!
//! The golden values hash the raw f32 bits of every agent's state at every
//! step of paper presets: plain seek, standard funnelling with static, successive and
//! moving goals (each other's pose, Fig. 6) and relaxed funnelling; and of
//! a car-like vehicle parking without pivoting. The
//! controllers use only IEEE-exact arithmetic and the crate's own trig
//! (`steering::base::trig`), never the platform's libm (a car-like agent's
//! Dubins plan uses the `libm` crate, the same code on every target), so
//! the bits must agree on every target. This file has no proptest and no file I/O so it also runs
//! under `wasm-pack test --headless --chrome`.

#[cfg(target_arch = "wasm32")]
wasm_bindgen_test::wasm_bindgen_test_configure!(run_in_browser);

use steering::funnelling::table::lookup::EtaTable;
use steering::world::scenario::Scenario;

mod common;
use common::world_hash;

static TABLE: &[u8] = include_bytes!("../tables/eta.bin");

const PRESETS: [(&str, &str, u64); 4] = [
    // Its second and third targets start a few metres from the first and
    // second: some are approached by turning first
    // (steering::funnelling::short_range).
    (
        "p000_fig7_variety",
        include_str!("../scenarios/p000_fig7_variety.json"),
        0x59af_eddb_246a_c97f,
    ),
    (
        "p000_fig6_face_to_face",
        include_str!("../scenarios/p000_fig6_face_to_face.json"),
        0x1b90_916b_206e_0129,
    ),
    (
        "p001_fig12_successive_relaxed",
        include_str!("../scenarios/p001_fig12_successive_relaxed.json"),
        0x70b0_b733_540d_3c78,
    ),
    // Plain seek (`"controller": "seek"`).
    (
        "p000_fig1_seek",
        include_str!("../scenarios/p000_fig1_seek.json"),
        0xaf99_6603_8f68_e453,
    ),
];

/// Steps simulated per preset (30 s at 60 Hz).
const STEPS: u32 = 1800;

/// FNV-1a over the f32 bit patterns of every state, every step.
fn trajectory_hash(table: &EtaTable, json: &str) -> u64 {
    let sc = Scenario::from_json(json).expect("preset parses and validates");
    let mut w = sc.world().expect("preset builds a world");
    world_hash(table, &mut w, STEPS)
}

#[test]
#[cfg_attr(target_arch = "wasm32", wasm_bindgen_test::wasm_bindgen_test)]
fn presets_match_golden_hashes() {
    let table = EtaTable::from_bytes(TABLE).expect("committed table loads");
    let got: Vec<(&str, u64)> = PRESETS
        .iter()
        .map(|(name, json, _)| (*name, trajectory_hash(&table, json)))
        .collect();
    for ((name, h), (_, _, golden)) in got.iter().zip(PRESETS) {
        assert_eq!(*h, golden, "preset {name}: got {h:#018x}; all: {got:#x?}");
    }
}

/// The car-like parking preset: a car that cannot turn on the spot loops
/// round a forward Dubins path into a bay (the one plan solved in f64,
/// with libm on both targets). Its η table is the small car-like one of
/// `tests/web_tables.rs` (6 × 12 × 3 × 4 × 4 entries, built here on each
/// target from the same generator): the full table would take minutes to
/// build in wasm, and any table the car uses pins the bits alike.
#[test]
#[cfg_attr(target_arch = "wasm32", wasm_bindgen_test::wasm_bindgen_test)]
fn the_car_like_parking_preset_matches_its_golden_hash() {
    use steering::funnelling::table::spec::TableSpec;
    use steering::funnelling::vehicle_file;
    let car = vehicle_file::reference("car_like").unwrap().vehicle;
    let table = TableSpec::for_vehicle(car, [6, 12, 3, 4, 4])
        .unwrap()
        .generate()
        .unwrap();
    let h = trajectory_hash(&table, include_str!("../scenarios/car_like_parking.json"));
    assert_eq!(h, 0xde60_1823_d0da_f540, "car_like_parking: got {h:#018x}");
}
