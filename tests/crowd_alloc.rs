//! A crowd step does not allocate once buffers have grown (allocation-free
//! per step, so a frame never waits on the allocator): counted with a global allocator that
//! tallies allocations made by this test's own thread.
#![cfg(not(target_arch = "wasm32"))]

use steering::crowd::boid_seek::Seek;
use steering::crowd::config::{CrowdConfig, PaperTest};
use steering::crowd::world::Crowd;

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

/// The stepping workers' strips: one worker's share, its cut moving every step (the
/// grid of a strip is rebuilt in last step's order), allocates nothing once
/// its buffers have grown to the widest strip (a first cycle of cuts).
#[test]
fn strip_steps_do_not_allocate_once_grown() {
    let cfg = CrowdConfig::paper(PaperTest::IV, Seek::Parker { fraction: 0.1 });
    let mut crowd = Crowd::new(&cfg).unwrap();
    let mut owned = Vec::new();
    let cut = |crowd: &Crowd, k: u32| {
        let xs = crowd.positions().iter().step_by(2);
        let (lo, hi) = xs.fold((f32::MAX, f32::MIN), |(a, b), &x| (a.min(x), b.max(x)));
        lo + (hi - lo) * (0.3 + 0.01 * (k % 40) as f32)
    };
    for k in 0..80 {
        let c = cut(&crowd, k);
        crowd.step_strip(f32::NEG_INFINITY, c, &mut owned);
    }
    let ((), n) = common::allocations(|| {
        for k in 80..480 {
            let c = cut(&crowd, k);
            crowd.step_strip(f32::NEG_INFINITY, c, &mut owned);
        }
    });
    assert_eq!(n, 0, "allocations during strip steps");
}
