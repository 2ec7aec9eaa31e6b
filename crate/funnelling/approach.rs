//! What every funnelling update does before and after choosing *where* to
//! aim (paper 000 Figs. 4–5; paper 001 §4.1): the part the standard
//! ([`crate::funnelling::funnel`]) and the relaxed ([`crate::funnelling::relaxed`]) controllers
//! share, written once so the two never drift apart.
//!
//! An update begins ([`Approach::begin`]) by measuring the goal in the
//! vehicle frame (distance D, bearing, radial angle α), capping the desired
//! speed for final halting, and running the position-tolerance phase of
//! Fig. 5 ([`tolerance_phase`]), which may settle the update outright (for
//! a goal moving by itself it also counts the laps the vehicle goes round
//! it without entering, and each lap lowers the approach speed,
//! [`lap_speed`]). The
//! controllers then differ only in the point they aim at — the goal itself,
//! or the relaxed point of paper 001 Fig. 7 — and both end the same way: one
//! table lookup there ([`Approach::look`]: reachability and the proactive
//! speed `v_dt`), and, when an orientation correction is needed, the bounded
//! modulation μ of Fig. 4 around the aim direction ([`Approach::funnel`]).

use core::cell::Cell;
use core::ops::ControlFlow;

use glam::Vec2;

use crate::base::angle::{diff, wrap};
use crate::base::minmax::MinMax;
use crate::base::vehicle::{VehicleParams, VehicleState};
use crate::funnelling::config::{
    Aim, Deviations, FunnelConfig, OrientationOnly, Reachability, Terminal, TolerancePhase,
};
use crate::funnelling::goal::{BetaDir, FunnelMemory, Goal};
use crate::funnelling::table::lookup::{EtaTable, Lookup};
use crate::funnelling::update::{Internals, Mode, Update};

/// Speed cap for final halting: the speed from which the vehicle can
/// still brake to rest at the target with 80 % of its deceleration.
#[inline]
#[must_use]
pub fn halting_speed(p: &VehicleParams, d: f32) -> f32 {
    (2.0 * 0.8 * p.accel_max * d.at_least(0.0)).sqrt()
}

/// Distance the vehicle still travels when it brakes to rest from speed
/// `v` at full deceleration, as [`VehicleParams::integrate`] brakes: the
/// continuous `v²/(2A)` plus one step at `v` (the explicit Euler pose moves
/// with the speed of the start of each step). An upper bound for either
/// integrator, whatever the vehicle does with its heading meanwhile.
#[inline]
#[must_use]
pub fn braking_distance(p: &VehicleParams, v: f32) -> f32 {
    v * v / (2.0 * p.accel_max) + v * p.dt
}

/// Whether the goal is done: inside the position tolerance (with the
/// braking disk for a halting goal) and facing β (also at rest): a
/// car-like vehicle's manoeuvre and its reverse gear both stop on it.
pub(crate) fn arrived(p: &VehicleParams, s: &VehicleState, g: &Goal, d: f32) -> bool {
    let err = diff(g.beta, s.theta);
    if g.halting {
        d + braking_distance(p, s.v.abs()) < g.d_tol
            && err.abs() < g.eps_tol
            && wrap(err - rest_rotation(p, s.omega)).abs() < g.eps_tol
    } else {
        d < g.d_tol && err.abs() < g.eps_tol
    }
}

/// Heading change, signed, while the angular speed `omega` decays to zero
/// when the commanded heading is the current one (End_of_Steering, and the
/// braking after the last halting goal, both hold the heading): the PD
/// law reduces to `ω̇ = −Kd·ω`, clamped to `±ω̇_max`. Above `ω̇_max/Kd`
/// ω falls linearly (turning `(ω² − ω₁²)/(2ω̇_max)`), below it
/// geometrically by `1 − Kd·dt` a step (turning `ω₁/Kd`, exactly, for the
/// explicit Euler pose); half a step at ω is added as a margin for the
/// discretisation of the linear part. Constant cost.
#[inline]
#[must_use]
pub fn rest_rotation(p: &VehicleParams, omega: f32) -> f32 {
    let w = omega.abs();
    let w1 = w.at_most(p.omega_accel_max / p.kd);
    let turn = (w * w - w1 * w1) / (2.0 * p.omega_accel_max) + w1 / p.kd + 0.5 * w * p.dt;
    turn.copysign(omega)
}

