//! The η table `Tη` (paper 000 §3, paper 001 §3 and Fig. 3; DESIGN §3):
//! its binary file format, a loader that validates everything, and the
//! constant-cost multilinear ("quintic linear") lookup.
//!
//! The table samples the seek controller's final radial-tangential angle η
//! over five axes: target distance `D`, radial angle `α`, current angular
//! speed, current forward speed `v_c` and desired speed `v_d`. See
//! `tables/README.md` for the byte layout and [`crate::table_gen`] for the
//! generator and the choice of axes.
//!
//! The angular-speed axis is stored *normalised*: `s = ω_c / min(ω_max,
//! A/v_c)` in `[-1, 1]`, so that every sampled state is admissible (a state
//! with `|v·ω| > A` cannot occur and would waste samples).

use core::f32::consts::PI;
use core::fmt;

use crate::angle::wrap;
use crate::grid::{Axis, AxisPos};
use crate::trig;
use crate::vehicle::{Integrator, VehicleParams};
use glam::Vec4;

/// File magic, the first 8 bytes.
pub const MAGIC: [u8; 8] = *b"STEERETA";
/// The format version this build reads and writes.
pub const FORMAT_VERSION: u32 = 1;
/// Number of axes.
pub const AXES: usize = 5;
/// Upper bound on entries accepted from a file (guards allocation).
pub const MAX_ENTRIES: usize = 4_000_000;

/// Entry flag: reachable at the sampled desired speed.
pub const FLAG_REACHABLE: u8 = 1;
/// Entry flag: the stored η is valid (reachable at `v_d` or at the
/// fallback speed; paper 001 Fig. 3c stores the fallback's η).
pub const FLAG_ETA_VALID: u8 = 2;

/// Names of the five axes, in storage order (slowest varying first).
pub const AXIS_NAMES: [&str; AXES] = [
    "distance",
    "alpha",
    "omegaFraction",
    "speed",
    "desiredSpeed",
];

/// Everything the table was generated with. A table is only valid for a
/// controller with exactly these parameters.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BuildParams {
    /// Vehicle and seek-controller parameters.
    pub vehicle: VehicleParams,
    /// Arrival radius of the reach simulation, m.
    pub reach_radius: f32,
    /// Net rotation (turns) declaring an orbit.
    pub orbit_turns: f32,
    /// Simulated-time cap, s.
    pub max_time: f32,
}

impl BuildParams {
    /// The 11 f32 parameters in header order: dt, v_max, accel_max,
    /// omega_max, omega_accel_max, normal_accel_max, kp, kd, reach_radius,
    /// orbit_turns, max_time.
    #[must_use]
    pub fn to_array(&self) -> [f32; 11] {
        let v = &self.vehicle;
        [
            v.dt,
            v.v_max,
            v.accel_max,
            v.omega_max,
            v.omega_accel_max,
            v.normal_accel_max,
            v.kp,
            v.kd,
            self.reach_radius,
            self.orbit_turns,
            self.max_time,
        ]
    }

    /// Inverse of [`BuildParams::to_array`].
    #[must_use]
    pub fn from_array(a: [f32; 11], integrator: Integrator) -> Self {
        let vehicle = VehicleParams {
            dt: a[0],
            v_max: a[1],
            accel_max: a[2],
            omega_max: a[3],
            omega_accel_max: a[4],
            normal_accel_max: a[5],
            kp: a[6],
            kd: a[7],
            integrator,
        };
        Self {
            vehicle,
            reach_radius: a[8],
            orbit_turns: a[9],
            max_time: a[10],
        }
    }
}

