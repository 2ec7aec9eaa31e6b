//! Arrival without pivoting, for car-like vehicles (a minimum turning
//! radius at every speed, [`VehicleParams::r_min`]; docs/DESIGN.md §14).
//!
//! The unicycle of paper 000 finishes an oriented arrival by turning on
//! the spot where it must (Orientation_only inside the position
//! tolerance, and targets too close to enter oriented). A car cannot: at
//! rest it cannot turn at all. Near its goal a car-like vehicle therefore
//! follows the shortest forward path to the goal *pose* (Dubins, solved in
//! constant time by [`DubinsPath::shortest`]) with a radius a little
//! larger than `R_min` ([`RHO_FACTOR`], the margin its angular
//! acceleration needs to change curvature), tracked by pure pursuit (the
//! seek controller aimed at a point [`LOOKAHEAD`] path radii ahead, which
//! follows an arc of that radius exactly), at a speed whose turning radius
//! is `R_min` ([`manoeuvre_speed`]), braking along the path to stop at the
//! goal for a halting goal. The path ends on a straight run-in along β
//! before the goal ([`runway`]) and goes on straight past it, so the
//! vehicle enters the position tolerance facing β.
//!
//! **Checked by simulation.** Whenever a path is solved, it is first
//! followed in simulation with the very update and seek step the world
//! runs (`trial`). When it would enter the position tolerance at the
//! wrong heading (the pursuit lags each change of curvature, and the
//! shortest word to the run-in may cut through the disk: a start close
//! to a large disk, or a fast start braking along its first arc), the
//! alternatives are simulated too, at most [`ALT_TRIALS`]: every
//! Dubins word, not only the shortest, of a few radii (`R_min` itself
//! among them) to run-ins of a few lengths, also off the goal's line, each
//! keeping out of the disk; the shortest drive that enters it facing β is
//! taken. A path whose simulation enters oriented is kept as it is, so
//! where the manoeuvre already arrived oriented nothing changes (the
//! car-like study's figures: docs/FIGURES.md, `car_like.forward.*`).
//!
//! A car with a reverse gear ([`VehicleParams::v_reverse`]) follows a
//! Reeds–Shepp path instead, forwards and backwards
//! ([`crate::funnelling::reverse`]).
//!
//! Goals in motion are left to funnelling (led to where they will be,
//! never finished by turning on the spot).
//!
//! Once begun, the manoeuvre goes on to the goal (this goal's memory
//! keeps it). Far from the goal, and not behind the vehicle ([`BEHIND`]),
//! the controller is the funnelling one (standard or
//! relaxed, with the car-like table, whose seek obeys the curvature
//! bound), its desired speed capped so that the vehicle reaches the
//! manoeuvre's range no faster than it can brake to the manoeuvre speed.
//!
//! The manoeuvre reports the mode Orientation_only (paper 000 Fig. 5's
//! blue triangle: the orientation is what is being fixed), End_of_Steering
//! once inside both tolerances (for a halting goal with the braking disk
//! and the heading at rest, as [`crate::funnelling::approach::tolerance_phase`]
//! judges them).
//!
//! Cost per update is bounded: at most one solve and three path samples.
//! A solve is one Dubins solve (six closed forms) and one simulated
//! follow, plus, when that enters askew, the alternatives' closed forms
//! and at most [`ALT_TRIALS`] more simulated follows (each at most
//! [`MAX_TRIAL_STEPS`] steps). A path is solved again only when the goal
//! pose moved, the vehicle strayed from the path by more than
//! [`REPLAN_ERR`] path radii, or it came to the end of the path without
//! arriving; [`Manoeuvre::solves`] counts the solves.

use glam::Vec2;

use crate::base::angle::diff;
use crate::base::dubins::{DubinsPath, WORDS};
use crate::base::minmax::MinMax;
use crate::base::trig;
use crate::base::vehicle::{VehicleParams, VehicleState};
use crate::funnelling::approach::{arrived, halting_speed, seen_from};
use crate::funnelling::goal::{Goal, Manoeuvre};
use crate::funnelling::reverse::{segment_distance, Pursuit, MAX_TRIAL_STEPS, TRIAL_EPS_SHARE};
use crate::funnelling::seek::seek_step_committed;
use crate::funnelling::update::{Internals, Mode, Update};