/// The position-tolerance phase of paper 000 Fig. 5, shared by the
/// standard and the relaxed controllers ([`crate::funnelling::relaxed`]): latches
/// [`FunnelMemory::position_met`] from the distance `d` to the goal centre
/// and, once met, fills `out` with End_of_Steering or Orientation_only.
/// Returns true when the position tolerance is met (then `out` is final).
///
/// Halting goals: End_of_Steering promises that the vehicle
/// comes to *rest* inside both tolerances, so both tests look at the rest
/// pose, not only the current one. The position counts as met only when
/// the whole braking disk lies inside the tolerance (`d` plus
/// [`braking_distance`] below `D_tol`): from then on the vehicle only
/// brakes (Orientation_only and End_of_Steering command speed 0), so it
/// rests inside whatever it does with its heading; until then it keeps
/// approaching under the halting speed cap, coming round again if it must.
/// End_of_Steering is declared only when the current heading *and* the
/// heading at rest ([`rest_rotation`]) are within `ε_tol`; otherwise
/// Orientation_only keeps turning towards β while braking. Non-halting
/// goals keep the paper's test on the current pose.
///
/// Goals moving by themselves (linear or circular motion) are never
/// latched: the paper's sequence, position then orientation, has the
/// vehicle brake and turn inside the disk, and a moving disk walks off
/// meanwhile, so End_of_Steering would be declared outside it.
/// End_of_Steering is declared only while the vehicle is inside the disk
/// *and* faces β, so always inside both tolerances (the envelope study
/// counts it, `steer envelope`); a pass through the disk unoriented is
/// counted ([`FunnelMemory::passes`]) and the approach goes on, led to
/// where the goal will be ([`lead`]) along a runway that each pass
/// lengthens ([`Approach::aim_depth`]).
///
/// A vehicle that goes round a moving goal without entering its disk
/// counts laps ([`LapCount`](crate::funnelling::goal::LapCount),
/// [`FunnelMemory::lap`]), and each lap lowers the speed the goal is
/// approached with ([`lap_speed`]): at full speed a vehicle can orbit a
/// small moving disk for the whole time limit without entering it
/// (`diagnostics/orbits.rs` lists the moving-goal runs of a seed that never
/// enter).
#[inline]
pub fn tolerance_phase(
    p: &VehicleParams,
    s: &VehicleState,
    g: &Goal,
    mem: &mut FunnelMemory,
    d: f32,
    out: &mut Internals,
) -> bool {
    if mem.goal_moves && !mem.goal_follows_agent {
        let heading_err = diff(g.beta, s.theta);
        let inside = d < g.d_tol;
        if mem.position_met && !inside {
            mem.passes = mem.passes.saturating_add(1);
        }
        let u = mem.beta_dir.unit(g.beta);
        mem.lap.observe(s, g, u, p.min_turn_radius(g.speed), d);
        mem.position_met = inside;
        if inside && heading_err.abs() < g.eps_tol {
            out.delta_eta = heading_err;
            out.mode = Mode::EndOfSteering;
            out.gamma = s.theta;
            out.v_dt = g.speed;
            return true;
        }
        return false;
    }
    let entered = if g.halting {
        d + braking_distance(p, s.v) < g.d_tol
    } else {
        d < g.d_tol
    };
    if entered {
        mem.position_met = true;
    } else if mem.position_met && d > FunnelMemory::release_radius(p, g) {
        mem.position_met = false;
    }
    if mem.position_met {
        let heading_err = diff(g.beta, s.theta);
        out.delta_eta = heading_err;
        let oriented = heading_err.abs() < g.eps_tol
            && (!g.halting || wrap(heading_err - rest_rotation(p, s.omega)).abs() < g.eps_tol);
        if oriented && !g.halting && !mem.goal_moves && d >= g.d_tol {
            // Faces β again but has left a static disk: come back
            // (FunnelMemory's docs).
            mem.position_met = false;
            return false;
        }
        if oriented {
            out.mode = Mode::EndOfSteering;
            out.gamma = s.theta;
            out.v_dt = if g.halting { 0.0 } else { g.speed };
        } else {
            out.mode = Mode::OrientationOnly;
            out.gamma = g.beta;
            out.v_dt = 0.0;
        }
        return true;
    }
    false
}

