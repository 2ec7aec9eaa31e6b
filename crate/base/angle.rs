//! Angle helpers shared by every controller.
//!
//! All angles are radians, counter-clockwise positive, and "wrapped" means in
//! `(-π, π]`. Keeping one definition avoids the classic bug where two modules
//! disagree on the seam (paper 000 §4 compares headings across ±π all the time).

use core::f32::consts::{PI, TAU};

/// Wraps an angle into `(-π, π]`.
#[inline]
#[must_use]
pub fn wrap(a: f32) -> f32 {
    if a > -PI && a <= PI {
        return a;
    }
    // One turn off, as sums and differences of two wrapped angles are: one
    // exact subtraction instead of a remainder (a software `fmod` on some
    // targets, and a noticeable share of a funnelling update's instructions).
    let b = if a > PI { a - TAU } else { a + TAU };
    if b > -PI && b <= PI {
        return b;
    }
    let r = (a + PI).rem_euclid(TAU) - PI;
    if r <= -PI {
        r + TAU
    } else {
        r
    }
}

/// Signed smallest difference `a - b`, wrapped.
#[inline]
#[must_use]
pub fn diff(a: f32, b: f32) -> f32 {
    wrap(a - b)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn wrap_is_in_range_and_idempotent() {
        for i in -2000..2000 {
            let a = i as f32 * 0.0137;
            let w = wrap(a);
            assert!(w > -PI && w <= PI, "{a} -> {w}");
            assert!((wrap(w) - w).abs() < 1e-6);
            assert!(((a - w) / TAU - ((a - w) / TAU).round()).abs() < 1e-4);
        }
        assert_eq!(wrap(PI), PI);
        assert!((wrap(-PI) - PI).abs() < 1e-6);
    }
}