/// The path radius over `R_min`: tracking a change of curvature takes the
/// time the angular acceleration needs, and the path must leave room for it.
pub const RHO_FACTOR: f32 = 1.1;
/// The manoeuvre takes over within this many path radii of the goal
/// (beyond the position tolerance).
pub const NEAR: f32 = 6.0;
/// A goal further than [`NEAR`] but at a bearing beyond this is reached
/// by the manoeuvre too: the shortest forward path turns round at once,
/// where funnelling a fast car towards a goal right behind it can drive
/// straight away (the seek's heading error flips at ±π).
pub const BEHIND: f32 = core::f32::consts::FRAC_PI_2;
/// The pure-pursuit aim point, path radii ahead along the path.
pub const LOOKAHEAD: f32 = 0.5;
/// Straying this many path radii from the path solves a new one.
pub const REPLAN_ERR: f32 = 0.3;
/// The manoeuvre speed over the fastest speed whose turning radius is
/// `R_min` ([`manoeuvre_speed`]): slower, a change of curvature is
/// tracked over a shorter distance (`2v²/(ρ·ω̇_max)`), so the path radius
/// can be closer to `R_min`.
pub const SPEED_FACTOR: f32 = 0.5;
/// The run-in beyond the position tolerance, path radii ([`runway`]).
pub const RUNWAY: f32 = 0.5;

/// The run-ins beyond the position tolerance of the paths tried when the
/// manoeuvre's own would enter askew, path radii (`alternatives`): a
/// longer one leaves the pursuit room to settle on the line.
pub const ALT_RUN_INS: [f32; 5] = [0.5, 0.0, 1.0, 2.0, 4.0];
/// Their lateral offsets from the goal, shares of `D_tol`: the run-in
/// need not cross the goal itself.
pub const ALT_OFFSETS: [f32; 3] = [0.0, 0.5, -0.5];
/// Their radii, in path radii: a wider one is tracked more closely.
pub const ALT_RADII: [f32; 3] = [1.0, 1.0 / RHO_FACTOR, 1.3];
/// How far they keep out of the disk, path radii: room for the pursuit's
/// tracking error.
pub const ALT_MARGIN: f32 = 0.15;
/// The most of them simulated per solve.
pub const ALT_TRIALS: usize = 24;

/// The speed a car-like vehicle manoeuvres at: the goal's desired speed,
/// at most [`SPEED_FACTOR`] of the fastest speed whose turning radius is still `R_min`
/// (`min(ω_max·R_min, √(A·R_min))`).
#[must_use]
pub fn manoeuvre_speed(p: &VehicleParams, g: &Goal) -> f32 {
    let v = (p.omega_max * p.r_min).at_most((p.normal_accel_max * p.r_min).sqrt());
    g.speed.at_most(SPEED_FACTOR * v)
}

/// The path radius of a car-like vehicle, m.
#[must_use]
pub fn path_radius(p: &VehicleParams) -> f32 {
    RHO_FACTOR * p.r_min
}

/// The straight run-in before the goal: the path ends this far before
/// it, on the line through it along β, and goes on straight, so the
/// vehicle enters the position tolerance already facing β (an arc ending
/// at the goal would enter up to `D_tol/ρ` off).
#[must_use]
pub fn runway(g: &Goal, rho: f32) -> f32 {
    g.d_tol + RUNWAY * rho
}

/// The run-in of the path followed: the one it was chosen with, or the
/// manoeuvre's own.
fn run_of(m: &Manoeuvre, g: &Goal, rho: f32) -> f32 {
    if m.run_in > 0.0 {
        m.run_in
    } else {
        runway(g, rho)
    }
}

/// Solves the path from the vehicle's pose to the start of the run-in.
/// A vehicle faster than the manoeuvre brakes along it and strays at
/// first, then solves again from where it is (planning with the radius
/// of its current speed instead made the study's paths twice as long).
/// With `simulate`, the path is followed in simulation first, and when it
/// would enter the disk askew the shortest of the [`alternatives`] that
/// enters it facing β is taken instead (module docs).
fn solve(m: &mut Manoeuvre, p: &VehicleParams, s: &VehicleState, g: &Goal, simulate: bool) {
    let rho = path_radius(p);
    let from = (s.pos.x, s.pos.y, s.theta);
    let start = g.pos - trig::unit(g.beta) * runway(g, rho);
    let to = (start.x, start.y, g.beta);
    let mut path = DubinsPath::shortest(from, to, rho)
        .unwrap_or_else(|| DubinsPath::from_segments(s.pos, s.theta, [0.0; 3], [0.0; 3]));
    let mut run_in = 0.0;
    if simulate && trial(p, *s, g, path, 0.0).is_none() {
        let mut best = f32::INFINITY;
        for (other, run) in alternatives(s, g, rho) {
            if let Some(l) = trial(p, *s, g, other, run) {
                if l < best {
                    best = l;
                    (path, run_in) = (other, run);
                }
            }
        }
    }
    m.path = path;
    m.run_in = run_in;
    m.s = 0.0;
    m.goal = g.pos;
    m.beta = g.beta;
    m.solves = m.solves.saturating_add(1);
    m.active = true;
}

