//! The entries of an agent's goal queue (paper 000 §6: moving and
//! successive targets): how a goal moves, when the next one takes over,
//! which goals may halt, and the mode memory each starts with.

use glam::Vec2;
use serde::{Deserialize, Serialize};

use crate::base::vehicle::{ParamError, VehicleState};
use crate::funnelling::goal::{FunnelMemory, Goal};

/// How a goal moves (paper 000 §1: "a possibly moving target").
///
/// A goal that moves by itself ([`GoalMotion::Linear`] with a non-zero
/// velocity, [`GoalMotion::Circle`] with a non-zero angular speed) cannot be
/// `halting`: it never stops, so no rest pose lies inside its
/// tolerances for long; [`World::add_agent`](crate::world::World::add_agent), scenario files and the lab
/// refuse the combination ([`GoalSpec::check_halting`]). A
/// [`GoalMotion::FaceAgent`] goal may halt: the agent it follows can stop.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize, Default)]
#[serde(rename_all = "camelCase", tag = "kind", deny_unknown_fields)]
pub enum GoalMotion {
    /// Static.
    #[default]
    Static,
    /// Constant velocity; the orientation is kept.
    Linear {
        /// Velocity, m/s.
        velocity: Vec2,
    },
    /// Around a circle counter-clockwise (clockwise if `angular_speed` < 0),
    /// starting at the goal's initial position; the orientation turns with
    /// the tangent.
    Circle {
        /// Circle centre, m.
        center: Vec2,
        /// Angular speed, rad/s.
        #[serde(rename = "angularSpeed")]
        angular_speed: f32,
    },
    /// Face another agent (paper 000 Fig. 6): the target is the point
    /// `distance` in front of agent `agent`, the orientation faces it.
    FaceAgent {
        /// Index of the other agent.
        agent: usize,
        /// Distance in front of it, m.
        distance: f32,
    },
}

/// When a goal counts as done and the next one in the queue takes over
/// (paper 000 §6, successive targets).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize, Default)]
#[serde(rename_all = "camelCase")]
pub enum SwitchRule {
    /// On End_of_Steering (position and orientation within tolerance).
    #[default]
    EndOfSteering,
    /// As soon as the position tolerance is entered.
    Tolerance,
}

/// A goal in an agent's queue.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize, Default)]
pub struct GoalSpec {
    /// The goal at time 0 (or when it becomes current, for static goals).
    pub goal: Goal,
    /// Its motion.
    pub motion: GoalMotion,
    /// When to switch to the next goal.
    pub switch: SwitchRule,
}

/// Why [`GoalSpec::check_halting`] refuses a goal.
pub const MOVING_HALTING: &str = "a moving goal cannot be halting: a goal in linear or circular \
     motion never stops, so the vehicle could never rest inside its tolerances (untick halting, \
     or make the goal static or faceAgent)";

impl GoalSpec {
    /// True when the goal moves by itself: linear motion with a non-zero
    /// velocity, or circular motion with a non-zero angular speed.
    #[must_use]
    pub fn moves_by_itself(&self) -> bool {
        match self.motion {
            GoalMotion::Linear { velocity } => velocity != Vec2::ZERO,
            GoalMotion::Circle { angular_speed, .. } => angular_speed != 0.0,
            GoalMotion::Static | GoalMotion::FaceAgent { .. } => false,
        }
    }

    /// True when the goal moves by itself or follows an agent.
    #[must_use]
    pub fn moves(&self) -> bool {
        self.moves_by_itself() || matches!(self.motion, GoalMotion::FaceAgent { .. })
    }

    /// The mode memory of this goal as it becomes current: nothing met
    /// yet, and the two facts of its motion the controllers read.
    #[must_use]
    pub fn fresh_memory(&self) -> FunnelMemory {
        FunnelMemory {
            position_met: false,
            goal_moves: self.moves(),
            goal_follows_agent: matches!(self.motion, GoalMotion::FaceAgent { .. }),
            passes: 0,
            ..FunnelMemory::default()
        }
    }

    /// Refuses a halting goal that moves by itself (see [`GoalMotion`]).
    ///
    /// # Errors
    /// [`ParamError::Inconsistent`] with [`MOVING_HALTING`].
    pub fn check_halting(&self) -> Result<(), ParamError> {
        if self.goal.halting && self.moves_by_itself() {
            return Err(ParamError::Inconsistent(MOVING_HALTING));
        }
        Ok(())
    }

    /// The goal at world time `t`, given the agents' states `states`.
    /// A static goal is a plain copy, made where it is read (every agent
    /// update reads its goal here); a moving one is computed out of line.
    #[must_use]
    #[inline(always)]
    pub fn at(&self, t: f32, states: &[VehicleState]) -> Goal {
        match self.motion {
            GoalMotion::Static => self.goal,
            _ => self.moved(t, states),
        }
    }

    /// [`GoalSpec::at`] for a goal in motion.
    #[inline(never)]
    fn moved(&self, t: f32, states: &[VehicleState]) -> Goal {
        let mut g = self.goal;
        match self.motion {
            GoalMotion::Static => {}
            GoalMotion::Linear { velocity } => {
                g.pos += velocity * t;
                g.vel = velocity;
            }
            GoalMotion::Circle {
                center,
                angular_speed,
            } => {
                let r0 = self.goal.pos - center;
                let rot = crate::base::trig::unit(angular_speed * t);
                let r = rot.rotate(r0);
                g.pos = center + r;
                g.beta = self.goal.beta + angular_speed * t;
                g.vel = r.perp() * angular_speed;
            }
            GoalMotion::FaceAgent { agent, distance } => {
                if let Some(o) = states.get(agent) {
                    g.pos = o.pos + o.forward() * distance;
                    g.beta = o.theta + core::f32::consts::PI;
                }
            }
        }
        g
    }
}
