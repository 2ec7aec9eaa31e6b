//! The η table `Tη` in memory and its constant-cost multilinear ("quintic
//! linear") lookup (paper 000 §3, paper 001 §3 and Fig. 3; docs/DESIGN.md §8).
//!
//! The table samples the seek controller's final radial-tangential angle η
//! over five axes: target distance `D`, radial angle `α`, current angular
//! speed, current forward speed `v_c` and desired speed `v_d`. See
//! `tables/README.md` for the byte layout and [`crate::funnelling::table::generate`] for the
//! generator and the choice of axes.
//!
//! The angular-speed axis is stored *normalised*: `s = ω_c / min(ω_max,
//! A/v_c)` in `[-1, 1]`, so that every sampled state is admissible (a state
//! with `|v·ω| > A` cannot occur and would waste samples).

use super::format::{BuildParams, TableError, AXES, FLAG_ETA_VALID, FLAG_REACHABLE};
use super::grid::{Axis, AxisPos};
use crate::base::angle::wrap;
use crate::base::minmax::MinMax;
use crate::base::trig;
use glam::Vec4;

/// One entry in memory, laid out for a branch-free blend: η as a unit
/// vector (so that blending is angle-safe across ±π by construction)
/// counted only where the sample is reachable at its desired speed, the
/// reach indicator, and the fallback speed where it is not. The 32 corners
/// of a lookup then accumulate one 4-wide multiply-add each, and one
/// `atan2` recovers η. 16 bytes: four cells share a cache line.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
struct Cell(Vec4);

impl Cell {
    const ZERO: Self = Self(Vec4::ZERO);

    /// The lookup cell of an entry.
    fn new(eta: f32, speed: f32, flags: u8) -> Self {
        let (s, c) = trig::sin_cos(eta);
        let reach = flags & FLAG_REACHABLE != 0;
        let r = if reach { 1.0 } else { 0.0 };
        Self(Vec4::new(r * c, r * s, r, if reach { 0.0 } else { speed }))
    }

    /// The cell of an entry's fallback η (unreachable at its desired
    /// speed, reachable slower). Only needed when no corner of a query is
    /// reachable, so it is built on the fly from the raw arrays rather than
    /// stored (it would double the memory of the hot cells).
    fn fallback(eta: f32, flags: u8) -> Self {
        if flags != FLAG_ETA_VALID {
            return Self::ZERO;
        }
        let (s, c) = trig::sin_cos(eta);
        Self(Vec4::new(c, s, 1.0, 0.0))
    }

    /// The cell of `|η|` for the μ bound: `[r·|η|, r, o·|η|, o]` with `r`
    /// and `o` as above, so reachable samples can be averaged on their own.
    fn magnitude(eta: f32, flags: u8) -> Self {
        let r = if flags & FLAG_REACHABLE != 0 {
            1.0
        } else {
            0.0
        };
        let o = if flags == FLAG_ETA_VALID { 1.0 } else { 0.0 };
        Self(Vec4::new(r * eta.abs(), r, o * eta.abs(), o))
    }
}

/// The shape of a blended cell array: sample counts and strides per axis,
/// and the largest index they can address, checked against the array's
/// length once, at load.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Grid<const K: usize> {
    counts: [u32; K],
    strides: [usize; K],
    /// `Σ (count − 1)·stride`, or `None` when that overflows or is not
    /// below the array's length (then every blend takes the checked path).
    last: Option<usize>,
}

impl<const K: usize> Grid<K> {
    const EMPTY: Self = Self {
        counts: [0; K],
        strides: [0; K],
        last: None,
    };

    fn new(counts: [usize; K], strides: [usize; K], len: usize) -> Self {
        let last = (0..K)
            .try_fold(0usize, |sum, k| {
                counts[k]
                    .checked_sub(1)?
                    .checked_mul(strides[k])?
                    .checked_add(sum)
            })
            // Pairs are read along the last axis: its stride must be 1.
            .filter(|&last| last < len && strides[K - 1] == 1);
        Self {
            counts: counts.map(|n| u32::try_from(n).unwrap_or(0)),
            strides,
            last,
        }
    }

