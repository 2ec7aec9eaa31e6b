//! The generator's reach simulations run several at a time, interleaved,
//! so that a table build takes less time natively.
//!
//! # Problem
//! One step of [`crate::funnelling::seek::simulate_reach`] is a chain of dependent
//! operations: position → bearing (`atan2`, a division and a polynomial) →
//! PD command → angular speed → heading → `sin_cos` (a degree-12 polynomial
//! in f64) → position. Each waits for the one before, so a lone simulation
//! leaves the processor idle most of the time: a step takes several
//! cycles for each of its about 100 instructions. The pedestrian's
//! table is 42 million steps (car 75 million at its own step, robot 21 million).
//!
//! # Design
//! [`LANES`] simulations advance together, one step of each in turn, so the
//! processor overlaps their independent chains (no SIMD: the CPU's
//! out-of-order core does it). Each lane runs exactly the operations of
//! `simulate_reach` on its own state, so every η is the same bits
//! (`tests/table_format.rs`: committed table == generator;
//! `tests/web_tables.rs`: Chromium == native). A lane that finishes takes
//! the next job at once: the next fallback speed of its own entry if the
//! target was unreachable (paper 001 Fig. 3c), else the next entry, so no
//! lane idles while work remains.
//!
//! Natively, one thread, this is faster than one simulation at a time
//! (`eta-table --threads 1` times a build); in wasm V8 gains nothing from
//! two or four lanes over the plain per-entry path, so
//! [`TableSpec::entries`] uses this module natively only.
//!
//! # Fallback
//! [`TableSpec::entry`] keeps the one-at-a-time path (tests compare the two).

use glam::Vec2;

use crate::base::angle::{diff, wrap};
use crate::base::trig;
use crate::base::vehicle::{Integrator, VehicleParams, VehicleState};
use crate::funnelling::table::{format::FLAG_ETA_VALID, format::FLAG_REACHABLE};

use super::spec::{Entry, TableSpec};

/// Simulations advanced together.
pub const LANES: usize = 4;

/// One simulation in flight: entry `job`, at desired speed level `level`
/// (10: the entry's `v_d`; 9..1: the fallback `v_d·k/10`).
#[derive(Clone, Copy)]
struct Lane {
    job: usize,
    level: u32,
    v_d: f32,
    target: Vec2,
    s: VehicleState,
    radial0: f32,
    turned: f32,
    step: u32,
    /// (distance, heading) one step back; distance < 0 at the first step.
    prev_dist: f32,
    prev_theta: f32,
}

/// What a step decided.
#[derive(Clone, Copy)]
enum Step {
    Running,
    Reached(f32),
    Unreachable,
}

#[derive(Clone, Copy)]
struct Sim {
    rr: f32,
    r2: f32,
    rr4: f32,
    max_steps: u32,
    orbit: f32,
}

impl Lane {
    /// A placeholder for a lane not in use.
    fn idle() -> Self {
        Self {
            job: 0,
            level: 0,
            v_d: 0.0,
            target: Vec2::ZERO,
            s: VehicleState::default(),
            radial0: 0.0,
            turned: 0.0,
            step: 0,
            prev_dist: -1.0,
            prev_theta: 0.0,
        }
    }

    fn start(spec: &TableSpec, job: usize, level: u32) -> Self {
        let (start, target, v_d) = spec.sample(spec.unravel(job));
        let v = if level == 10 {
            v_d
        } else {
            v_d * level as f32 / 10.0
        };
        let d0 = target - start.pos;
        Self {
            job,
            level,
            v_d: v,
            target,
            s: start,
            radial0: trig::atan2(d0.y, d0.x),
            turned: 0.0,
            step: 0,
            prev_dist: -1.0,
            prev_theta: 0.0,
        }
    }

    /// The first half of a step of `simulate_reach`: arrival, the straight
    /// run's early exit, else the bearing to steer on.
    #[inline(always)]
    fn look(&self, sim: &Sim) -> (Step, f32, f32) {
        if self.step >= sim.max_steps {
            return (Step::Unreachable, 0.0, 0.0);
        }
        let d = self.target - self.s.pos;
        let dist2 = d.length_squared();
        let dist = dist2.sqrt();
        if dist2 <= sim.r2 {
            let theta = if self.prev_dist >= 0.0 && self.prev_dist > dist {
                let (d0, th0) = (self.prev_dist, self.prev_theta);
                let f = ((d0 - sim.rr) / (d0 - dist)).clamp(0.0, 1.0);
                th0 + f * diff(self.s.theta, th0)
            } else {
                self.s.theta
            };
            return (Step::Reached(wrap(theta - self.radial0)), 0.0, 0.0);
        }
        let bearing = trig::atan2(d.y, d.x);
        if dist > sim.rr4 && self.s.omega.abs() < 1e-3 && diff(bearing, self.s.theta).abs() < 1e-3 {
            return (Step::Reached(wrap(bearing - self.radial0)), 0.0, 0.0);
        }
        (Step::Running, bearing, dist)
    }

