//! The boid world of crowded path following (paper 003): path following,
//! one of two seeks, separation, metrics, and a highlighted lap trace.
//!
//! One [`Crowd::step`] is one paper frame, updated synchronously: separation
//! is computed for every boid from the positions at the start of the step,
//! then each boid independently adds its seek steering (only when its
//! prediction is outside the path radius) and its separation to its
//! velocity, clamps the speed to `max_speed`, and moves by its velocity
//! (explicit Euler, unit time step, like Processing boids). Synchronous
//! update makes the result independent of boid order and bit-identical for
//! the same seed on every target.
//!
//! Buffers are flat `f32` arrays `[x0, y0, x1, y1, ...]` so a WebAssembly
//! front end can view them without copying; they are reused, so a step does
//! not allocate (except the first one after the boid count grows).
//!
//! Binding notes: everything a front end needs is on [`Crowd`] with plain
//! types — build from a preset ([`CrowdConfig::paper`] or the JSON files
//! via [`Crowd::from_json`]), call [`Crowd::step`] once per frame, draw
//! [`Crowd::positions`] / [`Crowd::velocities`] (2 floats per boid, valid
//! until the next mutating call; their address changes only when the boid
//! count grows), the highlighted boid's lap [`Crowd::trace`] and
//! [`Crowd::path`]; edit with `set_boid_count`, `set_path_points` (flat),
//! `set_path_radius`, `set_path_closed`, `set_seek`, `set_separation`.
//! Every setter returns a [`CrowdError`] (Display-able) on bad input and
//! leaves the crowd unchanged.

use glam::Vec2;

use crate::base::grid::NeighbourGrid;
use crate::base::rng::Rng;
use crate::crowd::boid_seek::Seek;
use crate::crowd::config::{CrowdConfig, PathConfig, MAX_BOIDS};
use crate::crowd::error::{check_range, CrowdError};
use crate::crowd::metrics::{CrowdMetrics, MetricsAccumulator};
use crate::crowd::path::Path;
use crate::crowd::path_follow::PathFollow;
use crate::crowd::separation::{count_overlaps, separate, separate_owned};

/// Most points kept for the highlighted lap trace; longer laps are
/// decimated (every other point dropped, sampling stride doubled).
pub const TRACE_CAPACITY: usize = 4096;

/// Stream base for per-boid spawn generators (boid `i` uses stream
/// `SPAWN_STREAM + i`, so changing the count never reshuffles other boids).
const SPAWN_STREAM: u64 = 0x5EED_0000;

/// The crowd: boids, path, strategies and measures.
#[derive(Clone, Debug)]
pub struct Crowd {
    config: CrowdConfig,
    path: Path,
    pos: Vec<f32>,
    vel: Vec<f32>,
    sep: Vec<f32>,
    grid: NeighbourGrid,
    metrics: MetricsAccumulator,
    metrics_on: bool,
    step: u64,
    traced: usize,
    trace_u: f64,
    trace_best: i64,
    trace_cur: Vec<f32>,
    trace_last: Vec<f32>,
    trace_stride: u32,
    trace_tick: u32,
    last_overlaps: u64,
    /// Strip steps ([`Crowd::step_strip`]): which boids this copy steps, and the grid's members.
    owned: Vec<bool>,
    members: Vec<u32>,
}

impl Crowd {
    /// A crowd from a validated config: boids spawned at seeded random arc
    /// lengths, lateral offsets within `spawn_spread × radius`, heading along
    /// the path at a seeded speed in `[0.5, 1) × max_speed`.
    ///
    /// # Errors
    /// See [`CrowdConfig::validate`].
    pub fn new(config: &CrowdConfig) -> Result<Self, CrowdError> {
        config.validate()?;
        let path = config.path.build()?;
        let mut c = Self {
            metrics: MetricsAccumulator::new(path.length(), path.radius(), path.is_closed()),
            config: config.clone(),
            path,
            pos: Vec::new(),
            vel: Vec::new(),
            sep: Vec::new(),
            grid: NeighbourGrid::new(),
            metrics_on: true,
            step: 0,
            traced: 0,
            trace_u: 0.0,
            trace_best: 0,
            trace_cur: Vec::with_capacity(2 * TRACE_CAPACITY),
            trace_last: Vec::with_capacity(2 * TRACE_CAPACITY),
            trace_stride: 1,
            trace_tick: 0,
            last_overlaps: 0,
            owned: Vec::new(),
            members: Vec::new(),
        };
        c.resize_boids(config.boids);
        let n = config.boids.max(1) as u32;
        c.select_traced(Rng::new(config.seed).below(n) as usize);
        Ok(c)
    }

