//! Per-run measures of crowded path following (after paper 003's
//! Results, which are only pictures: we put numbers on what they show).
//!
//! * **Lap time** — steps between two successive forward crossings of the
//!   path's start (arc length 0) by the same boid; a lap that started
//!   before the measurement window is not timed. Closed paths only.
//! * **Distance from the centre line** — mean and 95th percentile over all
//!   boid-steps of the distance from a boid to its closest path point. The
//!   percentile comes from a fixed histogram (bins of radius/20 up to 20
//!   radii, then the maximum), so recording never allocates.
//! * **Share outside** — share of boid-steps farther than the path radius.
//! * **Overlapping pairs per step** — unordered pairs closer than two boid
//!   radii (overlapping discs), averaged over steps.
//! * **Mean signed offset** — mean lateral offset, positive to the left of
//!   the travel direction (the inside of the counter-clockwise rectangle
//!   presets): the paper sees weak steering ride "alongside the outer wall".
//! * **Mean steering and separation** — mean magnitude per boid-step of the
//!   seek steering and of the separation velocity change; their ratio is
//!   the paper's Test IV explanation ("the magnitude of the separation
//!   velocity is much larger than the steering velocity").
//! * **Trace spread** — how much boids' (and laps') traces differ: the path
//!   is cut into [`STATIONS`] stretches of equal arc length; every passage
//!   of a boid through a stretch gives one value, its mean signed lateral
//!   offset; the spread is the standard deviation of those values per
//!   stretch, averaged over stretches. One boid on an "ideal traversal
//!   path" (the paper's Test I) gives a spread near 0; weak steering that
//!   "covers more space" gives a larger one. It needs O(boids + stations)
//!   memory, not a stored trace per boid.
//!
//! [`OffsetProfile`] (not collected by the crowd itself; a study records
//! it) keeps the mean signed offset per stretch of one boid over a window:
//! the "ideal traversal path" the paper sees in Test I, as numbers. Two
//! profiles compare by their RMS difference, so a test can tell whether two
//! boids, two seeks or two halves of one run follow the same path.

use serde::Serialize;

/// Number of equal arc-length stretches used by the trace spread.
pub const STATIONS: usize = 100;
const BINS_PER_RADIUS: usize = 20;
const HIST_RADII: usize = 20;
const NO_LAP: u64 = u64::MAX;
const NO_STATION: u32 = u32::MAX;

/// The measures of one run (see module docs). `None` when undefined (no
/// timed lap, no sample).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct CrowdMetrics {
    /// Steps measured.
    pub steps: u64,
    /// Laps timed (all boids).
    pub laps: u64,
    /// Mean lap time, steps.
    pub mean_lap_steps: Option<f32>,
    /// Mean distance from the centre line, world units.
    pub mean_distance: Option<f32>,
    /// 95th percentile distance from the centre line, world units.
    pub p95_distance: Option<f32>,
    /// Share of boid-steps outside the path radius, `[0, 1]`.
    pub outside_share: Option<f32>,
    /// Mean signed lateral offset, world units, positive to the left of travel.
    pub mean_offset: Option<f32>,
    /// Mean seek steering magnitude per boid-step, world units per step².
    pub mean_steer: Option<f32>,
    /// Mean separation magnitude per boid-step, world units per step².
    pub mean_separation: Option<f32>,
    /// Mean number of overlapping pairs per step.
    pub overlapping_pairs_per_step: Option<f32>,
    /// Mean standard deviation of lateral offset between traces, world units.
    pub trace_spread: Option<f32>,
}

/// Per-boid lap and station state.
#[derive(Clone, Copy, Debug)]
struct BoidTrack {
    /// Unwrapped arc-length progress (f64: many laps stay exact).
    u: f64,
    /// Arc length at the previous record (saves an fmod per boid-step).
    s_prev: f32,
    /// Highest lap index `floor(u / L)` reached.
    best: i64,
    /// Step at which the current timed lap started, or `NO_LAP`.
    lap_start: u64,
    station: u32,
    station_sum: f32,
    station_count: u32,
}

