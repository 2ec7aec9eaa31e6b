//! The [`World`]: many agents with goal queues, stepped together (the plain
//! step; the step with avoidance is in [`avoid_step`](crate::world::avoid_step)),
//! and its record writer.

use crate::avoidance::{
    avoider::Avoider, config::AvoidanceConfig, config::AvoidanceMethod, config::Obstacle,
};
use crate::base::vehicle::{ParamError, VehicleParams, VehicleState};
use crate::funnelling::config::FunnelConfig;
use crate::funnelling::controller::ControllerKind;
use crate::funnelling::relaxed::{RelaxedConfig, RelaxedInternals};
use crate::funnelling::seek::{seek_step, seek_step_committed_unicycle};
use crate::funnelling::table::format::TableError;
use crate::funnelling::table::lookup::EtaTable;
use crate::funnelling::update::{Internals, Update};
use crate::world::agent::Agent;
use crate::world::goals::{GoalMotion, GoalSpec};
use crate::world::planner::{advance_queue, Planner};
use crate::world::state_field::{write_record, STATE_STRIDE};

/// Agents a new [`World`] accepts until [`World::set_max_agents`] says
/// otherwise: a guard against a runaway loop or a typo filling memory (an
/// agent with [`RANDOM_GOALS`](crate::world::edit::RANDOM_GOALS) goals takes about
/// 1.2 KB, so a million take about 1.2 GB), with room for the native
/// crowds of half a million agents the parallel step is built for. The
/// page's bound is [`MAX_AGENTS`](crate::world::edit::MAX_AGENTS).
pub const DEFAULT_MAX_AGENTS: usize = 1_000_000;

/// Agents per parallel task of a step: a task's updates (about 0.1 µs
/// each natively) then outweigh handing it to a thread many times over.
pub const PARALLEL_CHUNK: usize = 512;

