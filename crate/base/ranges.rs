//! One table of validation ranges for every user-settable number of the
//! funnelling lab.
//!
//! Why: the core's `validate` functions, the lab's URL decoder and its
//! sliders must agree. Written three times they drift apart: a range the
//! page accepts and the core refuses (`#vd=50`, `#vmax=0.05`) leaves an
//! empty playground, and one the page accepts too widely (`#vd=0`) gives
//! an agent that never moves. Here each field is one [`FieldRange`] constant; the core's
//! validation ([`VehicleParams::validate`](crate::base::vehicle::VehicleParams::validate),
//! [`Goal::validate`](crate::funnelling::goal::Goal::validate), the funnel, relaxed,
//! scenario and world-edit checks) calls [`FieldRange::check`] on it, and
//! the bindings export [`ALL`] (`ranges()`), from which the page derives its
//! URL decoder, sliders and number inputs.
//!
//! Design: a range is closed and finite (docs/DESIGN.md §5: an f32 core must stay
//! finite), stored as f64 so the page reads the written number (0.01, not
//! 0.009999999776); the core compares in f32, and since rounding to f32 is
//! monotone a value the page accepts in f64 is accepted by the core.
//! Cross-field rules are data too: [`FieldRange::at_most`] names the field
//! whose current value also bounds this one (`goal.speed ≤ vMax`,
//! `|omega| ≤ omegaMax`). Keys are the names the error messages use (the
//! JSON / TypeScript key, with its section: `goal.dTol`, `funnel.gain`).
//! Units are SI and radians: a file's `epsTolDeg` is converted first.

use serde::Serialize;

use crate::base::range::{check_range, RangeError};

/// The accepted interval of one field.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
#[serde(rename_all = "camelCase")]
pub struct FieldRange {
    /// The field as errors name it (`vMax`, `goal.dTol`, `funnel.gain`).
    pub key: &'static str,
    /// Smallest accepted value.
    pub min: f64,
    /// Largest accepted value.
    pub max: f64,
    /// SI unit (`m`, `m/s`, `rad`, `s`; empty for a pure number).
    pub unit: &'static str,
    /// Only whole numbers (counts, seeds).
    pub integer: bool,
    /// A field whose current value also bounds this one: the value is at
    /// most it (for a range symmetric about 0, its magnitude is).
    pub at_most: Option<&'static str>,
    /// What the field is, for help texts.
    pub what: &'static str,
}

impl FieldRange {
    /// Checks `value` against `[min, max]` (in f32, as the core computes).
    ///
    /// # Errors
    /// A [`RangeError`] naming the field.
    pub fn check(&self, value: f32) -> Result<(), RangeError> {
        check_range(self.key, value, self.min as f32, self.max as f32)
    }

    /// Checks `value` against the range narrowed by the current value
    /// `limit` of the [`FieldRange::at_most`] field: `[min, min(max,
    /// limit)]`, or `[max(min, −limit), min(max, limit)]` for a range
    /// symmetric about 0.
    ///
    /// # Errors
    /// A [`RangeError`] naming the field, with the narrowed interval.
    pub fn check_at_most(&self, value: f32, limit: f32) -> Result<(), RangeError> {
        let max = (self.max as f32).min(limit);
        let min = if self.min < 0.0 {
            (self.min as f32).max(-limit)
        } else {
            self.min as f32
        };
        check_range(self.key, value, min, max)
    }
}

const fn range(
    key: &'static str,
    min: f64,
    max: f64,
    unit: &'static str,
    what: &'static str,
) -> FieldRange {
    FieldRange {
        key,
        min,
        max,
        unit,
        integer: false,
        at_most: None,
        what,
    }
}

const fn bounded_by(r: FieldRange, field: &'static str) -> FieldRange {
    FieldRange {
        at_most: Some(field),
        ..r
    }
}

const fn integer(r: FieldRange) -> FieldRange {
    FieldRange { integer: true, ..r }
}

/// Largest coordinate of a position, m.
const WORLD: f64 = 1e6;
/// Largest stored angle before wrapping, rad.
const TURNS: f64 = 1e3;

