//! The JavaScript boundary: the one module that knows about wasm-bindgen.
//!
//! Rules kept here:
//! - thin: conversion only, no steering logic; every value from JavaScript
//!   is validated and turned into a `JsError` with a readable message, never
//!   a panic (indices are checked, configs go through the core's `validate`);
//! - typed: configuration objects cross via serde-wasm-bindgen and carry real
//!   TypeScript types (`typescript_custom_section` + `unchecked_*_type`,
//!   both in the `lab_types` module);
//! - bulk per-agent state crosses as `Float32Array` (one copy per call);
//! - the core's validation ranges cross too (`ranges()`), so the page
//!   checks what the core checks.

use std::rc::Rc;

use glam::Vec2;
use wasm_bindgen::prelude::*;

use super::lab_types::{
    AgentConfig, ArcOut, GhostOut, GoalConfig, InternalsOut, ScenarioInfo, TableInfo,
};
use crate::base::rng::Rng;
use crate::base::vehicle::{VehicleParams, VehicleState};
use crate::bindings::boundary::{from_js, from_js_in, js_err, to_js};
use crate::funnelling::config::FunnelConfig;
use crate::funnelling::controller::{ControllerKind, Reading};
use crate::funnelling::ghost::{seek_ghost, table_limits, update_ghost, Ghost};
use crate::funnelling::relaxed::RelaxedConfig;
use crate::funnelling::seek::{simulate_reach, ReachLimits, ReachOutcome};
use crate::funnelling::table::lookup::EtaTable;
use crate::funnelling::table::spec::TableSpec;
use crate::funnelling::update::{Internals, Mode, Update};
use crate::world::scenario::Scenario;
use crate::world::{provisional_plan, World, STATE_STRIDE};

/// The crate version, to show on the page and check the package loaded.
#[wasm_bindgen]
#[must_use]
pub fn version() -> String {
    env!("CARGO_PKG_VERSION").to_owned()
}

/// The core's validation ranges, one per user-settable field
/// ([`crate::base::ranges::ALL`]): the page derives its URL decoder,
/// sliders and number inputs from them, so it accepts exactly what the
/// core accepts.
///
/// # Errors
/// Never in practice (plain numbers and strings).
#[wasm_bindgen(unchecked_return_type = "FieldRange[]")]
pub fn ranges() -> Result<JsValue, JsError> {
    to_js(&crate::base::ranges::ALL.as_slice())
}

/// The coordinate rule of [`crate::world::precision`]: an agent and
/// its goals stay within `min(⌊stepScale·v·dt⌋, ⌊toleranceScale·D_tol⌋,
/// coordMax)` metres (v its slowest goal speed). The page bounds its
/// positions with it, as it bounds the desired speed by the max speed.
///
/// # Errors
/// Never in practice (plain numbers).
#[wasm_bindgen(unchecked_return_type = "PrecisionRule")]
pub fn precision() -> Result<JsValue, JsError> {
    use crate::world::precision as p;
    to_js(&super::lab_types::PrecisionRule {
        step_scale: p::STEP_RESOLUTION_SCALE,
        tolerance_scale: p::TOLERANCE_RESOLUTION_SCALE,
        coord_max: p::COORD_MAX,
    })
}

/// A JavaScript number that must be a whole number in `r` (compared in
/// f64: f32 cannot tell 2³² from 2³² − 1).
pub(crate) fn whole(r: &crate::base::ranges::FieldRange, v: f64) -> Result<u64, JsError> {
    if v.is_finite() && v.fract() == 0.0 && v >= r.min && v <= r.max {
        Ok(v as u64)
    } else {
        Err(js_err(
            "random agents",
            format!(
                "{} = {v} is not a whole number in [{}, {}]",
                r.key, r.min, r.max
            ),
        ))
    }
}

