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

use crate::base::rng::Rng;
use crate::base::vehicle::VehicleParams;
use crate::bindings::boundary::{js_err, to_js};
use crate::funnelling::config::FunnelConfig;
use crate::funnelling::ghost::table_limits;
use crate::funnelling::seek::ReachLimits;
use crate::funnelling::table::lookup::EtaTable;
use crate::funnelling::table::spec::TableSpec;
use crate::world::{World, STATE_STRIDE};

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

/// What a lab knows of the table it waits for ([`Lab::without_table`]):
/// the committed table's key and reach limits, from its spec (no entries).
#[derive(Clone)]
pub(super) struct Expected {
    pub(super) key: String,
    pub(super) limits: ReachLimits,
}

/// The lab: the η table, the vehicle parameters and the agents.
#[wasm_bindgen]
pub struct Lab {
    /// Shared by the labs [`Lab::fork`] makes (one copy in memory, ~10 MB).
    /// `None` until the table has arrived (the first frame is drawn
    /// without it; see [`Lab::without_table`]).
    pub(super) table: Option<Rc<EtaTable>>,
    /// The table a lab without one waits for.
    pub(super) expected: Expected,
    pub(crate) world: World,
    pub(super) buf: Vec<f32>,
    pub(super) ghost: Vec<Vec2>,
}

impl Lab {
    /// Refuses an array that is not [`Lab::count`] × [`STATE_STRIDE`]
    /// floats long (`call`: the method that was given it).
    pub(super) fn check_state_array(
        &self,
        out: &js_sys::Float32Array,
        call: &str,
    ) -> Result<(), JsError> {
        let n = self.world.agents().len();
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
    pub(super) fn table(&self) -> Result<&EtaTable, JsError> {
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

    pub(super) fn expected_of(t: &EtaTable) -> Expected {
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
}

/// Every world the lab holds (new, forked, cleared, a scenario's) goes
/// through here: without the agents' path metrics, which no binding reads
/// (they cost a square root, an angle difference and the limit checks per
/// agent per step; the states are the same bits, `World::set_metrics`),
/// bounded by the page's own agent count (`MAX_AGENTS`: its controls
/// go to 100,000 random agents beside the playground agent), and stepping
/// on the table in force while the one for newly set vehicle limits is
/// being built (its η then approximate: `setParams` and `loadScenario`
/// say so, `World::allow_other_table`).
pub(super) fn lab_world(mut world: World) -> World {
    world.set_metrics(false);
    world.set_max_agents(crate::world::edit::MAX_AGENTS);
    world.allow_other_table(true);
    world
}
