//! Oriented arrival at short range for vehicles that can turn on the spot
//! (unicycles, [`VehicleParams::r_min`] 0; docs/DESIGN.md §10).
//!
//! The funnel corrects the predicted arrival heading by bending the path
//! (paper 000 §4), and a bend needs room: a few turning radii at the
//! desired speed. Closer than that, and from a start facing the wrong way,
//! the standard update enters the tolerance disk unoriented and finishes by
//! turning inside it (Orientation_only). A vehicle that can pivot has
//! better ways in, as a pedestrian shows: turn first where it stands, then
//! walk in; or, when it stands beside or in front of the disk, walk round
//! to behind it, turn, and walk in. Or it may still be quicker to loop,
//! which is what funnelling does, at the goal's speed or slower.
//!
//! **The choice** ([`decide`]), made once per static goal at its first
//! update, when the goal is closer than [`NEAR`] (scaled with the
//! vehicle): each way in is simulated from the vehicle's state with the
//! very update and step the world runs, to the first step inside the disk
//! (at most [`HORIZON`]): funnelling as it is, funnelling at the slow
//! speed [`SLOW`], and turning first round either side of the disk. The
//! first that enters oriented wins, the fastest among those; when none
//! does, funnelling as it is. So a goal that funnelling already enters
//! oriented and soonest is approached exactly as without this module.
//!
//! From [`NEAR`] out to [`FAR`] the funnel has room and usually enters
//! oriented: there funnelling is simulated first and kept unless it
//! enters askew within the horizon; only a goal it would enter askew (a
//! tight ε_tol with a large disk, mostly, where the bent path still
//! crosses the rim while turning) gets the other ways in, chosen as
//! above. This reach is the default funnel's only
//! ([`FunnelConfig::default`]): other settings are there to be seen
//! funnelling, and beyond [`NEAR`] are left as they are (the centre aim
//! enters a large disk askew by construction, which paper 001 Fig. 6b
//! shows; the reach study compares μ bounds and gains by their entries).
//! A goal at [`FAR`] or beyond is always approached by funnelling. Cost:
//! nothing per update but a flag; once per goal closer than [`FAR`], at
//! most four bounded simulations (beyond [`NEAR`], one when funnelling
//! does not enter askew).
//!
//! **Turning first** ([`turn_first`]). From where the vehicle stands, if
//! some heading within [`AIM_SHARE`]·ε_tol of β leads straight into the
//! disk's core ([`CORE`]·D_tol), turn to it at rest and walk in along it
//! ([`final_heading`]). Otherwise walk round the disk on the chosen side,
//! along an octagon [`CLEARANCE`] outside it, to the first corner it can
//! see on the way to the one behind the disk; every update goes to the
//! corner nearest to that one that is in sight, so the path is pulled
//! tight. The speed falls to zero as the heading error grows (a pivot at
//! each corner) and stays within braking distance of the disk. Halting and
//! pass-through goals alike: the tolerance phase
//! ([`crate::funnelling::approach::tolerance_phase`]) takes over inside
//! the disk as for every other approach.
//!
//! Goals in motion (and goals following an agent) are left to funnelling,
//! led to where they will be; car-like vehicles manoeuvre instead
//! ([`crate::funnelling::manoeuvre`]); paper 000's reading and plain seek
//! never use this module.

use glam::Vec2;

use crate::base::angle::{diff, wrap};
use crate::base::minmax::MinMax;
use crate::base::trig;
use crate::base::vehicle::{VehicleParams, VehicleState};
use crate::funnelling::approach::Approach;
use crate::funnelling::config::FunnelConfig;
use crate::funnelling::goal::{FunnelMemory, Goal, ShortRange};
use crate::funnelling::table::lookup::EtaTable;
use crate::funnelling::table::spec::VehicleScale;
use crate::funnelling::update::{Internals, Mode, Update};