/// `n` uniform samples in `[0, 1)` from the shared PCG32 generator, seeded:
/// the same seed gives the same numbers natively and in the browser.
#[wasm_bindgen(js_name = randomSamples)]
#[must_use]
pub fn random_samples(seed: u32, n: u32) -> Vec<f32> {
    let mut rng = Rng::new(u64::from(seed));
    (0..n).map(|_| rng.next_f32()).collect()
}

/// Appends one η-field sample per (distance, α) pair: `D, α, α+η, reachable`
/// (paper 001 Fig. 3b/c; samples without any η are left out).
fn field_samples(
    table: &EtaTable,
    distances: &[f32],
    omega_c: f32,
    v_c: f32,
    v_d: f32,
    out: &mut Vec<f32>,
) {
    for &d in distances {
        for &a in table.axis(1) {
            let lk = table.lookup(d, a, omega_c, v_c, v_d);
            if lk.eta_valid {
                out.extend_from_slice(&[d, a, a + lk.eta, f32::from(u8::from(lk.reachable))]);
            }
        }
    }
}

/// Points a ghost path keeps at most ([`crate::funnelling::ghost`]).
const GHOST_POINTS: usize = 256;

/// What a lab knows of the table it waits for ([`Lab::without_table`]):
/// the committed table's key and reach limits, from its spec (no entries).
#[derive(Clone)]
struct Expected {
    key: String,
    limits: ReachLimits,
}

/// The lab: the η table, the vehicle parameters and the agents.
#[wasm_bindgen]
pub struct Lab {
    /// Shared by the labs [`Lab::fork`] makes (one copy in memory, ~10 MB).
    /// `None` until the table has arrived (the first frame is drawn
    /// without it; see [`Lab::without_table`]).
    table: Option<Rc<EtaTable>>,
    /// The table a lab without one waits for.
    expected: Expected,
    pub(crate) world: World,
    buf: Vec<f32>,
    ghost: Vec<Vec2>,
}

/// What stepping before the η table has arrived says ([`Lab::step`],
/// [`Lab::step_into`]).
const NO_TABLE_CLOCK: &str = "η table: not loaded yet, the clock holds at t = 0";

impl Lab {
    /// Refuses an array that is not [`Lab::count`] × [`STATE_STRIDE`]
    /// floats long (`call`: the method that was given it).
    fn check_state_array(&self, out: &js_sys::Float32Array, call: &str) -> Result<(), JsError> {
        let n = self.world.agents.len();
        if out.length() as usize == n * STATE_STRIDE {
            return Ok(());
        }
        Err(JsError::new(&format!(
            "{call}: the array holds {} floats, the state {} ({n} agents × {STATE_STRIDE})",
            out.length(),
            n * STATE_STRIDE
        )))
    }

    /// The table, or the error every table-bound call gives before it arrives.
    fn table(&self) -> Result<&EtaTable, JsError> {
        self.table
            .as_deref()
            .ok_or_else(|| JsError::new("η table: not loaded yet"))
    }

    /// What a table-less lab expects: the default vehicle's committed table.
    fn expected_default() -> Expected {
        let spec = TableSpec::default_for(VehicleParams::default());
        Expected {
            key: spec.key(),
            limits: ReachLimits {
                reach_radius: spec.params.reach_radius,
                orbit_turns: spec.params.orbit_turns,
                max_time: spec.params.max_time,
            },
        }
    }

    fn expected_of(t: &EtaTable) -> Expected {
        Expected {
            key: t.key(),
            limits: table_limits(t),
        }
    }
}

#[wasm_bindgen]
impl Lab {
    /// Loads an η table from the bytes of `tables/eta.bin`; a corrupt,
    /// truncated or mismatched table is a `JsError` with the loader's message.
    #[wasm_bindgen(constructor)]
    pub fn new(table: &[u8]) -> Result<Lab, JsError> {
        let table = EtaTable::from_bytes(table).map_err(|e| js_err("η table", e))?;
        let params = table.params().vehicle;
        let world = lab_world(
            World::new(params, FunnelConfig::default())
                .map_err(|e| js_err("η table parameters", e))?,
        );
        Ok(Lab {
            expected: Self::expected_of(&table),
            table: Some(Rc::new(table)),
            world,
            buf: Vec::new(),
            ghost: Vec::new(),
        })
    }

