//! Funnelling control (paper 000 §4–5, Figs. 4 and 5; docs/DESIGN.md §9–10): reach a
//! target position *with a prescribed orientation* β by modulating the
//! heading fed to the plain seek controller.
//!
//! One update (Fig. 4): D and α in the vehicle frame; η interpolated from
//! the table (with the proactive fallback speed `v_dt` where the target
//! appears unreachable); Δη = β − (θ + α + η), the error between the target
//! orientation and the predicted final direction; μ = −gain·Δη (the paper
//! has gain 1, see [`FunnelConfig::gain`]) bounded by
//! [`MuBound`](crate::funnelling::config::MuBound); the
//! modulated heading γ = θ + α + μ goes to the seek controller with speed
//! `min(v_dt, A/|ω|)`, through the step that keeps its turn direction near
//! the ±π seam ([`crate::funnelling::seek::seek_step_committed`]). Constant cost, no
//! allocation. Table interpolations per update (counted in
//! [`EtaTable::lookup`](crate::funnelling::table::lookup::EtaTable::lookup)): the lookup blends once when the target is
//! reachable at the queried speed, twice when it is not (again at the
//! fallback speed v_dt), three times when no corner is reachable at v_dt
//! either (the stored fallback η's are blended), once when v_dt is 0; the
//! default μ bound ([`MuBound::TurningRadius`](crate::funnelling::config::MuBound::TurningRadius)) adds none, the literal
//! bounds one more (16 corners on the ω = 0 plane). So 1–3 per update by
//! default and 2–4 with the literal bound, against the paper's "in the
//! worst case two interpolations" (paper 000 §7).

use core::ops::ControlFlow;

use crate::base::angle::diff;
use crate::base::minmax::MinMax;
use crate::base::vehicle::{VehicleParams, VehicleState};
use crate::funnelling::approach::Approach;
use crate::funnelling::config::{Aim, Deviations, FunnelConfig};
use crate::funnelling::goal::Goal;
use crate::funnelling::seek::{seek_step, seek_step_committed};
use crate::funnelling::short_range;
use crate::funnelling::update::{Internals, Mode, Update};

/// Largest speed whose turning circle still passes through a target at
/// distance `d` and bearing `alpha`: the circle tangent to the heading
/// through the target has radius `d / (2|sin α|)`, and the vehicle turns on
/// radius `max(v/ω_max, v²/A)` at speed v.
#[inline]
#[must_use]
pub fn orbit_free_speed(p: &VehicleParams, d: f32, alpha: f32) -> f32 {
    let r = d / (2.0 * crate::base::trig::sin(alpha).abs()).at_least(1e-3);
    (p.omega_max * r).at_most((p.normal_accel_max * r).sqrt())
}

impl FunnelConfig {
    /// Chooses the mode and the seek command for one step, without moving
    /// the vehicle. Returns the internals; `gamma` and `v_dt` are the
    /// heading and desired speed to feed the seek controller.
    #[must_use]
    #[inline(always)]
    pub fn plan(&self, u: &mut Update<'_>) -> Internals {
        // Compiled twice: for ours, every switch a constant (the default
        // update pays one comparison for the switches), and for any other.
        let dev = self.deviations();
        if dev == Deviations::OURS {
            self.plan_with(u, Deviations::OURS)
        } else {
            self.plan_with(u, dev)
        }
    }

    /// [`FunnelConfig::plan`] for settings whose switches are ours
    /// ([`Deviations::OURS`], which the caller has checked once for many
    /// updates): the same update without its test of the switches.
    #[must_use]
    #[inline(always)]
    pub fn plan_ours(&self, u: &mut Update<'_>) -> Internals {
        debug_assert_eq!(self.deviations(), Deviations::OURS);
        self.plan_with(u, Deviations::OURS)
    }

    /// [`FunnelConfig::plan`] with the switches `dev`. With ours, a static
    /// goal near a unicycle is approached as [`short_range::decide`] chose
    /// at its first update: funnelling (as the paper's reading always
    /// does), funnelling slower, or turning first.
    #[inline(always)]
    fn plan_with(&self, u: &mut Update<'_>, dev: Deviations) -> Internals {
        if dev == Deviations::OURS {
            // Most updates funnel as decided (every goal farther than
            // short_range::NEAR): that is tested here, the rest is out of
            // line, so the common update carries none of it.
            let sr = u.memory.short_range;
            if !sr.decided || sr.side != 0 || sr.speed_cap > 0.0 {
                return self.plan_short_range(u);
            }
        }
        self.plan_begun(u, dev, 0)
    }