/// Goals closer than this at their first update are considered, m at the
/// pedestrian's scale ([`VehicleScale::length`]): every way in competes
/// on time.
pub const NEAR: f32 = 5.0;
/// Goals from [`NEAR`] to this, m at the pedestrian's scale, are
/// considered only when funnelling would enter them askew (the module's
/// docs): at 15 m and beyond the funnel enters oriented in 99–100 % of
/// runs and keeps its figures.
pub const FAR: f32 = 15.0;
/// The slow funnelling candidate's desired speed, m/s at the pedestrian's
/// scale: the envelope's slowest.
pub const SLOW: f32 = 0.5;
/// Longest simulated approach, s at the pedestrian's time scale (beyond
/// [`NEAR`], at least three times the straight drive at the goal's speed).
pub const HORIZON: f32 = 20.0;
/// The most steps one trial may take, whatever the time step: the
/// reference vehicles' horizons stay under it (the car's, the longest,
/// 3,375 steps at 60 Hz), and a hostile time step (1e-4 s) or speed
/// cannot turn a goal's one-off choice into minutes of simulation.
pub const MAX_TRIAL_STEPS: u32 = 16_384;
/// The walk round the disk keeps this far outside it, m at the
/// pedestrian's scale, plus a quarter of D_tol.
pub const CLEARANCE: f32 = 0.3;
/// The walk in aims within this share of D_tol of the centre.
pub const CORE: f32 = 0.6;
/// The walk in's heading lies within this share of ε_tol of β.
pub const AIM_SHARE: f32 = 0.4;
/// On the walk in, the speed is zero at this share of ε_tol of heading
/// error (rising linearly to the desired speed at none): the vehicle
/// turns at rest and never enters while still turning.
pub const GO_SHARE: f32 = 0.5;
/// Round the disk, the speed is zero at this heading error, rad.
pub const WALK_ERR: f32 = 0.5;

/// What one simulated approach did ([`trial`]).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
struct Trial {
    /// Entered the disk facing β within ε_tol (or finished without entering).
    oriented: bool,
    /// Steps to that.
    steps: u32,
    /// Entered the disk facing elsewhere (not merely out of time).
    askew: bool,
}

/// Chooses how the goal of `u` is approached ([`ShortRange`]; the
/// module's docs) and keeps it in the memory. Called once per goal, at its
/// first update, by [`FunnelConfig::plan`] with our switches.
#[inline(never)]
pub fn decide(cfg: &FunnelConfig, u: &mut Update<'_>) {
    u.memory.short_range = ShortRange::restored();
    let (p, s, g) = (u.params, *u.state, *u.goal);
    if p.car_like() || u.memory.goal_moves || g.eps_tol >= core::f32::consts::PI {
        return;
    }
    let sc = VehicleScale::of(p);
    let d = (g.pos - s.pos).length();
    let near = d < NEAR * sc.length;
    if d >= FAR * sc.length || d < g.d_tol || !(near || *cfg == FunnelConfig::default()) {
        return;
    }
    // Beyond NEAR a slow goal may take longer than HORIZON to reach:
    // three times the straight drive at its speed.
    let mut t_max = HORIZON * sc.time();
    if !near {
        t_max = t_max.at_least(3.0 * d / g.speed.at_least(SLOW * sc.speed));
    }
    let horizon = ((t_max / p.dt) as u32).min(MAX_TRIAL_STEPS);
    let base = *u.memory;
    let mut best = (
        trial(cfg, u.table, p, s, &g, base, horizon),
        base.short_range,
    );
    if !near && !best.0.askew {
        return;
    }
    let slow = SLOW * sc.speed;
    let mut candidates = [
        ShortRange::chosen(0.0, 1),
        ShortRange::chosen(0.0, -1),
        ShortRange::restored(),
    ];
    if g.speed > slow {
        candidates[2] = ShortRange::chosen(slow, 0);
    }
    for c in candidates {
        if c.is_plain() {
            continue;
        }
        let max = if best.0.oriented {
            best.0.steps
        } else {
            horizon
        };
        let t = trial(
            cfg,
            u.table,
            p,
            s,
            &g,
            FunnelMemory {
                short_range: c,
                ..base
            },
            max,
        );
        if t.oriented && (!best.0.oriented || t.steps < best.0.steps) {
            best = (t, c);
        }
    }
    u.memory.short_range = best.1;
}

/// Simulates the approach `mem` says from `s` for at most `max` steps, with
/// the update and the committed seek step a world runs for one agent, to
/// the first step inside the disk.
fn trial(
    cfg: &FunnelConfig,
    table: &EtaTable,
    p: &VehicleParams,
    mut s: VehicleState,
    g: &Goal,
    mut mem: FunnelMemory,
    max: u32,
) -> Trial {
    for k in 0..max {
        let out = cfg.plan(&mut Update {
            table,
            params: p,
            state: &mut s,
            goal: g,
            memory: &mut mem,
        });
        if out.mode == Mode::EndOfSteering {
            return Trial {
                oriented: true,
                steps: k,
                askew: false,
            };
        }
        cfg.seek_step(p, &mut s, out.gamma, out.v_dt);
        if (g.pos - s.pos).length() < g.d_tol {
            let oriented = diff(g.beta, s.theta).abs() < g.eps_tol;
            return Trial {
                oriented,
                steps: k + 1,
                askew: !oriented,
            };
        }
    }
    Trial::default()
}

