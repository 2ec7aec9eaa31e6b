//! Where a query falls on the η table's sampled axes, in constant time
//! (paper 000 §7: "the control update cost is constant"; docs/DESIGN.md §8).
//!
//! The table's axes are non-uniform on purpose (dense near, u² speeds,
//! anisotropic α), so the interval holding a coordinate is not one division
//! away. A binary search costs a dozen unpredictable branches per axis, a
//! large share of a funnelling update's instructions. Instead
//! each axis keeps a uniform grid of buckets over its range, at most half
//! as wide as its narrowest interval, so a bucket holds at most one
//! sample. Per bucket it stores the one sample inside it (if any) and the
//! two intervals either side of it, resolved (indices, lower sample,
//! reciprocal width): the interval of `x` is then one bucket read and one
//! comparison away, with no loop, no branch and no second table read
//! (storing a count of earlier samples instead, and the intervals apart,
//! costs more instructions per axis). The
//! bucket of a sample is computed at load time with the very arithmetic a
//! query uses, so rounding can never put a query on the wrong side of a
//! sample. An axis too uneven for the bucket cap falls back to a binary
//! search (correct, slower; no committed table has one).

use crate::base::minmax::MinMax;
use core::f32::consts::TAU;

/// Most buckets per axis (guards the allocation for odd axes).
const MAX_BUCKETS: usize = 4096;

/// `2^23`: adding it to a float in `[0, 2^22)` leaves that float rounded
/// to an integer in the low mantissa bits (no saturating conversion).
const MAGIC: f32 = 8_388_608.0;

/// Position of a query along one axis: the two neighbouring samples and
/// the weight `t` of the upper one (`0 ≤ t ≤ 1`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AxisPos {
    /// Lower sample index.
    pub i0: u32,
    /// Upper sample index (`i0 + 1`, or 0 across the periodic seam).
    pub i1: u32,
    /// Weight of the upper sample.
    pub t: f32,
}

/// One interval of an axis, resolved: what a query in it returns, minus
/// its weight.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Segment {
    i0: u32,
    i1: u32,
    /// Lower sample.
    x0: f32,
    /// `1 / (x[i0 + 1] - x[i0])` (a multiply, not a divide, per query).
    inv_dx: f32,
}

/// A bucket: the interval holding its start, and the one sample inside it
/// (`+∞` when none) with the interval that begins there. A query reads its
/// bucket and compares once: no second table read, no index arithmetic.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Bucket {
    split: f32,
    below: Segment,
    above: Segment,
}

/// A sampled axis with its bucket index. Samples must be finite and
/// strictly increasing (the table loader checks this first).
#[derive(Clone, Debug, PartialEq)]
pub struct Axis {
    periodic: bool,
    /// Covered range `[lo, hi]`.
    lo: f32,
    hi: f32,
    inv_width: f32,
    /// Index of the last bucket.
    last_bucket: usize,
    /// Per bucket, see [`Bucket`]. Empty when some bucket holds two
    /// samples (then [`Axis::locate`] searches `segments`).
    buckets: Vec<Bucket>,
    /// Per interval. A periodic axis has one more interval, from its last
    /// sample to its first + 2π.
    segments: Vec<Segment>,
}