/// The position-tolerance phase as paper 000 Fig. 5 writes it
/// ([`TolerancePhase::Fig5`]), judged on the current pose every update:
/// End_of_Steering when `d < D_tol` and `|β − θ| < ε_tol` (Fig. 5's
/// `α + η + Δη` is `β − θ` by the definition of Δη), Orientation_only when
/// `d < D_tol` only, speed 0 in both for a halting goal and the goal's
/// desired speed otherwise (End_of_Steering), 0 in Orientation_only until
/// [`Approach::begin`] applies [`FunnelConfig::orientation_only`].
/// [`FunnelMemory::position_met`] says whether the vehicle is inside now.
/// Returns true when the position tolerance is met (then `out` is final).
/// Out of line: inlined beside [`tolerance_phase`] it lengthened the
/// default update.
#[inline(never)]
pub fn fig5_tolerance_phase(
    s: &VehicleState,
    g: &Goal,
    mem: &mut FunnelMemory,
    d: f32,
    out: &mut Internals,
) -> bool {
    mem.position_met = d < g.d_tol;
    if !mem.position_met {
        return false;
    }
    let heading_err = diff(g.beta, s.theta);
    out.delta_eta = heading_err;
    if heading_err.abs() < g.eps_tol {
        out.mode = Mode::EndOfSteering;
        out.gamma = s.theta;
        out.v_dt = if g.halting { 0.0 } else { g.speed };
    } else {
        out.mode = Mode::OrientationOnly;
        out.gamma = g.beta;
        out.v_dt = 0.0;
    }
    true
}

/// The desired speed a goal moving by itself is approached with after
/// `laps` laps around it ([`FunnelMemory::lap`]): `v_d / (1 + laps/2)`,
/// not below the slower of `v_d` and the larger of 0.5 m/s (scaled with
/// the vehicle, the envelope's slowest desired speed) and twice the
/// goal's speed (a goal is never caught below its own speed).
///
/// Why: such orbits are near misses at speed. A 0.1 m disk at 1.8–2 m/s
/// is six steps wide and the vehicle turns on a 2.2–2.7 m radius; the
/// terminal pursuit brings it in along β but it can pass 1–3 cm outside
/// the disk, come round on the same wide loop and miss again, lap after
/// lap (left and right loops in turn for some), at full speed: the
/// table's proactive speed `v_dt` (paper 000 §3–4) judges a *static*
/// point reachable and never slows it. Slower, the turning radius and the
/// pursuit's carrot ([`Terminal::look`], which follows this speed)
/// shrink, the lateral offset decays over a shorter run-in, and the next
/// approach enters: the paper's proactive speed adaptation, driven by
/// what the vehicle did rather than by the table. Only goals moving by
/// themselves and only after a lap: no other trajectory depends on it.
/// `diagnostics/orbits.rs -- 1 10000` lists the
/// moving-goal runs of tune seed 1 that never enter the disk.
#[inline]
#[must_use]
pub fn lap_speed(p: &VehicleParams, g: &Goal, v_d: f32, laps: u8) -> f32 {
    if laps == 0 {
        return v_d;
    }
    let sc = crate::funnelling::table::spec::VehicleScale::of(p);
    let floor = v_d.at_most((0.5 * sc.speed).at_least(2.0 * g.vel.length()));
    (v_d / (1.0 + 0.5 * f32::from(laps))).at_least(floor)
}