    /// Whether every cell a blend at `pos` reads (`Σ i·stride` with `i`
    /// one of each axis's two samples, and that plus one) lies in an array
    /// of `len` cells.
    #[inline]
    fn holds(&self, pos: &[AxisPos; K], len: usize) -> bool {
        let mut inside = matches!(self.last, Some(last) if last < len);
        for (p, &n) in pos.iter().zip(&self.counts).take(K - 1) {
            inside &= p.i0.max(p.i1) < n;
        }
        let e = pos[K - 1];
        inside & (e.i0 < e.i1) & (e.i1 < self.counts[K - 1])
    }
}

/// The η table in memory.
#[derive(Clone, Debug, PartialEq)]
pub struct EtaTable {
    pub(super) params: BuildParams,
    pub(super) axes: [Vec<f32>; AXES],
    pub(super) eta: Vec<f32>,
    pub(super) v_fallback: Vec<f32>,
    pub(super) flags: Vec<u8>,
    cells: Vec<Cell>,
    /// `|η|` on the sampled plane ω = 0 (paper 000 Fig. 4's bound looks η
    /// up "for (D, Δη, 0, v_c, v_dt)"), indexed like the table without the
    /// ω axis; empty when the ω axis has no sample at 0.
    straight: Vec<Cell>,
    strides: [usize; AXES],
    /// The blend grids of `cells` and `straight`, checked against them.
    full: Grid<AXES>,
    plane: Grid<4>,
    /// Constant-time interval search on each axis (built on load).
    pub(super) grid: [Axis; AXES],
}

/// Result of one lookup.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Lookup {
    /// Interpolated η, rad (meaningful when `eta_valid`).
    pub eta: f32,
    /// Whether the target appears reachable at the queried desired speed.
    pub reachable: bool,
    /// Desired speed to use: the query's when reachable, else the stored
    /// fallback ("closest desired speed ensuring reachability", 0 if none).
    pub v_dt: f32,
    /// False when no neighbouring sample had an η (nothing reachable).
    pub eta_valid: bool,
    /// True when some coordinate was clamped to the sampled range.
    pub clamped: bool,
    /// Where the query fell on each axis (the desired-speed axis at
    /// `v_dt`): a follow-up interpolation at the same distance and speeds,
    /// such as the μ bound's, skips the search
    /// ([`EtaTable::straight_abs_eta_at`]).
    at: [AxisPos; AXES],
}

impl EtaTable {
    /// Builds a table from generated data (used by [`crate::funnelling::table::generate`]).
    ///
    /// # Errors
    /// The same validation as [`EtaTable::from_bytes`].
    pub fn from_parts(
        params: BuildParams,
        axes: [Vec<f32>; AXES],
        eta: Vec<f32>,
        v_fallback: Vec<f32>,
        flags: Vec<u8>,
    ) -> Result<Self, TableError> {
        let mut strides = [1usize; AXES];
        for k in (0..AXES - 1).rev() {
            strides[k] = strides[k + 1] * axes[k + 1].len();
        }
        let mut t = Self {
            params,
            axes,
            eta,
            v_fallback,
            flags,
            cells: Vec::new(),
            straight: Vec::new(),
            strides,
            full: Grid::EMPTY,
            plane: Grid::EMPTY,
            grid: core::array::from_fn(|_| Axis::new(&[0.0, 1.0], false)),
        };
        t.validate()?;
        t.cells = (0..t.eta.len())
            .map(|i| Cell::new(t.eta[i], t.v_fallback[i], t.flags[i]))
            .collect();
        if let Some(z) = t.axes[2].iter().position(|&f| f == 0.0) {
            t.straight = (0..t.eta.len())
                .filter(|&i| (i / t.strides[2]) % t.axes[2].len() == z)
                .map(|i| Cell::magnitude(t.eta[i], t.flags[i]))
                .collect();
        }
        t.grid = core::array::from_fn(|k| Axis::new(&t.axes[k], k == 1));
        let n = |k: usize| t.axes[k].len();
        t.full = Grid::new(core::array::from_fn(n), t.strides, t.cells.len());
        t.plane = Grid::new(
            [n(0), n(1), n(3), n(4)],
            [n(1) * n(3) * n(4), n(3) * n(4), n(4), 1],
            t.straight.len(),
        );
        Ok(t)
    }

