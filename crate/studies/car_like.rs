//! The envelope of a car-like vehicle (a minimum turning radius `R_min`
//! at every speed, [`VehicleParams::r_min`]), scaled to `R_min`: oriented
//! arrival without pivoting ([`crate::funnelling::manoeuvre`]) measured
//! per distance band in turning radii, including targets closer than one.
//!
//! | sampled | range |
//! |---|---|
//! | distance D | three bands in `R_min`, [`BANDS`], as many runs in each; log-uniform inside |
//! | bearing, start heading, β | any |
//! | start speed | 0..v_max, start ω uniform in the admissible range (`|ω| ≤ v/R_min` too) |
//! | D_tol | [`D_TOLS`] × `R_min` |
//! | ε_tol | the envelope's {2, 5, 10, 20, 45}° |
//! | desired speed | the envelope's, scaled with `v_max` |
//! | halting | half the runs |
//!
//! Each run is a one-agent [`World`] with the standard or the relaxed
//! controller, stepped
//! as the lab steps it. A run records reach, oriented on entry, the rest
//! pose of a halting run, path length against the Dubins shortest path
//! (radius `R_min`, and the radius at the desired speed), limit violations
//! (the metrics check `|ω| ≤ v/R_min` with the other limits), and the
//! manoeuvre's Dubins solves against the updates.
//!
//! With a reverse gear ([`VehicleParams::v_reverse`]) the same scenarios
//! are run, and also from rest ([`run_from`]: the sampled start's pose,
//! speeds 0); a run records its path over the shortest Reeds–Shepp path
//! too, and whether a wrong-heading entry was unavoidable
//! ([`entry_unavoidable`], the deciding test).

use core::f32::consts::PI;

use glam::Vec2;
use serde::Serialize;

use crate::base::angle::{diff, wrap};
use crate::base::dubins;
use crate::base::reeds_shepp;
use crate::base::rng::Rng;
use crate::base::vehicle::{VehicleParams, VehicleState};
use crate::funnelling::config::FunnelConfig;
use crate::funnelling::controller::ControllerKind;
use crate::funnelling::goal::Goal;
use crate::funnelling::relaxed::RelaxedConfig;
use crate::funnelling::table::lookup::EtaTable;
use crate::funnelling::table::spec::VehicleScale;
use crate::studies::envelope::{EPS_TOLS_DEG, SPEEDS};
use crate::world::{goals::GoalMotion, goals::GoalSpec, goals::SwitchRule, World};

/// Distance bands, in `R_min`: `[lo, hi)`.
pub const BANDS: [(f32, f32); 3] = [(0.15, 1.0), (1.0, 5.0), (5.0, 20.0)];
/// Position tolerances, in `R_min`.
pub const D_TOLS: [f32; 4] = [0.1, 0.25, 0.5, 1.0];
/// Time limit per run, s, and after it to come to rest.
pub const MAX_TIME: f32 = 300.0;

/// The `i`-th scenario of `seed` for vehicle `p`: start state and goal.
#[must_use]
pub fn scenario(p: &VehicleParams, seed: u64, i: usize) -> (VehicleState, Goal) {
    let mut r = Rng::with_stream(seed, 0xCA2 << 40 | i as u64);
    let scale = VehicleScale::of(p);
    let (lo, hi) = BANDS[i % BANDS.len()];
    let d = lo * (hi / lo).powf(r.next_f32()) * p.r_min;
    let v = r.range(0.0, p.v_max);
    let w = r.range(-1.0, 1.0) * p.omega_limit(v);
    let start = VehicleState::new(Vec2::ZERO, r.range(-PI, PI), v, w);
    let pick = |r: &mut Rng, n: usize| (r.next_u32() as usize) % n;
    let goal = Goal {
        pos: crate::base::trig::unit(r.range(-PI, PI)) * d,
        beta: r.range(-PI, PI),
        d_tol: D_TOLS[pick(&mut r, D_TOLS.len())] * p.r_min,
        eps_tol: EPS_TOLS_DEG[pick(&mut r, EPS_TOLS_DEG.len())].to_radians(),
        speed: SPEEDS[pick(&mut r, SPEEDS.len())] * scale.speed,
        halting: r.next_f32() < 0.5,
        vel: Vec2::ZERO,
    };
    (start, goal)
}

