//! The JavaScript boundary of crowded path following (paper 003): the
//! `CrowdLab` class the crowd page drives.
//!
//! Same rules as [`crate::bindings`]: conversion only, every value from
//! JavaScript is checked by the core (a [`crate::crowd::error::CrowdError`]
//! becomes a `JsError` with its message, never a panic), configuration
//! objects carry real TypeScript types, bulk per-boid data crosses as
//! `Float32Array` (one copy per call). Units: world units and steps (one
//! step is one paper frame).

use wasm_bindgen::prelude::*;

use crate::bindings::boundary::{from_js, js_err, to_js};

use crate::crowd::boid_seek::Seek;
use crate::crowd::config::CrowdConfig;
use crate::crowd::world::Crowd;

#[wasm_bindgen(typescript_custom_section)]
const TS_CROWD_TYPES: &'static str = r#"
/** A seek strategy (crate::crowd::boid_seek::Seek): Reynolds, or Parker with the share of the way to the target per step, in (0, 1]. */
export type CrowdSeek = { kind: "reynolds" } | { kind: "parker"; fraction: number };
/** The pathway (crate::crowd::config::PathConfig): polyline points [x, y] in travel order, radius (half-width). World units. */
export interface CrowdPathConfig {
  points: [number, number][];
  radius: number;
  closed: boolean;
}
/** A crowd run (crate::crowd::config::CrowdConfig). Lengths in world units, time in steps. */
export interface CrowdConfig {
  name?: string;
  seed: number;
  boids: number;
  seek: CrowdSeek;
  separation: boolean;
  separation_weight: number;
  boid_radius: number;
  max_speed: number;
  max_force: number;
  predict_distance: number;
  lookahead: number;
  spawn_spread: number;
  path: CrowdPathConfig;
  warmup_steps: number;
  measure_steps: number;
}
/** Measures since the last reset (crate::crowd::metrics::CrowdMetrics); null when undefined. */
export interface CrowdMetrics {
  steps: number;
  laps: number;
  mean_lap_steps: number | null;
  mean_distance: number | null;
  p95_distance: number | null;
  outside_share: number | null;
  mean_offset: number | null;
  mean_steer: number | null;
  mean_separation: number | null;
  overlapping_pairs_per_step: number | null;
  trace_spread: number | null;
}
"#;

/// Steps a single [`CrowdLab::step`] call may ask for.
const MAX_STEPS_PER_CALL: u32 = 10_000;

/// A crowd of boids following a pathway.
#[wasm_bindgen]
pub struct CrowdLab {
    crowd: Crowd,
    /// Boids the last [`CrowdLab::step_strip`] stepped.
    owned: Vec<u32>,
}

#[wasm_bindgen]
impl CrowdLab {
    /// A crowd from a configuration object; a malformed or out-of-range
    /// configuration is a `JsError` naming the field.
    #[wasm_bindgen(constructor)]
    pub fn new(
        #[wasm_bindgen(unchecked_param_type = "CrowdConfig")] config: JsValue,
    ) -> Result<CrowdLab, JsError> {
        let cfg: CrowdConfig = from_js("crowd configuration", config)?;
        let crowd = Crowd::new(&cfg).map_err(|e| js_err("crowd configuration", e))?;
        Ok(CrowdLab {
            crowd,
            owned: Vec::new(),
        })
    }

    /// A crowd from the JSON text of a preset (`scenarios/crowd/*.json`).
    #[wasm_bindgen(js_name = fromJson)]
    pub fn from_json(text: &str) -> Result<CrowdLab, JsError> {
        let crowd = Crowd::from_json(text).map_err(|e| js_err("crowd preset", e))?;
        Ok(CrowdLab {
            crowd,
            owned: Vec::new(),
        })
    }

    /// The paper's presets: Tests I–IV × (Reynolds, Parker 100 %, 10 %,
    /// 1 %, 0.1 %), in that order.
    #[wasm_bindgen(js_name = paperPresets, unchecked_return_type = "CrowdConfig[]")]
    pub fn paper_presets() -> Result<JsValue, JsError> {
        to_js(&CrowdConfig::paper_presets())
    }

    /// The current configuration (boid count and edits included).
    #[wasm_bindgen(unchecked_return_type = "CrowdConfig")]
    pub fn config(&self) -> Result<JsValue, JsError> {
        to_js(self.crowd.config())
    }

    /// Advances `n` steps (at most 10,000 per call).
    pub fn step(&mut self, n: u32) {
        for _ in 0..n.min(MAX_STEPS_PER_CALL) {
            self.crowd.step();
        }
    }

    /// Number of boids.
    #[must_use]
    pub fn count(&self) -> u32 {
        self.crowd.len() as u32
    }

