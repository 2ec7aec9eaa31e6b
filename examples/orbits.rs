//! Moving-goal runs of the envelope study that never enter the disk (or
//! never finish): `orbits -- SEED N [relaxed]`.
use steering::funnel::FunnelConfig;
use steering::funnelling::envelope::{run, EnvelopeStudy, GoalKind};
use steering::relaxed::{Controller, RelaxedConfig};
use steering::table::EtaTable;
use steering::vehicle::VehicleParams;
fn main() {
    let a: Vec<String> = std::env::args().collect();
    let seed: u64 = a.get(1).map_or(1, |s| s.parse().unwrap());
    let n: usize = a.get(2).map_or(2000, |s| s.parse().unwrap());
    let bytes = std::fs::read("tables/eta.bin").unwrap();
    let table = EtaTable::from_bytes(&bytes).unwrap();
    let p = VehicleParams::default();
    let st = EnvelopeStudy {
        seed,
        n_static: 0,
        n_moving: n,
        n_chain: 0,
        ..EnvelopeStudy::default()
    };
    let ctl = if a.get(3).is_some_and(|s| s == "relaxed") {
        Controller::Relaxed(FunnelConfig::default(), RelaxedConfig::default())
    } else {
        Controller::Standard(FunnelConfig::default())
    };
    for i in 0..n {
        let sc = st.scenario(&p, GoalKind::Moving, i);
        let r = run(&table, &p, &ctl, &sc, 150.0);
        if !r.reached || !r.finished {
            println!("{i}: {:?}\n  goals {:?}\n  rec {:?}", sc.start, sc.goals, r);
        }
    }
}
