//! The vehicle model of paper 000 §3 (docs/DESIGN.md §6).
//!
//! A unicycle with unit mass and unit yaw inertia: the state is a 2D pose
//! plus speed `v` and angular speed `ω`; `v ≥ 0` (forward only, the
//! paper's) unless the vehicle has a reverse gear
//! ([`VehicleParams::v_reverse`], then `v ≥ −v_reverse`). Every limit
//! the paper names is enforced *exactly* at every step, never just
//! approached: forward speed and acceleration, angular speed and
//! acceleration, and the normal acceleration `|v·ω| ≤ A`. Controllers only
//! choose the commanded accelerations; [`VehicleParams::integrate`] clamps
//! them into the admissible set, so no controller bug can break a limit.

use crate::base::minmax::MinMax;
use core::fmt;

use glam::Vec2;
use serde::{Deserialize, Serialize};

use crate::base::range::RangeError;

/// How the pose is advanced from the speeds.
///
/// The η table must be built with the integrator the controller runs (the
/// table header records it and the loader checks it).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize, Default)]
#[serde(rename_all = "camelCase")]
pub enum Integrator {
    /// Explicit Euler, as in the paper: the pose moves with the speeds of
    /// the start of the step, then the speeds are updated.
    #[default]
    Euler,
    /// Semi-implicit (symplectic) Euler: speeds first, then the pose moves
    /// with the new speeds. Slightly less orbit-prone.
    SemiImplicitEuler,
}

impl Integrator {
    /// Stable numeric code stored in the table header.
    #[must_use]
    pub fn code(self) -> u32 {
        match self {
            Self::Euler => 0,
            Self::SemiImplicitEuler => 1,
        }
    }

    /// Inverse of [`Integrator::code`].
    #[must_use]
    pub fn from_code(c: u32) -> Option<Self> {
        match c {
            0 => Some(Self::Euler),
            1 => Some(Self::SemiImplicitEuler),
            _ => None,
        }
    }
}

/// Vehicle limits and seek-controller gains. Units: metres, seconds,
/// radians. The defaults describe a walking pedestrian (about 1.3 m/s
/// cruising, able to jog at 2 m/s, a quarter turn in about a second).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields, rename_all = "camelCase")]
pub struct VehicleParams {
    /// Fixed time step, s.
    pub dt: f32,
    /// Maximum forward speed, m/s.
    pub v_max: f32,
    /// Maximum forward acceleration and deceleration, m/s².
    pub accel_max: f32,
    /// Maximum angular speed, rad/s.
    pub omega_max: f32,
    /// Maximum angular acceleration, rad/s².
    pub omega_accel_max: f32,
    /// Maximum normal (centripetal) acceleration `A = |v·ω|`, m/s².
    pub normal_accel_max: f32,
    /// Proportional gain of the angular controller, 1/s².
    pub kp: f32,
    /// Damping gain of the angular controller, 1/s.
    pub kd: f32,
    /// Pose integrator.
    pub integrator: Integrator,
    /// Minimum turning radius `R_min`, m, holding at every speed
    /// (`|ω| ≤ v / R_min`, so no rotation at rest): a car, a cart, a boat.
    /// 0, the default, is the paper's unicycle, which may turn on the spot
    /// (and whose serialised form, table key and bytes omit the field).
    #[serde(rename = "minTurnRadius", skip_serializing_if = "is_zero")]
    pub r_min: f32,
    /// Largest reverse speed, m/s: the speed may go down to `−v_reverse`.
    /// 0, the default, drives forwards only (the paper's vehicle, whose
    /// serialised form omits the field). Only a car-like vehicle's
    /// manoeuvre ([`crate::funnelling::reverse`]) commands a negative
    /// speed; the η table is built forwards and ignores it.
    #[serde(rename = "vReverse", skip_serializing_if = "is_zero")]
    pub v_reverse: f32,
    /// What one gear change is worth in metres of path when a car-like
    /// vehicle with a reverse gear chooses among Reeds–Shepp paths (it
    /// stops at every change): 0, the default, chooses the shortest.
    #[serde(rename = "gearChangeCost", skip_serializing_if = "is_zero")]
    pub gear_cost: f32,
}

