//! `Lab`'s world: agents added, posed and given goals, random crowds,
//! stepping, and the agents' state records copied out.

use glam::Vec2;
use wasm_bindgen::prelude::*;

use super::lab::{lab_world, whole, Lab};
use super::lab_types::{AgentConfig, GoalConfig};
use crate::bindings::boundary::{check_known_keys, from_js, js_err};
use crate::bindings::layout::Mode;
use crate::funnelling::controller::ControllerKind;
use crate::world::Agent;
use crate::world::{World, STATE_STRIDE};

/// What stepping before the η table has arrived says ([`Lab::step`],
/// [`Lab::step_into`]).
const NO_TABLE_CLOCK: &str = "η table: not loaded yet, the clock holds at t = 0";

/// Steps a single call may ask for (a frame needs a handful).
const MAX_STEPS_PER_CALL: u32 = 10_000;

impl Lab {
    /// Agent `i`, or the error naming the index and the count.
    fn agent_at(&self, i: u32) -> Result<&Agent, JsError> {
        self.world.agent(i as usize).map_err(|e| js_err("agent", e))
    }
}

#[wasm_bindgen]
impl Lab {
    /// Removes every agent and restarts the clock.
    pub fn clear(&mut self) -> Result<(), JsError> {
        self.world = lab_world(
            World::new(*self.world.params(), *self.world.config())
                .map_err(|e| js_err("world", e))?,
        );
        Ok(())
    }

    /// Number of agents.
    #[must_use]
    pub fn count(&self) -> u32 {
        self.world.agents().len() as u32
    }

    /// Simulated time, s.
    #[must_use]
    pub fn time(&self) -> f32 {
        self.world.time()
    }

    /// Adds an agent with its goal queue; returns its index. Amortised
    /// constant time: only the new agent is planned.
    #[wasm_bindgen(js_name = addAgent)]
    pub fn add_agent(
        &mut self,
        #[wasm_bindgen(unchecked_param_type = "AgentConfig")] agent: JsValue,
    ) -> Result<u32, JsError> {
        let a: AgentConfig = from_js("agent", agent)?;
        let relaxed = a.relaxed();
        let (state, goals) = a.into_core();
        self.world.check_room(1).map_err(|e| js_err("agent", e))?;
        let i = self
            .world
            .add_agent(state, goals)
            .map_err(|e| js_err("agent", e))?;
        self.plan_new(i..i + 1, relaxed)?;
        Ok(i as u32)
    }

    /// Adds many agents in one call, all or none (each checked as
    /// [`Lab::add_agent`] checks it); returns the first one's index. A
    /// refusal names the agent (`agents[3], field `theta``).
    #[wasm_bindgen(js_name = addAgents)]
    pub fn add_agents(
        &mut self,
        #[wasm_bindgen(unchecked_param_type = "AgentConfig[]")] agents: JsValue,
    ) -> Result<u32, JsError> {
        if !js_sys::Array::is_array(&agents) {
            return Err(JsError::new("agents: expected an array of agents"));
        }
        // Decoded whole, then each agent's keys checked on its own (one
        // agent's JSON tree at a time, not the whole array's).
        let list: Vec<AgentConfig> = match serde_wasm_bindgen::from_value(agents.clone()) {
            Ok(list) => list,
            // The first agent that does not decode, named by its index.
            Err(e) => {
                for (k, a) in js_sys::Array::from(&agents).iter().enumerate() {
                    from_js::<AgentConfig>(&format!("agents[{k}]"), a)?;
                }
                return Err(js_err("agents", e));
            }
        };
        let items = js_sys::Array::from(&agents);
        for (k, a) in list.iter().enumerate() {
            check_known_keys(&format!("agents[{k}]"), &items.get(k as u32), a)?;
        }
        let relaxed = list.iter().any(AgentConfig::relaxed);
        let core = list.into_iter().map(AgentConfig::into_core).collect();
        let new = self
            .world
            .add_agents(core)
            .map_err(|(k, e)| js_err(&format!("agents[{k}]"), e))?;
        let first = new.start;
        self.plan_new(new, relaxed)?;
        Ok(first as u32)
    }

