#![cfg(not(target_arch = "wasm32"))]
//! `Wanderer::step` never allocates (project convention: allocation-free
//! per step), checked with a counting global allocator over every preset
//! variant, including the trace ring wrapping round.

use std::alloc::{GlobalAlloc, Layout, System};
use std::sync::atomic::{AtomicUsize, Ordering};

use steering::wander::{WanderPreset, Wanderer};

struct Counting;

static ALLOCS: AtomicUsize = AtomicUsize::new(0);

// SAFETY: forwards to the system allocator, only counting calls.
#[allow(unsafe_code)]
unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        ALLOCS.fetch_add(1, Ordering::Relaxed);
        // SAFETY: same contract as the caller's.
        unsafe { System.alloc(layout) }
    }
    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        // SAFETY: same contract as the caller's.
        unsafe { System.dealloc(ptr, layout) }
    }
    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        ALLOCS.fetch_add(1, Ordering::Relaxed);
        // SAFETY: same contract as the caller's.
        unsafe { System.realloc(ptr, layout, new_size) }
    }
}

#[global_allocator]
static GLOBAL: Counting = Counting;

#[test]
fn steps_do_not_allocate() {
    let presets = [
        include_str!("../scenarios/wander/control.json"),
        include_str!("../scenarios/wander/distributions.json"),
        include_str!("../scenarios/wander/fields.json"),
        include_str!("../scenarios/wander/time-functions.json"),
        include_str!("../scenarios/wander/timed.json"),
        include_str!("../scenarios/wander/markov.json"),
        include_str!("../scenarios/wander/paths.json"),
        include_str!("../scenarios/wander/composed.json"),
    ];
    for json in presets {
        let preset = WanderPreset::from_json(json).unwrap();
        for v in &preset.variants {
            let mut config = v.config.clone();
            config.trace_capacity = 100;
            let mut w = Wanderer::new(config).unwrap();
            let before = ALLOCS.load(Ordering::Relaxed);
            w.run(500);
            let after = ALLOCS.load(Ordering::Relaxed);
            assert_eq!(
                after,
                before,
                "{} allocated {} times",
                v.label,
                after - before
            );
        }
    }
}
