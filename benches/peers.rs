//! Ours beside the native peers, the cost in one run (the figures
//! report's Peers section; `tests/peers.rs` measures the quality):
//!
//! - a Dubins solve: our `dubins::shortest_length` and
//!   `DubinsPath::shortest` against dubins_paths' `shortest_from` (f64),
//!   on the same 4,096 seeded queries as the agreement test draws;
//! - an agent update with avoidance: ours (funnelling, ORCA on the
//!   forward-only unicycle at the defaults, planned every other step;
//!   then planned every step; then without avoidance) against dodgy_2d's
//!   `Agent::compute_avoiding_velocity` on holonomic discs (nearest 10
//!   neighbours within 3 m found by our grid, then the position moved),
//!   1,024 agents on a 1.6 m lattice, each to a seeded target 20–30 m
//!   away (about 11 neighbours in reach, paths crossing everywhere).
//!
//! `cargo bench --bench peers -- --warm-up-time 1 --measurement-time 2`.
//! Everything runs on one thread (a rayon pool of one: our world would
//! spread a step's agents over the cores). Criterion times each piece;
//! then a plain loop times every piece in turn (thread CPU time),
//! interleaved rounds, the best round of each kept, and prints the
//! same-run ratios; with `FIGURES_DIR` set they are written as timed
//! records (`tests/common/figures.rs`).

use std::hint::black_box;
use std::time::Instant;

use criterion::{BenchmarkId, Criterion, Throughput};
use glam::Vec2;
use steering::avoidance::config::AvoidanceMethod;
use steering::base::dubins::{shortest_length, DubinsPath};
use steering::base::rng::Rng;
use steering::funnelling::table::lookup::EtaTable;
use steering::studies::avoidance::Bench;
use steering::world::scenario::{AgentSpec, GoalFile, Scenario};
use steering::world::World;

#[path = "../tests/common/figures.rs"]
mod figures;
use figures::{record_timed, Figure};
#[path = "cpu_clock.rs"]
mod cpu_clock;
#[path = "../tests/common/peers.rs"]
mod peers;
use peers::{dubins_query, locked_version, PeerWorld};

type Pose = (f32, f32, f32);

/// The agreement test's queries (its seed), the first 4,096.
fn queries() -> Vec<(Pose, Pose, f32)> {
    let mut r = Rng::new(50);
    (0..4096).map(|_| dubins_query(&mut r)).collect()
}

fn peer_solve(q: &(Pose, Pose, f32)) -> f64 {
    use dubins_paths::f64::{DubinsPath as PeerPath, PosRot};
    let p = |q: Pose| PosRot::from([f64::from(q.0), f64::from(q.1), f64::from(q.2)]);
    PeerPath::shortest_from(p(q.0), p(q.1), f64::from(q.2)).map_or(0.0, |path| path.length())
}

/// The lattice of `side²` agents as a benchmark scenario (the circle
/// swap's settings: radius, speeds, step, avoidance defaults), each at
/// rest facing its target, a seeded oriented target 20–30 m away.
fn lattice(side: usize, method: AvoidanceMethod) -> Scenario {
    let mut sc = Bench::CircleSwap(8).scenario(0, method);
    let g0 = sc.agents[0].goals[0].clone();
    let mut rng = Rng::new(18);
    sc.agents = (0..side * side)
        .map(|i| {
            let pos = Vec2::new((i % side) as f32, (i / side) as f32) * 1.6;
            let a = rng.range(-3.1, 3.1);
            let goal = pos + steering::base::trig::unit(a) * rng.range(20.0, 30.0);
            AgentSpec {
                x: pos.x,
                y: pos.y,
                theta_deg: a.to_degrees(),
                v: 0.0,
                omega: 0.0,
                goals: vec![GoalFile {
                    x: goal.x,
                    y: goal.y,
                    beta_deg: rng.range(-3.1, 3.1).to_degrees(),
                    ..g0.clone()
                }],
            }
        })
        .collect();
    sc
}

/// Steps of one restart cycle; the restart (a clone) is not timed.
const CYCLE: usize = 300;
const SIDE: usize = 32;