    /// The parameters the table was built with.
    #[must_use]
    pub fn params(&self) -> &BuildParams {
        &self.params
    }

    /// Sample values of axis `k` (see [`AXIS_NAMES`](crate::funnelling::table::format::AXIS_NAMES)).
    #[must_use]
    pub fn axis(&self, k: usize) -> &[f32] {
        &self.axes[k]
    }

    /// Sampled distances, m (`D_η` is the first).
    #[must_use]
    pub fn distances(&self) -> &[f32] {
        &self.axes[0]
    }

    /// Smallest sampled distance `D_η` (paper 000 Fig. 5).
    #[must_use]
    pub fn d_eta(&self) -> f32 {
        self.axes[0][0]
    }

    /// Number of entries.
    #[must_use]
    pub fn len(&self) -> usize {
        self.eta.len()
    }

    /// Never true for a valid table.
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.eta.is_empty()
    }

    /// Linear index of grid sample `idx`.
    #[must_use]
    pub fn index(&self, idx: [usize; AXES]) -> usize {
        (0..AXES).map(|k| idx[k] * self.strides[k]).sum()
    }

    /// Raw entry at a grid index: (η, fallback speed, flags).
    #[must_use]
    pub fn entry(&self, idx: [usize; AXES]) -> (f32, f32, u8) {
        let i = self.index(idx);
        (self.eta[i], self.v_fallback[i], self.flags[i])
    }

    /// The normalised angular-speed coordinate of a state.
    #[inline]
    #[must_use]
    pub fn omega_fraction(&self, omega: f32, v: f32) -> f32 {
        omega / self.params.vehicle.omega_limit_ahead(v.at_least(0.0))
    }

    #[inline(always)]
    fn positions(
        &self,
        d: f32,
        alpha: f32,
        omega: f32,
        v_c: f32,
        v_d: f32,
        clamped: &mut bool,
    ) -> [AxisPos; AXES] {
        let g = &self.grid;
        // Only the α axis is periodic (`from_parts`).
        let (pd, c0) = g[0].locate_linear(d);
        let mut ca = false;
        let pa = g[1].locate(wrap(alpha), &mut ca);
        let (pw, c2) = g[2].locate_linear(self.omega_fraction(omega, v_c));
        let (pv, c3) = g[3].locate_linear(v_c);
        let (pvd, c4) = g[4].locate_linear(v_d);
        *clamped |= c0 | ca | c2 | c3 | c4;
        [pd, pa, pw, pv, pvd]
    }

    /// Multilinear blend of `cells` at `pos` over `K` axes (5, or 4 for
    /// the ω = 0 plane); the last axis must have stride 1.
    ///
    /// A corner's weight factorises into an *outer* weight (the leading
    /// `K − 2` axes) times an *inner* one (the last two), so the 2^(K−2)
    /// outer corners each scale four neighbouring cells, accumulated per
    /// inner corner, and the four inner weights are applied once at the
    /// end: one 4-wide multiply-add per corner, four independent
    /// accumulators, and cells read in adjacent pairs along the last axis
    /// (one bounds check per pair). An axis that sits on a sample gets
    /// weights 0 and 1: reading the extra corner costs less than a branch.
    ///
    /// Bounds: [`Grid::holds`] checks the position against the sample
    /// counts (ten comparisons) and the cells reads are then unchecked.
    /// Why: the 16 per-pair checks (overflow, then length) would be a
    /// noticeable share of a lookup's instructions (`diagnostics/icount.rs`
    /// counts them under callgrind).
    /// Positions outside the grid (none from [`Axis::locate`]) take the
    /// checked path.
    #[inline]
    fn blend<const K: usize>(cells: &[Cell], pos: &[AxisPos; K], grid: &Grid<K>) -> Vec4 {
        count(if K == AXES {
            Read::Blend
        } else {
            Read::PlaneBlend
        });
        if grid.holds(pos, cells.len()) {
            Self::blend_pairs(pos, &grid.strides, |at| {
                debug_assert!(at + 1 < cells.len());
                // SAFETY: `Grid::holds`: every sample index of `pos` is
                // below its axis's count (the lower one on the last axis
                // below the count minus one), so `at + 1`, a sum of such
                // indices times the strides, is at most `Grid::last`, which
                // is below `cells.len()`.
                #[allow(unsafe_code)]
                unsafe {
                    (cells.get_unchecked(at).0, cells.get_unchecked(at + 1).0)
                }
            })
        } else {
            Self::blend_pairs(pos, &grid.strides, |at| {
                let pair: &[Cell; 2] = cells
                    .get(at..at.saturating_add(2))
                    .and_then(|p| p.try_into().ok())
                    .unwrap_or(&[Cell::ZERO; 2]);
                (pair[0].0, pair[1].0)
            })
        }
    }

    /// [`EtaTable::blend`] over cells given by `pair(at)`: the cells at
    /// offsets `at` and `at + 1`.
    #[inline]
    fn blend_pairs<const K: usize>(
        pos: &[AxisPos; K],
        strides: &[usize; K],
        pair: impl Fn(usize) -> (Vec4, Vec4),
    ) -> Vec4 {
        let side = |k: usize| {
            let (p, s) = (pos[k], strides[k]);
            ([p.i0 as usize * s, p.i1 as usize * s], [1.0 - p.t, p.t])
        };
        let mut outer = [(0usize, 1.0f32); 8];
        let mut n = 1;
        for k in 0..K - 2 {
            let (o, w) = side(k);
            for m in 0..n {
                outer[n + m] = (outer[m].0 + o[1], outer[m].1 * w[1]);
                outer[m] = (outer[m].0 + o[0], outer[m].1 * w[0]);
            }
            n *= 2;
        }
        let (od, wd) = side(K - 2);
        let (oe, we) = side(K - 1);
        let mut acc = [Vec4::ZERO; 4];
        for &(o, w) in &outer[..n] {
            for d in 0..2 {
                let (c0, c1) = pair(o + od[d] + oe[0]);
                acc[2 * d] += c0 * w;
                acc[2 * d + 1] += c1 * w;
            }
        }
        (acc[0] * (wd[0] * we[0]) + acc[1] * (wd[0] * we[1]))
            + (acc[2] * (wd[1] * we[0]) + acc[3] * (wd[1] * we[1]))
    }

    /// η at `pos`: the corners reachable at their desired speed, blended
    /// on their own whenever there are any (a fallback η belongs to another
    /// speed and would bias the result), else the fallback η's.
    #[inline]
    fn eta_at(&self, pos: &[AxisPos; AXES], main: Vec4) -> Option<f32> {
        if main[2] > 1e-6 {
            return Some(trig::atan2(main[1], main[0]));
        }
        count(Read::FallbackBlend);
        let fallback = |i: usize| match (self.eta.get(i), self.flags.get(i)) {
            (Some(&e), Some(&f)) => Cell::fallback(e, f).0,
            _ => Vec4::ZERO,
        };
        let fb = Self::blend_pairs(pos, &self.strides, |at| (fallback(at), fallback(at + 1)));
        (fb[2] > 1e-6).then(|| trig::atan2(fb[1], fb[0]))
    }

    /// η alone at `(D, α, ω_c, v_c, v_d)`: one multilinear interpolation.
    /// `None` when no neighbouring sample has an η.
    #[must_use]
    pub fn eta(&self, d: f32, alpha: f32, omega: f32, v_c: f32, v_d: f32) -> Option<f32> {
        let mut clamped = false;
        let pos = self.positions(d, alpha, omega, v_c, v_d, &mut clamped);
        self.eta_at(&pos, Self::blend(&self.cells, &pos, &self.full))
    }

    /// `|η(D, α, 0, v_c, v_dt)|` at the distance, current speed and desired
    /// speed (`v_dt`) of an earlier lookup, for radial angle `alpha`: the
    /// magnitude of η for a vehicle that is not rotating, which paper 000
    /// Fig. 4 interpolates to bound the modulation μ ("for (D, Δη, 0, v_c,
    /// v_dt)"). With a sample at ω = 0 (the committed table has one) this
    /// blends 16 precomputed magnitudes, reachable samples on their own as
    /// in [`EtaTable::eta`], at the cost of one axis search (the others are
    /// the lookup's); magnitudes are blended directly, which is seam-free at
    /// ±π. `None` when no neighbouring sample has an η.
    #[must_use]
    pub fn straight_abs_eta_at(&self, at: &Lookup, alpha: f32) -> Option<f32> {
        if self.straight.is_empty() {
            let p = |k: usize| {
                let (p, x) = (at.at[k], &self.axes[k]);
                let (a, b) = (x[p.i0 as usize], x[p.i1 as usize]);
                a + p.t * (b - a)
            };
            return self.eta(p(0), alpha, 0.0, p(3), p(4)).map(f32::abs);
        }
        let [d, _, _, v_c, v_d] = at.at;
        self.straight_at([d, self.grid[1].locate(wrap(alpha), &mut false), v_c, v_d])
    }

    fn straight_at(&self, pos: [AxisPos; 4]) -> Option<f32> {
        let b = Self::blend(&self.straight, &pos, &self.plane);
        if b[1] > 1e-6 {
            Some(b[0] / b[1])
        } else if b[3] > 1e-6 {
            Some(b[2] / b[3])
        } else {
            None
        }
    }

    /// η on the sampled distance ring `ring` (an index into
    /// [`EtaTable::distances`]): linear in α between the two neighbouring
    /// α samples, nearest sample on the ω, v_c and v_d axes. This is the
    /// cheaper "simple linear interpolation" paper 001 §4.2.4 uses for the
    /// two arc ends of the relaxed search (2 entries read instead of 32).
    /// `None` when neither neighbour has an η or `ring` is out of range.
    #[must_use]
    pub fn eta_ring_linear(
        &self,
        ring: usize,
        alpha: f32,
        omega: f32,
        v_c: f32,
        v_d: f32,
    ) -> Option<f32> {
        if ring >= self.axes[0].len() {
            return None;
        }
        count(Read::RingLinear);
        let g = &self.grid;
        let pa = g[1].locate(wrap(alpha), &mut false);
        let base = ring * self.strides[0]
            + g[2].nearest(self.omega_fraction(omega, v_c)) * self.strides[2]
            + g[3].nearest(v_c) * self.strides[3]
            + g[4].nearest(v_d) * self.strides[4];
        let ia = base + pa.i0 as usize * self.strides[1];
        let ib = base + pa.i1 as usize * self.strides[1];
        let va = self.flags[ia] & FLAG_ETA_VALID != 0;
        let vb = self.flags[ib] & FLAG_ETA_VALID != 0;
        match (va, vb) {
            (true, true) => {
                let ea = self.eta[ia];
                Some(wrap(ea + pa.t * wrap(self.eta[ib] - ea)))
            }
            (true, false) => Some(self.eta[ia]),
            (false, true) => Some(self.eta[ib]),
            (false, false) => None,
        }
    }

    /// The funnelling lookup of paper 000 Fig. 4, first half: reachability
    /// at the desired speed; if unreachable, the fallback speed `v_dt`, and
    /// η interpolated at `v_dt` (a second interpolation). Reachability is
    /// the weighted vote of the 32 neighbouring samples (≥ ½), a smoothed
    /// version of the paper's "closest element".
    #[must_use]
    pub fn lookup(&self, d: f32, alpha: f32, omega: f32, v_c: f32, v_d: f32) -> Lookup {
        count(Read::Lookup);
        let mut clamped = false;
        let mut pos = self.positions(d, alpha, omega, v_c, v_d, &mut clamped);
        let b = Self::blend(&self.cells, &pos, &self.full);
        // b = [Σw·r·cos η, Σw·r·sin η, Σw·r, Σw·(1−r)·v_fallback].
        let reachable = b[2] >= 0.5;
        let (v_dt, eta) = if reachable {
            (v_d, self.eta_at(&pos, b))
        } else {
            let v_dt = (b[2] * v_d + b[3]).at_most(v_d).at_least(0.0);
            if v_dt > 0.0 {
                pos[4] = self.grid[4].locate(v_dt, &mut false);
                (
                    v_dt,
                    self.eta_at(&pos, Self::blend(&self.cells, &pos, &self.full)),
                )
            } else {
                (v_dt, None)
            }
        };
        Lookup {
            eta: eta.unwrap_or(0.0),
            reachable,
            v_dt,
            eta_valid: eta.is_some(),
            clamped,
            at: pos,
        }
    }

    /// [`EtaTable::lookup`] with paper 000 Fig. 4's reachability read
    /// literally: "if closest Tη element appears unreachable, get the
    /// stored desired forward speed v_dt". The closest element is the
    /// nearest sample on every axis (α periodic); its flag decides, and
    /// when it is unreachable its stored speed is `v_dt` (never above the
    /// queried speed: the nearest desired-speed sample may lie above it),
    /// η then interpolated at `v_dt` as in [`EtaTable::lookup`]. One
    /// interpolation when reachable, two when not.
    #[must_use]
    #[inline(never)]
    pub fn lookup_closest(&self, d: f32, alpha: f32, omega: f32, v_c: f32, v_d: f32) -> Lookup {
        count(Read::Lookup);
        let mut clamped = false;
        let mut pos = self.positions(d, alpha, omega, v_c, v_d, &mut clamped);
        let nearest = |k: usize| {
            let p = pos[k];
            (if p.t < 0.5 { p.i0 } else { p.i1 }) as usize * self.strides[k]
        };
        let i = (0..AXES).map(nearest).sum::<usize>();
        let reachable = self.flags.get(i).is_some_and(|f| f & FLAG_REACHABLE != 0);
        let (v_dt, eta) = if reachable {
            (
                v_d,
                self.eta_at(&pos, Self::blend(&self.cells, &pos, &self.full)),
            )
        } else {
            let v_dt = self
                .v_fallback
                .get(i)
                .map_or(0.0, |&v| v.at_most(v_d).at_least(0.0));
            if v_dt > 0.0 {
                pos[4] = self.grid[4].locate(v_dt, &mut false);
                (
                    v_dt,
                    self.eta_at(&pos, Self::blend(&self.cells, &pos, &self.full)),
                )
            } else {
                (v_dt, None)
            }
        };
        Lookup {
            eta: eta.unwrap_or(0.0),
            reachable,
            v_dt,
            eta_valid: eta.is_some(),
            clamped,
            at: pos,
        }
    }
}