/// Where to aim for a goal in motion: the goal as it will be
/// when the vehicle, going straight at speed `v`, meets it.
///
/// Why: the η table predicts the heading on reaching a *fixed* point. A
/// vehicle funnelled towards where a moving goal is now arrives where it
/// was, facing β but behind it, then chases it from the wrong side:
/// fewer moving goals are entered oriented than static ones, and some
/// are never entered. Led to the interception point, the funnel shapes the
/// approach to where the goal will be. The interception time τ solves
/// |r + v_g τ| = v τ (r the goal's offset, v_g its velocity); when the goal
/// is about as fast as the vehicle or faster, τ = D / v. The path is a
/// curve, not a line, so τ is an underestimate that shrinks to zero on
/// arrival. Constant cost: one square root; nothing for static goals.
#[inline(always)]
#[must_use]
pub fn lead(g: &Goal, s: &VehicleState, v: f32) -> Goal {
    // A static goal (most of them) costs the test alone, inlined.
    if g.vel == Vec2::ZERO {
        return *g;
    }
    lead_moving(g, s, v)
}

/// [`lead`] for a goal in motion.
#[must_use]
fn lead_moving(g: &Goal, s: &VehicleState, v: f32) -> Goal {
    let r = g.pos - s.pos;
    let v = v.at_least(0.1);
    let a = v * v - g.vel.length_squared();
    let rv = r.dot(g.vel);
    let rr = r.length_squared();
    let tau = if a > 0.01 * v * v {
        (rv + (rv * rv + a * rr).sqrt()) / a
    } else {
        rr.sqrt() / v
    };
    Goal {
        pos: g.pos + g.vel * tau,
        ..*g
    }
}

/// Distance, world bearing and radial angle α (vehicle frame) of `point`
/// seen from the vehicle (bearing = heading when on the point).
#[inline]
#[must_use]
pub fn seen_from(s: &VehicleState, point: Vec2) -> (f32, f32, f32) {
    let rel = point - s.pos;
    let d = rel.length();
    let bearing = if d > 1e-6 {
        crate::base::trig::atan2(rel.y, rel.x)
    } else {
        s.theta
    };
    (d, bearing, diff(bearing, s.theta))
}

/// One update's view of its goal, once the tolerance phase has let it
/// through: the context (table, vehicle) and what was measured.
#[derive(Clone, Copy, Debug)]
pub struct Approach<'a> {
    /// The η table.
    pub table: &'a EtaTable,
    /// The vehicle's limits.
    pub p: &'a VehicleParams,
    /// The vehicle's state at the update.
    pub s: &'a VehicleState,
    /// Distance D to the goal centre, m.
    pub d: f32,
    /// World bearing of the goal centre, rad (the heading when on it).
    pub bearing: f32,
    /// Radial angle α of the goal centre (vehicle frame), rad.
    pub alpha: f32,
    /// Desired speed after the halting cap, m/s.
    pub v_d: f32,
    /// The goal follows another agent ([`FunnelMemory::goal_follows_agent`]).
    pub follows_agent: bool,
    /// Passes through a moving goal's disk so far ([`FunnelMemory::passes`]).
    pub passes: u8,
    /// Laps around a moving goal so far ([`FunnelMemory::lap`]).
    pub laps: u8,
    /// The goal to aim at: the goal itself, or for a goal in motion where
    /// the vehicle will meet it ([`lead`]). `d`, `bearing` and `alpha`
    /// are measured to it; the tolerance phase judged the goal itself.
    pub goal: Goal,
    /// The agent's kept β direction ([`BetaDir`], in its memory).
    pub beta_dir: &'a Cell<BetaDir>,
    /// The switches between the paper's steps and ours
    /// ([`FunnelConfig::deviations`]).
    pub dev: Deviations,
}