/// The paths tried when the manoeuvre's own would enter askew: every
/// Dubins word (not only the shortest) of the radii [`ALT_RADII`] to a
/// run-in along β at the lateral offsets [`ALT_OFFSETS`], starting
/// [`ALT_RUN_INS`] beyond the rim, with their run-ins, m, keeping out of
/// the disk; those keeping [`ALT_MARGIN`] path radii out (at most half
/// the start's distance from the rim) first, each set shortest first; at
/// most [`ALT_TRIALS`] of them.
fn alternatives(s: &VehicleState, g: &Goal, rho: f32) -> Vec<(DubinsPath, f32)> {
    let from = (s.pos.x, s.pos.y, s.theta);
    let d0 = (s.pos - g.pos).length();
    let keep = g.d_tol + (ALT_MARGIN * rho).at_most(0.5 * (d0 - g.d_tol).at_least(0.0));
    let (along, across) = (
        trig::unit(g.beta),
        trig::unit(g.beta + core::f32::consts::FRAC_PI_2),
    );
    let mut out = Vec::new();
    for offset in ALT_OFFSETS {
        let y = offset * g.d_tol;
        let rim = (g.d_tol * g.d_tol - y * y).at_least(0.0).sqrt();
        for run in ALT_RUN_INS {
            let run = rim + run * rho;
            let start = g.pos + across * y - along * run;
            for k in ALT_RADII {
                for word in WORDS {
                    let to = (start.x, start.y, g.beta);
                    let Some(path) = DubinsPath::of_word(word, from, to, k * rho) else {
                        continue;
                    };
                    let clear = path_clearance(&path, g.pos);
                    if clear > g.d_tol {
                        out.push((clear < keep, path.length() + run, path, run));
                    }
                }
            }
        }
    }
    out.sort_by(|a, b| a.0.cmp(&b.0).then(a.1.total_cmp(&b.1)));
    out.truncate(ALT_TRIALS);
    out.into_iter()
        .map(|(_, _, path, run)| (path, run))
        .collect()
}

/// The smallest distance of `path` from `q`.
fn path_clearance(path: &DubinsPath, q: Vec2) -> f32 {
    (0..3)
        .filter(|&i| path.len[i] > 0.0)
        .map(|i| {
            let (pos, th) = path.knots[i];
            segment_distance(q, pos, th, path.kappa[i], path.len[i])
        })
        .fold(f32::INFINITY, f32::min)
}

/// Simulates following `path` and then the run-in `run_in` (0: the
/// manoeuvre's own) from `s` with the update and the committed seek step
/// a world runs: the distance driven to the first entry into the disk
/// when it faces β (within [`TRIAL_EPS_SHARE`] of `ε_tol`), `None` when
/// it enters askew or not within the trial's steps.
fn trial(
    p: &VehicleParams,
    mut s: VehicleState,
    g: &Goal,
    path: DubinsPath,
    run_in: f32,
) -> Option<f32> {
    let rho = path_radius(p);
    let vm = manoeuvre_speed(p, g);
    let mut m = Manoeuvre {
        active: true,
        path,
        run_in,
        goal: g.pos,
        beta: g.beta,
        ..Manoeuvre::default()
    };
    let far = (s.pos - g.pos).length() + core::f32::consts::TAU * rho + path.length();
    let t = 2.0 * far / vm.at_least(1e-3) + 2.0 * s.v.abs() / p.accel_max;
    let steps = ((t / p.dt) as u32).clamp(1, MAX_TRIAL_STEPS);
    let mut length = 0.0;
    for _ in 0..steps {
        if (s.pos - g.pos).length() < g.d_tol {
            return (diff(g.beta, s.theta).abs() < TRIAL_EPS_SHARE * g.eps_tol).then_some(length);
        }
        let out = step(p, &s, g, &mut m, Internals::default(), false);
        let before = s.pos;
        seek_step_committed(p, &mut s, out.gamma, out.v_dt);
        length += (s.pos - before).length();
    }
    None
}

/// Advances the arc length reached to the vehicle's projection on the path
/// (two Newton steps along the tangent), never backwards and never further
/// than the vehicle can have gone since the last update plus a margin.
fn progress(m: &mut Manoeuvre, s: &VehicleState, rho: f32, dt: f32) -> Vec2 {
    let s0 = m.s;
    let s_max = s0 + s.v * dt + 0.1 * rho;
    let mut at = s0;
    for _ in 0..2 {
        let (q, th, _) = m.path.at(at);
        at = (at + (s.pos - q).dot(trig::unit(th))).clamp(s0, s_max);
    }
    m.s = at;
    m.path.at(at).0
}

