//! The oriented goal (paper 000 §5: a target position and orientation β
//! with tolerances D_tol and ε_tol) and what an agent remembers of its
//! current goal from one update to the next: whether the position has been
//! met (Fig. 5's sequential phases), passes and laps round a moving goal,
//! and β's kept direction.

use glam::Vec2;
use serde::{Deserialize, Serialize};

use crate::base::angle::diff;
use crate::base::dubins::DubinsPath;
use crate::base::reeds_shepp::ReedsSheppPath;
use crate::base::vehicle::{VehicleParams, VehicleState};

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
    /// controllers read it to lead the target ([`crate::funnelling::approach::lead`]).
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

/// Per-agent memory of the mode logic: whether the position tolerance has
/// been met. Paper 000 §5 achieves position and orientation *sequentially*
/// near the target: once inside the tolerance circle the controller "does
/// not care anymore about the position" (paper 001 §4.1). A forward-only
/// vehicle entering at speed cannot stop inside a small circle, so the
/// fact is latched until the target is farther than
/// [`FunnelMemory::release_radius`] (a moving target can walk away).
///
/// A *static* goal that is not halting gets one more rule: when the
/// vehicle, having braked and turned, faces β again but has left the
/// disk, the fact is forgotten and the goal approached again, so
/// End_of_Steering always finds both tolerances met. A goal following
/// an agent keeps the latch; a goal moving by itself is never latched
/// ([`crate::funnelling::approach::tolerance_phase`]): `position_met` then
/// says whether the vehicle is inside its disk now, and the laps the
/// vehicle goes round it without entering are counted (`lap`), each
/// lowering the approach speed ([`crate::funnelling::approach::lap_speed`]).
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
    /// to face) would fall into step side by side and chase each other for ever.
    #[serde(default)]
    pub goal_follows_agent: bool,
    /// A goal moving by itself: how often the vehicle has passed through
    /// its disk without facing β. Each pass lengthens the runway
    /// ([`crate::funnelling::approach::Approach::aim_depth`]).
    #[serde(default)]
    pub passes: u8,
    /// A goal moving by itself: the laps the vehicle has gone round it
    /// without entering its disk, and what counts them
    /// ([`crate::funnelling::goal::LapCount`]). Each lap lowers the
    /// desired speed the goal is approached with
    /// ([`crate::funnelling::approach::lap_speed`]).
    #[serde(default)]
    pub lap: crate::funnelling::goal::LapCount,
    /// β's unit vector, kept from one update to the next
    /// ([`crate::funnelling::goal::BetaDir`]): a cache, not part of the mode logic.
    #[serde(skip)]
    pub beta_dir: crate::funnelling::goal::BetaDir,
    /// A car-like vehicle's manoeuvre towards this goal
    /// ([`crate::funnelling::manoeuvre`]); idle for a unicycle, and then
    /// left out of the serialised memory.
    #[serde(default, skip_serializing_if = "Manoeuvre::is_idle")]
    pub manoeuvre: Manoeuvre,
    /// How this goal is approached at short range by a unicycle
    /// ([`crate::funnelling::short_range`]): funnelling, slower, or turning
    /// first. Left out of the serialised memory when funnelling, and read
    /// back as decided, so a world restored mid-approach does not choose again.
    #[serde(
        default = "ShortRange::restored",
        skip_serializing_if = "ShortRange::is_plain"
    )]
    pub short_range: ShortRange,
}

/// How a static goal near a unicycle is approached, chosen by
/// [`crate::funnelling::short_range::decide`]
/// and kept in the agent's [`FunnelMemory`].
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(default, rename_all = "camelCase")]
pub struct ShortRange {
    /// The choice has been made for this goal.
    pub decided: bool,
    /// Funnelling with the desired speed capped at this, m/s (0: uncapped).
    pub speed_cap: f32,
    /// Turning first, round the disk on the left of β (1) or the right
    /// (−1); 0: funnelling.
    pub side: i8,
}

impl ShortRange {
    /// Funnelling as without this module (whether decided or not).
    #[must_use]
    #[allow(clippy::trivially_copy_pass_by_ref)]
    pub fn is_plain(&self) -> bool {
        self.side == 0 && self.speed_cap == 0.0
    }

    /// What a memory read from a file holds when it says nothing: decided,
    /// funnelling (a world restored mid-approach does not choose again).
    #[must_use]
    pub fn restored() -> Self {
        Self {
            decided: true,
            ..Self::default()
        }
    }

    /// Decided: `speed_cap` and `side` as the fields say.
    #[must_use]
    pub fn chosen(speed_cap: f32, side: i8) -> Self {
        Self {
            decided: true,
            speed_cap,
            side,
        }
    }
}

/// What a car-like vehicle remembers of its manoeuvre
/// ([`crate::funnelling::manoeuvre`]): the Dubins path it follows, how far
/// along it is, the goal pose the path was solved for, and how many times
/// a path was solved for this goal (a deterministic count the cost tests
/// assert).
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(default, rename_all = "camelCase")]
pub struct Manoeuvre {
    /// Following the path (within reach of the goal).
    pub active: bool,
    /// The path followed.
    pub path: DubinsPath,
    /// Arc length reached along it, m.
    pub s: f32,
    /// The goal position the path ends at, m.
    pub goal: Vec2,
    /// The goal orientation it ends with, rad.
    pub beta: f32,
    /// Paths solved for this goal.
    pub solves: u32,
    /// The Reeds–Shepp path followed instead of [`Manoeuvre::path`] by a
    /// vehicle with a reverse gear ([`crate::funnelling::reverse`]).
    #[serde(skip_serializing_if = "ReedsSheppPath::is_unused")]
    pub rs: ReedsSheppPath,
    /// The straight run-in after [`Manoeuvre::path`], m, when the path
    /// was chosen by simulation with another than the manoeuvre's own
    /// (0: its own, [`crate::funnelling::manoeuvre::runway`]).
    #[serde(skip_serializing_if = "is_zero")]
    pub run_in: f32,
}

