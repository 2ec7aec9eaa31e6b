//! The envelope study: oriented arrival measured over the whole operating
//! envelope a user of the lab can reach, not at one operating point.
//! [`crate::studies::reach`] samples one point (D_tol 0.25 m, ε_tol 5°,
//! 1.3 m/s, D 1–30 m); settings tuned there do much worse on random
//! targets drawn over the sliders' range, so this is the study the
//! controller is tuned on (seed 1) and judged on (seed 2, held out).
//!
//! Every run is a one-agent [`World`](crate::world::World), stepped exactly as the lab and
//! `steer run` step it (goal queues, moving goals, the braking after the
//! last halting goal), so what is measured is what a user sees.
//!
//! | sampled | range |
//! |---|---|
//! | distance D | 0.4–60 m, log-uniform (chain legs 0.4–20 m) |
//! | bearing, start heading, β | any |
//! | start speed | 0..v_max |
//! | start angular speed | uniform in the admissible ±min(ω_max, A/v) |
//! | D_tol | {0.1, 0.25, 0.5, 1, 2} m |
//! | ε_tol | {2, 5, 10, 20, 45}° |
//! | desired speed | {0.5, 1.0, 1.3, 1.8, 2.0} m/s |
//! | halting | half the static goals and the last goal of half the chains |
//! | moving goals | linear, 0–0.4 m/s in any direction, never halting ([`crate::world`] refuses halting on a goal that never stops) |
//! | chains | three goals in a row, switching on End_of_Steering |
//!
//! Each group (static, moving, chain) is run with every [`Variant`]: the
//! standard and the relaxed controller, each with the default settings and
//! with the paper's literal reading ([`FunnelConfig::paper_000`](crate::funnelling::config::FunnelConfig::paper_000),
//! [`RelaxedConfig::paper_001`](crate::funnelling::relaxed::RelaxedConfig::paper_001)). Scenario `i` of a group is the same for every
//! variant (paired comparison). Runs stop at [`EnvelopeStudy::max_time`]
//! per goal.
//!
//! What a run records ([`RunRecord`]): reach (enters the first goal's
//! disk), oriented on entry (heading within ε_tol of β at the first step
//! inside D_tol) and the entry error, End_of_Steering declared with both
//! tolerances met, for halting runs the rest pose inside both tolerances,
//! finished (every goal done), path length over the Dubins length (radius
//! at the desired speed, [`crate::base::dubins`]), non-finite values and limit
//! violations ([`crate::base::metrics`]), and orbits (never enters).
//!
//! | module | what |
//! |---|---|
//! | `envelope_study.rs` | the sampled envelope: [`EnvelopeStudy`], its scenarios ([`EnvScenario`], [`GoalKind`]) and the values sampled |
//! | `variant.rs` | the controllers compared: [`Variant`], [`variants`], the paper's literal settings |
//! | `run_record.rs` | one [`run`] and its [`RunRecord`] |
//! | [`report`] | per-cell summaries, the runs of every variant, the parallel run |
//! | [`tables`] | markdown tables per cell, the targets, the per-cell JSON |

mod envelope_study;
pub mod report;
mod run_record;
pub mod tables;
mod variant;

pub use envelope_study::{
    EnvScenario, EnvelopeStudy, GoalKind, BANDS, CHAIN_LEG, D_RANGE, D_TOLS, EPS_TOLS_DEG,
    GOAL_SPEED_MAX, SPEEDS,
};
pub use run_record::{run, RunRecord, REST_TIME};
pub use variant::{literal_config, literal_relaxed_config, variants, Variant};
