//! The world above the controllers (paper 000 §6: moving targets,
//! successive targets, many entities): agents, each with its own state,
//! goal queue and funnelling memory, stepped together, with or without
//! avoidance. Stepping allocates nothing: the only buffer, a snapshot of
//! the agents' states for goals that follow other agents, is sized when
//! agents are added.
//!
//! | module | paper | what |
//! |---|---|---|
//! | this one | 000 §6 | [`World`] and [`Agent`]: many agents with goal queues, the plain step, the state records |
//! | [`goals`] | 000 §6 | goal-queue entries: motion (static, linear, circle, facing an agent), switch rule, which goals may halt |
//! | [`edit`] | 000 §6, Fig. 5 | edits of a running world: agents added (under the world's bound), pose reset, new goals (queue and memory restart), the seeded random crowd |
//! | [`avoid_step`] | 000 §7 | the step with avoidance: plan every funnel, avoid, step |
//! | [`split`] | 000 §6, Fig. 6 | a world split into contiguous slices that step alone (facing links kept inside one), for the lab's stepping workers |
//! | [`scenario`] | — | the scenario JSON schema (degrees in files) and its validation: positional arrays refused, agents × steps bounded |
//! | [`precision`] | — | the coordinate range where f32 resolves a quarter of one step (slowest goal speed × dt), measured; checked on every agent and goal |
//! | [`proximity`] | — | avoidance metrics: minimum pairwise distance, overlapping pairs, obstacle contacts, deadlocks, oriented entries |

pub mod avoid_step;
pub mod edit;
pub mod goals;
pub mod precision;
pub mod proximity;
pub mod scenario;
pub mod split;

use crate::avoidance::{
    avoider::Avoider, config::AvoidanceConfig, config::AvoidanceMethod, config::Obstacle,
};
use crate::base::metrics::PathMetrics;
use crate::base::vehicle::{ParamError, VehicleParams, VehicleState};
use crate::funnelling::config::FunnelConfig;
use crate::funnelling::controller::ControllerKind;
use crate::funnelling::goal::{FunnelMemory, Goal};
use crate::funnelling::relaxed::{RelaxedConfig, RelaxedInternals};
use crate::funnelling::seek::{seek_step, seek_step_committed_unicycle};
use crate::funnelling::table::format::TableError;
use crate::funnelling::table::lookup::EtaTable;
use crate::funnelling::update::{Internals, Mode, Update};
use crate::world::goals::{GoalMotion, GoalSpec, SwitchRule};

/// One agent.
#[derive(Clone, Debug, PartialEq)]
pub struct Agent {
    /// Kinematic state.
    pub state: VehicleState,
    /// Goal queue (changed directly, not through the world's edits: call
    /// [`World::queues_changed`] before the next step).
    pub goals: Vec<GoalSpec>,
    /// Index of the current goal (== `goals.len()` when all are done; as
    /// `goals` for direct changes).
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
    /// none, [`World::set_metrics`]).
    pub metrics: PathMetrics,
    /// Time at which the last goal was completed, s.
    pub finished_at: Option<f32>,
    /// `goals[current]` kept inside the agent: a step reads the current
    /// goal from the agent's own record, which the per-agent loop streams
    /// through, instead of from the queue's own allocation, a cache miss
    /// per agent per step in a big world. Same bits. Every change of `goals` or `current` goes
    /// through [`Agent::refresh_spec`] ([`World::queues_changed`] for
    /// direct changes); debug builds check it at each plan.
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

