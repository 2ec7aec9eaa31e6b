//! The choice of controller (paper 000 vs paper 001 §4): which one steers
//! the agents of a [`crate::world::World`] ([`ControllerKind`], the name
//! scenario files and the front end use) and a controller with its
//! settings ([`Controller`], what a study runs). Neither controller owns the
//! choice, so it lives beside both.

use serde::{Deserialize, Serialize};

use crate::base::vehicle::VehicleParams;
use crate::funnelling::config::{Deviations, FunnelConfig};
use crate::funnelling::relaxed::{RelaxedConfig, RelaxedInternals};
use crate::funnelling::update::{Internals, Update};

/// Which controller steers the agents of a [`crate::world::World`].
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize, Default)]
#[serde(rename_all = "camelCase")]
pub enum ControllerKind {
    /// Standard funnelling towards the disk centre and β (paper 000).
    #[default]
    Standard,
    /// Relaxed funnelling towards the region goal (paper 001 §4).
    Relaxed,
    /// Plain seek (paper 000 §3 and Fig. 1, paper 001 Fig. 1a): the goal's
    /// position only, β and ε_tol ignored, the table still lowering the
    /// desired speed where the target appears unreachable
    /// ([`FunnelConfig::plain_seek`]). Without it a seek figure had to
    /// rely on ε_tol 180°, and with the default seek threshold
    /// (0.25·ε_tol = 45°) a target behind was still funnelled towards β.
    Seek,
}

impl ControllerKind {
    /// Parses `standard`, `relaxed` or `seek`.
    #[must_use]
    pub fn parse(s: &str) -> Option<Self> {
        match s {
            "seek" => Some(Self::Seek),
            "standard" => Some(Self::Standard),
            "relaxed" => Some(Self::Relaxed),
            _ => None,
        }
    }

    /// `standard`, `relaxed` or `seek`.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Self::Standard => "standard",
            Self::Relaxed => "relaxed",
            Self::Seek => "seek",
        }
    }

    /// One update's plan with this controller (no move): what a world
    /// without avoidance and one with it both ask each agent. `ri` is
    /// written by the relaxed controller only.
    #[inline]
    pub fn plan(
        self,
        funnel: &FunnelConfig,
        relaxed: &RelaxedConfig,
        u: &mut Update<'_>,
        ri: &mut RelaxedInternals,
    ) -> Internals {
        match self {
            // A car-like vehicle manoeuvres where the unicycle would turn
            // on the spot (crate::funnelling::manoeuvre).
            Self::Standard | Self::Relaxed if u.params.car_like() => {
                crate::funnelling::manoeuvre::plan(u, |u| match self {
                    Self::Relaxed => relaxed.plan(funnel, u, ri),
                    _ => funnel.plan(u),
                })
            }
            Self::Standard => funnel.plan(u),
            Self::Seek => funnel
                .plain_seek()
                .plan(&mut u.towards(&u.goal.unoriented())),
            Self::Relaxed => relaxed.plan(funnel, u, ri),
        }
    }

    /// True for our standard controller on a unicycle without a reverse
    /// gear: [`ControllerKind::plan`] is then [`FunnelConfig::plan_ours`]
    /// and the seek step
    /// [`crate::funnelling::seek::seek_step_committed_unicycle`], which a
    /// world's step calls directly, the choice made once per step.
    #[inline]
    #[must_use]
    pub fn is_ours_unicycle(self, funnel: &FunnelConfig, p: &VehicleParams) -> bool {
        self == Self::Standard
            && !p.car_like()
            && !p.reverse_gear()
            && funnel.deviations() == Deviations::OURS
            && funnel.commit_turn
    }

    /// One update with this controller: [`ControllerKind::plan`] and the
    /// move (the committed seek step every controller ends with).
    #[inline]
    pub fn step(
        self,
        funnel: &FunnelConfig,
        relaxed: &RelaxedConfig,
        u: &mut Update<'_>,
        ri: &mut RelaxedInternals,
    ) -> Internals {
        let out = self.plan(funnel, relaxed, u, ri);
        funnel.seek_step(u.params, u.state, out.gamma, out.v_dt);
        out
    }
}

