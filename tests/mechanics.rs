//! The η table lookup's two decisions that no study pins exactly, on a
//! small synthetic table whose entries the test chooses (paper 000 Fig. 4,
//! first half; `table/lookup.rs`):
//!
//! - **reachability** is the weighted vote of the 32 samples around a
//!   query: reachable iff the weights of the reachable ones add up to at
//!   least ½ (our smoothed reading of the paper's "closest element");
//! - **the fallback speed** where it is not reachable is
//!   `v_dt = Σ w·(r·v_d + (1 − r)·v_fallback)`, the reachable corners
//!   voting for the queried speed and the others for their stored
//!   "closest desired speed ensuring reachability", capped at `v_d`.
//!
//! The studies that use the committed table moved by several points when
//! either was changed (a vote at ¼, the fallback speed without the
//! reachable corners' `v_d`) and still passed; here each decision is
//! asserted exactly, with k = 0..32 of the corners reachable.

use core::f32::consts::PI;

use steering::base::rng::Rng;
use steering::base::vehicle::VehicleParams;
use steering::funnelling::table::format::{BuildParams, AXES, FLAG_ETA_VALID, FLAG_REACHABLE};
use steering::funnelling::table::lookup::EtaTable;

/// Two samples per axis (three on the periodic α axis, the loader's
/// minimum), spaced by powers of two so that a query half-way between
/// them gets the weight ½ exactly on every axis: each of the 32 corners
/// then weighs exactly 1/32, and a sum of k of them is exactly k/32.
const AXIS_SAMPLES: [&[f32]; AXES] = [
    &[1.0, 3.0],       // D, m
    &[-2.0, 0.0, 2.0], // α, rad (periodic)
    &[-1.0, 1.0],      // ω as a fraction of its limit
    &[0.5, 1.5],       // v_c, m/s
    &[1.0, 2.0],       // v_d, m/s
];

/// The query at the centre of the 32 corners: D 2 m, α 1 rad, ω 0,
/// v_c 1 m/s, v_d 1.5 m/s.
const QUERY: (f32, f32, f32, f32, f32) = (2.0, 1.0, 0.0, 1.0, 1.5);

/// Reachable corners store this η.
const ETA: f32 = 0.3;

/// The grid index (per axis) of corner `c` (bits: D, α, ω, v_c, v_d) of
/// [`QUERY`]: on the α axis the two samples round 1 rad are 0 and 2 rad.
fn corner(c: usize) -> [usize; AXES] {
    [c >> 4 & 1, 1 + (c >> 3 & 1), c >> 2 & 1, c >> 1 & 1, c & 1]
}

/// Corner `c`'s stored fallback speed: distinct per corner, below every
/// sampled desired speed.
fn fallback(c: usize) -> f32 {
    0.05 + 0.02 * c as f32
}

/// The synthetic table: corners in `reachable` reachable at their desired
/// speed with η = [`ETA`]; the other corners unreachable, with
/// [`fallback`] speeds and a fallback η; every other entry (the α sample
/// at −2 rad, outside the query's corners) unreachable with nothing stored.
fn table(reachable: &[usize]) -> EtaTable {
    let counts = AXIS_SAMPLES.map(<[f32]>::len);
    let n: usize = counts.iter().product();
    let mut strides = [1usize; AXES];
    for k in (0..AXES - 1).rev() {
        strides[k] = strides[k + 1] * counts[k + 1];
    }
    let (mut eta, mut v_fb, mut flags) = (vec![0.0f32; n], vec![0.0f32; n], vec![0u8; n]);
    for c in 0..32 {
        let i: usize = corner(c).iter().zip(&strides).map(|(a, s)| a * s).sum();
        if reachable.contains(&c) {
            eta[i] = ETA;
            flags[i] = FLAG_REACHABLE | FLAG_ETA_VALID;
        } else {
            // The η of the fallback speed (another speed's prediction).
            eta[i] = -1.0;
            v_fb[i] = fallback(c);
            flags[i] = FLAG_ETA_VALID;
        }
    }
    let params = BuildParams {
        vehicle: VehicleParams::default(),
        reach_radius: 0.25,
        orbit_turns: 2.0,
        max_time: 30.0,
    };
    EtaTable::from_parts(params, AXIS_SAMPLES.map(<[f32]>::to_vec), eta, v_fb, flags)
        .expect("a valid synthetic table")
}

/// Subsets of the 32 corners with k members, k = 0..=32: the first k in
/// index order, the last k, and three seeded random draws.
fn subsets() -> Vec<Vec<usize>> {
    let mut rng = Rng::new(45);
    let mut out = Vec::new();
    for k in 0..=32 {
        out.push((0..k).collect());
        out.push((32 - k..32).collect());
        for _ in 0..3 {
            let mut all: Vec<usize> = (0..32).collect();
            for i in (1..32).rev() {
                all.swap(i, rng.below(i as u32 + 1) as usize);
            }
            all.truncate(k);
            out.push(all);
        }
    }
    out
}