/// What one run measured.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize)]
#[serde(rename_all = "camelCase")]
pub struct CarRun {
    /// Index of the scenario.
    pub index: usize,
    /// Initial distance, in `R_min`.
    pub d0: f32,
    /// D_tol, in `R_min`.
    pub d_tol: f32,
    /// ε_tol, degrees.
    pub eps_tol_deg: f32,
    /// Start speed, m/s.
    pub v0: f32,
    /// Halting goal.
    pub halting: bool,
    /// Started inside the disk (no entry to judge).
    pub starts_inside: bool,
    /// Entered the disk.
    pub reached: bool,
    /// Facing β within ε_tol at the first step inside.
    pub oriented_on_entry: bool,
    /// Finished (End_of_Steering) within the limit.
    pub finished: bool,
    /// Halting: at rest inside both tolerances.
    pub rest_ok: bool,
    /// Path length until finished, m.
    pub length: f32,
    /// Dubins shortest length from the start pose to the goal pose with
    /// radius `R_min`, m.
    pub dubins: f32,
    /// The same with the turning radius at the desired speed, m.
    pub dubins_at_speed: f32,
    /// Steps with a violated limit (`|ω| ≤ v/R_min` included).
    pub violations: u32,
    /// Updates run.
    pub updates: u32,
    /// Dubins paths solved by the manoeuvre.
    pub solves: u32,
    /// Largest solves in one update.
    pub max_solves_per_update: u32,
    /// Turning by more than 1° in a step slower than 2 % of `v_max`
    /// (pivoting), steps.
    pub pivots: u32,
    /// Reeds–Shepp shortest length from the start pose to the goal pose
    /// with radius `R_min`, m.
    pub reeds_shepp: f32,
    /// A wrong-heading entry was unavoidable ([`entry_unavoidable`]).
    pub unavoidable: bool,
    /// Steps driven backwards.
    pub backing: u32,
}

/// The deciding test of an unavoidable wrong-heading entry. With a
/// reverse gear: [`full_lock_askew`]. Forwards only: no path of the
/// sampled search [`crate::studies::car_entry`] enters the disk facing β
/// (forward paths of radius `R_min` after braking from a moving start
/// along a tightening full-lock or straight lead-in, to entry poses
/// sampled on the rim, keeping out of the disk before). Not the
/// full-lock test there: its arcs keep a moving start's radius, where
/// braking tightens the turn, and it excused a run the manoeuvre entered
/// oriented (the study asserts the search excuses none). A start inside
/// the disk is never counted.
#[must_use]
pub fn entry_unavoidable(p: &VehicleParams, s: &VehicleState, g: &Goal) -> bool {
    if p.car_like() && p.v_reverse <= 0.0 {
        !crate::studies::car_entry::oriented_entry_possible(p, s, g)
    } else {
        full_lock_askew(p, s, g)
    }
}

/// The full-lock test of an unavoidable wrong-heading entry: from `s`,
/// the vehicle's two extreme paths, full lock left and full lock right at the
/// radius of its speed (`max(R_min, v²/A)`), both enter the position
/// tolerance disk within the distance the vehicle is committed to (a
/// full turn forwards only; with a reverse gear only its braking
/// distance, after which it can back away), and β ± ε_tol lies outside the
/// headings between the two entries (what any path between the extremes
/// can face on entering). Traced in steps of at most a quarter of D_tol
/// and 2 % of the radius. A start inside the disk is never counted.
#[must_use]
pub fn full_lock_askew(p: &VehicleParams, s: &VehicleState, g: &Goal) -> bool {
    let v = s.v.abs();
    if (s.pos - g.pos).length() < g.d_tol || !p.car_like() {
        return false;
    }
    let r = p.r_min.max(v * v / p.normal_accel_max);
    let reach = if p.v_reverse > 0.0 {
        crate::funnelling::approach::braking_distance(p, v)
    } else {
        2.0 * PI * r
    };
    let h = (0.25 * g.d_tol).min(0.02 * r).max(1e-4);
    let steps = (reach / h).ceil() as u32;
    // Heading turned on entry for each side, or None (escapes).
    let mut turned = [0.0f32; 2];
    for (k, side) in [1.0f32, -1.0].into_iter().enumerate() {
        let centre = s.pos + crate::base::trig::unit(s.theta + side * PI / 2.0) * r;
        let mut hit = None;
        for i in 1..=steps {
            let phi = (i as f32 * h / r).min(reach / r);
            let at = centre + crate::base::trig::unit(s.theta - side * PI / 2.0 + side * phi) * r;
            if (at - g.pos).length() < g.d_tol {
                hit = Some(side * phi);
                break;
            }
        }
        match hit {
            Some(t) => turned[k] = t,
            None => return false,
        }
    }
    // β relative to the start heading, unwrapped about the middle of the
    // interval [right turn, left turn].
    let mid = 0.5 * (turned[0] + turned[1]);
    let b = mid + wrap(diff(g.beta, s.theta) - mid);
    b + g.eps_tol < turned[1] || b - g.eps_tol > turned[0]
}

