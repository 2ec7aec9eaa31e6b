//! Edits of a running world (the logic of the lab page's drags, sliders
//! and performance runs lives in the core, the bindings only convert):
//! agents added, never past the world's bound ([`World::max_agents`], the
//! caller's choice); a pose reset or a new goal queue restarts the agent's
//! queue and its mode memory (paper 000 Fig. 5's Position_only latch); and
//! the seeded random crowd of the performance runs. Every edit validates
//! first and changes nothing when it refuses, so a front end can pass user
//! input straight through.

use glam::Vec2;

use crate::base::metrics::PathMetrics;
use crate::base::vehicle::{ParamError, VehicleParams, VehicleState};
use crate::funnelling::goal::{FunnelMemory, Goal};
use crate::funnelling::relaxed::RelaxedInternals;
use crate::funnelling::update::{Internals, Mode};
use crate::world::precision;
use crate::world::{goals::GoalMotion, goals::GoalSpec, goals::SwitchRule, Agent, World};
use crate::world::{provisional_plan, world::faces};

/// Fastest a goal may move by itself, m/s: each component of a linear
/// velocity ([`crate::base::ranges::MOTION_VX`]), and the tangential
/// speed `radius·|ω|` of a circling goal (each factor within its own
/// range, a circle of 1e6 m at 100 rad/s would move its goal at 1e8 m/s).
pub const MAX_GOAL_MOTION_SPEED: f32 = crate::base::ranges::MOTION_VX.max as f32;

/// Agents the lab's page lets a world hold ([`World::set_max_agents`] in
/// its bindings): the playground agent and
/// [`AGENTS`](crate::base::ranges::AGENTS)' largest count of random
/// agents (the page's performance runs go to 100,000).
pub const MAX_AGENTS: usize = crate::base::ranges::AGENTS.max as usize + 1;

/// Goals queued per agent by [`World::spawn_random`] (minutes of funnelling).
pub const RANDOM_GOALS: usize = 16;

/// Why an edit of a running world (a reset, a new goal, more agents) was
/// refused; nothing is changed when it is.
#[derive(Clone, Debug, PartialEq)]
pub enum EditError {
    /// There is no agent with this index.
    NoAgent {
        /// The index asked for.
        index: usize,
        /// Agents in the world.
        count: usize,
    },
    /// Adding the agents would exceed the world's bound
    /// ([`World::max_agents`]).
    TooManyAgents {
        /// Agents asked for.
        adding: usize,
        /// Agents already in the world.
        count: usize,
        /// The world's bound.
        max: usize,
    },
    /// A pose, goal or setting is out of range.
    Param(ParamError),
}

impl core::fmt::Display for EditError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self {
            Self::NoAgent { index, count } => write!(f, "no agent {index} (there are {count})"),
            Self::TooManyAgents { adding, count, max } => write!(
                f,
                "{adding} more agents would exceed {max} (there are {count})"
            ),
            Self::Param(e) => e.fmt(f),
        }
    }
}

impl std::error::Error for EditError {}

impl From<ParamError> for EditError {
    fn from(e: ParamError) -> Self {
        Self::Param(e)
    }
}

impl GoalSpec {
    /// Checks the goal and its motion against the vehicle `p`.
    ///
    /// # Errors
    /// The first value out of range (NaN included), named.
    pub fn validate(&self, p: &VehicleParams) -> Result<(), ParamError> {
        use crate::base::ranges as r;
        self.goal.validate(p)?;
        self.check_halting()?;
        match self.motion {
            GoalMotion::Linear { velocity } => {
                r::MOTION_VX.check(velocity.x)?;
                r::MOTION_VY.check(velocity.y)?;
            }
            GoalMotion::Circle {
                center,
                angular_speed,
            } => {
                r::MOTION_CX.check(center.x)?;
                r::MOTION_CY.check(center.y)?;
                r::MOTION_ANGULAR_SPEED.check(angular_speed)?;
                let radius = (self.goal.pos - center).length();
                crate::base::vehicle::check_range(
                    "motion tangential speed (radius·|angularSpeed|)",
                    radius * angular_speed.abs(),
                    0.0,
                    MAX_GOAL_MOTION_SPEED,
                )?;
            }
            GoalMotion::FaceAgent { distance, .. } => r::MOTION_DISTANCE.check(distance)?,
            GoalMotion::Static => {}
        }
        Ok(())
    }
}

/// Edits of a running world, as the lab page makes them (a drag, a slider,
/// a performance run): each validates first and changes nothing when it
/// refuses, so a front end can pass user input straight through.
impl World {
    /// Adds an agent; returns its index.
    ///
    /// # Errors
    /// [`EditError::TooManyAgents`] when the world already holds
    /// [`World::max_agents`]; [`EditError::Param`] for an invalid state or
    /// goal (NaN, out of range; an agent index that does not exist yet is
    /// allowed only if it will: checked in `step`).
    pub fn add_agent(
        &mut self,
        state: VehicleState,
        goals: Vec<GoalSpec>,
    ) -> Result<usize, EditError> {
        self.check_room(1)?;
        self.check_new_agent(&state, &goals)?;
        Ok(self.push_agent(state, goals))
    }

