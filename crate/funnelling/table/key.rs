//! The η table's parameter key: one 64-bit FNV-1a hash of
//! everything a table's bytes depend on (format version, integrator, the
//! 11 build parameters, the minimum turning radius when not 0, every axis value and the generator's time step
//! when it is not the vehicle's), written as 16 hex digits.
//!
//! Why: tables are built on demand for any vehicle, and cached
//! (natively in a directory, in the browser in IndexedDB). A cache keyed
//! by this hash can only ever return a table built for exactly these
//! limits; the key is recomputed from a cached file's own header before it
//! is used, so a renamed or stale file is rebuilt, never used silently.
//! The same function runs natively and in wasm, so both caches agree.

use super::format::{BuildParams, AXES, FORMAT_VERSION};
use super::lookup::EtaTable;
use super::spec::{generator_dt, TableSpec};

const FNV_OFFSET: u64 = 0xcbf2_9ce4_8422_2325;
const FNV_PRIME: u64 = 0x0000_0100_0000_01b3;

fn mix(h: &mut u64, word: u32) {
    for b in word.to_le_bytes() {
        *h ^= u64::from(b);
        *h = h.wrapping_mul(FNV_PRIME);
    }
}

/// The key of a table with build parameters `params` and axes `axes`.
#[must_use]
pub fn key_of(params: &BuildParams, axes: [&[f32]; AXES]) -> String {
    let mut h = FNV_OFFSET;
    mix(&mut h, FORMAT_VERSION);
    mix(&mut h, params.vehicle.integrator.code());
    for x in params.to_array() {
        mix(&mut h, x.to_bits());
    }
    // The generator's step, when not the vehicle's own (so the keys of
    // tables whose step never changed stay as they were).
    // The minimum turning radius, when there is one (a unicycle's key is
    // unchanged).
    if params.vehicle.car_like() {
        mix(&mut h, 0x524D_494E);
        mix(&mut h, params.vehicle.r_min.to_bits());
    }
    let step = generator_dt(&params.vehicle);
    if step.to_bits() != params.vehicle.dt.to_bits() {
        mix(&mut h, 0x5354_4550);
        mix(&mut h, step.to_bits());
    }
    for a in axes {
        mix(&mut h, a.len() as u32);
        for x in a {
            mix(&mut h, x.to_bits());
        }
    }
    format!("{h:016x}")
}

impl TableSpec {
    /// The parameter key of the table this spec generates.
    #[must_use]
    pub fn key(&self) -> String {
        key_of(
            &self.params,
            core::array::from_fn(|k| self.axes[k].as_slice()),
        )
    }
}

impl EtaTable {
    /// The parameter key of this table (equal to its spec's
    /// [`TableSpec::key`]).
    #[must_use]
    pub fn key(&self) -> String {
        key_of(self.params(), core::array::from_fn(|k| self.axis(k)))
    }
}
