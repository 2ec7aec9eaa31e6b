//! What the lab's stepping workers call: the world's
//! slices ([`crate::world::split`]) and a hash of the state, so
//! the page can check N workers against one core.

use wasm_bindgen::prelude::*;

use super::lab::{whole, Lab};
use crate::bindings::boundary::js_err;

#[wasm_bindgen]
impl Lab {
    /// At most `parts` contiguous agent ranges, flattened `[start0, end0,
    /// start1, end1, …]`: about equal, no facing link (paper 000 Fig. 6)
    /// crossing a cut, one range when avoidance couples the agents.
    #[wasm_bindgen(js_name = splitRanges)]
    #[must_use]
    pub fn split_ranges(&self, parts: u32) -> Vec<u32> {
        self.world
            .split_ranges(parts as usize)
            .into_iter()
            .flat_map(|r| [r.start as u32, r.end as u32])
            .collect()
    }

    /// Keeps agents `start..end` only, renumbered from 0 (a worker's slice):
    /// stepped, they give the same bits as in the whole world. Refused,
    /// nothing changed, for a bad range, a facing link cut, or avoidance on.
    #[wasm_bindgen(js_name = retainRange)]
    pub fn retain_range(&mut self, start: u32, end: u32) -> Result<(), JsError> {
        self.world
            .retain_range(start as usize..end as usize)
            .map_err(|e| js_err("agents", e))
    }

    /// `spawnRandom(n, seed, extent, speed)`'s agents `start..end` only
    /// (a worker's slice of the playground's crowd: the same agents, bit for
    /// bit, without building the others). Checked as `spawnRandom`.
    #[wasm_bindgen(js_name = spawnRandomRange)]
    pub fn spawn_random_range(
        &mut self,
        n: f64,
        seed: f64,
        extent: f32,
        speed: f32,
        start: u32,
        end: u32,
    ) -> Result<(), JsError> {
        let n = whole(&crate::base::ranges::AGENTS, n)?;
        let seed = whole(&crate::base::ranges::SEED, seed)?;
        self.world
            .spawn_random_kept(
                n as usize,
                seed,
                extent,
                speed,
                start as usize..end as usize,
            )
            .map_err(|e| js_err("random agents", e))
    }
}
