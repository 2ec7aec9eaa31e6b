//! The controllers the envelope study compares: the standard and the
//! relaxed controller, each with the default settings and with the
//! paper's literal reading.

use crate::funnelling::config::FunnelConfig;
use crate::funnelling::controller::Controller;
use crate::funnelling::relaxed::{RelaxedAim, RelaxedConfig};

/// A controller with its settings, named for the tables.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Variant {
    /// Name in the tables and the JSON.
    pub name: &'static str,
    /// The controller.
    pub controller: Controller,
}

/// The paper's literal standard funnelling ([`FunnelConfig::paper_000`]:
/// Figs. 4 and 5 as written, nothing of ours added).
#[must_use]
pub fn literal_config() -> FunnelConfig {
    FunnelConfig::paper_000()
}

/// Paper 001 Fig. 7 as written ([`RelaxedConfig::paper_001`]): the relaxed
/// point on the ring arc 𝒜, the whole disk and T searched.
#[must_use]
pub fn literal_relaxed_config() -> RelaxedConfig {
    RelaxedConfig::paper_001()
}

/// The five variants: standard and relaxed, default and literal, and the
/// relaxed controller's paper arc with the default funnelling settings.
#[must_use]
pub fn variants() -> [Variant; 5] {
    let d = FunnelConfig::default();
    let l = literal_config();
    let r = RelaxedConfig::default();
    let rl = literal_relaxed_config();
    [
        Variant {
            name: "standard",
            controller: Controller::Standard(d),
        },
        Variant {
            name: "standard-literal",
            controller: Controller::Standard(l),
        },
        Variant {
            name: "relaxed",
            controller: Controller::Relaxed(d, r),
        },
        Variant {
            name: "relaxed-literal",
            controller: Controller::Relaxed(l, rl),
        },
        Variant {
            name: "relaxed-paper-arc",
            controller: Controller::Relaxed(
                d,
                RelaxedConfig {
                    aim: RelaxedAim::PaperArc,
                    ..r
                },
            ),
        },
    ]
}
