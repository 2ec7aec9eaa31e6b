use steering::avoidance::benchmarks::Bench;
use steering::avoidance::AvoidanceMethod;
use steering::table::EtaTable;
fn main() {
    let table = EtaTable::from_bytes(&std::fs::read("tables/eta.bin").unwrap()).unwrap();
    let which: String = std::env::args().nth(1).unwrap();
    let b = if which == "door" {
        Bench::Doorway
    } else {
        Bench::Corridor
    };
    let mut sc = b.scenario(1, AvoidanceMethod::Orca);
    sc.avoidance.bias_deg = 45.0;
    let mut w = sc.world().unwrap();
    w.plan(&table);
    for k in 0..1800 {
        w.step(&table);
        if k % 300 == 299 {
            println!("t={:.0}", w.time);
            for (i, a) in w.agents.iter().enumerate() {
                let c = w.avoider.commands[i];
                println!("  {i} pos=({:.2},{:.2}) th={:.2} v={:.2} done={} gamma={:.2} vdt={:.2} cmd=({:.2},{:.2},{})", a.state.pos.x, a.state.pos.y, a.state.theta, a.state.v, a.done(), a.internals.gamma, a.internals.v_dt, c.heading, c.speed, c.active);
            }
        }
    }
}