/// The walk round the disk's clearance: [`CLEARANCE`] (scaled) plus a
/// quarter of D_tol, m.
#[must_use]
pub fn clearance(p: &VehicleParams, g: &Goal) -> f32 {
    CLEARANCE * VehicleScale::of(p).length + 0.25 * g.d_tol
}

/// The heading of the walk in from `pos` (distance `d` to the centre of
/// goal `g`, β's unit vector `u`), if there is one: a heading within
/// [`AIM_SHARE`]·ε_tol of β whose ray passes within [`CORE`]·D_tol of the
/// centre, the nearest to β.
#[must_use]
pub fn final_heading(pos: Vec2, g: &Goal, d: f32) -> Option<f32> {
    let core = CORE * g.d_tol;
    if d <= core {
        return Some(g.beta);
    }
    let to = g.pos - pos;
    let bearing = trig::atan2(to.y, to.x);
    let half = trig::atan2(core, (d * d - core * core).at_least(0.0).sqrt());
    let h = wrap(bearing + diff(g.beta, bearing).clamp(-half, half));
    (diff(h, g.beta).abs() <= AIM_SHARE * g.eps_tol).then_some(h)
}

/// `(cos, sin)` of `k·π/4`, k = 0..8: the octagon's corners.
const CORNERS: [(f32, f32); 8] = [
    (1.0, 0.0),
    (
        core::f32::consts::FRAC_1_SQRT_2,
        core::f32::consts::FRAC_1_SQRT_2,
    ),
    (0.0, 1.0),
    (
        -core::f32::consts::FRAC_1_SQRT_2,
        core::f32::consts::FRAC_1_SQRT_2,
    ),
    (-1.0, 0.0),
    (
        -core::f32::consts::FRAC_1_SQRT_2,
        -core::f32::consts::FRAC_1_SQRT_2,
    ),
    (0.0, -1.0),
    (
        core::f32::consts::FRAC_1_SQRT_2,
        -core::f32::consts::FRAC_1_SQRT_2,
    ),
];

/// `cos(π/8)`: an octagon round a circle of radius r has its corners at
/// `r / cos(π/8)`.
const COS_PI_8: f32 = 0.923_879_5;

/// Whether the segment from `a` to `b` stays at least `r` from `c`.
fn clear(a: Vec2, b: Vec2, c: Vec2, r: f32) -> bool {
    let ab = b - a;
    let t = ((c - a).dot(ab) / ab.length_squared().at_least(1e-12)).clamp(0.0, 1.0);
    (a + ab * t - c).length() >= r
}

/// The corner to walk to round the disk on side `side` (1: left of β):
/// of the octagon's corners, ordered from the one behind the disk round
/// that side to the front and back round the other, the first in sight.
/// `None` when none is (the vehicle stands on the clearance ring between
/// two corners' lines of sight): then it steps away from the disk.
fn corner(pos: Vec2, g: &Goal, u: Vec2, side: f32, m: f32, d: f32) -> Option<Vec2> {
    let n = u.perp() * side;
    let rho = (g.d_tol + m) / COS_PI_8;
    let r_clear = (g.d_tol + 0.5 * m).at_most(0.5 * (d + g.d_tol));
    CORNERS.iter().find_map(|&(c, s)| {
        let at = g.pos + (-u * c + n * s) * rho;
        clear(pos, at, g.pos, r_clear).then_some(at)
    })
}

/// How far the vehicle can go straight ahead before it enters the disk
/// of goal `g`, m (infinite when the line misses it).
#[must_use]
pub fn room_ahead(s: &VehicleState, g: &Goal) -> f32 {
    let to = g.pos - s.pos;
    let along = to.dot(s.forward());
    let off2 = to.length_squared() - along * along;
    let r2 = g.d_tol * g.d_tol;
    if along <= 0.0 || off2 >= r2 {
        return f32::INFINITY;
    }
    (along - (r2 - off2).sqrt()).at_least(0.0)
}