    /// The PD command and the new speeds of [`VehicleParams::integrate`]
    /// (the same operations): the part of the seek step before the heading
    /// is turned into a direction. Returns (ω before, ω after, v before, v after).
    #[inline(always)]
    fn speeds(&self, p: &VehicleParams, bearing: f32) -> (f32, f32, f32, f32) {
        let s = &self.s;
        let acc = p.kp * diff(bearing, s.theta) - p.kd * s.omega;
        let (v0, w0) = (s.v, s.omega);
        let (w1, v1) = p.new_speeds(v0, w0, acc, self.v_d);
        (w0, w1, v0, v1)
    }
}

/// The heading after a step and the speed the position moves at, per
/// integrator ([`VehicleParams::integrate`]).
#[inline(always)]
fn heading_move(
    p: &VehicleParams,
    theta: f32,
    (_, w1, v0, v1): (f32, f32, f32, f32),
) -> (f32, f32) {
    match p.integrator {
        Integrator::Euler => (theta, v0 * p.dt),
        Integrator::SemiImplicitEuler => (wrap(theta + w1 * p.dt), v1 * p.dt),
    }
}

/// Rounds of [`Batch::rounds`] per call. Why a bound: V8 runs a wasm
/// function in its baseline compiler (Liftoff) until it returns and tiers
/// it up for the *next* call (no on-stack replacement), so one call that
/// ran a worker's whole slice would stay at baseline speed, far slower
/// than the optimised code (`node --no-liftoff` shows the difference).
/// Short calls reach the optimised code after the first few; natively the
/// bound costs nothing.
const ROUNDS_PER_CALL: u32 = 2048;

/// The simulations in flight over a range of entries.
struct Batch<'a> {
    spec: &'a TableSpec,
    /// The simulated vehicle ([`TableSpec::sim_vehicle`]).
    p: VehicleParams,
    sim: Sim,
    lanes: [Lane; LANES],
    /// Lanes in use: `lanes[..n]`.
    n: usize,
    next: usize,
    end: usize,
    base: usize,
    out: Vec<Option<Entry>>,
}

impl<'a> Batch<'a> {
    fn new(spec: &'a TableSpec, range: core::ops::Range<usize>) -> Self {
        let lim = &spec.params;
        let p = spec.sim_vehicle();
        let sim = Sim {
            rr: lim.reach_radius,
            r2: lim.reach_radius * lim.reach_radius,
            rr4: 4.0 * lim.reach_radius,
            max_steps: (lim.max_time / p.dt) as u32,
            orbit: lim.orbit_turns * core::f32::consts::TAU,
        };
        let mut b = Self {
            spec,
            p,
            sim,
            lanes: [Lane::idle(); LANES],
            n: 0,
            next: range.start,
            end: range.end,
            base: range.start,
            out: vec![None; range.len()],
        };
        while b.n < LANES {
            match b.take() {
                Some(i) => {
                    b.lanes[b.n] = Lane::start(spec, i, 10);
                    b.n += 1;
                }
                None => break,
            }
        }
        b
    }

    /// The next entry to simulate (mirrored ones are skipped).
    fn take(&mut self) -> Option<usize> {
        while self.next < self.end {
            let i = self.next;
            self.next += 1;
            if !self.spec.is_mirrored(i) {
                return Some(i);
            }
        }
        None
    }

    /// Up to `max` rounds of one step per lane; false once every entry is done.
    #[inline(never)]
    fn rounds(&mut self, max: u32) -> bool {
        let p = self.p;
        let p = &p;
        let sim = self.sim;
        let sim = &sim;
        let mut steer = [(0.0f32, 0.0f32); LANES];
        let mut verdict = [Step::Running; LANES];
        for _ in 0..max {
            if self.n == 0 {
                return false;
            }
            let n = self.n;
            let lanes = &mut self.lanes;
            // Every lane's bearing first, then every lane's step: the
            // lanes' chains are independent, so the processor overlaps them.
            let mut all_running = true;
            for k in 0..n {
                let (v, b, d) = lanes[k].look(sim);
                all_running &= matches!(v, Step::Running);
                verdict[k] = v;
                steer[k] = (b, d);
            }
            // The seek step in passes over the lanes, so that the long
            // chains (atan2 above, sin_cos here) of every lane overlap.
            let mut sp = [(0.0f32, 0.0f32, 0.0f32, 0.0f32); LANES];
            let mut hm = [(0.0f32, 0.0f32); LANES];
            for k in 0..n {
                sp[k] = lanes[k].speeds(p, steer[k].0);
                hm[k] = heading_move(p, lanes[k].s.theta, sp[k]);
            }
            let mut dir = [Vec2::ZERO; LANES];
            for k in 0..n {
                dir[k] = trig::unit(hm[k].0);
            }
            for k in 0..n {
                if !matches!(verdict[k], Step::Running) {
                    continue;
                }
                let lane = &mut lanes[k];
                let (w0, w1, _, v1) = sp[k];
                let th0 = lane.s.theta;
                lane.prev_dist = steer[k].1;
                lane.prev_theta = th0;
                lane.s.pos += dir[k] * hm[k].1;
                lane.s.theta = match p.integrator {
                    Integrator::Euler => wrap(th0 + w0 * p.dt),
                    Integrator::SemiImplicitEuler => hm[k].0,
                };
                lane.s.v = v1;
                lane.s.omega = w1;
                lane.turned += diff(lane.s.theta, th0);
                if lane.turned.abs() > sim.orbit {
                    verdict[k] = Step::Unreachable;
                    all_running = false;
                } else {
                    lane.step += 1;
                }
            }
            if !all_running {
                self.settle(&mut verdict);
            }
        }
        self.n > 0
    }

