//! Angular displacement, velocity and acceleration control with clamps, and
//! the constant-speed agent they steer (paper 004 §1, figures 101–120).
//!
//! The paper controls the *angle* of motion directly (unlike Reynolds'
//! steering force) and keeps the forward speed constant. A component
//! produces one command per step, and the [`Mode`] says which angular
//! quantity the command sets:
//!
//! - displacement: `heading = base + clamp(q, ±max_displacement)`, where
//!   `base` is the agent's initial heading ("limited within 10 degrees of
//!   the original displacement", figures 102–105);
//! - velocity: `ω = clamp(q, ±max_velocity)`, `heading += ω`
//!   (figures 106–109);
//! - acceleration: `α = clamp(q, ±max_acceleration)`,
//!   `ω = clamp(ω + α, ±max_velocity)`, `heading += ω` (figures 110–120).
//!
//! All angles are per simulation step. The clamps are hard: a trace never
//! shows a turn larger than `max_velocity` nor a change of turn larger than
//! `max_acceleration` (property-tested in `tests/wander_props.rs`).

use glam::Vec2;
use serde::{Deserialize, Serialize};

use super::error::{finite, in_range, WanderError};
use crate::base::angle;
use crate::base::trig;

/// Which angular quantity the command sets (paper §1).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Mode {
    /// The command is the heading offset from the initial heading.
    Displacement,
    /// The command is the turn per step.
    Velocity,
    /// The command is the change of turn per step.
    Acceleration,
}

/// Clamps and mode, in degrees as a user writes them.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ControlConfig {
    /// Which quantity is controlled.
    pub mode: Mode,
    /// Largest heading offset from the initial heading, degrees in
    /// `(0, 180]`; default 180 (no limit). Used in displacement mode.
    #[serde(default = "deg180")]
    pub max_displacement_deg: f32,
    /// Largest turn per step, degrees in `(0, 180]`; default 180. Used in
    /// velocity and acceleration modes.
    #[serde(default = "deg180")]
    pub max_velocity_deg: f32,
    /// Largest change of turn per step, degrees in `(0, 180]`; default 180.
    /// Used in acceleration mode.
    #[serde(default = "deg180")]
    pub max_acceleration_deg: f32,
    /// Optional discrete angle set (paper §2 "Discrete Distributions"):
    /// each command is snapped to the nearest multiple of this step
    /// (degrees, in `(0, max of the controlled quantity]`), then pulled one
    /// step towards zero if the snap overshot the clamp. With displacement
    /// ±180° and uniform commands, 90° gives {0, 90, 180, 270} with equal
    /// probability, 72° the five multiples of 72°, and so on.
    #[serde(default)]
    pub quantize_deg: Option<f32>,
}

fn deg180() -> f32 {
    180.0
}

impl ControlConfig {
    /// Checks the clamps (finite, in `(0°, 180°]`) and the quantum.
    pub fn validate(&self) -> Result<(), WanderError> {
        let clamp = |what, v: f32| -> Result<(), WanderError> {
            in_range(what, v, 0.0, 180.0)?;
            if v == 0.0 {
                return Err(WanderError::NotPositive { what, value: v });
            }
            Ok(())
        };
        clamp("control.max_displacement_deg", self.max_displacement_deg)?;
        clamp("control.max_velocity_deg", self.max_velocity_deg)?;
        clamp("control.max_acceleration_deg", self.max_acceleration_deg)?;
        if let Some(q) = self.quantize_deg {
            finite("control.quantize_deg", q)?;
            let max = self.scale_deg();
            if !(q > 0.0 && q <= max) {
                return Err(WanderError::Range(crate::base::range::RangeError {
                    field: "control.quantize_deg",
                    value: q,
                    min: 0.0,
                    max,
                }));
            }
        }
        Ok(())
    }

    /// The clamp of the controlled quantity, degrees.
    fn scale_deg(&self) -> f32 {
        match self.mode {
            Mode::Displacement => self.max_displacement_deg,
            Mode::Velocity => self.max_velocity_deg,
            Mode::Acceleration => self.max_acceleration_deg,
        }
    }
}

/// The constant-speed agent of paper §"This post only looks at steering".
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Agent {
    /// Position (world units).
    pub pos: Vec2,
    /// Heading, radians, wrapped to `(-π, π]`.
    pub heading: f32,
    /// Forward distance per step (constant).
    pub speed: f32,
}

impl Agent {
    /// Moves one step forward along the current heading.
    #[inline]
    pub fn advance(&mut self) {
        let (s, c) = trig::sin_cos(self.heading);
        self.pos += self.speed * Vec2::new(c, s);
    }
}

/// Built control stage: clamps in radians plus the angular state.
#[derive(Clone, Debug, PartialEq)]
pub struct Control {
    mode: Mode,
    max_d: f32,
    max_v: f32,
    max_a: f32,
    quantum: f32,
    base: f32,
    velocity: f32,
}

impl Control {
    /// Validates `cfg` and builds the stage for an agent starting at
    /// heading `base` (radians).
    pub fn new(cfg: &ControlConfig, base: f32) -> Result<Self, WanderError> {
        cfg.validate()?;
        Ok(Self {
            mode: cfg.mode,
            max_d: cfg.max_displacement_deg.to_radians(),
            max_v: cfg.max_velocity_deg.to_radians(),
            max_a: cfg.max_acceleration_deg.to_radians(),
            quantum: cfg.quantize_deg.map_or(0.0, f32::to_radians),
            base,
            velocity: 0.0,
        })
    }

    /// The mode.
    #[must_use]
    pub fn mode(&self) -> Mode {
        self.mode
    }

    /// The clamp of the controlled quantity (radians): what a normalised
    /// command `u ∈ [-1, 1]` is multiplied by.
    #[inline]
    #[must_use]
    pub fn scale(&self) -> f32 {
        match self.mode {
            Mode::Displacement => self.max_d,
            Mode::Velocity => self.max_v,
            Mode::Acceleration => self.max_a,
        }
    }

    /// The current angular velocity (radians per step) in velocity and
    /// acceleration modes; 0 in displacement mode.
    #[must_use]
    pub fn velocity(&self) -> f32 {
        self.velocity
    }

    /// Snaps `q` to the discrete angle set, if one is configured.
    #[inline]
    #[must_use]
    pub fn quantize(&self, q: f32) -> f32 {
        if self.quantum <= 0.0 {
            return q;
        }
        let mut s = (q / self.quantum).round() * self.quantum;
        if s.abs() > self.scale() * (1.0 + 1e-6) {
            s -= self.quantum.copysign(s);
        }
        s
    }

    /// Applies command `q` (radians; NaN is treated as 0) to the agent's
    /// heading, honouring every clamp.
    #[inline]
    pub fn apply(&mut self, agent: &mut Agent, q: f32) {
        let q = if q.is_nan() { 0.0 } else { q };
        match self.mode {
            Mode::Displacement => {
                agent.heading = angle::wrap(self.base + q.clamp(-self.max_d, self.max_d));
            }
            Mode::Velocity => {
                self.velocity = q.clamp(-self.max_v, self.max_v);
                agent.heading = angle::wrap(agent.heading + self.velocity);
            }
            Mode::Acceleration => {
                let a = q.clamp(-self.max_a, self.max_a);
                self.velocity = (self.velocity + a).clamp(-self.max_v, self.max_v);
                agent.heading = angle::wrap(agent.heading + self.velocity);
            }
        }
    }
}