    /// [`FunnelConfig::plan_with`] with our switches, for a goal not yet
    /// decided or approached otherwise than by funnelling as it is.
    #[inline(never)]
    fn plan_short_range(&self, u: &mut Update<'_>) -> Internals {
        let dev = Deviations::OURS;
        if !u.memory.short_range.decided {
            short_range::decide(self, u);
        }
        let sr = u.memory.short_range;
        if sr.speed_cap > 0.0 {
            let slow = Goal {
                speed: u.goal.speed.at_most(sr.speed_cap),
                ..*u.goal
            };
            return self.plan_begun(&mut u.towards(&slow), dev, 0);
        }
        self.plan_begun(u, dev, sr.side)
    }

    /// The tolerance phase, then funnelling, or turning first round side
    /// `side` of the disk (0: funnelling; [`short_range::turn_first`]).
    #[inline(always)]
    fn plan_begun(&self, u: &mut Update<'_>, dev: Deviations, side: i8) -> Internals {
        let (a, out) = match Approach::begin(u, dev) {
            ControlFlow::Break(done) => return done,
            ControlFlow::Continue(begun) => begun,
        };
        if side != 0 {
            return short_range::turn_first(&a, side, out);
        }
        self.aim_and_funnel(&a, &a.goal, out)
    }

    /// What follows the tolerance phase: the terminal pursuit, else the
    /// aim point's table lookup, Δη, and Position_only or the bounded
    /// modulation. Shared with the relaxed controller's entry-point aim.
    #[must_use]
    #[inline(always)]
    pub fn aim_and_funnel(&self, a: &Approach<'_>, g: &Goal, mut out: Internals) -> Internals {
        if let Some(t) = &self.terminal {
            if a.terminal(t, g, &mut out) {
                return out;
            }
        }
        let (d, bearing, alpha) = match a.aim(self.aim) {
            Aim::Centre => (a.d, a.bearing, a.alpha),
            Aim::Entry => a.seen_aim(g, self.terminal.as_ref()),
        };
        out.gamma = bearing;
        let lk = a.look(d, alpha, &mut out);
        let final_dir = a.s.theta + alpha + lk.eta;
        out.delta_eta = diff(g.beta, final_dir);
        if d < a.table.d_eta() {
            // Closer than the first sampled ring the table cannot slow the
            // vehicle down proactively; do it geometrically instead, so a
            // near target is never orbited (paper 000 §3).
            // A moving aim point is never caught below its own speed: at
            // least twice the goal's, or the vehicle rides alongside it
            // for good.
            if a.dev.orbit_free {
                let floor = 2.0 * g.vel.length();
                out.v_dt = out
                    .v_dt
                    .at_most(orbit_free_speed(a.p, d, alpha).at_least(floor));
            }
            out.mode = Mode::PositionOnly;
            return out;
        }
        if out.delta_eta.abs() < self.seek_threshold * g.eps_tol || !lk.eta_valid {
            out.mode = Mode::PositionOnly;
            return out;
        }
        a.funnel(self, &lk, d, bearing, out)
    }

    /// One funnelling update: plan, then one seek step with the modulated
    /// heading γ and the desired speed `v_dt` (the vehicle model relaxes
    /// it to `min(v_dt, A/|ω|)`).
    pub fn step(&self, u: &mut Update<'_>) -> Internals {
        let out = self.plan(u);
        self.seek_step(u.params, u.state, out.gamma, out.v_dt);
        out
    }

    /// The seek step every controller ends with: towards heading `heading`
    /// at desired speed `speed`, with the turn commitment near the ±π seam
    /// ([`seek_step_committed`]) or without it, the plain step of paper 000
    /// §3 ([`seek_step`]), as [`FunnelConfig::commit_turn`] says.
    #[inline]
    pub fn seek_step(&self, p: &VehicleParams, s: &mut VehicleState, heading: f32, speed: f32) {
        if self.commit_turn {
            seek_step_committed(p, s, heading, speed);
        } else {
            plain_seek_step(p, s, heading, speed);
        }
    }
}

/// [`seek_step`] kept out of line: the default configuration commits the
/// turn, and the plain step inlined beside the committed one lengthened
/// the world's step.
#[cold]
#[inline(never)]
fn plain_seek_step(p: &VehicleParams, s: &mut VehicleState, heading: f32, speed: f32) {
    seek_step(p, s, heading, speed);
}
