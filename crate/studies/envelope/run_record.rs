//! One run of the envelope study (a one-agent world stepped as the lab
//! steps it) and what it records.

use serde::Serialize;

use crate::base::angle::diff;
use crate::base::dubins;
use crate::base::vehicle::VehicleParams;
use crate::funnelling::controller::{Controller, ControllerKind};
use crate::funnelling::relaxed::RelaxedConfig;
use crate::funnelling::table::lookup::EtaTable;
use crate::funnelling::update::Mode;
use crate::studies::envelope::envelope_study::EnvScenario;
use crate::world::{goals::GoalMotion, World};

/// Time allowed after the last halting goal for the vehicle to come to
/// rest, s (braking from v_max takes 1.3 s).
pub const REST_TIME: f32 = 10.0;

/// What one run measured.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize)]
#[serde(rename_all = "camelCase")]
pub struct RunRecord {
    /// Index in its group.
    pub index: usize,
    /// Initial distance to the first goal, m.
    pub d0: f32,
    /// First goal's D_tol, m.
    pub d_tol: f32,
    /// First goal's ε_tol, degrees.
    pub eps_tol_deg: f32,
    /// First goal's desired speed, m/s.
    pub speed: f32,
    /// The last goal halts.
    pub halting: bool,
    /// Started inside the first goal's disk (no entry to judge: such runs
    /// are left out of the oriented-on-entry share and counted apart).
    pub starts_inside: bool,
    /// Entered the first goal's disk.
    pub reached: bool,
    /// Heading within ε_tol of β at the first step inside D_tol.
    pub oriented_on_entry: bool,
    /// |β − θ| at that step, degrees (NaN if never entered).
    pub entry_err_deg: f32,
    /// End_of_Steering declarations (one per goal done).
    pub eos: u32,
    /// Declarations with D < D_tol and |β − θ| < ε_tol at that step (and,
    /// for the last goal of a halting run, a rest pose inside both).
    pub eos_ok: u32,
    /// Halting runs: came to rest with both tolerances met.
    pub rest_ok: bool,
    /// Halting runs: distance and heading error at rest, m and degrees.
    pub rest_err: (f32, f32),
    /// Every goal done within the time limit.
    pub finished: bool,
    /// Path length until the last goal was done (or the limit), m.
    pub length: f32,
    /// Dubins length through the goal poses (radius at each goal's
    /// desired speed; moving goals where they were when done), m.
    pub dubins: f32,
    /// Steps with a non-finite value.
    pub nan: u32,
    /// Steps with a violated limit (includes the non-finite ones).
    pub violations: u32,
    /// Never entered the first goal's disk, still moving at the limit.
    pub orbit: bool,
    /// Time to finish, s (the limit if not finished).
    pub time: f32,
}

/// Runs one scenario with one controller.
#[must_use]
pub fn run(
    table: &EtaTable,
    p: &VehicleParams,
    ctl: &Controller,
    sc: &EnvScenario,
    max_time: f32,
) -> RunRecord {
    let (cfg, kind, rcfg) = match *ctl {
        Controller::Standard(f) => (f, ControllerKind::Standard, RelaxedConfig::default()),
        Controller::Relaxed(f, r) => (f, ControllerKind::Relaxed, r),
    };
    let first = sc.goals[0].goal;
    let last = sc.goals[sc.goals.len() - 1].goal;
    let mut rec = RunRecord {
        index: sc.index,
        d0: (first.pos - sc.start.pos).length(),
        d_tol: first.d_tol,
        eps_tol_deg: first.eps_tol.to_degrees(),
        speed: first.speed,
        halting: last.halting,
        starts_inside: (first.pos - sc.start.pos).length() < first.d_tol,
        entry_err_deg: f32::NAN,
        rest_err: (f32::NAN, f32::NAN),
        ..Default::default()
    };
    // Sampled scenarios are valid by construction; an invalid one would be
    // a bug in the sampler, reported as a run that never finishes.
    let Ok(mut w) = World::new(*p, cfg) else {
        return rec;
    };
    if w.set_controller(kind, rcfg).is_err() || w.add_agent(sc.start, sc.goals.clone()).is_err() {
        return rec;
    }
    // A goal moving away at 0.4 m/s from a vehicle asked for 0.5 m/s closes
    // at 0.1 m/s: 50 m take 500 s whatever the controller. Moving goals get
    // the time to close the initial distance at the speed difference on
    // top of the limit, so an unfinished run is the controller's doing.
    let chase = match sc.goals[0].motion {
        GoalMotion::Linear { velocity } => rec.d0 / (first.speed - velocity.length()).max(0.05),
        _ => 0.0,
    };
    let limit = ((max_time * sc.goals.len() as f32 + chase) / p.dt) as u32;
    let rest_limit = (REST_TIME / p.dt) as u32;
    let mut done_at: Option<u32> = None;
    let mut last_eos_ok = false;
    let mut dubins_from = (sc.start.pos.x, sc.start.pos.y, sc.start.theta);
    for k in 0..limit + rest_limit {
        let prev = w.agents()[0].state;
        let cur = w.agents()[0].current;
        if done_at.is_none() && k >= limit {
            break;
        }
        w.step(table).expect("the table is built for these limits");
        let a = &w.agents()[0];
        if !a.state.pos.is_finite() || !a.state.theta.is_finite() || !a.state.v.is_finite() {
            rec.nan += 1;
        }
        if done_at.is_some() {
            if a.state.v == 0.0 && a.state.omega.abs() < 1e-3 {
                break;
            }
            continue;
        }
        let g = a.goal_now;
        let d = (g.pos - prev.pos).length();
        let err = diff(g.beta, prev.theta).abs();
        if cur == 0 && !rec.reached && d < g.d_tol {
            rec.reached = true;
            rec.entry_err_deg = err.to_degrees();
            rec.oriented_on_entry = err < g.eps_tol;
        }
        if a.current > cur && a.internals.mode == Mode::EndOfSteering {
            rec.eos += 1;
            last_eos_ok = d < g.d_tol && err < g.eps_tol;
            if last_eos_ok {
                rec.eos_ok += 1;
            }
            let to = (g.pos.x, g.pos.y, g.beta);
            rec.dubins += dubins::shortest_length(dubins_from, to, p.min_turn_radius(g.speed));
            dubins_from = to;
        }
        if a.done() {
            done_at = Some(k);
            rec.finished = true;
            rec.time = k as f32 * p.dt;
            rec.length = a.metrics.length;
            if !last.halting {
                break;
            }
        }
    }
    let a = &w.agents()[0];
    rec.violations = a.metrics.violations;
    if !rec.finished {
        rec.time = limit as f32 * p.dt;
        rec.length = a.metrics.length;
        rec.orbit = !rec.reached && a.state.v > 0.05;
    }
    if last.halting && rec.finished {
        let g = a.goal_now;
        let d = (g.pos - a.state.pos).length();
        let e = diff(g.beta, a.state.theta).abs();
        rec.rest_err = (d, e.to_degrees());
        rec.rest_ok = a.state.v == 0.0 && d < g.d_tol && e < g.eps_tol;
        // A halting goal's End_of_Steering promised this rest pose too.
        if last_eos_ok && !rec.rest_ok {
            rec.eos_ok -= 1;
        }
    }
    rec
}
