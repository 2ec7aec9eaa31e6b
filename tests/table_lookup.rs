//! Invariants of the constant-time lookup (`grid.rs`, `EtaTable::lookup`),
//! by property tests: the bucket search agrees with a binary search on any
//! admissible axis, and a lookup of any finite query is finite, in range
//! and flagged when clamped.
#![cfg(not(target_arch = "wasm32"))]

use proptest::prelude::*;
use steering::funnelling::table::grid::Axis;
use steering::funnelling::table::lookup::EtaTable;

fn committed() -> &'static EtaTable {
    static TABLE: std::sync::OnceLock<EtaTable> = std::sync::OnceLock::new();
    TABLE.get_or_init(|| {
        EtaTable::from_bytes(
            &std::fs::read(concat!(env!("CARGO_MANIFEST_DIR"), "/tables/eta.bin")).unwrap(),
        )
        .unwrap()
    })
}

/// A strictly increasing axis from a start and positive gaps (as the
/// loader admits: no gap below 1e-6 of the span).
fn axis_from(start: f32, gaps: &[f32]) -> Vec<f32> {
    let mut x = vec![start];
    for g in gaps {
        x.push(x[x.len() - 1] + g);
    }
    x
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(500))]

    #[test]
    fn bucket_search_agrees_with_binary_search(
        start in -100.0f32..100.0,
        gaps in proptest::collection::vec(1e-3f32..50.0, 1..40),
        probes in proptest::collection::vec(0.0f32..1.0, 50),
    ) {
        let x = axis_from(start, &gaps);
        let a = Axis::new(&x, false);
        let (lo, hi) = (x[0], x[x.len() - 1]);
        for u in probes {
            let v = lo + u * (hi - lo);
            let mut clamped = false;
            let p = a.locate(v, &mut clamped);
            let expect = x.partition_point(|&s| s <= v).saturating_sub(1).min(x.len() - 2);
            prop_assert_eq!(p.i0 as usize, expect, "v {} on {:?}", v, x);
            prop_assert_eq!(p.i1, p.i0 + 1);
            prop_assert!((0.0..=1.0).contains(&p.t));
            prop_assert!(!clamped);
        }
        // Outside the range: clamped and flagged.
        let mut clamped = false;
        let p = a.locate(hi + 1.0, &mut clamped);
        prop_assert!(clamped && p.t == 1.0 && p.i1 as usize == x.len() - 1);
    }

    #[test]
    fn any_finite_query_gives_a_finite_lookup(
        d in -5.0f32..60.0,
        alpha in -10.0f32..10.0,
        omega in -3.0f32..3.0,
        v in -1.0f32..3.0,
        v_d in 0.0f32..3.0,
    ) {
        let t = committed();
        let lk = t.lookup(d, alpha, omega, v, v_d);
        prop_assert!(lk.eta.is_finite() && lk.eta.abs() <= std::f32::consts::PI + 1e-6);
        prop_assert!(lk.v_dt.is_finite() && lk.v_dt >= 0.0 && lk.v_dt <= v_d);
        let (dmin, dmax) = (t.distances()[0], *t.distances().last().unwrap());
        if !(dmin..=dmax).contains(&d) || !(0.0..=2.0).contains(&v) {
            prop_assert!(lk.clamped);
        }
        let b = t.straight_abs_eta_at(&lk, alpha).unwrap_or(0.0);
        prop_assert!(b.is_finite() && (0.0..=std::f32::consts::PI + 1e-6).contains(&b));
    }
}

#[test]
fn a_query_on_a_sample_returns_the_sample() {
    let t = committed();
    let idx = [5, 20, 2, 4, 6];
    let (eta, _, flags) = t.entry(idx);
    assert!(flags & 1 != 0, "pick a reachable sample");
    let x: Vec<f32> = (0..5).map(|k| t.axis(k)[idx[k]]).collect();
    let omega = x[2] * steering::base::vehicle::VehicleParams::default().omega_limit(x[3]);
    let lk = t.lookup(x[0], x[1], omega, x[3], x[4]);
    assert!(lk.reachable);
    assert!((lk.eta - eta).abs() < 1e-5, "{} vs {eta}", lk.eta);
}
