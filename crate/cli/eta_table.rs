//! `eta-table` arguments: where to write the η table and how densely to
//! sample each axis ([`crate::table::generate`]).

use std::path::PathBuf;

use clap::Parser;

use super::pool::PoolArgs;
use crate::table::AXES;

/// Generates the η table from the committed default parameters
/// (deterministic: the same bytes whatever the thread count).
#[derive(Parser, Clone, Debug, PartialEq)]
#[command(name = "eta-table", version, about)]
pub struct EtaTableCli {
    /// Output file.
    #[arg(long, value_name = "FILE", default_value = "tables/eta.bin")]
    pub out: PathBuf,
    /// Samples per axis: distance, α, ω fraction, current speed, desired speed.
    #[arg(long, value_name = "ND,NA,NS,NV,NVD", value_parser = parse_counts, default_value = "16,36,5,9,9")]
    pub counts: [usize; AXES],
    /// Thread pool.
    #[command(flatten)]
    pub pool: PoolArgs,
}

/// Parses `ND,NA,NS,NV,NVD`: five integers ≥ 2.
///
/// # Errors
/// A message naming what is wrong.
pub fn parse_counts(s: &str) -> Result<[usize; AXES], String> {
    let v = s
        .split(',')
        .map(|x| {
            x.trim()
                .parse::<usize>()
                .map_err(|e| format!("`{x}` is not a count: {e}"))
        })
        .collect::<Result<Vec<_>, _>>()?;
    let c = <[usize; AXES]>::try_from(v).map_err(|v| {
        format!(
            "wants five integers ≥ 2, e.g. 16,36,5,9,9 (got {})",
            v.len()
        )
    })?;
    if c.iter().any(|&n| n < 2) {
        return Err("every count must be ≥ 2, e.g. 16,36,5,9,9".into());
    }
    Ok(c)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::table::generate::DEFAULT_COUNTS;

    #[test]
    fn the_default_counts_are_the_committed_tables() {
        let cli = EtaTableCli::try_parse_from(["eta-table"]).unwrap();
        assert_eq!(cli.counts, DEFAULT_COUNTS);
    }
}
