//! The inputs of the cost measurements, one definition for the two that
//! read them: the benchmarks time the updates over these cases
//! (`benches/core.rs`, `benches/relaxed.rs`) and the counted cost claims
//! count table reads over the very same cases (`tests/fidelity_cost.rs`),
//! so a count and a time always describe the same updates.
//!
//! Paper 000 §7 times one update to a far (30 units) and a near target;
//! paper 001 Table 1 bins updates by distance to the region and by the
//! offset of β from the bearing, at a small and a large tolerance.

use glam::Vec2;

use crate::base::rng::Rng;
use crate::base::trig::unit;
use crate::base::vehicle::{VehicleParams, VehicleState};
use crate::funnelling::goal::Goal;

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
