//! Funnelling control (paper 000 §4–5, Figs. 4 and 5; DESIGN §4–5): reach a
//! target position *with a prescribed orientation* β by modulating the
//! heading fed to the plain seek controller.
//!
//! One update (Fig. 4): D and α in the vehicle frame; η interpolated from
//! the table (with the proactive fallback speed `v_dt` where the target
//! appears unreachable); Δη = β − (θ + α + η), the error between the target
//! orientation and the predicted final direction; μ = −gain·Δη (the paper
//! has gain 1, see [`FunnelConfig::gain`]) bounded by [`MuBound`]; the
//! modulated heading γ = θ + α + μ goes to the seek controller with speed
//! `min(v_dt, A/|ω|)`, through the step that keeps its turn direction near
//! the ±π seam ([`crate::funnelling::seek::seek_step_committed`]). Constant cost, no
//! allocation. Table interpolations per update (counted in
//! [`EtaTable::lookup`]): the lookup blends once when the target is
//! reachable at the queried speed, twice when it is not (again at the
//! fallback speed v_dt), three times when no corner is reachable at v_dt
//! either (the stored fallback η's are blended), once when v_dt is 0; the
//! default μ bound ([`MuBound::TurningRadius`]) adds none, the literal
//! bounds one more (16 corners on the ω = 0 plane). So 1–3 per update by
//! default and 2–4 with the literal bound, against the paper's "in the
//! worst case two interpolations" (paper 000 §7).

use crate::base::minmax::MinMax;
use core::f32::consts::FRAC_PI_2;
use core::ops::ControlFlow;

use glam::Vec2;
use serde::{Deserialize, Serialize};

use crate::base::angle::diff;
use crate::base::vehicle::{VehicleParams, VehicleState};
use crate::funnelling::approach::{Approach, Terminal};
use crate::funnelling::seek::seek_step_committed;
use crate::funnelling::table::spec::VehicleScale;
use crate::funnelling::table::{lookup::EtaTable, lookup::Lookup};

/// The control mode chosen every step (paper 000 Fig. 5).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize, Default)]
#[serde(rename_all = "camelCase")]
#[repr(u8)]
pub enum Mode {
    /// Within both tolerances: done (brakes to rest when halting).
    EndOfSteering = 0,
    /// Within the position tolerance: turn to β regardless of position.
    OrientationOnly = 1,
    /// Plain seek: closer than `D_η`, or no orientation correction needed.
    PositionOnly = 2,
    /// Heading modulated to reach the orientation too.
    #[default]
    Funnelling = 3,
}

/// How the modulation μ = −Δη is bounded (paper 000 §4: the bound must
/// vanish as D → ∞ so that distant targets are approached like a seek).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "camelCase", tag = "kind")]
pub enum MuBound {
    /// The paper's literal reading: `|η(D, Δη, 0, v_c, v_dt)|`, the η of a
    /// target at distance D seen at angle Δη with no rotation.
    Literal,
    /// The literal bound scaled by `gain` and capped at π/2: keeps the
    /// literal shape (→ 0 as D → ∞) with more authority near the target.
    ScaledLiteral {
        /// Multiplier of the literal bound.
        gain: f32,
    },
    /// A geometric bound `atan(factor·R_min / D)` capped at π/2, where
    /// `R_min` is the minimum turning radius at the current desired speed:
    /// the lateral offset worth aiming at is a few turning radii whatever
    /// the distance, so the angle vanishes as D → ∞. One table
    /// interpolation per update only.
    TurningRadius {
        /// Multiple of the minimum turning radius.
        factor: f32,
    },
    /// A constant π/2 (for comparison: does not vanish with distance).
    Constant,
}

/// A goal: an oriented target with tolerances (paper 000 §5).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields, rename_all = "camelCase")]
pub struct Goal {
    /// Target position, m.
    pub pos: Vec2,
    /// Target orientation β, rad.
    pub beta: f32,
    /// Position tolerance `D_tol`, m (circle radius in the drawing).
    pub d_tol: f32,
    /// Orientation tolerance `ε_tol`, rad (triangle half-opening).
    pub eps_tol: f32,
    /// Desired forward speed `v_d`, m/s.
    pub speed: f32,
    /// Arrive at rest (final halting).
    pub halting: bool,
    /// The goal's velocity now, m/s: zero for a static goal, filled by
    /// [`crate::world::goals::GoalSpec::at`] for goals moving by themselves. Not
    /// part of the file format (the motion is, in the goal's spec): the
    /// controllers read it to lead the target ([`crate::approach::lead`]).
    #[serde(skip)]
    pub vel: Vec2,
}

