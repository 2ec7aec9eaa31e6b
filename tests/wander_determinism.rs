//! Same seed, same trajectory — natively and in WebAssembly (paper 004 §7:
//! determinism for replay and networked games; docs/DESIGN.md §5).
//!
//! The golden values hash the raw f32 bits of every pose of every preset
//! variant. The toolkit uses only IEEE-exact arithmetic and its own
//! polynomial trig (`steering::base::trig`), so the bits — not just rounded values —
//! must agree on every target. This file has no proptest so it also runs as
//! a wasm-bindgen test:
//! `CARGO_TARGET_WASM32_UNKNOWN_UNKNOWN_RUNNER=wasm-bindgen-test-runner cargo test --target wasm32-unknown-unknown --test wander_determinism`.

#[cfg(target_arch = "wasm32")]
wasm_bindgen_test::wasm_bindgen_test_configure!(run_in_browser);

use steering::wander::{pipeline::WanderPreset, pipeline::Wanderer};

mod common;
use common::{fnv, FNV_OFFSET, WANDER_PRESETS};

/// Hash of every variant's trace after the preset's suggested steps.
fn preset_hash(json: &str) -> u64 {
    let preset = WanderPreset::from_json(json).expect("preset parses and validates");
    let mut h = FNV_OFFSET;
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

#[test]
#[cfg_attr(target_arch = "wasm32", wasm_bindgen_test::wasm_bindgen_test)]
fn presets_match_golden_hashes() {
    // The golden values are in `tests/common/mod.rs` (`WANDER_PRESETS`),
    // shared with the same check through the bindings (`tests/web_gallery.rs`).
    let got: Vec<(&str, u64)> = WANDER_PRESETS
        .iter()
        .map(|(name, json, _)| (*name, preset_hash(json)))
        .collect();
    for ((name, h), (_, _, golden)) in got.iter().zip(WANDER_PRESETS) {
        assert_eq!(*h, golden, "preset {name}: got {h:#018x}; all: {got:#x?}");
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
