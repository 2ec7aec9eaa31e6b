//! What a scenario says about avoidance: the method (off,
//! separation, ORCA), the agents' body radius and the method's settings,
//! and the static obstacles (discs and line segments). Validation uses the
//! one table of ranges ([`crate::base::ranges`]); errors name the
//! field (`obstacles[2]: obstacle.radius = -1 is outside [0.01, 10000]`).
//!
//! The default is `off`: a scenario that says nothing steps exactly as
//! without avoidance (the same trajectory bits).

use glam::Vec2;
use serde::{Deserialize, Serialize};

use crate::base::ranges as r;
use crate::base::vehicle::ParamError;

/// How moving agents avoid each other and the obstacles.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize, Default)]
#[serde(rename_all = "camelCase")]
pub enum AvoidanceMethod {
    /// Ghosts: agents pass through each other and through obstacles.
    #[default]
    Off,
    /// Paper 003's separation (Parker): a push away from neighbours closer
    /// than two radii plus the margin, added to the funnel's velocity; the
    /// obstacles push the same way. A baseline, not a guarantee.
    Separation,
    /// Optimal reciprocal collision avoidance (van den Berg et al. 2011):
    /// the velocity nearest the funnel's that no neighbour within the time
    /// horizon can collide with, each agent taking half the avoidance.
    Orca,
}

impl AvoidanceMethod {
    /// Parses `off`, `separation` or `orca`.
    #[must_use]
    pub fn parse(s: &str) -> Option<Self> {
        match s {
            "off" => Some(Self::Off),
            "separation" => Some(Self::Separation),
            "orca" => Some(Self::Orca),
            _ => None,
        }
    }

    /// `off`, `separation` or `orca`.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Self::Off => "off",
            Self::Separation => "separation",
            Self::Orca => "orca",
        }
    }
}

/// Avoidance settings shared by every agent of a world.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields, rename_all = "camelCase")]
pub struct AvoidanceConfig {
    /// The method (default off).
    pub method: AvoidanceMethod,
    /// Body radius of every agent, m: two agents overlap when closer than
    /// twice this.
    pub radius: f32,
    /// Extra clearance the avoidance keeps (added to the radius it avoids
    /// with, never to the overlap count), m: the forward-only vehicle
    /// cannot take the ORCA velocity at once, it turns and brakes within its
    /// limits, so it needs some room.
    pub margin: f32,
    /// ORCA time horizon between agents, s.
    pub horizon: f32,
    /// ORCA time horizon for static obstacles, s.
    pub obstacle_horizon: f32,
    /// Neighbour search distance, m (the grid's cell; at least two radii
    /// plus the margin).
    pub reach: f32,
    /// Nearest neighbours considered per agent (1–16): the cost per agent
    /// is bounded by it, whatever the crowd's density.
    pub max_neighbours: u32,
    /// Separation method only: the push per metre of overlap, 1/s.
    pub separation_weight: f32,
    /// ORCA only: when the funnel's velocity is not admissible, the
    /// velocity sought is the funnel's turned this many degrees clockwise
    /// (keep right). Pure ORCA (0) answers a symmetric approach by slowing
    /// straight on, and a forward-only crowd converging on one point then
    /// jams for good (circle swap: every agent deadlocked); a common side
    /// breaks the symmetry into a roundabout.
    pub bias_deg: f32,
    /// Steps between one agent's avoidance plans (1–4; the agents take
    /// turns, by index): in between it keeps the command of its last plan,
    /// or takes its funnel's when that plan left the funnel's alone. At the
    /// default 1/60 s step, 2 plans at 30 Hz, the rate game engines give
    /// their avoidance; 1 plans every step (what the avoidance adds to an
    /// agent update nearly halves from 1 to 2: [`crate::avoidance::avoider`]'s
    /// module doc). Slower rates are offered to explore, not for use: a
    /// command held over 3 or 4 steps is old enough for circle-swap agents
    /// to touch and for agents of the paper figures to deadlock or not
    /// finish.
    pub replan_every: u32,
}

impl Default for AvoidanceConfig {
    fn default() -> Self {
        Self {
            method: AvoidanceMethod::Off,
            radius: 0.3,
            margin: 0.15,
            horizon: 2.0,
            obstacle_horizon: 1.0,
            reach: 3.0,
            max_neighbours: 10,
            separation_weight: 4.0,
            bias_deg: 90.0,
            replan_every: 2,
        }
    }
}

impl AvoidanceConfig {
    /// The default settings with `method`.
    #[must_use]
    pub fn with_method(method: AvoidanceMethod) -> Self {
        Self {
            method,
            ..Self::default()
        }
    }

