//! The world's step with avoidance on: every funnel plans, the avoidance
//! adjusts the plans together, then every agent steps. With avoidance off
//! [`World::step`] keeps its own loop, so a world without avoidance steps
//! to the same bits whether or not this module exists.

use crate::avoidance::config::{validate_obstacles, AvoidanceConfig, AvoidanceMethod, Obstacle};
use crate::avoidance::patience;
use crate::base::angle::diff;
use crate::base::vehicle::ParamError;
use crate::base::vehicle::{VehicleParams, VehicleState};
use crate::funnelling::table::lookup::EtaTable;
use crate::world::World;

impl World {
    /// Sets the avoidance method, settings and static obstacles.
    ///
    /// # Errors
    /// An invalid setting or obstacle (the world is unchanged).
    pub fn set_avoidance(
        &mut self,
        cfg: AvoidanceConfig,
        obstacles: Vec<Obstacle>,
    ) -> Result<(), String> {
        cfg.validate().map_err(|e: ParamError| e.to_string())?;
        validate_obstacles(&obstacles)?;
        self.avoidance = cfg;
        self.obstacles = obstacles;
        Ok(())
    }

    /// [`World::step`] with avoidance on.
    pub(crate) fn step_avoiding(&mut self, table: &EtaTable) {
        debug_assert_ne!(self.avoidance.method, AvoidanceMethod::Off);
        // 1. Every funnel plans (mode memory advances as in a plain step).
        // The buffer is taken out and put back (no allocation) so that the
        // planner may borrow the world beside it.
        // Each agent plans alone (on every core natively, as in the plain
        // step); the avoidance between them (2.) runs on one thread.
        let mut preferred = core::mem::take(&mut self.preferred);
        preferred.clear();
        preferred.resize(self.agents.len(), (0.0, 0.0));
        let chunk = self.parallel_chunk();
        let (planner, agents) = self.planning(table);
        let (p, t) = (*planner.p, planner.t);
        crate::base::parallel::for_each_mut_with(agents, &mut preferred, 1, chunk, |a, pref| {
            pref[0] = if a.done() {
                let speed = a.cruise_speed();
                a.hold(speed);
                (a.state.theta, speed)
            } else {
                planner.plan(a, true);
                (a.internals.gamma, a.internals.v_dt)
            };
        });
        self.preferred = preferred;
        // Right of way: nearer the current goal first, finished agents last.
        self.avoider.priority.clear();
        self.avoider.priority.extend(self.agents.iter().map(|a| {
            if a.done() {
                f32::INFINITY
            } else {
                (a.goal_now.pos - a.state.pos).length()
            }
        }));
        self.avoider.goals.clear();
        self.avoider
            .goals
            .extend(self.agents.iter().map(|a| a.goal_now.pos));
        // Patience clocks (`avoidance::patience`), on the states at the
        // start of the step; all reset when agents come or go.
        if self.avoider.stalled.len() != self.agents.len() {
            self.avoider.stalled.clear();
            self.avoider.stalled.resize(self.agents.len(), 0.0);
        }
        for (c, a) in self.avoider.stalled.iter_mut().zip(&self.agents) {
            *c = patience::tick(*c, a.done(), a.state.v, p.dt);
        }
        // 2. The avoidance, on the states at the start of the step.
        self.avoider.compute(
            &p,
            &self.avoidance,
            &self.obstacles,
            &self.snapshot,
            &self.preferred,
        );
        // 3. Every agent steps with its command; goals switch as usual.
        let metrics_on = self.metrics_on;
        let commands = &self.avoider.commands;
        crate::base::parallel::for_each_mut_beside(&mut self.agents, commands, chunk, |a, c| {
            let prev = a.state;
            if c.active && c.walls {
                avoidance_step(&p, &mut a.state, c.heading, c.speed);
            } else {
                // The funnel's own command: its step, the same bits.
                self.config.seek_step(&p, &mut a.state, c.heading, c.speed);
            }
            if !a.done() {
                let spec = a.goals[a.current];
                crate::world::planner::advance_queue(a, &spec, t);
            } else {
                a.internals.gamma = a.state.theta;
            }
            if metrics_on {
                a.metrics.add(&p, &prev, &a.state);
            }
        });
        self.time += p.dt;
    }
}

/// Half-width of the band around the ±π seam of the heading error in
/// which the avoidance's seek step keeps the current turn direction: 45° (the
/// funnel's own step keeps it within 10°, `seek::TURN_COMMIT_WINDOW`).
pub const AVOID_TURN_COMMIT_WINDOW: f32 = core::f32::consts::FRAC_PI_4;

/// The seek step for a command the avoidance changed near an obstacle: the
/// PD law, with the current turn kept while the agent is at rest (below
/// `STUCK_SPEED`) and the error is within [`AVOID_TURN_COMMIT_WINDOW`] of
/// ±π. Only near obstacles: in open space (paper 000 Fig. 6 with ORCA) it
/// would keep two agents at rest turning round for good. Why wider than
/// the funnel's: an agent at rest behind a wall, facing away from its way,
/// can be told to turn to headings 156° one way and 161° the other on
/// alternate steps (the funnel's γ and the goal's direction, as the wall
/// test flips), and with the funnel's window sits turning neither way for
/// good (the doorway benchmark, tune seed 1007).
#[inline]
fn avoidance_step(p: &VehicleParams, s: &mut VehicleState, heading: f32, speed: f32) {
    let e = diff(heading, s.theta);
    let e = if s.v < crate::avoidance::stalled::STUCK_SPEED
        && e.abs() > core::f32::consts::PI - AVOID_TURN_COMMIT_WINDOW
        && e * s.omega < 0.0
    {
        e + core::f32::consts::TAU.copysign(s.omega)
    } else {
        e
    };
    p.integrate(s, p.kp * e - p.kd * s.omega, speed);
}
