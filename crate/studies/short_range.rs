//! Oriented arrival at every distance for vehicles that turn on the spot
//! (unicycles): the short-range approach of
//! [`crate::funnelling::short_range`] measured per distance band, for
//! starts at rest and in motion, halting and pass-through goals.
//!
//! | sampled | range |
//! |---|---|
//! | distance D | log-uniform 0.4–60 m ([`D_RANGE`]), scaled with the vehicle ([`VehicleScale`]); reported in [`BANDS`] |
//! | bearing, start heading, β | any |
//! | start | even runs at rest; odd runs moving, speed uniform in (5 %, 100 %] of v_max, ω uniform in the admissible range |
//! | D_tol, ε_tol, desired speed | the envelope's sets ([`D_TOLS`]: 0.1–2 m, [`EPS_TOLS_DEG`]: 2–45°, [`SPEEDS`]: 0.5–2 m/s), scaled |
//! | halting | half the runs |
//!
//! Each run is a one-agent [`World`] with the standard controller, stepped
//! as the lab steps it. It records whether the vehicle entered the disk
//! facing β within ε_tol (the first step inside), whether a wrong-heading
//! entry was unavoidable from its start
//! ([`crate::funnelling::short_range::entry_unavoidable`]), the rest pose
//! of a halting run, limit violations, and which approach was chosen. With
//! `plain` the agent's memory is marked decided before the first update,
//! so the same scenarios run with funnelling only: the approach without
//! the short-range choice, for the before/after comparison.

use core::f32::consts::PI;

use glam::Vec2;
use serde::Serialize;

use crate::base::angle::diff;
use crate::base::rng::Rng;
use crate::base::vehicle::{VehicleParams, VehicleState};
use crate::funnelling::config::FunnelConfig;
use crate::funnelling::goal::{Goal, ShortRange};
use crate::funnelling::short_range::entry_unavoidable;
use crate::funnelling::table::lookup::EtaTable;
use crate::funnelling::table::spec::VehicleScale;
use crate::studies::envelope::{D_TOLS, EPS_TOLS_DEG, SPEEDS};
use crate::world::{goals::GoalMotion, goals::GoalSpec, goals::SwitchRule, World};

/// Distance bands, m at the pedestrian's scale: `[lo, hi)`.
pub const BANDS: [(f32, f32); 4] = [(0.4, 2.0), (2.0, 5.0), (5.0, 15.0), (15.0, 60.0)];
/// Distance range, m at the pedestrian's scale (log-uniform).
pub const D_RANGE: (f32, f32) = (0.4, 60.0);
/// Time limit per run, s at the pedestrian's time scale.
pub const MAX_TIME: f32 = 150.0;

/// The `i`-th scenario of `seed` for vehicle `p`: start state and goal.
#[must_use]
pub fn scenario(p: &VehicleParams, seed: u64, i: usize) -> (VehicleState, Goal) {
    let mut r = Rng::with_stream(seed, 0x5407 << 40 | i as u64);
    let sc = VehicleScale::of(p);
    let (lo, hi) = D_RANGE;
    let d = lo * (hi / lo).powf(r.next_f32()) * sc.length;
    let heading = r.range(-PI, PI);
    let start = if i % 2 == 0 {
        VehicleState::new(Vec2::ZERO, heading, 0.0, 0.0)
    } else {
        let v = r.range(0.05, 1.0) * p.v_max;
        let w = r.range(-1.0, 1.0) * p.omega_limit(v);
        VehicleState::new(Vec2::ZERO, heading, v, w)
    };
    let pick = |r: &mut Rng, n: usize| (r.next_u32() as usize) % n;
    let goal = Goal {
        pos: crate::base::trig::unit(r.range(-PI, PI)) * d,
        beta: r.range(-PI, PI),
        // A robot's smallest tolerance is below the core's D_tol range:
        // run at its minimum, as the envelope does.
        d_tol: (D_TOLS[pick(&mut r, D_TOLS.len())] * sc.length)
            .max(crate::base::ranges::GOAL_D_TOL.min as f32),
        eps_tol: EPS_TOLS_DEG[pick(&mut r, EPS_TOLS_DEG.len())].to_radians(),
        speed: SPEEDS[pick(&mut r, SPEEDS.len())] * sc.speed,
        halting: r.next_f32() < 0.5,
        vel: Vec2::ZERO,
    };
    (start, goal)
}