/// Runs scenario `i` of `seed` with controller `kind` (standard or
/// relaxed: both manoeuvre near the goal).
#[must_use]
pub fn run(
    table: &EtaTable,
    p: &VehicleParams,
    kind: ControllerKind,
    seed: u64,
    i: usize,
) -> CarRun {
    run_from(table, p, kind, seed, i, false)
}

/// [`run`], from rest when `rest` (the sampled start's pose, speeds 0).
#[must_use]
pub fn run_from(
    table: &EtaTable,
    p: &VehicleParams,
    kind: ControllerKind,
    seed: u64,
    i: usize,
    rest: bool,
) -> CarRun {
    let (mut start, g) = scenario(p, seed, i);
    if rest {
        start.v = 0.0;
        start.omega = 0.0;
    }
    let d0 = (g.pos - start.pos).length();
    let mut rec = CarRun {
        index: i,
        d0: d0 / p.r_min,
        d_tol: g.d_tol / p.r_min,
        eps_tol_deg: g.eps_tol.to_degrees(),
        v0: start.v,
        halting: g.halting,
        starts_inside: d0 < g.d_tol,
        dubins: dubins::shortest_length(
            (0.0, 0.0, start.theta),
            (g.pos.x, g.pos.y, g.beta),
            p.r_min,
        ),
        dubins_at_speed: dubins::shortest_length(
            (0.0, 0.0, start.theta),
            (g.pos.x, g.pos.y, g.beta),
            p.min_turn_radius(g.speed),
        ),
        reeds_shepp: reeds_shepp::shortest_length(
            (0.0, 0.0, start.theta),
            (g.pos.x, g.pos.y, g.beta),
            p.r_min,
        ),
        unavoidable: entry_unavoidable(p, &start, &g),
        ..CarRun::default()
    };
    let Ok(mut w) = World::new(*p, FunnelConfig::default()) else {
        return rec;
    };
    let spec = GoalSpec {
        goal: g,
        motion: GoalMotion::Static,
        switch: SwitchRule::EndOfSteering,
    };
    if w.set_controller(kind, RelaxedConfig::default()).is_err()
        || w.add_agent(start, vec![spec]).is_err()
    {
        return rec;
    }
    let limit = (MAX_TIME / p.dt) as u32;
    let mut done = false;
    for _ in 0..2 * limit {
        let prev = w.agents()[0].state;
        let solves = w.agents()[0].memory.manoeuvre.solves;
        if !done && rec.updates >= limit {
            break;
        }
        w.step(table).expect("the table is built for these limits");
        let a = &w.agents()[0];
        rec.backing += u32::from(a.state.v < 0.0);
        if diff(a.state.theta, prev.theta).abs() > 1f32.to_radians()
            && prev.v.abs() < 0.02 * p.v_max
        {
            rec.pivots += 1;
        }
        if done {
            if a.state.v == 0.0 && a.state.omega.abs() < 1e-3 {
                break;
            }
            continue;
        }
        rec.updates += 1;
        let fresh = a.memory.manoeuvre.solves.saturating_sub(solves);
        rec.solves += fresh;
        rec.max_solves_per_update = rec.max_solves_per_update.max(fresh);
        let d = (g.pos - prev.pos).length();
        if !rec.reached && d < g.d_tol {
            rec.reached = true;
            rec.oriented_on_entry = diff(g.beta, prev.theta).abs() < g.eps_tol;
        }
        if a.done() {
            done = true;
            rec.finished = true;
            rec.length = a.metrics.length;
            if !g.halting {
                break;
            }
        }
    }
    let a = &w.agents()[0];
    rec.violations = a.metrics.violations;
    if !rec.finished {
        rec.length = a.metrics.length;
    }
    if g.halting && rec.finished {
        let d = (g.pos - a.state.pos).length();
        let e = diff(g.beta, a.state.theta).abs();
        rec.rest_ok = a.state.v == 0.0 && d < g.d_tol && e < g.eps_tol;
    }
    rec
}

/// Runs `n` scenarios of `seed` with `kind` (in parallel natively).
#[must_use]
pub fn run_all(
    table: &EtaTable,
    p: &VehicleParams,
    kind: ControllerKind,
    seed: u64,
    n: usize,
) -> Vec<CarRun> {
    crate::base::parallel::map_indices(n, |i| run(table, p, kind, seed, i))
}

