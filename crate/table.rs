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

use core::f32::consts::{PI, TAU};
use core::fmt;

use crate::angle::wrap;
use crate::vehicle::{Integrator, VehicleParams};

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
/// vector (so that blending is angle-safe across ±π by construction),
/// split into the part from samples reachable at their desired speed and
/// the part from fallback samples, with the reach indicator and fallback
/// speed. The 32 corners of a lookup then accumulate eight multiply-adds
/// each (vectorisable), and one `atan2` recovers η.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
#[repr(C, align(32))]
struct Cell([f32; 8]);

impl Cell {
    fn new(eta: f32, speed: f32, flags: u8) -> Self {
        let (s, c) = eta.sin_cos();
        let valid = flags & FLAG_ETA_VALID != 0;
        let reach = flags & FLAG_REACHABLE != 0;
        let r = if reach && valid { 1.0 } else { 0.0 };
        let o = if !reach && valid { 1.0 } else { 0.0 };
        Self([
            r * c,
            r * s,
            o * c,
            o * s,
            r,
            o,
            if reach { 0.0 } else { speed },
            0.0,
        ])
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
    strides: [usize; AXES],
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
}

/// Position of a query along one axis: lower index and weight of the upper.
#[derive(Clone, Copy, Debug)]
struct AxisPos {
    i0: usize,
    i1: usize,
    t: f32,
}

#[inline]
fn axis_pos(axis: &[f32], x: f32, clamped: &mut bool) -> AxisPos {
    let n = axis.len();
    if x <= axis[0] {
        *clamped |= x < axis[0];
        return AxisPos {
            i0: 0,
            i1: 1,
            t: 0.0,
        };
    }
    if x >= axis[n - 1] {
        *clamped |= x > axis[n - 1];
        return AxisPos {
            i0: n - 2,
            i1: n - 1,
            t: 1.0,
        };
    }
    let i = axis.partition_point(|&a| a <= x) - 1;
    AxisPos {
        i0: i,
        i1: i + 1,
        t: (x - axis[i]) / (axis[i + 1] - axis[i]),
    }
}

/// Position on the periodic α axis: between the last sample and the first
/// one (+2π) the interval wraps around.
#[inline]
fn periodic_pos(axis: &[f32], a: f32) -> AxisPos {
    let n = axis.len();
    let i = axis.partition_point(|&x| x <= a);
    if i == 0 || i == n {
        let lo = axis[n - 1];
        let hi = axis[0] + TAU;
        let x = if i == 0 { a + TAU } else { a };
        return AxisPos {
            i0: n - 1,
            i1: 0,
            t: ((x - lo) / (hi - lo)).clamp(0.0, 1.0),
        };
    }
    AxisPos {
        i0: i - 1,
        i1: i,
        t: ((a - axis[i - 1]) / (axis[i] - axis[i - 1])).clamp(0.0, 1.0),
    }
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
            strides,
        };
        t.validate()?;
        t.cells = (0..t.eta.len())
            .map(|i| Cell::new(t.eta[i], t.v_fallback[i], t.flags[i]))
            .collect();
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
        let pa = periodic_pos(&self.axes[1], wrap(alpha));
        [
            axis_pos(&self.axes[0], d, clamped),
            pa,
            axis_pos(&self.axes[2], self.omega_fraction(omega, v_c), clamped),
            axis_pos(&self.axes[3], v_c, clamped),
            axis_pos(&self.axes[4], v_d, clamped),
        ]
    }

    /// Interpolates η, the reachability vote and the fallback speed at the
    /// 32 corners around `pos` (fewer when the query sits on a sample).
    /// η is blended as a unit vector, so samples on both sides of ±π never
    /// average to 0. Corners reachable at their desired speed are blended
    /// on their own whenever there are any: a fallback η belongs to another
    /// speed and would bias the result.
    #[inline]
    fn blend(&self, pos: &[AxisPos; AXES]) -> Blend {
        let mut off = [[0usize; 2]; AXES];
        let mut wt = [[0f32; 2]; AXES];
        let mut n = [2usize; AXES];
        for k in 0..AXES {
            let p = pos[k];
            off[k] = [p.i0 * self.strides[k], p.i1 * self.strides[k]];
            wt[k] = [1.0 - p.t, p.t];
            if p.t == 0.0 {
                n[k] = 1;
            } else if p.t == 1.0 {
                off[k][0] = off[k][1];
                wt[k][0] = 1.0;
                n[k] = 1;
            }
        }
        let mut acc = [0f32; 8];
        for a in 0..n[0] {
            let (ia, wa) = (off[0][a], wt[0][a]);
            for c in 0..n[1] {
                let (ic, wc) = (ia + off[1][c], wa * wt[1][c]);
                for d in 0..n[2] {
                    let (id, wd) = (ic + off[2][d], wc * wt[2][d]);
                    for e in 0..n[3] {
                        let (ie, we) = (id + off[3][e], wd * wt[3][e]);
                        for f in 0..n[4] {
                            let w = we * wt[4][f];
                            let cell = &self.cells[ie + off[4][f]].0;
                            for (x, y) in acc.iter_mut().zip(cell) {
                                *x += w * y;
                            }
                        }
                    }
                }
            }
        }
        Blend(acc)
    }

    /// η alone at `(D, α, ω_c, v_c, v_d)`: one multilinear interpolation.
    /// `None` when no neighbouring sample has an η.
    #[must_use]
    pub fn eta(&self, d: f32, alpha: f32, omega: f32, v_c: f32, v_d: f32) -> Option<f32> {
        let mut clamped = false;
        let pos = self.positions(d, alpha, omega, v_c, v_d, &mut clamped);
        self.blend(&pos).eta()
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
        let pa = periodic_pos(&self.axes[1], wrap(alpha));
        let near = |k: usize, x: f32| {
            let mut c = false;
            let p = axis_pos(&self.axes[k], x, &mut c);
            if p.t < 0.5 {
                p.i0
            } else {
                p.i1
            }
        };
        let base = ring * self.strides[0]
            + near(2, self.omega_fraction(omega, v_c)) * self.strides[2]
            + near(3, v_c) * self.strides[3]
            + near(4, v_d) * self.strides[4];
        let ia = base + pa.i0 * self.strides[1];
        let ib = base + pa.i1 * self.strides[1];
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
        let b = self.blend(&pos);
        let reachable = b.reach() >= 0.5;
        let mut v_dt = v_d;
        let mut eta = b.eta();
        if !reachable {
            v_dt = b.speed(v_d).min(v_d).max(0.0);
            eta = None;
            if v_dt > 0.0 {
                let mut c2 = false;
                pos[4] = axis_pos(&self.axes[4], v_dt, &mut c2);
                eta = self.blend(&pos).eta();
            }
        }
        Lookup {
            eta: eta.unwrap_or(0.0),
            reachable,
            v_dt,
            eta_valid: eta.is_some(),
            clamped,
        }
    }
}

/// Accumulators of one blend, in [`Cell`] order.
#[derive(Clone, Copy, Debug, Default)]
struct Blend([f32; 8]);

impl Blend {
    /// Weight of corners reachable at their desired speed.
    #[inline]
    fn reach(&self) -> f32 {
        self.0[4]
    }

    /// Blended speed: the query's `v_d` where reachable, else the fallback.
    #[inline]
    fn speed(&self, v_d: f32) -> f32 {
        self.0[4] * v_d + self.0[6]
    }

    #[inline]
    fn eta(&self) -> Option<f32> {
        let a = &self.0;
        if a[4] > 1e-6 {
            Some(a[1].atan2(a[0]))
        } else if a[5] > 1e-6 {
            Some(a[3].atan2(a[2]))
        } else {
            None
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
