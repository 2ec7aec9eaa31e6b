//! One vocabulary for "this number is not acceptable": every
//! paper's inputs (vehicle limits, goals, funnel settings, crowd and wander
//! configurations, world edits) are checked with [`check_range`] and refused
//! with the same [`RangeError`], so a front end shows one kind of message:
//! `goal.dTol = 0 is outside [0.01, 1000]` or `kp = NaN is not finite`.
//!
//! Why a closed interval for everything: the core is f32 and must stay
//! finite (docs/DESIGN.md §5, determinism); every accepted value therefore has a
//! finite lower and upper bound, written where the field is validated.

use core::fmt;

/// A number that is NaN, infinite or outside its closed interval
/// `[min, max]`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RangeError {
    /// The field as the user wrote it (JSON / JavaScript name, with its path).
    pub field: &'static str,
    /// The refused value.
    pub value: f32,
    /// Smallest accepted value.
    pub min: f32,
    /// Largest accepted value.
    pub max: f32,
}

impl RangeError {
    /// True when the value was NaN or infinite (rather than out of bounds).
    #[must_use]
    pub fn not_finite(&self) -> bool {
        !self.value.is_finite()
    }
}

/// A number as a person reads it: plain from 0.001 to 99,999, else in
/// scientific notation (`1e6`, `1.1754944e-38`), never forty digits.
struct Num(f32);

impl fmt::Display for Num {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let a = self.0.abs();
        if a.is_finite() && a != 0.0 && !(1e-3..1e5).contains(&a) {
            write!(f, "{:e}", self.0)
        } else {
            write!(f, "{}", self.0)
        }
    }
}

impl fmt::Display for RangeError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.not_finite() {
            write!(f, "{} = {} is not finite", self.field, self.value)
        } else {
            write!(
                f,
                "{} = {} is outside [{}, {}]",
                self.field,
                Num(self.value),
                Num(self.min),
                Num(self.max)
            )
        }
    }
}

impl std::error::Error for RangeError {}

/// Checks that `value` is finite and within `[min, max]`.
///
/// # Errors
/// A [`RangeError`] naming `field` otherwise.
pub fn check_range(field: &'static str, value: f32, min: f32, max: f32) -> Result<(), RangeError> {
    if value.is_finite() && value >= min && value <= max {
        Ok(())
    } else {
        Err(RangeError {
            field,
            value,
            min,
            max,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn messages_name_the_field_the_value_and_the_interval() {
        let e = check_range("goal.dTol", 0.0, 0.01, 1e3).unwrap_err();
        assert_eq!(e.to_string(), "goal.dTol = 0 is outside [0.01, 1000]");
        let e = check_range("kp", f32::NAN, 0.01, 1e4).unwrap_err();
        assert_eq!(e.to_string(), "kp = NaN is not finite");
        assert!(e.not_finite());
        let e = check_range("x", f32::NEG_INFINITY, -1.0, 1.0).unwrap_err();
        assert_eq!(e.to_string(), "x = -inf is not finite");
        let e = check_range("pos.x", 2e6, -1e6, 1e6).unwrap_err();
        assert_eq!(e.to_string(), "pos.x = 2e6 is outside [-1e6, 1e6]");
        let e = check_range("fraction", 0.0, f32::MIN_POSITIVE, 1.0).unwrap_err();
        assert_eq!(e.to_string(), "fraction = 0 is outside [1.1754944e-38, 1]");
        let e = check_range("dt", 1.0, 1e-4, 0.1).unwrap_err();
        assert_eq!(e.to_string(), "dt = 1 is outside [1e-4, 0.1]");
    }

    #[test]
    fn bounds_are_inclusive() {
        assert!(check_range("a", 0.01, 0.01, 1e3).is_ok());
        assert!(check_range("a", 1e3, 0.01, 1e3).is_ok());
        assert!(check_range("a", 1e3 + 0.001, 0.01, 1e3).is_err());
    }
}