/// [`run_all`], every start at rest when `rest`.
#[must_use]
pub fn run_all_from(
    table: &EtaTable,
    p: &VehicleParams,
    kind: ControllerKind,
    seed: u64,
    n: usize,
    rest: bool,
) -> Vec<CarRun> {
    crate::base::parallel::map_indices(n, |i| run_from(table, p, kind, seed, i, rest))
}

/// One distance band's summary of a seed's runs.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Band {
    /// Runs.
    pub runs: usize,
    /// Entered the disk (or started inside).
    pub reached: usize,
    /// Halting runs.
    pub halting: usize,
    /// Halting runs at rest inside both tolerances.
    pub rest_ok: usize,
    /// Runs that entered from outside.
    pub entries: usize,
    /// Of those, oriented on entry.
    pub oriented: usize,
    /// Entries at ε_tol ≥ 5°, and the oriented ones.
    pub oriented_eps5: (usize, usize),
    /// Path length / Dubins shortest (`R_min`) of the finished runs.
    pub ratios: Vec<f32>,
    /// Path length / Dubins shortest at the desired speed's radius.
    pub ratios_speed: Vec<f32>,
    /// [`Band::ratios`] of the runs starting at most `v_slow`.
    pub ratios_slow: Vec<f32>,
    /// Runs entering from outside where a wrong-heading entry was
    /// unavoidable ([`entry_unavoidable`]).
    pub unavoidable: usize,
    /// Entries where an oriented one was possible, and the oriented ones.
    pub oriented_possible: (usize, usize),
    /// Path length / Reeds–Shepp shortest (`R_min`) of the finished runs.
    pub ratios_rs: Vec<f32>,
}

/// The runs summarised per band of [`BANDS`]; `v_slow` selects
/// [`Band::ratios_slow`].
#[must_use]
pub fn summarise(runs: &[CarRun], v_slow: f32) -> Vec<Band> {
    let mut bands: Vec<Band> = BANDS.iter().map(|_| Band::default()).collect();
    for r in runs {
        let k = BANDS
            .iter()
            .position(|(lo, hi)| r.d0 >= lo * 0.999 && r.d0 < *hi)
            .unwrap_or(BANDS.len() - 1);
        let b = &mut bands[k];
        b.runs += 1;
        b.reached += usize::from(r.reached || r.starts_inside);
        if r.halting {
            b.halting += 1;
            b.rest_ok += usize::from(r.rest_ok);
        }
        if r.reached && !r.starts_inside {
            b.entries += 1;
            b.oriented += usize::from(r.oriented_on_entry);
            if r.eps_tol_deg >= 4.9 {
                b.oriented_eps5.0 += 1;
                b.oriented_eps5.1 += usize::from(r.oriented_on_entry);
            }
            if r.unavoidable {
                b.unavoidable += 1;
            } else {
                b.oriented_possible.0 += 1;
                b.oriented_possible.1 += usize::from(r.oriented_on_entry);
            }
        }
        if r.finished && r.reeds_shepp > 0.0 {
            b.ratios_rs.push(r.length / r.reeds_shepp);
        }
        if r.finished && r.dubins > 0.0 {
            b.ratios.push(r.length / r.dubins);
            b.ratios_speed.push(r.length / r.dubins_at_speed);
            if r.v0 <= v_slow {
                b.ratios_slow.push(r.length / r.dubins);
            }
        }
    }
    bands
}

/// Oriented on entry per cell (band × ε_tol × D_tol), one line per band
/// and ε_tol; and the smallest share over the cells at D ≥ 5 R_min with
/// ε_tol ≥ 5° (cells of at least 10 entries).
#[must_use]
pub fn cells(runs: &[CarRun]) -> (Vec<String>, f64) {
    let mut lines = Vec::new();
    let mut worst = 100.0f64;
    for (lo, hi) in BANDS {
        for eps in EPS_TOLS_DEG {
            let mut line = format!("  oriented on entry, D {lo}–{hi} R_min, ε_tol {eps}°:");
            for dt in D_TOLS {
                let sel: Vec<&CarRun> = runs
                    .iter()
                    .filter(|r| {
                        r.d0 >= lo * 0.999
                            && r.d0 < hi
                            && (r.eps_tol_deg - eps).abs() < 0.01
                            && (r.d_tol - dt).abs() < 1e-3
                            && r.reached
                            && !r.starts_inside
                    })
                    .collect();
                let ok = sel.iter().filter(|r| r.oriented_on_entry).count();
                let share = pct(ok, sel.len());
                line += &format!(" D_tol {dt} R: {share:.0} % of {};", sel.len());
                if lo >= 5.0 && eps >= 5.0 && sel.len() >= 10 {
                    worst = worst.min(share);
                }
            }
            lines.push(line);
        }
    }
    (lines, worst)
}