    /// [`Crowd::new`] from JSON text.
    ///
    /// # Errors
    /// See [`CrowdConfig::from_json`].
    pub fn from_json(text: &str) -> Result<Self, CrowdError> {
        Self::new(&CrowdConfig::from_json(text)?)
    }

    fn resize_boids(&mut self, n: usize) {
        let old = self.pos.len() / 2;
        self.pos.truncate(2 * n);
        self.vel.truncate(2 * n);
        for i in old..n {
            let mut rng = Rng::with_stream(self.config.seed, SPAWN_STREAM + i as u64);
            let s = rng.range(0.0, self.path.length());
            let tangent = self.path.tangent_at(s);
            let lateral = rng.range(-1.0, 1.0) * self.config.spawn_spread * self.path.radius();
            let p = self.path.point_at(s) + tangent.perp() * lateral;
            let v = tangent * self.config.max_speed * rng.range(0.5, 1.0);
            self.pos.extend_from_slice(&[p.x, p.y]);
            self.vel.extend_from_slice(&[v.x, v.y]);
        }
        self.sep.resize(2 * n, 0.0);
        self.config.boids = n;
        let (path, pos) = (&self.path, &self.pos);
        self.metrics.resize(n, |i| {
            path.normal_point(Vec2::new(pos[2 * i], pos[2 * i + 1])).s
        });
    }

    fn boid(&self, i: usize) -> (Vec2, Vec2) {
        (
            Vec2::new(self.pos[2 * i], self.pos[2 * i + 1]),
            Vec2::new(self.vel[2 * i], self.vel[2 * i + 1]),
        )
    }

    /// Advances the world by one step (module docs).
    pub fn step(&mut self) {
        let n = self.len();
        let cfg = &self.config;
        let sep_on = cfg.separation && n > 1;
        if sep_on {
            self.last_overlaps = separate(
                &mut self.grid,
                &self.pos,
                cfg.boid_radius,
                cfg.separation_weight,
                &mut self.sep,
            );
        } else if self.metrics_on {
            self.last_overlaps = count_overlaps(&mut self.grid, &self.pos, cfg.boid_radius);
        } else {
            self.last_overlaps = 0;
        }
        let radius = self.path.radius();
        self.step += 1;
        for i in 0..n {
            let (p, steer, sep) = self.advance_boid(i, sep_on);
            if self.metrics_on {
                let np = self.path.normal_point(p);
                let offset = self.path.lateral_offset(p, &np);
                self.metrics
                    .record_boid(i, self.step, np.s, np.distance, offset, radius);
                self.metrics.record_forces(steer.length(), sep.length());
            }
        }
        if self.metrics_on {
            self.metrics.record_overlaps(self.last_overlaps);
            self.metrics.end_step();
        }
        self.record_trace();
    }

    /// One step of the boids whose x at the step's start lies in
    /// `[lo, hi)` (a NaN x counts as −∞; `hi = +∞` takes +∞), as one
    /// worker's share of a world split into vertical strips. Separation
    /// reads every boid within reach of an owned one (the strip and a halo
    /// of twice the reach each side), so owned boids get the same bits as
    /// in [`Crowd::step`]; the other boids keep their state (the caller
    /// loads the next complete state with [`Crowd::set_state`]). No metrics,
    /// no trace (the page records the trace from the complete state,
    /// [`Crowd::observe_step`]). `owned` receives the owned indices.
    pub fn step_strip(&mut self, lo: f32, hi: f32, owned: &mut Vec<u32>) {
        let n = self.len();
        let cfg = &self.config;
        let sep_on = cfg.separation && n > 1;
        let halo = 4.0 * cfg.boid_radius;
        let (hlo, hhi) = (lo - halo, hi + halo);
        owned.clear();
        self.members.clear();
        self.owned.clear();
        self.owned.resize(n, false);
        for i in 0..n {
            let x = self.pos[2 * i];
            let xo = if x.is_nan() { f32::NEG_INFINITY } else { x };
            let own = xo >= lo && (xo < hi || hi == f32::INFINITY);
            if own {
                owned.push(i as u32);
                self.owned[i] = true;
            }
            if own || (x >= hlo && x < hhi) {
                self.members.push(i as u32);
            }
        }
        if sep_on && owned.len() == n {
            // One worker owns every boid: the whole grid, rebuilt in last
            // step's order (`NeighbourGrid::rebuild`), same bits.
            separate(
                &mut self.grid,
                &self.pos,
                cfg.boid_radius,
                cfg.separation_weight,
                &mut self.sep,
            );
        } else if sep_on {
            separate_owned(
                &mut self.grid,
                &self.pos,
                &self.members,
                &self.owned,
                cfg.boid_radius,
                cfg.separation_weight,
                &mut self.sep,
            );
        }
        for &i in owned.iter() {
            self.advance_boid(i as usize, sep_on);
        }
        self.step += 1;
    }

