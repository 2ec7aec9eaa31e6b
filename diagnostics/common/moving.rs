//! What `orbits` and `orbit_trace` share, as clap arguments: the η table
//! (`--table` or `TABLE`, default `tables/eta.bin`), the vehicle
//! (`--vehicle` or `VEHICLE`, a reference vehicle of `scenarios/vehicles/`,
//! default the pedestrian), the controller, and the envelope study's first
//! `n` moving-goal scenarios of `seed`, scaled to the vehicle.
use std::path::PathBuf;

use steering::base::vehicle::VehicleParams;
use steering::funnelling::table::lookup::EtaTable;
use steering::studies::envelope::EnvelopeStudy;

/// The table and the vehicle.
#[derive(clap::Args)]
pub struct Setup {
    /// η table, built for the vehicle (e.g. from `steer run`'s cache).
    #[arg(long, env = "TABLE", default_value = "tables/eta.bin")]
    pub table: PathBuf,
    /// Reference vehicle of `scenarios/vehicles/` (default: the pedestrian).
    #[arg(long, env = "VEHICLE")]
    pub vehicle: Option<String>,
}

/// Which funnelling controller steers.
#[derive(clap::ValueEnum, Clone, Copy, Debug, PartialEq, Eq)]
pub enum Law {
    /// Standard funnelling.
    Standard,
    /// Relaxed funnelling.
    Relaxed,
}

impl Setup {
    /// The table, the vehicle and the study of `n` moving goals of `seed`.
    pub fn setup(&self, seed: u64, n: usize) -> (EtaTable, VehicleParams, EnvelopeStudy) {
        let table = EtaTable::from_bytes(&std::fs::read(&self.table).unwrap()).unwrap();
        let p = self
            .vehicle
            .as_ref()
            .map_or_else(VehicleParams::default, |n| {
                steering::funnelling::vehicle_file::reference(n)
                    .unwrap()
                    .vehicle
            });
        let study = EnvelopeStudy {
            seed,
            n_static: 0,
            n_moving: n,
            n_chain: 0,
            ..EnvelopeStudy::for_vehicle(&p)
        };
        (table, p, study)
    }
}
