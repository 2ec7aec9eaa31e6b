//! Timed transitions (paper 004 §5, figures 140–152).
//!
//! "Instead of changing the angular displacement (or velocity or
//! acceleration) at every time step, we can change it only every once in a
//! while": the source is sampled only when this timer fires and the last
//! command is held in between. A fixed interval gives regular motion; a
//! random interval (uniform integer in `[min, max]` steps) the more
//! interesting one. The timer fires on the first step, so a wanderer always
//! has a command.

use serde::{Deserialize, Serialize};

use super::error::{in_range_u, WanderError};
use crate::base::rng::Rng;

/// When the command may change.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case", deny_unknown_fields)]
pub enum HoldConfig {
    /// Every `every` steps (≥ 1).
    Fixed {
        /// Interval in steps.
        every: u32,
    },
    /// After a uniform random number of steps in `[min, max]` (1 ≤ min ≤ max).
    Random {
        /// Shortest interval.
        min: u32,
        /// Longest interval.
        max: u32,
    },
}

impl HoldConfig {
    /// Checks the intervals.
    pub fn validate(&self) -> Result<(), WanderError> {
        match self {
            Self::Fixed { every } => in_range_u("hold.every", *every, 1, 1 << 24),
            Self::Random { min, max } => {
                in_range_u("hold.min", *min, 1, 1 << 24)?;
                in_range_u("hold.max", *max, *min, 1 << 24)
            }
        }
    }
}

/// A built timer.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Hold {
    cfg: HoldConfig,
    remaining: u32,
}

impl Hold {
    /// Validates `cfg`; the first [`Hold::due`] returns true.
    pub fn new(cfg: &HoldConfig) -> Result<Self, WanderError> {
        cfg.validate()?;
        Ok(Self {
            cfg: cfg.clone(),
            remaining: 0,
        })
    }

    /// Whether the command changes this step (then the next interval is
    /// drawn from `rng`).
    #[inline]
    pub fn due(&mut self, rng: &mut Rng) -> bool {
        if self.remaining > 1 {
            self.remaining -= 1;
            return false;
        }
        self.remaining = match self.cfg {
            HoldConfig::Fixed { every } => every,
            HoldConfig::Random { min, max } => min + rng.below(max - min + 1),
        };
        true
    }
}