#[allow(clippy::trivially_copy_pass_by_ref)]
fn is_zero(x: &f32) -> bool {
    *x == 0.0
}

impl Default for VehicleParams {
    fn default() -> Self {
        Self {
            dt: 1.0 / 60.0,
            v_max: 2.0,
            accel_max: 1.5,
            omega_max: 2.0,
            omega_accel_max: 8.0,
            normal_accel_max: 1.5,
            kp: 12.0,
            kd: 6.0,
            integrator: Integrator::Euler,
            r_min: 0.0,
            v_reverse: 0.0,
            gear_cost: 0.0,
        }
    }
}

/// Why a parameter set, a state or a goal was refused: a field out of
/// range or not finite, in the crate's one vocabulary ([`RangeError`]), or
/// values that are each valid but make no sense together.
#[derive(Clone, Debug, PartialEq)]
pub enum ParamError {
    /// A field out of range or not finite.
    Range(RangeError),
    /// Values that are each valid but make no sense together.
    Inconsistent(&'static str),
}

impl From<RangeError> for ParamError {
    fn from(e: RangeError) -> Self {
        Self::Range(e)
    }
}

impl fmt::Display for ParamError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Range(e) => e.fmt(f),
            Self::Inconsistent(m) => f.write_str(m),
        }
    }
}

impl std::error::Error for ParamError {}

/// [`crate::base::range::check_range`] with this module's error.
pub(crate) fn check_range(
    field: &'static str,
    value: f32,
    min: f32,
    max: f32,
) -> Result<(), ParamError> {
    crate::base::range::check_range(field, value, min, max).map_err(ParamError::Range)
}

impl VehicleParams {
    /// Rejects NaN and out-of-range values (every range excludes 0; the
    /// ranges are [`crate::base::ranges`]'s) with a typed error.
    ///
    /// # Errors
    /// The first offending field.
    pub fn validate(&self) -> Result<(), ParamError> {
        use crate::base::ranges as r;
        r::DT.check(self.dt)?;
        r::V_MAX.check(self.v_max)?;
        r::ACCEL_MAX.check(self.accel_max)?;
        r::OMEGA_MAX.check(self.omega_max)?;
        r::OMEGA_ACCEL_MAX.check(self.omega_accel_max)?;
        r::NORMAL_ACCEL_MAX.check(self.normal_accel_max)?;
        r::KP.check(self.kp)?;
        r::KD.check(self.kd)?;
        r::MIN_TURN_RADIUS.check(self.r_min)?;
        r::V_REVERSE.check_at_most(self.v_reverse, self.v_max)?;
        r::GEAR_CHANGE_COST.check(self.gear_cost)?;
        Ok(())
    }

    /// True for a car-like vehicle (a minimum turning radius at every
    /// speed, [`VehicleParams::r_min`]).
    #[inline]
    #[must_use]
    pub fn car_like(&self) -> bool {
        self.r_min > 0.0
    }

    /// Largest admissible angular speed at speed `v` (either sign):
    /// `min(ω_max, A / |v|)`, and `|v| / R_min` for a car-like vehicle (the
    /// one place the curvature bound enters the limits).
    #[inline]
    #[must_use]
    pub fn omega_limit(&self, v: f32) -> f32 {
        self.omega_limit_as(self.car_like(), v)
    }

    /// True with a reverse gear ([`VehicleParams::v_reverse`] above 0).
    #[inline]
    #[must_use]
    pub fn reverse_gear(&self) -> bool {
        self.v_reverse > 0.0
    }

    /// [`VehicleParams::omega_limit`] at a speed `v` that is not negative
    /// (−0 and +0 included): the same bits. A vehicle that is not car-like
    /// skips the reverse gear's |v|, which changes nothing there (−0 and +0
    /// give the same limit); the table's lookup and the μ bound call it
    /// every update.
    #[inline(always)]
    #[must_use]
    pub fn omega_limit_ahead(&self, v: f32) -> f32 {
        if self.car_like() {
            self.omega_limit_as(true, v)
        } else if v * self.omega_max > self.normal_accel_max {
            self.normal_accel_max / v
        } else {
            self.omega_max
        }
    }

