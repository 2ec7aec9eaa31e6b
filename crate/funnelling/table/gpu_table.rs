//! The η table as a GPU kernel reads it (docs/DESIGN.md §8, §20): the
//! numbers [`EtaTable::lookup`] blends, laid out as flat arrays for storage
//! buffers, so the kernel (`web/src/gpu/`) interpolates the same cells with
//! the same weights and differs from the core only in float order and in
//! its own `atan2`.
//!
//! Three arrays:
//! - `meta` (`u32`, [`GpuTable::META_WORDS`]): per axis its sample count,
//!   stride, offset of its samples and of its reciprocal widths in `axes`,
//!   and its interval count; then the entry count.
//! - `axes` (`f32`): per axis its samples ([`Axis::intervals`]: the α axis
//!   closed by its first sample + 2π) and each interval's reciprocal width,
//!   the very numbers the core's constant-time locate uses.
//! - `cells` (`f32`, four per entry): `(cos η, sin η, kind, speed)`, where
//!   `kind` is 1 for a reachable entry (its blend cell is `(cos, sin, 1, 0)`),
//!   2 for an unreachable one whose stored fallback η is valid (blend cell
//!   `(0, 0, 0, speed)`, fallback cell `(cos, sin, 1, 0)`), 0 for neither
//!   (`(0, 0, 0, speed)`, no fallback). `cos` and `sin` are the core's own
//!   ([`trig::sin_cos`]), so both sides blend the same bits.

use super::format::{AXES, FLAG_ETA_VALID, FLAG_REACHABLE};
use super::grid::Axis;
use super::lookup::EtaTable;
use crate::base::trig;

/// The η table's arrays for a GPU kernel (the module's doc gives the layout).
#[derive(Clone, Debug, PartialEq)]
pub struct GpuTable {
    /// Counts, strides and offsets, `u32`.
    pub meta: Vec<u32>,
    /// The axes' samples and reciprocal interval widths.
    pub axes: Vec<f32>,
    /// Four floats per entry: `cos η, sin η, kind, speed`.
    pub cells: Vec<f32>,
}

impl GpuTable {
    /// Words of `meta`: five per axis field (count, stride, samples'
    /// offset, reciprocals' offset, intervals), the entry count, padding to
    /// a multiple of four.
    pub const META_WORDS: usize = 28;

    /// The layout of `table`.
    #[must_use]
    pub fn of(table: &EtaTable) -> Self {
        let mut meta = vec![0u32; Self::META_WORDS];
        let mut axes = Vec::new();
        let mut strides = [1usize; AXES];
        for k in (0..AXES - 1).rev() {
            strides[k] = strides[k + 1] * table.axes[k + 1].len();
        }
        for (k, axis) in table.grid.iter().enumerate() {
            let (x, inv) = Axis::intervals(axis);
            meta[k] = table.axes[k].len() as u32;
            meta[AXES + k] = strides[k] as u32;
            meta[2 * AXES + k] = axes.len() as u32;
            axes.extend_from_slice(&x);
            meta[3 * AXES + k] = axes.len() as u32;
            meta[4 * AXES + k] = inv.len() as u32;
            axes.extend_from_slice(&inv);
        }
        meta[5 * AXES] = table.eta.len() as u32;
        let mut cells = Vec::with_capacity(4 * table.eta.len());
        for ((&eta, &speed), &flags) in table.eta.iter().zip(&table.v_fallback).zip(&table.flags) {
            let (s, c) = trig::sin_cos(eta);
            let kind = if flags & FLAG_REACHABLE != 0 {
                1.0
            } else if flags == FLAG_ETA_VALID {
                2.0
            } else {
                0.0
            };
            cells.extend_from_slice(&[c, s, kind, speed]);
        }
        Self { meta, axes, cells }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::base::vehicle::VehicleParams;
    use crate::funnelling::table::spec::TableSpec;

    #[test]
    fn the_layout_names_every_axis_and_entry() {
        let spec = TableSpec::with_counts(VehicleParams::default(), [3, 8, 3, 3, 3]);
        let t = spec.generate().unwrap();
        let g = GpuTable::of(&t);
        let n: Vec<u32> = (0..AXES).map(|k| t.axis(k).len() as u32).collect();
        assert_eq!(g.meta[..AXES], n[..]);
        assert_eq!(g.meta[2 * AXES - 1], 1, "the last axis is contiguous");
        assert_eq!(g.meta[AXES], n[1] * n[2] * n[3] * n[4]);
        // α is periodic: as many intervals as samples; the others one fewer.
        assert_eq!(g.meta[4 * AXES + 1], n[1]);
        assert_eq!(g.meta[4 * AXES], n[0] - 1);
        assert_eq!(g.meta[5 * AXES] as usize, t.len());
        assert_eq!(g.cells.len(), 4 * t.len());
        let x0 = g.meta[2 * AXES] as usize;
        assert_eq!(g.axes[x0..x0 + 3], t.axis(0)[..]);
    }
}
