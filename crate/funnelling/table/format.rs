//! The η table's file format (paper 000 §3; docs/DESIGN.md §8): the header and its
//! [`BuildParams`], the typed [`TableError`]s and the layout constants.
//! The bytes themselves (CRC-32, validation of every field, to and from
//! bytes) are in [`codec`](super::codec). `tables/README.md` gives the byte
//! layout.
//!
//! Why a format of our own: the table is 3 MB of f32/u8 arrays that the
//! browser fetches and the loader must refuse whole when anything is off
//! (truncated, corrupt, built for other vehicle limits), with a message
//! that names what; a flat little-endian layout with a checksum does that
//! in a hundred lines and reads the same natively and in wasm.

use core::fmt;

use crate::base::vehicle::{Integrator, VehicleParams};

/// File magic, the first 8 bytes.
pub const MAGIC: [u8; 8] = *b"STEERETA";
/// The format version this build reads and writes for a unicycle.
pub const FORMAT_VERSION: u32 = 1;
/// The format version of a car-like vehicle's table: version 1 with one
/// more f32 after the 11 parameters, the minimum turning radius. A
/// unicycle's table stays version 1, byte for byte.
pub const FORMAT_VERSION_CAR: u32 = 2;
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
            r_min: 0.0,
            v_reverse: 0.0,
            gear_cost: 0.0,
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
    /// No table can be built for these vehicle limits (the generator's
    /// ranges and ratios, [`check_vehicle`](super::spec::check_vehicle)).
    Vehicle(String),
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
            Self::Vehicle(m) => write!(f, "no η table can be built for this vehicle: {m}"),
        }
    }
}

impl std::error::Error for TableError {}

/// Bytes before the axis values: magic, version, integrator, 11 f32
/// parameters, 5 axis counts.
pub const HEADER_LEN: usize = 8 + 4 + 4 + 11 * 4 + AXES * 4;

/// Bytes before the axis values in format `version` ([`HEADER_LEN`], plus
/// the minimum turning radius in [`FORMAT_VERSION_CAR`]).
#[must_use]
pub fn header_len(version: u32) -> usize {
    if version == FORMAT_VERSION_CAR {
        HEADER_LEN + 4
    } else {
        HEADER_LEN
    }
}

impl BuildParams {
    /// The format version a table with these parameters is written in.
    #[must_use]
    pub fn version(&self) -> u32 {
        if self.vehicle.car_like() {
            FORMAT_VERSION_CAR
        } else {
            FORMAT_VERSION
        }
    }
}