    /// Finished lanes: record their entry, or start the next fallback speed
    /// or the next entry; lanes left without work are dropped.
    fn settle(&mut self, verdict: &mut [Step; LANES]) {
        let mut k = 0;
        while k < self.n {
            let lane = self.lanes[k];
            let done = match verdict[k] {
                Step::Running => None,
                Step::Reached(eta) => {
                    let flags = if lane.level == 10 {
                        FLAG_REACHABLE | FLAG_ETA_VALID
                    } else {
                        FLAG_ETA_VALID
                    };
                    Some((eta, lane.v_d, flags))
                }
                Step::Unreachable if lane.level > 1 => {
                    self.lanes[k] = Lane::start(self.spec, lane.job, lane.level - 1);
                    None
                }
                Step::Unreachable => Some((0.0, 0.0, 0)),
            };
            if let Some(e) = done {
                self.out[lane.job - self.base] = Some(e);
                match self.take() {
                    Some(i) => self.lanes[k] = Lane::start(self.spec, i, 10),
                    None => {
                        self.n -= 1;
                        self.lanes.swap(k, self.n);
                        verdict.swap(k, self.n);
                        continue;
                    }
                }
            }
            k += 1;
        }
    }
}

/// Entries `range` of `spec`, `None` for those [`TableSpec::is_mirrored`]:
/// equal to `range.map(|i| spec.unless_mirrored(i))`, [`LANES`] simulations
/// at a time.
#[must_use]
pub fn entries(spec: &TableSpec, range: core::ops::Range<usize>) -> Vec<Option<Entry>> {
    let mut b = Batch::new(spec, range);
    while b.rounds(ROUNDS_PER_CALL) {}
    b.out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::base::vehicle::VehicleParams;
    use crate::funnelling::table::spec::TableSpec;

    /// The interleaved lanes give every entry the one-at-a-time
    /// simulation's bits: both integrators, reachable, fallback and
    /// unreachable entries, ranges that start and end anywhere.
    #[test]
    fn lanes_equal_one_simulation_at_a_time() {
        let robot = VehicleParams {
            v_max: 0.5,
            omega_max: 4.0,
            omega_accel_max: 64.0,
            kp: 192.0,
            kd: 24.0,
            ..VehicleParams::default()
        };
        let semi = VehicleParams {
            integrator: Integrator::SemiImplicitEuler,
            ..VehicleParams::default()
        };
        let fast = VehicleParams {
            v_max: 4.0,
            ..VehicleParams::default()
        };
        let car_like = VehicleParams {
            r_min: 1.5,
            ..VehicleParams::default()
        };
        for p in [VehicleParams::default(), robot, semi, fast, car_like] {
            let spec = TableSpec::with_counts(p, [6, 24, 3, 4, 3]);
            let n = spec.len();
            let bits = |v: Vec<Option<Entry>>| -> Vec<Option<(u32, u32, u8)>> {
                v.into_iter()
                    .map(|e| e.map(|(a, b, f)| (a.to_bits(), b.to_bits(), f)))
                    .collect()
            };
            let want: Vec<Option<Entry>> = (0..n).map(|i| spec.unless_mirrored(i)).collect();
            assert!(
                want.iter().flatten().any(|e| e.2 == FLAG_ETA_VALID),
                "a fallback entry"
            );
            let want = bits(want);
            assert_eq!(bits(entries(&spec, 0..n)), want);
            for (a, b) in [(0, 1), (5, 5), (7, 300), (n - 13, n)] {
                assert_eq!(bits(entries(&spec, a..b)), want[a..b].to_vec(), "{a}..{b}");
            }
        }
    }
}
