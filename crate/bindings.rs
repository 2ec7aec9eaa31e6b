//! The JavaScript boundary: the one module that knows about wasm-bindgen.
//!
//! Rules kept here (issue 5):
//! - thin: conversion only, no steering logic; every value from JavaScript
//!   is validated and turned into a `JsError` with a readable message, never
//!   a panic (indices are checked, configs go through the core's `validate`);
//! - typed: configuration objects cross via serde-wasm-bindgen and carry real
//!   TypeScript types (`typescript_custom_section` + `unchecked_*_type`);
//! - bulk per-agent state crosses as `Float32Array` (one copy per call).

use serde::{Deserialize, Serialize};
use wasm_bindgen::prelude::*;

use crate::rng::Rng;
use crate::table::EtaTable;
use crate::vehicle::VehicleParams;

#[wasm_bindgen(typescript_custom_section)]
const TS_TYPES: &'static str = r#"
/** Vehicle limits and seek gains (crate::vehicle::VehicleParams). Units: m, s, rad. */
export interface VehicleParams {
  dt: number;
  vMax: number;
  accelMax: number;
  omegaMax: number;
  omegaAccelMax: number;
  normalAccelMax: number;
  kp: number;
  kd: number;
  integrator: "euler" | "semiImplicitEuler";
}
/** An oriented goal (crate::funnel::Goal): position (m), β (rad), tolerances, desired speed (m/s). */
export interface GoalConfig {
  x: number;
  y: number;
  beta: number;
  dTol: number;
  epsTol: number;
  speed: number;
  halting: boolean;
  relaxed: boolean;
}
/** One agent: start pose and its goal queue. */
export interface AgentConfig {
  x: number;
  y: number;
  theta: number;
  v?: number;
  omega?: number;
  goals: GoalConfig[];
  /** Start the queue again after the last goal. */
  loopGoals?: boolean;
}
/** What one controller update computed (crate::funnel::Internals). Angles in rad. */
export interface Internals {
  /** 0 End_of_Steering, 1 Orientation_only, 2 Position_only, 3 Funnelling. */
  mode: 0 | 1 | 2 | 3;
  d: number;
  alpha: number;
  eta: number;
  deltaEta: number;
  mu: number;
  muMax: number;
  gamma: number;
  reachable: boolean;
  vDt: number;
  /** Relaxed funnelling: arc 𝒜 = [alphaMin, alphaMax] on the ring `radius`, chosen α_r (vehicle frame). */
  arc?: { alphaMin: number; alphaMax: number; alphaR: number; radius: number } | null;
}
/** The loaded η table's shape. */
export interface TableInfo {
  entries: number;
  distances: number[];
  alphas: number[];
  omegaFractions: number[];
  speeds: number[];
  desiredSpeeds: number[];
  /** Smallest sampled distance D_η, m. */
  dEta: number;
  params: VehicleParams;
}
/** A loaded scenario: its name and the world box to show. */
export interface ScenarioInfo {
  name: string;
  agents: number;
  minX: number;
  minY: number;
  maxX: number;
  maxY: number;
}
"#;

fn js_err(context: &str, e: impl core::fmt::Display) -> JsError {
    JsError::new(&format!("{context}: {e}"))
}

fn from_js<T: for<'de> Deserialize<'de>>(what: &str, v: JsValue) -> Result<T, JsError> {
    serde_wasm_bindgen::from_value(v).map_err(|e| js_err(what, e))
}

fn to_js<T: Serialize>(v: &T) -> Result<JsValue, JsError> {
    v.serialize(&serde_wasm_bindgen::Serializer::json_compatible())
        .map_err(|e| js_err("conversion to JavaScript", e))
}

/// The crate version, to show on the page and check the package loaded.
#[wasm_bindgen]
#[must_use]
pub fn version() -> String {
    env!("CARGO_PKG_VERSION").to_owned()
}

/// `n` uniform samples in `[0, 1)` from the shared PCG32 generator, seeded:
/// the same seed gives the same numbers natively and in the browser.
#[wasm_bindgen(js_name = randomSamples)]
#[must_use]
pub fn random_samples(seed: u32, n: u32) -> Vec<f32> {
    let mut rng = Rng::new(u64::from(seed));
    (0..n).map(|_| rng.next_f32()).collect()
}

#[derive(Serialize)]
#[serde(rename_all = "camelCase")]
struct TableInfo<'a> {
    entries: usize,
    distances: &'a [f32],
    alphas: &'a [f32],
    omega_fractions: &'a [f32],
    speeds: &'a [f32],
    desired_speeds: &'a [f32],
    d_eta: f32,
    params: VehicleParams,
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

/// The lab: the η table, the vehicle parameters and the agents.
#[wasm_bindgen]
pub struct Lab {
    table: EtaTable,
    params: VehicleParams,
}

#[wasm_bindgen]
impl Lab {
    /// Loads an η table from the bytes of `tables/eta.bin`; a corrupt,
    /// truncated or mismatched table is a `JsError` with the loader's message.
    #[wasm_bindgen(constructor)]
    pub fn new(table: &[u8]) -> Result<Lab, JsError> {
        let table = EtaTable::from_bytes(table).map_err(|e| js_err("η table", e))?;
        let params = table.params().vehicle;
        params
            .validate()
            .map_err(|e| js_err("η table parameters", e))?;
        Ok(Lab { table, params })
    }

    /// The table's axes and build parameters.
    #[wasm_bindgen(js_name = tableInfo, unchecked_return_type = "TableInfo")]
    pub fn table_info(&self) -> Result<JsValue, JsError> {
        to_js(&TableInfo {
            entries: self.table.len(),
            distances: self.table.axis(0),
            alphas: self.table.axis(1),
            omega_fractions: self.table.axis(2),
            speeds: self.table.axis(3),
            desired_speeds: self.table.axis(4),
            d_eta: self.table.d_eta(),
            params: self.table.params().vehicle,
        })
    }

    /// The vehicle parameters in force.
    #[wasm_bindgen(unchecked_return_type = "VehicleParams")]
    pub fn params(&self) -> Result<JsValue, JsError> {
        to_js(&self.params)
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
        self.params = p;
        Ok(match self.table.check_params(&p) {
            Ok(()) => String::new(),
            Err(e) => format!("{e} (η predictions are approximate until then)"),
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
        if v_c.is_finite() && omega_c.is_finite() && v_d.is_finite() {
            field_samples(
                &self.table,
                self.table.distances(),
                omega_c,
                v_c,
                v_d,
                &mut out,
            );
        }
        out
    }

    /// The sampled ring of the table nearest to distance `d` (paper 001
    /// Fig. 4), same layout as [`Lab::eta_field`].
    #[wasm_bindgen(js_name = etaRingAt)]
    #[must_use]
    pub fn eta_ring_at(&self, d: f32, v_c: f32, omega_c: f32, v_d: f32) -> Vec<f32> {
        let mut out = Vec::new();
        if !(d.is_finite() && v_c.is_finite() && omega_c.is_finite() && v_d.is_finite()) {
            return out;
        }
        let ring = self
            .table
            .distances()
            .iter()
            .copied()
            .min_by(|a, b| (a - d).abs().total_cmp(&(b - d).abs()));
        if let Some(r) = ring {
            field_samples(&self.table, &[r], omega_c, v_c, v_d, &mut out);
        }
        out
    }
}