/// Why a table file was refused. Every variant has a readable message.
#[derive(Clone, Debug, PartialEq)]
pub enum TableError {
    /// The file ends before the layout its header announces.
    Truncated {
        /// Bytes needed.
        expected: usize,
        /// Bytes present.
        actual: usize,
    },
    /// More bytes than the header announces.
    TrailingBytes {
        /// Bytes expected.
        expected: usize,
        /// Bytes present.
        actual: usize,
    },
    /// Not an η table.
    BadMagic,
    /// A format version this build does not read.
    UnknownVersion(u32),
    /// Stored and computed CRC-32 differ: the file is corrupt.
    ChecksumMismatch {
        /// Stored checksum.
        stored: u32,
        /// Checksum of the bytes read.
        computed: u32,
    },
    /// A NaN or infinite value.
    NonFinite {
        /// Where.
        what: &'static str,
        /// Index within that section.
        index: usize,
    },
    /// An axis is not strictly increasing.
    NonMonotonicAxis(&'static str),
    /// Any other structural inconsistency (bad counts, bad α axis, flags).
    Invalid(String),
    /// Built for different vehicle/controller parameters.
    ParamsMismatch {
        /// Parameter name.
        field: &'static str,
        /// Value in the table.
        table: f32,
        /// Value of the running controller.
        controller: f32,
    },
}

impl fmt::Display for TableError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Truncated { expected, actual } => {
                write!(f, "η table is truncated: {actual} bytes, expected {expected}")
            }
            Self::TrailingBytes { expected, actual } => {
                write!(f, "η table has trailing bytes: {actual} bytes, expected {expected}")
            }
            Self::BadMagic => write!(f, "not an η table (bad magic; expected \"STEERETA\")"),
            Self::UnknownVersion(v) => {
                write!(f, "η table format version {v} is not supported (this build reads {FORMAT_VERSION})")
            }
            Self::ChecksumMismatch { stored, computed } => write!(
                f,
                "η table is corrupt: checksum {stored:#010x} stored, {computed:#010x} computed"
            ),
            Self::NonFinite { what, index } => write!(f, "η table has a non-finite {what} at index {index}"),
            Self::NonMonotonicAxis(a) => write!(f, "η table axis `{a}` is not strictly increasing"),
            Self::Invalid(m) => write!(f, "η table is invalid: {m}"),
            Self::ParamsMismatch { field, table, controller } => write!(
                f,
                "η table was built for {field} = {table}, but the controller uses {controller}: regenerate the table"
            ),
        }
    }
}

impl std::error::Error for TableError {}

/// CRC-32 (IEEE 802.3, reflected, polynomial 0xEDB88320).
#[must_use]
pub fn crc32(bytes: &[u8]) -> u32 {
    const fn make() -> [u32; 256] {
        let mut t = [0u32; 256];
        let mut i = 0;
        while i < 256 {
            let mut c = i as u32;
            let mut k = 0;
            while k < 8 {
                c = if c & 1 != 0 {
                    0xEDB8_8320 ^ (c >> 1)
                } else {
                    c >> 1
                };
                k += 1;
            }
            t[i] = c;
            i += 1;
        }
        t
    }
    const TABLE: [u32; 256] = make();
    let mut c = !0u32;
    for &b in bytes {
        c = TABLE[((c ^ u32::from(b)) & 0xFF) as usize] ^ (c >> 8);
    }
    !c
}

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

