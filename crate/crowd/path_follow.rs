//! Path following (paper 003, "Path following", after Reynolds 1999).
//!
//! Each step: predict the boid's future position a fixed distance ahead
//! along its velocity, find the normal point of that prediction on the path
//! ([`Path::normal_point`]), and if the prediction is farther from the path
//! than the path radius, seek a target a set distance further along the
//! path ("else keep follow path": inside the radius no steering is applied).
//!
//! A boid at rest has no heading to predict along; its prediction is its own
//! position (the paper divides by the speed implicitly when normalising).

use glam::Vec2;

use crate::crowd::path::{NormalPoint, Path};

/// What path following decided for one boid this step.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FollowDecision {
    /// The predicted future position.
    pub predicted: Vec2,
    /// Normal point of the prediction on the path.
    pub normal: NormalPoint,
    /// The point to seek, or `None` when the prediction is within the path
    /// radius (no steering needed).
    pub target: Option<Vec2>,
}

/// Path-following distances, world units.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PathFollow {
    /// How far ahead along the velocity the future position is predicted.
    pub predict_distance: f32,
    /// How far along the path beyond the normal point the target lies
    /// (the paper's `x` pixels).
    pub lookahead: f32,
}

impl PathFollow {
    /// Runs the paper's per-step rule for a boid at `pos` moving at `vel`.
    #[inline]
    #[must_use]
    pub fn decide(&self, path: &Path, pos: Vec2, vel: Vec2) -> FollowDecision {
        let predicted = pos + vel.normalize_or_zero() * self.predict_distance;
        let normal = path.normal_point(predicted);
        let target =
            (normal.distance > path.radius()).then(|| path.target_ahead(&normal, self.lookahead));
        FollowDecision {
            predicted,
            normal,
            target,
        }
    }
}
