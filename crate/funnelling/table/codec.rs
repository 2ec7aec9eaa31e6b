//! The η table to and from bytes (paper 000 §3; docs/DESIGN.md §8): the CRC-32,
//! the validation of every field of a loaded table, and the little-endian
//! reader and writer of the layout in [`format`](super::format) and
//! `tables/README.md`.
//!
//! Why the loader refuses whole: a truncated, corrupt or mismatched table
//! would steer wrongly without a sign; every check names what is off.

use core::f32::consts::PI;

use super::format::{
    header_len, BuildParams, TableError, AXES, AXIS_NAMES, FLAG_ETA_VALID, FLAG_REACHABLE,
    FORMAT_VERSION, FORMAT_VERSION_CAR, HEADER_LEN, MAGIC, MAX_ENTRIES,
};
use super::lookup::EtaTable;
use crate::base::vehicle::{Integrator, VehicleParams};

/// CRC-32 (IEEE 802.3, reflected, polynomial 0xEDB88320), through
/// `crc32fast`: the page checks the 3.2 MB table before its first frame,
/// and `crc32fast`'s slice-by-16 fallback (SIMD-free, so the same
/// everywhere) takes a fraction of a byte-at-a-time loop's time, natively
/// and in wasm. `crc32_bytewise` is the reference the tests compare with.
#[must_use]
pub fn crc32(bytes: &[u8]) -> u32 {
    crc32fast::hash(bytes)
}

/// The textbook byte-at-a-time CRC-32, kept as the reference of [`crc32`].
#[must_use]
pub fn crc32_bytewise(bytes: &[u8]) -> u32 {
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

impl EtaTable {
    pub(super) fn validate(&self) -> Result<(), TableError> {
        let v = &self.params.vehicle;
        for (i, x) in self.params.to_array().iter().enumerate() {
            if !x.is_finite() {
                return Err(TableError::NonFinite {
                    what: "build parameter",
                    index: i,
                });
            }
        }
        if !v.r_min.is_finite() {
            return Err(TableError::NonFinite {
                what: "build parameter",
                index: 11,
            });
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
        b.extend_from_slice(&self.params.version().to_le_bytes());
        b.extend_from_slice(&self.params.vehicle.integrator.code().to_le_bytes());
        for x in self.params.to_array() {
            b.extend_from_slice(&x.to_le_bytes());
        }
        if self.params.vehicle.car_like() {
            b.extend_from_slice(&self.params.vehicle.r_min.to_le_bytes());
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
        header_len(self.params.version())
            + 4 * self.axes.iter().map(Vec::len).sum::<usize>()
            + 9 * n
            + 4
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
        if version != FORMAT_VERSION && version != FORMAT_VERSION_CAR {
            return Err(TableError::UnknownVersion(version));
        }
        let icode = r.u32()?;
        let mut pf = [0f32; 11];
        for x in &mut pf {
            *x = r.f32()?;
        }
        let r_min = if version == FORMAT_VERSION_CAR {
            r.f32()?
        } else {
            0.0
        };
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
        let expected = header_len(version) + 4 * counts.iter().sum::<usize>() + 9 * n + 4;
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
            r_min,
            ..VehicleParams::default()
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
            ("minTurnRadius", t.r_min, p.r_min),
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
}

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

#[cfg(test)]
mod tests {
    use super::{crc32, crc32_bytewise as bytewise};

    #[test]
    fn crc32_is_the_standard_one_at_every_length() {
        assert_eq!(crc32(b"123456789"), 0xCBF4_3926);
        assert_eq!(crc32(b""), 0);
        let mut r = crate::base::rng::Rng::new(3);
        let data: Vec<u8> = (0..3000).map(|_| (r.next_u32() & 0xFF) as u8).collect();
        for n in (0..64).chain([255, 1000, 2999, 3000]) {
            assert_eq!(crc32(&data[..n]), bytewise(&data[..n]), "length {n}");
        }
    }
}
