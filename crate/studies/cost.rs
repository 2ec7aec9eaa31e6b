//! The inputs of the cost measurements, one definition for the two that
//! read them: the benchmarks time the updates over these cases
//! (`benches/core.rs`, `benches/relaxed.rs`) and the counted cost claims
//! count table reads over the very same cases (`tests/fidelity_cost.rs`),
//! so a count and a time always describe the same updates.
//!
//! Paper 000 §7 times one update to a far (30 units) and a near target;
//! paper 001 Table 1 bins updates by distance to the region and by the
//! offset of β from the bearing, at a small and a large tolerance. The
//! claims' sentences are here too, so that the counted record and the
//! timed one of a claim quote it alike.

use glam::Vec2;

use crate::base::rng::Rng;
use crate::base::trig::unit;
use crate::base::vehicle::{VehicleParams, VehicleState};
use crate::funnelling::goal::Goal;

/// Paper 000 §7's cost claim, far against near targets.
pub const SEC7_FAR_CLAIM: &str =
    "the update costs less for a distant target (30 units): 9.5 against 12.5 µs (0.76)";
/// Paper 000 §7's far / near update cost: 9.5 / 12.5 µs.
pub const SEC7_FAR_NEAR: f64 = 9.5 / 12.5;

/// Axis counts of a 43,200-entry table, paper 000 §3's size (as
/// `tests/fidelity.rs`'s `paper_size_table`).
pub const PAPER_SIZE_COUNTS: [usize; 5] = [10, 24, 5, 4, 6];

/// Paper 001 Table 1's small tolerances (m, degrees).
pub const TABLE1_SMALL: (f32, f32) = (0.1, 1.0);
/// Paper 001 Table 1's large tolerances (m, degrees).
pub const TABLE1_LARGE: (f32, f32) = (2.5, 15.0);
/// Paper 001 Table 1's claim at small tolerances.
pub const TABLE1_SMALL_CLAIM: &str =
    "standard and relaxed funnelling costs do not differ significantly for small tolerances (0.1 m, 1°)";
/// Paper 001 Table 1's claim at large tolerances.
pub const TABLE1_LARGE_CLAIM: &str =
    "relaxed funnelling is on average 50 % cheaper than standard for large tolerances (2.5 m, 15°)";

/// Paper 001 Table 1's distance bins (m).
pub const TABLE1_DISTANCES: [f32; 4] = [1.5, 4.0, 10.0, 25.0];
/// Paper 001 Table 1's offsets of β from the bearing (degrees).
pub const TABLE1_BETAS_DEG: [f32; 4] = [0.0, 60.0, 120.0, 180.0];

/// 1,024 random oriented goals at distances in `[lo, hi]` m from the
/// origin (seed 17): near is 1–4 m, far 20–30 m in the benches.
#[must_use]
pub fn oriented_goals(lo: f32, hi: f32) -> Vec<Goal> {
    let mut r = Rng::new(17);
    (0..1024)
        .map(|_| Goal {
            pos: unit(r.range(-3.1, 3.1)) * r.range(lo, hi),
            beta: r.range(-3.1, 3.1),
            ..Default::default()
        })
        .collect()
}

/// 1,024 random admissible start states at the origin (seed 23) for the
/// default vehicle: speed in `[0, v_max]`, turn rate within its limit.
#[must_use]
pub fn start_states() -> Vec<VehicleState> {
    let p = VehicleParams::default();
    let mut r = Rng::new(23);
    (0..1024)
        .map(|_| {
            let v = r.range(0.0, p.v_max);
            VehicleState::new(Vec2::ZERO, 0.0, v, r.range(-1.0, 1.0) * p.omega_limit(v))
        })
        .collect()
}

/// 256 (state, goal) cases of one Table 1 bin: start at the origin, a
/// random bearing to the goal at distance `d`, a random admissible
/// (v, ω), β = bearing ± `beta_deg`, tolerances `tol` = (m, degrees).
#[must_use]
pub fn table1_bin(d: f32, beta_deg: f32, tol: (f32, f32), seed: u64) -> Vec<(VehicleState, Goal)> {
    let p = VehicleParams::default();
    let mut r = Rng::new(seed);
    (0..256)
        .map(|_| {
            let bearing = r.range(-3.1, 3.1);
            let v = r.range(0.0, p.v_max);
            let w = r.range(-1.0, 1.0) * p.omega_limit(v);
            let sign = if r.range(0.0, 1.0) < 0.5 { -1.0 } else { 1.0 };
            (
                VehicleState::new(Vec2::ZERO, 0.0, v, w),
                Goal {
                    pos: Vec2::from_angle(bearing) * d,
                    beta: bearing + sign * beta_deg.to_radians(),
                    d_tol: tol.0,
                    eps_tol: tol.1.to_radians(),
                    speed: 1.3,
                    halting: false,
                    vel: Vec2::ZERO,
                },
            )
        })
        .collect()
}

/// Paper 001 Table 1's 16 bins at tolerances `tol`, distance-major
/// ([`TABLE1_DISTANCES`] × [`TABLE1_BETAS_DEG`]), bin `i · 4 + j` seeded
/// with its index.
#[must_use]
pub fn table1_bins(tol: (f32, f32)) -> Vec<Vec<(VehicleState, Goal)>> {
    let mut bins = Vec::with_capacity(16);
    for (i, d) in TABLE1_DISTANCES.iter().enumerate() {
        for (j, b) in TABLE1_BETAS_DEG.iter().enumerate() {
            bins.push(table1_bin(*d, *b, tol, (i * 4 + j) as u64));
        }
    }
    bins
}
