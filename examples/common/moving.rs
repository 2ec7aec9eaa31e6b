//! What `orbits` and `orbit_trace` share: the η table (`TABLE`, default
//! `tables/eta.bin`), the vehicle (`VEHICLE`, a reference vehicle of
//! `scenarios/vehicles/`, default the pedestrian) and the envelope study's
//! first `n` moving-goal scenarios of `seed`, scaled to the vehicle.
use steering::base::vehicle::VehicleParams;
use steering::funnelling::table::lookup::EtaTable;
use steering::studies::envelope::EnvelopeStudy;

pub fn setup(seed: u64, n: usize) -> (EtaTable, VehicleParams, EnvelopeStudy) {
    let path = std::env::var("TABLE").unwrap_or_else(|_| "tables/eta.bin".into());
    let table = EtaTable::from_bytes(&std::fs::read(path).unwrap()).unwrap();
    let p = std::env::var("VEHICLE").map_or_else(
        |_| VehicleParams::default(),
        |n| {
            steering::funnelling::vehicle_file::reference(&n)
                .unwrap()
                .vehicle
        },
    );
    let study = EnvelopeStudy {
        seed,
        n_static: 0,
        n_moving: n,
        n_chain: 0,
        ..EnvelopeStudy::for_vehicle(&p)
    };
    (table, p, study)
}
