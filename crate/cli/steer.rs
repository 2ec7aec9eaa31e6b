//! `steer` arguments: one enum variant and one argument struct per
//! subcommand (add a subcommand by adding both, and one function in
//! `crate/bin/steer.rs`).

use std::path::PathBuf;

use clap::{Args, Parser, Subcommand};

use super::pool::PoolArgs;
use crate::relaxed::ControllerKind;

/// The funnelling runner: simulate a scenario, or run a seeded study.
#[derive(Parser, Clone, Debug, PartialEq)]
#[command(name = "steer", version, about)]
pub struct SteerCli {
    /// What to do.
    #[command(subcommand)]
    pub command: Command,
}

/// The subcommands.
#[derive(Subcommand, Clone, Debug, PartialEq)]
pub enum Command {
    /// Simulate a scenario file and write every agent's trajectory and metrics.
    Run(RunArgs),
    /// The seeded random reach study for every μ-bound variant (paper 000 §5).
    Reach(ReachArgs),
    /// Standard vs relaxed funnelling: paper 001 presets, then random region goals.
    Relaxed(RelaxedArgs),
    /// The envelope study (issue 13): tolerances × speed × distance, static, moving and chained goals.
    Envelope(EnvelopeArgs),
}

/// `steer run`.
#[derive(Args, Clone, Debug, PartialEq)]
pub struct RunArgs {
    /// Scenario file (schema: `crate/funnelling/scenario.rs`).
    #[arg(value_name = "SCENARIO.json")]
    pub scenario: PathBuf,
    /// Trajectory output.
    #[arg(long, value_name = "FILE")]
    pub out: PathBuf,
    /// Record every N-th step.
    #[arg(long, value_name = "N", default_value_t = 1, value_parser = clap::value_parser!(u32).range(1..))]
    pub every: u32,
    /// η table.
    #[arg(long, value_name = "FILE", default_value = "tables/eta.bin")]
    pub table: PathBuf,
    /// Override the scenario's controller.
    #[arg(long, value_name = "standard|relaxed", value_parser = parse_controller)]
    pub controller: Option<ControllerKind>,
}

/// `steer reach`.
#[derive(Args, Clone, Debug, PartialEq)]
pub struct ReachArgs {
    /// Number of random scenarios.
    #[arg(long, value_name = "N", default_value_t = crate::study::ReachStudy::default().n)]
    pub n: usize,
    /// Seed.
    #[arg(long, value_name = "S", default_value_t = crate::study::ReachStudy::default().seed)]
    pub seed: u64,
    /// η table.
    #[arg(long, value_name = "FILE", default_value = "tables/eta.bin")]
    pub table: PathBuf,
    /// Thread pool.
    #[command(flatten)]
    pub pool: PoolArgs,
}

/// `steer relaxed`.
#[derive(Args, Clone, Debug, PartialEq)]
pub struct RelaxedArgs {
    /// Number of random region goals.
    #[arg(long, value_name = "N", default_value_t = crate::region_study::RegionStudy::default().n)]
    pub n: usize,
    /// Seed.
    #[arg(long, value_name = "S", default_value_t = crate::region_study::RegionStudy::default().seed)]
    pub seed: u64,
    /// η table.
    #[arg(long, value_name = "FILE", default_value = "tables/eta.bin")]
    pub table: PathBuf,
    /// Folder holding the `p001_*_standard.json` presets.
    #[arg(long, value_name = "DIR", default_value = "scenarios")]
    pub scenarios: PathBuf,
    /// Where the relaxed controller aims (default: the relaxed controller's, entry).
    #[arg(long, value_name = "entry|paper-arc", value_parser = parse_aim)]
    pub aim: Option<crate::relaxed::RelaxedAim>,
    /// Relaxed setting `diskMargin` (default: the relaxed controller's).
    #[arg(long, value_name = "F")]
    pub disk_margin: Option<f32>,
    /// Relaxed setting `orientationMargin` (default: the relaxed controller's).
    #[arg(long, value_name = "F")]
    pub orientation_margin: Option<f32>,
    /// Thread pool.
    #[command(flatten)]
    pub pool: PoolArgs,
}

/// Parses `standard` or `relaxed`.
///
/// # Errors
/// Anything else.
pub fn parse_controller(s: &str) -> Result<ControllerKind, String> {
    ControllerKind::parse(s).ok_or_else(|| format!("`{s}` is neither standard nor relaxed"))
}

/// Parses `--aim`.
///
/// # Errors
/// Neither `entry` nor `paper-arc`.
pub fn parse_aim(s: &str) -> Result<crate::relaxed::RelaxedAim, String> {
    match s {
        "entry" => Ok(crate::relaxed::RelaxedAim::Entry),
        "paper-arc" => Ok(crate::relaxed::RelaxedAim::PaperArc),
        _ => Err(format!("`{s}` is neither entry nor paper-arc")),
    }
}

/// `steer envelope`.
#[derive(Args, Clone, Debug, PartialEq)]
pub struct EnvelopeArgs {
    /// Static scenarios per variant (moving and chained: N/5 each).
    #[arg(long, value_name = "N", default_value_t = 2000)]
    pub n: usize,
    /// Seed.
    #[arg(long, value_name = "S", default_value_t = 1)]
    pub seed: u64,
    /// Write the per-group and per-cell summaries as JSON.
    #[arg(long, value_name = "FILE")]
    pub json: Option<PathBuf>,
    /// η table.
    #[arg(long, value_name = "FILE", default_value = "tables/eta.bin")]
    pub table: PathBuf,
    /// Settings of the standard (and relaxed) variant's funnelling, as
    /// JSON (`FunnelConfig`, camelCase; missing fields take the defaults),
    /// e.g. `{"gain": 3}`.
    #[arg(long, value_name = "JSON")]
    pub standard: Option<String>,
    /// Run only these variants (comma-separated names).
    #[arg(long, value_name = "NAMES")]
    pub only: Option<String>,
    /// Print the summary and the targets only, not the per-cell tables.
    #[arg(long)]
    pub brief: bool,
}
