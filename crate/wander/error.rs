//! Typed configuration errors for the random steering toolkit.
//!
//! Why typed: the gallery builds wanderers from user-edited JSON, so every
//! bad input (NaN, negative clamp, a Markov row that does not sum to one, an
//! empty set...) must come back as a value the UI can show, never a panic.

use core::fmt;

use crate::base::range::{check_range, RangeError};

/// Everything that can be wrong with a wander configuration.
#[derive(Clone, Debug, PartialEq)]
pub enum WanderError {
    /// The JSON did not parse or did not match the schema (unknown field,
    /// unknown `kind`, wrong type...). Carries serde's message.
    Json(String),
    /// A number was NaN, infinite or outside its closed interval.
    Range(RangeError),
    /// A number that must be strictly positive was zero or negative.
    NotPositive {
        /// Which parameter.
        what: &'static str,
        /// The offending value.
        value: f32,
    },
    /// A list that must not be empty was empty.
    Empty {
        /// Which list.
        what: &'static str,
    },
    /// A list that must be strictly increasing was not.
    NotIncreasing {
        /// Which list.
        what: &'static str,
    },
    /// Two lists (or a table and its ranges) disagree in length.
    ShapeMismatch {
        /// Which list.
        what: &'static str,
        /// Length it should have.
        expected: usize,
        /// Length it has.
        found: usize,
    },
    /// A row of a transition table does not sum to 1 (tolerance 1e-3).
    RowSum {
        /// Row index.
        row: usize,
        /// Its sum.
        sum: f32,
    },
    /// A generated structure would be too large (points, grid cells...).
    TooLarge {
        /// What would be too large.
        what: &'static str,
        /// Requested size.
        value: u64,
        /// Largest allowed size.
        max: u64,
    },
    /// Path following commands an angular velocity: it needs `mode: velocity`.
    PathNeedsVelocityMode,
    /// This source cannot be a part of a mix (paths, nested mixes).
    NotMixable {
        /// Which source kind.
        what: &'static str,
    },
}

impl fmt::Display for WanderError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Json(m) => write!(f, "invalid wander config: {m}"),
            Self::Range(e) => e.fmt(f),
            Self::NotPositive { what, value } => write!(f, "{what} = {value} must be > 0"),
            Self::Empty { what } => write!(f, "{what} must not be empty"),
            Self::NotIncreasing { what } => write!(f, "{what} must be strictly increasing"),
            Self::ShapeMismatch {
                what,
                expected,
                found,
            } => {
                write!(f, "{what} must have {expected} entries (got {found})")
            }
            Self::RowSum { row, sum } => {
                write!(
                    f,
                    "transition table row {row} must sum to 1 (sums to {sum})"
                )
            }
            Self::TooLarge { what, value, max } => {
                write!(f, "{what} too large: {value} (max {max})")
            }
            Self::PathNeedsVelocityMode => {
                write!(f, "path following needs control.mode = \"velocity\"")
            }
            Self::NotMixable { what } => write!(f, "a {what} cannot be part of a mix"),
        }
    }
}

impl std::error::Error for WanderError {}

impl From<RangeError> for WanderError {
    fn from(e: RangeError) -> Self {
        Self::Range(e)
    }
}

/// Largest world coordinate or length accepted anywhere (keeps every
/// derived distance finite in f32).
pub const WORLD_LIMIT: f32 = 1e6;

/// Checks that `v` is finite.
pub(crate) fn finite(what: &'static str, v: f32) -> Result<(), WanderError> {
    Ok(check_range(what, v, f32::NEG_INFINITY, f32::INFINITY)?)
}

/// Checks that `v` is finite and strictly positive.
pub(crate) fn positive(what: &'static str, v: f32) -> Result<(), WanderError> {
    finite(what, v)?;
    if v > 0.0 {
        Ok(())
    } else {
        Err(WanderError::NotPositive { what, value: v })
    }
}

/// Checks that `v` is finite and in `[min, max]`.
pub(crate) fn in_range(what: &'static str, v: f32, min: f32, max: f32) -> Result<(), WanderError> {
    Ok(check_range(what, v, min, max)?)
}

/// Checks that an integer parameter is in `[min, max]`.
pub(crate) fn in_range_u(
    what: &'static str,
    v: u32,
    min: u32,
    max: u32,
) -> Result<(), WanderError> {
    if (min..=max).contains(&v) {
        Ok(())
    } else {
        Err(RangeError {
            field: what,
            value: v as f32,
            min: min as f32,
            max: max as f32,
        }
        .into())
    }
}