    /// A lab for the default vehicle whose η table has not arrived yet
    /// (the page draws its first frame while the table loads).
    /// Agents, goals, presets, edits and settings work as usual; until
    /// [`Lab::set_table`] the internals are the provisional plan (the goal
    /// measured from the vehicle, γ its bearing: seek steering; the mode
    /// settled inside the tolerance, else Funnelling), the ghost is the
    /// plain seek path towards the goal, the η field and ring are empty,
    /// and `step` is refused: the clock holds at t = 0, so the run after
    /// the table arrives is the one `new Lab(bytes)` gives, bit for bit
    /// (`tests/web_bindings.rs`).
    #[wasm_bindgen(js_name = withoutTable)]
    pub fn without_table() -> Result<Lab, JsError> {
        let world = lab_world(
            World::new(VehicleParams::default(), FunnelConfig::default())
                .map_err(|e| js_err("vehicle parameters", e))?,
        );
        Ok(Lab {
            table: None,
            expected: Self::expected_default(),
            world,
            buf: Vec::new(),
            ghost: Vec::new(),
        })
    }

    /// Whether the η table is in (see [`Lab::without_table`]).
    #[wasm_bindgen(js_name = hasTable)]
    #[must_use]
    pub fn has_table(&self) -> bool {
        self.table.is_some()
    }

    /// A new lab on the same η table (shared, not copied) with an empty
    /// world and default settings: one per live figure of the learn page.
    pub fn fork(&self) -> Result<Lab, JsError> {
        let params = self
            .table
            .as_ref()
            .map_or_else(VehicleParams::default, |t| t.params().vehicle);
        let world = lab_world(
            World::new(params, FunnelConfig::default())
                .map_err(|e| js_err("η table parameters", e))?,
        );
        Ok(Lab {
            table: self.table.clone(),
            expected: self.expected.clone(),
            world,
            buf: Vec::new(),
            ghost: Vec::new(),
        })
    }

    /// The table's axes and build parameters.
    #[wasm_bindgen(js_name = tableInfo, unchecked_return_type = "TableInfo")]
    pub fn table_info(&self) -> Result<JsValue, JsError> {
        let t = self.table()?;
        to_js(&TableInfo {
            entries: t.len(),
            distances: t.axis(0),
            alphas: t.axis(1),
            omega_fractions: t.axis(2),
            speeds: t.axis(3),
            desired_speeds: t.axis(4),
            d_eta: t.d_eta(),
            params: t.params().vehicle,
        })
    }

    /// Replaces the η table (the bytes of a table file, e.g. one built
    /// by the workers for the limits in force, or read from the browser's
    /// cache); the agents keep their state. Returns the table's key. A
    /// corrupt file, or one whose key is not `expected_key` when given,
    /// is an error and changes nothing (the cache's bytes are checked
    /// here, loaded once). The first table of a lab made
    /// [`Lab::without_table`] also plans every agent, as adding them to a
    /// lab with a table would have (its clock has not run).
    #[wasm_bindgen(js_name = setTable)]
    pub fn set_table(
        &mut self,
        bytes: &[u8],
        expected_key: Option<String>,
    ) -> Result<String, JsError> {
        let t = EtaTable::from_bytes(bytes).map_err(|e| js_err("η table", e))?;
        let key = t.key();
        if let Some(want) = expected_key {
            if key != want {
                return Err(JsError::new(&format!(
                    "η table: built for other limits (key {key}, expected {want})"
                )));
            }
        }
        let first = self.table.is_none();
        self.expected = Self::expected_of(&t);
        self.table = Some(Rc::new(t));
        if first {
            if let Some(t) = &self.table {
                self.world.plan(t);
            }
        }
        Ok(key)
    }

