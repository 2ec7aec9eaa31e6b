#![cfg(not(target_arch = "wasm32"))]
//! `Wanderer::step` never allocates (project convention: allocation-free
//! per step), checked with a counting global allocator over every preset
//! variant, including the trace ring wrapping round.

use steering::wander::{pipeline::WanderPreset, pipeline::Wanderer};

mod common;

#[global_allocator]
static GLOBAL: common::CountingAlloc = common::CountingAlloc;

#[test]
fn steps_do_not_allocate() {
    let (_, n) = common::allocations(|| vec![0u8; 64]);
    assert_eq!(n, 1, "the counting allocator is installed and counts");
    for (_, json, _) in common::WANDER_PRESETS {
        let preset = WanderPreset::from_json(json).unwrap();
        for v in &preset.variants {
            let mut config = v.config.clone();
            config.trace_capacity = 100;
            let mut w = Wanderer::new(config).unwrap();
            let ((), n) = common::allocations(|| w.run(500));
            assert_eq!(n, 0, "{} allocated {n} times", v.label);
        }
    }
}