/// Which reading of the papers the settings follow: the papers' own
/// algorithms, nothing of ours added ([`FunnelConfig::paper_000`],
/// [`RelaxedConfig::paper_001`]), or ours, the defaults (what each
/// deviation does and why: `docs/READINGS.md`). Scenario files name it
/// (`"reading": "paper"`), `steer run --reading`, `steer relaxed --reading`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize, Default)]
#[serde(rename_all = "camelCase")]
pub enum Reading {
    /// Ours: the defaults.
    #[default]
    Ours,
    /// The papers' algorithms as written (paper 000 Figs. 4–5, paper 001
    /// Fig. 7).
    Paper,
}

impl Reading {
    /// Parses `ours` or `paper`.
    #[must_use]
    pub fn parse(s: &str) -> Option<Self> {
        match s {
            "ours" => Some(Self::Ours),
            "paper" => Some(Self::Paper),
            _ => None,
        }
    }

    /// `ours` or `paper`.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Self::Ours => "ours",
            Self::Paper => "paper",
        }
    }

    /// The standard controller's settings of this reading.
    #[must_use]
    pub fn funnel(self) -> FunnelConfig {
        match self {
            Self::Ours => FunnelConfig::default(),
            Self::Paper => FunnelConfig::paper_000(),
        }
    }

    /// The relaxed controller's settings of this reading.
    #[must_use]
    pub fn relaxed(self) -> RelaxedConfig {
        match self {
            Self::Ours => RelaxedConfig::default(),
            Self::Paper => RelaxedConfig::paper_001(),
        }
    }

    /// The reading `funnel` and `relaxed` are exactly, if any (the relaxed
    /// settings count only for the relaxed controller).
    #[must_use]
    pub fn of(
        kind: ControllerKind,
        funnel: &FunnelConfig,
        relaxed: &RelaxedConfig,
    ) -> Option<Self> {
        [Self::Ours, Self::Paper].into_iter().find(|r| {
            r.funnel() == *funnel && (kind != ControllerKind::Relaxed || r.relaxed() == *relaxed)
        })
    }

    /// What a user is shown for a controller with these settings:
    /// `paper 000 standard`, `paper 001 relaxed`, `paper 000 seek`, `ours
    /// standard`, `ours relaxed`, `ours seek`, or `custom …` when the
    /// settings are neither reading's.
    #[must_use]
    pub fn label(kind: ControllerKind, funnel: &FunnelConfig, relaxed: &RelaxedConfig) -> String {
        let who = match (Self::of(kind, funnel, relaxed), kind) {
            (Some(Self::Paper), ControllerKind::Relaxed) => "paper 001",
            (Some(Self::Paper), _) => "paper 000",
            (Some(Self::Ours), _) => "ours",
            (None, _) => "custom",
        };
        format!("{who} {}", kind.name())
    }
}

/// A controller with its settings: what a study or a world runs.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Controller {
    /// Standard funnelling.
    Standard(FunnelConfig),
    /// Relaxed funnelling (the μ bound from the [`FunnelConfig`]).
    Relaxed(FunnelConfig, RelaxedConfig),
}

impl Controller {
    /// The standard controller of a reading.
    #[must_use]
    pub fn standard(reading: Reading) -> Self {
        Self::Standard(reading.funnel())
    }

    /// The relaxed controller of a reading (its standard funnelling too).
    #[must_use]
    pub fn relaxed(reading: Reading) -> Self {
        Self::Relaxed(reading.funnel(), reading.relaxed())
    }

    /// The kind and the settings, for [`ControllerKind`]'s dispatch.
    #[inline]
    fn parts(&self) -> (ControllerKind, &FunnelConfig, RelaxedConfig) {
        match self {
            Self::Standard(f) => (ControllerKind::Standard, f, RelaxedConfig::default()),
            Self::Relaxed(f, r) => (ControllerKind::Relaxed, f, *r),
        }
    }

    /// One update with whichever controller; `ri` is reset for the
    /// standard one.
    #[inline]
    pub fn step(&self, u: &mut Update<'_>, ri: &mut RelaxedInternals) -> Internals {
        if let Self::Standard(_) = self {
            *ri = RelaxedInternals::default();
        }
        let (kind, f, r) = self.parts();
        kind.step(f, &r, u, ri)
    }

    /// One plan (no motion), for the benches.
    #[inline]
    #[must_use]
    pub fn plan(&self, u: &mut Update<'_>, ri: &mut RelaxedInternals) -> Internals {
        let (kind, f, r) = self.parts();
        kind.plan(f, &r, u, ri)
    }
}