    /// Steps since construction.
    #[must_use]
    pub fn time(&self) -> f64 {
        self.crowd.time() as f64
    }

    /// Boid positions, flat `[x0, y0, x1, y1, ...]`.
    #[must_use]
    pub fn positions(&self) -> Vec<f32> {
        self.crowd.positions().to_vec()
    }

    /// Boid velocities, flat `[vx0, vy0, ...]`, world units per step.
    #[must_use]
    pub fn velocities(&self) -> Vec<f32> {
        self.crowd.velocities().to_vec()
    }

    /// The highlighted boid's last complete lap, flat `[x, y, ...]` (its
    /// current partial lap until it completes one).
    #[must_use]
    pub fn trace(&self) -> Vec<f32> {
        self.crowd.trace().to_vec()
    }

    /// Index of the highlighted boid.
    #[wasm_bindgen(js_name = tracedBoid)]
    #[must_use]
    pub fn traced_boid(&self) -> u32 {
        self.crowd.traced_boid() as u32
    }

    /// Highlights boid `i` (clears the trace).
    #[wasm_bindgen(js_name = selectTraced)]
    pub fn select_traced(&mut self, i: u32) -> Result<(), JsError> {
        let n = self.crowd.len();
        if i as usize >= n {
            return Err(JsError::new(&format!("no boid {i} (there are {n})")));
        }
        self.crowd.select_traced(i as usize);
        Ok(())
    }

    /// The path's points, flat `[x0, y0, ...]`.
    #[wasm_bindgen(js_name = pathPoints)]
    #[must_use]
    pub fn path_points(&self) -> Vec<f32> {
        self.crowd.path().points_flat()
    }

    /// The path radius (half-width), world units.
    #[wasm_bindgen(js_name = pathRadius)]
    #[must_use]
    pub fn path_radius(&self) -> f32 {
        self.crowd.path().radius()
    }

    /// Whether the path is a closed circuit.
    #[wasm_bindgen(js_name = pathClosed)]
    #[must_use]
    pub fn path_closed(&self) -> bool {
        self.crowd.path().is_closed()
    }

    /// The boid radius, world units.
    #[wasm_bindgen(js_name = boidRadius)]
    #[must_use]
    pub fn boid_radius(&self) -> f32 {
        self.crowd.config().boid_radius
    }

    /// Changes the boid count (existing boids keep their state).
    #[wasm_bindgen(js_name = setBoidCount)]
    pub fn set_boid_count(&mut self, n: u32) -> Result<(), JsError> {
        self.crowd
            .set_boid_count(n as usize)
            .map_err(|e| js_err("boid count", e))
    }

    /// Replaces the path points (flat `[x0, y0, ...]`); resets the measures
    /// and the trace. On error nothing changes.
    #[wasm_bindgen(js_name = setPathPoints)]
    pub fn set_path_points(&mut self, xy: &[f32]) -> Result<(), JsError> {
        self.crowd
            .set_path_points(xy)
            .map_err(|e| js_err("path points", e))
    }

    /// Sets the path radius; resets the measures.
    #[wasm_bindgen(js_name = setPathRadius)]
    pub fn set_path_radius(&mut self, radius: f32) -> Result<(), JsError> {
        self.crowd
            .set_path_radius(radius)
            .map_err(|e| js_err("path radius", e))
    }

    /// Opens or closes the path; resets the measures and the trace.
    #[wasm_bindgen(js_name = setPathClosed)]
    pub fn set_path_closed(&mut self, closed: bool) -> Result<(), JsError> {
        self.crowd
            .set_path_closed(closed)
            .map_err(|e| js_err("path", e))
    }

    /// Switches the seek strategy (next step).
    #[wasm_bindgen(js_name = setSeek)]
    pub fn set_seek(
        &mut self,
        #[wasm_bindgen(unchecked_param_type = "CrowdSeek")] seek: JsValue,
    ) -> Result<(), JsError> {
        let s: Seek = from_js("seek", seek)?;
        self.crowd.set_seek(s).map_err(|e| js_err("seek", e))
    }

    /// Switches separation and sets its weight (in `[0, 10]`).
    #[wasm_bindgen(js_name = setSeparation)]
    pub fn set_separation(&mut self, on: bool, weight: f32) -> Result<(), JsError> {
        self.crowd
            .set_separation(on, weight)
            .map_err(|e| js_err("separation", e))
    }

    /// The measures since the last reset.
    #[wasm_bindgen(unchecked_return_type = "CrowdMetrics")]
    pub fn metrics(&self) -> Result<JsValue, JsError> {
        to_js(&self.crowd.metrics())
    }

    /// Clears the measures (boids keep their state).
    #[wasm_bindgen(js_name = resetMetrics)]
    pub fn reset_metrics(&mut self) {
        self.crowd.reset_metrics();
    }