    /// Adds many agents at once, all or none: each is checked as
    /// [`World::add_agent`] checks it before any is added. Returns the
    /// new agents' indices. One allocation of the world's lists for the
    /// lot, where one [`World::add_agent`] per agent may grow them many
    /// times.
    ///
    /// # Errors
    /// [`EditError::TooManyAgents`] (index 0) when they do not all fit,
    /// else the first refused agent's index (in `agents`) and why; nothing
    /// is added then.
    pub fn add_agents(
        &mut self,
        agents: Vec<(VehicleState, Vec<GoalSpec>)>,
    ) -> Result<core::ops::Range<usize>, (usize, EditError)> {
        self.check_room(agents.len()).map_err(|e| (0, e))?;
        for (k, (state, goals)) in agents.iter().enumerate() {
            self.check_new_agent(state, goals).map_err(|e| (k, e))?;
        }
        let first = self.agents.len();
        self.agents.reserve(agents.len());
        self.snapshot.reserve(agents.len());
        for (state, goals) in agents {
            self.push_agent(state, goals);
        }
        Ok(first..self.agents.len())
    }

    /// What [`World::add_agent`] checks of one agent (room aside).
    fn check_new_agent(&self, state: &VehicleState, goals: &[GoalSpec]) -> Result<(), EditError> {
        state.validate(&self.params)?;
        for g in goals {
            g.validate(&self.params)?;
        }
        crate::world::precision::check_agent(&self.params, state.pos, goals, None)?;
        Ok(())
    }

    /// Appends a checked agent; returns its index.
    fn push_agent(&mut self, state: VehicleState, goals: Vec<GoalSpec>) -> usize {
        let goal_now = goals.first().map(|g| g.goal).unwrap_or_default();
        let internals = if goals.is_empty() {
            Internals {
                mode: Mode::EndOfSteering,
                gamma: state.theta,
                ..Default::default()
            }
        } else {
            provisional_plan(&self.params, &state, &goal_now)
        };
        let memory = goals
            .first()
            .map_or_else(FunnelMemory::default, GoalSpec::fresh_memory);
        let spec = goals.first().copied().unwrap_or_default();
        self.facing += usize::from(faces(&goals));
        self.agents.push(Agent {
            spec,
            state,
            goals,
            current: 0,
            memory,
            internals,
            relaxed: RelaxedInternals::default(),
            goal_now,
            metrics: PathMetrics::default(),
            finished_at: None,
        });
        self.snapshot.push(state);
        self.agents.len() - 1
    }

    /// Agent `i`.
    ///
    /// # Errors
    /// [`EditError::NoAgent`] when there is none.
    pub fn agent(&self, i: usize) -> Result<&Agent, EditError> {
        let count = self.agents.len();
        self.agents
            .get(i)
            .ok_or(EditError::NoAgent { index: i, count })
    }

    /// Restarts agent `i`'s goal queue (the index is valid): first goal as
    /// it stands now (a goal that faces another agent faces it where it is),
    /// fresh mode memory (paper 000 Fig. 5's latches open again), not
    /// finished. An edit, not a step: the states are gathered anew.
    fn restart(&mut self, i: usize) {
        let t = self.time;
        let others: Vec<VehicleState> = self.agents.iter().map(|a| a.state).collect();
        let a = &mut self.agents[i];
        a.current = 0;
        a.refresh_spec();
        a.goal_now = a
            .goals
            .first()
            .map(|g| g.at(t, &others))
            .unwrap_or_default();
        a.memory = a
            .goals
            .first()
            .map_or_else(FunnelMemory::default, GoalSpec::fresh_memory);
        a.finished_at = None;
    }

    /// Checks that `adding` more agents fit under [`World::max_agents`]
    /// (every path that adds agents checks it: [`World::add_agent`],
    /// [`World::spawn_random`], scenario worlds through `add_agent`).
    ///
    /// # Errors
    /// [`EditError::TooManyAgents`].
    pub fn check_room(&self, adding: usize) -> Result<(), EditError> {
        let count = self.agents.len();
        if count.saturating_add(adding) > self.max_agents {
            return Err(EditError::TooManyAgents {
                adding,
                count,
                max: self.max_agents,
            });
        }
        Ok(())
    }

    /// Most agents the world accepts ([`DEFAULT_MAX_AGENTS`](super::DEFAULT_MAX_AGENTS) unless set).
    #[must_use]
    pub fn max_agents(&self) -> usize {
        self.max_agents
    }

