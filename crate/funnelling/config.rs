//! The funnelling controller's settings (paper 000 §4, Fig. 4): the bound
//! on the modulation μ and its gain, where to aim, when no orientation
//! correction is needed, and the terminal line pursuit; the bounded
//! modulation itself.

use core::f32::consts::FRAC_PI_2;

use serde::{Deserialize, Serialize};

use crate::base::minmax::MinMax;
use crate::base::vehicle::{VehicleParams, VehicleState};
use crate::funnelling::goal::Goal;
use crate::funnelling::table::lookup::{EtaTable, Lookup};
use crate::funnelling::table::spec::VehicleScale;

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

/// The default: a geometric bound of eight turning radii (each at least
/// [`FunnelConfig::min_bound_radius`]). It vanishes with distance like
/// the literal one and needs no table interpolation of its own (the
/// literal bound adds one to the lookup's one to three), which keeps a
/// funnelling update near 4× a seek step. Eight radii are chosen over the
/// whole envelope (`steer envelope`, tune seed 1), not at `steer reach`'s
/// single operating point: six orient worse in the hardest cells (ε_tol
/// 2°, D ≥ 5 m), ten lengthen paths for no gain.
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
    /// the tolerance circle while still turning: for D_tol 2 m most
    /// entries miss ε_tol (`steer envelope`, tune seed 1).
    Centre,
    /// The disk's entry point along β
    /// ([`Approach::entry_point`](crate::funnelling::approach::Approach::entry_point)): the
    /// table then predicts the heading on *entering* the tolerance disk.
    #[default]
    Entry,
}

/// How the update reads reachability from the η table (paper 000 Fig. 4:
/// "If closest Tη element appears unreachable, get the stored desired
/// forward speed v_dt").
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize, Default)]
#[serde(rename_all = "camelCase")]
pub enum Reachability {
    /// Ours: the weighted vote of the 32 samples around the query (reachable
    /// when the reachable ones weigh at least ½), `v_dt` the blend of their
    /// stored speeds ([`EtaTable::lookup`]). The closest sample flips
    /// abruptly from one update to the next where reachability changes
    /// between two samples; the vote moves the switch to where the blend
    /// crosses ½, and `v_dt` changes continuously.
    #[default]
    Vote,
    /// The paper's closest element: the flag of the nearest sample on every
    /// axis, its stored speed as `v_dt` ([`EtaTable::lookup_closest`]).
    Closest,
}

/// What Orientation_only (paper 000 Fig. 5: inside the position tolerance,
/// turn to β "regardless of a target position") commands as speed for a
/// goal that is not halting; a halting goal brakes in either case.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize, Default)]
#[serde(rename_all = "camelCase")]
pub enum OrientationOnly {
    /// Ours: speed 0, so the vehicle turns nearly on the spot inside the
    /// disk (the unicycle of paper 000 §3 can): it cannot leave the disk
    /// while turning. Pivoting shortens paths that pass through a disk
    /// (paper 001 Figs. 10–12 compare lengths).
    #[default]
    Stop,
    /// The paper says nothing of the speed: the goal's desired speed is
    /// kept, like every other mode (the seek controller relaxes it to
    /// `min(v_d, A/|ω|)`), and the vehicle turns to β while moving on.
    KeepSpeed,
}

/// The position-tolerance phase (paper 000 Fig. 5's first two tests).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize, Default)]
#[serde(rename_all = "camelCase")]
pub enum TolerancePhase {
    /// Ours ([`crate::funnelling::approach::tolerance_phase`]): the position
    /// is latched once met (a forward-only vehicle entering at speed cannot
    /// stop in a small disk), a halting goal is judged at its rest pose and
    /// approached under a braking speed cap, a static goal left facing β is
    /// approached again, and a goal moving by itself counts passes and laps
    /// (each lap lowers the approach speed).
    #[default]
    Latched,
    /// Fig. 5 as written: every update, End_of_Steering when `D < D_tol` and
    /// `|β − θ| < ε_tol`, else Orientation_only when `D < D_tol`
    /// ([`crate::funnelling::approach::fig5_tolerance_phase`]). Nothing is
    /// remembered and no speed is capped.
    Fig5,
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
    /// speed: at 0.5 m/s (R_min 0.25 m) and 10 m the plain bound allows
    /// about 11°, too little to correct anything, which makes 0.5 m/s the
    /// weakest desired speed of the envelope. Default 1 m (chosen on the
    /// envelope study's tune seed 1); 0 gives the plain bound.
    pub min_bound_radius: f32,
    /// The terminal line pursuit
    /// ([`Approach::terminal`](crate::funnelling::approach::Approach::terminal)); `None`: off.
    pub terminal: Option<Terminal>,
    /// How reachability and `v_dt` are read from the table ([`Reachability`]).
    pub reachability: Reachability,
    /// Orientation_only's speed for a goal that is not halting ([`OrientationOnly`]).
    pub orientation_only: OrientationOnly,
    /// The position-tolerance phase ([`TolerancePhase`]).
    pub tolerance: TolerancePhase,
    /// Aim a goal in motion where the vehicle will meet it
    /// ([`crate::funnelling::approach::lead`]); the paper aims at where the
    /// target is now ("the target may be mobile without incurring
    /// additional computing cost", paper 000 §1). Default true.
    pub lead: bool,
    /// Closer than the first table ring `D_η`, cap the speed so that the
    /// turning circle passes through the target
    /// ([`crate::funnelling::funnel::orbit_free_speed`]); the paper seeks
    /// there with the table's `v_dt` of the first ring. Default true.
    pub orbit_free: bool,
    /// Near the ±π seam of the heading error keep the current turn
    /// direction ([`crate::funnelling::seek::seek_step_committed`]); the
    /// paper feeds the plain seek controller. Default true.
    pub commit_turn: bool,
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
            reachability: Deviations::OURS.reachability,
            orientation_only: Deviations::OURS.orientation_only,
            tolerance: Deviations::OURS.tolerance,
            lead: Deviations::OURS.lead,
            orbit_free: Deviations::OURS.orbit_free,
            commit_turn: true,
        }
    }
}