    /// [`VehicleParams::omega_limit`] with [`VehicleParams::car_like`]
    /// given, a constant where the caller knows it for many steps.
    #[inline(always)]
    fn omega_limit_as(&self, car_like: bool, v: f32) -> f32 {
        self.omega_limit_geared(car_like, true, v)
    }

    /// [`VehicleParams::omega_limit_as`], the reverse gear tested only when
    /// `geared` (false: the caller knows there is none).
    #[inline(always)]
    fn omega_limit_geared(&self, car_like: bool, geared: bool, v: f32) -> f32 {
        // Forwards only, v ≥ 0 is used as it is (the same bits as ever,
        // −0 included); backing, its magnitude.
        let v = if geared && self.reverse_gear() {
            v.abs()
        } else {
            v
        };
        let w = if v * self.omega_max > self.normal_accel_max {
            self.normal_accel_max / v
        } else {
            self.omega_max
        };
        if car_like {
            w.at_most(v.at_least(0.0) / self.r_min)
        } else {
            w
        }
    }

    /// Largest admissible forward speed at angular speed `ω`:
    /// `min(v_max, A / |ω|)`.
    #[inline]
    #[must_use]
    pub fn speed_limit(&self, omega: f32) -> f32 {
        let w = omega.abs();
        if w * self.v_max > self.normal_accel_max {
            self.normal_accel_max / w
        } else {
            self.v_max
        }
    }

    /// Minimum turning radius when cruising at `v` (m): the geometric limit
    /// used for Dubins comparisons, `v / min(ω_max, A/v)`.
    #[must_use]
    pub fn min_turn_radius(&self, v: f32) -> f32 {
        let v = v.clamp(1e-3, self.v_max);
        v / self.omega_limit_ahead(v)
    }

    /// The curvature bound of a car-like vehicle applied after the speed
    /// is chosen: the new speed `v1` must carry the new angular speed
    /// (`|ω₁| ≤ v₁ / R_min`). Braking has priority over turning (a car
    /// can stop with its wheels turned): ω₁ is lowered towards 0, but no
    /// faster than the angular acceleration allows, and where even that
    /// is not enough, v₁ is held up to `|ω| · R_min` for the smallest
    /// reachable `|ω|`. Both stay inside every other window: that `|ω|` is
    /// at most `|ω₀| ≤ v₀ / R_min` and `(|ω₀| − ω̇·dt)(|ω₀| + ω̇·dt)·R_min
    /// ≤ |ω₀|²·R_min ≤ A`, so `A / |ω₁|` is not crossed.
    ///
    /// Backing (`v₀ < 0`, or from rest `v₀ = 0` to `v₁ < 0`) the same
    /// holds for `|v₁|`: the speed stays at most `−|ω|·R_min`. A step
    /// never crosses 0 (either branch stops at it), so a gear change
    /// takes a step at rest, where `ω` is 0.
    #[inline]
    fn curvature_bound(&self, v0: f32, w0: f32, w1: f32, v1: f32) -> (f32, f32) {
        let need = (w0.abs() - self.omega_accel_max * self.dt).at_least(0.0);
        if v0 < 0.0 || (v0 == 0.0 && v1 < 0.0) {
            let v1 = v1.at_most(-need * self.r_min);
            let wl = -v1 / self.r_min;
            return (w1.clamp(-wl, wl), v1);
        }
        let v1 = v1.at_least(need * self.r_min);
        let wl = v1 / self.r_min;
        (w1.clamp(-wl, wl), v1)
    }

    /// The speeds after one step from `v0`, `w0` under the commanded
    /// angular acceleration `ang_acc` and desired speed `v_des`: (ω₁, v₁),
    /// as [`VehicleParams::integrate`] sets them. Public so that the table
    /// generator's interleaved simulations
    /// (`crate::funnelling::table::batch`) run the very same operations.
    #[inline(always)]
    #[must_use]
    pub fn new_speeds(&self, v0: f32, w0: f32, ang_acc: f32, v_des: f32) -> (f32, f32) {
        self.new_speeds_as(self.car_like(), true, v0, w0, ang_acc, v_des)
    }