    /// Overlapping pairs at the last step.
    #[wasm_bindgen(js_name = lastOverlaps)]
    #[must_use]
    pub fn last_overlaps(&self) -> f64 {
        self.crowd.last_overlaps() as f64
    }

    /// The complete state, for the crowd's stepping workers: flat
    /// `[x0, y0, …, x(n−1), y(n−1), vx0, vy0, …]` (positions, then
    /// velocities).
    #[must_use]
    pub fn state(&self) -> Vec<f32> {
        let mut s = Vec::with_capacity(2 * self.crowd.positions().len());
        s.extend_from_slice(self.crowd.positions());
        s.extend_from_slice(self.crowd.velocities());
        s
    }

    /// Loads a complete state (the layout of [`CrowdLab::state`]) and the
    /// step count; the trace and measures are kept. A wrong length is an
    /// error naming it, and nothing changes.
    #[wasm_bindgen(js_name = loadState)]
    pub fn load_state(&mut self, state: &[f32], time: f64) -> Result<(), JsError> {
        let half = state.len() / 2;
        if state.len() != 2 * self.crowd.positions().len() {
            return Err(JsError::new(&format!(
                "crowd state: {} floats for {} boids (4 per boid)",
                state.len(),
                self.crowd.len()
            )));
        }
        let (pos, vel) = state.split_at(half);
        self.crowd
            .set_state(pos, vel, time.max(0.0) as u64)
            .map_err(|e| js_err("crowd state", e))
    }

    /// One step of the boids whose x lies in `[lo, hi)` (one worker's
    /// vertical strip, `Crowd::step_strip`: the same bits as a whole
    /// step); returns how many it stepped. Read them with
    /// [`CrowdLab::owned_indices`] and [`CrowdLab::owned_state`].
    #[wasm_bindgen(js_name = stepStrip)]
    pub fn step_strip(&mut self, lo: f32, hi: f32) -> u32 {
        self.crowd.step_strip(lo, hi, &mut self.owned);
        self.owned.len() as u32
    }

    /// The boids the last `stepStrip` stepped, ascending.
    #[wasm_bindgen(js_name = ownedIndices)]
    #[must_use]
    pub fn owned_indices(&self) -> Vec<u32> {
        self.owned.clone()
    }

    /// Their new states, `[x, y, vx, vy]` per boid in the order of
    /// `ownedIndices`.
    #[wasm_bindgen(js_name = ownedState)]
    #[must_use]
    pub fn owned_state(&self) -> Vec<f32> {
        let (p, v) = (self.crowd.positions(), self.crowd.velocities());
        let mut out = Vec::with_capacity(4 * self.owned.len());
        for &i in &self.owned {
            let i = 2 * i as usize;
            out.extend_from_slice(&[p[i], p[i + 1], v[i], v[i + 1]]);
        }
        out
    }

    /// The workers' hand-back without copies: views of the
    /// core's own memory, `[indices of the last stepStrip's boids
    /// (ascending), every boid's positions (x, y), every boid's velocities]`.
    /// The worker copies the owned boids straight into its state buffer
    /// (all of them in two bulk copies when it owns every boid) instead of
    /// taking [`CrowdLab::owned_indices`] and [`CrowdLab::owned_state`]
    /// (two allocations and copies out of the core, then a copy in JS: most
    /// of a hand-back's time in a big crowd).
    ///
    /// The views are valid until the next call into the core (one that
    /// allocates may grow the memory and detach them): read them at once.
    #[wasm_bindgen(js_name = stripViews, unchecked_return_type = "[Uint32Array, Float32Array, Float32Array]")]
    #[must_use]
    #[allow(unsafe_code)]
    pub fn strip_views(&self) -> js_sys::Array {
        // SAFETY: the views alias memory owned by `self` and are handed to
        // JS without an allocation in between; the caller reads them before
        // calling into the core again (documented above), so no memory
        // growth can detach them and no Rust code mutates them meanwhile.
        unsafe {
            js_sys::Array::of3(
                &js_sys::Uint32Array::view(&self.owned),
                &js_sys::Float32Array::view(self.crowd.positions()),
                &js_sys::Float32Array::view(self.crowd.velocities()),
            )
        }
    }

    /// A step run in workers: counts it and records the traced boid's new
    /// position (`x`, `y`) in its lap trace.
    #[wasm_bindgen(js_name = observeStep)]
    pub fn observe_step(&mut self, x: f32, y: f32) {
        self.crowd.observe_step(glam::Vec2::new(x, y));
    }

    /// Switches metric recording (on by default).
    #[wasm_bindgen(js_name = setMetricsEnabled)]
    pub fn set_metrics_enabled(&mut self, on: bool) {
        self.crowd.set_metrics_enabled(on);
    }
}
