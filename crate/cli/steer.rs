//! `steer` arguments: one enum variant and one argument struct per
//! subcommand (add a subcommand by adding both, and one function in
//! `crate/bin/steer.rs`).

use std::path::PathBuf;

use clap::{Args, Parser, Subcommand};

use super::pool::PoolArgs;
use crate::funnelling::controller::{ControllerKind, Reading};

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
    /// The envelope study: tolerances × speed × distance, static, moving and chained goals.
    Envelope(EnvelopeArgs),
    /// Avoidance benchmarks: circle swap, corridor, doorway, Fig. 6 / Fig. 8; off vs separation vs ORCA.
    Avoid(AvoidArgs),
    /// The figures report: docs/FIGURES.md from the records the tests, studies and benchmarks write (`--check`: compare only).
    Report(super::report::ReportArgs),
}

/// `steer avoid`.
#[derive(Args, Clone, Debug, PartialEq)]
pub struct AvoidArgs {
    /// Seeded runs per benchmark and method (the paper figures run once), 1 to 10,000.
    #[arg(long, value_name = "N", default_value_t = 100, value_parser = parse_seeds)]
    pub seeds: usize,
    /// First seed.
    #[arg(long, value_name = "S", default_value_t = 1)]
    pub seed: u64,
    /// Only these benchmarks (comma-separated: circle8, circle32, circle100, corridor, doorway, fig6, fig8).
    #[arg(long, value_name = "NAMES")]
    pub only: Option<String>,
    /// Steps between an agent's avoidance plans, 1 (every step) to 4.
    #[arg(long, value_name = "N", default_value_t = crate::avoidance::config::AvoidanceConfig::default().replan_every, value_parser = parse_replan_every)]
    pub replan_every: u32,
    /// Write the benchmark presets (seed `--seed`, ORCA) into DIR as `avoid_*.json` and stop.
    #[arg(long, value_name = "DIR")]
    pub write_presets: Option<PathBuf>,
    /// η table.
    #[arg(long, value_name = "FILE", default_value = "tables/eta.bin")]
    pub table: PathBuf,
    /// `--record`: the summary as a figures record.
    #[command(flatten)]
    pub record: super::records::RecordArgs,
    /// Thread pool.
    #[command(flatten)]
    pub pool: PoolArgs,
}

/// Parses `steer avoid --seeds`: 1 to 10,000.
///
/// # Errors
/// See [`parse_bounded`].
pub fn parse_seeds(s: &str) -> Result<usize, String> {
    parse_bounded(s, 1, 10_000).map(|v| v as usize)
}

/// Parses `steer avoid --replan-every`: 1 to 4.
///
/// # Errors
/// See [`parse_bounded`].
pub fn parse_replan_every(s: &str) -> Result<u32, String> {
    parse_bounded(s, 1, 4).map(|v| v as u32)
}

impl AvoidArgs {
    /// The benchmarks to run: all, or those named by `--only`.
    ///
    /// # Errors
    /// A name that is not a benchmark.
    pub fn benches(&self) -> Result<Vec<crate::studies::avoidance::Bench>, String> {
        let all = crate::studies::avoidance::Bench::ALL.to_vec();
        let Some(only) = &self.only else {
            return Ok(all);
        };
        let known: Vec<String> = all.iter().map(|b| b.name()).collect();
        if let Some(bad) = only.split(',').find(|n| !known.iter().any(|k| k == n)) {
            return Err(format!(
                "--only: `{bad}` is not a benchmark (known: {})",
                known.join(", ")
            ));
        }
        Ok(all
            .into_iter()
            .filter(|b| only.split(',').any(|n| n == b.name()))
            .collect())
    }
}

/// `steer run`.
#[derive(Args, Clone, Debug, PartialEq)]
pub struct RunArgs {
    /// Scenario file (schema: `crate/world/scenario.rs`).
    #[arg(value_name = "SCENARIO.json")]
    pub scenario: PathBuf,
    /// Trajectory output, streamed while simulating; the extension
    /// (case-insensitive) chooses the format: `.csv` one row per agent per
    /// recorded step (agent,t,x,y,theta,v,omega,mode), time-ordered;
    /// `.json` one document {name, source, dt, steps, every, agents,
    /// frames: [{t, x: [per agent], y, theta, v, omega, mode}], metrics:
    /// [per agent]}; `.jsonl` the same as JSON Lines (header, one frame per
    /// line, then {metrics}). Checked before simulating; never the scenario.
    #[arg(long, value_name = "FILE")]
    pub out: PathBuf,
    /// Record every N-th step, 1 to 36,000,000.
    #[arg(long, value_name = "N", default_value_t = 1, value_parser = parse_every)]
    pub every: u32,
    /// η table; it must match the scenario's vehicle (else an error).
    /// Without it: the scenario's `table`, else `tables/eta.bin` if built
    /// for the scenario's vehicle, else the matching table from the cache
    /// (`$STEER_TABLE_CACHE`, `$XDG_CACHE_HOME/steering-lab/tables` or
    /// `~/.cache/steering-lab/tables`), built there if missing.
    #[arg(long, value_name = "FILE")]
    pub table: Option<PathBuf>,
    /// Override the scenario's controller.
    #[arg(long, value_name = "standard|relaxed|seek", value_parser = parse_controller)]
    pub controller: Option<ControllerKind>,
    /// Override the scenario's settings with a reading's: `paper` (paper
    /// 000's standard and paper 001's relaxed funnelling exactly as
    /// written) or `ours` (the defaults); docs/READINGS.md.
    #[arg(long, value_name = "paper|ours", value_parser = parse_reading)]
    pub reading: Option<Reading>,
}

