//! `eta-table` arguments: where to write the η table and how densely to
//! sample each axis ([`crate::funnelling::table::generate`]).

use std::path::PathBuf;

use clap::Parser;

use super::pool::PoolArgs;
use crate::funnelling::table::format::AXES;

/// Generates the η table for a vehicle (default: the pedestrian of the
/// committed table; axes scale with the vehicle's turning radius and
/// v_max). Deterministic: the same bytes whatever the thread count.
#[derive(Parser, Clone, Debug, PartialEq)]
#[command(name = "eta-table", version, about)]
pub struct EtaTableCli {
    /// Output file.
    #[arg(long, value_name = "FILE", default_value = "tables/eta.bin")]
    pub out: PathBuf,
    /// Vehicle file (the scenarios' `vehicle` schema, bare or as
    /// `{"name", "description", "vehicle": {…}}`; e.g.
    /// `scenarios/vehicles/car.json`). Default: the pedestrian.
    #[arg(long, value_name = "VEHICLE.json")]
    pub vehicle: Option<PathBuf>,
    /// Samples per axis: distance, α, ω fraction, current speed, desired speed.
    #[arg(long, value_name = "ND,NA,NS,NV,NVD", value_parser = parse_counts, default_value = "16,36,5,9,9")]
    pub counts: [usize; AXES],
    /// Thread pool.
    #[command(flatten)]
    pub pool: PoolArgs,
}

/// Most samples on one axis.
pub const MAX_AXIS_COUNT: usize = 4096;

/// Parses `ND,NA,NS,NV,NVD`: five integers in `[2, MAX_AXIS_COUNT]` whose
/// product (the entries) is at most the loader's
/// [`MAX_ENTRIES`](crate::funnelling::table::format::MAX_ENTRIES).
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
    if c.iter().any(|&n| !(2..=MAX_AXIS_COUNT).contains(&n)) {
        return Err(format!(
            "every count must be in [2, {MAX_AXIS_COUNT}], e.g. 16,36,5,9,9"
        ));
    }
    let entries: usize = c.iter().product();
    let max = crate::funnelling::table::format::MAX_ENTRIES;
    if entries > max {
        return Err(format!(
            "{entries} entries, more than a table may hold ({max})"
        ));
    }
    Ok(c)
}

impl EtaTableCli {
    /// The vehicle: `--vehicle`'s file, parsed and checked, or the
    /// pedestrian.
    ///
    /// # Errors
    /// An unreadable file, or a refused field, named.
    pub fn vehicle_params(&self) -> Result<crate::base::vehicle::VehicleParams, String> {
        match &self.vehicle {
            None => Ok(crate::base::vehicle::VehicleParams::default()),
            Some(path) => {
                let shown = path.display();
                let text = std::fs::read_to_string(path)
                    .map_err(|e| format!("cannot read {shown}: {e}"))?;
                crate::funnelling::vehicle_file::parse(&text)
                    .map(|f| f.vehicle)
                    .map_err(|e| format!("{shown}: {e}"))
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::funnelling::table::spec::DEFAULT_COUNTS;

    #[test]
    fn the_default_counts_are_the_committed_tables() {
        let cli = EtaTableCli::try_parse_from(["eta-table"]).unwrap();
        assert_eq!(cli.counts, DEFAULT_COUNTS);
    }
}