/// The terminal line pursuit: the last stretch before the tolerance disk,
/// steered along the goal's line instead of by the table.
///
/// Why: the η table predicts the heading on reaching a point, and close to
/// a point that prediction is ill-conditioned. Seeking a point at 0.3 m
/// with a lateral offset of 1 cm already means a heading 2° off, so at
/// ε_tol 2° a funnelled approach right to within the table's
/// interpolation error still enters the disk 2–4° off. Once the
/// vehicle is behind the disk, close to the line through the goal along β
/// and already nearly facing β, it pursues a carrot on that line one
/// `lookahead`-second of travel ahead of its projection (pure pursuit):
/// the lateral offset and the heading error decay together, and the disk
/// is entered along β. On the envelope study (tune seed 1) it lowers the
/// median entry error and lifts the worst ε_tol 2° cells at D ≥ 5 m
/// (`steer envelope --standard '{"terminal": null}'` runs without it). It replaces neither the table nor the funnel: a vehicle that is
/// not nearly lined up is funnelled as usual.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields, rename_all = "camelCase")]
pub struct Terminal {
    /// Carrot distance ahead of the projection, as seconds of travel at
    /// the current speed (at least 0.5 m/s), s.
    pub lookahead: f32,
    /// Largest heading error |β − θ| at which the stage starts, rad.
    pub heading: f32,
    /// The stage starts within this many carrot distances of the disk.
    pub range: f32,
}

impl Terminal {
    /// The carrot distance, m: `lookahead` seconds at the current speed,
    /// the goal's desired speed if higher, and at least 0.5 m/s (seconds
    /// and speed scaled with the vehicle, [`crate::funnelling::table::spec::VehicleScale`]).
    #[inline]
    #[must_use]
    pub fn look(&self, p: &VehicleParams, s: &VehicleState, g: &Goal) -> f32 {
        // Seconds and the 0.5 m/s floor are the pedestrian's, scaled with
        // the vehicle (×1 for the pedestrian).
        let sc = crate::funnelling::table::spec::VehicleScale::of(p);
        self.lookahead * sc.time() * s.v.at_least(g.speed).at_least(0.5 * sc.speed)
    }
}

impl Default for Terminal {
    fn default() -> Self {
        Self {
            lookahead: 1.0,
            heading: 0.5,
            range: 1.0,
        }
    }
}

/// The switches of [`FunnelConfig`] that choose between a step of paper
/// 000's update as written and ours and are read inside the update
/// ([`crate::funnelling::approach::Approach`]), gathered so that the
/// update can be compiled once for ours with every switch a constant
/// ([`FunnelConfig::plan`]): the default update then costs what it cost
/// before the switches existed.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Deviations {
    /// [`FunnelConfig::reachability`].
    pub reachability: Reachability,
    /// [`FunnelConfig::orientation_only`].
    pub orientation_only: OrientationOnly,
    /// [`FunnelConfig::tolerance`].
    pub tolerance: TolerancePhase,
    /// [`FunnelConfig::lead`].
    pub lead: bool,
    /// [`FunnelConfig::orbit_free`].
    pub orbit_free: bool,
}

impl Deviations {
    /// Ours, the defaults.
    pub const OURS: Self = Self {
        reachability: Reachability::Vote,
        orientation_only: OrientationOnly::Stop,
        tolerance: TolerancePhase::Latched,
        lead: true,
        orbit_free: true,
    };
}

impl FunnelConfig {
    /// The switches read inside the update.
    #[inline]
    #[must_use]
    pub fn deviations(&self) -> Deviations {
        Deviations {
            reachability: self.reachability,
            orientation_only: self.orientation_only,
            tolerance: self.tolerance,
            lead: self.lead,
            orbit_free: self.orbit_free,
        }
    }

    /// Paper 000's standard funnelling exactly as Figs. 4 and 5 write it,
    /// nothing of ours added (`docs/READINGS.md` names the reading of every
    /// garbled line): aim at the goal centre, `μ = −Δη` (gain 1) bounded by
    /// the literal `|η(D, Δη, 0, v_c, v_dt)|`, Position_only once
    /// `|Δη| < ε_tol`, reachability and `v_dt` from the closest table
    /// element, the mode chosen from the current pose every update
    /// (no latch, no halting cap), Orientation_only keeping the desired
    /// speed, no terminal pursuit, no lead of moving goals, no orbit-free
    /// speed near the target, the plain seek step.
    #[must_use]
    pub fn paper_000() -> Self {
        Self {
            bound: MuBound::Literal,
            gain: 1.0,
            seek_threshold: 1.0,
            aim: Aim::Centre,
            min_bound_radius: 0.0,
            terminal: None,
            reachability: Reachability::Closest,
            orientation_only: OrientationOnly::KeepSpeed,
            tolerance: TolerancePhase::Fig5,
            lead: false,
            orbit_free: false,
            commit_turn: false,
        }
    }

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
                // vehicle's turning radius (×1 for the pedestrian).
                let floor = self.min_bound_radius * VehicleScale::of(p).length;
                let r = factor * p.min_turn_radius(lk.v_dt.at_least(v)).at_least(floor);
                crate::base::trig::atan2(r, d).at_most(FRAC_PI_2)
            }
            MuBound::Constant => FRAC_PI_2,
        }
    }
}