    /// Boid `i`'s update, shared by [`Crowd::step`] and
    /// [`Crowd::step_strip`]: path following plus its separation (from
    /// `self.sep` when `sep_on`), written back; returns its new position,
    /// steering force and separation (for the measures).
    #[inline]
    fn advance_boid(&mut self, i: usize, sep_on: bool) -> (Vec2, Vec2, Vec2) {
        let cfg = &self.config;
        let follow = PathFollow {
            predict_distance: cfg.predict_distance,
            lookahead: cfg.lookahead,
        };
        let (p, v) = self.boid(i);
        let sep = if sep_on {
            Vec2::new(self.sep[2 * i], self.sep[2 * i + 1])
        } else {
            Vec2::ZERO
        };
        let (p, v, steer) = advance(
            &self.path,
            &follow,
            cfg.seek,
            cfg.max_speed,
            cfg.max_force,
            p,
            v,
            sep,
        );
        self.pos[2 * i] = p.x;
        self.pos[2 * i + 1] = p.y;
        self.vel[2 * i] = v.x;
        self.vel[2 * i + 1] = v.y;
        (p, steer, sep)
    }

    /// Loads a complete state (positions and velocities, flat, two floats
    /// per boid each, for the present count) and the step count, as the
    /// page's stepping workers hand it back; the trace and the measures
    /// are kept.
    ///
    /// # Errors
    /// A length other than `2 × count`, named by field; nothing changes.
    pub fn set_state(&mut self, pos: &[f32], vel: &[f32], time: u64) -> Result<(), CrowdError> {
        let want = self.pos.len() as f32;
        check_range("positions length", pos.len() as f32, want, want)?;
        check_range("velocities length", vel.len() as f32, want, want)?;
        self.pos.copy_from_slice(pos);
        self.vel.copy_from_slice(vel);
        self.step = time;
        Ok(())
    }

    /// A step run elsewhere (in workers): counts it and records
    /// the traced boid's new position `p` in the lap trace, as
    /// [`Crowd::step`] would have.
    pub fn observe_step(&mut self, p: Vec2) {
        self.step += 1;
        if self.traced < self.len() {
            self.record_trace_at(p);
        }
    }

    /// Runs `steps` steps.
    pub fn run(&mut self, steps: u32) {
        for _ in 0..steps {
            self.step();
        }
    }

    /// The batch protocol of the presets: `warmup_steps` steps, reset the
    /// measures, `measure_steps` steps, return the measures.
    pub fn run_measured(&mut self) -> CrowdMetrics {
        self.run(self.config.warmup_steps);
        self.reset_metrics();
        self.run(self.config.measure_steps);
        self.metrics()
    }

    fn record_trace(&mut self) {
        if self.traced >= self.len() {
            return;
        }
        let (p, _) = self.boid(self.traced);
        self.record_trace_at(p);
    }

