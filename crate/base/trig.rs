//! Deterministic trigonometry, shared by every controller and the η table.
//!
//! Why not `f32::sin_cos`/`atan2`: std forwards them to the platform's libm,
//! whose last-bit rounding differs between glibc and the wasm build. Every
//! controller feeds headings back into positions (and positions back into
//! headings), so one ulp grows into a visibly different path and the "same
//! scenario, same trajectory natively and in the browser" promise (docs/DESIGN.md
//! §5) breaks. These versions use only
//! IEEE-exact operations (+, −, ×, ÷; `sin_cos` in f64,
//! `atan2` in f32, no fused multiply-adds), so they are bit-identical on
//! every target, and accurate to well under 1e-6. They are
//! also no slower than libm's (`cargo bench --bench core -- atan2` times
//! `atan2` here against glibc's `atan2f` in the same run).

use core::f64::consts::{FRAC_2_PI, FRAC_PI_2};

/// `(sin x, cos x)`, bit-identical on every target; absolute error < 1e-6
/// for `|x| < 1e4`. NaN in, NaN out.
///
/// The quadrant is restored by bit operations (a swap by selects, the
/// signs by xor), not by a `match` on it: a `match` compiles to a jump
/// table whose indirect jump is mispredicted about two times in three
/// where the angles fall in any quadrant from one call to the next
/// (agents' headings, one after another: most of the avoidance's indirect
/// mispredictions). The same bits as the `match` (the tests compare
/// them over every quadrant, NaN and the saturated extremes).
#[inline]
#[must_use]
pub fn sin_cos(x: f32) -> (f32, f32) {
    let (k, s, c) = reduced(x);
    let (s, c) = (s.to_bits(), c.to_bits());
    // Quadrants 1 and 3 swap sine and cosine; the sine is negated in 2
    // and 3, the cosine in 1 and 2 (negation flips the sign bit, NaN
    // included, as `-` does).
    let swap = k & 1 != 0;
    let (a, b) = (if swap { c } else { s }, if swap { s } else { c });
    let neg_s = ((k >> 1) & 1) << 63;
    let neg_c = ((k ^ (k >> 1)) & 1) << 63;
    (
        f64::from_bits(a ^ neg_s) as f32,
        f64::from_bits(b ^ neg_c) as f32,
    )
}

/// The quadrant `k` (as `i64`, `as` saturating) and the sine and cosine of
/// the reduced argument, [`sin_cos`]'s shared part.
#[inline(always)]
fn reduced(x: f32) -> (u64, f64, f64) {
    let x = f64::from(x);
    // The nearest quadrant, ties to even, by the classic 1.5·2^52 shift:
    // two exact additions (for |x| < 1e15) where `f64::round` is a
    // software call on x86-64 and wasm32 (about 25 instructions, for every
    // sin_cos of every update); a tie can only differ from `round` by picking
    // the other, equally reduced, quadrant.
    const SHIFT: f64 = 6_755_399_441_055_744.0;
    let k = (x * FRAC_2_PI + SHIFT) - SHIFT;
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
    ((k as i64) as u64, s, c)
}

/// The unit vector at angle `a`: `(cos a, sin a)`, bit-identical on every
/// target (glam's `Vec2::from_angle` uses the platform's libm).
#[inline]
#[must_use]
pub fn unit(a: f32) -> glam::Vec2 {
    let (s, c) = sin_cos(a);
    glam::Vec2::new(c, s)
}

/// `sin x` (see [`sin_cos`]).
#[inline]
#[must_use]
pub fn sin(x: f32) -> f32 {
    sin_cos(x).0
}

/// Four-quadrant arctangent in `[-π, π]`, bit-identical on every target;
/// `atan2(0, 0) = 0`. Absolute error < 4e-7 rad (2e-5°).
///
/// One division and a degree-15 odd minimax polynomial of `atan` on
/// `[0, 1]` (coefficients fitted for f32 evaluation, error 1.2e-7,
/// evaluated by Estrin's scheme for a short dependency chain), then
/// the octant is restored with selects, not branches: the η-table lookup
/// and every controller step call this, with bearings in all directions.
#[inline]
#[must_use]
pub fn atan2(y: f32, x: f32) -> f32 {
    const C: [f32; 8] = [
        0.999_999_34,
        -0.333_298_6,
        0.199_465_6,
        -0.139_086_04,
        0.096_421_33,
        -0.055_911_474,
        0.021_862_382,
        -0.004_054_412,
    ];
    let (ax, ay) = (x.abs(), y.abs());
    let steep = ay > ax;
    let (n, d) = if steep { (ax, ay) } else { (ay, ax) };
    if d == 0.0 {
        return 0.0;
    }
    let t = n / d;
    let u = t * t;
    // Estrin's scheme: the same polynomial as Horner's, half the latency.
    let u2 = u * u;
    let u4 = u2 * u2;
    let p = (C[0] + C[1] * u) + u2 * (C[2] + C[3] * u);
    let q = (C[4] + C[5] * u) + u2 * (C[6] + C[7] * u);
    let a = t * (p + u4 * q);
    let a = if steep {
        core::f32::consts::FRAC_PI_2 - a
    } else {
        a
    };
    let a = if x < 0.0 {
        core::f32::consts::PI - a
    } else {
        a
    };
    if y < 0.0 {
        -a
    } else {
        a
    }
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
                    let exact = f64::from(y).atan2(f64::from(x));
                    assert!((f64::from(a) - exact).abs() < 4e-7, "atan2({y},{x}) {a}");
                }
            }
        }
        assert!(sin(f32::NAN).is_nan());
        // The selects give the bits of the quadrant restored by a `match`
        // (the former form), every quadrant, both signs, NaN and the
        // saturated extremes included.
        let sin_cos_match = |x: f32| {
            let (k, s, c) = reduced(x);
            // `as` saturates (and maps NaN to 0, whose r is NaN anyway).
            let (s, c) = match k & 3 {
                0 => (s, c),
                1 => (c, -s),
                2 => (-s, -c),
                _ => (-c, s),
            };
            (s as f32, c as f32)
        };
        for i in -40_000..40_000 {
            for x in [i as f32 * 0.000_37, i as f32 * 0.0173, i as f32 * 3.7] {
                let (a, b) = (sin_cos_match(x), sin_cos(x));
                assert_eq!(
                    (a.0.to_bits(), a.1.to_bits()),
                    (b.0.to_bits(), b.1.to_bits()),
                    "{x}"
                );
            }
        }
        for x in [
            f32::NAN,
            f32::INFINITY,
            f32::NEG_INFINITY,
            f32::MAX,
            f32::MIN,
            0.0,
            -0.0,
        ] {
            let (a, b) = (sin_cos_match(x), sin_cos(x));
            assert_eq!(
                (a.0.to_bits(), a.1.to_bits()),
                (b.0.to_bits(), b.1.to_bits()),
                "{x}"
            );
        }
        assert!(atan2(f32::NAN, 1.0).is_nan());
    }
}