// ------------------------------------------------------------ cost counts

/// One read of the table, as the cost counts tally it ([`counters`]).
///
/// Paper 000 §7 states the update's cost as "in the worst case two
/// interpolations of the η angle" and paper 001 §4.2.4 trades a "quintic
/// linear" interpolation for a "simple linear" one: counting the reads
/// by kind lets a test check those statements exactly, on any machine,
/// where timings only give ratios.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Read {
    /// One funnelling lookup ([`EtaTable::lookup`] or
    /// [`EtaTable::lookup_closest`]); its blends are counted on their own.
    Lookup,
    /// A multilinear blend of the 32 corners around a query.
    Blend,
    /// A blend of the 32 corners' fallback η, when none of them is
    /// reachable at the queried speed ([`EtaTable::eta_at`]).
    FallbackBlend,
    /// A blend of 16 corners on the ω = 0 plane (the literal μ bound,
    /// [`EtaTable::straight_abs_eta_at`]).
    PlaneBlend,
    /// The 2-entry linear read on a sampled ring ([`EtaTable::eta_ring_linear`]).
    RingLinear,
}

/// Tallies `read` with the `counters` feature; without it, nothing (an
/// empty inline function: the default and wasm builds run the same
/// instructions as without the calls).
#[inline(always)]
fn count(read: Read) {
    #[cfg(feature = "counters")]
    counters::add(read);
    #[cfg(not(feature = "counters"))]
    let _ = read;
}

