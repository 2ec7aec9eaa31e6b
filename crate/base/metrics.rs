//! Path metrics (docs/DESIGN.md §17): what a trajectory is measured by.
//!
//! Accumulated step by step so that a run never stores its trajectory to be
//! measured: path length, integrated |curvature| (`∫|κ| ds = ∫|dθ|` for a
//! forward-moving vehicle), time, and a limit check of every step against
//! the vehicle's bounds (speed, angular speed, both accelerations, normal
//! acceleration) plus finiteness.

use crate::base::angle::diff;
use crate::base::vehicle::{VehicleParams, VehicleState};

/// Running path measures of one agent.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct PathMetrics {
    /// Path length, m.
    pub length: f32,
    /// Integrated |curvature| (total absolute heading change), rad.
    pub curvature: f32,
    /// Steps accumulated.
    pub steps: u32,
    /// Steps where a limit was exceeded or a value was not finite.
    pub violations: u32,
}

impl PathMetrics {
    /// Adds the step from `prev` to `next`.
    #[inline]
    pub fn add(&mut self, p: &VehicleParams, prev: &VehicleState, next: &VehicleState) {
        self.length += (next.pos - prev.pos).length();
        self.curvature += diff(next.theta, prev.theta).abs();
        self.steps += 1;
        let tol = 1.0001;
        let ok = next.within_limits(p)
            && (next.v - prev.v).abs() <= p.accel_max * p.dt * tol + 1e-6
            && (next.omega - prev.omega).abs() <= p.omega_accel_max * p.dt * tol + 1e-6;
        if !ok {
            self.violations += 1;
        }
    }
}

/// Percentile `q` in [0, 1] of `v` (sorted in place); NaN when empty.
#[must_use]
pub fn percentile(v: &mut [f32], q: f32) -> f32 {
    if v.is_empty() {
        return f32::NAN;
    }
    v.sort_by(f32::total_cmp);
    v[((v.len() - 1) as f32 * q.clamp(0.0, 1.0)).round() as usize]
}