/// One update of a car-like vehicle towards an oriented goal: the
/// manoeuvre near the goal, `far` (the funnelling controller) elsewhere.
#[inline(never)]
pub fn plan(u: &mut Update<'_>, far: impl FnOnce(&mut Update<'_>) -> Internals) -> Internals {
    if u.memory.goal_moves {
        // A goal in motion is never finished by turning on the spot (the
        // tolerance phase declares End_of_Steering only inside the disk
        // facing β), and a path solved to where it is now is stale at
        // once: funnelling, led to where it will be, steers it.
        return far(u);
    }
    let p = *u.params;
    let s = *u.state;
    let g = *u.goal;
    let rho = path_radius(&p);
    let (d, bearing, alpha) = seen_from(&s, g.pos);
    let mut out = Internals {
        d,
        alpha,
        gamma: bearing,
        reachable: true,
        ..Internals::default()
    };
    if arrived(&p, &s, &g, d) {
        u.memory.position_met = true;
        u.memory.manoeuvre.active = false;
        out.mode = Mode::EndOfSteering;
        out.delta_eta = diff(g.beta, s.theta);
        out.gamma = s.theta;
        out.v_dt = if g.halting { 0.0 } else { g.speed };
        return out;
    }
    u.memory.position_met = false;
    let near = NEAR * rho + g.d_tol;
    let m = &mut u.memory.manoeuvre;
    if !m.active && d >= near && alpha.abs() < BEHIND {
        // Funnelling, no faster than braking to the manoeuvre speed by the
        // time the manoeuvre's range is reached.
        let vm = manoeuvre_speed(&p, &g);
        let cap = (vm * vm + 2.0 * 0.8 * p.accel_max * (d - near)).sqrt();
        let capped = Goal {
            speed: g.speed.at_most(cap),
            ..g
        };
        return far(&mut u.towards(&capped));
    }
    if p.v_reverse > 0.0 {
        // With a reverse gear: Reeds–Shepp paths, backing where shorter.
        let k = Pursuit {
            rho,
            speed: manoeuvre_speed(&p, &g),
            run_in: crate::funnelling::reverse::run_in(&g, rho),
            lookahead: LOOKAHEAD,
            replan: REPLAN_ERR,
        };
        return crate::funnelling::reverse::follow(&p, &s, &g, m, &k, out);
    }
    follow(&p, &s, &g, m, out)
}

/// The manoeuvre's update: solve a path when needed, then the pure-pursuit
/// heading and the speed along it.
fn follow(
    p: &VehicleParams,
    s: &VehicleState,
    g: &Goal,
    m: &mut Manoeuvre,
    out: Internals,
) -> Internals {
    step(p, s, g, m, out, true)
}

/// [`follow`]; a path solved meanwhile is chosen by simulation when
/// `simulate` (never inside a simulation).
fn step(
    p: &VehicleParams,
    s: &VehicleState,
    g: &Goal,
    m: &mut Manoeuvre,
    mut out: Internals,
    simulate: bool,
) -> Internals {
    let rho = path_radius(p);
    let moved =
        (g.pos - m.goal).length() > 0.1 * g.d_tol || diff(g.beta, m.beta).abs() > 0.1 * g.eps_tol;
    let vm = manoeuvre_speed(p, g);
    // At most one solve per update: a fresh path starts at the vehicle.
    let fresh = !m.active || moved;
    if fresh {
        solve(m, p, s, g, simulate);
    }
    let on_path = progress(m, s, rho, p.dt);
    let run = run_of(m, g, rho);
    let len = m.path.length() + run;
    let stopped = s.v < 0.05 * vm && m.s > len - 0.05 * rho;
    let strayed = (s.pos - on_path).length() > REPLAN_ERR * rho;
    if !fresh && (strayed || stopped || m.s > len + rho) {
        solve(m, p, s, g, simulate);
    }
    let run = run_of(m, g, rho);
    let (aim, _, _) = m.path.at(m.s + LOOKAHEAD * rho);
    let (_, gamma, _) = seen_from(s, aim);
    let left = (m.path.length() + run - m.s).at_least(0.0);
    // On a straight, up to the goal's speed, braking to the manoeuvre
    // speed by the next arc.
    let straight = m.path.straight_ahead(m.s).at_most(left);
    let mut v = vm.at_least(
        g.speed
            .at_most((vm * vm + 2.0 * 0.8 * p.accel_max * straight).sqrt()),
    );
    if g.halting {
        v = v.at_most(halting_speed(p, left));
    }
    out.mode = Mode::OrientationOnly;
    out.delta_eta = diff(g.beta, s.theta);
    out.gamma = gamma;
    out.v_dt = v;
    out
}
