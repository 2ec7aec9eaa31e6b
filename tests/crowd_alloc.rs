//! A crowd step does not allocate once buffers have grown (issue 6:
//! "allocation-free per step"): counted with a global allocator that
//! tallies allocations made by this test's own thread.
#![cfg(not(target_arch = "wasm32"))]
#![allow(unsafe_code)]

use std::alloc::{GlobalAlloc, Layout, System};
use std::cell::Cell;
use std::sync::atomic::{AtomicUsize, Ordering};

use steering::crowd::boid_seek::Seek;
use steering::crowd::config::{CrowdConfig, PaperTest};
use steering::crowd::Crowd;

struct Counting;

static ALLOCS: AtomicUsize = AtomicUsize::new(0);
thread_local! {
    static COUNTING: Cell<bool> = const { Cell::new(false) };
}

// SAFETY: forwards every call unchanged to the system allocator.
unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        if COUNTING.with(Cell::get) {
            ALLOCS.fetch_add(1, Ordering::Relaxed);
        }
        unsafe { System.alloc(layout) }
    }
    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        unsafe { System.dealloc(ptr, layout) }
    }
    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        if COUNTING.with(Cell::get) {
            ALLOCS.fetch_add(1, Ordering::Relaxed);
        }
        unsafe { System.realloc(ptr, layout, new_size) }
    }
}

#[global_allocator]
static GLOBAL: Counting = Counting;

#[test]
fn steps_do_not_allocate_after_the_first() {
    for (sep, test) in [(true, PaperTest::IV), (false, PaperTest::II)] {
        let cfg = CrowdConfig::paper(test, Seek::Parker { fraction: 0.1 });
        assert_eq!(cfg.separation, sep);
        let mut crowd = Crowd::new(&cfg).unwrap();
        crowd.step();
        COUNTING.with(|c| c.set(true));
        // Long enough for laps to complete (the trace buffers swap).
        crowd.run(2_000);
        COUNTING.with(|c| c.set(false));
        assert_eq!(
            ALLOCS.swap(0, Ordering::Relaxed),
            0,
            "allocations during steps (separation {sep})"
        );
    }
}