// Vehicle limits and gains (`VehicleParams`, paper 000 §3).
/// Fixed time step.
pub const DT: FieldRange = range("dt", 1e-4, 0.1, "s", "time step");
/// Maximum forward speed.
pub const V_MAX: FieldRange = range("vMax", 0.01, 100.0, "m/s", "maximum forward speed");
/// Maximum forward acceleration.
pub const ACCEL_MAX: FieldRange = range(
    "accelMax",
    0.01,
    1000.0,
    "m/s²",
    "maximum forward acceleration",
);
/// Maximum angular speed.
pub const OMEGA_MAX: FieldRange = range("omegaMax", 0.01, 100.0, "rad/s", "maximum angular speed");
/// Maximum angular acceleration.
pub const OMEGA_ACCEL_MAX: FieldRange = range(
    "omegaAccelMax",
    0.01,
    10_000.0,
    "rad/s²",
    "maximum angular acceleration",
);
/// Maximum normal acceleration `A = |v·ω|`.
pub const NORMAL_ACCEL_MAX: FieldRange = range(
    "normalAccelMax",
    0.01,
    1000.0,
    "m/s²",
    "maximum normal acceleration",
);
/// Proportional gain of the seek's angular controller.
pub const KP: FieldRange = range("kp", 0.01, 10_000.0, "1/s²", "seek proportional gain");
/// Damping gain of the seek's angular controller.
pub const KD: FieldRange = range("kd", 0.01, 10_000.0, "1/s", "seek damping gain");
/// Minimum turning radius at every speed (0: the unicycle, which turns on
/// the spot).
pub const MIN_TURN_RADIUS: FieldRange = range(
    "minTurnRadius",
    0.0,
    1000.0,
    "m",
    "minimum turning radius (0: turns on the spot)",
);

// A vehicle's state (the start pose of an agent). Positions have a
// cross-field rule too: an agent and its goals stay within
// `precision::agent_limit` (where f32 still resolves a quarter of a step
// of its slowest goal; 45,438 m at 1.3 m/s and 1/60 s). ±1e6 m is the cap
// for fast, coarse vehicles.
/// Start x.
pub const POS_X: FieldRange = range("pos.x", -WORLD, WORLD, "m", "start x");
/// Start y.
pub const POS_Y: FieldRange = range("pos.y", -WORLD, WORLD, "m", "start y");
/// Start heading.
pub const THETA: FieldRange = range("theta", -TURNS, TURNS, "rad", "start heading");
/// Largest reverse speed (0: forward only; at most `vMax`).
pub const V_REVERSE: FieldRange = bounded_by(
    range(
        "vReverse",
        0.0,
        100.0,
        "m/s",
        "largest reverse speed (0: forward only)",
    ),
    "vMax",
);
/// What a gear change is worth in metres of path (0: the shortest path).
pub const GEAR_CHANGE_COST: FieldRange = range(
    "gearChangeCost",
    0.0,
    1000.0,
    "m",
    "cost of one gear change, metres of path",
);
/// Start speed (at most `vMax`).
pub const V: FieldRange = bounded_by(range("v", 0.0, 100.0, "m/s", "start speed"), "vMax");
/// Start angular speed (magnitude at most `omegaMax`).
pub const OMEGA: FieldRange = bounded_by(
    range("omega", -100.0, 100.0, "rad/s", "start angular speed"),
    "omegaMax",
);

// A goal (paper 000 §5).
/// Target x.
pub const GOAL_X: FieldRange = range("goal.pos.x", -WORLD, WORLD, "m", "target x");
/// Target y.
pub const GOAL_Y: FieldRange = range("goal.pos.y", -WORLD, WORLD, "m", "target y");
/// Target orientation β.
pub const GOAL_BETA: FieldRange = range("goal.beta", -TURNS, TURNS, "rad", "target orientation β");
/// Position tolerance `D_tol`.
pub const GOAL_D_TOL: FieldRange = range("goal.dTol", 0.01, 1e3, "m", "position tolerance D_tol");
/// Orientation tolerance `ε_tol`.
pub const GOAL_EPS_TOL: FieldRange = range(
    "goal.epsTol",
    1e-3,
    core::f64::consts::PI,
    "rad",
    "orientation tolerance ε_tol",
);
/// Desired speed `v_d`: positive (a desired speed of 0 gives an agent that
/// never moves) and at most `vMax`. The smallest equals `vMax`'s smallest,
/// so every vehicle has goals.
pub const GOAL_SPEED: FieldRange = bounded_by(
    range("goal.speed", 0.01, 100.0, "m/s", "desired speed v_d"),
    "vMax",
);

// Goal motion (paper 000 §6).
/// Linear motion, x velocity.
pub const MOTION_VX: FieldRange =
    range("motion.velocity.x", -100.0, 100.0, "m/s", "goal velocity x");
/// Linear motion, y velocity.
pub const MOTION_VY: FieldRange =
    range("motion.velocity.y", -100.0, 100.0, "m/s", "goal velocity y");