    /// After agents were added: the relaxed controller when one of them
    /// asks for it, and the plan at t = 0 of the new agents (of all of
    /// them when the controller changed), so the mode shown before the
    /// first step is the one chosen then (without a table: when it
    /// arrives, `set_table`).
    fn plan_new(&mut self, new: core::ops::Range<usize>, relaxed: bool) -> Result<(), JsError> {
        let before = self.world.controller();
        if relaxed {
            self.use_controller(true)?;
        }
        if let Some(t) = &self.table {
            if self.world.controller() == before {
                self.world
                    .plan_agents(t, new)
                    .map_err(|e| js_err("η table", e))?;
            } else {
                self.world.plan(t).map_err(|e| js_err("η table", e))?;
            }
        }
        Ok(())
    }

    /// Whether agent `i` is done: every goal of its queue reached (its
    /// last in End_of_Steering; it may still be braking).
    pub fn done(&self, i: u32) -> Result<bool, JsError> {
        Ok(self.agent_at(i)?.done())
    }

    /// Whether agent `i` is done and at rest (speed 0, turning stopped):
    /// inside both tolerances of a halting last goal, for good.
    #[wasm_bindgen(js_name = atRest)]
    pub fn at_rest(&self, i: u32) -> Result<bool, JsError> {
        Ok(self.agent_at(i)?.at_rest())
    }

    /// Agent `i`'s control mode now.
    pub fn mode(&self, i: u32) -> Result<Mode, JsError> {
        Ok(self.agent_at(i)?.internals.mode.into())
    }

    /// Every agent's control mode, one byte each (a [`Mode`] number).
    #[must_use]
    pub fn modes(&self) -> Vec<u8> {
        (0..self.count())
            .filter_map(|i| self.agent_at(i).ok())
            .map(|a| Mode::from(a.internals.mode) as u8)
            .collect()
    }

    /// Switches the world between standard and relaxed funnelling.
    fn use_controller(&mut self, relaxed: bool) -> Result<(), JsError> {
        let kind = if relaxed {
            ControllerKind::Relaxed
        } else {
            ControllerKind::Standard
        };
        let cfg = *self.world.relaxed();
        self.world
            .set_controller(kind, cfg)
            .map_err(|e| js_err("relaxed settings", e))
    }

    /// Puts agent `i` at rest at a pose (a drag on the page); its goal
    /// queue restarts.
    #[wasm_bindgen(js_name = setPose)]
    pub fn set_pose(&mut self, i: u32, x: f32, y: f32, theta: f32) -> Result<(), JsError> {
        self.world
            .set_pose(i as usize, Vec2::new(x, y), theta)
            .map_err(|e| js_err("pose", e))
    }

    /// Replaces agent `i`'s goal queue with one goal (a drag or a slider);
    /// `relaxed` switches the world's controller.
    #[wasm_bindgen(js_name = setGoal)]
    pub fn set_goal(
        &mut self,
        i: u32,
        #[wasm_bindgen(unchecked_param_type = "GoalConfig")] goal: JsValue,
    ) -> Result<(), JsError> {
        let g: GoalConfig = from_js("goal", goal)?;
        self.world
            .set_goals(i as usize, vec![g.to_spec()])
            .map_err(|e| js_err("goal", e))?;
        self.use_controller(g.relaxed)
    }

    /// Refuses `n` more agents when they would not fit (the core's
    /// `World::check_room`), without adding any: what `spawnRandom` checks
    /// first, for a caller that wants the answer before the work.
    #[wasm_bindgen(js_name = checkRoom)]
    pub fn check_room(&self, n: f64) -> Result<(), JsError> {
        let n = whole(&crate::base::ranges::AGENTS, n)?;
        self.world
            .check_room(n as usize)
            .map_err(|e| js_err("random agents", e))
    }

