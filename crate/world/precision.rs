//! Where f32 positions still resolve one step: the coordinate
//! range an agent and its goals must lie in, from the agent's slowest
//! goal speed and the time step.
//!
//! Problem: positions are f32 (docs/DESIGN.md §5: the same bits natively and in
//! wasm). One step moves `s = v·dt`; far from the origin the spacing of
//! f32 numbers (ulp, `2^(e−24)` for `|x| < 2^e`) approaches `s` and every
//! step is rounded: at x = 999,980 m a 1.3 m/s agent does not move at
//! all, at 300,000 m it stops 0.44 m short.
//!
//! Measured (a 20 m oriented reach, start at rest, goal 16 m ahead and
//! 12 m aside with β = 90°, D_tol 0.25 m, ε_tol 5°; path length against
//! the same run at the origin; `tests/hardening.rs` keeps the probe):
//! the run stays within 1 % while `ulp(|x|) ≤ s/4` — e.g. 1.3 m/s at
//! 1/60 s is within 0.11 % at 30 km, +21 % at 100 km; 0.1 m/s within 0.05 %
//! at 3 km, +1.7 % at 10 km; 0.01 m/s within 0.6 % at 1 km, +7.8 % at 3 km;
//! past `ulp ≈ 2s` the agent freezes and never finishes. Tight position
//! tolerances need their own resolution: a halting goal with D_tol 0.01 m
//! at dt 5 ms and 1.3 m/s finishes at 8 km but not at 16 km, although the
//! step rule alone would allow 13.6 km. Runs whose D_tol is near 0.01 m can also sit
//! on a near miss (a loop or not), so their length is not monotonic in x
//! (e.g. 1.3 m/s, D_tol 0.01 m at dt 1/60 s: one loop at the origin, none
//! from 2 km on); that is sensitivity, not resolution.
//!
//! Choice: enforce the range rather than move to local origins (which
//! would change every golden trajectory and the bindings' state layout).
//! [`coordinate_limit`] is `2^21·s` (so `ulp ≤ s/4` inside it) capped at
//! [`COORD_MAX`]: 45 km at the default 1.3 m/s and 1/60 s, 350 m at the
//! slowest goal speed (0.01 m/s), 1e6 m only from `s ≥ 0.48 m` (e.g.
//! 5 m/s at dt 0.1 s); and at most `2^18·D_tol` (`ulp ≤ D_tol/32`): 65 km
//! at the default 0.25 m, 2.6 km at 0.01 m. Checked on an agent's start and every goal of its
//! queue (circle centres and radii included), in scenario files, in
//! [`World::add_agent`](crate::world::World::add_agent) and in the world
//! edits. A linear goal keeps moving: a scenario (which has a duration)
//! checks where it ends; in an open-ended world (the lab) a goal that
//! drifts beyond the limit is steered with coarser steps.

use crate::base::vehicle::{check_range, ParamError, VehicleParams};
use crate::world::{goals::GoalMotion, goals::GoalSpec};

/// Largest |coordinate| anywhere, m (f32 spacing there: 6.25 cm).
pub const COORD_MAX: f32 = 1e6;

/// Coordinates stay within `STEP_RESOLUTION_SCALE · v·dt`: `2^21`, so the
/// f32 spacing there is at most a quarter of one step (measured above).
pub const STEP_RESOLUTION_SCALE: f32 = 2_097_152.0;

/// The largest |coordinate| at which f32 resolves a quarter of a step at
/// speed `speed` with the vehicle's time step, in whole metres (never above
/// [`COORD_MAX`]).
#[must_use]
pub fn coordinate_limit(p: &VehicleParams, speed: f32) -> f32 {
    (STEP_RESOLUTION_SCALE * speed * p.dt)
        .min(COORD_MAX)
        .floor()
}

/// Coordinates stay within `TOLERANCE_RESOLUTION_SCALE · D_tol`: `2^18`,
/// so the f32 spacing there is at most D_tol / 32 (measured: halting goals
/// with D_tol 0.01 m at dt 5 ms finish at 8 km, not at 16 km; 0.05 m at
/// 16 km, not at 32 km).
pub const TOLERANCE_RESOLUTION_SCALE: f32 = 262_144.0;

/// The limit for an agent with goal queue `goals`: set by its slowest goal
/// and its tightest position tolerance, in whole metres (an agent without
/// goals only has to stay under [`COORD_MAX`]).
#[must_use]
pub fn agent_limit(p: &VehicleParams, goals: &[GoalSpec]) -> f32 {
    goals
        .iter()
        .map(|g| {
            coordinate_limit(p, g.goal.speed)
                .min((TOLERANCE_RESOLUTION_SCALE * g.goal.d_tol).floor())
        })
        .fold(COORD_MAX, f32::min)
}

/// Checks a position against `limit`, naming its fields.
///
/// # Errors
/// A coordinate outside `[−limit, limit]`.
pub fn check_point(
    fields: (&'static str, &'static str),
    pos: glam::Vec2,
    limit: f32,
) -> Result<(), ParamError> {
    check_range(fields.0, pos.x, -limit, limit)?;
    check_range(fields.1, pos.y, -limit, limit)
}

/// Checks an agent's start `pos` and its goals (positions, circle centres
/// and the far side of each circle, and, when `duration` is known, where a
/// linear goal ends) against [`agent_limit`].
///
/// # Errors
/// The first coordinate out of range, named (`pos.x`, `goal.pos.y`,
/// `motion.center.x`, …) with the limit as its interval.
pub fn check_agent(
    p: &VehicleParams,
    pos: glam::Vec2,
    goals: &[GoalSpec],
    duration: Option<f32>,
) -> Result<(), ParamError> {
    let limit = agent_limit(p, goals);
    check_point(("pos.x", "pos.y"), pos, limit)?;
    for g in goals {
        check_point(("goal.pos.x", "goal.pos.y"), g.goal.pos, limit)?;
        match g.motion {
            GoalMotion::Circle { center, .. } => {
                check_point(("motion.center.x", "motion.center.y"), center, limit)?;
                let far = center + (center - g.goal.pos);
                check_point(("goal.pos.x (circle)", "goal.pos.y (circle)"), far, limit)?;
            }
            GoalMotion::Linear { velocity } => {
                if let Some(t) = duration {
                    let end = g.goal.pos + velocity * t;
                    check_point(
                        (
                            "goal.pos.x (at the end of its motion)",
                            "goal.pos.y (at the end of its motion)",
                        ),
                        end,
                        limit,
                    )?;
                }
            }
            GoalMotion::Static | GoalMotion::FaceAgent { .. } => {}
        }
    }
    Ok(())
}