    /// Sets the most agents the world accepts, the caller's choice (the
    /// lab's page keeps [`MAX_AGENTS`]). Agents already in stay; while
    /// they are more than `max` no agent is added.
    pub fn set_max_agents(&mut self, max: usize) {
        self.max_agents = max;
    }

    /// Puts agent `i` at rest at `pos`, heading `theta` (wrapped), and
    /// restarts its goal queue.
    ///
    /// # Errors
    /// No such agent, or a pose out of range (NaN included).
    pub fn set_pose(&mut self, i: usize, pos: Vec2, theta: f32) -> Result<(), EditError> {
        let s = VehicleState::new(pos, crate::base::angle::wrap(theta), 0.0, 0.0);
        self.agent(i)?;
        s.validate(&self.params)?;
        precision::check_agent(&self.params, pos, &self.agents[i].goals, None)?;
        self.agents[i].state = s;
        self.restart(i);
        Ok(())
    }

    /// Replaces agent `i`'s goal queue and restarts it.
    ///
    /// # Errors
    /// No such agent, or a goal out of range.
    pub fn set_goals(&mut self, i: usize, goals: Vec<GoalSpec>) -> Result<(), EditError> {
        self.agent(i)?;
        for g in &goals {
            g.validate(&self.params)?;
        }
        precision::check_agent(&self.params, self.agents[i].state.pos, &goals, None)?;
        self.facing -= usize::from(faces(&self.agents[i].goals));
        self.facing += usize::from(faces(&goals));
        self.agents[i].goals = goals;
        self.restart(i);
        Ok(())
    }

    /// Adds `n` agents for performance runs: random poses at rest in the
    /// square of half-side `extent` centred on the origin, each with a
    /// queue of [`RANDOM_GOALS`] random oriented goals in the same square
    /// (D_tol 0.3 m, ε_tol 10°, switched on entering the tolerance) at
    /// desired speed `speed` clamped to [min(0.1, v_max), v_max]. Seeded PCG32: the same
    /// seed gives the same crowd natively and in the browser.
    ///
    /// # Errors
    /// `extent` outside [0.001, 1e5] or not finite, `speed` not finite, or more than
    /// [`World::max_agents`] agents in all; nothing is added then.
    pub fn spawn_random(
        &mut self,
        n: usize,
        seed: u64,
        extent: f32,
        speed: f32,
    ) -> Result<(), EditError> {
        self.spawn_random_kept(n, seed, extent, speed, 0..n)
    }

    /// [`World::spawn_random`]'s agents `keep` only (a stepping worker's
    /// slice): the same agents, bit for bit, without building the
    /// others (their random draws are made and dropped).
    ///
    /// # Errors
    /// As [`World::spawn_random`]; nothing is added then.
    pub fn spawn_random_kept(
        &mut self,
        n: usize,
        seed: u64,
        extent: f32,
        speed: f32,
        keep: core::ops::Range<usize>,
    ) -> Result<(), EditError> {
        self.check_room(n)?;
        let mut added = Ok(0);
        let p = self.params;
        Self::random_crowd(&p, n, seed, extent, speed, |k, state, goals| {
            if keep.contains(&k) && added.is_ok() {
                added = self.add_agent(state, goals);
            }
        })?;
        added.map(|_| ())
    }

