//! Coherent noise: smooth (value) noise and Perlin gradient noise
//! (paper 004 §2 "Smooth Noise" and "Perlin Noise", §4 noise blends).
//!
//! Both are *random access* (a pure function of a seed and a coordinate)
//! rather than streams: the time functions of §4 need `perlin_noise(T − t)`,
//! i.e. the same sequence read backwards, and random access gives that for
//! free while staying allocation-free. Lattice values come from an integer
//! hash, so the noise is bit-identical natively and in WebAssembly.

/// A 32-bit integer hash of a seed and two lattice coordinates
/// (murmur3-style finaliser; good avalanche, no tables).
#[inline]
#[must_use]
pub fn hash(seed: u32, i: i32, j: i32) -> u32 {
    let mut h = seed ^ 0x9e37_79b9;
    h = (h ^ i as u32).wrapping_mul(0x85eb_ca6b);
    h = h.rotate_left(13) ^ (j as u32).wrapping_mul(0xc2b2_ae35);
    h ^= h >> 16;
    h = h.wrapping_mul(0x85eb_ca6b);
    h ^= h >> 13;
    h = h.wrapping_mul(0xc2b2_ae35);
    h ^ (h >> 16)
}

/// Uniform value in `[-1, 1)` for a lattice point: the white noise that
/// smooth noise interpolates.
#[inline]
#[must_use]
pub fn white(seed: u32, i: i32) -> f32 {
    (hash(seed, i, 0) >> 8) as f32 * (2.0 / 16_777_216.0) - 1.0
}

/// Perlin's quintic fade `6t⁵ − 15t⁴ + 10t³`: C² continuous joins.
#[inline]
fn fade(t: f32) -> f32 {
    t * t * t * (t * (t * 6.0 - 15.0) + 10.0)
}

#[inline]
fn lerp(a: f32, b: f32, t: f32) -> f32 {
    a + (b - a) * t
}

/// Splits `x` into its lattice cell and the fraction inside it.
#[inline]
fn cell(x: f32) -> (i32, f32) {
    let f = x.floor();
    (f as i32, x - f)
}

/// Smooth noise: white noise on the integers, linearly interpolated in
/// between (paper §2: "0 1 0 0 → 0 0.5 1 0.5 0 0 0"). Range `[-1, 1]`.
/// Linear, not cosine, interpolation because it is what the paper shows.
#[inline]
#[must_use]
pub fn smooth1(seed: u32, x: f32) -> f32 {
    let (i, f) = cell(x);
    lerp(white(seed, i), white(seed, i.wrapping_add(1)), f)
}

/// 1D Perlin gradient noise, scaled to `[-1, 1]`. Zero on the integers.
///
/// Gradients are uniform slopes in `[-1, 1]`; the raw noise is bounded by
/// 1/2 (reached at a cell midpoint with opposite unit slopes), hence the ×2.
#[must_use]
pub fn perlin1(seed: u32, x: f32) -> f32 {
    let (i, f) = cell(x);
    let g0 = white(seed, i);
    let g1 = white(seed, i.wrapping_add(1));
    2.0 * lerp(g0 * f, g1 * (f - 1.0), fade(f))
}

/// Eight gradient directions for 2D Perlin noise (Perlin 2002 style).
const GRAD2: [(f32, f32); 8] = [
    (1.0, 0.0),
    (-1.0, 0.0),
    (0.0, 1.0),
    (0.0, -1.0),
    (
        core::f32::consts::FRAC_1_SQRT_2,
        core::f32::consts::FRAC_1_SQRT_2,
    ),
    (
        -core::f32::consts::FRAC_1_SQRT_2,
        core::f32::consts::FRAC_1_SQRT_2,
    ),
    (
        core::f32::consts::FRAC_1_SQRT_2,
        -core::f32::consts::FRAC_1_SQRT_2,
    ),
    (
        -core::f32::consts::FRAC_1_SQRT_2,
        -core::f32::consts::FRAC_1_SQRT_2,
    ),
];

#[inline]
fn grad2(seed: u32, i: i32, j: i32, x: f32, y: f32) -> f32 {
    let (gx, gy) = GRAD2[(hash(seed, i, j) >> 29) as usize];
    gx * x + gy * y
}