    fn record_trace_at(&mut self, p: Vec2) {
        let s = f64::from(self.path.normal_point(p).s);
        if self.path.is_closed() {
            let total = f64::from(self.path.length());
            let mut ds = s - self.trace_u.rem_euclid(total);
            if ds > total / 2.0 {
                ds -= total;
            } else if ds < -total / 2.0 {
                ds += total;
            }
            self.trace_u += ds;
            let lap = (self.trace_u / total).floor() as i64;
            if lap > self.trace_best {
                self.trace_best = lap;
                core::mem::swap(&mut self.trace_cur, &mut self.trace_last);
                self.trace_cur.clear();
                self.trace_stride = 1;
                self.trace_tick = 0;
            }
        }
        self.trace_tick += 1;
        if self.trace_tick >= self.trace_stride {
            self.trace_tick = 0;
            if self.trace_cur.len() >= 2 * TRACE_CAPACITY {
                let kept = self.trace_cur.len() / 4;
                for k in 0..kept {
                    self.trace_cur[2 * k] = self.trace_cur[4 * k];
                    self.trace_cur[2 * k + 1] = self.trace_cur[4 * k + 1];
                }
                self.trace_cur.truncate(2 * kept);
                self.trace_stride *= 2;
            }
            self.trace_cur.extend_from_slice(&[p.x, p.y]);
        }
    }

    /// Number of boids.
    #[must_use]
    pub fn len(&self) -> usize {
        self.pos.len() / 2
    }

    /// Whether there are no boids.
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.pos.is_empty()
    }

    /// Steps run since construction.
    #[must_use]
    pub fn time(&self) -> u64 {
        self.step
    }

    /// Positions, flat `[x0, y0, x1, y1, ...]`, world units.
    #[must_use]
    pub fn positions(&self) -> &[f32] {
        &self.pos
    }

    /// Velocities, flat `[vx0, vy0, ...]`, world units per step.
    #[must_use]
    pub fn velocities(&self) -> &[f32] {
        &self.vel
    }

    /// The highlighted boid's last complete lap (flat `[x, y, ...]`, at most
    /// [`TRACE_CAPACITY`] points), or its current partial lap if it has not
    /// completed one yet (paper 003 figures show "a random lap of a random
    /// boid").
    #[must_use]
    pub fn trace(&self) -> &[f32] {
        if self.trace_last.is_empty() {
            &self.trace_cur
        } else {
            &self.trace_last
        }
    }

    /// Index of the highlighted boid (seeded random at construction).
    #[must_use]
    pub fn traced_boid(&self) -> usize {
        self.traced
    }

    /// Highlights boid `i` instead (clamped to the last boid); clears the trace.
    pub fn select_traced(&mut self, i: usize) {
        self.traced = i.min(self.len().saturating_sub(1));
        self.trace_cur.clear();
        self.trace_last.clear();
        self.trace_stride = 1;
        self.trace_tick = 0;
        if self.traced < self.len() {
            let (p, _) = self.boid(self.traced);
            self.trace_u = f64::from(self.path.normal_point(p).s);
            self.trace_best = (self.trace_u / f64::from(self.path.length())).floor() as i64;
        }
    }

    /// The current configuration (boid count and edits included).
    #[must_use]
    pub fn config(&self) -> &CrowdConfig {
        &self.config
    }

    /// The path.
    #[must_use]
    pub fn path(&self) -> &Path {
        &self.path
    }

    /// The measures since the last reset.
    #[must_use]
    pub fn metrics(&self) -> CrowdMetrics {
        self.metrics.metrics()
    }

    /// Overlapping pairs at the last step (0 when neither separation nor
    /// metrics ran).
    #[must_use]
    pub fn last_overlaps(&self) -> u64 {
        self.last_overlaps
    }

    /// Candidate pairs examined by the neighbour grid since construction
    /// (or the last [`Crowd::reset_neighbour_checks`]).
    #[must_use]
    pub fn neighbour_checks(&self) -> u64 {
        self.grid.checks()
    }

    /// Resets the neighbour-check counter.
    pub fn reset_neighbour_checks(&mut self) {
        self.grid.reset_checks();
    }

    /// Clears the measures (boids keep their state).
    pub fn reset_metrics(&mut self) {
        self.metrics = MetricsAccumulator::new(
            self.path.length(),
            self.path.radius(),
            self.path.is_closed(),
        );
        let (path, pos) = (&self.path, &self.pos);
        self.metrics.resize(self.pos.len() / 2, |i| {
            path.normal_point(Vec2::new(pos[2 * i], pos[2 * i + 1])).s
        });
    }

    /// Switches metric recording (on by default; off skips the per-step
    /// measures, a large share of a step).
    pub fn set_metrics_enabled(&mut self, on: bool) {
        self.metrics_on = on;
    }

    /// Changes the boid count: existing boids keep their state, new ones
    /// spawn as at construction (boid `i`'s spawn depends only on the seed
    /// and `i`).
    ///
    /// # Errors
    /// More than [`MAX_BOIDS`].
    pub fn set_boid_count(&mut self, n: usize) -> Result<(), CrowdError> {
        check_range("boids", n as f32, 0.0, MAX_BOIDS as f32)?;
        let was_empty = self.is_empty();
        self.resize_boids(n);
        if self.traced >= n || was_empty {
            self.select_traced(if was_empty { self.traced } else { 0 });
        }
        Ok(())
    }

    /// Replaces the path points (flat `[x0, y0, ...]`); resets the measures
    /// and the trace, since progress along the old path means nothing on
    /// the new one. On error nothing changes.
    ///
    /// # Errors
    /// See [`Path::set_points_flat`].
    pub fn set_path_points(&mut self, xy: &[f32]) -> Result<(), CrowdError> {
        self.path.set_points_flat(xy)?;
        self.config.path = PathConfig {
            points: self.path.points().iter().map(|p| p.to_array()).collect(),
            radius: self.path.radius(),
            closed: self.path.is_closed(),
        };
        self.reset_metrics();
        self.select_traced(self.traced);
        Ok(())
    }

    /// Opens or closes the path; resets the measures and the trace.
    ///
    /// # Errors
    /// See [`Path::set_closed`].
    pub fn set_path_closed(&mut self, closed: bool) -> Result<(), CrowdError> {
        self.path.set_closed(closed)?;
        self.config.path.closed = closed;
        self.reset_metrics();
        self.select_traced(self.traced);
        Ok(())
    }

    /// Sets the path radius; resets the measures.
    ///
    /// # Errors
    /// See [`Path::set_radius`].
    pub fn set_path_radius(&mut self, radius: f32) -> Result<(), CrowdError> {
        self.path.set_radius(radius)?;
        self.config.path.radius = radius;
        self.reset_metrics();
        Ok(())
    }

    /// Switches the seek strategy (takes effect next step).
    ///
    /// # Errors
    /// See [`Seek::validate`].
    pub fn set_seek(&mut self, seek: Seek) -> Result<(), CrowdError> {
        seek.validate()?;
        self.config.seek = seek;
        Ok(())
    }

    /// Switches separation and sets its weight.
    ///
    /// # Errors
    /// Weight not finite or outside `[0, 10]`.
    pub fn set_separation(&mut self, on: bool, weight: f32) -> Result<(), CrowdError> {
        check_range("separation_weight", weight, 0.0, 10.0)?;
        self.config.separation = on;
        self.config.separation_weight = weight;
        Ok(())
    }
}