    /// The seeded random crowd of [`World::spawn_random`], agent by agent:
    /// `each(k, start, goals)` for k in `0..n`, drawn in this order from one
    /// stream (so a caller that keeps only some agents, or only their first
    /// goals, gets those of `spawn_random` bit for bit). No room is checked.
    ///
    /// # Errors
    /// `extent` outside [0.001, 1e5] or not finite, `speed` not finite.
    pub fn random_crowd(
        p: &VehicleParams,
        n: usize,
        seed: u64,
        extent: f32,
        speed: f32,
        mut each: impl FnMut(usize, VehicleState, Vec<GoalSpec>),
    ) -> Result<(), EditError> {
        use core::f32::consts::PI;
        crate::base::ranges::EXTENT
            .check(extent)
            .map_err(ParamError::Range)?;
        crate::base::vehicle::check_range("speed", speed, f32::MIN, f32::MAX)?;
        // At least 0.1 m/s, unless the vehicle is slower: `clamp` panics
        // when its lower end is above the upper (v_max 0.05 did, in wasm).
        let speed = speed.clamp(0.1f32.min(p.v_max), p.v_max);
        let mut rng = crate::base::rng::Rng::new(seed);
        let point = |rng: &mut crate::base::rng::Rng| {
            Vec2::new(rng.range(-extent, extent), rng.range(-extent, extent))
        };
        for k in 0..n {
            let pos = point(&mut rng);
            let state = VehicleState::new(pos, rng.range(-PI, PI), 0.0, 0.0);
            let goals = (0..RANDOM_GOALS)
                .map(|_| GoalSpec {
                    goal: Goal {
                        pos: point(&mut rng),
                        beta: rng.range(-PI, PI),
                        d_tol: 0.3,
                        eps_tol: 10f32.to_radians(),
                        speed,
                        halting: false,
                        vel: Vec2::ZERO,
                    },
                    motion: GoalMotion::Static,
                    switch: SwitchRule::Tolerance,
                })
                .collect();
            each(k, state, goals);
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::funnelling::config::FunnelConfig;

    #[test]
    fn random_agents_of_a_vehicle_slower_than_a_tenth_of_a_metre_per_second() {
        let p = VehicleParams {
            v_max: 0.05,
            ..Default::default()
        };
        let mut w = World::new(p, FunnelConfig::default()).unwrap();
        w.spawn_random(3, 7, 10.0, 1.3).unwrap();
        assert_eq!(w.agents.len(), 3);
        assert!(w.agents[0].goals.iter().all(|g| g.goal.speed == 0.05));
    }

    /// Planning only the agents just added gives every agent the plan a
    /// whole-world plan gives it (what the bindings' amortised adds rely on).
    #[test]
    #[cfg(not(target_arch = "wasm32"))]
    fn planning_the_new_agents_equals_planning_all() {
        let bytes = std::fs::read(concat!(env!("CARGO_MANIFEST_DIR"), "/tables/eta.bin")).unwrap();
        let table = crate::funnelling::table::lookup::EtaTable::from_bytes(&bytes).unwrap();
        let mut one = World::new(VehicleParams::default(), FunnelConfig::default()).unwrap();
        one.spawn_random(40, 3, 10.0, 1.3).unwrap();
        let mut all = one.clone();
        for _ in 0..30 {
            one.step(&table).unwrap();
            all.step(&table).unwrap();
        }
        let starts = [(-3.0, 1.0, 0.5), (2.0, -4.0, 2.0), (0.5, 0.5, -1.0)];
        for (k, &(x, y, theta)) in starts.iter().enumerate() {
            let state = VehicleState::new(Vec2::new(x, y), theta, 0.0, 0.0);
            let goal = GoalSpec {
                goal: Goal {
                    pos: Vec2::new(-x, -y),
                    beta: theta + 1.0,
                    d_tol: 0.3,
                    eps_tol: 0.2,
                    speed: 1.3,
                    halting: k != 1,
                    vel: Vec2::ZERO,
                },
                motion: GoalMotion::Static,
                switch: SwitchRule::EndOfSteering,
            };
            let i = one.add_agent(state, vec![goal]).unwrap();
            one.plan_agents(&table, i..i + 1).unwrap();
            all.add_agent(state, vec![goal]).unwrap();
        }
        all.plan(&table).unwrap();
        // The old agents' plans are the ones of their last step in `one`,
        // the whole-world plan's in `all`: compare the new agents.
        let n = all.agents.len();
        for i in n - starts.len()..n {
            assert_eq!(one.agents[i], all.agents[i], "agent {i}");
        }
        for _ in 0..200 {
            one.step(&table).unwrap();
            all.step(&table).unwrap();
        }
        assert_eq!(one.agents, all.agents, "the same run from there on");
    }

    #[test]
    fn many_agents_are_added_all_or_none() {
        let mut w = World::new(VehicleParams::default(), FunnelConfig::default()).unwrap();
        let goal = |x: f32| GoalSpec {
            goal: Goal {
                pos: Vec2::new(x, 1.0),
                beta: 0.5,
                d_tol: 0.3,
                eps_tol: 0.2,
                speed: 1.3,
                halting: true,
                vel: Vec2::ZERO,
            },
            motion: GoalMotion::Static,
            switch: SwitchRule::EndOfSteering,
        };
        let at = |x: f32| VehicleState::new(Vec2::new(x, 0.0), 0.0, 0.0, 0.0);
        assert_eq!(
            w.add_agents(vec![(at(0.0), vec![goal(3.0)]), (at(1.0), vec![goal(4.0)])]),
            Ok(0..2)
        );
        let bad = vec![(at(2.0), vec![goal(5.0)]), (at(f32::NAN), vec![goal(6.0)])];
        assert!(matches!(w.add_agents(bad), Err((1, EditError::Param(_)))));
        assert_eq!(w.agents.len(), 2, "nothing added when one is refused");
        w.set_max_agents(3);
        let two = vec![(at(2.0), vec![]), (at(3.0), vec![])];
        assert!(matches!(
            w.add_agents(two),
            Err((0, EditError::TooManyAgents { .. }))
        ));
        assert_eq!(w.add_agents(vec![(at(2.0), vec![])]), Ok(2..3));
    }
}
