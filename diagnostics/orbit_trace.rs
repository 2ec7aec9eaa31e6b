//! Traces one envelope moving-goal run step by step, to see an orbit form.
//!
//! `orbit_trace -- SEED INDEX [EVERY] [standard|relaxed]` prints t, pose,
//! speed, laps, mode, D to the goal and its least value so far, the aim
//! point (distance, α), v_dt, passes; `--vehicle` / `VEHICLE` and
//! `--table` / `TABLE` as in `orbits.rs`. Runs 150 s.

// clap is a native dev-dependency: under `wasm-pack test` (wasm32) this
// diagnostic is empty.
#![cfg_attr(target_arch = "wasm32", no_main)]
#![cfg(not(target_arch = "wasm32"))]
use clap::Parser;
use steering::funnelling::config::FunnelConfig;
use steering::funnelling::controller::ControllerKind;
use steering::funnelling::relaxed::RelaxedConfig;
use steering::studies::envelope::GoalKind;
use steering::world::World;
#[path = "common/moving.rs"]
mod moving;

/// One envelope moving-goal run step by step.
#[derive(Parser)]
struct Args {
    /// The envelope study's seed.
    #[arg(default_value_t = 1)]
    seed: u64,
    /// The moving-goal scenario's index.
    #[arg(default_value_t = 0)]
    i: usize,
    /// Print every N-th step.
    #[arg(default_value_t = 30)]
    every: u32,
    /// Controller.
    #[arg(value_enum, default_value_t = moving::Law::Standard)]
    law: moving::Law,
    #[command(flatten)]
    setup: moving::Setup,
}

fn main() {
    let a = Args::parse();
    let (seed, i, every) = (a.seed, a.i, a.every);
    let relaxed = a.law == moving::Law::Relaxed;
    let (table, p, st) = a.setup.setup(seed, i + 1);
    let sc = st.scenario(&p, GoalKind::Moving, i);
    let mut w = World::new(p, FunnelConfig::default()).unwrap();
    if relaxed {
        w.set_controller(ControllerKind::Relaxed, RelaxedConfig::default())
            .unwrap();
    }
    w.add_agent(sc.start, sc.goals.clone()).unwrap();
    println!("start {:?}\ngoal {:?}", sc.start, sc.goals[0]);
    let mut dmin = f32::INFINITY;
    for k in 0..(150.0 / p.dt) as u32 {
        w.step(&table).unwrap();
        let ag = &w.agents()[0];
        let g = ag.goal_now;
        let d = (g.pos - ag.state.pos).length();
        dmin = dmin.min(d);
        if k % every == 0 {
            let it = ag.internals;
            println!(
                "t {:6.2} L{} pos ({:7.3},{:7.3}) th {:6.1} v {:4.2} w {:5.2} | D {:6.3} dmin {:5.3} {:?} aimD {:5.2} aimA {:6.1} vdt {:4.2} ia {} reach {} de {:6.1} mu {:6.1} pass {}",
                k as f32 * p.dt, ag.memory.lap.laps, ag.state.pos.x, ag.state.pos.y, ag.state.theta.to_degrees(), ag.state.v, ag.state.omega,
                d, dmin, it.mode, it.aim_d, it.aim_alpha.to_degrees(), it.v_dt, ag.memory.passes, it.reachable, it.delta_eta.to_degrees(), it.mu.to_degrees(), ag.memory.passes
            );
        }
        if ag.done() {
            println!("done at {}", k as f32 * p.dt);
            break;
        }
    }
}
