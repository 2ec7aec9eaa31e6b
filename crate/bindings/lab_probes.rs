//! `Lab`'s η probes: the η field and a ring of the table round a vehicle
//! (paper 001 Figs. 3 and 4), and the seek simulations the table saves
//! against its lookups, for the learn page to time.

use glam::Vec2;
use wasm_bindgen::prelude::*;

use super::lab::Lab;
use crate::base::rng::Rng;
use crate::base::vehicle::VehicleState;
use crate::bindings::boundary::js_err;
use crate::funnelling::ghost::table_limits;
use crate::funnelling::seek::{simulate_reach, ReachOutcome};
use crate::funnelling::table::lookup::EtaTable;

#[wasm_bindgen]
impl Lab {
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
                simulate_reach(self.world.params(), start, target, v_d, &lim),
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
        let v_max = self.world.params().v_max;
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