/// Deterministic cost counts of the table's reads, per thread, for tests
/// (the `counters` feature; `tests/fidelity_cost.rs`). Take the counts
/// before and after the updates to be measured: [`counters::take`]
/// returns what was tallied since the last take and starts again at zero.
#[cfg(feature = "counters")]
pub mod counters {
    use super::Read;
    use std::cell::Cell;

    /// Reads tallied on this thread.
    #[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
    pub struct Counts {
        /// Funnelling lookups ([`super::EtaTable::lookup`]).
        pub lookups: u64,
        /// Multilinear blends of 32 corners (η at the query, again at the
        /// fallback speed, or η alone: [`super::EtaTable::eta`]).
        pub blends: u64,
        /// Blends of the 32 corners' fallback η (nothing reachable).
        pub fallback_blends: u64,
        /// Blends of 16 corners on the ω = 0 plane (the literal μ bound).
        pub plane_blends: u64,
        /// 2-entry linear reads on a ring (paper 001 §4.2.4).
        pub ring_reads: u64,
    }

    impl Counts {
        const ZERO: Self = Self {
            lookups: 0,
            blends: 0,
            fallback_blends: 0,
            plane_blends: 0,
            ring_reads: 0,
        };

        /// Multilinear interpolations of η (paper 000 §7's unit: the
        /// 32-corner blends, fallback ones included, and the μ bound's
        /// 16-corner blend).
        #[must_use]
        pub fn interpolations(&self) -> u64 {
            self.blends + self.fallback_blends + self.plane_blends
        }

