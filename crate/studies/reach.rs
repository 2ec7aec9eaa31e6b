//! Reproducible measurement campaigns (the acceptance figures of paper
//! 000's funnelling, one operating point): seeded
//! random reach scenarios for the funnelling controller, run to the end and
//! summarised. Shared by the tests and by `steer reach`.

use glam::Vec2;

use crate::base::angle::diff;
use crate::base::dubins;
use crate::base::metrics::{percentile, PathMetrics};
use crate::base::rng::Rng;
use crate::base::vehicle::{VehicleParams, VehicleState};
use crate::funnelling::config::FunnelConfig;
use crate::funnelling::goal::{FunnelMemory, Goal};
use crate::funnelling::table::lookup::EtaTable;
use crate::funnelling::update::{Mode, Update};

/// The random scenario family of the acceptance figures: static targets at
/// D in [1, 30] m, any bearing and β, initial v in [0, v_max], initial ω
/// admissible; `D_tol` = 0.25 m, `ε_tol` = 5°, desired speed 1.3 m/s.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ReachStudy {
    /// Number of scenarios.
    pub n: usize,
    /// Seed.
    pub seed: u64,
    /// Distance range, m.
    pub d_range: (f32, f32),
    /// Position tolerance, m.
    pub d_tol: f32,
    /// Orientation tolerance, rad.
    pub eps_tol: f32,
    /// Desired speed, m/s.
    pub speed: f32,
    /// Time limit, s.
    pub max_time: f32,
}

impl Default for ReachStudy {
    fn default() -> Self {
        Self {
            n: 10_000,
            seed: 1,
            d_range: (1.0, 30.0),
            d_tol: 0.25,
            eps_tol: 5f32.to_radians(),
            speed: 1.3,
            max_time: 60.0,
        }
    }
}

/// Outcome of one scenario.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct RunResult {
    /// Reached End_of_Steering within the time limit.
    pub reached: bool,
    /// Entered the position tolerance already within ε_tol.
    pub oriented_on_entry: bool,
    /// |β − θ| when first entering the position tolerance, rad (NaN if never).
    pub entry_orientation_error: f32,
    /// |β − θ| at the end, rad.
    pub final_orientation_error: f32,
    /// Distance to the target at the end, m.
    pub final_position_error: f32,
    /// Time to reach, s (the limit if not reached).
    pub time: f32,
    /// Path metrics up to the end.
    pub path: PathMetrics,
    /// Dubins shortest length with the minimum turning radius at the
    /// desired speed, to the target pose, m.
    pub dubins: f32,
}

/// Runs one funnelling scenario from `start` to the static `goal`.
#[must_use]
pub fn run(
    table: &EtaTable,
    p: &VehicleParams,
    cfg: &FunnelConfig,
    start: VehicleState,
    goal: &Goal,
    max_time: f32,
) -> RunResult {
    let mut s = start;
    let mut r = RunResult {
        entry_orientation_error: f32::NAN,
        ..Default::default()
    };
    let steps = (max_time / p.dt) as u32;
    let mut entered = false;
    let mut mem = FunnelMemory::default();
    for k in 0..steps {
        let prev = s;
        let out = cfg.step(&mut Update {
            table,
            params: p,
            state: &mut s,
            goal,
            memory: &mut mem,
        });
        if !entered && (goal.pos - prev.pos).length() < goal.d_tol {
            entered = true;
            let e = diff(goal.beta, prev.theta).abs();
            r.entry_orientation_error = e;
            r.oriented_on_entry = e < goal.eps_tol;
        }
        if out.mode == Mode::EndOfSteering {
            r.reached = true;
            r.time = k as f32 * p.dt;
            s = prev;
            break;
        }
        r.path.add(p, &prev, &s);
    }
    if !r.reached {
        r.time = max_time;
    }
    r.final_orientation_error = diff(goal.beta, s.theta).abs();
    r.final_position_error = (goal.pos - s.pos).length();
    let rho = p.min_turn_radius(goal.speed);
    r.dubins = dubins::shortest_length(
        (start.pos.x, start.pos.y, start.theta),
        (goal.pos.x, goal.pos.y, goal.beta),
        rho,
    );
    r
}