/// `steer reach`.
#[derive(Args, Clone, Debug, PartialEq)]
pub struct ReachArgs {
    /// Number of random scenarios, 1 to 1,000,000.
    #[arg(long, value_name = "N", default_value_t = crate::studies::reach::ReachStudy::default().n, value_parser = parse_study_n)]
    pub n: usize,
    /// Seed.
    #[arg(long, value_name = "S", default_value_t = crate::studies::reach::ReachStudy::default().seed)]
    pub seed: u64,
    /// η table.
    #[arg(long, value_name = "FILE", default_value = "tables/eta.bin")]
    pub table: PathBuf,
    /// `--record`: the summary as a figures record.
    #[command(flatten)]
    pub record: super::records::RecordArgs,
    /// Thread pool.
    #[command(flatten)]
    pub pool: PoolArgs,
}

/// `steer relaxed`.
#[derive(Args, Clone, Debug, PartialEq)]
pub struct RelaxedArgs {
    /// Number of random region goals, 1 to 1,000,000.
    #[arg(long, value_name = "N", default_value_t = crate::studies::region::RegionStudy::default().n, value_parser = parse_study_n)]
    pub n: usize,
    /// Seed.
    #[arg(long, value_name = "S", default_value_t = crate::studies::region::RegionStudy::default().seed)]
    pub seed: u64,
    /// η table.
    #[arg(long, value_name = "FILE", default_value = "tables/eta.bin")]
    pub table: PathBuf,
    /// Folder holding the `p001_*_standard.json` presets.
    #[arg(long, value_name = "DIR", default_value = "scenarios")]
    pub scenarios: PathBuf,
    /// The reading both controllers start from: `ours` (default) or
    /// `paper` (paper 000's standard against paper 001's relaxed
    /// funnelling, exactly as written); `--aim` and the margins override it.
    #[arg(long, value_name = "paper|ours", default_value = "ours", value_parser = parse_reading)]
    pub reading: Reading,
    /// Where the relaxed controller aims (default: the reading's; ours: entry).
    #[arg(long, value_name = "entry|paper-arc", value_parser = parse_aim)]
    pub aim: Option<crate::funnelling::relaxed::RelaxedAim>,
    /// Relaxed setting `diskMargin` (default: the relaxed controller's).
    #[arg(long, value_name = "F")]
    pub disk_margin: Option<f32>,
    /// Relaxed setting `orientationMargin` (default: the relaxed controller's).
    #[arg(long, value_name = "F")]
    pub orientation_margin: Option<f32>,
    /// `--record`: the summary as a figures record.
    #[command(flatten)]
    pub record: super::records::RecordArgs,
    /// Thread pool.
    #[command(flatten)]
    pub pool: PoolArgs,
}

/// Largest `--n` of a study (`reach`, `relaxed`, `envelope`): results are
/// kept per case (tens of bytes each) and the time grows linearly (the
/// default 10,000 takes seconds), so a million is minutes and megabytes.
pub const MAX_STUDY_N: usize = 1_000_000;

/// Parses a whole number in `[min, max]`, naming the bound when it is
/// outside (a number too large for any integer type included).
///
/// # Errors
/// Not a whole number, or outside the bounds.
pub fn parse_bounded(s: &str, min: u64, max: u64) -> Result<u64, String> {
    let t = s.trim();
    if t.is_empty() || !t.bytes().all(|b| b.is_ascii_digit()) {
        return Err(format!("`{s}` is not a whole number in [{min}, {max}]"));
    }
    match t.parse::<u64>() {
        Ok(v) if (min..=max).contains(&v) => Ok(v),
        _ => Err(format!("{t} is outside [{min}, {max}]")),
    }
}

/// Parses `--n` of a study: 1 to [`MAX_STUDY_N`].
///
/// # Errors
/// See [`parse_bounded`].
pub fn parse_study_n(s: &str) -> Result<usize, String> {
    parse_bounded(s, 1, MAX_STUDY_N as u64).map(|v| v as usize)
}

/// Smallest `steer envelope --n`: the moving and chained groups get N/5
/// runs each, and an empty group would print rows of NaN.
pub const MIN_ENVELOPE_N: usize = 5;

/// Parses `steer envelope --n`: [`MIN_ENVELOPE_N`] to [`MAX_STUDY_N`].
///
/// # Errors
/// See [`parse_bounded`].
pub fn parse_envelope_n(s: &str) -> Result<usize, String> {
    parse_bounded(s, MIN_ENVELOPE_N as u64, MAX_STUDY_N as u64).map(|v| v as usize)
}