/// `100·a/b` (0 for an empty `b`).
#[must_use]
pub fn pct(a: usize, b: usize) -> f64 {
    100.0 * a as f64 / b.max(1) as f64
}

/// The slowest start the ratios of [`Band::ratios_slow`] keep: the
/// manoeuvre speed at `v_max`.
#[must_use]
pub fn slow_start(p: &VehicleParams) -> f32 {
    crate::funnelling::manoeuvre::manoeuvre_speed(
        p,
        &Goal {
            speed: p.v_max,
            ..Goal::default()
        },
    )
}

/// The summary lines (per band, then over all bands) of `runs`.
#[must_use]
pub fn text(p: &VehicleParams, runs: &[CarRun]) -> String {
    use crate::base::metrics::percentile;
    use core::fmt::Write;
    let v_slow = slow_start(p);
    let bands = summarise(runs, v_slow);
    let mut out = String::new();
    for (b, (lo, hi)) in bands.iter().zip(BANDS) {
        let mut r = b.ratios.clone();
        let mut rs = b.ratios_speed.clone();
        let mut rl = b.ratios_slow.clone();
        let _ = writeln!(
            out,
            "D {lo}–{hi} R_min: {} runs, reach {:.2} %, rest ok {:.2} % of {}, oriented on entry {:.1} % of {} ({:.1} % of {} at ε ≥ 5°), length/Dubins(R_min) median {:.2} p90 {:.2}, /Dubins(speed) median {:.2} p90 {:.2}; starting at most {v_slow:.1} m/s: /Dubins(R_min) median {:.2} p90 {:.2} of {}",
            b.runs,
            pct(b.reached, b.runs),
            pct(b.rest_ok, b.halting),
            b.halting,
            pct(b.oriented, b.entries),
            b.entries,
            pct(b.oriented_eps5.1, b.oriented_eps5.0),
            b.oriented_eps5.0,
            percentile(&mut r, 0.5),
            percentile(&mut r, 0.9),
            percentile(&mut rs, 0.5),
            percentile(&mut rs, 0.9),
            percentile(&mut rl, 0.5),
            percentile(&mut rl, 0.9),
            rl.len(),
        );
    }
    let mut all: Vec<f32> = bands
        .iter()
        .flat_map(|b| b.ratios.iter().copied())
        .collect();
    let _ = writeln!(
        out,
        "all bands: length/Dubins(R_min) median {:.2} p90 {:.2} of {}; limit violations {}, pivot steps {}",
        percentile(&mut all, 0.5),
        percentile(&mut all, 0.9),
        all.len(),
        runs.iter().map(|r| r.violations).sum::<u32>(),
        runs.iter().map(|r| r.pivots).sum::<u32>(),
    );
    for line in cells(runs).0 {
        let _ = writeln!(out, "{line}");
    }
    out
}

/// The lines of a run set with and without a reverse gear: per band,
/// oriented on entry, the entries where a wrong-heading one was
/// unavoidable, oriented among the others, and the path over the
/// shortest Reeds–Shepp path.
#[must_use]
pub fn text_reverse(runs: &[CarRun]) -> String {
    use crate::base::metrics::percentile;
    use core::fmt::Write;
    let bands = summarise(runs, 0.0);
    let mut out = String::new();
    for (b, (lo, hi)) in bands.iter().zip(BANDS) {
        let mut rs = b.ratios_rs.clone();
        let _ = writeln!(
            out,
            "D {lo}–{hi} R_min: {} runs, oriented on entry {:.1} % of {}, unavoidable {}, oriented where possible {:.1} % of {}, rest ok {:.2} % of {}, length/Reeds–Shepp(R_min) median {:.2} p90 {:.2} of {}",
            b.runs,
            pct(b.oriented, b.entries),
            b.entries,
            b.unavoidable,
            pct(b.oriented_possible.1, b.oriented_possible.0),
            b.oriented_possible.0,
            pct(b.rest_ok, b.halting),
            b.halting,
            percentile(&mut rs, 0.5),
            percentile(&mut rs, 0.9),
            rs.len(),
        );
    }
    let _ = writeln!(
        out,
        "limit violations {}, pivot steps {}, steps backing {}",
        runs.iter().map(|r| r.violations).sum::<u32>(),
        runs.iter().map(|r| r.pivots).sum::<u32>(),
        runs.iter().map(|r| r.backing).sum::<u32>(),
    );
    out
}
