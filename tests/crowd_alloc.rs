//! A crowd step does not allocate once buffers have grown (issue 6:
//! "allocation-free per step"): counted with a global allocator that
//! tallies allocations made by this test's own thread.
#![cfg(not(target_arch = "wasm32"))]

use steering::crowd::boid_seek::Seek;
use steering::crowd::config::{CrowdConfig, PaperTest};
use steering::crowd::Crowd;

mod common;

#[global_allocator]
static GLOBAL: common::CountingAlloc = common::CountingAlloc;

#[test]
fn steps_do_not_allocate_after_the_first() {
    for (sep, test) in [(true, PaperTest::IV), (false, PaperTest::II)] {
        let cfg = CrowdConfig::paper(test, Seek::Parker { fraction: 0.1 });
        assert_eq!(cfg.separation, sep);
        let mut crowd = Crowd::new(&cfg).unwrap();
        crowd.step();
        // Long enough for laps to complete (the trace buffers swap).
        let ((), n) = common::allocations(|| crowd.run(2_000));
        assert_eq!(n, 0, "allocations during steps (separation {sep})");
    }
}
