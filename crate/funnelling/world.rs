//! A world of agents, each with its own state, goal queue and funnelling
//! memory, stepped together (paper 000 §6: moving targets, successive
//! targets, many entities). Stepping allocates nothing: the only buffer,
//! a snapshot of the agents' states for goals that follow other agents, is
//! sized when agents are added.

use glam::Vec2;
use serde::{Deserialize, Serialize};

use crate::funnel::{FunnelConfig, FunnelMemory, Goal, Internals, Mode};
use crate::metrics::PathMetrics;
use crate::relaxed::{ControllerKind, RelaxedConfig, RelaxedInternals};
use crate::seek::seek_step;
use crate::table::EtaTable;
use crate::vehicle::{ParamError, VehicleParams, VehicleState};

/// How a goal moves (paper 000 §1: "a possibly moving target").
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

impl GoalSpec {
    /// The goal at world time `t`, given the agents' states `states`.
    #[must_use]
    pub fn at(&self, t: f32, states: &[VehicleState]) -> Goal {
        let mut g = self.goal;
        match self.motion {
            GoalMotion::Static => {}
            GoalMotion::Linear { velocity } => g.pos += velocity * t,
            GoalMotion::Circle {
                center,
                angular_speed,
            } => {
                let r0 = self.goal.pos - center;
                let rot = crate::trig::unit(angular_speed * t);
                g.pos = center + rot.rotate(r0);
                g.beta = self.goal.beta + angular_speed * t;
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

/// One agent.
#[derive(Clone, Debug, PartialEq)]
pub struct Agent {
    /// Kinematic state.
    pub state: VehicleState,
    /// Goal queue.
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
    /// Path metrics since the start.
    pub metrics: PathMetrics,
    /// Time at which the last goal was completed, s.
    pub finished_at: Option<f32>,
}

impl Agent {
    /// True once every goal is done.
    #[must_use]
    pub fn done(&self) -> bool {
        self.current >= self.goals.len()
    }
}

/// The world.
#[derive(Clone, Debug, PartialEq)]
pub struct World {
    /// Vehicle parameters shared by every agent.
    pub params: VehicleParams,
    /// Funnelling settings shared by every agent.
    pub config: FunnelConfig,
    /// Which controller steers the agents (standard unless set).
    pub controller: ControllerKind,
    /// Relaxed-controller settings (used when `controller` is relaxed).
    pub relaxed: RelaxedConfig,
    /// The agents.
    pub agents: Vec<Agent>,
    /// Simulated time, s.
    pub time: f32,
    snapshot: Vec<VehicleState>,
}

impl World {
    /// An empty world.
    ///
    /// # Errors
    /// Invalid vehicle parameters or settings.
    pub fn new(params: VehicleParams, config: FunnelConfig) -> Result<Self, ParamError> {
        params.validate()?;
        config.validate()?;
        Ok(Self {
            params,
            config,
            controller: ControllerKind::Standard,
            relaxed: RelaxedConfig::default(),
            agents: Vec::new(),
            time: 0.0,
            snapshot: Vec::new(),
        })
    }

    /// Chooses the controller (paper 001: standard or relaxed funnelling).
    ///
    /// # Errors
    /// Invalid relaxed settings.
    pub fn set_controller(
        &mut self,
        kind: ControllerKind,
        relaxed: RelaxedConfig,
    ) -> Result<(), ParamError> {
        relaxed.validate()?;
        self.controller = kind;
        self.relaxed = relaxed;
        Ok(())
    }

    /// Relaxed internals of agent `i` from its last update (for the
    /// bindings and the front end), `None` if there is no such agent.
    #[must_use]
    pub fn relaxed_internals(&self, i: usize) -> Option<&RelaxedInternals> {
        self.agents.get(i).map(|a| &a.relaxed)
    }

    /// Adds an agent; returns its index.
    ///
    /// # Errors
    /// An invalid state or goal (NaN, out of range, an agent index that
    /// does not exist yet is allowed only if it will: checked in `step`).
    pub fn add_agent(
        &mut self,
        state: VehicleState,
        goals: Vec<GoalSpec>,
    ) -> Result<usize, ParamError> {
        state.validate(&self.params)?;
        for g in &goals {
            g.goal.validate(&self.params)?;
            match g.motion {
                GoalMotion::Linear { velocity } => {
                    crate::vehicle::check_range("motion.velocity.x", velocity.x, -100.0, 100.0)?;
                    crate::vehicle::check_range("motion.velocity.y", velocity.y, -100.0, 100.0)?;
                }
                GoalMotion::Circle {
                    center,
                    angular_speed,
                } => {
                    crate::vehicle::check_range("motion.center.x", center.x, -1e6, 1e6)?;
                    crate::vehicle::check_range("motion.center.y", center.y, -1e6, 1e6)?;
                    crate::vehicle::check_range(
                        "motion.angularSpeed",
                        angular_speed,
                        -100.0,
                        100.0,
                    )?;
                }
                GoalMotion::FaceAgent { distance, .. } => {
                    crate::vehicle::check_range("motion.distance", distance, 0.0, 1e3)?;
                }
                GoalMotion::Static => {}
            }
        }
        let goal_now = goals.first().map(|g| g.goal).unwrap_or_default();
        self.agents.push(Agent {
            state,
            goals,
            current: 0,
            memory: FunnelMemory::default(),
            internals: Internals {
                mode: Mode::EndOfSteering,
                ..Default::default()
            },
            relaxed: RelaxedInternals::default(),
            goal_now,
            metrics: PathMetrics::default(),
            finished_at: None,
        });
        self.snapshot.push(state);
        Ok(self.agents.len() - 1)
    }

    /// Advances every agent by one time step. Agents see each other's
    /// states from the start of the step, so the order does not matter.
    pub fn step(&mut self, table: &EtaTable) {
        for (s, a) in self.snapshot.iter_mut().zip(&self.agents) {
            *s = a.state;
        }
        let p = self.params;
        let t = self.time;
        for a in &mut self.agents {
            let prev = a.state;
            if a.done() {
                // All goals done: rest if the last goal halts, else cruise on.
                let halt = a.goals.last().is_none_or(|g| g.goal.halting);
                let speed = if halt {
                    0.0
                } else {
                    a.goals.last().map_or(0.0, |g| g.goal.speed)
                };
                let hold = a.state.theta;
                seek_step(&p, &mut a.state, hold, speed);
                a.relaxed = RelaxedInternals::default();
                a.internals = Internals {
                    mode: Mode::EndOfSteering,
                    v_dt: speed,
                    gamma: a.state.theta,
                    ..Default::default()
                };
            } else {
                let spec = a.goals[a.current];
                let goal = spec.at(t, &self.snapshot);
                a.goal_now = goal;
                a.internals = match self.controller {
                    ControllerKind::Standard => {
                        self.config
                            .step(table, &p, &mut a.state, &goal, &mut a.memory)
                    }
                    ControllerKind::Relaxed => self.relaxed.step(
                        &self.config,
                        table,
                        &p,
                        &mut a.state,
                        &goal,
                        &mut a.memory,
                        &mut a.relaxed,
                    ),
                };
                let switch = match spec.switch {
                    SwitchRule::EndOfSteering => a.internals.mode == Mode::EndOfSteering,
                    SwitchRule::Tolerance => a.memory.position_met,
                };
                // A goal that follows another agent never completes while
                // that agent moves on: it completes like any other.
                if switch {
                    a.current += 1;
                    a.memory = FunnelMemory::default();
                    if a.done() {
                        a.finished_at = Some(t);
                    }
                }
            }
            a.metrics.add(&p, &prev, &a.state);
        }
        self.time += p.dt;
    }

    /// Writes the per-agent state into `out` with stride [`STATE_STRIDE`],
    /// each float at its [`StateField`] offset (the page reads the record by
    /// those names, never by number). `out` is resized if needed.
    pub fn write_state(&self, out: &mut Vec<f32>) {
        use StateField as F;
        out.resize(self.agents.len() * STATE_STRIDE, 0.0);
        for (a, o) in self.agents.iter().zip(out.chunks_exact_mut(STATE_STRIDE)) {
            let i = &a.internals;
            let g = &a.goal_now;
            let mut put = |f: StateField, v: f32| o[f as usize] = v;
            put(F::X, a.state.pos.x);
            put(F::Y, a.state.pos.y);
            put(F::Theta, a.state.theta);
            put(F::V, a.state.v);
            put(F::Omega, a.state.omega);
            put(F::Mode, f32::from(i.mode as u8));
            put(F::D, i.d);
            put(F::Alpha, i.alpha);
            put(F::Eta, i.eta);
            put(F::DeltaEta, i.delta_eta);
            put(F::Mu, i.mu);
            put(F::Gamma, i.gamma);
            put(F::Reachable, f32::from(u8::from(i.reachable)));
            put(F::VDt, i.v_dt);
            put(F::GoalX, g.pos.x);
            put(F::GoalY, g.pos.y);
            put(F::GoalBeta, g.beta);
            put(F::GoalDTol, g.d_tol);
            put(F::GoalEpsTol, g.eps_tol);
        }
    }
}

/// One float of an agent's record in [`World::write_state`]; the
/// discriminant is its offset. Defined once here so that the writer, the
/// bindings' export (`StateField` in JavaScript) and the page agree by name.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[repr(u8)]
#[allow(missing_docs)] // the names are the quantities of `Internals` and `Goal`
pub enum StateField {
    X = 0,
    Y,
    Theta,
    V,
    Omega,
    /// [`Mode`] as its number.
    Mode,
    D,
    Alpha,
    Eta,
    DeltaEta,
    Mu,
    Gamma,
    /// 1 reachable at v_dt, else 0.
    Reachable,
    VDt,
    GoalX,
    GoalY,
    GoalBeta,
    GoalDTol,
    GoalEpsTol,
}

impl StateField {
    /// Every field in offset order: `ALL[k] as usize == k` (checked below).
    pub const ALL: [StateField; STATE_STRIDE] = {
        use StateField as F;
        [
            F::X,
            F::Y,
            F::Theta,
            F::V,
            F::Omega,
            F::Mode,
            F::D,
            F::Alpha,
            F::Eta,
            F::DeltaEta,
            F::Mu,
            F::Gamma,
            F::Reachable,
            F::VDt,
            F::GoalX,
            F::GoalY,
            F::GoalBeta,
            F::GoalDTol,
            F::GoalEpsTol,
        ]
    };
}

/// Floats per agent in [`World::write_state`]: one past the last field.
pub const STATE_STRIDE: usize = StateField::GoalEpsTol as usize + 1;

const _: () = {
    let mut k = 0;
    while k < STATE_STRIDE {
        assert!(
            StateField::ALL[k] as usize == k,
            "StateField::ALL is in offset order"
        );
        k += 1;
    }
};
