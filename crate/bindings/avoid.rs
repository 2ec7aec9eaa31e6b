//! The avoidance through the lab's binding: the method of the
//! world in force (presets carry theirs, `scenarios/avoid_*.json`), the
//! obstacles as a flat array for drawing and dragging (`obstacles` /
//! `setObstacles`, the same five floats per obstacle), and the overlap
//! count the e2e test reads. Thin: the core does the work.

use wasm_bindgen::prelude::*;

use super::boundary::js_err;
use super::lab::Lab;
use crate::avoidance::{config::AvoidanceMethod, config::Obstacle};

#[wasm_bindgen]
impl Lab {
    /// The avoidance method in force: `off`, `separation` or `orca`.
    #[wasm_bindgen(js_name = avoidance)]
    pub fn avoidance_method(&self) -> String {
        self.world.avoidance().method.name().into()
    }

    /// Switches the avoidance method (`off`, `separation`, `orca`), keeping
    /// the world's other avoidance settings and obstacles; anything else is
    /// an error and changes nothing.
    #[wasm_bindgen(js_name = setAvoidance)]
    pub fn set_avoidance_method(&mut self, method: &str) -> Result<(), JsError> {
        let m = AvoidanceMethod::parse(method).ok_or_else(|| {
            js_err(
                "avoidance",
                format!("`{method}` is not off, separation or orca"),
            )
        })?;
        let mut cfg = *self.world.avoidance();
        cfg.method = m;
        let obstacles = self.world.obstacles().to_vec();
        self.world
            .set_avoidance(cfg, obstacles)
            .map_err(|e| js_err("avoidance", e))
    }

    /// Steps between an agent's avoidance plans
    /// ([`crate::avoidance::config::AvoidanceConfig::replan_every`]).
    #[wasm_bindgen(js_name = avoidanceReplanEvery)]
    pub fn avoidance_replan_every(&self) -> u32 {
        self.world.avoidance().replan_every
    }

    /// Sets the steps between an agent's avoidance plans (the core's range,
    /// `avoidance.replanEvery`); out of range is an error and changes
    /// nothing.
    #[wasm_bindgen(js_name = setAvoidanceReplanEvery)]
    pub fn set_avoidance_replan_every(&mut self, every: u32) -> Result<(), JsError> {
        let mut cfg = *self.world.avoidance();
        cfg.replan_every = every;
        let obstacles = self.world.obstacles().to_vec();
        self.world
            .set_avoidance(cfg, obstacles)
            .map_err(|e| js_err("avoidance", e))
    }

    /// The agents' body radius, m (the lab draws the bodies with it).
    #[wasm_bindgen(js_name = avoidanceRadius)]
    pub fn avoidance_radius(&self) -> f32 {
        self.world.avoidance().radius
    }

    /// Pairs of agents whose bodies (radius `avoidance.radius`) overlap now.
    pub fn overlaps(&self) -> u32 {
        let r = self.world.avoidance().radius;
        let r2 = 4.0 * r * r;
        let a = self.world.agents();
        let mut n = 0u32;
        // Lab worlds are small enough for the pairwise count; the metric
        // of the studies goes through the grid (avoidance::proximity).
        for i in 0..a.len() {
            for b in &a[i + 1..] {
                if (a[i].state.pos - b.state.pos).length_squared() < r2 {
                    n += 1;
                }
            }
        }
        n
    }

    /// The obstacles, 5 floats each: kind (0 disc, 1 segment), then
    /// `x, y, radius, 0` for a disc or `x1, y1, x2, y2` for a segment.
    pub fn obstacles(&self) -> Vec<f32> {
        let mut out = Vec::with_capacity(5 * self.world.obstacles().len());
        for o in self.world.obstacles() {
            match *o {
                Obstacle::Disc { x, y, radius } => out.extend([0.0, x, y, radius, 0.0]),
                Obstacle::Segment { x1, y1, x2, y2 } => out.extend([1.0, x1, y1, x2, y2]),
            }
        }
        out
    }

    /// Replaces the obstacles with `flat`, in the layout of
    /// [`Lab::obstacles`] (the lab's drags send the whole list back).
    /// A bad record (length not a multiple of 5, unknown kind, a value out
    /// of range, a zero-length segment, too many) is an error naming
    /// `obstacles[i]` and changes nothing.
    #[wasm_bindgen(js_name = setObstacles)]
    pub fn set_obstacles(&mut self, flat: &[f32]) -> Result<(), JsError> {
        if flat.len() % 5 != 0 {
            return Err(js_err(
                "obstacles",
                format!("{} floats is not 5 per obstacle", flat.len()),
            ));
        }
        let mut list = Vec::with_capacity(flat.len() / 5);
        for (i, r) in flat.chunks_exact(5).enumerate() {
            list.push(match r[0] {
                0.0 => Obstacle::Disc {
                    x: r[1],
                    y: r[2],
                    radius: r[3],
                },
                1.0 => Obstacle::Segment {
                    x1: r[1],
                    y1: r[2],
                    x2: r[3],
                    y2: r[4],
                },
                k => {
                    return Err(js_err(
                        &format!("obstacles[{i}]"),
                        format!("kind {k} is not 0 (disc) or 1 (segment)"),
                    ))
                }
            });
        }
        let cfg = *self.world.avoidance();
        self.world
            .set_avoidance(cfg, list)
            .map_err(|e| js_err("obstacles", e))
    }
}