impl Default for Goal {
    fn default() -> Self {
        Self {
            pos: Vec2::ZERO,
            beta: 0.0,
            d_tol: 0.25,
            eps_tol: 5f32.to_radians(),
            speed: 1.3,
            halting: false,
            vel: Vec2::ZERO,
        }
    }
}

impl Goal {
    /// The goal without a prescribed orientation (the seek controller,
    /// [`crate::funnelling::controller::ControllerKind::Seek`]): any heading is within an
    /// infinite ε_tol, so the tolerance phase judges the position alone.
    #[must_use]
    pub fn unoriented(&self) -> Self {
        Self {
            eps_tol: f32::INFINITY,
            ..*self
        }
    }

    /// Rejects non-finite or out-of-range goals ([`crate::base::ranges`]),
    /// a desired speed of 0 included (the agent would never move).
    ///
    /// # Errors
    /// The offending field.
    pub fn validate(&self, p: &VehicleParams) -> Result<(), crate::base::vehicle::ParamError> {
        use crate::base::ranges as r;
        r::GOAL_X.check(self.pos.x)?;
        r::GOAL_Y.check(self.pos.y)?;
        r::GOAL_BETA.check(self.beta)?;
        r::GOAL_D_TOL.check(self.d_tol)?;
        r::GOAL_EPS_TOL.check(self.eps_tol)?;
        r::GOAL_SPEED.check_at_most(self.speed, p.v_max)?;
        Ok(())
    }
}

/// Everything one update computed, for the front end and the tests.
#[derive(Clone, Copy, Debug, PartialEq, Default, Serialize, Deserialize)]
#[serde(rename_all = "camelCase")]
pub struct Internals {
    /// Mode chosen this step.
    pub mode: Mode,
    /// Distance to the target, m.
    pub d: f32,
    /// Radial angle α (target bearing in the vehicle frame), rad.
    pub alpha: f32,
    /// Interpolated η, rad (0 when not looked up).
    pub eta: f32,
    /// Δη = β − (θ + α + η), rad.
    pub delta_eta: f32,
    /// Applied modulation μ, rad.
    pub mu: f32,
    /// Bound on |μ| this step, rad.
    pub mu_max: f32,
    /// Modulated heading γ (absolute), rad.
    pub gamma: f32,
    /// Whether the table says reachable at the desired speed.
    pub reachable: bool,
    /// Desired speed used (fallback when unreachable), m/s.
    pub v_dt: f32,
    /// Where this update asked the table (the aim: goal centre, entry
    /// point or relaxed point), distance from the vehicle, m; 0 when it
    /// did not ask (tolerance phase, terminal pursuit). With `aim_alpha`
    /// and `v_query` it says which seek the η above predicts, so the
    /// predicted path can be drawn ([`crate::funnelling::ghost`]).
    #[serde(default)]
    pub aim_d: f32,
    /// Radial angle of that aim point (vehicle frame), rad.
    #[serde(default)]
    pub aim_alpha: f32,
    /// The desired speed the table was asked with, m/s (v_d after the
    /// halting cap, at least the lowest sampled desired speed).
    #[serde(default)]
    pub v_query: f32,
}

/// The default: a geometric bound of eight turning radii (each at least
/// [`FunnelConfig::min_bound_radius`]). It vanishes with distance like
/// the literal one and needs no table interpolation of its own (the
/// literal bound adds one to the lookup's one to three), which keeps a
/// funnelling update near 4× a seek step. Six radii
/// were chosen on `steer reach`'s single operating point; over the whole
/// envelope (`steer envelope`, tune seed 1) eight orient better (worst
/// ε_tol 2° cell at D ≥ 5 m: 83 % → 86 %) at a median path of 1.09×
/// Dubins; ten gained nothing more and lengthened paths (1.11×).
impl Default for MuBound {
    fn default() -> Self {
        Self::TurningRadius { factor: 8.0 }
    }
}

/// Which point the standard controller funnels towards.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize, Default)]
#[serde(rename_all = "camelCase")]
pub enum Aim {
    /// The goal centre (paper 000 literally). The η table predicts the
    /// heading on reaching the table's reach circle (0.25 m) around the
    /// point it is asked about, so for a larger D_tol the vehicle crosses
    /// the tolerance circle while still turning: oriented entries fell to
    /// 29 % for D_tol 2 m (issue 13, tune seed).
    Centre,
    /// The disk's entry point along β ([`Approach::entry_point`]): the
    /// table then predicts the heading on *entering* the tolerance disk.
    #[default]
    Entry,
}

