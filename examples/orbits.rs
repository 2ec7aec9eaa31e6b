//! Moving-goal runs of the envelope study that never enter the disk (or
//! never finish): `orbits -- SEED N [relaxed]`. Another vehicle:
//! `VEHICLE=robot TABLE=path/to/its/eta-KEY.bin` (a reference vehicle
//! of `scenarios/vehicles/` and its table, e.g. from `steer run`'s cache);
//! runs get the study's time limit scaled to the vehicle.
use steering::funnelling::config::FunnelConfig;
use steering::funnelling::controller::Controller;
use steering::funnelling::relaxed::RelaxedConfig;
use steering::studies::envelope::{run, GoalKind};
#[path = "common/moving.rs"]
mod moving;

fn main() {
    let a: Vec<String> = std::env::args().collect();
    let seed: u64 = a.get(1).map_or(1, |s| s.parse().unwrap());
    let n: usize = a.get(2).map_or(2000, |s| s.parse().unwrap());
    let (table, p, st) = moving::setup(seed, n);
    let ctl = if a.get(3).is_some_and(|s| s == "relaxed") {
        Controller::Relaxed(FunnelConfig::default(), RelaxedConfig::default())
    } else {
        Controller::Standard(FunnelConfig::default())
    };
    for i in 0..n {
        let sc = st.scenario(&p, GoalKind::Moving, i);
        let r = run(
            &table,
            &p,
            &ctl,
            &sc,
            st.max_time * steering::funnelling::table::spec::VehicleScale::of(&p).time(),
        );
        if !r.reached || !r.finished {
            println!("{i}: {:?}\n  goals {:?}\n  rec {:?}", sc.start, sc.goals, r);
        }
    }
}
