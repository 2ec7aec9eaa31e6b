//! The crowd's golden trajectories (tests/common) pin the step's
//! bits, so a cheaper step or one split across workers must give the same
//! boids. Metrics on or off must not change them either.
#![cfg(not(target_arch = "wasm32"))]

mod common;

use common::{crowd_golden_cases, crowd_hash_step, fnv, FNV_OFFSET};
use steering::crowd::world::Crowd;

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

/// The crowd stepped as `k` vertical strips (the page's workers): every
/// strip a full copy loaded with the last complete state, stepping only
/// the boids in its strip; the page's copy records the trace from the
/// complete state. Cuts at quantiles of x, recomputed every `recut` steps.
fn run_strips(cfg: &steering::crowd::config::CrowdConfig, steps: u32, k: usize, recut: u32) -> u64 {
    let mut page = Crowd::new(cfg).unwrap();
    page.set_metrics_enabled(false);
    let mut strips: Vec<Crowd> = (0..k).map(|_| page.clone()).collect();
    let n = page.len();
    let (mut pos, mut vel) = (page.positions().to_vec(), page.velocities().to_vec());
    let mut cuts = vec![f32::NEG_INFINITY; k + 1];
    let mut owned = Vec::new();
    let mut h = FNV_OFFSET;
    for t in 0..steps {
        if t % recut == 0 {
            let mut xs: Vec<f32> = (0..n).map(|i| pos[2 * i]).collect();
            xs.sort_by(f32::total_cmp);
            for (w, c) in cuts.iter_mut().enumerate().skip(1) {
                *c = xs.get(w * n / k).copied().unwrap_or(0.0);
            }
            cuts[k] = f32::INFINITY;
        }
        let (mut npos, mut nvel) = (pos.clone(), vel.clone());
        for (w, s) in strips.iter_mut().enumerate() {
            s.set_state(&pos, &vel, u64::from(t)).unwrap();
            s.step_strip(cuts[w], cuts[w + 1], &mut owned);
            for &i in &owned {
                let i = i as usize;
                npos[2 * i..2 * i + 2].copy_from_slice(&s.positions()[2 * i..2 * i + 2]);
                nvel[2 * i..2 * i + 2].copy_from_slice(&s.velocities()[2 * i..2 * i + 2]);
            }
        }
        (pos, vel) = (npos, nvel);
        let tr = page.traced_boid();
        page.observe_step(glam::Vec2::new(pos[2 * tr], pos[2 * tr + 1]));
        crowd_hash_step(&mut h, &pos, &vel);
    }
    page.set_state(&pos, &vel, u64::from(steps)).unwrap();
    fnv(&mut h, page.trace());
    h
}

#[test]
fn crowd_split_into_strips_gives_the_golden_bits() {
    let mut bad = Vec::new();
    for (name, cfg, steps, golden) in crowd_golden_cases() {
        for (k, recut) in [(1, 1000), (2, 1), (3, 7), (5, 50)] {
            let h = run_strips(&cfg, steps, k, recut);
            if h != golden {
                bad.push(format!(
                    "{name} in {k} strips: {h:#018x}, golden {golden:#018x}"
                ));
            }
        }
    }
    assert!(bad.is_empty(), "{bad:#?}");
}

#[test]
fn a_bad_state_length_is_refused_and_changes_nothing() {
    let (_, cfg, _, _) = &crowd_golden_cases()[0];
    let mut c = Crowd::new(cfg).unwrap();
    let before = c.positions().to_vec();
    let e = c
        .set_state(&[0.0; 4], c.velocities().to_vec().as_slice(), 9)
        .unwrap_err();
    assert!(e.to_string().contains("positions length"), "{e}");
    assert_eq!(c.positions(), &before[..]);
    assert_eq!(c.time(), 0);
}