    /// The key of the table in force (its cache key); before the table of
    /// a lab [`Lab::without_table`] has arrived, the key of the table it
    /// waits for (the default vehicle's).
    #[wasm_bindgen(js_name = tableKey)]
    #[must_use]
    pub fn table_key(&self) -> String {
        self.table
            .as_ref()
            .map_or_else(|| self.expected.key.clone(), |t| t.key())
    }

    /// The vehicle parameters in force.
    #[wasm_bindgen(unchecked_return_type = "VehicleParams")]
    pub fn params(&self) -> Result<JsValue, JsError> {
        to_js(&self.world.params)
    }

    /// Replaces the vehicle parameters (validated). Returns a warning when
    /// they differ from the ones the table was built with (its η values are
    /// then only approximate), else an empty string.
    #[wasm_bindgen(js_name = setParams)]
    pub fn set_params(
        &mut self,
        #[wasm_bindgen(unchecked_param_type = "VehicleParams")] params: JsValue,
    ) -> Result<String, JsError> {
        let p: VehicleParams = from_js("vehicle parameters", params)?;
        p.validate().map_err(|e| js_err("vehicle parameters", e))?;
        self.world.params = p;
        Ok(match self.table.as_ref().map(|t| t.check_params(&p)) {
            None | Some(Ok(())) => String::new(),
            Some(Err(e)) => format!("{e} (η predictions are approximate until then)"),
        })
    }

    /// The funnelling settings every agent uses (μ bound, gain, seek
    /// threshold), so the page can show what is in force.
    #[wasm_bindgen(unchecked_return_type = "FunnelConfig")]
    pub fn funnel(&self) -> Result<JsValue, JsError> {
        to_js(&self.world.config)
    }

    /// Replaces the funnelling settings (validated; a refused config
    /// leaves the current one in force). Agents keep their state, goals
    /// and mode memory: the next update uses the new settings, so μ-bound
    /// variants can be compared on a running scene.
    #[wasm_bindgen(js_name = setFunnel)]
    pub fn set_funnel(
        &mut self,
        #[wasm_bindgen(unchecked_param_type = "FunnelConfig")] config: JsValue,
    ) -> Result<(), JsError> {
        let c: FunnelConfig = from_js_in("funnel settings", "funnel.", config)?;
        c.validate().map_err(|e| js_err("funnel settings", e))?;
        self.world.config = c;
        Ok(())
    }

    /// Replaces the relaxed controller's settings (paper 001; in force
    /// whenever the world runs the relaxed controller), e.g. its aim: the
    /// disk's entry point (default) or the paper's relaxed point.
    #[wasm_bindgen(js_name = setRelaxed)]
    pub fn set_relaxed(
        &mut self,
        #[wasm_bindgen(unchecked_param_type = "RelaxedConfig")] config: JsValue,
    ) -> Result<(), JsError> {
        let c: RelaxedConfig = from_js_in("relaxed settings", "relaxed.", config)?;
        let kind = self.world.controller;
        self.world
            .set_controller(kind, c)
            .map_err(|e| js_err("relaxed settings", e))
    }

    /// Puts the funnelling and relaxed settings of a reading in force:
    /// `"paper"` (paper 000's standard and paper 001's relaxed funnelling
    /// exactly as written) or `"ours"` (the defaults). Agents keep their
    /// state and goals.
    #[wasm_bindgen(js_name = setReading)]
    pub fn set_reading(
        &mut self,
        #[wasm_bindgen(unchecked_param_type = "Reading")] reading: JsValue,
    ) -> Result<(), JsError> {
        let r: Reading = from_js("reading", reading)?;
        let kind = self.world.controller;
        self.world
            .set_controller(kind, r.relaxed())
            .map_err(|e| js_err("reading", e))?;
        self.world.config = r.funnel();
        Ok(())
    }

    /// What the page shows for the controller in force: `paper 001
    /// relaxed`, `paper 000 standard`, `ours standard`, `custom relaxed`, …
    #[wasm_bindgen(js_name = controllerLabel)]
    #[must_use]
    pub fn controller_label(&self) -> String {
        Reading::label(
            self.world.controller,
            &self.world.config,
            &self.world.relaxed,
        )
    }

