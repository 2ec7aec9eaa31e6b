//! `f32` max / min as comparisons, for the per-agent hot paths.
//!
//! **Why.** wasm's `f32.max` / `f32.min` propagate NaN, Rust's
//! `f32::max` / `min` return the other operand, so in wasm each one becomes
//! a call to compiler-builtins' `fmaxf` / `fminf`: an out-of-line call in
//! the η lookup's axis positions, the vehicle model and the funnel's speed
//! caps, a noticeable share of a world step's time in wasm for calls
//! that do one comparison each. Natively they are one instruction plus
//! a NaN fix-up either way.
//!
//! **The same numbers.** [`MinMax::at_least`] is libm's `fmax` and
//! [`MinMax::at_most`] its `fmin`, written out (`x < y` and a NaN test): a
//! NaN operand gives the other, otherwise the larger / smaller, and on a
//! tie the receiver. So wasm computes what it computed through the calls,
//! for every input; natively IEEE 754 leaves the order of +0 and −0 open,
//! and the golden trajectory hashes, equal natively and in Chromium
//! (`tests/funnel_determinism.rs`), check that no path depends on it.

/// `max` / `min` without a library call in wasm (module docs).
pub trait MinMax: Sized {
    /// `self.max(lo)`: at least `lo`.
    #[must_use]
    fn at_least(self, lo: Self) -> Self;
    /// `self.min(hi)`: at most `hi`.
    #[must_use]
    fn at_most(self, hi: Self) -> Self;
}

impl MinMax for f32 {
    #[inline(always)]
    fn at_least(self, lo: f32) -> f32 {
        if self.is_nan() || self < lo {
            lo
        } else {
            self
        }
    }

    #[inline(always)]
    fn at_most(self, hi: f32) -> f32 {
        if hi.is_nan() || self < hi {
            self
        } else {
            hi
        }
    }
}

#[cfg(test)]
mod tests {
    use super::MinMax;

    #[test]
    fn as_max_and_min() {
        let xs = [
            -2.5f32,
            -1.0,
            0.0,
            0.25,
            3.0,
            f32::INFINITY,
            f32::NEG_INFINITY,
            f32::NAN,
        ];
        for &x in &xs {
            for &y in &xs {
                let (a, b) = (x.at_least(y), x.max(y));
                assert!(
                    a == b || (a.is_nan() && b.is_nan()),
                    "{x} at_least {y}: {a} vs {b}"
                );
                let (a, b) = (x.at_most(y), x.min(y));
                assert!(
                    a == b || (a.is_nan() && b.is_nan()),
                    "{x} at_most {y}: {a} vs {b}"
                );
            }
        }
    }
}