        /// Table entries read: 32 per blend, 16 per plane blend, 2 per
        /// ring read. Weighs an interpolation by what it reads, as paper
        /// 001 §4.2.4 does when it prefers the linear read.
        #[must_use]
        pub fn entries_read(&self) -> u64 {
            32 * (self.blends + self.fallback_blends) + 16 * self.plane_blends + 2 * self.ring_reads
        }
    }

    thread_local! {
        static COUNTS: Cell<Counts> = const { Cell::new(Counts::ZERO) };
    }

    /// The counts tallied on this thread since the last take; they start
    /// again at zero.
    #[must_use]
    pub fn take() -> Counts {
        COUNTS.with(|c| c.replace(Counts::ZERO))
    }

    pub(super) fn add(read: Read) {
        COUNTS.with(|c| {
            let mut n = c.get();
            match read {
                Read::Lookup => n.lookups += 1,
                Read::Blend => n.blends += 1,
                Read::FallbackBlend => n.fallback_blends += 1,
                Read::PlaneBlend => n.plane_blends += 1,
                Read::RingLinear => n.ring_reads += 1,
            }
            c.set(n);
        });
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn at(i0: u32, i1: u32) -> AxisPos {
        AxisPos { i0, i1, t: 0.5 }
    }

    /// The unchecked blend is taken only for positions inside the grid;
    /// any other position (none comes from `Axis::locate`) reads through
    /// the checked path and counts missing cells as zero.
    #[test]
    fn blend_reads_unchecked_only_inside_the_grid() {
        let cells: Vec<Cell> = (0..2 * 3 * 4)
            .map(|i| Cell(Vec4::splat(i as f32)))
            .collect();
        let grid = Grid::new([2, 3, 4], [12, 4, 1], cells.len());
        assert_eq!(grid.last, Some(23));
        let inside = [at(0, 1), at(2, 0), at(2, 3)];
        assert!(grid.holds(&inside, cells.len()));
        // Cells are their own index: the blend is the weighted mean index.
        let b = EtaTable::blend(&cells, &inside, &grid);
        assert!((b.x - (6.0 + 4.0 + 2.5)).abs() < 1e-4, "{b}");
        for outside in [
            [at(0, 2), at(0, 1), at(0, 1)],
            [at(0, 1), at(3, 0), at(0, 1)],
            [at(0, 1), at(0, 1), at(3, 4)],
            [at(0, 1), at(0, 1), at(1, 0)],
        ] {
            assert!(!grid.holds(&outside, cells.len()), "{outside:?}");
            assert!(EtaTable::blend(&cells, &outside, &grid).is_finite());
        }
        // A grid checked against a longer array is refused for a shorter one.
        assert!(!grid.holds(&inside, cells.len() - 1));
        assert_eq!(Grid::new([2, 3, 4], [12, 4, 2], cells.len()).last, None);
        assert_eq!(Grid::new([2, 3, 5], [12, 4, 1], cells.len()).last, None);
    }
}
