//! `Lab`'s scenarios: a scenario file's world put in force, and what the
//! page shows of it.

use glam::Vec2;
use wasm_bindgen::prelude::*;

use super::lab::{lab_world, Lab};
use super::lab_types::ScenarioInfo;
use crate::bindings::boundary::{js_err, to_js};
use crate::world::scenario::Scenario;

#[wasm_bindgen]
impl Lab {
    /// Replaces the world with a scenario file's (scenarios/*.json, see
    /// crate::world::scenario); returns its name, description and bounding box.
    #[wasm_bindgen(js_name = loadScenario, unchecked_return_type = "ScenarioInfo")]
    pub fn load_scenario(&mut self, json: &str) -> Result<JsValue, JsError> {
        let sc = Scenario::from_json(json).map_err(|e| js_err("scenario", e))?;
        let mut world = lab_world(sc.world().map_err(|e| js_err("scenario", e))?);
        if let Some(t) = &self.table {
            world.plan(t).map_err(|e| js_err("η table", e))?;
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
        let warning = match self.table.as_ref().map(|t| t.check_params(world.params())) {
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
