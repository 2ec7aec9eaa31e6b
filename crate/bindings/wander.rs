//! The JavaScript boundary of the random steering toolkit (paper 004): the
//! `WanderLab` class the gallery page drives.
//!
//! Same rules as [`crate::bindings`]: conversion only, every configuration
//! goes through the core's validation (a [`crate::wander::error::WanderError`]
//! becomes a `JsError` with its message, never a panic), configuration
//! objects carry real TypeScript types (snake_case, as in the preset
//! files), traces cross as `Float32Array`. A configuration and its seed give
//! the same trace bit for bit as natively.

use wasm_bindgen::prelude::*;

use crate::bindings::boundary::{from_js, js_err, to_js};

use crate::wander::{config::WanderConfig, pipeline::WanderPreset, pipeline::Wanderer};

#[wasm_bindgen(typescript_custom_section)]
const TS_WANDER_TYPES: &'static str = r#"
/** Start pose and constant speed (crate::wander::config::AgentConfig). World units per step, degrees. */
export interface WanderAgent { x?: number; y?: number; heading_deg?: number; speed?: number }
/** What is controlled and its clamps, degrees (crate::wander::control::ControlConfig). */
export interface WanderControl {
  mode: "displacement" | "velocity" | "acceleration";
  max_displacement_deg?: number;
  max_velocity_deg?: number;
  max_acceleration_deg?: number;
  quantize_deg?: number | null;
}
/** A distribution of random commands (§2). */
export type WanderDistribution =
  | { kind: "uniform" }
  | { kind: "smooth_noise"; period: number }
  | { kind: "perlin"; period: number; octaves?: number; persistence?: number }
  | { kind: "curve"; points: [number, number][] };
/** A noise envelope or blend of a time function (§4). */
export type WanderNoise = { kind: "white" } | { kind: "smooth"; period: number } | { kind: "perlin"; period: number };
/** One term of a sum of periodic functions (§4). */
export interface WanderTerm {
  amplitude: number;
  frequency: number;
  phase?: number;
  weight?: "one" | "blend" | "complement" | "blend_reversed";
  shape?: "sine" | "saw" | "square";
}
/** A function of time (§4). */
export interface WanderTimeFunction {
  terms: WanderTerm[];
  dt?: number;
  envelope?: WanderNoise | null;
  blend?: WanderNoise | null;
  horizon?: number;
}
/** A random vector field (§3). */
export interface WanderField {
  cols: number;
  rows: number;
  cell: number;
  values?: "uniform" | "perlin";
  count?: number;
  switch_every?: number;
  jitter_deg?: number;
  bias?: boolean;
}
/** A transition table over angle ranges (§6). */
export interface WanderMarkov {
  edges_deg: number[];
  table: number[][];
  change_probability?: number[] | null;
  initial_range?: number;
  /** Read the table as a smooth 2D response curve (§6). */
  response_curve?: boolean;
}
/** A generated path (§7). */
export type WanderPath =
  | { kind: "fractal"; start: [number, number]; end: [number, number]; depth: number; roughness: number; rule: "midpoint" | "thirds" }
  | { kind: "circle"; center: [number, number]; radius: number; coefficients: number[]; random_coefficients?: boolean; samples?: number; shape?: "sine" | "saw" | "square" };
/** The command source (crate::wander::config::SourceConfig). */
export type WanderSource =
  | { kind: "random"; distribution: WanderDistribution }
  | { kind: "field"; field: WanderField }
  | { kind: "time_function"; function: WanderTimeFunction }
  | { kind: "markov"; markov: WanderMarkov }
  | { kind: "path"; path: WanderPath; lookahead: number }
  | { kind: "mix"; parts: { weight: number; source: WanderSource }[] };
