//! `crowd-metrics` arguments (paper 003 Tests I–IV × five seek variants).

use clap::Parser;

/// Runs every preset in `scenarios/crowd/` with its warm-up and measurement
/// window and prints a markdown table of the metrics.
#[derive(Parser, Clone, Debug, PartialEq)]
#[command(name = "crowd-metrics", version, about)]
pub struct CrowdMetricsCli {
    /// (Re)write the presets from `CrowdConfig::paper` instead of loading them.
    #[arg(long)]
    pub write_presets: bool,
    /// Override a top-level config field of every preset, value in JSON
    /// (repeatable), e.g. `--set max_force=0.3`.
    #[arg(long = "set", value_name = "KEY=VALUE", value_parser = parse_override)]
    pub overrides: Vec<(String, serde_json::Value)>,
}

/// Parses `key=value` with the value in JSON.
///
/// # Errors
/// No `=`, an empty key, or a value that is not JSON.
pub fn parse_override(s: &str) -> Result<(String, serde_json::Value), String> {
    let (k, v) = s
        .split_once('=')
        .ok_or_else(|| format!("`{s}` is not key=value"))?;
    if k.is_empty() {
        return Err(format!("`{s}` has an empty key"));
    }
    let v = serde_json::from_str(v).map_err(|e| format!("the value of `{k}` is not JSON: {e}"))?;
    Ok((k.to_owned(), v))
}