/// Parses `steer run --every`: 1 to [`super::trajectory::MAX_EVERY`].
///
/// # Errors
/// See [`parse_bounded`].
pub fn parse_every(s: &str) -> Result<u32, String> {
    parse_bounded(s, 1, u64::from(super::trajectory::MAX_EVERY)).map(|v| v as u32)
}

/// Parses `paper` or `ours`.
///
/// # Errors
/// Any other word, named.
pub fn parse_reading(s: &str) -> Result<Reading, String> {
    Reading::parse(s).ok_or_else(|| format!("`{s}` is neither paper nor ours"))
}

/// Parses `standard`, `relaxed` or `seek`.
///
/// # Errors
/// Anything else.
pub fn parse_controller(s: &str) -> Result<ControllerKind, String> {
    ControllerKind::parse(s).ok_or_else(|| format!("`{s}` is none of standard, relaxed or seek"))
}

/// Parses `--aim`.
///
/// # Errors
/// Neither `entry` nor `paper-arc`.
pub fn parse_aim(s: &str) -> Result<crate::funnelling::relaxed::RelaxedAim, String> {
    match s {
        "entry" => Ok(crate::funnelling::relaxed::RelaxedAim::Entry),
        "paper-arc" => Ok(crate::funnelling::relaxed::RelaxedAim::PaperArc),
        _ => Err(format!("`{s}` is neither entry nor paper-arc")),
    }
}

/// `steer envelope`.
#[derive(Args, Clone, Debug, PartialEq)]
pub struct EnvelopeArgs {
    /// Static scenarios per variant (moving and chained: N/5 each), 5 to 1,000,000.
    #[arg(long, value_name = "N", default_value_t = 2000, value_parser = parse_envelope_n)]
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
    /// Vehicle file (e.g. `scenarios/vehicles/car.json`): the
    /// study's distances, tolerances and speeds are scaled to its turning
    /// radius and v_max (the tables stay in pedestrian-equivalent units),
    /// the table is `--table` if built for it, else the cached or newly
    /// built one (`steer run`'s cache); the per-vehicle measures
    /// (η accuracy at D ≥ 4 turning radii, reach, oriented entries at
    /// D ≥ 5 turning radii and ε_tol 5°) are printed first; for a
    /// car-like vehicle (`minTurnRadius`), `--n` runs of the envelope
    /// scaled to R_min too, per distance band in R_min.
    #[arg(long, value_name = "VEHICLE.json")]
    pub vehicle: Option<PathBuf>,
    /// Off-grid queries of the η accuracy measure (with `--vehicle`).
    #[arg(long, value_name = "N", default_value_t = 10_000, value_parser = clap::value_parser!(u32).range(1..=1_000_000))]
    pub queries: u32,
    /// `--record`: the summary as a figures record.
    #[command(flatten)]
    pub record: super::records::RecordArgs,
}

impl RelaxedArgs {
    /// The relaxed settings: the reading's with `--aim`, `--disk-margin`
    /// and `--orientation-margin` applied, validated.
    ///
    /// # Errors
    /// A margin out of range, named.
    pub fn relaxed_config(&self) -> Result<crate::funnelling::relaxed::RelaxedConfig, String> {
        let mut rcfg = self.reading.relaxed();
        if let Some(aim) = self.aim {
            rcfg.aim = aim;
        }
        if let Some(m) = self.disk_margin {
            rcfg.disk_margin = m;
        }
        if let Some(m) = self.orientation_margin {
            rcfg.orientation_margin = m;
        }
        rcfg.validate().map_err(|e| e.to_string())?;
        Ok(rcfg)
    }
}

impl EnvelopeArgs {
    /// `--standard` parsed and validated (`None` without it).
    ///
    /// # Errors
    /// Not a `FunnelConfig`, or a value out of range.
    pub fn standard_config(
        &self,
    ) -> Result<Option<crate::funnelling::config::FunnelConfig>, String> {
        let Some(json) = &self.standard else {
            return Ok(None);
        };
        let cfg: crate::funnelling::config::FunnelConfig =
            serde_json::from_str(json).map_err(|e| format!("--standard: {e}"))?;
        cfg.validate().map_err(|e| format!("--standard: {e}"))?;
        Ok(Some(cfg))
    }

    /// The variants to run: all, or those named by `--only`.
    ///
    /// # Errors
    /// A name that is not a variant.
    pub fn variants(&self) -> Result<Vec<crate::studies::envelope::Variant>, String> {
        let mut vs = crate::studies::envelope::variants().to_vec();
        if let Some(only) = &self.only {
            let known: Vec<&str> = vs.iter().map(|v| v.name).collect();
            if let Some(bad) = only.split(',').find(|n| !known.contains(n)) {
                return Err(format!(
                    "--only: `{bad}` is not a variant (known: {})",
                    known.join(", ")
                ));
            }
            vs.retain(|v| only.split(',').any(|n| n == v.name));
        }
        Ok(vs)
    }
}