    /// Checks every field.
    ///
    /// # Errors
    /// The first field out of range, or a reach shorter than two radii plus
    /// the margin.
    pub fn validate(&self) -> Result<(), ParamError> {
        r::AVOID_RADIUS.check(self.radius)?;
        r::AVOID_MARGIN.check(self.margin)?;
        r::AVOID_HORIZON.check(self.horizon)?;
        r::AVOID_OBSTACLE_HORIZON.check(self.obstacle_horizon)?;
        r::AVOID_REACH.check(self.reach)?;
        r::AVOID_NEIGHBOURS.check(self.max_neighbours as f32)?;
        r::AVOID_SEPARATION_WEIGHT.check(self.separation_weight)?;
        r::AVOID_BIAS.check(self.bias_deg)?;
        r::AVOID_REPLAN_EVERY.check(self.replan_every as f32)?;
        if self.reach < 2.0 * (self.radius + self.margin) {
            return Err(ParamError::Inconsistent(
                "avoidance.reach must be at least 2 × (avoidance.radius + avoidance.margin)",
            ));
        }
        Ok(())
    }
}

/// A static obstacle.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "camelCase", deny_unknown_fields)]
pub enum Obstacle {
    /// A disc.
    Disc {
        /// Centre x, m.
        x: f32,
        /// Centre y, m.
        y: f32,
        /// Radius, m.
        radius: f32,
    },
    /// A line segment (a wall of no thickness: agents keep their radius
    /// from it).
    Segment {
        /// First end x, m.
        x1: f32,
        /// First end y, m.
        y1: f32,
        /// Second end x, m.
        x2: f32,
        /// Second end y, m.
        y2: f32,
    },
}

impl Obstacle {
    /// Checks every field.
    ///
    /// # Errors
    /// The first field out of range, or a segment of zero length.
    pub fn validate(&self) -> Result<(), ParamError> {
        match *self {
            Self::Disc { x, y, radius } => {
                r::OBSTACLE_X.check(x)?;
                r::OBSTACLE_Y.check(y)?;
                r::OBSTACLE_RADIUS.check(radius)?;
            }
            Self::Segment { x1, y1, x2, y2 } => {
                r::OBSTACLE_X.check(x1)?;
                r::OBSTACLE_Y.check(y1)?;
                r::OBSTACLE_X.check(x2)?;
                r::OBSTACLE_Y.check(y2)?;
                if (Vec2::new(x2, y2) - Vec2::new(x1, y1)).length_squared() < 1e-8 {
                    return Err(ParamError::Inconsistent(
                        "a segment obstacle needs two different ends (x1, y1) ≠ (x2, y2)",
                    ));
                }
            }
        }
        Ok(())
    }

    /// The signed distance from `p` to the obstacle's surface (negative
    /// inside a disc) and the unit normal pointing from the obstacle
    /// towards `p` (a disc's radial direction; for a point on a segment,
    /// the segment's left normal).
    #[inline]
    #[must_use]
    pub fn distance_normal(&self, p: Vec2) -> (f32, Vec2) {
        match *self {
            Self::Disc { x, y, radius } => {
                let d = p - Vec2::new(x, y);
                let len = d.length();
                let n = if len > 1e-9 { d / len } else { Vec2::X };
                (len - radius, n)
            }
            Self::Segment { x1, y1, x2, y2 } => {
                let a = Vec2::new(x1, y1);
                let ab = Vec2::new(x2, y2) - a;
                let t = ((p - a).dot(ab) / ab.length_squared()).clamp(0.0, 1.0);
                let d = p - (a + ab * t);
                let len = d.length();
                let n = if len > 1e-9 {
                    d / len
                } else {
                    ab.perp().normalize_or_zero()
                };
                (len, n)
            }
        }
    }
}

/// Most obstacles in a world: obstacles are not indexed by the grid (each
/// agent tests every one), so they are meant to be few.
pub const MAX_OBSTACLES: usize = 1024;

/// Checks a list of obstacles, naming the first bad one by index.
///
/// # Errors
/// `obstacles[i]: …`, or too many obstacles.
pub fn validate_obstacles(obstacles: &[Obstacle]) -> Result<(), String> {
    if obstacles.len() > MAX_OBSTACLES {
        return Err(format!(
            "{} obstacles (at most {MAX_OBSTACLES})",
            obstacles.len()
        ));
    }
    for (i, o) in obstacles.iter().enumerate() {
        o.validate().map_err(|e| format!("obstacles[{i}]: {e}"))?;
    }
    Ok(())
}
