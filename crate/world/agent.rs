//! One agent of a [`World`](crate::world::World): its state, goal queue,
//! funnelling memory and the internals of its last update, and when it is
//! done and at rest.

use crate::base::metrics::PathMetrics;
use crate::base::vehicle::VehicleState;
use crate::funnelling::goal::{FunnelMemory, Goal};
use crate::funnelling::relaxed::RelaxedInternals;
use crate::funnelling::update::{Internals, Mode};
use crate::world::goals::GoalSpec;

/// One agent, read through [`World::agents`](crate::world::World::agents)
/// and [`World::agent`](crate::world::World::agent); changed only by the
/// world's edits, which validate (a user cannot build one: the world keeps
/// a copy of its current goal).
#[derive(Clone, Debug, PartialEq)]
pub struct Agent {
    /// Kinematic state.
    pub state: VehicleState,
    /// Goal queue ([`World::set_goals`](crate::world::World::set_goals)
    /// replaces it).
    pub goals: Vec<GoalSpec>,
    /// Index of the current goal (== `goals.len()` when all are done).
    pub current: usize,
    /// Mode-logic memory for the current goal.
    pub memory: FunnelMemory,
    /// Internals of the last update.
    pub internals: Internals,
    /// Relaxed-search internals of the last update (paper 001 Fig. 7:
    /// 𝒜, F, T, α_r, Δη, relaxed point); default when the standard
    /// controller runs or the position is met.
    pub relaxed: RelaxedInternals,
    /// The current goal as it was last evaluated (moving goals move).
    pub goal_now: Goal,
    /// Path metrics since the start (left empty while the world keeps
    /// none, [`World::set_metrics`](crate::world::World::set_metrics)).
    pub metrics: PathMetrics,
    /// Time at which the last goal was completed, s.
    pub finished_at: Option<f32>,
    /// `goals[current]` kept inside the agent: a step reads the current
    /// goal from the agent's own record, which the per-agent loop streams
    /// through, instead of from the queue's own allocation, a cache miss
    /// per agent per step in a big world. Same bits. Every change of `goals` or `current` goes
    /// through [`Agent::refresh_spec`]; debug builds check it at each plan.
    pub(crate) spec: GoalSpec,
}

impl Agent {
    /// Copies the current goal into [`Agent::spec`] (kept as it was once
    /// every goal is done: nothing reads it then).
    pub(crate) fn refresh_spec(&mut self) {
        if let Some(g) = self.goals.get(self.current) {
            self.spec = *g;
        }
    }

    /// True once every goal is done: each goal's [`SwitchRule`](crate::world::goals::SwitchRule) has fired
    /// (an agent without goals is done from the start).
    ///
    /// What the last goal's rule promises when it fires:
    /// - [`SwitchRule::EndOfSteering`](crate::world::goals::SwitchRule::EndOfSteering): the controller declared
    ///   End_of_Steering, so the vehicle was inside both tolerances
    ///   (`D_tol`, `ε_tol`) at that update. For a *halting* goal the test
    ///   is on the pose the vehicle will rest at, not on the current one
    ///   (paper 000 Fig. 5 as [`tolerance_phase`] implements it): the
    ///   whole braking distance lies inside `D_tol` and the heading, now
    ///   and after the rotation still to come, inside `ε_tol`. The vehicle
    ///   may still be moving then (braking at full deceleration with its
    ///   heading held); it comes to rest inside both tolerances a little
    ///   later, which [`Agent::at_rest`] says.
    /// - [`SwitchRule::Tolerance`](crate::world::goals::SwitchRule::Tolerance): the position tolerance was entered
    ///   (for a halting goal, with the braking distance inside it); the
    ///   orientation is not checked.
    ///
    /// Past its last goal an agent rests if that goal halts, else cruises
    /// on at its speed, heading held ([`Agent::cruise_speed`]).
    ///
    /// [`tolerance_phase`]: crate::funnelling::approach::tolerance_phase
    #[must_use]
    pub fn done(&self) -> bool {
        self.current >= self.goals.len()
    }

    /// True once the agent is [`done`](Agent::done) and stopped: forward
    /// speed exactly 0 and angular speed at most [`REST_OMEGA`] (the
    /// heading then turns by less than `REST_OMEGA / kd`, 1.7e-5 rad for
    /// the pedestrian, before it stops). Only an agent whose last goal
    /// halts (or that had no goal) comes to rest; one past a non-halting
    /// goal cruises on and is never at rest.
    #[must_use]
    pub fn at_rest(&self) -> bool {
        self.done() && self.state.v == 0.0 && self.state.omega.abs() <= REST_OMEGA
    }

    /// The speed of an agent past its last goal: rest if that goal halts
    /// (or there was none), else cruise on at its speed.
    #[must_use]
    pub fn cruise_speed(&self) -> f32 {
        self.goals
            .last()
            .filter(|g| !g.goal.halting)
            .map_or(0.0, |g| g.goal.speed)
    }

    /// Records that the agent, past its last goal, holds its heading at
    /// `speed` (End_of_Steering; no relaxed search).
    pub(crate) fn hold(&mut self, speed: f32) {
        self.relaxed = RelaxedInternals::default();
        self.internals = Internals {
            mode: Mode::EndOfSteering,
            v_dt: speed,
            gamma: self.state.theta,
            ..Default::default()
        };
    }
}

/// Angular speed below which a done agent counts as at rest
/// ([`Agent::at_rest`]), rad/s: past a halting goal the heading is held,
/// so ω decays geometrically (by `1 − kd·dt` a step) and reaches 0 only
/// when f32 underflows, seconds later.
pub const REST_OMEGA: f32 = 1e-4;