/// What one run measured.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize)]
#[serde(rename_all = "camelCase")]
pub struct ShortRun {
    /// Index of the scenario.
    pub index: usize,
    /// Initial distance, m at the pedestrian's scale.
    pub d0: f32,
    /// Started moving (odd runs).
    pub moving: bool,
    /// Halting goal.
    pub halting: bool,
    /// Started inside the disk (no entry to judge).
    pub starts_inside: bool,
    /// A wrong-heading entry was unavoidable from the start.
    pub unavoidable: bool,
    /// Entered the disk.
    pub reached: bool,
    /// Facing β within ε_tol at the first step inside.
    pub oriented_on_entry: bool,
    /// Finished (End_of_Steering) within the limit.
    pub finished: bool,
    /// Halting: at rest inside both tolerances.
    pub rest_ok: bool,
    /// Steps with a violated limit.
    pub violations: u32,
    /// The approach chosen: turning first.
    pub turned_first: bool,
    /// The approach chosen: funnelling slower.
    pub slowed: bool,
    /// Time to the entry (or the limit), s.
    pub entry_time: f32,
}

/// Runs scenario `i` of `seed`; `plain`: funnelling only (the module's docs).
#[must_use]
pub fn run(table: &EtaTable, p: &VehicleParams, seed: u64, i: usize, plain: bool) -> ShortRun {
    let (start, g) = scenario(p, seed, i);
    let sc = VehicleScale::of(p);
    let d0 = (g.pos - start.pos).length();
    let mut rec = ShortRun {
        index: i,
        d0: d0 / sc.length,
        moving: start.v > 0.0,
        halting: g.halting,
        starts_inside: d0 < g.d_tol,
        unavoidable: entry_unavoidable(p, &start, &g),
        ..ShortRun::default()
    };
    let Ok(mut w) = World::new(*p, FunnelConfig::default()) else {
        return rec;
    };
    let spec = GoalSpec {
        goal: g,
        motion: GoalMotion::Static,
        switch: SwitchRule::EndOfSteering,
    };
    if w.add_agent(start, vec![spec]).is_err() {
        return rec;
    }
    if plain {
        if let Some(m) = w.memory_mut(0) {
            m.short_range = ShortRange::restored();
        }
    }
    let limit = (MAX_TIME * sc.time() / p.dt) as u32;
    let mut done = false;
    let mut updates = 0u32;
    for _ in 0..2 * limit {
        if !done && updates >= limit {
            break;
        }
        let prev = w.agents()[0].state;
        if w.step(table).is_err() {
            break;
        }
        let a = &w.agents()[0];
        if done {
            if a.state.v == 0.0 && a.state.omega.abs() < 1e-3 {
                break;
            }
            continue;
        }
        if updates == 0 {
            rec.turned_first = a.memory.short_range.side != 0;
            rec.slowed = a.memory.short_range.speed_cap > 0.0;
        }
        updates += 1;
        if !rec.reached && (g.pos - prev.pos).length() < g.d_tol && !rec.starts_inside {
            rec.reached = true;
            rec.oriented_on_entry = diff(g.beta, prev.theta).abs() < g.eps_tol;
            rec.entry_time = updates as f32 * p.dt;
        }
        if a.done() {
            done = true;
            rec.finished = true;
            if !g.halting {
                break;
            }
        }
    }
    if !rec.reached {
        rec.entry_time = updates as f32 * p.dt;
    }
    let a = &w.agents()[0];
    rec.violations = a.metrics.violations;
    if g.halting && rec.finished {
        let d = (g.pos - a.state.pos).length();
        let e = diff(g.beta, a.state.theta).abs();
        rec.rest_ok = a.state.v == 0.0 && d < g.d_tol && e < g.eps_tol;
    }
    rec
}

/// Runs `n` scenarios of `seed` (in parallel natively).
#[must_use]
pub fn run_all(
    table: &EtaTable,
    p: &VehicleParams,
    seed: u64,
    n: usize,
    plain: bool,
) -> Vec<ShortRun> {
    crate::base::parallel::map_indices(n, |i| run(table, p, seed, i, plain))
}

/// The band of [`BANDS`] a run's initial distance lies in.
#[must_use]
pub fn band_of(d0: f32) -> usize {
    BANDS
        .iter()
        .position(|(lo, hi)| d0 >= lo * 0.999 && d0 < *hi)
        .unwrap_or(BANDS.len() - 1)
}