    /// What the η table saves, for the learn page to time on the reader's
    /// machine: `n` plain seeks simulated to their end (the simulation the
    /// table was built from, paper 000 §3) from seeded samples of target
    /// distance and angle, current and desired speed. Returns how many
    /// reached (so the work is used); the page times the call. Pair with
    /// [`Lab::table_lookups`] on the same `seed`: the same samples.
    #[wasm_bindgen(js_name = seekSimulations)]
    pub fn seek_simulations(&self, n: u32, seed: u32) -> Result<u32, JsError> {
        let table = self.timed_table(n)?;
        let lim = table_limits(table);
        let mut reached = 0;
        for (d, alpha, v_c, v_d) in self.cost_samples(table, n, seed) {
            let start = VehicleState::new(Vec2::ZERO, 0.0, v_c, 0.0);
            let target = Vec2::new(d * alpha.cos(), d * alpha.sin());
            if matches!(
                simulate_reach(&self.world.params, start, target, v_d, &lim),
                ReachOutcome::Reached { .. }
            ) {
                reached += 1;
            }
        }
        Ok(reached)
    }

    /// The table's answer for the samples of [`Lab::seek_simulations`]:
    /// `n` lookups of η (one multilinear interpolation each). Returns how
    /// many had an η.
    #[wasm_bindgen(js_name = tableLookups)]
    pub fn table_lookups(&self, n: u32, seed: u32) -> Result<u32, JsError> {
        let table = self.timed_table(n)?;
        let found = self
            .cost_samples(table, n, seed)
            .filter(|&(d, alpha, v_c, v_d)| table.eta(d, alpha, 0.0, v_c, v_d).is_some())
            .count();
        Ok(u32::try_from(found).unwrap_or(u32::MAX))
    }

    /// The table, for a timing of `n` samples (at most a million).
    fn timed_table(&self, n: u32) -> Result<&EtaTable, JsError> {
        crate::base::range::check_range("n", n as f32, 0.0, 1e6)
            .map_err(|e| js_err("timing", e))?;
        self.table
            .as_deref()
            .ok_or_else(|| JsError::new("η table: not loaded yet"))
    }

    /// Seeded (D, α, v_c, v_d) within the table's distances and the
    /// vehicle's speeds.
    fn cost_samples<'a>(
        &'a self,
        table: &'a EtaTable,
        n: u32,
        seed: u32,
    ) -> impl Iterator<Item = (f32, f32, f32, f32)> + 'a {
        let ds = table.distances();
        let (d0, d1) = (
            ds.first().copied().unwrap_or(0.5),
            ds.last().copied().unwrap_or(10.0),
        );
        let v_max = self.world.params.v_max;
        let mut rng = Rng::new(u64::from(seed));
        (0..n).map(move |_| {
            let d = rng.range(d0.max(0.3), d1);
            let alpha = rng.range(-core::f32::consts::PI, core::f32::consts::PI);
            let v_c = rng.range(0.0, v_max);
            let v_d = rng.range(0.1 * v_max, v_max);
            (d, alpha, v_c, v_d)
        })
    }

    /// The η field around a vehicle (paper 001 Fig. 3b/c): for every sampled
    /// target (D, α) at current speed `v_c`, angular speed `omega_c` and
    /// desired speed `v_d`, the final direction α+η in the vehicle frame.
    /// Four floats per sample: D, α, α+η, reachable (1/0).
    #[wasm_bindgen(js_name = etaField)]
    #[must_use]
    pub fn eta_field(&self, v_c: f32, omega_c: f32, v_d: f32) -> Vec<f32> {
        let mut out = Vec::new();
        let Some(table) = self.table.as_deref() else {
            return out;
        };
        if v_c.is_finite() && omega_c.is_finite() && v_d.is_finite() {
            field_samples(table, table.distances(), omega_c, v_c, v_d, &mut out);
        }
        out
    }

    /// The sampled ring of the table nearest to distance `d` (paper 001
    /// Fig. 4), same layout as [`Lab::eta_field`].
    #[wasm_bindgen(js_name = etaRingAt)]
    #[must_use]
    pub fn eta_ring_at(&self, d: f32, v_c: f32, omega_c: f32, v_d: f32) -> Vec<f32> {
        let mut out = Vec::new();
        let Some(table) = self.table.as_deref() else {
            return out;
        };
        if !(d.is_finite() && v_c.is_finite() && omega_c.is_finite() && v_d.is_finite()) {
            return out;
        }
        let ring = table
            .distances()
            .iter()
            .copied()
            .min_by(|a, b| (a - d).abs().total_cmp(&(b - d).abs()));
        if let Some(r) = ring {
            field_samples(table, &[r], omega_c, v_c, v_d, &mut out);
        }
        out
    }
}