impl Axis {
    /// Indexes `samples`. A periodic axis (period 2π) covers
    /// `[samples[0], samples[0] + 2π)`, the last interval wrapping round.
    #[must_use]
    pub fn new(samples: &[f32], periodic: bool) -> Self {
        let n = samples.len();
        let mut x = samples.to_vec();
        if periodic {
            x.push(samples[0] + TAU);
        }
        let intervals = x.len() - 1;
        let (lo, hi) = (x[0], x[intervals]);
        let span = hi - lo;
        let narrowest = x
            .windows(2)
            .map(|w| w[1] - w[0])
            .fold(f32::INFINITY, f32::min);
        let count = ((2.0 * span / narrowest).ceil() as usize).clamp(1, MAX_BUCKETS);
        let segments: Vec<Segment> = x
            .windows(2)
            .enumerate()
            .map(|(i, w)| Segment {
                i0: i as u32,
                // The upper sample, or the first across the periodic seam.
                i1: if i + 1 == n { 0 } else { i as u32 + 1 },
                x0: w[0],
                inv_dx: 1.0 / (w[1] - w[0]),
            })
            .collect();
        let mut axis = Self {
            periodic,
            lo,
            hi,
            inv_width: count as f32 / span,
            last_bucket: count - 1,
            buckets: Vec::new(),
            segments,
        };
        // Per bucket: samples in earlier buckets, and the sample inside.
        let mut index = vec![(0u32, f32::INFINITY); count];
        let mut below = 0u32;
        let mut prev = usize::MAX;
        for &sample in &x {
            let b = axis.bucket(sample);
            if b == prev {
                // Two samples in one bucket: binary search instead.
                return axis;
            }
            for slot in &mut index[prev.wrapping_add(1).min(b)..b] {
                slot.0 = below;
            }
            index[b] = (below, sample);
            below += 1;
            prev = b;
        }
        for slot in &mut index[prev + 1..] {
            slot.0 = below;
        }
        // The interval of `c` is (samples ≤ c) − 1, and `hi` itself lies in
        // the last interval.
        let interval = |samples_le: u32| (samples_le.saturating_sub(1) as usize).min(intervals - 1);
        axis.buckets = index
            .iter()
            .map(|&(below, inside)| Bucket {
                split: inside,
                below: axis.segments[interval(below)],
                above: axis.segments[interval(below + 1)],
            })
            .collect();
        axis
    }

    /// The bucket of a coordinate `c` in `[lo, hi]`: monotone in `c`, and
    /// the same arithmetic at load time and at query time.
    #[inline]
    fn bucket(&self, c: f32) -> usize {
        let f = (c - self.lo) * self.inv_width + MAGIC;
        ((f.to_bits() & 0x007F_FFFF) as usize).min(self.last_bucket)
    }

    /// Where `v` falls. Outside a non-periodic axis (or for NaN) the
    /// position is clamped to the end sample and `clamped` is set; a
    /// periodic axis takes `v` already wrapped into `(-π, π]`.
    #[inline(always)]
    #[must_use]
    pub fn locate(&self, v: f32, clamped: &mut bool) -> AxisPos {
        let v = if self.periodic && v < self.lo {
            v + TAU
        } else {
            v
        };
        let (p, outside) = self.locate_linear(v);
        *clamped |= outside;
        p
    }

    /// [`Axis::locate`] without the periodic wrap, for an axis known not
    /// to be periodic, and with the clamp flag returned rather than
    /// accumulated through a reference: a lookup's five searches then keep
    /// one flag in a register (the flag's five stores and the five
    /// `periodic` tests would be a noticeable share of
    /// [`EtaTable::lookup`](crate::funnelling::table::lookup::EtaTable::lookup)'s
    /// axis searches; `diagnostics/icount.rs` counts them under callgrind).
    #[inline(always)]
    #[must_use]
    pub fn locate_linear(&self, v: f32) -> (AxisPos, bool) {
        let (lo, hi) = (self.lo, self.hi);
        // Plain comparisons (NaN fails both and becomes `lo`): cheaper than
        // the NaN-aware `max`/`min`.
        #[allow(clippy::manual_clamp)]
        let c = if v >= lo {
            if v <= hi {
                v
            } else {
                hi
            }
        } else {
            lo
        };
        let seg = match self.buckets.get(self.bucket(c)) {
            Some(b) => {
                if b.split <= c {
                    b.above
                } else {
                    b.below
                }
            }
            None => self.search(c),
        };
        // Exactly 1 at the upper end (a clamped query uses that sample
        // alone), whatever the rounding of the reciprocal.
        let t = if c >= hi {
            1.0
        } else {
            ((c - seg.x0) * seg.inv_dx).at_most(1.0)
        };
        let p = AxisPos {
            i0: seg.i0,
            i1: seg.i1,
            t,
        };
        (p, c != v)
    }