/// A summary of some runs (one band, one kind of start, …).
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize)]
#[serde(rename_all = "camelCase")]
pub struct Tally {
    /// Runs starting outside the disk.
    pub runs: usize,
    /// Of those, oriented on entry.
    pub oriented: usize,
    /// Runs where a wrong-heading entry was unavoidable.
    pub unavoidable: usize,
    /// Runs where it was not, and of those the oriented ones.
    pub possible: (usize, usize),
    /// Halting runs (finished or not), and those at rest inside both tolerances.
    pub halting: (usize, usize),
    /// Runs that turned first, and that funnelled slower.
    pub chosen: (usize, usize),
    /// Steps with a violated limit.
    pub violations: u32,
}

impl Tally {
    /// The runs selected by `keep`, summarised.
    #[must_use]
    pub fn of(runs: &[ShortRun], keep: impl Fn(&ShortRun) -> bool) -> Self {
        let mut t = Self::default();
        for r in runs.iter().filter(|r| keep(r)) {
            t.violations += r.violations;
            if r.halting {
                t.halting.0 += 1;
                t.halting.1 += usize::from(r.rest_ok);
            }
            if r.starts_inside {
                continue;
            }
            t.runs += 1;
            t.oriented += usize::from(r.oriented_on_entry);
            t.chosen.0 += usize::from(r.turned_first);
            t.chosen.1 += usize::from(r.slowed);
            if r.unavoidable {
                t.unavoidable += 1;
            } else {
                t.possible.0 += 1;
                t.possible.1 += usize::from(r.oriented_on_entry);
            }
        }
        t
    }

    /// Oriented on entry, % of the runs starting outside.
    #[must_use]
    pub fn oriented_pct(&self) -> f64 {
        pct(self.oriented, self.runs)
    }

    /// Oriented on entry, % of the runs where it was possible.
    #[must_use]
    pub fn possible_pct(&self) -> f64 {
        pct(self.possible.1, self.possible.0)
    }

    /// Halting runs at rest inside both tolerances, %.
    #[must_use]
    pub fn rest_pct(&self) -> f64 {
        pct(self.halting.1, self.halting.0)
    }
}

/// `100·a/b` (100 for an empty `b`: nothing failed).
#[must_use]
pub fn pct(a: usize, b: usize) -> f64 {
    if b == 0 {
        100.0
    } else {
        100.0 * a as f64 / b as f64
    }
}

/// Which starts a line of the summary keeps.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Starts {
    /// Every run.
    All,
    /// Starts at rest.
    Rest,
    /// Starts in motion.
    Moving,
}

impl Starts {
    /// Every kind, in the summary's order.
    pub const ALL: [Self; 3] = [Self::All, Self::Rest, Self::Moving];

    /// Whether `r` is of this kind.
    #[must_use]
    pub fn keeps(self, r: &ShortRun) -> bool {
        match self {
            Self::All => true,
            Self::Rest => !r.moving,
            Self::Moving => r.moving,
        }
    }

    /// Lower-case name.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Self::All => "all",
            Self::Rest => "rest",
            Self::Moving => "moving",
        }
    }
}

/// The tally of band `b` (`None`: all D), starts `starts`, and halting
/// `halting` (`None`: both).
#[must_use]
pub fn tally(runs: &[ShortRun], b: Option<usize>, starts: Starts, halting: Option<bool>) -> Tally {
    Tally::of(runs, |r| {
        b.is_none_or(|b| band_of(r.d0) == b)
            && starts.keeps(r)
            && halting.is_none_or(|h| r.halting == h)
    })
}

/// The summary lines of `runs`: per band and kind of start, halting and
/// pass-through apart.
#[must_use]
pub fn text(runs: &[ShortRun]) -> String {
    use core::fmt::Write;
    let mut out = String::new();
    let bands = BANDS
        .iter()
        .enumerate()
        .map(|(b, &(lo, hi))| (Some(b), format!("D {lo}–{hi} m")));
    for (b, label) in bands.chain([(None, "all D".to_string())]) {
        for starts in Starts::ALL {
            let t = tally(runs, b, starts, None);
            let h = tally(runs, b, starts, Some(true));
            let q = tally(runs, b, starts, Some(false));
            let _ = writeln!(
                out,
                "{label}, {}: oriented on entry {:.1} % of {} (halting {:.1} %, pass-through {:.1} %); of the possible {:.1} % of {}; unavoidable {}; halting at rest inside {:.1} % of {}; turned first {}, slower {}; violations {}",
                starts.name(),
                t.oriented_pct(),
                t.runs,
                h.oriented_pct(),
                q.oriented_pct(),
                t.possible_pct(),
                t.possible.0,
                t.unavoidable,
                t.rest_pct(),
                t.halting.0,
                t.chosen.0,
                t.chosen.1,
                t.violations,
            );
        }
    }
    out
}