/// Every world the lab holds (new, forked, cleared, a scenario's) goes
/// through here: without the agents' path metrics, which no binding reads
/// (they cost a square root, an angle difference and the limit checks per
/// agent per step; the states are the same bits, `World::set_metrics`),
/// and bounded by the page's own agent count (`MAX_AGENTS`: its controls
/// go to 100,000 random agents beside the playground agent).
fn lab_world(mut world: World) -> World {
    world.set_metrics(false);
    world.set_max_agents(crate::world::edit::MAX_AGENTS);
    world
}

/// Steps a single call may ask for (a frame needs a handful).
const MAX_STEPS_PER_CALL: u32 = 10_000;
#[wasm_bindgen]
impl Lab {
    /// Removes every agent and restarts the clock.
    pub fn clear(&mut self) -> Result<(), JsError> {
        self.world = lab_world(
            World::new(self.world.params, self.world.config).map_err(|e| js_err("world", e))?,
        );
        Ok(())
    }

    /// Number of agents.
    #[must_use]
    pub fn count(&self) -> u32 {
        self.world.agents.len() as u32
    }

    /// Simulated time, s.
    #[must_use]
    pub fn time(&self) -> f32 {
        self.world.time
    }

    /// Adds an agent with its goal queue; returns its index.
    #[wasm_bindgen(js_name = addAgent)]
    pub fn add_agent(
        &mut self,
        #[wasm_bindgen(unchecked_param_type = "AgentConfig")] agent: JsValue,
    ) -> Result<u32, JsError> {
        let a: AgentConfig = from_js("agent", agent)?;
        let goals = a.goals.iter().map(GoalConfig::to_spec).collect();
        let state = VehicleState::new(Vec2::new(a.x, a.y), a.theta, a.v, a.omega);
        self.world.check_room(1).map_err(|e| js_err("agent", e))?;
        let i = self
            .world
            .add_agent(state, goals)
            .map_err(|e| js_err("agent", e))?;
        if a.goals.iter().any(|g| g.relaxed) {
            self.use_controller(true)?;
        }
        // The mode shown before the first step is the one chosen at t = 0
        // (without a table: when it arrives, `set_table`).
        if let Some(t) = &self.table {
            self.world.plan(t);
        }
        Ok(i as u32)
    }

    /// Switches the world between standard and relaxed funnelling.
    fn use_controller(&mut self, relaxed: bool) -> Result<(), JsError> {
        let kind = if relaxed {
            ControllerKind::Relaxed
        } else {
            ControllerKind::Standard
        };
        let cfg = self.world.relaxed;
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
            self.world.step(t);
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
        self.world.step_writing(t, &mut self.buf);
        out.copy_from(&self.buf);
        Ok(())
    }

    /// Floats per agent in [`Lab::state`].
    #[wasm_bindgen(js_name = stateStride)]
    #[must_use]
    pub fn state_stride() -> u32 {
        STATE_STRIDE as u32
    }