/// The world: agents with their goal queues, stepped together at the
/// vehicle's `dt`.
///
/// The η table is not part of the world: every [`World::step`] borrows
/// it, so one table serves many worlds. It must have been built for the
/// world's vehicle limits: every call that plans or steps
/// ([`World::plan`], [`World::step`], [`World::step_writing`]) checks it
/// first ([`World::check_table`]) and refuses one built for other limits,
/// unless the world was told to accept that ([`World::allow_other_table`]).
///
/// The agents and settings are read through methods ([`World::agents`],
/// [`World::params`], …) and changed only through methods that validate
/// ([`World::add_agent`], [`World::set_pose`], [`World::set_goals`],
/// [`World::set_params`], …): a world never holds more agents than its
/// bound ([`World::max_agents`]), a value that is not finite, or an agent
/// its step buffers do not know.
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
    /// Vehicle parameters shared by every agent ([`World::params`]).
    pub(super) params: VehicleParams,
    /// Funnelling settings shared by every agent ([`World::config`]).
    pub(super) config: FunnelConfig,
    /// Which controller steers the agents (standard unless set).
    pub(super) controller: ControllerKind,
    /// Relaxed-controller settings (used when `controller` is relaxed).
    pub(super) relaxed: RelaxedConfig,
    /// The agents; the snapshot below has one state per agent, always.
    pub(super) agents: Vec<Agent>,
    /// Simulated time, s.
    pub(super) time: f32,
    /// Avoidance between agents and of the obstacles (off by
    /// default). Set with [`World::set_avoidance`].
    pub(super) avoidance: AvoidanceConfig,
    /// Static obstacles (avoided when the avoidance is on).
    pub(super) obstacles: Vec<Obstacle>,
    pub(super) snapshot: Vec<VehicleState>,
    /// Agents whose queue holds a goal facing an agent
    /// ([`GoalMotion::FaceAgent`]), the only goals that read the snapshot:
    /// while there are none and the avoidance (which reads it too) is off,
    /// a step takes no snapshot (a pass over every agent's record before
    /// the update pass, a large share of the loop's own cost in a big
    /// world; same bits). Kept by every edit of a queue.
    pub(super) facing: usize,
    pub(super) preferred: Vec<(f32, f32)>,
    /// The avoidance's buffers and this step's commands.
    pub(super) avoider: Avoider,
    /// Whether a step adds to every agent's [`Agent::metrics`] (on unless
    /// set with [`World::set_metrics`]).
    pub(super) metrics_on: bool,
    /// Most agents the world accepts ([`World::set_max_agents`]).
    pub(super) max_agents: usize,
    /// Whether a step accepts a table built for other vehicle limits
    /// ([`World::allow_other_table`]; off unless set).
    pub(super) other_table: bool,
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
            other_table: false,
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

    /// The agents, in index order (changed only through the world's
    /// edits: [`World::add_agent`], [`World::set_pose`], [`World::set_goals`], …).
    ///
    /// Neither the list nor an agent can be changed past the world's
    /// checks (the bound, finite values, the step buffers' one state per
    /// agent):
    ///
    /// ```compile_fail
    /// # use steering::prelude::*;
    /// let mut w = World::new(VehicleParams::default(), FunnelConfig::default()).unwrap();
    /// w.agents.clear(); // private: the world's buffers hold one value per agent
    /// ```
    ///
    /// ```compile_fail
    /// # use steering::prelude::*;
    /// let mut w = World::new(VehicleParams::default(), FunnelConfig::default()).unwrap();
    /// w.add_agent(VehicleState::default(), Vec::new()).unwrap();
    /// w.agents()[0].state.v = f32::NAN; // read only: `set_pose` validates
    /// ```
    #[must_use]
    pub fn agents(&self) -> &[Agent] {
        &self.agents
    }

    /// Agent `i`'s goal memory, for the crate's own studies that start a
    /// run from a chosen memory (the short-range study's funnelling-only
    /// baseline, crate::studies::short_range). Crate-internal: the public
    /// API edits agents only through the validating methods.
    #[cfg(feature = "studies")]
    pub(crate) fn memory_mut(
        &mut self,
        i: usize,
    ) -> Option<&mut crate::funnelling::goal::FunnelMemory> {
        self.agents.get_mut(i).map(|a| &mut a.memory)
    }

    /// The vehicle parameters every agent shares.
    #[must_use]
    pub fn params(&self) -> &VehicleParams {
        &self.params
    }

    /// Replaces the vehicle parameters; the agents keep their states and
    /// goals. A table built for the old limits is refused from then on
    /// (unless [`World::allow_other_table`]).
    ///
    /// # Errors
    /// An invalid parameter, named (NaN included); nothing is changed then.
    pub fn set_params(&mut self, params: VehicleParams) -> Result<(), ParamError> {
        params.validate()?;
        self.params = params;
        Ok(())
    }

    /// The funnelling settings every agent shares.
    #[must_use]
    pub fn config(&self) -> &FunnelConfig {
        &self.config
    }

    /// Replaces the funnelling settings. Agents keep their state, goals
    /// and mode memory: the next update uses the new settings.
    ///
    /// # Errors
    /// An invalid setting, named; nothing is changed then.
    pub fn set_config(&mut self, config: FunnelConfig) -> Result<(), ParamError> {
        config.validate()?;
        self.config = config;
        Ok(())
    }

    /// Which controller steers the agents ([`World::set_controller`]).
    #[must_use]
    pub fn controller(&self) -> ControllerKind {
        self.controller
    }

    /// The relaxed controller's settings ([`World::set_controller`]).
    #[must_use]
    pub fn relaxed(&self) -> &RelaxedConfig {
        &self.relaxed
    }

    /// Simulated time, s.
    #[must_use]
    pub fn time(&self) -> f32 {
        self.time
    }

    /// The avoidance settings ([`World::set_avoidance`]).
    #[must_use]
    pub fn avoidance(&self) -> &AvoidanceConfig {
        &self.avoidance
    }

    /// The static obstacles ([`World::set_avoidance`]).
    #[must_use]
    pub fn obstacles(&self) -> &[Obstacle] {
        &self.obstacles
    }

    /// The avoidance's buffers and the last step's commands.
    #[must_use]
    pub fn avoider(&self) -> &Avoider {
        &self.avoider
    }

    /// Restarts the avoidance's count of pairwise checks
    /// ([`Avoider::checks`]).
    pub fn reset_avoidance_checks(&mut self) {
        self.avoider.reset_checks();
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
    ///
    /// # Errors
    /// A table built for other vehicle limits ([`World::step`] says
    /// when one is accepted); nothing is planned then.
    pub fn plan(&mut self, table: &EtaTable) -> Result<(), TableError> {
        self.plan_agents(table, 0..self.agents.len())
    }

    /// [`World::plan`] of the agents in `range` only (clipped to the
    /// agents there are): the ones just added, whose plan does not change
    /// any other's. Constant cost per agent planned, whatever the world's
    /// size: the states are gathered only when one of them has a goal
    /// that faces an agent (the only plan that reads other agents).
    ///
    /// # Errors
    /// As [`World::plan`]; nothing is planned then.
    pub fn plan_agents(
        &mut self,
        table: &EtaTable,
        range: core::ops::Range<usize>,
    ) -> Result<(), TableError> {
        self.check_table_in_force(table)?;
        let n = self.agents.len();
        let range = range.start.min(n)..range.end.min(n);
        let facing = self.agents[range.clone()].iter().any(|a| faces(&a.goals));
        if facing {
            for (s, a) in self.snapshot.iter_mut().zip(&self.agents) {
                *s = a.state;
            }
        }
        let planner = Planner {
            kind: self.controller,
            funnel: &self.config,
            relaxed: &self.relaxed,
            table,
            p: &self.params,
            t: self.time,
            snapshot: if facing { &self.snapshot } else { &[] },
        };
        for a in &mut self.agents[range] {
            if a.done() {
                a.hold(a.cruise_speed());
            } else {
                planner.plan(a, false);
            }
        }
        Ok(())
    }

    /// What the world keeps about its agents' goal queues, recomputed after
    /// an edit that changed queues in place (a slice's renumbered facing
    /// links): each agent's current goal (`Agent::spec`'s copy) and the
    /// count of queues facing an agent (`World::facing`).
    pub(super) fn queues_changed(&mut self) {
        for a in &mut self.agents {
            a.refresh_spec();
        }
        self.facing = self.agents.iter().filter(|a| faces(&a.goals)).count();
    }

    /// Checks that `table` was built for this world's vehicle limits, bit
    /// for bit (η is only exact for the limits it was simulated with).
    /// Every call that plans or steps checks it first; this says why one
    /// would be refused before stepping.
    ///
    /// # Errors
    /// [`TableError::ParamsMismatch`] naming the first limit that differs,
    /// with the table's value and the world's.
    pub fn check_table(&self, table: &EtaTable) -> Result<(), TableError> {
        table.check_params(&self.params)
    }

    /// Lets the world plan and step on a table built for other vehicle
    /// limits (`true`), or refuse one (`false`, the default). The η values
    /// of such a table are only approximate for this world: the lab's page
    /// accepts that while the table for newly set limits is being built,
    /// and says so; a library user has no reason to.
    pub fn allow_other_table(&mut self, allowed: bool) {
        self.other_table = allowed;
    }

    /// [`World::check_table`] unless [`World::allow_other_table`] is on.
    fn check_table_in_force(&self, table: &EtaTable) -> Result<(), TableError> {
        if self.other_table {
            Ok(())
        } else {
            self.check_table(table)
        }
    }

    /// Advances every agent by one time step. Agents see each other's
    /// states from the start of the step, so the order does not matter
    /// (and natively they are updated on every core, see [`World`]).
    ///
    /// The table is checked first ([`World::check_table`]: nine numbers
    /// compared, nothing beside a step's cost).
    ///
    /// # Errors
    /// A table built for other vehicle limits (unless
    /// [`World::allow_other_table`]); nothing is stepped then.
    pub fn step(&mut self, table: &EtaTable) -> Result<(), TableError> {
        self.check_table_in_force(table)?;
        self.step_each(table, None);
        Ok(())
    }

    /// [`World::step`], then the records [`World::write_state`] writes,
    /// each written as soon as its agent has stepped, while the agent's
    /// memory is at hand (a stepping worker's step and state in one pass
    /// over the agents instead of two; the same floats).
    ///
    /// # Errors
    /// As [`World::step`]; nothing is stepped or written then.
    pub fn step_writing(&mut self, table: &EtaTable, out: &mut Vec<f32>) -> Result<(), TableError> {
        self.check_table_in_force(table)?;
        out.resize(self.agents.len() * STATE_STRIDE, 0.0);
        self.step_each(table, Some(out));
        Ok(())
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
    /// each float at its [`StateField`](crate::world::StateField) offset (the page reads the record by
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

/// True if a queue holds a goal that faces an agent (reads the snapshot).
pub(crate) fn faces(goals: &[GoalSpec]) -> bool {
    goals
        .iter()
        .any(|g| matches!(g.motion, GoalMotion::FaceAgent { .. }))
}
