//! Planning one agent towards its current goal: what a plan needs from its
//! world ([`Planner`]), the goal queue's advance after an update, and the
//! provisional plan of an agent before the η table is at hand.

use crate::base::vehicle::{VehicleParams, VehicleState};
use crate::funnelling::config::FunnelConfig;
use crate::funnelling::controller::ControllerKind;
use crate::funnelling::goal::{FunnelMemory, Goal};
use crate::funnelling::relaxed::{RelaxedConfig, RelaxedInternals};
use crate::funnelling::table::lookup::EtaTable;
use crate::funnelling::update::{Internals, Mode, Update};
use crate::world::agent::Agent;
use crate::world::goals::{GoalMotion, GoalSpec, SwitchRule};

/// What planning an agent needs from its world: the controller, its
/// settings and the time and states the goals are read at. One piece for
/// the three per-agent loops ([`World::plan`](crate::world::World::plan), [`World::step`](crate::world::World::step), the
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
    /// left as it was ([`World::plan`](crate::world::World::plan)). Returns the goal's spec, for
    /// [`advance_queue`].
    #[inline]
    pub(crate) fn plan(&self, a: &mut Agent, advance: bool) -> GoalSpec {
        let (kind, f, r) = (self.kind, self.funnel, self.relaxed);
        self.plan_by(a, advance, |u, ri| kind.plan(f, r, u, ri))
    }

    /// True when the world's controller is our standard one on a unicycle
    /// without a reverse gear ([`ControllerKind::is_ours_unicycle`]): a
    /// step then plans every
    /// agent with [`FunnelConfig::plan_ours`] and moves it with
    /// [`seek_step_committed_unicycle`](crate::funnelling::seek::seek_step_committed_unicycle).
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

/// The part of the first plan that needs no η table (see [`World::plan`](crate::world::World::plan)):
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