/// Serde's test of a field left out when 0.
#[allow(clippy::trivially_copy_pass_by_ref)]
fn is_zero(x: &f32) -> bool {
    *x == 0.0
}

impl Manoeuvre {
    /// Never used (a unicycle's, or a car's far from its goal so far).
    #[must_use]
    #[allow(clippy::trivially_copy_pass_by_ref)]
    pub fn is_idle(&self) -> bool {
        *self == Self::default()
    }
}

impl FunnelMemory {
    /// Distance beyond which a met position is forgotten: twice the
    /// tolerance plus the braking distance from full speed.
    #[must_use]
    pub fn release_radius(p: &VehicleParams, g: &Goal) -> f32 {
        2.0 * g.d_tol + p.v_max * p.v_max / (2.0 * p.accel_max)
    }
}

/// The laps of a vehicle circling a goal moving by itself without entering
/// its disk ([`FunnelMemory::lap`]), and what counts them. Three ways round count:
/// - a full turn of the heading, signed: the vehicle circles the goal or
///   the point it aims at;
/// - a *near miss*: the vehicle passes the goal (crosses the line through
///   its centre across β, going β's way) beside the disk, within a
///   turning radius at the desired speed: it came in along β but
///   laterally off, and must come round again;
/// - a lap's length of travel, `2π` turning radii at the desired speed
///   plus `D_tol`, without coming closer to the goal than before: the
///   vehicle hovers near the goal (or near its runway) as fast as it
///   moves, getting no closer.
///
/// Each count starts afresh after a lap, and on entering the disk. The
/// same state twice (the relaxed controller's fallback plans again)
/// counts nothing. Constant cost: a few products and one square root.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct LapCount {
    /// Laps so far.
    pub laps: u8,
    /// The heading turned (signed, rad) since the last lap was counted
    /// or the disk was last entered.
    turned: f32,
    /// The heading at the previous update, rad (`turned` adds the change).
    last_theta: f32,
    /// `last_theta` and `last_pos` hold the previous update's (false until
    /// the first update).
    started: bool,
    /// The position at the previous update, m.
    last_pos: Vec2,
    /// The least distance to the goal since the last lap, m.
    best_d: f32,
    /// The distance travelled since `best_d` last fell, m.
    travel: f32,
    /// The vehicle was ahead of the goal along β at the previous update
    /// (a near miss crosses from behind to ahead beside the disk).
    ahead: bool,
}

impl LapCount {
    /// Counts this update (vehicle `s`, goal `g` at distance `d`, β's
    /// direction `u`, turning radius at the desired speed `radius`).
    #[inline]
    pub(crate) fn observe(&mut self, s: &VehicleState, g: &Goal, u: Vec2, radius: f32, d: f32) {
        if self.started && s.pos == self.last_pos {
            return;
        }
        let r = s.pos - g.pos;
        let ahead = r.dot(u) >= 0.0;
        if d < g.d_tol || !self.started || d < self.best_d {
            self.best_d = d;
            self.travel = 0.0;
        } else {
            self.travel += (s.pos - self.last_pos).length();
        }
        if d < g.d_tol {
            self.turned = 0.0;
        } else if self.started {
            self.turned += diff(s.theta, self.last_theta);
            let missed = ahead && !self.ahead && r.perp_dot(u).abs() < g.d_tol + radius;
            let stalled = self.travel > core::f32::consts::TAU * radius + g.d_tol;
            if missed || stalled || self.turned.abs() >= core::f32::consts::TAU {
                self.laps = self.laps.saturating_add(1);
                self.turned = 0.0;
                self.travel = 0.0;
                self.best_d = d;
            }
        }
        self.ahead = ahead;
        self.last_theta = s.theta;
        self.last_pos = s.pos;
        self.started = true;
    }
}

/// The unit vector of a goal's orientation β, kept in the agent's
/// [`FunnelMemory`] from one update to the next.
///
/// Why: the entry aim and the terminal pursuit need β's direction every
/// update, and [`crate::base::trig::sin_cos`] (f64, for bits that are the
/// same natively and in wasm) is a noticeable share of a world step
/// (`diagnostics/world_bench.rs` times one). A goal's β changes only with the goal (or every step for
/// a goal that follows an agent or circles), so the vector is recomputed
/// only when β's bits differ from the kept ones: the same vector, the same
/// bits. A cache, not state: any two compare equal, and it is not
/// serialised.
#[derive(Clone, Copy, Debug)]
pub struct BetaDir {
    /// β's bits, `u32::MAX` (a NaN no valid goal has) when empty.
    beta: u32,
    dir: Vec2,
}

impl Default for BetaDir {
    fn default() -> Self {
        Self {
            beta: u32::MAX,
            dir: Vec2::NAN,
        }
    }
}

impl PartialEq for BetaDir {
    fn eq(&self, _: &Self) -> bool {
        true
    }
}

impl Eq for BetaDir {}

impl BetaDir {
    /// `(cos β, sin β)`: kept, or computed and kept.
    #[inline]
    pub fn unit(&mut self, beta: f32) -> Vec2 {
        if beta.to_bits() != self.beta {
            self.dir = crate::base::trig::unit(beta);
            self.beta = beta.to_bits();
        }
        self.dir
    }
}