    /// [`VehicleParams::new_speeds`] with [`VehicleParams::car_like`] given,
    /// and the reverse gear tested only when `geared`.
    #[inline(always)]
    fn new_speeds_as(
        &self,
        car_like: bool,
        geared: bool,
        v0: f32,
        w0: f32,
        ang_acc: f32,
        v_des: f32,
    ) -> (f32, f32) {
        let dt = self.dt;
        let a = ang_acc.clamp(-self.omega_accel_max, self.omega_accel_max);
        let wl = self.omega_limit_geared(car_like, geared, v0);
        let w1 = (w0 + a * dt).clamp(-wl, wl);
        let dv = self.accel_max * dt;
        let vcap = self.speed_limit(w1);
        // Forwards only, the floor is 0 (the same bits as ever); with a
        // reverse gear, −min(v_reverse, A/|ω₁|).
        let floor = if geared && self.reverse_gear() {
            -self.v_reverse.at_most(vcap)
        } else {
            0.0
        };
        let v1 = v_des.clamp(v0 - dv, v0 + dv).at_most(vcap).at_least(floor);
        if car_like {
            self.curvature_bound(v0, w0, w1, v1)
        } else {
            (w1, v1)
        }
    }

    /// Advances `s` by one step under the commanded angular acceleration
    /// `ang_acc` and the desired forward speed `v_des`.
    ///
    /// Angular control has priority (paper 000 §3): the new ω is the
    /// commanded one clamped to the acceleration window and to
    /// `±min(ω_max, A/v)`; then the new v tracks `v_des` within the
    /// acceleration window and `[0, min(v_max, A/|ω_new|)]`. Because the
    /// previous state satisfied `|v·ω| ≤ A`, both windows are never empty,
    /// so every limit holds exactly after every step.
    #[inline]
    pub fn integrate(&self, s: &mut VehicleState, ang_acc: f32, v_des: f32) {
        self.integrate_as(self.car_like(), true, s, ang_acc, v_des);
    }

    /// [`VehicleParams::integrate`] for a unicycle without a reverse gear
    /// (`R_min` and `v_reverse` 0, which the caller has checked once for
    /// many steps): the same operations, without the two tests for the
    /// curvature bound and the two for the reverse gear (a world's default
    /// step, [`crate::funnelling::seek::seek_step_committed_unicycle`]).
    #[inline]
    pub fn integrate_unicycle(&self, s: &mut VehicleState, ang_acc: f32, v_des: f32) {
        debug_assert!(!self.car_like() && !self.reverse_gear());
        self.integrate_as(false, false, s, ang_acc, v_des);
    }

    /// [`VehicleParams::integrate`] with [`VehicleParams::car_like`] given,
    /// and the reverse gear tested only when `geared`.
    #[inline(always)]
    fn integrate_as(
        &self,
        car_like: bool,
        geared: bool,
        s: &mut VehicleState,
        ang_acc: f32,
        v_des: f32,
    ) {
        let dt = self.dt;
        let (v0, w0) = (s.v, s.omega);
        let (w1, v1) = self.new_speeds_as(car_like, geared, v0, w0, ang_acc, v_des);
        match self.integrator {
            Integrator::Euler => {
                s.pos += crate::base::trig::unit(s.theta) * (v0 * dt);
                s.theta = crate::base::angle::wrap(s.theta + w0 * dt);
            }
            Integrator::SemiImplicitEuler => {
                s.theta = crate::base::angle::wrap(s.theta + w1 * dt);
                s.pos += crate::base::trig::unit(s.theta) * (v1 * dt);
            }
        }
        s.v = v1;
        s.omega = w1;
    }
}

/// The kinematic state of one vehicle.
#[derive(Clone, Copy, Debug, PartialEq, Default, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct VehicleState {
    /// Position, m.
    pub pos: Vec2,
    /// Heading θ, rad, wrapped to (−π, π].
    pub theta: f32,
    /// Speed along the heading, m/s (≥ 0, or ≥ −`v_reverse` backing).
    pub v: f32,
    /// Angular speed, rad/s (counter-clockwise positive).
    pub omega: f32,
}

impl VehicleState {
    /// A state at `pos` heading `theta` with speeds `v` and `omega`.
    #[must_use]
    pub fn new(pos: Vec2, theta: f32, v: f32, omega: f32) -> Self {
        Self {
            pos,
            theta,
            v,
            omega,
        }
    }