/// Circular motion, centre x.
pub const MOTION_CX: FieldRange = range(
    "motion.center.x",
    -WORLD,
    WORLD,
    "m",
    "goal circle centre x",
);
/// Circular motion, centre y.
pub const MOTION_CY: FieldRange = range(
    "motion.center.y",
    -WORLD,
    WORLD,
    "m",
    "goal circle centre y",
);
/// Circular motion, angular speed.
pub const MOTION_ANGULAR_SPEED: FieldRange = range(
    "motion.angularSpeed",
    -100.0,
    100.0,
    "rad/s",
    "goal circle angular speed",
);
/// Facing an agent, distance in front of it.
pub const MOTION_DISTANCE: FieldRange = range(
    "motion.distance",
    0.0,
    1e3,
    "m",
    "distance in front of the followed agent",
);

// Funnel settings (`FunnelConfig`, paper 000 Fig. 4–5).
/// Seek threshold (fraction of ε_tol).
pub const SEEK_THRESHOLD: FieldRange = range(
    "funnel.seekThreshold",
    0.0,
    1.0,
    "",
    "seek threshold (fraction of ε_tol)",
);
/// Gain k of μ = −k·Δη.
pub const FUNNEL_GAIN: FieldRange = range("funnel.gain", 0.0, 100.0, "", "μ gain k");
/// Gain of the scaled literal μ bound.
pub const BOUND_GAIN: FieldRange = range(
    "funnel.bound.gain",
    0.0,
    100.0,
    "",
    "scaled literal bound gain",
);
/// Factor of the turning-radius μ bound.
pub const BOUND_FACTOR: FieldRange = range(
    "funnel.bound.factor",
    0.0,
    1000.0,
    "",
    "turning-radius bound factor",
);

// Relaxed funnelling (`RelaxedConfig`, paper 001 §4).
/// Disk margin.
pub const DISK_MARGIN: FieldRange =
    range("relaxed.diskMargin", 0.05, 1.0, "", "relaxed disk margin");
/// Orientation margin.
pub const ORIENTATION_MARGIN: FieldRange = range(
    "relaxed.orientationMargin",
    0.05,
    1.0,
    "",
    "relaxed orientation margin",
);

// Scenarios and the lab's crowd.
/// Simulated duration of a scenario.
pub const DURATION: FieldRange = range("duration", 0.0, 3600.0, "s", "simulated duration");
/// Agents in a scenario, or random agents added to the lab's playground.
pub const AGENTS: FieldRange = integer(range("agents", 0.0, 100_000.0, "", "number of agents"));
/// Seed of the lab's random agents (a u32 at the boundary).
pub const SEED: FieldRange = integer(range(
    "seed",
    0.0,
    4_294_967_295.0,
    "",
    "seed of the random agents",
));
/// Half-side of the square the random agents start in: 10 km, inside the
/// coordinate limit of `precision.rs` for goal speeds from 0.29 m/s (a
/// slower crowd spread that far is refused there, with the limit named).
pub const EXTENT: FieldRange = range(
    "extent",
    1e-3,
    1e4,
    "m",
    "half-side of the random agents' square",
);

// Avoidance between agents and static obstacles (`AvoidanceConfig`,
// `Obstacle`).
/// Body radius of every agent (overlap = closer than two radii).
pub const AVOID_RADIUS: FieldRange =
    range("avoidance.radius", 0.01, 100.0, "m", "agent body radius");
/// Safety margin added to the radius by the avoidance (not by the overlap count).
pub const AVOID_MARGIN: FieldRange = range(
    "avoidance.margin",
    0.0,
    10.0,
    "m",
    "avoidance safety margin",
);
/// ORCA time horizon between agents.
pub const AVOID_HORIZON: FieldRange = range(
    "avoidance.horizon",
    0.1,
    60.0,
    "s",
    "ORCA time horizon (agents)",
);
/// ORCA time horizon for static obstacles.
pub const AVOID_OBSTACLE_HORIZON: FieldRange = range(
    "avoidance.obstacleHorizon",
    0.05,
    60.0,
    "s",
    "ORCA time horizon (obstacles)",
);
/// Neighbour search distance (the grid's cell).
pub const AVOID_REACH: FieldRange = range(
    "avoidance.reach",
    0.02,
    1000.0,
    "m",
    "neighbour search distance",
);
/// Nearest neighbours considered per agent.
pub const AVOID_NEIGHBOURS: FieldRange = integer(range(
    "avoidance.maxNeighbours",
    1.0,
    16.0,
    "",
    "nearest neighbours considered",
));
/// Weight of the separation method's push.
pub const AVOID_SEPARATION_WEIGHT: FieldRange = range(
    "avoidance.separationWeight",
    0.0,
    100.0,
    "1/s",
    "separation weight",
);
/// ORCA's keep-right turn of the sought velocity, degrees (a file's unit).
pub const AVOID_BIAS: FieldRange =
    range("avoidance.biasDeg", 0.0, 90.0, "°", "ORCA keep-right bias");