/// Accumulates [`CrowdMetrics`]; owned by the crowd. Allocation-free per
/// step once sized.
#[derive(Clone, Debug)]
pub struct MetricsAccumulator {
    path_length: f32,
    closed: bool,
    bin_width: f32,
    hist: Vec<u64>,
    max_distance: f32,
    samples: u64,
    outside: u64,
    sum_distance: f64,
    sum_offset: f64,
    sum_steer: f64,
    sum_separation: f64,
    steps: u64,
    overlap_sum: u64,
    overlap_steps: u64,
    laps: u64,
    lap_steps_sum: u64,
    station_sum: Vec<f64>,
    station_sumsq: Vec<f64>,
    station_n: Vec<u64>,
    tracks: Vec<BoidTrack>,
}

impl MetricsAccumulator {
    /// An empty accumulator for a path of `path_length` and `radius`.
    #[must_use]
    pub fn new(path_length: f32, radius: f32, closed: bool) -> Self {
        Self {
            path_length,
            closed,
            bin_width: radius / BINS_PER_RADIUS as f32,
            hist: vec![0; BINS_PER_RADIUS * HIST_RADII],
            max_distance: 0.0,
            samples: 0,
            outside: 0,
            sum_distance: 0.0,
            sum_offset: 0.0,
            sum_steer: 0.0,
            sum_separation: 0.0,
            steps: 0,
            overlap_sum: 0,
            overlap_steps: 0,
            laps: 0,
            lap_steps_sum: 0,
            station_sum: vec![0.0; STATIONS],
            station_sumsq: vec![0.0; STATIONS],
            station_n: vec![0; STATIONS],
            tracks: Vec::new(),
        }
    }

    /// Starts tracking `n` boids; `s_of(i)` is boid `i`'s current arc length.
    /// Existing boids keep their state; new ones start untimed.
    pub fn resize(&mut self, n: usize, s_of: impl Fn(usize) -> f32) {
        let old = self.tracks.len();
        self.tracks.truncate(n);
        for i in old..n {
            let s = s_of(i);
            let u = f64::from(s);
            self.tracks.push(BoidTrack {
                u,
                s_prev: s,
                best: (u / f64::from(self.path_length)).floor() as i64,
                lap_start: NO_LAP,
                station: NO_STATION,
                station_sum: 0.0,
                station_count: 0,
            });
        }
    }

    /// Records one step's overlapping-pair count.
    pub fn record_overlaps(&mut self, pairs: u64) {
        self.overlap_sum += pairs;
        self.overlap_steps += 1;
    }

    /// Records the magnitudes of one boid's seek steering and separation
    /// this step.
    pub fn record_forces(&mut self, steer: f32, separation: f32) {
        self.sum_steer += f64::from(steer);
        self.sum_separation += f64::from(separation);
    }

    /// Ends a step (counts it).
    pub fn end_step(&mut self) {
        self.steps += 1;
    }

    /// Records boid `i` at step `step`: its closest-point arc length `s`,
    /// distance from the centre line and signed lateral offset. Returns
    /// `true` when the boid just completed a forward crossing of the start.
    pub fn record_boid(
        &mut self,
        i: usize,
        step: u64,
        s: f32,
        distance: f32,
        offset: f32,
        radius: f32,
    ) -> bool {
        self.samples += 1;
        self.sum_distance += f64::from(distance);
        self.sum_offset += f64::from(offset);
        if distance > radius {
            self.outside += 1;
        }
        self.max_distance = self.max_distance.max(distance);
        let bin = ((distance / self.bin_width) as usize).min(self.hist.len() - 1);
        self.hist[bin] += 1;

        let total = f64::from(self.path_length);
        let t = &mut self.tracks[i];
        let mut crossed = false;
        if self.closed {
            let mut ds = f64::from(s) - f64::from(t.s_prev);
            if ds > total / 2.0 {
                ds -= total;
            } else if ds < -total / 2.0 {
                ds += total;
            }
            t.u += ds;
            t.s_prev = s;
            // Compare before dividing: a floor per boid-step shows in profiles.
            if t.u >= (t.best + 1) as f64 * total {
                t.best = (t.u / total).floor() as i64;
                crossed = true;
                if t.lap_start != NO_LAP {
                    self.laps += 1;
                    self.lap_steps_sum += step - t.lap_start;
                }
                t.lap_start = step;
            }
        }

        let station = ((s / self.path_length * STATIONS as f32) as usize).min(STATIONS - 1) as u32;
        if station != t.station {
            if t.station_count > 0 {
                let v = f64::from(t.station_sum / t.station_count as f32);
                let k = t.station as usize;
                self.station_sum[k] += v;
                self.station_sumsq[k] += v * v;
                self.station_n[k] += 1;
            }
            t.station = station;
            t.station_sum = 0.0;
            t.station_count = 0;
        }
        t.station_sum += offset;
        t.station_count += 1;
        crossed
    }