/// One boid's update of [`Crowd::step`] (module docs): seek only when the
/// prediction leaves the path, plus separation, speed clamp, Euler move.
/// Returns the new position, velocity and the seek steering.
#[inline]
#[allow(clippy::too_many_arguments)]
fn advance(
    path: &Path,
    follow: &PathFollow,
    seek: Seek,
    max_speed: f32,
    max_force: f32,
    p: Vec2,
    mut v: Vec2,
    sep: Vec2,
) -> (Vec2, Vec2, Vec2) {
    let decision = follow.decide(path, p, v);
    let steer = decision.target.map_or(Vec2::ZERO, |target| {
        seek.steer(p, v, target, max_speed, max_force)
    });
    v += steer + sep;
    v = v.clamp_length_max(max_speed);
    (p + v, v, steer)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::crowd::config::PaperTest;

    /// Small and proptest-free, so it can also run under wasm-bindgen-test.
    #[test]
    fn same_seed_gives_bit_identical_steps() {
        let cfg = CrowdConfig::paper(PaperTest::III, Seek::Parker { fraction: 0.01 });
        let mut a = Crowd::new(&cfg).unwrap();
        let mut b = Crowd::new(&cfg).unwrap();
        for _ in 0..50 {
            a.step();
            b.step();
        }
        assert_eq!(a.positions(), b.positions());
        assert_eq!(a.velocities(), b.velocities());
        assert_eq!(a.traced_boid(), b.traced_boid());
        assert!(a.positions().iter().all(|x| x.is_finite()));
    }
}
