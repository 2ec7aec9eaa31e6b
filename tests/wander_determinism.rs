//! Same seed, same trajectory — natively and in WebAssembly (paper 004 §7:
//! determinism for replay and networked games; DESIGN §8).
//!
//! The golden values hash the raw f32 bits of every pose of every preset
//! variant. The toolkit uses only IEEE-exact arithmetic and its own
//! polynomial trig (`steering::trig`), so the bits — not just rounded values —
//! must agree on every target. This file has no proptest so it also runs as
//! a wasm-bindgen test:
//! `CARGO_TARGET_WASM32_UNKNOWN_UNKNOWN_RUNNER=wasm-bindgen-test-runner cargo test --target wasm32-unknown-unknown --test wander_determinism`.

#[cfg(target_arch = "wasm32")]
wasm_bindgen_test::wasm_bindgen_test_configure!(run_in_browser);

use steering::wander::{WanderPreset, Wanderer};

const PRESETS: [(&str, &str); 8] = [
    ("control", include_str!("../scenarios/wander/control.json")),
    (
        "distributions",
        include_str!("../scenarios/wander/distributions.json"),
    ),
    ("fields", include_str!("../scenarios/wander/fields.json")),
    (
        "time-functions",
        include_str!("../scenarios/wander/time-functions.json"),
    ),
    ("timed", include_str!("../scenarios/wander/timed.json")),
    ("markov", include_str!("../scenarios/wander/markov.json")),
    ("paths", include_str!("../scenarios/wander/paths.json")),
    (
        "composed",
        include_str!("../scenarios/wander/composed.json"),
    ),
];

/// FNV-1a over the f32 bit patterns.
fn fnv(hash: &mut u64, values: &[f32]) {
    for v in values {
        for b in v.to_bits().to_le_bytes() {
            *hash ^= u64::from(b);
            *hash = hash.wrapping_mul(0x0000_0100_0000_01b3);
        }
    }
}

/// Hash of every variant's trace after the preset's suggested steps.
fn preset_hash(json: &str) -> u64 {
    let preset = WanderPreset::from_json(json).expect("preset parses and validates");
    let mut h = 0xcbf2_9ce4_8422_2325;
    for v in &preset.variants {
        let mut w = Wanderer::new(v.config.clone()).expect("variant builds");
        w.run(preset.steps);
        let trace = w.trace();
        assert_eq!(trace.len(), 3 * (preset.steps as usize + 1));
        assert!(trace.iter().all(|x| x.is_finite()), "{}", v.label);
        fnv(&mut h, &trace);
    }
    h
}

/// Golden hashes, one per preset file (recorded natively, checked in wasm).
const GOLDEN: [(&str, u64); 8] = [
    ("control", 0xa0ca_8f10_df0b_3566),
    ("distributions", 0xfc4a_d28a_96ea_0ecb),
    ("fields", 0xd388_8293_835d_0d35),
    ("time-functions", 0x6d73_78d6_c8fc_744f),
    ("timed", 0xcb03_e86b_eccc_24a2),
    ("markov", 0x7cb6_c4f8_9c41_4986),
    ("paths", 0xdca7_270c_11a5_ae3b),
    ("composed", 0xd2b8_71aa_0185_462c),
];

#[test]
#[cfg_attr(target_arch = "wasm32", wasm_bindgen_test::wasm_bindgen_test)]
fn presets_match_golden_hashes() {
    let mut got = Vec::new();
    for (name, json) in PRESETS {
        got.push((name, preset_hash(json)));
    }
    for ((name, h), (gname, g)) in got.iter().zip(GOLDEN) {
        assert_eq!(*name, gname);
        assert_eq!(*h, g, "preset {name}: got {h:#018x}; all: {got:#x?}");
    }
}

#[test]
#[cfg_attr(target_arch = "wasm32", wasm_bindgen_test::wasm_bindgen_test)]
fn same_seed_same_trajectory_other_seed_differs() {
    let json = r#"{"seed": 7, "control": {"mode": "acceleration", "max_acceleration_deg": 1,
        "max_velocity_deg": 10}, "source": {"kind": "random", "distribution":
        {"kind": "perlin", "period": 30}}, "hold": {"kind": "random", "min": 1, "max": 5}}"#;
    let mut a = Wanderer::from_json(json).unwrap();
    let mut b = Wanderer::from_json(json).unwrap();
    a.run(500);
    b.run(500);
    assert_eq!(a.trace(), b.trace());
    // Reset replays exactly.
    let first = a.trace();
    a.reset();
    a.run(500);
    assert_eq!(a.trace(), first);
    let mut c = Wanderer::from_json(&json.replace("\"seed\": 7", "\"seed\": 8")).unwrap();
    c.run(500);
    assert_ne!(c.trace(), first);
}

#[test]
#[cfg_attr(target_arch = "wasm32", wasm_bindgen_test::wasm_bindgen_test)]
fn trace_ring_keeps_the_newest_poses_in_order() {
    let json = r#"{"seed": 1, "trace_capacity": 10, "control": {"mode": "velocity",
        "max_velocity_deg": 5}, "source": {"kind": "random", "distribution": {"kind": "uniform"}}}"#;
    let mut w = Wanderer::from_json(json).unwrap();
    let mut poses = vec![w.pose()];
    for _ in 0..25 {
        w.step();
        poses.push(w.pose());
    }
    assert_eq!(w.trace_len(), 10);
    let flat: Vec<f32> = poses[poses.len() - 10..]
        .iter()
        .flatten()
        .copied()
        .collect();
    assert_eq!(w.trace(), flat);
    let mut small = [0.0f32; 9];
    assert_eq!(w.trace_into(&mut small), 3);
    assert_eq!(&small[..], &flat[..9]);
}