    /// The measures so far.
    #[must_use]
    pub fn metrics(&self) -> CrowdMetrics {
        // A mean over `n` samples, none when there are none.
        let mean = |sum: f64, n: u64| (n > 0).then(|| (sum / n as f64) as f32);
        let mut spread_sum = 0.0;
        let mut spread_n = 0usize;
        for k in 0..STATIONS {
            let n = self.station_n[k];
            if n >= 2 {
                let avg = self.station_sum[k] / n as f64;
                let var = (self.station_sumsq[k] / n as f64 - avg * avg).max(0.0);
                spread_sum += var.sqrt();
                spread_n += 1;
            }
        }
        CrowdMetrics {
            steps: self.steps,
            laps: self.laps,
            mean_lap_steps: mean(self.lap_steps_sum as f64, self.laps),
            mean_distance: mean(self.sum_distance, self.samples),
            p95_distance: (self.samples > 0).then(|| self.percentile(0.95)),
            outside_share: mean(self.outside as f64, self.samples),
            mean_offset: mean(self.sum_offset, self.samples),
            mean_steer: mean(self.sum_steer, self.samples),
            mean_separation: mean(self.sum_separation, self.samples),
            overlapping_pairs_per_step: mean(self.overlap_sum as f64, self.overlap_steps),
            trace_spread: mean(spread_sum, spread_n as u64),
        }
    }

    fn percentile(&self, q: f64) -> f32 {
        let want = q * self.samples as f64;
        let mut cum = 0u64;
        for (b, &c) in self.hist.iter().enumerate() {
            if c == 0 {
                continue;
            }
            if (cum + c) as f64 >= want {
                if b == self.hist.len() - 1 {
                    return self.max_distance;
                }
                let within = ((want - cum as f64) / c as f64).clamp(0.0, 1.0) as f32;
                return (b as f32 + within) * self.bin_width;
            }
            cum += c;
        }
        self.max_distance
    }
}

/// Mean signed lateral offset per stretch of the path ([`STATIONS`] of
/// equal arc length, as for the trace spread) of whatever is recorded into
/// it: one boid over a window, typically. See the module docs.
#[derive(Clone, Debug, PartialEq)]
pub struct OffsetProfile {
    path_length: f32,
    sum: Vec<f64>,
    n: Vec<u32>,
}

impl OffsetProfile {
    /// An empty profile of a path of `path_length`.
    #[must_use]
    pub fn new(path_length: f32) -> Self {
        Self {
            path_length,
            sum: vec![0.0; STATIONS],
            n: vec![0; STATIONS],
        }
    }

    /// Records a position at arc length `s` with signed lateral `offset`
    /// (as [`crate::crowd::path::Path::lateral_offset`] gives it).
    pub fn record(&mut self, s: f32, offset: f32) {
        let k = ((s / self.path_length * STATIONS as f32) as usize).min(STATIONS - 1);
        self.sum[k] += f64::from(offset);
        self.n[k] += 1;
    }

    /// The mean offset per stretch; `None` where nothing was recorded (a
    /// boid that cuts a corner never has its normal point there).
    #[must_use]
    pub fn means(&self) -> Vec<Option<f32>> {
        self.sum
            .iter()
            .zip(&self.n)
            .map(|(&s, &n)| (n > 0).then(|| (s / f64::from(n)) as f32))
            .collect()
    }

    /// Root mean square of the difference of the two profiles over the
    /// stretches both recorded; `None` when they share none. Stretches only
    /// one of them visited (a corner one boid cuts) do not count: the
    /// difference is of the paths where both ran.
    #[must_use]
    pub fn rms_difference(&self, other: &Self) -> Option<f32> {
        let (mut sq, mut k) = (0.0f64, 0u32);
        for (a, b) in self.means().into_iter().zip(other.means()) {
            if let (Some(a), Some(b)) = (a, b) {
                sq += f64::from(a - b).powi(2);
                k += 1;
            }
        }
        (k > 0).then(|| (sq / f64::from(k)).sqrt() as f32)
    }
}
