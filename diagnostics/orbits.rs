//! Lists the envelope study's moving-goal runs that never enter the disk or never finish.
//!
//! `orbits -- SEED N [standard|relaxed]`. Another vehicle:
//! `--vehicle robot --table path/to/its/eta-KEY.bin`, or
//! `VEHICLE=robot TABLE=path/to/its/eta-KEY.bin` (a reference vehicle
//! of `scenarios/vehicles/` and its table, e.g. from `steer run`'s cache);
//! runs get the study's time limit scaled to the vehicle.

// clap is a native dev-dependency: under `wasm-pack test` (wasm32) this
// diagnostic is empty.
#![cfg_attr(target_arch = "wasm32", no_main)]
#![cfg(not(target_arch = "wasm32"))]
use clap::Parser;
use steering::funnelling::config::FunnelConfig;
use steering::funnelling::controller::Controller;
use steering::funnelling::relaxed::RelaxedConfig;
use steering::studies::envelope::{run, GoalKind};
#[path = "common/moving.rs"]
mod moving;

/// Moving-goal runs of the envelope study that never enter the disk or
/// never finish.
#[derive(Parser)]
struct Args {
    /// The envelope study's seed.
    #[arg(default_value_t = 1)]
    seed: u64,
    /// Moving-goal scenarios.
    #[arg(default_value_t = 2000)]
    n: usize,
    /// Controller.
    #[arg(value_enum, default_value_t = moving::Law::Standard)]
    law: moving::Law,
    #[command(flatten)]
    setup: moving::Setup,
}

fn main() {
    let a = Args::parse();
    let (seed, n) = (a.seed, a.n);
    let (table, p, st) = a.setup.setup(seed, n);
    let ctl = if a.law == moving::Law::Relaxed {
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
