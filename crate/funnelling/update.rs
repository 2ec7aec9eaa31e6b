//! One controller update (paper 000 Fig. 4): what it reads and keeps
//! ([`Update`]: the η table, the vehicle's limits, one agent's state, goal
//! and memory of that goal) and what it reports ([`Mode`] of Fig. 5 and the
//! [`Internals`] the page draws). Every controller, standard, relaxed or
//! plain seek, plans and steps through the same [`Update`].

use serde::{Deserialize, Serialize};

use crate::base::vehicle::{VehicleParams, VehicleState};
use crate::funnelling::goal::{FunnelMemory, Goal};
use crate::funnelling::table::lookup::EtaTable;

/// One agent's update by a funnelling controller: the world's η table and
/// vehicle limits, and the agent's state, goal and memory of that goal.
/// Planning reads the state and may change the memory; stepping also moves
/// the state.
#[derive(Debug)]
pub struct Update<'a> {
    /// The η table the controller predicts with.
    pub table: &'a EtaTable,
    /// The vehicle's limits.
    pub params: &'a VehicleParams,
    /// The agent's state (moved by a step, read by a plan).
    pub state: &'a mut VehicleState,
    /// The goal now (for a moving goal, where it is this update).
    pub goal: &'a Goal,
    /// The agent's memory of this goal.
    pub memory: &'a mut FunnelMemory,
}

impl<'a> Update<'a> {
    /// The same update towards another goal (the plain seek's unoriented
    /// goal, the relaxed controller's fallback): the state and memory
    /// reborrowed.
    #[inline]
    pub fn towards<'b>(&'b mut self, goal: &'b Goal) -> Update<'b> {
        Update {
            table: self.table,
            params: self.params,
            state: &mut *self.state,
            goal,
            memory: &mut *self.memory,
        }
    }
}

/// The control mode chosen every step (paper 000 Fig. 5).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize, Default)]
#[serde(rename_all = "camelCase")]
#[repr(u8)]
pub enum Mode {
    /// Within both tolerances: done (brakes to rest when halting).
    EndOfSteering = 0,
    /// Within the position tolerance: turn to β regardless of position.
    OrientationOnly = 1,
    /// Plain seek: closer than `D_η`, or no orientation correction needed.
    PositionOnly = 2,
    /// Heading modulated to reach the orientation too.
    #[default]
    Funnelling = 3,
}

/// Everything one update computed, for the front end and the tests.
#[derive(Clone, Copy, Debug, PartialEq, Default, Serialize, Deserialize)]
#[serde(rename_all = "camelCase")]
pub struct Internals {
    /// Mode chosen this step.
    pub mode: Mode,
    /// Distance to the target, m.
    pub d: f32,
    /// Radial angle α (target bearing in the vehicle frame), rad.
    pub alpha: f32,
    /// Interpolated η, rad (0 when not looked up).
    pub eta: f32,
    /// Δη = β − (θ + α + η), rad.
    pub delta_eta: f32,
    /// Applied modulation μ, rad.
    pub mu: f32,
    /// Bound on |μ| this step, rad.
    pub mu_max: f32,
    /// Modulated heading γ (absolute), rad.
    pub gamma: f32,
    /// Whether the table says reachable at the desired speed.
    pub reachable: bool,
    /// Desired speed used (fallback when unreachable), m/s.
    pub v_dt: f32,
    /// Where this update asked the table (the aim: goal centre, entry
    /// point or relaxed point), distance from the vehicle, m; 0 when it
    /// did not ask (tolerance phase, terminal pursuit). With `aim_alpha`
    /// and `v_query` it says which seek the η above predicts, so the
    /// predicted path can be drawn ([`crate::funnelling::ghost`]).
    #[serde(default)]
    pub aim_d: f32,
    /// Radial angle of that aim point (vehicle frame), rad.
    #[serde(default)]
    pub aim_alpha: f32,
    /// The desired speed the table was asked with, m/s (v_d after the
    /// halting cap, at least the lowest sampled desired speed).
    #[serde(default)]
    pub v_query: f32,
}