    /// Agent `i`'s controller internals for its *current* state and goal,
    /// evaluated without stepping (so a drag while paused shows the new
    /// mode at once).
    #[wasm_bindgen(unchecked_return_type = "Internals")]
    pub fn internals(&self, i: u32) -> Result<JsValue, JsError> {
        let a = self
            .world
            .agent(i as usize)
            .map_err(|e| js_err("agent", e))?;
        let mut out = InternalsOut::from(self.plan_of(i)?);
        if self.world.controller == ControllerKind::Relaxed && !a.done() && self.table.is_some() {
            let r = &a.relaxed;
            out.arc = Some(ArcOut {
                alpha_min: r.arc_min,
                alpha_max: r.arc_max,
                alpha_r: r.alpha_r,
                radius: r.ring,
                f_min: r.f_min,
                f_max: r.f_max,
                t_min: r.t_min,
                t_max: r.t_max,
                branch: r.branch as u8,
            });
        }
        to_js(&out)
    }

    /// The predicted seek path of agent `i`'s current update (paper 000
    /// Fig. 1c, [`crate::funnelling::ghost::update_ghost`]): from its state towards the
    /// point its controller asked the η table about, at the queried speed
    /// (or the fallback v_dt where the table says unreachable). `points`
    /// holds x, y pairs (at most 256 points).
    #[wasm_bindgen(unchecked_return_type = "Ghost")]
    pub fn ghost(&mut self, i: u32) -> Result<JsValue, JsError> {
        let inter = self.plan_of(i)?;
        let a = self
            .world
            .agent(i as usize)
            .map_err(|e| js_err("agent", e))?;
        let Some(table) = self.table.as_deref() else {
            // Before the table: the plain seek towards the goal centre.
            self.ghost.clear();
            let g = seek_ghost(
                &self.world.params,
                a.state,
                a.goal_now.pos,
                a.goal_now.speed,
                &self.expected.limits,
                GHOST_POINTS,
                &mut self.ghost,
            );
            return self.ghost_out(&g);
        };
        let g = update_ghost(
            table,
            &self.world.params,
            &a.state,
            &inter,
            &a.goal_now,
            GHOST_POINTS,
            &mut self.ghost,
        );
        self.ghost_out(&g)
    }

    /// The predicted seek path from any state (position, heading θ, speed
    /// v, angular speed ω) towards the point (`tx`, `ty`) at desired speed
    /// `v_d`: the table generator's simulation ([`crate::funnelling::ghost::seek_ghost`]).
    #[wasm_bindgen(js_name = ghostFrom, unchecked_return_type = "Ghost")]
    #[allow(clippy::too_many_arguments)]
    pub fn ghost_from(
        &mut self,
        x: f32,
        y: f32,
        theta: f32,
        v: f32,
        omega: f32,
        tx: f32,
        ty: f32,
        v_d: f32,
    ) -> Result<JsValue, JsError> {
        let s = VehicleState::new(Vec2::new(x, y), theta, v, omega);
        s.validate(&self.world.params)
            .map_err(|e| js_err("ghost state", e))?;
        crate::base::range::check_range("ghost.tx", tx, -1e6, 1e6)
            .map_err(|e| js_err("ghost", e))?;
        crate::base::range::check_range("ghost.ty", ty, -1e6, 1e6)
            .map_err(|e| js_err("ghost", e))?;
        crate::base::range::check_range("ghost.vD", v_d, 0.0, self.world.params.v_max)
            .map_err(|e| js_err("ghost", e))?;
        self.ghost.clear();
        let g = seek_ghost(
            &self.world.params,
            s,
            Vec2::new(tx, ty),
            v_d,
            &self
                .table
                .as_deref()
                .map_or(self.expected.limits, table_limits),
            GHOST_POINTS,
            &mut self.ghost,
        );
        self.ghost_out(&g)
    }