    /// True once every goal is done: each goal's [`SwitchRule`] has fired
    /// (an agent without goals is done from the start).
    ///
    /// What the last goal's rule promises when it fires:
    /// - [`SwitchRule::EndOfSteering`]: the controller declared
    ///   End_of_Steering, so the vehicle was inside both tolerances
    ///   (`D_tol`, `ε_tol`) at that update. For a *halting* goal the test
    ///   is on the pose the vehicle will rest at, not on the current one
    ///   (paper 000 Fig. 5 as [`tolerance_phase`] implements it): the
    ///   whole braking distance lies inside `D_tol` and the heading, now
    ///   and after the rotation still to come, inside `ε_tol`. The vehicle
    ///   may still be moving then (braking at full deceleration with its
    ///   heading held); it comes to rest inside both tolerances a little
    ///   later, which [`Agent::at_rest`] says.
    /// - [`SwitchRule::Tolerance`]: the position tolerance was entered
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

/// Agents a new [`World`] accepts until [`World::set_max_agents`] says
/// otherwise: a guard against a runaway loop or a typo filling memory (an
/// agent with [`RANDOM_GOALS`](edit::RANDOM_GOALS) goals takes about
/// 1.2 KB, so a million take about 1.2 GB), with room for the native
/// crowds of half a million agents the parallel step is built for. The
/// page's bound is [`MAX_AGENTS`](edit::MAX_AGENTS).
pub const DEFAULT_MAX_AGENTS: usize = 1_000_000;

/// Agents per parallel task of a step: a task's updates (about 0.1 µs
/// each natively) then outweigh handing it to a thread many times over.
pub const PARALLEL_CHUNK: usize = 512;

/// The world: agents with their goal queues, stepped together at the
/// vehicle's `dt`.
///
/// The η table is not part of the world: every [`World::step`] borrows
/// it, so one table serves many worlds. It must have been built for the
/// world's vehicle limits ([`World::check_table`]; [`World::try_step`]
/// checks and steps).
///
/// Natively a step updates the agents on every core of the current rayon
/// pool ([`PARALLEL_CHUNK`] agents per task, worlds of fewer than two
/// chunks on the calling thread); the states are the same bits on one
/// thread or many, because within a step each agent reads only its own
/// record and the states of the start of the step. Run a world on one
/// thread by stepping it inside a one-thread pool's `install`. On wasm32
/// a step is sequential (the lab's page splits a world over Web Workers,
/// [`World::split_ranges`]).
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
    /// Avoidance between agents and of the obstacles (off by
    /// default). Set with [`World::set_avoidance`].
    pub avoidance: AvoidanceConfig,
    /// Static obstacles (avoided when the avoidance is on).
    pub obstacles: Vec<Obstacle>,
    pub(crate) snapshot: Vec<VehicleState>,
    /// Agents whose queue holds a goal facing an agent
    /// ([`GoalMotion::FaceAgent`]), the only goals that read the snapshot:
    /// while there are none and the avoidance (which reads it too) is off,
    /// a step takes no snapshot (a pass over every agent's record before
    /// the update pass, a large share of the loop's own cost in a big
    /// world; same bits). Kept by every edit of a queue.
    pub(crate) facing: usize,
    pub(crate) preferred: Vec<(f32, f32)>,
    /// The avoidance's buffers and this step's commands.
    pub avoider: Avoider,
    /// Whether a step adds to every agent's [`Agent::metrics`] (on unless
    /// set with [`World::set_metrics`]).
    pub(crate) metrics_on: bool,
    /// Most agents the world accepts ([`World::set_max_agents`]).
    pub(crate) max_agents: usize,
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
            avoidance: AvoidanceConfig::default(),
            obstacles: Vec::new(),
            snapshot: Vec::new(),
            facing: 0,
            preferred: Vec::new(),
            avoider: Avoider::default(),
            metrics_on: true,
            max_agents: DEFAULT_MAX_AGENTS,
        })
    }

    /// Keeps (`true`, the default) or stops keeping every agent's path
    /// metrics ([`Agent::metrics`]: length, curvature, limit checks), which
    /// only studies, the command line and tests read.
    ///
    /// The lab's page never reads them, and keeping them costs a square
    /// root, an angle difference and the limit checks per agent per step.
    /// The states are the same bits either way: nothing in a step reads
    /// the metrics.
    pub fn set_metrics(&mut self, on: bool) {
        self.metrics_on = on;
    }

    /// Whether steps keep the agents' path metrics ([`World::set_metrics`]).
    #[must_use]
    pub fn metrics_on(&self) -> bool {
        self.metrics_on
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
        if kind != self.controller {
            // The relaxed search's internals mean nothing to the other
            // controller; the rest is refreshed by the next step or by
            // `plan` (which needs the η table this call does not have).
            for a in &mut self.agents {
                a.relaxed = RelaxedInternals::default();
            }
        }
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

    /// Fills every agent's internals (and relaxed internals) with what its
    /// controller chooses for the current state — the plan the next
    /// [`World::step`] makes — without moving anything or changing the mode
    /// memory (so the first trajectory row reports a mode that is true at
    /// t = 0). [`World::add_agent`] has no η table, so until this
    /// runs (or the first step) a new agent's internals are provisional:
    /// exact inside the tolerance, else Funnelling towards the goal centre.
    /// Call it after adding agents or changing the controller (stepping
    /// does not need it). Constant cost per agent, no allocation.
    pub fn plan(&mut self, table: &EtaTable) {
        let (planner, agents) = self.planning(table);
        for a in agents {
            if a.done() {
                a.hold(a.cruise_speed());
            } else {
                planner.plan(a, false);
            }
        }
    }

    /// What the world keeps about its agents' goal queues, recomputed after
    /// `agents[i].goals` or `.current` were changed directly (the world's
    /// own edits keep it): each agent's current goal (`Agent::spec`'s
    /// copy) and the count of queues facing an agent (`World::facing`).
    pub fn queues_changed(&mut self) {
        for a in &mut self.agents {
            a.refresh_spec();
        }
        self.facing = self.agents.iter().filter(|a| faces(&a.goals)).count();
    }

    /// Checks that `table` was built for this world's vehicle limits, bit
    /// for bit (η is only exact for the limits it was simulated with).
    ///
    /// # Errors
    /// [`TableError::ParamsMismatch`] naming the first limit that differs,
    /// with the table's value and the world's.
    pub fn check_table(&self, table: &EtaTable) -> Result<(), TableError> {
        table.check_params(&self.params)
    }

    /// [`World::step`] on a table checked first ([`World::check_table`]):
    /// what a library user calls. The check compares nine numbers, nothing
    /// beside a step's cost.
    ///
    /// # Errors
    /// A table built for other vehicle limits; nothing is stepped then.
    pub fn try_step(&mut self, table: &EtaTable) -> Result<(), TableError> {
        self.check_table(table)?;
        self.step(table);
        Ok(())
    }

    /// Advances every agent by one time step. Agents see each other's
    /// states from the start of the step, so the order does not matter
    /// (and natively they are updated on every core, see [`World`]).
    ///
    /// The table is not checked: the lab's page steps on the table it has
    /// while the one for newly set limits is being built (its predictions
    /// are then approximate, and the page says so). Check it once with
    /// [`World::check_table`], or step with [`World::try_step`].
    pub fn step(&mut self, table: &EtaTable) {
        self.step_each(table, None);
    }

    /// [`World::step`], then the records [`World::write_state`] writes,
    /// each written as soon as its agent has stepped, while the agent's
    /// memory is at hand (a stepping worker's step and state in one pass
    /// over the agents instead of two; the same floats).
    pub fn step_writing(&mut self, table: &EtaTable, out: &mut Vec<f32>) {
        out.resize(self.agents.len() * STATE_STRIDE, 0.0);
        self.step_each(table, Some(out));
    }

    /// One step, each agent's record written to `out` (when given) once it
    /// has stepped (with the avoidance on, once every agent has: its step
    /// is whole-world).
    #[inline(always)]
    fn step_each(&mut self, table: &EtaTable, out: Option<&mut [f32]>) {
        if self.avoidance.method != AvoidanceMethod::Off {
            self.step_avoiding(table);
            if let Some(out) = out {
                self.write_records(out);
            }
            return;
        }
        let metrics_on = self.metrics_on;
        let parallel = self.parallel_chunk() < self.agents.len();
        let (planner, agents) = self.planning(table);
        let dt = planner.p.dt;
        // The default (our standard controller, a unicycle) is compiled on
        // its own, every choice of controller, reading and vehicle made
        // here once instead of per agent; the same operations, so the same
        // bits.
        if planner.ours_unicycle() {
            let f = planner.funnel;
            let step = |a: &mut Agent| {
                let plan = |u: &mut Update<'_>, _: &mut RelaxedInternals| f.plan_ours(u);
                step_agent(&planner, metrics_on, a, plan, seek_step_committed_unicycle);
            };
            step_agents(agents, parallel, out, &step);
        } else {
            let (kind, f, r) = (planner.kind, planner.funnel, planner.relaxed);
            let step = |a: &mut Agent| {
                let plan = |u: &mut Update<'_>, ri: &mut RelaxedInternals| kind.plan(f, r, u, ri);
                step_agent(&planner, metrics_on, a, plan, |p, s, h, v| {
                    f.seek_step(p, s, h, v);
                });
            };
            step_agents(agents, parallel, out, &step);
        }
        self.time += dt;
    }

    /// What every per-agent loop of a step begins with (plan, step, the
    /// avoidance step): the snapshot of the states at the start of the step
    /// (goals that follow other agents read it), and the planner over it,
    /// beside the agents to update (disjoint borrows of the world).
    pub(crate) fn planning<'a>(
        &'a mut self,
        table: &'a EtaTable,
    ) -> (Planner<'a>, &'a mut [Agent]) {
        let snapshot: &[VehicleState] =
            if self.facing > 0 || self.avoidance.method != AvoidanceMethod::Off {
                for (s, a) in self.snapshot.iter_mut().zip(&self.agents) {
                    *s = a.state;
                }
                &self.snapshot
            } else {
                &[]
            };
        let planner = Planner {
            kind: self.controller,
            funnel: &self.config,
            relaxed: &self.relaxed,
            table,
            p: &self.params,
            t: self.time,
            snapshot,
        };
        (planner, &mut self.agents)
    }

    /// Agents per task of a per-agent loop of a step: [`PARALLEL_CHUNK`]
    /// when the world has at least two chunks of agents and the current
    /// pool more than one thread, else all of them (one task: the calling
    /// thread, no hand-over).
    pub(crate) fn parallel_chunk(&self) -> usize {
        let n = self.agents.len();
        if n >= 2 * PARALLEL_CHUNK && crate::base::parallel::threads() > 1 {
            PARALLEL_CHUNK
        } else {
            n.max(1)
        }
    }

    /// Writes the per-agent state into `out` with stride [`STATE_STRIDE`],
    /// each float at its [`StateField`] offset (the page reads the record by
    /// those names, never by number). `out` is resized if needed.
    pub fn write_state(&self, out: &mut Vec<f32>) {
        out.resize(self.agents.len() * STATE_STRIDE, 0.0);
        self.write_records(out);
    }

    /// Every agent's record into `out` (exactly agents × [`STATE_STRIDE`]).
    fn write_records(&self, out: &mut [f32]) {
        for (a, o) in self.agents.iter().zip(out.chunks_exact_mut(STATE_STRIDE)) {
            write_record(a, o);
        }
    }
}

