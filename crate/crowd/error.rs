//! Typed errors for crowded path following (paper 003).
//!
//! Why one enum: every user-editable input of the crowd (path points and
//! radius, boid count, seek strategy, JSON presets) is checked up front and
//! rejected with a message a front end can show as is. Nothing in the crowd
//! modules panics on user input.

use core::fmt;

use crate::base::range::RangeError;

/// Why a crowd, a path or a crowd configuration was rejected.
#[derive(Clone, Debug, PartialEq)]
pub enum CrowdError {
    /// A path needs at least two points (three when it is closed).
    TooFewPoints {
        /// Points given.
        got: usize,
        /// Points needed.
        need: usize,
    },
    /// A flat coordinate buffer had an odd number of values.
    OddCoordinateCount(usize),
    /// Path point `index` is NaN or infinite.
    NonFinitePoint(usize),
    /// Path points `index` and `index + 1` (or the closing pair) coincide,
    /// so the segment between them has no direction.
    DegenerateSegment(usize),
    /// A numeric parameter (named as in the JSON config) is NaN, infinite
    /// or outside its range.
    Range(RangeError),
    /// The JSON text could not be parsed into a `CrowdConfig`: the path of
    /// the field at fault and why (`crate::base::field_error`).
    Json(String),
}

impl fmt::Display for CrowdError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::TooFewPoints { got, need } => {
                write!(f, "path needs at least {need} points, got {got}")
            }
            Self::OddCoordinateCount(n) => {
                write!(f, "flat point buffer must hold x,y pairs; got {n} values")
            }
            Self::NonFinitePoint(i) => write!(f, "path point {i} is not a finite number"),
            Self::DegenerateSegment(i) => {
                write!(f, "path segment {i} has zero length (repeated point)")
            }
            Self::Range(e) => e.fmt(f),
            Self::Json(msg) => write!(f, "invalid crowd config JSON: {msg}"),
        }
    }
}

impl std::error::Error for CrowdError {}

impl From<RangeError> for CrowdError {
    fn from(e: RangeError) -> Self {
        Self::Range(e)
    }
}

/// Checks that `value` is finite and within `[lo, hi]`.
pub(crate) fn check_range(
    name: &'static str,
    value: f32,
    lo: f32,
    hi: f32,
) -> Result<(), CrowdError> {
    Ok(crate::base::range::check_range(name, value, lo, hi)?)
}