/// Summary figures of a study.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Summary {
    /// Scenarios run.
    pub n: usize,
    /// Share reaching End_of_Steering.
    pub reach_rate: f32,
    /// Share entering the tolerance already oriented.
    pub oriented_rate: f32,
    /// Median and p95 of the entry orientation error, degrees.
    pub entry_err_deg: (f32, f32),
    /// Median and p95 of the final orientation error of reached runs, degrees.
    pub final_err_deg: (f32, f32),
    /// Median and p90 of path length / Dubins length (reached runs).
    pub length_ratio: (f32, f32),
    /// Median and p95 of the final distance to the target (reached runs), m.
    pub final_pos_err: (f32, f32),
    /// Median time to reach, s.
    pub median_time: f32,
    /// Steps with a violated limit or a non-finite value, over all runs.
    pub violations: u32,
}

impl ReachStudy {
    /// The `i`-th scenario: start state and goal. The start is at the
    /// origin heading +x; the target is placed around it.
    #[must_use]
    pub fn scenario(&self, p: &VehicleParams, i: usize) -> (VehicleState, Goal) {
        let mut r = Rng::with_stream(self.seed, i as u64);
        let d = r.range(self.d_range.0, self.d_range.1);
        let bearing = r.range(-core::f32::consts::PI, core::f32::consts::PI);
        let beta = r.range(-core::f32::consts::PI, core::f32::consts::PI);
        let v = r.range(0.0, p.v_max);
        let w = r.range(-1.0, 1.0) * p.omega_limit(v);
        let start = VehicleState::new(Vec2::ZERO, 0.0, v, w);
        let goal = Goal {
            pos: crate::base::trig::unit(bearing) * d,
            beta,
            d_tol: self.d_tol,
            eps_tol: self.eps_tol,
            speed: self.speed,
            halting: false,
            vel: Vec2::ZERO,
        };
        (start, goal)
    }

    /// Runs the whole study: in parallel on the current rayon pool natively,
    /// sequentially on wasm32; results in scenario order, independent of
    /// the thread count ([`crate::base::parallel`]).
    #[must_use]
    pub fn run_all(
        &self,
        table: &EtaTable,
        p: &VehicleParams,
        cfg: &FunnelConfig,
    ) -> Vec<RunResult> {
        crate::base::parallel::map_indices(self.n, |i| {
            let (s, g) = self.scenario(p, i);
            run(table, p, cfg, s, &g, self.max_time)
        })
    }
}

/// Summarises results.
#[must_use]
pub fn summarise(results: &[RunResult]) -> Summary {
    let n = results.len().max(1);
    let reached: Vec<&RunResult> = results.iter().filter(|r| r.reached).collect();
    let mut entry: Vec<f32> = results
        .iter()
        .filter(|r| r.entry_orientation_error.is_finite())
        .map(|r| r.entry_orientation_error.to_degrees())
        .collect();
    let mut fin: Vec<f32> = reached
        .iter()
        .map(|r| r.final_orientation_error.to_degrees())
        .collect();
    let mut ratio: Vec<f32> = reached
        .iter()
        .filter(|r| r.dubins > 1e-3)
        .map(|r| r.path.length / r.dubins)
        .collect();
    let mut times: Vec<f32> = reached.iter().map(|r| r.time).collect();
    let mut pos: Vec<f32> = reached.iter().map(|r| r.final_position_error).collect();
    Summary {
        n: results.len(),
        reach_rate: reached.len() as f32 / n as f32,
        oriented_rate: results.iter().filter(|r| r.oriented_on_entry).count() as f32 / n as f32,
        entry_err_deg: (percentile(&mut entry, 0.5), percentile(&mut entry, 0.95)),
        final_err_deg: (percentile(&mut fin, 0.5), percentile(&mut fin, 0.95)),
        length_ratio: (percentile(&mut ratio, 0.5), percentile(&mut ratio, 0.9)),
        final_pos_err: (percentile(&mut pos, 0.5), percentile(&mut pos, 0.95)),
        median_time: percentile(&mut times, 0.5),
        violations: results.iter().map(|r| r.path.violations).sum(),
    }
}