    fn ghost_out(&self, g: &Ghost) -> Result<JsValue, JsError> {
        let out = to_js(&GhostOut::from(g))?;
        let pts: Vec<f32> = self.ghost.iter().flat_map(|p| [p.x, p.y]).collect();
        js_sys::Reflect::set(
            &out,
            &JsValue::from_str("points"),
            &js_sys::Float32Array::from(pts.as_slice()),
        )
        .map_err(|_| JsError::new("ghost: could not attach the points"))?;
        Ok(out)
    }

    /// What agent `i`'s controller chooses for its current state and goal
    /// (no stepping; the relaxed controller's last update).
    fn plan_of(&self, i: u32) -> Result<Internals, JsError> {
        let a = self
            .world
            .agent(i as usize)
            .map_err(|e| js_err("agent", e))?;
        Ok(if a.done() {
            Internals {
                mode: Mode::EndOfSteering,
                gamma: a.state.theta,
                ..Default::default()
            }
        } else if self.table.is_none() {
            // Before the table: what the core can say without one; no η.
            Internals {
                eta: f32::NAN,
                delta_eta: f32::NAN,
                mu: f32::NAN,
                mu_max: f32::NAN,
                ..provisional_plan(&self.world.params, &a.state, &a.goal_now)
            }
        } else if self.world.controller == ControllerKind::Relaxed {
            // Relaxed funnelling plans towards the relaxed point: show what
            // its last update did.
            a.internals
        } else {
            let (mut mem, mut state) = (a.memory, a.state);
            self.world.config.plan(&mut Update {
                table: self.table()?,
                params: &self.world.params,
                state: &mut state,
                goal: &a.goal_now,
                memory: &mut mem,
            })
        })
    }

    /// The table ring nearest to agent `i`'s target distance, in its frame,
    /// for its current speeds and goal speed (paper 001 Fig. 4).
    #[wasm_bindgen(js_name = etaRing)]
    pub fn eta_ring(&self, i: u32) -> Result<Vec<f32>, JsError> {
        let a = self
            .world
            .agent(i as usize)
            .map_err(|e| js_err("agent", e))?;
        let d = (a.goal_now.pos - a.state.pos).length();
        Ok(self.eta_ring_at(d, a.state.v, a.state.omega, a.goal_now.speed))
    }
}

#[wasm_bindgen]
impl Lab {
    /// Replaces the world with a scenario file's (scenarios/*.json, see
    /// crate::world::scenario); returns its name, description and bounding box.
    #[wasm_bindgen(js_name = loadScenario, unchecked_return_type = "ScenarioInfo")]
    pub fn load_scenario(&mut self, json: &str) -> Result<JsValue, JsError> {
        let sc = Scenario::from_json(json).map_err(|e| js_err("scenario", e))?;
        let mut world = lab_world(sc.world().map_err(|e| js_err("scenario", e))?);
        if let Some(t) = &self.table {
            world.plan(t);
        }
        let (mut lo, mut hi) = (Vec2::splat(f32::INFINITY), Vec2::splat(f32::NEG_INFINITY));
        for a in &sc.agents {
            for p in core::iter::once(Vec2::new(a.x, a.y))
                .chain(a.goals.iter().map(|g| Vec2::new(g.x, g.y)))
            {
                lo = lo.min(p);
                hi = hi.max(p);
            }
        }
        if !lo.is_finite() || !hi.is_finite() {
            (lo, hi) = (Vec2::splat(-5.0), Vec2::splat(5.0));
        }
        let warning = match self.table.as_ref().map(|t| t.check_params(&world.params)) {
            None | Some(Ok(())) => String::new(),
            Some(Err(e)) => e.to_string(),
        };
        self.world = world;
        to_js(&ScenarioInfo {
            name: sc.name,
            description: sc.description,
            source: sc.source,
            claim: sc.claim,
            measured: sc.measured,
            agents: sc.agents.len(),
            min_x: lo.x - 1.0,
            min_y: lo.y - 1.0,
            max_x: hi.x + 1.0,
            max_y: hi.y + 1.0,
            warning,
        })
    }
}
