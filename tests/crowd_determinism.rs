//! Issue 17: the crowd's golden trajectories (tests/common) pin the step's
//! bits, so a cheaper step or one split across workers must give the same
//! boids. Metrics on or off must not change them either.
#![cfg(not(target_arch = "wasm32"))]

mod common;

use common::{crowd_golden_cases, crowd_hash_step, fnv, FNV_OFFSET};
use steering::crowd::Crowd;

fn run(cfg: &steering::crowd::config::CrowdConfig, steps: u32, metrics: bool) -> u64 {
    let mut c = Crowd::new(cfg).unwrap();
    c.set_metrics_enabled(metrics);
    let mut h = FNV_OFFSET;
    for _ in 0..steps {
        c.step();
        crowd_hash_step(&mut h, c.positions(), c.velocities());
    }
    fnv(&mut h, c.trace());
    h
}

#[test]
fn crowd_golden_hashes_hold_with_metrics_on_and_off() {
    let mut bad = Vec::new();
    for (name, cfg, steps, golden) in crowd_golden_cases() {
        let on = run(&cfg, steps, true);
        let off = run(&cfg, steps, false);
        println!("{name}: {on:#018x} (metrics off {off:#018x})");
        if on != golden || off != golden {
            bad.push(format!(
                "{name}: {on:#018x} / {off:#018x}, golden {golden:#018x}"
            ));
        }
    }
    assert!(bad.is_empty(), "{bad:#?}");
}
