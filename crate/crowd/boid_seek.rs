//! The two interchangeable seek strategies compared by paper 003 ("Seek").
//!
//! Both return a *steering* vector: the change of velocity applied in one
//! step (world units per step per step). Boids in paper 003 are
//! Processing-style point masses integrated once per frame, so force,
//! acceleration and per-step velocity change are the same quantity.
//!
//! * [`Seek::Reynolds`] — `craig_reynolds_seek`: desired velocity is the
//!   direction to the target at max speed; steer = desired − velocity,
//!   limited to the boid's max force (Reynolds 1999, the paper's ref. 2).
//! * [`Seek::Parker`] — `conrad_parker_seek`: steer = (target − position)/x.
//!   The paper names its variants by the share of the way moved towards the
//!   target per step, 100 %, 10 %, 1 %, 0.1 %, so we store that share
//!   `fraction = 1/x`. Like Parker's pseudocode (the paper's ref. 4) the
//!   steer is *not* force-limited; the only bound is the boid's max speed,
//!   applied after all contributions are summed.

use glam::Vec2;
use serde::{Deserialize, Serialize};

use crate::crowd::error::{check_range, CrowdError};

/// A seek strategy (paper 003, "Seek"). JSON: `{"kind": "reynolds"}` or
/// `{"kind": "parker", "fraction": 0.1}`; any other field is rejected.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(try_from = "SeekJson", into = "SeekJson")]
pub enum Seek {
    /// Reynolds: (max-speed desired velocity − velocity), limited to max force.
    Reynolds,
    /// Parker: (target − position) × `fraction`, unlimited.
    Parker {
        /// Share of the way to the target per step, in `(0, 1]`
        /// (1 = 100 %, 0.001 = 0.1 %); the paper's `1/x`.
        fraction: f32,
    },
}

/// Wire form of [`Seek`]: serde's internally tagged enums ignore
/// `deny_unknown_fields` on unit variants (`{"kind": "reynolds",
/// "fraction": 1}` would load silently), so we check by hand.
#[derive(Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct SeekJson {
    kind: SeekKind,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    fraction: Option<f32>,
}

#[derive(Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
enum SeekKind {
    Reynolds,
    Parker,
}

impl TryFrom<SeekJson> for Seek {
    type Error = String;
    fn try_from(j: SeekJson) -> Result<Self, String> {
        match (j.kind, j.fraction) {
            (SeekKind::Reynolds, None) => Ok(Seek::Reynolds),
            (SeekKind::Reynolds, Some(_)) => Err("reynolds seek takes no `fraction`".to_owned()),
            (SeekKind::Parker, Some(fraction)) => Ok(Seek::Parker { fraction }),
            (SeekKind::Parker, None) => Err("parker seek needs a `fraction` in (0, 1]".to_owned()),
        }
    }
}

impl From<Seek> for SeekJson {
    fn from(s: Seek) -> Self {
        match s {
            Seek::Reynolds => SeekJson {
                kind: SeekKind::Reynolds,
                fraction: None,
            },
            Seek::Parker { fraction } => SeekJson {
                kind: SeekKind::Parker,
                fraction: Some(fraction),
            },
        }
    }
}

impl Seek {
    /// The five variants the paper tests, in its order: Reynolds, then
    /// Parker at 100 %, 10 %, 1 % and 0.1 %.
    pub const PAPER_VARIANTS: [Seek; 5] = [
        Seek::Reynolds,
        Seek::Parker { fraction: 1.0 },
        Seek::Parker { fraction: 0.1 },
        Seek::Parker { fraction: 0.01 },
        Seek::Parker { fraction: 0.001 },
    ];

    /// Checks the parameters.
    ///
    /// # Errors
    /// A Parker fraction that is NaN or outside `(0, 1]`.
    pub fn validate(&self) -> Result<(), CrowdError> {
        match *self {
            Seek::Reynolds => Ok(()),
            Seek::Parker { fraction } => {
                check_range("seek.fraction", fraction, f32::MIN_POSITIVE, 1.0)
            }
        }
    }

    /// Short label, e.g. `reynolds`, `parker 10%`, `parker 0.1%`.
    #[must_use]
    pub fn label(&self) -> String {
        match *self {
            Seek::Reynolds => "reynolds".to_owned(),
            Seek::Parker { fraction } => {
                let pct = fraction * 100.0;
                if (pct - pct.round()).abs() < 1e-3 {
                    format!("parker {}%", pct.round())
                } else {
                    format!("parker {pct}%")
                }
            }
        }
    }

    /// The steering (velocity change this step) towards `target` for a boid
    /// at `pos` moving at `vel`.
    #[inline]
    #[must_use]
    pub fn steer(
        &self,
        pos: Vec2,
        vel: Vec2,
        target: Vec2,
        max_speed: f32,
        max_force: f32,
    ) -> Vec2 {
        match *self {
            Seek::Reynolds => {
                let desired = (target - pos).normalize_or_zero() * max_speed;
                (desired - vel).clamp_length_max(max_force)
            }
            Seek::Parker { fraction } => (target - pos) * fraction,
        }
    }
}