/// The funnelling controller's settings.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields, rename_all = "camelCase")]
pub struct FunnelConfig {
    /// How μ is bounded.
    pub bound: MuBound,
    /// Gain of the modulation, `μ = −gain·Δη` before the bound. Paper 000
    /// Fig. 4 reads `μ = −Δη` (gain 1). Measured (`steer reach`, 10,000
    /// random scenarios, seed 1, every other setting the default): with
    /// gain 1 the predicted error Δη decays over about 1.75 m of travel,
    /// so targets closer than ~5 m run out of room and 76.3 % of runs
    /// enter the tolerance oriented; with gain 2, 96.6 % do (length/Dubins
    /// median 1.12 vs 1.17). Default 2.
    pub gain: f32,
    /// Fraction of `ε_tol` below which |Δη| counts as "no orientation
    /// correction needed" (Position_only). Paper 000 Fig. 5 compares with
    /// `ε_tol` itself (1.0): then the funnel stops correcting as soon as
    /// the *predicted* error is just inside the tolerance, and arrivals
    /// cluster at the edge (median 4.8° for ε_tol = 5°). Default 0.25:
    /// arrivals centre on the target orientation (median ≈ 1°).
    pub seek_threshold: f32,
    /// Where to aim ([`Aim`]).
    pub aim: Aim,
    /// Smallest turning radius the [`MuBound::TurningRadius`] bound is
    /// computed with, m. The bound `atan(factor·R_min/D)` shrinks with
    /// speed: at 0.5 m/s (R_min 0.25 m) and 10 m it allowed 8.5°, too
    /// little to correct anything, and 0.5 m/s was the weakest speed of the
    /// envelope (issue 13: 65 % oriented on entry at ε_tol 5°, D ≥ 5 m).
    /// Default 1 m: 97 % (tune seed). 0 restores the plain bound.
    pub min_bound_radius: f32,
    /// The terminal line pursuit ([`Approach::terminal`]); `None`: off.
    pub terminal: Option<Terminal>,
}

impl Default for FunnelConfig {
    fn default() -> Self {
        Self {
            bound: MuBound::TurningRadius { factor: 8.0 },
            gain: 2.0,
            seek_threshold: 0.25,
            aim: Aim::Entry,
            min_bound_radius: 1.0,
            terminal: Some(Terminal::default()),
        }
    }
}

/// Per-agent memory of the mode logic: whether the position tolerance has
/// been met. Paper 000 §5 achieves position and orientation *sequentially*
/// near the target: once inside the tolerance circle the controller "does
/// not care anymore about the position" (paper 001 §4.1). A forward-only
/// vehicle entering at speed cannot stop inside a small circle, so the
/// fact is latched until the target is farther than
/// [`FunnelMemory::release_radius`] (a moving target can walk away).
///
/// A *static* goal that is not halting gets one more rule (issue 13): when
/// the vehicle, having braked and turned, faces β again but has left the
/// disk, the fact is forgotten and the goal approached again, so
/// End_of_Steering always finds both tolerances met (tune seed 1: 97.9 %
/// → 100 % of declarations, every run still finishes). A goal following
/// an agent keeps the latch; a goal moving by itself is never latched
/// ([`crate::approach::tolerance_phase`]): `position_met` then says
/// whether the vehicle is inside its disk now, and the laps the vehicle
/// goes round it without entering are counted (`lap`, issue 13), each lowering the approach speed
/// ([`crate::approach::lap_speed`]).
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct FunnelMemory {
    /// The position tolerance has been met.
    pub position_met: bool,
    /// The goal moves (in motion or following an agent): a static goal's
    /// re-approach rule does not apply. Set once when the goal becomes current
    /// ([`crate::world::goals::GoalSpec::fresh_memory`]).
    #[serde(default)]
    pub goal_moves: bool,
    /// The goal follows another agent: it is aimed at its centre, as in
    /// the paper. Its entry point moves with the agent it follows, and two
    /// agents aiming at each other's entry points (paper 000 Fig. 6, face
    /// to face) fell into step side by side and chased each other for ever.
    #[serde(default)]
    pub goal_follows_agent: bool,
    /// A goal moving by itself: how often the vehicle has passed through
    /// its disk without facing β. Each pass lengthens the runway
    /// ([`crate::approach::Approach::aim_depth`]).
    #[serde(default)]
    pub passes: u8,
    /// A goal moving by itself: the laps the vehicle has gone round it
    /// without entering its disk, and what counts them
    /// ([`crate::funnelling::approach::LapCount`]). Each lap lowers the
    /// desired speed the goal is approached with
    /// ([`crate::approach::lap_speed`]).
    #[serde(default)]
    pub lap: crate::funnelling::approach::LapCount,
    /// β's unit vector, kept from one update to the next
    /// ([`crate::funnelling::approach::BetaDir`]): a cache, not part of the mode logic.
    #[serde(skip)]
    pub beta_dir: crate::funnelling::approach::BetaDir,
}