    /// Unit forward direction.
    #[inline]
    #[must_use]
    pub fn forward(&self) -> Vec2 {
        crate::base::trig::unit(self.theta)
    }

    /// True when every field is finite and the state satisfies `p`'s limits
    /// (with a small tolerance for f32 rounding).
    #[must_use]
    pub fn within_limits(&self, p: &VehicleParams) -> bool {
        let eps = 1e-4;
        self.pos.is_finite()
            && self.theta.is_finite()
            && self.v.is_finite()
            && self.omega.is_finite()
            && self.v >= -p.v_reverse
            && self.v <= p.v_max + eps
            && self.omega.abs() <= p.omega_max + eps
            && (self.v * self.omega).abs() <= p.normal_accel_max * (1.0 + eps) + eps
            && (!p.car_like() || self.omega.abs() * p.r_min <= self.v.abs() * (1.0 + eps) + eps)
    }

    /// Rejects non-finite or out-of-limit states (negative speed, speed or
    /// angular speed above the limits, normal acceleration above `A`).
    ///
    /// # Errors
    /// A [`ParamError`] naming the offending field.
    pub fn validate(&self, p: &VehicleParams) -> Result<(), ParamError> {
        use crate::base::ranges as r;
        r::POS_X.check(self.pos.x)?;
        r::POS_Y.check(self.pos.y)?;
        r::THETA.check(self.theta)?;
        if self.v < 0.0 && p.v_reverse > 0.0 {
            check_range("v (backing: -vReverse ≤ v)", self.v, -p.v_reverse, 0.0)?;
        } else {
            r::V.check_at_most(self.v, p.v_max)?;
        }
        r::OMEGA.check_at_most(self.omega, p.omega_max)?;
        if p.car_like() {
            let lim = self.v.abs() / p.r_min;
            check_range(
                "omega (curvature |ω| ≤ v / minTurnRadius)",
                self.omega,
                -lim,
                lim,
            )?;
        }
        let lim = p.omega_limit(self.v);
        check_range(
            "omega (normal acceleration |v·ω| ≤ A)",
            self.omega,
            -lim,
            lim,
        )?;
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn default_params_are_valid_and_bad_ones_are_named() {
        assert!(VehicleParams::default().validate().is_ok());
        let p = VehicleParams {
            kp: f32::NAN,
            ..Default::default()
        };
        let e = p.validate().unwrap_err();
        assert!(
            matches!(&e, ParamError::Range(r) if r.not_finite() && r.field == "kp"),
            "{e}"
        );
        assert_eq!(e.to_string(), "kp = NaN is not finite");
        let p = VehicleParams {
            v_max: -1.0,
            ..Default::default()
        };
        let e = p.validate().unwrap_err();
        assert_eq!(e.to_string(), "vMax = -1 is outside [0.01, 100]");
        let p = VehicleParams {
            dt: 1.0,
            ..Default::default()
        };
        assert!(matches!(p.validate(), Err(ParamError::Range(r)) if r.field == "dt"));
    }

    #[test]
    fn integrate_respects_every_limit_under_extreme_commands() {
        let p = VehicleParams::default();
        let mut s = VehicleState::default();
        for i in 0..10_000 {
            let prev = s;
            let a = if (i / 37) % 2 == 0 { 1e6 } else { -1e6 };
            let vd = if (i / 91) % 2 == 0 { 100.0 } else { 0.0 };
            p.integrate(&mut s, a, vd);
            assert!(s.within_limits(&p), "{s:?}");
            assert!((s.v - prev.v).abs() <= p.accel_max * p.dt * 1.0001);
            assert!((s.omega - prev.omega).abs() <= p.omega_accel_max * p.dt * 1.0001);
        }
    }

    #[test]
    fn serde_round_trip_uses_camel_case() {
        let p = VehicleParams::default();
        let j = serde_json::to_string(&p).unwrap();
        assert!(j.contains("\"vMax\""), "{j}");
        let q: VehicleParams = serde_json::from_str(&j).unwrap();
        assert_eq!(p, q);
        assert!(serde_json::from_str::<VehicleParams>("{\"vmax\": 1}").is_err());
    }
}