fn ours(sc: &Scenario, table: &EtaTable) -> World {
    let mut w = sc.world().expect("valid lattice");
    w.plan(table).unwrap();
    w
}

fn bench(c: &mut Criterion, table: &EtaTable) {
    let qs = queries();
    let mut g = c.benchmark_group("peers_dubins");
    g.throughput(Throughput::Elements(qs.len() as u64));
    g.bench_function("ours_shortest_length", |b| {
        b.iter(|| {
            for q in &qs {
                black_box(shortest_length(q.0, q.1, q.2));
            }
        });
    });
    g.bench_function("ours_path", |b| {
        b.iter(|| {
            for q in &qs {
                black_box(DubinsPath::shortest(q.0, q.1, q.2));
            }
        });
    });
    g.bench_function("dubins_paths_f64", |b| {
        b.iter(|| {
            for q in &qs {
                black_box(peer_solve(q));
            }
        });
    });
    g.finish();
    let mut g = c.benchmark_group("peers_avoid");
    g.throughput(Throughput::Elements((SIDE * SIDE) as u64));
    let w0 = ours(&lattice(SIDE, AvoidanceMethod::Orca), table);
    g.bench_with_input(BenchmarkId::new("ours_orca", SIDE * SIDE), &w0, |b, w0| {
        let mut w = w0.clone();
        let mut k = 0;
        b.iter(|| {
            if k == CYCLE {
                w = w0.clone();
                k = 0;
            }
            w.step(table).unwrap();
            k += 1;
        });
    });
    let p0 = PeerWorld::new(&lattice(SIDE, AvoidanceMethod::Orca), 0.0);
    g.bench_with_input(BenchmarkId::new("dodgy_2d", SIDE * SIDE), &p0, |b, p0| {
        let mut w = p0.clone();
        let mut k = 0;
        b.iter(|| {
            if k == CYCLE {
                w = p0.clone();
                k = 0;
            }
            w.step();
            k += 1;
        });
    });
    g.finish();
}

/// ns (thread CPU time; wall time without that clock) of `f`.
fn timed(f: impl FnOnce()) -> f64 {
    let (t0, w0) = (cpu_clock::thread_ns(), Instant::now());
    f();
    match (t0, cpu_clock::thread_ns()) {
        (Some(a), Some(b)) => (b - a) as f64,
        _ => w0.elapsed().as_secs_f64() * 1e9,
    }
}

/// Rounds of the interleaved loops; the best of each piece is kept.
const ROUNDS: usize = 7;

/// ns per query: ours (length, path) and dubins_paths.
fn dubins_ratio() -> [f64; 3] {
    let qs = queries();
    let n = qs.len() as f64 * 50.0;
    let mut best = [f64::INFINITY; 3];
    for _ in 0..ROUNDS {
        let t = [
            timed(|| {
                for _ in 0..50 {
                    for q in &qs {
                        black_box(shortest_length(black_box(q.0), q.1, q.2));
                    }
                }
            }),
            timed(|| {
                for _ in 0..50 {
                    for q in &qs {
                        black_box(DubinsPath::shortest(black_box(q.0), q.1, q.2));
                    }
                }
            }),
            timed(|| {
                for _ in 0..50 {
                    for q in &qs {
                        black_box(peer_solve(black_box(q)));
                    }
                }
            }),
        ];
        for (b, t) in best.iter_mut().zip(t) {
            *b = b.min(t / n);
        }
    }
    best
}

/// ns per agent update over one restart cycle: ours (defaults: plans at
/// 30 Hz), ours planning every step, ours without avoidance, dodgy_2d.
fn avoid_ratio(table: &EtaTable) -> [f64; 4] {
    let orca = lattice(SIDE, AvoidanceMethod::Orca);
    let mut every = orca.clone();
    every.avoidance.replan_every = 1;
    let worlds = [
        ours(&orca, table),
        ours(&every, table),
        ours(&lattice(SIDE, AvoidanceMethod::Off), table),
    ];
    let peer = PeerWorld::new(&orca, 0.0);
    let per = (CYCLE * SIDE * SIDE) as f64;
    let mut best = [f64::INFINITY; 4];
    for _ in 0..5 {
        for (k, w0) in worlds.iter().enumerate() {
            let mut w = w0.clone();
            let t = timed(|| {
                for _ in 0..CYCLE {
                    w.step(table).unwrap();
                }
            });
            black_box(&w);
            best[k] = best[k].min(t / per);
        }
        let mut w = peer.clone();
        let t = timed(|| {
            for _ in 0..CYCLE {
                w.step();
            }
        });
        black_box(&w.agents);
        best[3] = best[3].min(t / per);
    }
    best
}