impl FunnelMemory {
    /// Distance beyond which a met position is forgotten: twice the
    /// tolerance plus the braking distance from full speed.
    #[must_use]
    pub fn release_radius(p: &VehicleParams, g: &Goal) -> f32 {
        2.0 * g.d_tol + p.v_max * p.v_max / (2.0 * p.accel_max)
    }
}

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
    /// Plain seek with these settings (paper 000 §3, Fig. 1): aim at the
    /// centre, no terminal pursuit, Position_only whatever Δη (an infinite
    /// seek threshold). The table lookup stays: it lowers the desired speed
    /// where the target appears unreachable, which is the paper's seek
    /// mode. Use it with [`Goal::unoriented`].
    #[must_use]
    pub fn plain_seek(&self) -> Self {
        Self {
            seek_threshold: f32::INFINITY,
            aim: Aim::Centre,
            terminal: None,
            ..*self
        }
    }

    /// Rejects non-finite or out-of-range settings.
    ///
    /// # Errors
    /// The offending field.
    pub fn validate(&self) -> Result<(), crate::base::vehicle::ParamError> {
        use crate::base::ranges as r;
        r::SEEK_THRESHOLD.check(self.seek_threshold)?;
        r::FUNNEL_GAIN.check(self.gain)?;
        match self.bound {
            MuBound::ScaledLiteral { gain } => r::BOUND_GAIN.check(gain)?,
            MuBound::TurningRadius { factor } => r::BOUND_FACTOR.check(factor)?,
            MuBound::Literal | MuBound::Constant => {}
        }
        Ok(())
    }

    /// The modulation `μ = −gain·Δη`, bounded by `±mu_max` (paper 000
    /// Fig. 4 with the gain of [`FunnelConfig::gain`]).
    #[inline]
    #[must_use]
    pub fn modulation(&self, delta_eta: f32, mu_max: f32) -> f32 {
        (-self.gain * delta_eta).clamp(-mu_max, mu_max)
    }

    /// The bound on |μ| at distance `d` for orientation error `delta_eta`,
    /// current speed `v`; `lk` is this update's table lookup (its desired
    /// speed `v_dt`, and for the literal bounds its position on the
    /// distance and speed axes).
    #[inline]
    #[must_use]
    pub fn mu_max(
        &self,
        table: &EtaTable,
        p: &VehicleParams,
        lk: &Lookup,
        d: f32,
        delta_eta: f32,
        v: f32,
    ) -> f32 {
        match self.bound {
            MuBound::Literal => table.straight_abs_eta_at(lk, delta_eta).unwrap_or(0.0),
            MuBound::ScaledLiteral { gain } => {
                (gain * table.straight_abs_eta_at(lk, delta_eta).unwrap_or(0.0)).at_most(FRAC_PI_2)
            }
            MuBound::TurningRadius { factor } => {
                // The floor is the pedestrian's metres, scaled with the
                // vehicle's turning radius (×1 for the pedestrian; issue 14).
                let floor = self.min_bound_radius * VehicleScale::of(p).length;
                let r = factor * p.min_turn_radius(lk.v_dt.at_least(v)).at_least(floor);
                crate::base::trig::atan2(r, d).at_most(FRAC_PI_2)
            }
            MuBound::Constant => FRAC_PI_2,
        }
    }

    /// Chooses the mode and the seek command for one step, without moving
    /// the vehicle. Returns the internals; `gamma` and `v_dt` are the
    /// heading and desired speed to feed the seek controller.
    #[must_use]
    #[inline(always)]
    pub fn plan(
        &self,
        table: &EtaTable,
        p: &VehicleParams,
        s: &VehicleState,
        g: &Goal,
        mem: &mut FunnelMemory,
    ) -> Internals {
        let (a, out) = match Approach::begin(table, p, s, g, mem) {
            ControlFlow::Break(done) => return done,
            ControlFlow::Continue(begun) => begun,
        };
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
            // least twice the goal's (issue 13, tune seed 1: 32 of 2,000
            // moving goals were ridden alongside for good, 6 with this).
            let floor = 2.0 * g.vel.length();
            out.v_dt = out
                .v_dt
                .at_most(orbit_free_speed(a.p, d, alpha).at_least(floor));
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
    pub fn step(
        &self,
        table: &EtaTable,
        p: &VehicleParams,
        s: &mut VehicleState,
        g: &Goal,
        mem: &mut FunnelMemory,
    ) -> Internals {
        let out = self.plan(table, p, s, g, mem);
        seek_step_committed(p, s, out.gamma, out.v_dt);
        out
    }
}