    /// Adds `n` funnelling agents for performance runs (see
    /// `World::spawn_random`: random poses and 16 random goals each in a
    /// square of half-side `extent`, seeded).
    /// `n` and `seed` are JavaScript numbers checked here against the
    /// core's ranges (`agents`, `seed`): a `u32` would wrap 2³² to 0 and
    /// −1 to 4,294,967,295 without a word.
    #[wasm_bindgen(js_name = spawnRandom)]
    pub fn spawn_random(
        &mut self,
        n: f64,
        seed: f64,
        extent: f32,
        speed: f32,
    ) -> Result<(), JsError> {
        let n = whole(&crate::base::ranges::AGENTS, n)?;
        let seed = whole(&crate::base::ranges::SEED, seed)?;
        self.world
            .spawn_random(n as usize, seed, extent, speed)
            .map_err(|e| js_err("random agents", e))
    }

    /// Advances the world by `n` steps of `dt`; refused before the η table
    /// has arrived ([`Lab::without_table`]: the clock holds at t = 0).
    pub fn step(&mut self, n: u32) -> Result<(), JsError> {
        let Some(t) = &self.table else {
            return if n == 0 {
                Ok(())
            } else {
                Err(JsError::new(NO_TABLE_CLOCK))
            };
        };
        for _ in 0..n.min(MAX_STEPS_PER_CALL) {
            self.world.step(t).map_err(|e| js_err("η table", e))?;
        }
        Ok(())
    }

    /// Every agent's state, [`STATE_STRIDE`] floats each: x, y, θ, v, ω,
    /// mode, D, α, η, Δη, μ, γ, reachable, v_dt, goal x, goal y, goal β,
    /// goal D_tol, goal ε_tol.
    #[must_use]
    pub fn state(&mut self) -> Vec<f32> {
        self.world.write_state(&mut self.buf);
        self.buf.clone()
    }

    /// [`Lab::state`] written into `out` (a stepping worker's slice of the
    /// page's shared buffer) with one copy out of the core's
    /// memory, instead of a `Vec` clone, a new JS array and a copy of that.
    ///
    /// # Errors
    /// `out` is not exactly [`Lab::count`] × [`STATE_STRIDE`] floats long
    /// (nothing written).
    #[wasm_bindgen(js_name = stateInto)]
    pub fn state_into(&mut self, out: &js_sys::Float32Array) -> Result<(), JsError> {
        self.check_state_array(out, "stateInto")?;
        self.world.write_state(&mut self.buf);
        out.copy_from(&self.buf);
        Ok(())
    }

    /// One step ([`Lab::step`] of 1), then [`Lab::state`] written into
    /// `out` as [`Lab::state_into`] writes it: each agent's record as soon
    /// as it has stepped (a stepping worker's step and copy in one pass
    /// over its agents; `World::step_writing`).
    ///
    /// # Errors
    /// No η table yet, or `out` not exactly [`Lab::count`] ×
    /// [`STATE_STRIDE`] floats long (nothing stepped, nothing written).
    #[wasm_bindgen(js_name = stepInto)]
    pub fn step_into(&mut self, out: &js_sys::Float32Array) -> Result<(), JsError> {
        self.check_state_array(out, "stepInto")?;
        let Some(t) = &self.table else {
            return Err(JsError::new(NO_TABLE_CLOCK));
        };
        self.world
            .step_writing(t, &mut self.buf)
            .map_err(|e| js_err("η table", e))?;
        out.copy_from(&self.buf);
        Ok(())
    }

    /// Floats per agent in [`Lab::state`].
    #[wasm_bindgen(js_name = stateStride)]
    #[must_use]
    pub fn state_stride() -> u32 {
        STATE_STRIDE as u32
    }
}