fn ratios(table: &EtaTable) {
    let d = dubins_ratio();
    let dv = locked_version("dubins_paths");
    println!(
        "same-run, ns per Dubins query: ours shortest_length {:.1}, ours DubinsPath::shortest {:.1}, dubins_paths {dv} {:.1}",
        d[0], d[1], d[2]
    );
    let f = |id: &str, what: &str, v: f64| Figure::new(id, what, v, "×", 2);
    let why = "more work: ours takes the sines and cosines of the frame again for each of the six words, where dubins_paths takes them once per query, and uses libm's portable trig (the same bits natively and in wasm) where dubins_paths calls the host's";
    record_timed(
        "peers",
        "dubins_cost",
        &[
            f(
                "peers.cost.dubins.length.over_peer",
                &format!("time per shortest-length query, ours (`dubins::shortest_length`) / dubins_paths {dv} (`f64::DubinsPath::shortest_from`), 4,096 seeded queries; above 1: the peer is ahead ({why})"),
                d[0] / d[2],
            ),
            f(
                "peers.cost.dubins.path.over_peer",
                &format!("time per path solve, ours (`DubinsPath::shortest`, the path a car-like agent follows, its segments' start poses placed too) / dubins_paths {dv}; above 1: the peer is ahead ({why})"),
                d[1] / d[2],
            ),
        ],
    );
    let a = avoid_ratio(table);
    let v = locked_version("dodgy_2d");
    println!(
        "same-run, ns per agent update ({} agents): ours ORCA (defaults) {:.1}, ours ORCA planned every step {:.1}, ours without avoidance {:.1}, dodgy_2d {v} {:.1}",
        SIDE * SIDE,
        a[0],
        a[1],
        a[2],
        a[3]
    );
    let lattice_what = "1,024 agents on a 1.6 m lattice to seeded targets 20–30 m away, 300-step cycles from rest, best of 5 interleaved rounds, one thread";
    record_timed(
        "peers",
        "avoidance_cost",
        &[
            f(
                "peers.cost.avoid.ours_over_peer",
                &format!("time per agent update, ours (funnelling + ORCA on the forward-only unicycle, the defaults: planned every other step) / dodgy_2d {v} (`compute_avoiding_velocity` every step on holonomic discs, neighbours by our grid, position moved), {lattice_what}; above 1: the peer is ahead (less work: no heading, no vehicle limits, no funnel to an oriented target)"),
                a[0] / a[3],
            ),
            f(
                "peers.cost.avoid.ours_every_step_over_peer",
                "the same, ours planning its avoidance every step as dodgy_2d does / dodgy_2d; above 1: the peer is ahead (less work)",
                a[1] / a[3],
            ),
            f(
                "peers.cost.avoid.ours_off_over_peer",
                "ours without avoidance (funnelling and the vehicle only) / dodgy_2d with it: what the oriented, limited vehicle costs before any avoidance",
                a[2] / a[3],
            ),
        ],
    );
}

fn main() {
    // One thread for both sides: natively our world spreads a step's
    // agents over the cores (rayon), dodgy_2d's loop here runs on one; and
    // the timing loop reads this thread's CPU clock.
    rayon::ThreadPoolBuilder::new()
        .num_threads(1)
        .build_global()
        .expect("the global pool, before any parallel work");
    let table = EtaTable::from_bytes(include_bytes!("../tables/eta.bin")).unwrap();
    let mut c = Criterion::default().configure_from_args();
    bench(&mut c, &table);
    // Not under `cargo test --benches` (criterion's test mode).
    if std::env::args().any(|a| a == "--bench") {
        ratios(&table);
    }
    c.final_summary();
}
