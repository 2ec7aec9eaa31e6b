//! Deterministic trigonometry for the toolkit.
//!
//! Why not `f32::sin_cos`/`atan2`: std forwards them to the platform's libm,
//! whose last-bit rounding differs between glibc and the wasm build. A wander
//! trajectory feeds headings back into positions (and, for vector fields,
//! positions back into headings), so one ulp grows into a visibly different
//! path and the "same seed, same trajectory in the browser" promise (DESIGN
//! §8, "everything seeded and deterministic") breaks. These versions use only
//! IEEE-exact operations (+, −, ×, ÷, `round`) in f64, so they are
//! bit-identical on every target, and accurate to well under 1e-6.

use core::f64::consts::{FRAC_2_PI, FRAC_PI_2, FRAC_PI_4, PI};

/// `(sin x, cos x)`, bit-identical on every target; absolute error < 1e-6
/// for `|x| < 1e4`. NaN in, NaN out.
#[must_use]
pub fn sin_cos(x: f32) -> (f32, f32) {
    let x = f64::from(x);
    let k = (x * FRAC_2_PI).round();
    let r = x - k * FRAC_PI_2;
    let r2 = r * r;
    // Taylor polynomials on |r| <= π/4: truncation error < 1e-10.
    let s = r
        * (1.0
            + r2 * (-1.0 / 6.0
                + r2 * (1.0 / 120.0
                    + r2 * (-1.0 / 5040.0 + r2 * (1.0 / 362_880.0 - r2 / 39_916_800.0)))));
    let c = 1.0
        + r2 * (-0.5
            + r2 * (1.0 / 24.0
                + r2 * (-1.0 / 720.0
                    + r2 * (1.0 / 40_320.0 + r2 * (-1.0 / 3_628_800.0 + r2 / 479_001_600.0)))));
    // `as` saturates (and maps NaN to 0, whose r is NaN anyway).
    let (s, c) = match (k as i64) & 3 {
        0 => (s, c),
        1 => (c, -s),
        2 => (-s, -c),
        _ => (-c, s),
    };
    (s as f32, c as f32)
}

/// `sin x` (see [`sin_cos`]).
#[inline]
#[must_use]
pub fn sin(x: f32) -> f32 {
    sin_cos(x).0
}

/// Four-quadrant arctangent in `[-π, π]`, bit-identical on every target;
/// `atan2(0, 0) = 0`. Absolute error < 1e-7 (before rounding to f32).
#[must_use]
pub fn atan2(y: f32, x: f32) -> f32 {
    let (y, x) = (f64::from(y), f64::from(x));
    if y == 0.0 && x == 0.0 {
        return 0.0;
    }
    let (ax, ay) = (x.abs(), y.abs());
    let (num, den, swapped) = if ay > ax {
        (ax, ay, true)
    } else {
        (ay, ax, false)
    };
    let mut a = atan_unit(num / den);
    if swapped {
        a = FRAC_PI_2 - a;
    }
    if x < 0.0 {
        a = PI - a;
    }
    if y < 0.0 {
        a = -a;
    }
    a as f32
}

/// `atan t` for `t` in `[0, 1]`.
fn atan_unit(t: f64) -> f64 {
    const TAN_PI_8: f64 = 0.414_213_562_373_095_03;
    if t > TAN_PI_8 {
        FRAC_PI_4 + atan_small((t - 1.0) / (t + 1.0))
    } else {
        atan_small(t)
    }
}

/// Taylor series of `atan z` for `|z| <= tan(π/8)`; error < 1e-10.
fn atan_small(z: f64) -> f64 {
    let z2 = z * z;
    let mut acc = 0.0;
    let mut k = 21.0;
    while k > 1.0 {
        let sign = if (k as i32 / 2) % 2 == 0 { 1.0 } else { -1.0 };
        acc = sign / k + z2 * acc;
        k -= 2.0;
    }
    z * (1.0 + z2 * acc)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn matches_std_closely() {
        for i in -20_000..20_000 {
            let x = i as f32 * 0.0173;
            let (s, c) = sin_cos(x);
            assert!((s - x.sin()).abs() < 2e-6, "sin {x}");
            assert!((c - x.cos()).abs() < 2e-6, "cos {x}");
        }
        for i in -200..200 {
            for j in -200..200 {
                let (y, x) = (i as f32 * 0.37, j as f32 * 0.41);
                let a = atan2(y, x);
                if x == 0.0 && y == 0.0 {
                    assert_eq!(a, 0.0);
                } else {
                    assert!((a - y.atan2(x)).abs() < 1e-6, "atan2({y},{x}) {a}");
                }
            }
        }
        assert!(sin(f32::NAN).is_nan());
        assert!(atan2(f32::NAN, 1.0).is_nan());
    }
}
