//! `Lab` for the GPU kernel (`web/src/gpu/`): the η table's and the world's
//! arrays as the kernel reads them, and, for its parity checks, the core's
//! own lookups at given probes and a run's arrival counts.

use wasm_bindgen::prelude::*;

use super::lab::{whole, Lab};
use crate::bindings::boundary::js_err;
use crate::funnelling::table::gpu_table::GpuTable;
use crate::world::entry_judge::EntryJudge;
use crate::world::gpu_world::GpuWorld;

/// Most agents of a GPU random crowd: 16 GPU words of agent and goal, a
/// few hundred MB of wasm memory, past that.
const AGENTS_GPU: u32 = 4_000_000;

/// `gpuWorld`'s one array: the agents', goals' and held commands' word
/// counts, then the agents, the goals, the commands and the settings' bits.
fn pack(g: GpuWorld) -> Vec<u32> {
    let mut out = Vec::with_capacity(
        3 + g.agents.len() + g.goals.len() + g.commands.len() + g.settings.len(),
    );
    out.extend([
        g.agents.len() as u32,
        g.goals.len() as u32,
        g.commands.len() as u32,
    ]);
    out.extend(g.agents);
    out.extend(g.goals);
    out.extend(g.commands);
    out.extend(g.settings.iter().map(|x| x.to_bits()));
    out
}

/// Floats per probe of [`Lab::lookup_probes`]: D, α, ω, v_c, v_d.
const PROBE: usize = 5;

#[wasm_bindgen]
impl Lab {
    /// The η table's counts and offsets (`GpuTable::meta`).
    #[wasm_bindgen(js_name = gpuTableMeta)]
    pub fn gpu_table_meta(&self) -> Result<Vec<u32>, JsError> {
        Ok(GpuTable::of(self.table()?).meta)
    }

    /// The η table's axes (`GpuTable::axes`).
    #[wasm_bindgen(js_name = gpuTableAxes)]
    pub fn gpu_table_axes(&self) -> Result<Vec<f32>, JsError> {
        Ok(GpuTable::of(self.table()?).axes)
    }

    /// The η table's cells, four floats per entry (`GpuTable::cells`).
    #[wasm_bindgen(js_name = gpuTableCells)]
    pub fn gpu_table_cells(&self) -> Result<Vec<f32>, JsError> {
        Ok(GpuTable::of(self.table()?).cells)
    }

    /// Why the GPU kernel cannot step this world, or undefined when it can.
    #[wasm_bindgen(js_name = gpuRefusal)]
    #[must_use]
    pub fn gpu_refusal(&self) -> Option<String> {
        GpuWorld::refusal(&self.world)
    }

    /// The world for the kernel, as one array of words: the agents', the
    /// goals' and the held commands' word counts, then the agents, the
    /// goals, the commands and the settings (`f32` bits).
    #[wasm_bindgen(js_name = gpuWorld)]
    pub fn gpu_world(&self) -> Result<Vec<u32>, JsError> {
        let g = GpuWorld::of(&self.world, self.table()?).map_err(|e| JsError::new(&e))?;
        Ok(pack(g))
    }

    /// The seeded random crowd of `spawnRandom` for the kernel, in
    /// `gpuWorld`'s layout, without building it in this lab's world (up
    /// to `AGENTS_GPU` agents, each with its first `goals` goals).
    #[wasm_bindgen(js_name = gpuRandomCrowd)]
    pub fn gpu_random_crowd(
        &self,
        n: u32,
        seed: f64,
        extent: f32,
        speed: f32,
        goals: u32,
    ) -> Result<Vec<u32>, JsError> {
        if n > AGENTS_GPU {
            return Err(JsError::new(&format!(
                "gpuRandomCrowd: {n} agents is more than {AGENTS_GPU}"
            )));
        }
        let seed = whole(&crate::base::ranges::SEED, seed)?;
        let g = GpuWorld::random_crowd(
            &self.world,
            self.table()?,
            n as usize,
            seed,
            extent,
            speed,
            goals as usize,
        )
        .map_err(|e| JsError::new(&e))?;
        Ok(pack(g))
    }

    /// The short-range choices the kernel awaits (`GpuWorld::decide_pending`),
    /// made with this lab's vehicle, settings and table: `agents` as read
    /// back after a step (changed in place), `goals` as uploaded. Returns
    /// how many were made.
    #[wasm_bindgen(js_name = gpuDecide)]
    pub fn gpu_decide(&self, agents: &mut [u32], goals: &[u32]) -> Result<u32, JsError> {
        if agents.len() % GpuWorld::AGENT_WORDS != 0 {
            return Err(JsError::new(&format!(
                "gpuDecide: {} words is not a whole number of agents of {}",
                agents.len(),
                GpuWorld::AGENT_WORDS
            )));
        }
        Ok(GpuWorld::decide_pending(
            &self.world,
            self.table()?,
            agents,
            goals,
        ))
    }

    /// The core's lookup at each probe (five floats each: D, α, ω, v_c,
    /// v_d): four floats each, η, reachable (1/0), v_dt, η valid (1/0).
    #[wasm_bindgen(js_name = lookupProbes)]
    pub fn lookup_probes(&self, probes: &[f32]) -> Result<Vec<f32>, JsError> {
        if probes.len() % PROBE != 0 {
            return Err(JsError::new(&format!(
                "lookupProbes: {} floats is not a whole number of probes of {PROBE}",
                probes.len()
            )));
        }
        let t = self.table()?;
        Ok(probes
            .chunks_exact(PROBE)
            .flat_map(|q| {
                let lk = t.lookup(q[0], q[1], q[2], q[3], q[4]);
                let flag = |b: bool| if b { 1.0 } else { 0.0 };
                [lk.eta, flag(lk.reachable), lk.v_dt, flag(lk.eta_valid)]
            })
            .collect())
    }

    /// Steps `n` times (at most 10,000), counting per agent its goals left
    /// and those entered oriented (`EntryJudge`): two words per agent.
    #[wasm_bindgen(js_name = stepJudging)]
    pub fn step_judging(&mut self, n: u32) -> Result<Vec<u32>, JsError> {
        let t = self
            .table
            .clone()
            .ok_or_else(|| JsError::new("η table: not loaded yet"))?;
        let mut judge = EntryJudge::new(&self.world);
        for _ in 0..n.min(10_000) {
            self.world.step(&t).map_err(|e| js_err("η table", e))?;
            judge.observe(&self.world);
        }
        Ok(judge.verdicts())
    }
}