impl<'a> Approach<'a> {
    /// Measures the goal and runs the tolerance phase `dev` names
    /// ([`FunnelConfig::tolerance`]). `Break` carries the final internals
    /// when the phase settles the update; `Continue` the approach and the
    /// internals filled so far (`d`, `alpha`, `gamma` = bearing, `v_dt` =
    /// `v_d`, reachable).
    #[inline(always)]
    pub fn begin(
        u: &'a mut Update<'_>,
        dev: Deviations,
    ) -> ControlFlow<Internals, (Self, Internals)> {
        let (table, p, g): (&'a EtaTable, &'a VehicleParams, &Goal) = (u.table, u.params, u.goal);
        let s: &'a VehicleState = &*u.state;
        let mem: &'a mut FunnelMemory = &mut *u.memory;
        let (d, bearing, alpha) = seen_from(s, g.pos);
        let latched = dev.tolerance == TolerancePhase::Latched;
        let mut v_d = g.speed;
        if g.halting && latched {
            v_d = v_d.at_most(halting_speed(p, d - 0.9 * g.d_tol));
        }
        let mut out = Internals {
            d,
            alpha,
            gamma: bearing,
            v_dt: v_d,
            reachable: true,
            ..Default::default()
        };
        let settled = if latched {
            tolerance_phase(p, s, g, mem, d, &mut out)
        } else {
            fig5_tolerance_phase(s, g, mem, d, &mut out)
        };
        if settled {
            if out.mode == Mode::OrientationOnly
                && dev.orientation_only == OrientationOnly::KeepSpeed
                && !g.halting
            {
                out.v_dt = v_d;
            }
            return ControlFlow::Break(out);
        }
        // After laps around a goal moving by itself, it is approached
        // slower (lap_speed): the speed asked of the table, the lead, the
        // runway and the terminal pursuit's carrot all follow.
        let (v_d, goal) = if mem.lap.laps > 0 {
            let v = lap_speed(p, g, v_d, mem.lap.laps);
            out.v_dt = v;
            (
                v,
                Goal {
                    speed: v,
                    ..lead(g, s, v)
                },
            )
        } else if dev.lead {
            (v_d, lead(g, s, v_d))
        } else {
            (v_d, *g)
        };
        let (d, bearing, alpha) = if goal.pos == g.pos {
            (d, bearing, alpha)
        } else {
            seen_from(s, goal.pos)
        };
        ControlFlow::Continue((
            Self {
                table,
                p,
                s,
                d,
                bearing,
                alpha,
                v_d,
                follows_agent: mem.goal_follows_agent,
                passes: mem.passes,
                laps: mem.lap.laps,
                goal,
                beta_dir: Cell::from_mut(&mut mem.beta_dir),
                dev,
            },
            out,
        ))
    }

    /// The aim to use: `configured`, except the centre for a goal that
    /// follows another agent ([`FunnelMemory::goal_follows_agent`]).
    #[inline]
    #[must_use]
    pub fn aim(&self, configured: Aim) -> Aim {
        if self.follows_agent {
            Aim::Centre
        } else {
            configured
        }
    }

    /// `(cos β, sin β)` of goal `g` ([`BetaDir`]).
    #[inline]
    #[must_use]
    pub fn beta_unit(&self, g: &Goal) -> Vec2 {
        let mut kept = self.beta_dir.get();
        let u = kept.unit(g.beta);
        self.beta_dir.set(kept);
        u
    }

    /// Distance, world bearing and radial angle α of `point` from the
    /// vehicle ([`seen_from`]).
    #[inline]
    #[must_use]
    pub fn seen(&self, point: Vec2) -> (f32, f32, f32) {
        seen_from(self.s, point)
    }

    /// The disk's *entry point*: `d_tol − r_reach` before the centre along
    /// β (`r_reach` the table's reach radius), the centre itself for disks
    /// no larger than `r_reach`. The η table predicts the heading on
    /// reaching a `r_reach` circle around the point it is asked about, so
    /// asked about this point it predicts the heading on *entering* the
    /// tolerance disk, which is what End_of_Steering and a user judge.
    #[inline]
    #[must_use]
    pub fn entry_point(&self, g: &Goal) -> Vec2 {
        g.pos - self.beta_unit(g) * self.entry_depth(g)
    }