#[test]
fn synthetic_query_sits_at_the_centre_of_its_32_corners() {
    // Every corner weighs 1/32: with one reachable corner the vote is
    // exactly 1/32 of the way (seen through the fallback speed, below),
    // and with all 32 reachable the blended η is the stored one.
    let (d, a, w, v, vd) = QUERY;
    let lk = table(&(0..32).collect::<Vec<_>>()).lookup(d, a, w, v, vd);
    assert!(lk.reachable && lk.eta_valid && !lk.clamped, "{lk:?}");
    assert!((lk.eta - ETA).abs() < 1e-6, "{lk:?}");
    assert_eq!(lk.v_dt, vd);
    // The sample at α = −2 rad is not one of the corners: marking it
    // reachable everywhere changes nothing.
    assert_eq!(corner(0)[1], 1);
    assert_eq!(corner(8)[1], 2);
}

#[test]
fn reachable_iff_the_weighted_vote_is_at_least_one_half() {
    let (d, a, w, v, vd) = QUERY;
    for set in subsets() {
        let k = set.len();
        let lk = table(&set).lookup(d, a, w, v, vd);
        // 16 of 32 corners is exactly ½: reachable; 15 is not.
        assert_eq!(
            lk.reachable,
            k >= 16,
            "{k} of 32 corners reachable ({set:?}): vote {k}/32, lookup says reachable = {}",
            lk.reachable
        );
        if lk.reachable {
            // η blends the reachable corners alone.
            assert!((lk.eta - ETA).abs() < 1e-6, "k {k}: η {}", lk.eta);
        }
    }
}

#[test]
fn reachability_vote_weighs_corners_by_their_distance_to_the_query() {
    // Off the centre the weights differ: on the distance axis at a quarter
    // of the way (D 1.5 m) and on a sample on every other axis, only two
    // corners weigh anything, ¾ (D 1 m) and ¼ (D 3 m).
    let near = 0b00000; // D 1 m, α 0, ω −1, v_c 0.5, v_d 1
    let far = 0b10000; // D 3 m, same
    let q = |t: &EtaTable| {
        t.lookup(
            1.5,
            0.0,
            -VehicleParams::default().omega_limit(0.5),
            0.5,
            1.0,
        )
    };
    let only_far = q(&table(&[far]));
    let only_near = q(&table(&[near]));
    assert!(!only_far.clamped && !only_near.clamped);
    assert!(
        !only_far.reachable,
        "a ¼ vote is not reachable: {only_far:?}"
    );
    assert!(only_near.reachable, "a ¾ vote is reachable: {only_near:?}");
    // At D 2 m both weigh ½: either one alone is exactly the threshold.
    let q2 = |t: &EtaTable| {
        t.lookup(
            2.0,
            0.0,
            -VehicleParams::default().omega_limit(0.5),
            0.5,
            1.0,
        )
    };
    assert!(q2(&table(&[far])).reachable && q2(&table(&[near])).reachable);
    assert!(!q2(&table(&[])).reachable);
}

#[test]
fn fallback_speed_blends_the_queried_speed_and_the_stored_fallbacks() {
    let (d, a, w, v, vd) = QUERY;
    for set in subsets() {
        let k = set.len();
        if k >= 16 {
            continue; // reachable: v_dt is the query's (asserted above)
        }
        let lk = table(&set).lookup(d, a, w, v, vd);
        assert!(!lk.reachable);
        // v_dt = (k/32)·v_d + Σ_unreachable v_fallback / 32, capped at v_d.
        let stored: f32 = (0..32)
            .filter(|c| !set.contains(c))
            .map(fallback)
            .sum::<f32>()
            / 32.0;
        let want = (k as f32 / 32.0 * vd + stored).min(vd);
        assert!(
            (lk.v_dt - want).abs() < 1e-5,
            "{k} of 32 reachable ({set:?}): v_dt {} against (k/32)·v_d + Σ v_fallback/32 = {:.5} + {:.5} = {want}",
            lk.v_dt,
            k as f32 / 32.0 * vd,
            stored
        );
        // η at v_dt (a second blend): the reachable corners that weigh
        // anything at v_dt if there are any (v_d 1 m/s with weight 1 − t,
        // 2 m/s with weight t, v_dt clamped to the axis), else the
        // fallback η (−1) of all of them.
        let t = (lk.v_dt - 1.0).clamp(0.0, 1.0);
        let weighed = set
            .iter()
            .any(|c| if c & 1 == 0 { t < 1.0 } else { t > 0.0 });
        let want_eta = if weighed { ETA } else { -1.0 };
        assert!(
            lk.eta_valid && (lk.eta - want_eta).abs() < 1e-5,
            "k {k}: {lk:?}"
        );
    }
    // Nothing reachable anywhere near and nothing stored: v_dt 0, no η.
    let empty = {
        let mut t = table(&[]);
        // Rebuilt with zero fallback speeds and no valid η.
        let counts = AXIS_SAMPLES.map(<[f32]>::len);
        let n: usize = counts.iter().product();
        t = EtaTable::from_parts(
            *t.params(),
            AXIS_SAMPLES.map(<[f32]>::to_vec),
            vec![0.0; n],
            vec![0.0; n],
            vec![0; n],
        )
        .unwrap();
        t
    };
    let lk = empty.lookup(d, a, w, v, vd);
    assert!(!lk.reachable && lk.v_dt == 0.0 && !lk.eta_valid, "{lk:?}");
    assert!(lk.eta.abs() <= PI);
}
