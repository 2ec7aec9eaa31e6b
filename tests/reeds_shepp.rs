//! Our Reeds–Shepp solve ([`steering::base::reeds_shepp`]) against the
//! `reeds_shepp` crate on seeded random queries: the shortest lengths
//! agree within 1e-4·R.
//!
//! The crate's conventions differ from ours, so each query is normalised
//! before it is asked: it takes poses with headings in *degrees* and a
//! *unit* turning radius (no radius argument), so positions are divided by
//! R, headings converted to degrees, and its length (in radii) compared
//! with ours divided by R. Its solve is f64, from the same f32 query.
#![cfg(not(target_arch = "wasm32"))]

mod common;
#[path = "common/peers.rs"]
mod peers;

use common::figures::{record, Figure, Kind, Seeds};

use reeds_shepp_lib::{get_optimal_path, path_length, Pose};
use steering::base::reeds_shepp::{cheapest, shortest_length, ReedsSheppPath};
use steering::base::rng::Rng;

use peers::{dubins_query, locked_version};

/// Queries of the agreement.
const QUERIES: usize = 100_000;
/// Its seed (nothing is tuned on it).
const SEED: u64 = 51;
/// Agreement bound, in turning radii.
const TOLERANCE: f64 = 1e-4;

/// The crate's shortest length, in radii, for our f32 query.
fn peer_length(s: (f32, f32, f32), g: (f32, f32, f32), rho: f32) -> f64 {
    let r = f64::from(rho);
    let pose = |q: (f32, f32, f32)| Pose {
        x: f64::from(q.0) / r,
        y: f64::from(q.1) / r,
        theta_degree: f64::from(q.2).to_degrees(),
    };
    path_length(&get_optimal_path(pose(s), pose(g)).expect("a path always exists"))
}

#[test]
fn our_reeds_shepp_lengths_agree_with_the_reeds_shepp_crate() {
    let mut r = Rng::new(SEED);
    let (mut worst_len, mut worst_path) = (0.0f64, 0.0f64);
    let (mut over_len, mut over_path) = (0usize, 0usize);
    let (mut shorter, mut longer) = (0usize, 0usize);
    let mut worst_query = None;
    for _ in 0..QUERIES {
        // The Dubins peers' queries: half within 4 R, where the words
        // with cusps win.
        let (s, g, rho) = dubins_query(&mut r);
        let theirs = peer_length(s, g, rho);
        let ours = f64::from(shortest_length(s, g, rho)) / f64::from(rho);
        let (c, _) = cheapest(s, g, rho, 0.0, |_, _| true).expect("finite query");
        let path = f64::from(ReedsSheppPath::of(s, &c, rho, 0.0, 1.0).length()) / f64::from(rho);
        let err = (ours - theirs).abs();
        if err > worst_len {
            worst_query = Some((s, g, rho, theirs, ours));
        }
        worst_len = worst_len.max(err);
        worst_path = worst_path.max((path - theirs).abs());
        over_len += usize::from(err > TOLERANCE);
        over_path += usize::from((path - theirs).abs() > TOLERANCE);
        shorter += usize::from(ours < theirs - TOLERANCE);
        longer += usize::from(ours > theirs + TOLERANCE);
    }
    println!("worst query (start, goal, R, the crate's length, ours; in R): {worst_query:?}");
    println!("ours shorter {shorter}, longer {longer}");
    let v = locked_version("reeds_shepp");
    let figs = [
        Figure::new(
            "peers.reeds_shepp.queries",
            &format!("seeded random queries, ours against the reeds_shepp crate {v} (its f64 solve, unit radius and degrees: queries normalised by R): R log-uniform in 0.1–100 m, start in a 200 m square, goal within 4 R (half) or 4–40 R, any headings"),
            QUERIES as f64,
            "queries",
            0,
        ),
        Figure::new(
            "peers.reeds_shepp.length.max_error",
            "largest |ours − reeds_shepp| of the shortest length (`reeds_shepp::shortest_length`, what the car-like study compares paths with), in millionths of R",
            worst_len * 1e6,
            "× 10⁻⁶ R",
            2,
        ),
        Figure::new(
            "peers.reeds_shepp.length.over_tolerance",
            "queries where `reeds_shepp::shortest_length` differs from the crate by more than 1e-4·R",
            over_len as f64,
            "queries",
            0,
        ),
        Figure::new(
            "peers.reeds_shepp.path.max_error",
            "largest |ours − reeds_shepp| of the length of the path a car with a reverse gear follows (`ReedsSheppPath`, f32 per segment), in millionths of R",
            worst_path * 1e6,
            "× 10⁻⁶ R",
            2,
        ),
    ];
    record(
        "tests/reeds_shepp.rs::our_reeds_shepp_lengths_agree_with_the_reeds_shepp_crate",
        "cargo test --release --features cli,counters --test reeds_shepp -- --nocapture",
        Kind::Deterministic,
        &Seeds {
            tuning: vec![],
            report: vec![SEED],
        },
        &figs,
    );
    assert_eq!(over_len, 0, "worst {worst_len} R: {worst_query:?}");
    assert_eq!(over_path, 0, "worst {worst_path} R");
}
