use steering::avoidance::benchmarks::{run, Bench};
use steering::avoidance::AvoidanceMethod;
use steering::table::EtaTable;
fn main() {
    let table = EtaTable::from_bytes(&std::fs::read("tables/eta.bin").unwrap()).unwrap();
    let a: Vec<f32> = std::env::args()
        .skip(1)
        .map(|s| s.parse().unwrap())
        .collect();
    for b in [
        Bench::CircleSwap(32),
        Bench::CircleSwap(100),
        Bench::Corridor,
        Bench::Doorway,
    ] {
        let mut line = String::new();
        for seed in 1..=4 {
            let mut sc = b.scenario(seed, AvoidanceMethod::Orca);
            sc.avoidance.bias_deg = a[0];
            sc.avoidance.horizon = a[1];
            sc.avoidance.margin = a[2];
            sc.avoidance.obstacle_horizon = a[3];
            let r = run(&sc, &table);
            line += &format!(
                " [reach {}/{} or {}/{} dl {} ov {} minD {:.2} t {:?}]",
                r.reached,
                r.agents,
                r.oriented,
                r.entries,
                r.deadlocks,
                r.overlap_pair_steps,
                r.min_distance,
                r.finish_time.map(|t| t.round())
            );
        }
        println!("{}:{line}", b.name());
    }
}
