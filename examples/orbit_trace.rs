//! One envelope moving-goal run step by step (to see an orbit form):
//! `orbit_trace -- SEED INDEX [EVERY] [relaxed]` prints t, pose, speed,
//! laps, mode, D to the goal and its least value so far, the aim point
//! (distance, α), v_dt, passes; `VEHICLE` and `TABLE` as in
//! `examples/orbits.rs`. Runs 150 s.
use steering::funnelling::controller::ControllerKind;
use steering::funnelling::funnel::FunnelConfig;
use steering::funnelling::relaxed::RelaxedConfig;
use steering::studies::envelope::GoalKind;
use steering::world::World;
#[path = "common/moving.rs"]
mod moving;

fn main() {
    let a: Vec<String> = std::env::args().collect();
    let seed: u64 = a.get(1).map_or(1, |s| s.parse().unwrap());
    let i: usize = a.get(2).map_or(0, |s| s.parse().unwrap());
    let every: u32 = a.get(3).map_or(30, |s| s.parse().unwrap());
    let relaxed = a.get(4).is_some_and(|s| s == "relaxed");
    let (table, p, st) = moving::setup(seed, i + 1);
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
        w.step(&table);
        let ag = &w.agents[0];
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