/// One update of turning first (the module's docs), once the tolerance
/// phase has let it through: the heading and speed, and the mode the page
/// shows (Orientation_only while turning nearly at rest, Position_only
/// while walking).
#[must_use]
pub fn turn_first(a: &Approach<'_>, side: i8, mut out: Internals) -> Internals {
    let (p, s, g) = (a.p, a.s, &a.goal);
    let u = a.beta_unit(g);
    let d = a.d;
    let (heading, v) = if let Some(h) = final_heading(s.pos, g, d) {
        let e = diff(h, s.theta).abs();
        (h, a.v_d * (1.0 - e / (GO_SHARE * g.eps_tol)).at_least(0.0))
    } else {
        let m = clearance(p, g);
        let h = match corner(s.pos, g, u, f32::from(side), m, d) {
            Some(at) => {
                let to = at - s.pos;
                trig::atan2(to.y, to.x)
            }
            None => wrap(a.bearing + core::f32::consts::PI),
        };
        let e = diff(h, s.theta).abs();
        // Never closer to the disk, straight ahead, than the braking
        // distance: whatever the turn does meanwhile, the vehicle can stop
        // short of it.
        let room = room_ahead(s, g);
        let v = a.v_d.at_most((2.0 * 0.8 * p.accel_max * room).sqrt());
        (h, v * (1.0 - e / WALK_ERR).at_least(0.0))
    };
    out.mode = if v < 0.1 * a.v_d {
        Mode::OrientationOnly
    } else {
        Mode::PositionOnly
    };
    out.gamma = heading;
    out.mu = diff(heading, a.bearing);
    out.delta_eta = diff(g.beta, s.theta);
    out.v_dt = v;
    out
}

/// Whether entering goal `g`'s disk at a wrong heading is unavoidable
/// for a unicycle starting in state `s`: the test the short-range study
/// counts such runs by.
///
/// A vehicle that comes to rest outside the disk can always enter it
/// oriented (it turns on the spot, then walks in), so an oriented entry is
/// possible when some way of braking keeps it outside the disk or brings
/// it in facing β within ε_tol. Four ways are tried, each braking at full
/// deceleration from the first step: holding the heading, turning
/// towards β (the PD law), and turning hard left or right. When every one
/// enters the disk facing elsewhere, the entry is counted unavoidable. The
/// test is a sufficient one for possible (a subtler way of braking might
/// escape where these four do not), so it can only overcount the
/// unavoidable runs. A start inside the disk is not an entry: false.
#[must_use]
pub fn entry_unavoidable(p: &VehicleParams, s: &VehicleState, g: &Goal) -> bool {
    if (g.pos - s.pos).length() < g.d_tol {
        return false;
    }
    let hold = s.theta;
    let ways: [&dyn Fn(&VehicleState) -> f32; 4] = [
        &|x| p.kp * diff(hold, x.theta) - p.kd * x.omega,
        &|x| p.kp * diff(g.beta, x.theta) - p.kd * x.omega,
        &|_| p.omega_accel_max,
        &|_| -p.omega_accel_max,
    ];
    let max_steps = (2.0 * p.v_max / (p.accel_max * p.dt)) as u32 + 2;
    !ways.iter().any(|way| {
        let mut x = *s;
        for _ in 0..max_steps {
            if x.v == 0.0 {
                return true;
            }
            let acc = way(&x);
            p.integrate(&mut x, acc, 0.0);
            if (g.pos - x.pos).length() < g.d_tol {
                return diff(g.beta, x.theta).abs() < g.eps_tol;
            }
        }
        true
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_walk_in_heading_is_beta_behind_the_disk_and_none_in_front() {
        let g = Goal {
            pos: Vec2::ZERO,
            beta: 0.0,
            d_tol: 0.5,
            eps_tol: 10f32.to_radians(),
            ..Goal::default()
        };
        assert_eq!(final_heading(Vec2::new(-2.0, 0.1), &g, 2.0), Some(0.0));
        assert_eq!(final_heading(Vec2::new(2.0, 0.0), &g, 2.0), None);
        assert_eq!(final_heading(Vec2::new(0.0, 2.0), &g, 2.0), None);
    }

    #[test]
    fn a_start_at_rest_outside_is_never_unavoidable_and_a_fast_one_close_by_is() {
        let p = VehicleParams::default();
        let g = Goal {
            pos: Vec2::new(1.0, 0.0),
            beta: core::f32::consts::FRAC_PI_2,
            d_tol: 0.5,
            eps_tol: 5f32.to_radians(),
            ..Goal::default()
        };
        let rest = VehicleState::default();
        assert!(!entry_unavoidable(&p, &rest, &g));
        let fast = VehicleState::new(Vec2::ZERO, 0.0, 2.0, 0.0);
        assert!(entry_unavoidable(&p, &fast, &g));
    }
}