/// Steps between an agent's avoidance plans.
pub const AVOID_REPLAN_EVERY: FieldRange = integer(range(
    "avoidance.replanEvery",
    1.0,
    4.0,
    "steps",
    "steps between avoidance plans",
));
/// Centre or end point of a static obstacle.
pub const OBSTACLE_X: FieldRange = range("obstacle.x", -WORLD, WORLD, "m", "obstacle x");
/// Centre or end point of a static obstacle.
pub const OBSTACLE_Y: FieldRange = range("obstacle.y", -WORLD, WORLD, "m", "obstacle y");
/// Radius of a disc obstacle.
pub const OBSTACLE_RADIUS: FieldRange =
    range("obstacle.radius", 0.01, 1e4, "m", "disc obstacle radius");

// Every vehicle has goals: the smallest desired speed fits the slowest
// vehicle, the largest the fastest (checked when compiling).
const _: () = assert!(GOAL_SPEED.min <= V_MAX.min && GOAL_SPEED.max >= V_MAX.max);

/// Every range, in the order above (exported to the page as `ranges()`).
pub const ALL: [FieldRange; 50] = [
    DT,
    V_MAX,
    ACCEL_MAX,
    OMEGA_MAX,
    OMEGA_ACCEL_MAX,
    NORMAL_ACCEL_MAX,
    KP,
    KD,
    MIN_TURN_RADIUS,
    V_REVERSE,
    GEAR_CHANGE_COST,
    POS_X,
    POS_Y,
    THETA,
    V,
    OMEGA,
    GOAL_X,
    GOAL_Y,
    GOAL_BETA,
    GOAL_D_TOL,
    GOAL_EPS_TOL,
    GOAL_SPEED,
    MOTION_VX,
    MOTION_VY,
    MOTION_CX,
    MOTION_CY,
    MOTION_ANGULAR_SPEED,
    MOTION_DISTANCE,
    SEEK_THRESHOLD,
    FUNNEL_GAIN,
    BOUND_GAIN,
    BOUND_FACTOR,
    DISK_MARGIN,
    ORIENTATION_MARGIN,
    DURATION,
    AGENTS,
    SEED,
    EXTENT,
    AVOID_RADIUS,
    AVOID_MARGIN,
    AVOID_HORIZON,
    AVOID_OBSTACLE_HORIZON,
    AVOID_REACH,
    AVOID_NEIGHBOURS,
    AVOID_SEPARATION_WEIGHT,
    AVOID_BIAS,
    AVOID_REPLAN_EVERY,
    OBSTACLE_X,
    OBSTACLE_Y,
    OBSTACLE_RADIUS,
];

/// The range named `key`, if any.
#[must_use]
pub fn find(key: &str) -> Option<&'static FieldRange> {
    ALL.iter().find(|r| r.key == key)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn keys_are_unique_and_ranges_finite_and_ordered() {
        for (i, r) in ALL.iter().enumerate() {
            assert!(
                r.min.is_finite() && r.max.is_finite() && r.min < r.max,
                "{r:?}"
            );
            assert!(!r.integer || (r.min.fract() == 0.0 && r.max.fract() == 0.0));
            if let Some(f) = r.at_most {
                assert!(find(f).is_some(), "{} is bounded by unknown {f}", r.key);
            }
            for q in &ALL[..i] {
                assert_ne!(q.key, r.key, "duplicate key");
            }
        }
    }

    #[test]
    fn at_most_narrows_both_sides_of_a_signed_range() {
        assert!(OMEGA.check_at_most(1.5, 2.0).is_ok());
        let e = OMEGA.check_at_most(-2.5, 2.0).unwrap_err();
        assert_eq!(e.to_string(), "omega = -2.5 is outside [-2, 2]");
        let e = GOAL_SPEED.check_at_most(0.0, 2.0).unwrap_err();
        assert_eq!(e.to_string(), "goal.speed = 0 is outside [0.01, 2]");
    }
}
