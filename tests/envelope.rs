//! The envelope study on a small held-out sample: seed 3, which
//! neither tuning (seed 1) nor the reported figures (seed 2) use. Locks
//! what every controller must keep over the whole operating envelope.
#![cfg(not(target_arch = "wasm32"))]

use steering::base::vehicle::VehicleParams;
use steering::studies::envelope::{report::summarise, variants, EnvelopeStudy, GoalKind};

mod common;
use common::table;

#[test]
fn every_variant_stays_finite_and_within_limits_and_standard_finishes() {
    let study = EnvelopeStudy {
        seed: 3,
        n_static: 300,
        n_moving: 60,
        n_chain: 60,
        ..Default::default()
    };
    let p = VehicleParams::default();
    let report = study.run_all(&table(), &p, &variants());
    for v in &report.variants {
        for g in &v.groups {
            let s = summarise(&g.runs);
            assert_eq!(
                (s.nan, s.violations),
                (0, 0),
                "{} {:?}: {s:?}",
                v.name,
                g.kind
            );
        }
    }
    let std = &report.variants[0];
    assert_eq!(std.name, "standard");
    for kind in GoalKind::ALL {
        let s = summarise(std.runs(kind));
        assert!(s.finished >= 0.99, "standard {kind:?}: {s:?}");
    }
}

/// The envelope's targets, locked on seed 3 (1,000 static runs: the cells
/// are too small here to judge one by one, so the bands are judged whole;
/// `steer envelope --n 10000 --seed 2` reports every cell).
#[test]
fn default_controllers_meet_the_envelope_targets_on_the_test_seed() {
    use steering::studies::envelope::BANDS;
    let study = EnvelopeStudy {
        seed: 3,
        n_static: 1000,
        n_moving: 200,
        n_chain: 200,
        ..Default::default()
    };
    let p = VehicleParams::default();
    let vs: Vec<_> = variants()
        .into_iter()
        .filter(|v| v.name == "standard" || v.name == "relaxed")
        .collect();
    let report = study.run_all(&table(), &p, &vs);
    let (std, rel) = (&report.variants[0], &report.variants[1]);
    let runs = std.runs(GoalKind::Static);
    let far = BANDS[BANDS.len() - 1].0;
    let share = |f: &dyn Fn(&&steering::studies::envelope::RunRecord) -> bool| {
        summarise(runs.iter().filter(f)).oriented
    };
    let far_wide = share(&|r| r.d0 >= far && r.eps_tol_deg > 3.0);
    let far_tight = share(&|r| r.d0 >= far && r.eps_tol_deg < 3.0);
    let all = summarise(runs);
    println!(
        "D ≥ 5 m: ε_tol ≥ 5° {far_wide}, 2° {far_tight}; all D {}",
        all.oriented
    );
    assert!(far_wide >= 0.95, "{far_wide}");
    assert!(far_tight >= 0.85, "{far_tight}");
    assert!(all.oriented >= 0.80, "{all:?}");
    assert!(all.length_ratio.0 <= 1.15, "{all:?}");
    let r = summarise(rel.runs(GoalKind::Static));
    assert!(r.reach >= 0.995 && r.orbits == 0, "{r:?}");
    // Compared where both funnel: closer than the short-range reach the
    // standard controller may turn first
    // (steering::funnelling::short_range), the relaxed one does not.
    let reach = steering::funnelling::short_range::FAR;
    let rel_far = summarise(rel.runs(GoalKind::Static).iter().filter(|r| r.d0 >= reach));
    let std_far = summarise(runs.iter().filter(|r| r.d0 >= reach));
    assert!(
        rel_far.oriented >= std_far.oriented,
        "relaxed {rel_far:?} vs standard {std_far:?}"
    );
    for v in [std, rel] {
        for kind in [GoalKind::Moving, GoalKind::Chain] {
            let s = summarise(v.runs(kind));
            assert!(s.finished >= 0.99, "{} {kind:?}: {s:?}", v.name);
        }
        // End_of_Steering inside both tolerances for every goal, static,
        // chained or moving (a moving goal's position is never latched);
        // halting runs at rest inside both.
        for kind in GoalKind::ALL {
            let s = summarise(v.runs(kind));
            assert!(s.eos_ok >= 0.995, "{} {kind:?}: {s:?}", v.name);
            if kind != GoalKind::Moving {
                assert!(s.rest_ok >= 1.0, "{} {kind:?}: {s:?}", v.name);
            }
        }
        // Led to where they will be, moving goals are entered oriented
        // about as often as static ones.
        let m = summarise(v.runs(GoalKind::Moving));
        assert!(m.oriented >= 0.8, "{} moving: {m:?}", v.name);
    }
}