/** Timed transitions (§5): hold each command for a fixed or random number of steps. */
export type WanderHold = { kind: "fixed"; every: number } | { kind: "random"; min: number; max: number };
/** A whole wander behaviour (crate::wander::config::WanderConfig). */
export interface WanderConfig {
  seed?: number;
  agent?: WanderAgent;
  control: WanderControl;
  source: WanderSource;
  hold?: WanderHold | null;
  trace_capacity?: number;
}
/** One labelled variant of a preset file. */
export interface WanderVariant { label: string; figure?: string | null; config: WanderConfig }
/** A preset file scenarios/wander/*.json: one component, its figure series. */
export interface WanderPreset { title: string; section: string; steps: number; variants: WanderVariant[] }
"#;

/// Steps a single [`WanderLab::run`] call may ask for.
const MAX_STEPS_PER_CALL: u32 = 1_000_000;

/// One wandering agent built from a configuration.
#[wasm_bindgen]
pub struct WanderLab {
    wanderer: Wanderer,
}

#[wasm_bindgen]
impl WanderLab {
    /// A wanderer from a configuration object (validated; a bad one is a
    /// `JsError` naming the field).
    #[wasm_bindgen(constructor)]
    pub fn new(
        #[wasm_bindgen(unchecked_param_type = "WanderConfig")] config: JsValue,
    ) -> Result<WanderLab, JsError> {
        let cfg: WanderConfig = from_js("wander configuration", config)?;
        let wanderer = Wanderer::new(cfg).map_err(|e| js_err("wander configuration", e))?;
        Ok(WanderLab { wanderer })
    }

    /// A wanderer from JSON text.
    #[wasm_bindgen(js_name = fromJson)]
    pub fn from_json(text: &str) -> Result<WanderLab, JsError> {
        let wanderer = Wanderer::from_json(text).map_err(|e| js_err("wander configuration", e))?;
        Ok(WanderLab { wanderer })
    }

    /// Parses and validates a preset file (`scenarios/wander/*.json`).
    #[wasm_bindgen(js_name = parsePreset, unchecked_return_type = "WanderPreset")]
    pub fn parse_preset(text: &str) -> Result<JsValue, JsError> {
        let p = WanderPreset::from_json(text).map_err(|e| js_err("wander preset", e))?;
        to_js(&p)
    }

    /// The configuration this wanderer was built from.
    #[wasm_bindgen(unchecked_return_type = "WanderConfig")]
    pub fn config(&self) -> Result<JsValue, JsError> {
        to_js(self.wanderer.config())
    }

    /// Advances one step.
    pub fn step(&mut self) {
        self.wanderer.step();
    }

    /// Advances `n` steps (at most 1,000,000 per call).
    pub fn run(&mut self, n: u32) {
        self.wanderer.run(n.min(MAX_STEPS_PER_CALL));
    }

    /// Back to step 0 with the same seed (replays the same trace).
    pub fn reset(&mut self) {
        self.wanderer.reset();
    }

    /// Steps taken since construction or reset.
    #[must_use]
    pub fn steps(&self) -> u32 {
        self.wanderer.steps()
    }

    /// Current pose `[x, y, θ]` (θ in radians).
    #[must_use]
    pub fn pose(&self) -> Vec<f32> {
        self.wanderer.pose().to_vec()
    }

    /// The trace, oldest first, flat `[x0, y0, θ0, x1, ...]` (at most
    /// `trace_capacity` poses).
    #[must_use]
    pub fn trace(&self) -> Vec<f32> {
        self.wanderer.trace()
    }

    /// Poses in the trace.
    #[wasm_bindgen(js_name = traceLen)]
    #[must_use]
    pub fn trace_len(&self) -> u32 {
        self.wanderer.trace_len() as u32
    }

    /// The generated path, flat `[x0, y0, ...]` (empty unless the source is
    /// a path).
    #[wasm_bindgen(js_name = pathPoints)]
    #[must_use]
    pub fn path_points(&self) -> Vec<f32> {
        self.wanderer.path_points().to_vec()
    }
}
