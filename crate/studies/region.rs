//! Seeded random region-goal scenarios (paper 001 §5; the relaxed
//! controller's acceptance figures):
//! the same start and region goal run with the standard and the relaxed
//! controller, compared on path length and integrated |curvature|, and
//! checked for reach (ends inside the disk with a heading inside T).
//! Shared by `tests/relaxed.rs` and `steer relaxed`.

use core::f32::consts::PI;

use glam::Vec2;

use crate::base::angle::diff;
use crate::base::metrics::PathMetrics;
use crate::base::rng::Rng;
use crate::base::vehicle::{VehicleParams, VehicleState};
use crate::funnelling::controller::Controller;
use crate::funnelling::goal::{FunnelMemory, Goal};
use crate::funnelling::relaxed::RelaxedInternals;
use crate::funnelling::table::lookup::EtaTable;
use crate::funnelling::update::{Mode, Update};

/// The random family: start at the origin heading +x with a random
/// admissible (v, ω); disk centre at D ∈ `d_range` in any direction,
/// radius ∈ `r_range`, β any, τ ∈ `tau_range`, desired speed 1.3 m/s.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RegionStudy {
    /// Number of scenarios.
    pub n: usize,
    /// Seed.
    pub seed: u64,
    /// Centre distance range, m.
    pub d_range: (f32, f32),
    /// Disk radius range, m.
    pub r_range: (f32, f32),
    /// τ range, rad.
    pub tau_range: (f32, f32),
    /// Desired speed, m/s.
    pub speed: f32,
    /// Time limit, s.
    pub max_time: f32,
}

impl Default for RegionStudy {
    fn default() -> Self {
        Self {
            n: 1000,
            seed: 4,
            d_range: (3.0, 30.0),
            r_range: (0.5, 2.5),
            tau_range: (5f32.to_radians(), 30f32.to_radians()),
            speed: 1.3,
            max_time: 90.0,
        }
    }
}

/// Outcome of one run.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct RegionRun {
    /// End_of_Steering reached within the time limit.
    pub ended: bool,
    /// Ended inside the disk with a heading inside T (the acceptance test).
    pub reached: bool,
    /// Path metrics up to the end.
    pub path: PathMetrics,
    /// Part of `path.curvature` turned in Orientation_only mode (inside
    /// the disk, turning towards T at low speed), rad.
    pub in_place_turn: f32,
    /// Distance to the centre at the end, m.
    pub final_distance: f32,
    /// |β − θ| at the end, rad.
    pub final_heading_error: f32,
    /// Time, s.
    pub time: f32,
}

/// Runs one region goal to End_of_Steering (or the time limit).
#[must_use]
pub fn run_region(
    table: &EtaTable,
    p: &VehicleParams,
    ctl: &Controller,
    start: VehicleState,
    goal: &Goal,
    max_time: f32,
) -> RegionRun {
    let mut s = start;
    let mut r = RegionRun::default();
    let mut mem = FunnelMemory::default();
    let mut ri = RelaxedInternals::default();
    let steps = (max_time / p.dt) as u32;
    for k in 0..steps {
        let prev = s;
        let mut u = Update {
            table,
            params: p,
            state: &mut s,
            goal,
            memory: &mut mem,
        };
        let out = ctl.step(&mut u, &mut ri);
        if out.mode == Mode::EndOfSteering {
            r.ended = true;
            r.time = k as f32 * p.dt;
            s = prev;
            break;
        }
        r.path.add(p, &prev, &s);
        if out.mode == Mode::OrientationOnly {
            r.in_place_turn += diff(s.theta, prev.theta).abs();
        }
    }
    if !r.ended {
        r.time = max_time;
    }
    r.final_distance = (goal.pos - s.pos).length();
    r.final_heading_error = diff(goal.beta, s.theta).abs();
    r.reached = r.ended && r.final_distance < goal.d_tol && r.final_heading_error < goal.eps_tol;
    r
}

impl RegionStudy {
    /// The `i`-th scenario.
    #[must_use]
    pub fn scenario(&self, p: &VehicleParams, i: usize) -> (VehicleState, Goal) {
        let mut r = Rng::with_stream(self.seed, i as u64);
        let d = r.range(self.d_range.0, self.d_range.1);
        let bearing = r.range(-PI, PI);
        let beta = r.range(-PI, PI);
        let radius = r.range(self.r_range.0, self.r_range.1);
        let tau = r.range(self.tau_range.0, self.tau_range.1);
        let v = r.range(0.0, p.v_max);
        let w = r.range(-1.0, 1.0) * p.omega_limit(v);
        (
            VehicleState::new(Vec2::ZERO, 0.0, v, w),
            Goal {
                pos: crate::base::trig::unit(bearing) * d,
                beta,
                d_tol: radius,
                eps_tol: tau,
                speed: self.speed,
                halting: false,
                vel: Vec2::ZERO,
            },
        )
    }

    /// Runs the whole study with `ctl`: in parallel on the current rayon
    /// pool natively, sequentially on wasm32; results in scenario order,
    /// independent of the thread count ([`crate::base::parallel`]).
    #[must_use]
    pub fn run_all(&self, table: &EtaTable, p: &VehicleParams, ctl: &Controller) -> Vec<RegionRun> {
        crate::base::parallel::map_indices(self.n, |i| {
            let (s, g) = self.scenario(p, i);
            run_region(table, p, ctl, s, &g, self.max_time)
        })
    }
}

/// Paired comparison of two runs of the same cases.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Comparison {
    /// Pairs compared.
    pub n: usize,
    /// Mean path length, standard and relaxed, m.
    pub length: (f32, f32),
    /// Mean integrated |curvature|, standard and relaxed, rad.
    pub curvature: (f32, f32),
    /// Share of pairs where relaxed is shorter.
    pub relaxed_shorter: f32,
    /// Share of pairs where relaxed is less curved.
    pub relaxed_less_curved: f32,
    /// Reach rate (inside disk and T at the end), standard and relaxed.
    pub reach: (f32, f32),
}

/// Compares paired (length, curvature, reached) triples.
#[must_use]
pub fn compare(std: &[(PathMetrics, bool)], rel: &[(PathMetrics, bool)]) -> Comparison {
    let n = std.len().min(rel.len());
    if n == 0 {
        return Comparison::default();
    }
    let nf = n as f64;
    let mean = |v: &[(PathMetrics, bool)], f: fn(&PathMetrics) -> f32| {
        (v[..n].iter().map(|x| f64::from(f(&x.0))).sum::<f64>() / nf) as f32
    };
    let share =
        |pred: &dyn Fn(usize) -> bool| (0..n).filter(|&i| pred(i)).count() as f32 / n as f32;
    Comparison {
        n,
        length: (mean(std, |m| m.length), mean(rel, |m| m.length)),
        curvature: (mean(std, |m| m.curvature), mean(rel, |m| m.curvature)),
        relaxed_shorter: share(&|i| rel[i].0.length < std[i].0.length),
        relaxed_less_curved: share(&|i| rel[i].0.curvature < std[i].0.curvature),
        reach: (share(&|i| std[i].1), share(&|i| rel[i].1)),
    }
}