/// 2D Perlin gradient noise, scaled by √2 and clamped to `[-1, 1]`
/// (unit gradients bound the raw value by √2/2). Zero on lattice points.
/// Used to give vector fields spatially coherent angles.
#[must_use]
pub fn perlin2(seed: u32, x: f32, y: f32) -> f32 {
    let (i, fx) = cell(x);
    let (j, fy) = cell(y);
    let (i1, j1) = (i.wrapping_add(1), j.wrapping_add(1));
    let n00 = grad2(seed, i, j, fx, fy);
    let n10 = grad2(seed, i1, j, fx - 1.0, fy);
    let n01 = grad2(seed, i, j1, fx, fy - 1.0);
    let n11 = grad2(seed, i1, j1, fx - 1.0, fy - 1.0);
    let (u, v) = (fade(fx), fade(fy));
    let n = lerp(lerp(n00, n10, u), lerp(n01, n11, u), v);
    (n * core::f32::consts::SQRT_2).clamp(-1.0, 1.0)
}

/// Fractal (octave) sum of [`perlin1`]: octave `k` has frequency `2^k` and
/// weight `persistence^k`; normalised by the weight sum so the range stays
/// `[-1, 1]`. Each octave uses its own seed so octaves are independent.
#[must_use]
pub fn fbm1(seed: u32, x: f32, octaves: u32, persistence: f32) -> f32 {
    let mut sum = 0.0;
    let mut norm = 0.0;
    let mut w = 1.0;
    let mut freq = 1.0;
    for k in 0..octaves.max(1) {
        sum += w * perlin1(seed.wrapping_add(k.wrapping_mul(0x68e3_1da4)), x * freq);
        norm += w;
        w *= persistence;
        freq *= 2.0;
    }
    sum / norm
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn perlin_is_zero_on_lattice_bounded_and_continuous() {
        for i in -50..50 {
            assert_eq!(perlin1(7, i as f32), 0.0);
            assert_eq!(perlin2(7, i as f32, (i * 3) as f32), 0.0);
        }
        let h = 1e-3;
        let mut prev = perlin1(3, -20.0);
        let mut x = -20.0 + h;
        while x < 20.0 {
            let v = perlin1(3, x);
            assert!((-1.0..=1.0).contains(&v));
            // |slope| <= 2 * (max over cell) < 2 * 2.0; h * 4 bounds the jump.
            assert!((v - prev).abs() <= 4.0 * h + 1e-5, "jump at {x}");
            prev = v;
            x += h;
        }
        for a in 0..200 {
            for b in 0..200 {
                let (x, y) = (a as f32 * 0.05 - 5.0, b as f32 * 0.05 - 5.0);
                let v = perlin2(11, x, y);
                assert!((-1.0..=1.0).contains(&v));
                let dx = perlin2(11, x + 1e-3, y) - v;
                let dy = perlin2(11, x, y + 1e-3) - v;
                assert!(dx.abs() < 1e-2 && dy.abs() < 1e-2, "2D jump at {x},{y}");
            }
        }
    }

    #[test]
    fn smooth_noise_interpolates_white_noise() {
        for i in -10..10 {
            let a = white(5, i);
            let b = white(5, i + 1);
            assert_eq!(smooth1(5, i as f32), a);
            assert!((smooth1(5, i as f32 + 0.5) - 0.5 * (a + b)).abs() < 1e-6);
        }
    }

    #[test]
    fn perlin_uses_its_range_and_is_centred() {
        let (mut lo, mut hi, mut sum) = (0.0f32, 0.0f32, 0.0f64);
        let n = 100_000;
        for k in 0..n {
            let v = perlin1(99, k as f32 * 0.137);
            lo = lo.min(v);
            hi = hi.max(v);
            sum += f64::from(v);
        }
        assert!(lo < -0.7 && hi > 0.7, "range {lo}..{hi}");
        assert!((sum / f64::from(n)).abs() < 0.02);
        let f = fbm1(1, 3.3, 4, 0.5);
        assert!((-1.0..=1.0).contains(&f));
    }
}
