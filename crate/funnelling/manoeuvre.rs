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
//! Cost per update is bounded: at most one Dubins solve (six closed forms)
//! and three path samples. A path is solved again only when the goal pose
//! moved, the vehicle strayed from the path by more than [`REPLAN_ERR`]
//! path radii, or it came to the end of the path without arriving;
//! [`Manoeuvre::solves`] counts the solves.

use glam::Vec2;

use crate::base::angle::diff;
use crate::base::dubins::DubinsPath;
use crate::base::minmax::MinMax;
use crate::base::trig;
use crate::base::vehicle::{VehicleParams, VehicleState};
use crate::funnelling::approach::{arrived, halting_speed, seen_from};
use crate::funnelling::goal::{Goal, Manoeuvre};
use crate::funnelling::reverse::Pursuit;
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

/// Solves the path from the vehicle's pose to the start of the run-in.
/// A vehicle faster than the manoeuvre brakes along it and strays at
/// first, then solves again from where it is (planning with the radius
/// of its current speed instead made the study's paths twice as long).
fn solve(m: &mut Manoeuvre, s: &VehicleState, g: &Goal, rho: f32) {
    let from = (s.pos.x, s.pos.y, s.theta);
    let start = g.pos - trig::unit(g.beta) * runway(g, rho);
    let to = (start.x, start.y, g.beta);
    m.path = DubinsPath::shortest(from, to, rho)
        .unwrap_or_else(|| DubinsPath::from_segments(s.pos, s.theta, [0.0; 3], [0.0; 3]));
    m.s = 0.0;
    m.goal = g.pos;
    m.beta = g.beta;
    m.solves = m.solves.saturating_add(1);
    m.active = true;
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
    follow(&p, &s, &g, m, rho, out)
}

/// The manoeuvre's update: solve a path when needed, then the pure-pursuit
/// heading and the speed along it.
fn follow(
    p: &VehicleParams,
    s: &VehicleState,
    g: &Goal,
    m: &mut Manoeuvre,
    rho: f32,
    mut out: Internals,
) -> Internals {
    let moved =
        (g.pos - m.goal).length() > 0.1 * g.d_tol || diff(g.beta, m.beta).abs() > 0.1 * g.eps_tol;
    let vm = manoeuvre_speed(p, g);
    // At most one solve per update: a fresh path starts at the vehicle.
    let fresh = !m.active || moved;
    if fresh {
        solve(m, s, g, rho);
    }
    let on_path = progress(m, s, rho, p.dt);
    let len = m.path.length() + runway(g, rho);
    let stopped = s.v < 0.05 * vm && m.s > len - 0.05 * rho;
    let strayed = (s.pos - on_path).length() > REPLAN_ERR * rho;
    if !fresh && (strayed || stopped || m.s > len + rho) {
        solve(m, s, g, rho);
    }
    let (aim, _, _) = m.path.at(m.s + LOOKAHEAD * rho);
    let (_, gamma, _) = seen_from(s, aim);
    let left = (m.path.length() + runway(g, rho) - m.s).at_least(0.0);
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