    /// How far before the centre the entry point lies, m (0: the centre).
    #[inline]
    #[must_use]
    pub fn entry_depth(&self, g: &Goal) -> f32 {
        (g.d_tol - self.table.params().reach_radius).at_least(0.0)
    }

    /// How far before the centre to aim with the entry aim: the entry
    /// point's depth, or for a goal in motion ([`Goal::vel`]) the start
    /// of a *runway* inside the terminal pursuit's reach.
    ///
    /// Why: near a moving goal, a vehicle aimed at the disk falls in
    /// beside it and rides along, facing the goal's way instead of β, for
    /// as long as the goal moves (on the tune seed 1 of the envelope study,
    /// mostly goals with D_tol ≤ 0.25 m). A static
    /// goal stops such a vehicle: it brakes inside and turns (paper 000
    /// §5); a moving one walks off meanwhile. Aimed at the runway start,
    /// the funnel brings the vehicle onto β's line behind the goal, and
    /// the terminal pursuit ([`Terminal`]) takes it in along β; a vehicle
    /// that passes the runway start unaligned turns and comes round again.
    #[inline]
    #[must_use]
    pub fn aim_depth(&self, g: &Goal, t: Option<&Terminal>) -> f32 {
        let entry = self.entry_depth(g);
        match t {
            Some(t) if g.vel != Vec2::ZERO => {
                entry.at_least(g.d_tol + 0.75 * self.terminal_range(t) * t.look(self.p, self.s, g))
            }
            _ => entry,
        }
    }

    /// Distance, bearing and α of the entry aim's point ([`Approach::aim_depth`]
    /// before the centre along β), except at the start of the runway of a
    /// goal coming against β faster than half the approach speed, once
    /// the vehicle has gone a lap ([`FunnelMemory::lap`]): when that
    /// point is closer than the table's first ring `D_η`, the carrot on
    /// β's line one carrot distance ([`Terminal::look`]) ahead of the
    /// vehicle's projection.
    ///
    /// Why: a vehicle that reaches the runway start unaligned seeks it at
    /// close range, and a goal coming against β carries the point on
    /// nearly as fast as the vehicle can follow: seeking it, the vehicle
    /// would hover at it, turning this way and that, never facing β (on
    /// tune seed 1, a goal at 0.37 m/s and a vehicle asked for 0.5 m/s, for
    /// the whole 150 s; slowing down cannot help, the vehicle is at its
    /// floor). There the runway has done its work: pursuing the line turns
    /// the vehicle onto it, facing the goal that comes to meet it, and the
    /// terminal pursuit takes over. The two conditions keep the carrot
    /// from goals that the funnel brings round in its own time (without
    /// them, large disks of the tune seed are never finished).
    #[inline]
    #[must_use]
    pub fn seen_aim(&self, g: &Goal, t: Option<&Terminal>) -> (f32, f32, f32) {
        let depth = self.aim_depth(g, t);
        let seen = self.seen_entry(g, depth);
        match t {
            Some(t)
                if self.laps > 0
                    && seen.0 < self.table.d_eta()
                    && depth > self.entry_depth(g)
                    && g.vel.dot(self.beta_unit(g)) < -0.5 * self.v_d =>
            {
                let u = self.beta_unit(g);
                let along = (self.s.pos - g.pos).dot(u);
                self.seen(g.pos + u * (along + t.look(self.p, self.s, g)))
            }
            _ => seen,
        }
    }

    /// The terminal pursuit's range in carrot distances: `t.range`, one
    /// more per pass through a moving goal's disk ([`FunnelMemory::passes`]).
    #[inline]
    #[must_use]
    pub fn terminal_range(&self, t: &Terminal) -> f32 {
        t.range * (1.0 + f32::from(self.passes))
    }