    /// The interval holding `c` by binary search: the fallback of an axis
    /// too uneven for buckets (kept out of line: no committed table has one).
    #[cold]
    #[inline(never)]
    fn search(&self, c: f32) -> Segment {
        let last = self.segments.len() - 1;
        let i = self.segments[1..=last].partition_point(|s| s.x0 <= c);
        self.segments[i]
    }

    /// The axis as a GPU kernel reads it (`crate::funnelling::table::gpu_table`):
    /// its samples, the periodic seam's closing sample included, and each
    /// interval's reciprocal width, the very numbers [`Axis::locate_linear`]
    /// interpolates with, so a search over the samples finds the same
    /// interval and the same weight.
    #[must_use]
    pub fn intervals(&self) -> (Vec<f32>, Vec<f32>) {
        let mut x: Vec<f32> = self.segments.iter().map(|s| s.x0).collect();
        x.push(self.hi);
        (x, self.segments.iter().map(|s| s.inv_dx).collect())
    }

    /// The nearest sample to `v` (clamped to the axis).
    #[inline]
    #[must_use]
    pub fn nearest(&self, v: f32) -> usize {
        let p = self.locate(v, &mut false);
        (if p.t < 0.5 { p.i0 } else { p.i1 }) as usize
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use core::f32::consts::PI;

    fn binary(x: &[f32], v: f32) -> usize {
        x.partition_point(|&a| a <= v)
            .saturating_sub(1)
            .min(x.len() - 2)
    }

    #[test]
    fn bucket_search_equals_binary_search() {
        let axes: [Vec<f32>; 3] = [
            (0..16).map(|i| 0.5 * 64f32.powf(i as f32 / 15.0)).collect(),
            (0..9).map(|k| 2.0 * (k as f32 / 8.0).powi(2)).collect(),
            vec![0.0, 1e-3, 1.0, 1000.0],
        ];
        for x in &axes {
            let a = Axis::new(x, false);
            let (lo, hi) = (x[0], x[x.len() - 1]);
            for k in 0..=20_000 {
                let v = lo + (hi - lo) * k as f32 / 20_000.0;
                let p = a.locate(v, &mut false);
                if v > lo && v < hi {
                    assert_eq!(p.i0 as usize, binary(x, v), "{v} in {x:?}");
                    assert!(x[p.i0 as usize] <= v && v < x[p.i1 as usize]);
                }
                assert!((0.0..=1.0).contains(&p.t));
            }
            // Every sample itself, and out of range.
            for (i, &v) in x.iter().enumerate().skip(1).take(x.len() - 2) {
                let i = i as u32;
                assert_eq!(
                    a.locate(v, &mut false),
                    AxisPos {
                        i0: i,
                        i1: i + 1,
                        t: 0.0
                    }
                );
            }
            let mut c = false;
            assert_eq!(a.locate(lo - 1.0, &mut c).t, 0.0);
            assert!(c);
            let mut c = false;
            assert_eq!(a.locate(f32::NAN, &mut c).i0, 0);
            assert!(c);
        }
    }

    #[test]
    fn periodic_axis_wraps_round_the_seam() {
        let x: Vec<f32> = (0..36).map(|k| -PI + k as f32 * TAU / 36.0).collect();
        let a = Axis::new(&x, true);
        let p = a.locate(PI, &mut false);
        assert_eq!((p.i0, p.i1), (35, 0));
        assert!((p.t - 1.0).abs() < 1e-5);
        let p = a.locate(x[35] + 0.01, &mut false);
        assert_eq!((p.i0, p.i1), (35, 0));
        // A periodic axis that does not start at −π: values below its
        // first sample belong to the wrapping interval.
        let y: Vec<f32> = x.iter().map(|v| v + 0.05).collect();
        let b = Axis::new(&y, true);
        let p = b.locate(-PI + 0.01, &mut false);
        assert_eq!((p.i0, p.i1), (35, 0));
        assert!(p.t > 0.0 && p.t < 1.0);
    }
}