/// The η table in memory.
#[derive(Clone, Debug, PartialEq)]
pub struct EtaTable {
    params: BuildParams,
    axes: [Vec<f32>; AXES],
    eta: Vec<f32>,
    v_fallback: Vec<f32>,
    flags: Vec<u8>,
    cells: Vec<Cell>,
    /// `|η|` on the sampled plane ω = 0 (paper 000 Fig. 4's bound looks η
    /// up "for (D, Δη, 0, v_c, v_dt)"), indexed like the table without the
    /// ω axis; empty when the ω axis has no sample at 0.
    straight: Vec<Cell>,
    strides: [usize; AXES],
    /// Constant-time interval search on each axis (built on load).
    grid: [Axis; AXES],
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
    /// Builds a table from generated data (used by [`crate::table_gen`]).
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
        Ok(t)
    }

    fn validate(&self) -> Result<(), TableError> {
        let v = &self.params.vehicle;
        for (i, x) in self.params.to_array().iter().enumerate() {
            if !x.is_finite() {
                return Err(TableError::NonFinite {
                    what: "build parameter",
                    index: i,
                });
            }
        }
        v.validate()
            .map_err(|e| TableError::Invalid(format!("build parameters: {e}")))?;
        let mut n = 1usize;
        for (k, axis) in self.axes.iter().enumerate() {
            let min_len = if k == 1 { 3 } else { 2 };
            if axis.len() < min_len || axis.len() > 4096 {
                return Err(TableError::Invalid(format!(
                    "axis `{}` has {} samples (needs {min_len}..=4096)",
                    AXIS_NAMES[k],
                    axis.len()
                )));
            }
            for (i, x) in axis.iter().enumerate() {
                if !x.is_finite() {
                    return Err(TableError::NonFinite {
                        what: "axis value",
                        index: i,
                    });
                }
            }
            if axis.windows(2).any(|w| w[1] <= w[0]) {
                return Err(TableError::NonMonotonicAxis(AXIS_NAMES[k]));
            }
            // Interpolation divides by the sample spacing: a spacing that is
            // a rounding error of the span would make weights meaningless.
            let span = axis[axis.len() - 1] - axis[0];
            if axis.windows(2).any(|w| w[1] - w[0] < 1e-6 * span) {
                return Err(TableError::Invalid(format!(
                    "axis `{}` has samples closer than 1e-6 of its span",
                    AXIS_NAMES[k]
                )));
            }
            n = n.saturating_mul(axis.len());
        }
        if n > MAX_ENTRIES {
            return Err(TableError::Invalid(format!(
                "{n} entries exceed the limit {MAX_ENTRIES}"
            )));
        }
        // α is periodic: samples strictly increasing within [−π, π).
        let al = &self.axes[1];
        if al[0] < -PI - 1e-6 || al[al.len() - 1] >= PI {
            return Err(TableError::Invalid(
                "alpha samples must lie in [-π, π)".into(),
            ));
        }
        if self.axes[0][0] <= 0.0 {
            return Err(TableError::Invalid("distances must be positive".into()));
        }
        let s = &self.axes[2];
        if s[0] < -1.0 - 1e-6 || s[s.len() - 1] > 1.0 + 1e-6 {
            return Err(TableError::Invalid(
                "omega fractions must lie in [-1, 1]".into(),
            ));
        }
        if self.axes[3][0] < 0.0 || self.axes[4][0] <= 0.0 {
            return Err(TableError::Invalid(
                "speeds must be non-negative, desired speeds positive".into(),
            ));
        }
        if self.eta.len() != n || self.v_fallback.len() != n || self.flags.len() != n {
            return Err(TableError::Invalid(format!(
                "entry arrays do not hold {n} entries"
            )));
        }
        for (i, e) in self.eta.iter().enumerate() {
            if !e.is_finite() {
                return Err(TableError::NonFinite {
                    what: "η",
                    index: i,
                });
            }
            if e.abs() > PI + 1e-5 {
                return Err(TableError::Invalid(format!(
                    "η at entry {i} is {e}, outside [-π, π]"
                )));
            }
        }
        for (i, s) in self.v_fallback.iter().enumerate() {
            if !s.is_finite() {
                return Err(TableError::NonFinite {
                    what: "fallback speed",
                    index: i,
                });
            }
            if *s < 0.0 || *s > self.params.vehicle.v_max + 1e-5 {
                return Err(TableError::Invalid(format!(
                    "fallback speed at entry {i} is {s}"
                )));
            }
        }
        if let Some(i) = self
            .flags
            .iter()
            .position(|f| *f > (FLAG_REACHABLE | FLAG_ETA_VALID))
        {
            return Err(TableError::Invalid(format!(
                "unknown flags {:#x} at entry {i}",
                self.flags[i]
            )));
        }
        if let Some(i) = self.flags.iter().position(|f| *f == FLAG_REACHABLE) {
            return Err(TableError::Invalid(format!(
                "entry {i} is reachable without a valid η"
            )));
        }
        Ok(())
    }

    /// Serialises to the versioned little-endian format of `tables/README.md`.
    #[must_use]
    pub fn to_bytes(&self) -> Vec<u8> {
        let mut b = Vec::with_capacity(self.encoded_len());
        b.extend_from_slice(&MAGIC);
        b.extend_from_slice(&FORMAT_VERSION.to_le_bytes());
        b.extend_from_slice(&self.params.vehicle.integrator.code().to_le_bytes());
        for x in self.params.to_array() {
            b.extend_from_slice(&x.to_le_bytes());
        }
        for a in &self.axes {
            b.extend_from_slice(&(a.len() as u32).to_le_bytes());
        }
        for a in &self.axes {
            for x in a {
                b.extend_from_slice(&x.to_le_bytes());
            }
        }
        for x in &self.eta {
            b.extend_from_slice(&x.to_le_bytes());
        }
        for x in &self.v_fallback {
            b.extend_from_slice(&x.to_le_bytes());
        }
        b.extend_from_slice(&self.flags);
        let c = crc32(&b);
        b.extend_from_slice(&c.to_le_bytes());
        b
    }

    fn encoded_len(&self) -> usize {
        let n = self.eta.len();
        HEADER_LEN + 4 * self.axes.iter().map(Vec::len).sum::<usize>() + 9 * n + 4
    }

    /// Parses and validates a table file. Never panics, whatever the bytes.
    ///
    /// # Errors
    /// A [`TableError`] saying what is wrong: truncation, bad magic,
    /// unknown version, checksum mismatch, non-finite values, non-monotonic
    /// axes or any other inconsistency.
    pub fn from_bytes(bytes: &[u8]) -> Result<Self, TableError> {
        if bytes.len() < MAGIC.len() {
            return Err(if MAGIC.starts_with(bytes) {
                TableError::Truncated {
                    expected: HEADER_LEN,
                    actual: bytes.len(),
                }
            } else {
                TableError::BadMagic
            });
        }
        if bytes[..8] != MAGIC {
            return Err(TableError::BadMagic);
        }
        let mut r = Reader { b: bytes, at: 8 };
        let version = r.u32()?;
        if version != FORMAT_VERSION {
            return Err(TableError::UnknownVersion(version));
        }
        let icode = r.u32()?;
        let mut pf = [0f32; 11];
        for x in &mut pf {
            *x = r.f32()?;
        }
        let mut counts = [0usize; AXES];
        for c in &mut counts {
            *c = r.u32()? as usize;
        }
        let mut n = 1usize;
        for c in counts {
            n = n.saturating_mul(c);
        }
        if n > MAX_ENTRIES || counts.iter().any(|&c| c > 4096) {
            return Err(TableError::Invalid(format!(
                "axis sizes {counts:?} are implausible"
            )));
        }
        let expected = HEADER_LEN + 4 * counts.iter().sum::<usize>() + 9 * n + 4;
        if bytes.len() < expected {
            return Err(TableError::Truncated {
                expected,
                actual: bytes.len(),
            });
        }
        if bytes.len() > expected {
            return Err(TableError::TrailingBytes {
                expected,
                actual: bytes.len(),
            });
        }
        let stored = u32::from_le_bytes([
            bytes[expected - 4],
            bytes[expected - 3],
            bytes[expected - 2],
            bytes[expected - 1],
        ]);
        let computed = crc32(&bytes[..expected - 4]);
        if stored != computed {
            return Err(TableError::ChecksumMismatch { stored, computed });
        }
        let integrator = Integrator::from_code(icode)
            .ok_or_else(|| TableError::Invalid(format!("unknown integrator code {icode}")))?;
        let axes: [Vec<f32>; AXES] = core::array::from_fn(|k| r.f32s(counts[k]));
        let eta = r.f32s(n);
        let v_fallback = r.f32s(n);
        let flags = bytes[r.at..r.at + n].to_vec();
        let vehicle = VehicleParams {
            dt: pf[0],
            v_max: pf[1],
            accel_max: pf[2],
            omega_max: pf[3],
            omega_accel_max: pf[4],
            normal_accel_max: pf[5],
            kp: pf[6],
            kd: pf[7],
            integrator,
        };
        let params = BuildParams {
            vehicle,
            reach_radius: pf[8],
            orbit_turns: pf[9],
            max_time: pf[10],
        };
        Self::from_parts(params, axes, eta, v_fallback, flags)
    }

    /// Checks that the table was built for exactly the running controller's
    /// parameters (bit-for-bit: the table is only exact for them).
    ///
    /// # Errors
    /// [`TableError::ParamsMismatch`] naming the first differing parameter.
    pub fn check_params(&self, p: &VehicleParams) -> Result<(), TableError> {
        let t = &self.params.vehicle;
        if t.integrator != p.integrator {
            return Err(TableError::ParamsMismatch {
                field: "integrator",
                table: t.integrator.code() as f32,
                controller: p.integrator.code() as f32,
            });
        }
        let pairs = [
            ("dt", t.dt, p.dt),
            ("vMax", t.v_max, p.v_max),
            ("accelMax", t.accel_max, p.accel_max),
            ("omegaMax", t.omega_max, p.omega_max),
            ("omegaAccelMax", t.omega_accel_max, p.omega_accel_max),
            ("normalAccelMax", t.normal_accel_max, p.normal_accel_max),
            ("kp", t.kp, p.kp),
            ("kd", t.kd, p.kd),
        ];
        for (field, table, controller) in pairs {
            if table.to_bits() != controller.to_bits() {
                return Err(TableError::ParamsMismatch {
                    field,
                    table,
                    controller,
                });
            }
        }
        Ok(())
    }

    /// The parameters the table was built with.
    #[must_use]
    pub fn params(&self) -> &BuildParams {
        &self.params
    }

    /// Sample values of axis `k` (see [`AXIS_NAMES`]).
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
        omega / self.params.vehicle.omega_limit(v.max(0.0))
    }

    #[inline]
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
        [
            g[0].locate(d, clamped),
            g[1].locate(wrap(alpha), clamped),
            g[2].locate(self.omega_fraction(omega, v_c), clamped),
            g[3].locate(v_c, clamped),
            g[4].locate(v_d, clamped),
        ]
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
    #[inline]
    fn blend<const K: usize>(cells: &[Cell], pos: &[AxisPos; K], strides: &[usize; K]) -> Vec4 {
        Self::blend_pairs(pos, strides, |at| {
            let pair: &[Cell; 2] = cells[at..at + 2].try_into().unwrap_or(&[Cell::ZERO; 2]);
            (pair[0].0, pair[1].0)
        })
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
        self.eta_at(&pos, Self::blend(&self.cells, &pos, &self.strides))
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
        let (n3, n4) = (self.axes[3].len(), self.axes[4].len());
        let strides = [self.axes[1].len() * n3 * n4, n3 * n4, n4, 1];
        let b = Self::blend(&self.straight, &pos, &strides);
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
        let mut clamped = false;
        let mut pos = self.positions(d, alpha, omega, v_c, v_d, &mut clamped);
        let b = Self::blend(&self.cells, &pos, &self.strides);
        // b = [Σw·r·cos η, Σw·r·sin η, Σw·r, Σw·(1−r)·v_fallback].
        let reachable = b[2] >= 0.5;
        let (v_dt, eta) = if reachable {
            (v_d, self.eta_at(&pos, b))
        } else {
            let v_dt = (b[2] * v_d + b[3]).min(v_d).max(0.0);
            if v_dt > 0.0 {
                pos[4] = self.grid[4].locate(v_dt, &mut false);
                (
                    v_dt,
                    self.eta_at(&pos, Self::blend(&self.cells, &pos, &self.strides)),
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

/// Bytes before the axis values: magic, version, integrator, 11 f32
/// parameters, 5 axis counts.
pub const HEADER_LEN: usize = 8 + 4 + 4 + 11 * 4 + AXES * 4;

struct Reader<'a> {
    b: &'a [u8],
    at: usize,
}

impl Reader<'_> {
    fn take4(&mut self) -> Result<[u8; 4], TableError> {
        let s = self
            .b
            .get(self.at..self.at + 4)
            .ok_or(TableError::Truncated {
                expected: HEADER_LEN,
                actual: self.b.len(),
            })?;
        self.at += 4;
        Ok([s[0], s[1], s[2], s[3]])
    }
    fn u32(&mut self) -> Result<u32, TableError> {
        self.take4().map(u32::from_le_bytes)
    }
    fn f32(&mut self) -> Result<f32, TableError> {
        self.take4().map(f32::from_le_bytes)
    }
    /// Only called after the total length was checked.
    fn f32s(&mut self, n: usize) -> Vec<f32> {
        let s = &self.b[self.at..self.at + 4 * n];
        self.at += 4 * n;
        s.chunks_exact(4)
            .map(|c| f32::from_le_bytes([c[0], c[1], c[2], c[3]]))
            .collect()
    }
}
