//! A wander behaviour's JSON configuration (paper 004: "these can be
//! combined in various ways"): the agent, the control, the command source
//! (one of the seven components, or a mix) and the optional hold, each
//! validated before anything is built, so a gallery edit that is refused
//! comes back as a [`WanderError`] naming its field. The
//! [`pipeline`](super::pipeline) builds and runs what this describes.

use serde::{Deserialize, Serialize};

use super::control::{ControlConfig, Mode};
use super::distribution::DistributionConfig;
use super::error::{finite, in_range, in_range_u, WanderError, WORLD_LIMIT};
use super::field::FieldConfig;
use super::generated_path::{validate_lookahead, PathConfig};
use super::markov::MarkovConfig;
use super::time_fn::TimeFnConfig;
use super::timed::HoldConfig;

/// Initial pose and speed of the agent.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct AgentConfig {
    /// Start x (world units), default 0.
    #[serde(default)]
    pub x: f32,
    /// Start y, default 0.
    #[serde(default)]
    pub y: f32,
    /// Start heading, degrees, default 0 (+x). Also the `base` of
    /// displacement mode.
    #[serde(default)]
    pub heading_deg: f32,
    /// Constant forward distance per step, world units in `[0, 1e6]`
    /// (0 turns on the spot), default 2.
    #[serde(default = "speed_default")]
    pub speed: f32,
}

fn speed_default() -> f32 {
    2.0
}

impl Default for AgentConfig {
    fn default() -> Self {
        Self {
            x: 0.0,
            y: 0.0,
            heading_deg: 0.0,
            speed: speed_default(),
        }
    }
}

/// What produces the command each step.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case", deny_unknown_fields)]
pub enum SourceConfig {
    /// Random numbers from a distribution (§1, §2).
    Random {
        /// The distribution.
        distribution: DistributionConfig,
    },
    /// A random vector field (§3).
    Field {
        /// The field.
        field: FieldConfig,
    },
    /// A function of time (§4).
    TimeFunction {
        /// The function.
        function: TimeFnConfig,
    },
    /// A transition table (§6).
    Markov {
        /// The table.
        markov: MarkovConfig,
    },
    /// A generated path to follow (§7); needs velocity mode.
    Path {
        /// The generator.
        path: PathConfig,
        /// Look-ahead distance along the path (world units, > 0).
        lookahead: f32,
    },
    /// A weighted sum of other sources ("these can be combined in various
    /// ways", paper introduction), e.g. a sum of sines plus a little
    /// uniform noise, or a transition table jittered by Perlin noise.
    /// Each part's command (radians, already scaled by the clamp) is
    /// multiplied by its weight and the products are summed; the clamps
    /// apply to the sum. Parts cannot be paths or mixes.
    Mix {
        /// The parts (1–8).
        parts: Vec<MixPart>,
    },
}

/// One weighted part of a [`SourceConfig::Mix`].
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct MixPart {
    /// Weight (finite).
    pub weight: f32,
    /// The source.
    pub source: SourceConfig,
}

impl SourceConfig {
    /// Checks the source for a wanderer in `mode`; `nested` is true inside
    /// a mix.
    fn validate(&self, mode: Mode, nested: bool) -> Result<(), WanderError> {
        match self {
            Self::Random { distribution } => distribution.validate(),
            Self::Field { field } => field.validate(),
            Self::TimeFunction { function } => function.validate(),
            Self::Markov { markov } => markov.validate(),
            Self::Path { .. } if nested => Err(WanderError::NotMixable { what: "path" }),
            Self::Path { path, lookahead } => {
                if mode != Mode::Velocity {
                    return Err(WanderError::PathNeedsVelocityMode);
                }
                validate_lookahead(*lookahead)?;
                path.validate()
            }
            Self::Mix { .. } if nested => Err(WanderError::NotMixable { what: "mix" }),
            Self::Mix { parts } => {
                if parts.is_empty() {
                    return Err(WanderError::Empty { what: "mix.parts" });
                }
                if parts.len() > 8 {
                    return Err(WanderError::TooLarge {
                        what: "mix.parts",
                        value: parts.len() as u64,
                        max: 8,
                    });
                }
                for part in parts {
                    finite("mix.parts[].weight", part.weight)?;
                    part.source.validate(mode, true)?;
                }
                Ok(())
            }
        }
    }
}

/// A whole wander behaviour.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct WanderConfig {
    /// Seed of every random choice; default 0.
    #[serde(default)]
    pub seed: u64,
    /// Initial pose and speed.
    #[serde(default)]
    pub agent: AgentConfig,
    /// Mode, clamps and optional discrete set.
    pub control: ControlConfig,
    /// The command source.
    pub source: SourceConfig,
    /// Optional timed transitions.
    #[serde(default)]
    pub hold: Option<HoldConfig>,
    /// Poses kept in the trace ring buffer (1–1 000 000), default 4096.
    #[serde(default = "trace_default")]
    pub trace_capacity: u32,
}

fn trace_default() -> u32 {
    4096
}

impl WanderConfig {
    /// Parses JSON (schema errors become [`WanderError::Json`]) and
    /// validates.
    pub fn from_json(json: &str) -> Result<Self, WanderError> {
        let cfg: Self = crate::base::field_error::from_str(json)
            .map_err(|e| WanderError::Json(e.to_string()))?;
        cfg.validate()?;
        Ok(cfg)
    }

    /// Checks the whole configuration, component by component.
    pub fn validate(&self) -> Result<(), WanderError> {
        in_range("agent.x", self.agent.x, -WORLD_LIMIT, WORLD_LIMIT)?;
        in_range("agent.y", self.agent.y, -WORLD_LIMIT, WORLD_LIMIT)?;
        finite("agent.heading_deg", self.agent.heading_deg)?;
        in_range("agent.speed", self.agent.speed, 0.0, WORLD_LIMIT)?;
        self.control.validate()?;
        in_range_u("trace_capacity", self.trace_capacity, 1, 1_000_000)?;
        if let Some(h) = &self.hold {
            h.validate()?;
        }
        self.source.validate(self.control.mode, false)
    }
}