    /// Distance, bearing and α of the point `depth` before the centre
    /// along β; the centre's, already measured, when the two coincide
    /// (then β's sin/cos is not computed).
    #[inline]
    #[must_use]
    pub fn seen_entry(&self, g: &Goal, depth: f32) -> (f32, f32, f32) {
        if depth == 0.0 {
            (self.d, self.bearing, self.alpha)
        } else {
            self.seen(g.pos - self.beta_unit(g) * depth)
        }
    }

    /// The terminal line pursuit ([`Terminal`]): when the vehicle is behind
    /// the disk (along the line through the goal along β), within
    /// `range` carrot distances of its edge, laterally within half its
    /// distance to the centre (or D_tol) and facing β within `heading`,
    /// aims at the carrot on the line and returns true (`out` is then
    /// final: Funnelling, μ the offset from the centre's bearing, Δη the
    /// heading error). Constant cost: the heading test, then (nearly
    /// facing β only) β's sin/cos and two dot products, and when it
    /// steers one atan2. The heading is tested first so that most updates
    /// skip the sin/cos, a noticeable share of an update's instructions
    /// (`diagnostics/icount.rs` counts them).
    #[inline]
    pub fn terminal(&self, t: &Terminal, g: &Goal, out: &mut Internals) -> bool {
        let s = self.s;
        let heading_err = diff(g.beta, s.theta);
        if heading_err.abs() >= t.heading {
            return false;
        }
        let u = self.beta_unit(g);
        let r = s.pos - g.pos;
        let along = r.dot(u);
        let lateral = r.perp_dot(u);
        let look = t.look(self.p, s, g);
        if along >= 0.0
            || -along - g.d_tol >= self.terminal_range(t) * look
            || lateral.abs() >= 0.5 * (-along).at_least(g.d_tol)
        {
            return false;
        }
        let (_, b, _) = self.seen(g.pos + u * (along + look));
        out.mode = Mode::Funnelling;
        out.gamma = b;
        out.mu = diff(b, self.bearing);
        out.delta_eta = heading_err;
        true
    }

    /// The desired speed as queried in the table (raised to the table's
    /// lowest sampled desired speed).
    #[inline]
    #[must_use]
    pub fn v_query(&self) -> f32 {
        self.v_d.at_least(self.table.axis(4)[0])
    }

    /// The full table lookup for an aim point at distance `dist` and radial
    /// angle `alpha`, reachability read as [`FunnelConfig::reachability`] says;
    /// fills `reachable`, `v_dt` (the proactive fallback speed when
    /// unreachable) and `eta` in `out`.
    #[inline(always)]
    pub fn look(&self, dist: f32, alpha: f32, out: &mut Internals) -> Lookup {
        let s = self.s;
        let lk = match self.dev.reachability {
            Reachability::Vote => self.table.lookup(dist, alpha, s.omega, s.v, self.v_query()),
            Reachability::Closest => {
                self.table
                    .lookup_closest(dist, alpha, s.omega, s.v, self.v_query())
            }
        };
        out.aim_d = dist;
        out.aim_alpha = alpha;
        out.v_query = self.v_query();
        out.reachable = lk.reachable;
        out.v_dt = if lk.reachable { self.v_d } else { lk.v_dt };
        out.eta = lk.eta;
        lk
    }

    /// Funnelling mode: the modulation μ of `out.delta_eta`, bounded at the
    /// aim point (distance `dist`, lookup `lk`), added to the world aim
    /// direction `dir` (paper 000 Fig. 4: γ = θ + α + μ).
    #[inline]
    #[must_use]
    pub fn funnel(
        &self,
        cfg: &FunnelConfig,
        lk: &Lookup,
        dist: f32,
        dir: f32,
        mut out: Internals,
    ) -> Internals {
        out.mode = Mode::Funnelling;
        out.mu_max = cfg.mu_max(self.table, self.p, lk, dist, out.delta_eta, self.s.v);
        out.mu = cfg.modulation(out.delta_eta, out.mu_max);
        out.gamma = wrap(dir + out.mu);
        out
    }
}