/// Every agent's `step`, on the calling thread or (`parallel`) the
/// current rayon pool, each agent's record written to `out` (when given)
/// once it has stepped.
#[inline(always)]
fn step_agents(
    agents: &mut [Agent],
    parallel: bool,
    out: Option<&mut [f32]>,
    step: &(impl Fn(&mut Agent) + Sync),
) {
    match (parallel, out) {
        (false, None) => agents.iter_mut().for_each(step),
        (false, Some(out)) => {
            for (a, o) in agents.iter_mut().zip(out.chunks_exact_mut(STATE_STRIDE)) {
                step(a);
                write_record(a, o);
            }
        }
        (true, None) => crate::base::parallel::for_each_mut(agents, PARALLEL_CHUNK, step),
        (true, Some(out)) => crate::base::parallel::for_each_mut_with(
            agents,
            out,
            STATE_STRIDE,
            PARALLEL_CHUNK,
            |a, o| {
                step(a);
                write_record(a, o);
            },
        ),
    }
}

/// One agent's share of a plain step (no avoidance): plan towards the
/// current goal (`plan`, the world's controller) and step (`seek`, its
/// seek step), or, all goals done, rest if the last goal halts, else
/// cruise on; then the path metrics. Reads nothing of another agent but
/// the planner's snapshot, so agents step in any order, on any thread.
#[inline(always)]
fn step_agent(
    planner: &Planner<'_>,
    metrics_on: bool,
    a: &mut Agent,
    plan: impl FnOnce(&mut Update<'_>, &mut RelaxedInternals) -> Internals,
    seek: impl FnOnce(&VehicleParams, &mut VehicleState, f32, f32),
) {
    let p = planner.p;
    let prev = a.state;
    if a.done() {
        let speed = a.cruise_speed();
        let hold = a.state.theta;
        seek_step(p, &mut a.state, hold, speed);
        a.hold(speed);
    } else {
        let spec = planner.plan_by(a, true, plan);
        seek(p, &mut a.state, a.internals.gamma, a.internals.v_dt);
        advance_queue(a, &spec, planner.t);
    }
    if metrics_on {
        a.metrics.add(p, &prev, &a.state);
    }
}

/// One agent's record of [`World::write_state`] into `o`
/// ([`STATE_STRIDE`] floats).
#[inline(always)]
fn write_record(a: &Agent, o: &mut [f32]) {
    use StateField as F;
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

/// What planning an agent needs from its world: the controller, its
/// settings and the time and states the goals are read at. One piece for
/// the three per-agent loops ([`World::plan`], [`World::step`], the
/// avoidance step), which differ only in what they do with the plan.
pub(crate) struct Planner<'a> {
    pub(crate) kind: ControllerKind,
    pub(crate) funnel: &'a FunnelConfig,
    pub(crate) relaxed: &'a RelaxedConfig,
    pub(crate) table: &'a EtaTable,
    pub(crate) p: &'a VehicleParams,
    pub(crate) t: f32,
    pub(crate) snapshot: &'a [VehicleState],
}

impl Planner<'_> {
    /// Plans agent `a` (not done) towards its current goal at `t`: the goal
    /// goes to `goal_now`, the plan to `internals`. `advance` lets the plan
    /// update the agent's mode memory (a step); without it the memory is
    /// left as it was ([`World::plan`]). Returns the goal's spec, for
    /// [`advance_queue`].
    #[inline]
    pub(crate) fn plan(&self, a: &mut Agent, advance: bool) -> GoalSpec {
        let (kind, f, r) = (self.kind, self.funnel, self.relaxed);
        self.plan_by(a, advance, |u, ri| kind.plan(f, r, u, ri))
    }

    /// True when the world's controller is our standard one on a unicycle
    /// ([`ControllerKind::is_ours_unicycle`]): a step then plans every
    /// agent with [`FunnelConfig::plan_ours`] and moves it with
    /// [`seek_step_committed_unicycle`].
    #[inline]
    pub(crate) fn ours_unicycle(&self) -> bool {
        self.kind.is_ours_unicycle(self.funnel, self.p)
    }

    /// [`Planner::plan`] with the controller's plan given (`plan`: the
    /// world's controller, or the same one with its choices made once
    /// per step).
    #[inline(always)]
    pub(crate) fn plan_by(
        &self,
        a: &mut Agent,
        advance: bool,
        plan: impl FnOnce(&mut Update<'_>, &mut RelaxedInternals) -> Internals,
    ) -> GoalSpec {
        debug_assert_eq!(Some(&a.spec), a.goals.get(a.current), "a stale goal spec");
        let spec = a.spec;
        debug_assert!(
            !self.snapshot.is_empty() || !matches!(spec.motion, GoalMotion::FaceAgent { .. }),
            "a goal facing an agent, and no snapshot (World::facing not kept)"
        );
        let goal = spec.at(self.t, self.snapshot);
        a.goal_now = goal;
        let mut kept = a.memory;
        let mem = if advance { &mut a.memory } else { &mut kept };
        let mut u = Update {
            table: self.table,
            params: self.p,
            state: &mut a.state,
            goal: &goal,
            memory: mem,
        };
        a.internals = plan(&mut u, &mut a.relaxed);
        spec
    }
}

/// After an agent's update on goal `spec` at time `t`: moves on to the next
/// goal when the switch rule says so (a goal that follows another agent
/// completes like any other), and records the finishing time.
#[inline]
pub(crate) fn advance_queue(a: &mut Agent, spec: &GoalSpec, t: f32) {
    let switch = match spec.switch {
        SwitchRule::EndOfSteering => a.internals.mode == Mode::EndOfSteering,
        SwitchRule::Tolerance => a.memory.position_met,
    };
    if switch {
        a.current += 1;
        a.refresh_spec();
        a.memory = a
            .goals
            .get(a.current)
            .map_or_else(FunnelMemory::default, GoalSpec::fresh_memory);
        if a.done() {
            a.finished_at = Some(t);
        }
    }
}

/// True if a queue holds a goal that faces an agent (reads the snapshot).
pub(crate) fn faces(goals: &[GoalSpec]) -> bool {
    goals
        .iter()
        .any(|g| matches!(g.motion, GoalMotion::FaceAgent { .. }))
}

/// The part of the first plan that needs no η table (see [`World::plan`]):
/// the goal measured from the vehicle, and the position-tolerance phase of
/// paper 000 Fig. 5, which settles the mode inside the tolerance; outside,
/// Funnelling towards the centre until the table is consulted. Also what
/// the lab shows before its table has arrived (its first frame).
#[must_use]
pub fn provisional_plan(p: &VehicleParams, s: &VehicleState, g: &Goal) -> Internals {
    let rel = g.pos - s.pos;
    let d = rel.length();
    let bearing = if d > 1e-6 {
        crate::base::trig::atan2(rel.y, rel.x)
    } else {
        s.theta
    };
    let mut out = Internals {
        mode: Mode::Funnelling,
        d,
        alpha: crate::base::angle::diff(bearing, s.theta),
        gamma: bearing,
        v_dt: if g.halting {
            g.speed.min(crate::funnelling::approach::halting_speed(
                p,
                d - 0.9 * g.d_tol,
            ))
        } else {
            g.speed
        },
        reachable: true,
        ..Default::default()
    };
    let mut mem = FunnelMemory::default();
    crate::funnelling::approach::tolerance_phase(p, s, g, &mut mem, d, &mut out);
    out
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
