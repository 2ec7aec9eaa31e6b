//! Avoidance between funnelling agents: the fast slice of the
//! benchmark targets (`steer avoid --seeds 100` runs the 100-seed study),
//! the combination with funnelling (an unobstructed agent steps the same
//! bits as without avoidance), scenario errors naming the field, the
//! neighbour search's constant cost per agent, and determinism.

#![cfg(not(target_arch = "wasm32"))]

use steering::avoidance::{config::AvoidanceConfig, config::AvoidanceMethod, config::Obstacle};
use steering::studies::avoidance::{run, Bench};
use steering::world::scenario::Scenario;

mod common;
use common::{table, world_hash};

fn hash_run(sc: &Scenario, steps: u32) -> u64 {
    let t = table();
    world_hash(&t, &mut sc.world().unwrap(), steps)
}

#[test]
fn circle_swap_with_orca_has_no_overlap_and_arrives_oriented() {
    let t = table();
    for (n, seeds) in [(32usize, 1..=3u64), (100, 1..=1)] {
        let (mut agents, mut reached, mut entries, mut oriented) = (0, 0, 0, 0);
        for seed in seeds {
            let r = run(
                &Bench::CircleSwap(n).scenario(seed, AvoidanceMethod::Orca),
                &t,
            );
            println!("circle{n} seed {seed}: {r:?}");
            assert_eq!(r.overlap_pair_steps, 0, "circle{n} seed {seed}: {r:?}");
            assert_eq!(r.violations, 0);
            assert_eq!(r.nan, 0);
            // Deadlock = unfinished and under 0.05 m/s for 10 s: at N = 100
            // a few agents wait that long in the centre's jam and still
            // arrive (100 seeds: 108 agents of 10,000, 99.86 % reach).
            let allowed = if n == 100 { 3 } else { 0 };
            assert!(r.deadlocks <= allowed, "circle{n} seed {seed}: {r:?}");
            agents += r.agents;
            reached += r.reached;
            entries += r.entries;
            oriented += r.oriented;
        }
        assert!(
            reached as f32 >= 0.99 * agents as f32,
            "circle{n}: reach {reached}/{agents}"
        );
        // The target is at N = 100 (ε_tol 10°); N = 32 measured 90/96 here.
        let floor = if n == 100 { 0.95 } else { 0.9 };
        assert!(
            oriented as f32 >= floor * entries as f32,
            "circle{n}: oriented {oriented}/{entries}"
        );
    }
}

#[test]
fn without_avoidance_the_circle_swap_overlaps() {
    // What avoidance is for: the same scenario, avoidance off, overlaps.
    let r = run(
        &Bench::CircleSwap(32).scenario(1, AvoidanceMethod::Off),
        &table(),
    );
    assert!(r.overlap_pair_steps > 1000, "{r:?}");
    assert_eq!(r.reached, r.agents);
}

#[test]
fn walls_are_never_crossed_and_limits_hold() {
    let t = table();
    for b in [Bench::Corridor, Bench::Doorway] {
        for seed in 1..=2 {
            let r = run(&b.scenario(seed, AvoidanceMethod::Orca), &t);
            println!("{} seed {seed}: {r:?}", b.name());
            assert_eq!(r.obstacle_contacts, 0, "{}: {r:?}", b.name());
            assert_eq!(r.overlap_pair_steps, 0, "{}: {r:?}", b.name());
            assert_eq!((r.violations, r.nan), (0, 0));
            // All four arrive whole (corridor seed 2 keeps every agent
            // because agents at rest seek their goal's direction,
            // `avoidance::stalled`).
            assert_eq!(r.reached, r.agents, "{}: {r:?}", b.name());
        }
    }
}

#[test]
fn corridor_groups_keep_right_early_and_pass_in_lanes() {
    // Tune seeds 1000–1099. Without an early keep-right the two blocks
    // meet at full width and lock mid-corridor. The keep-right seen from
    // far ahead (`avoidance::passing`, lanes; mates merge behind each
    // other into the lane), agents at rest seeking their goal's direction
    // (`avoidance::stalled`) and patience (`avoidance::patience`: a margin
    // shrinking after 3 s at rest) leave no agent waiting 10 s or more
    // (the deadlock target); 2,397 arrive: 3 agents beyond the corridor,
    // their targets behind two arrived ones, still creep towards them at
    // the end.
    let t = table();
    let runs: Vec<_> = steering::base::parallel::map_indices(100, |k| {
        run(
            &Bench::Corridor.scenario(1000 + k as u64, AvoidanceMethod::Orca),
            &t,
        )
    });
    let agents: usize = runs.iter().map(|r| r.agents).sum();
    let reached: usize = runs.iter().map(|r| r.reached).sum();
    let deadlocks: usize = runs.iter().map(|r| r.deadlocks).sum();
    let jammed = runs.iter().filter(|r| r.deadlocks > 0).count();
    println!(
        "corridor 1000–1099: reach {reached}/{agents}, deadlocked {deadlocks} in {jammed} runs"
    );
    assert_eq!(agents, 2400);
    assert!(reached >= 2397, "{reached}");
    assert_eq!((deadlocks, jammed), (0, 0));
    for r in &runs {
        assert_eq!((r.overlap_pair_steps, r.obstacle_contacts), (0, 0), "{r:?}");
        assert_eq!((r.violations, r.nan), (0, 0));
    }
}

#[test]
fn the_doorway_agents_stuck_at_the_wall_end_now_pass() {
    // Tune seeds where an agent at rest by the doorway's wall got stuck:
    // 1012 (a neighbour beside the way flipped in and out of "oncoming
    // ahead" judged along the funnel's γ, so the keep-right turn swung the
    // velocity sought between the gap and the wall) and 1007 (after that
    // fix: headings 156° one way and 161° the other on alternate steps,
    // no turn kept). Both arrive whole, nobody deadlocked.
    let t = table();
    for seed in [1007, 1012] {
        let r = run(&Bench::Doorway.scenario(seed, AvoidanceMethod::Orca), &t);
        assert_eq!(
            (r.reached, r.deadlocks),
            (r.agents, 0),
            "seed {seed}: {r:?}"
        );
        assert_eq!((r.overlap_pair_steps, r.obstacle_contacts), (0, 0));
    }
}

#[test]
fn an_unobstructed_agent_steps_the_same_bits_as_without_avoidance() {
    // Fig. 7's agents are far apart: with ORCA and no obstacle in reach the
    // preferred velocity is admissible, so (γ, v_dt) goes to the seek step
    // unchanged and the trajectory is bit-identical (it still arrives
    // oriented once the way is clear).
    let text = include_str!("../scenarios/p000_fig1_seek.json");
    let off = Scenario::from_json(text).unwrap();
    let mut on = off.clone();
    on.avoidance = AvoidanceConfig::with_method(AvoidanceMethod::Orca);
    on.avoidance.radius = 0.05;
    on.avoidance.margin = 0.0;
    on.avoidance.reach = 0.2;
    assert_eq!(hash_run(&off, 1200), hash_run(&on, 1200));
}

#[test]
fn fig6_with_orca_keeps_the_pairs_apart() {
    let t = table();
    let off = run(&Bench::Fig6.scenario(0, AvoidanceMethod::Off), &t);
    let orca = run(&Bench::Fig6.scenario(0, AvoidanceMethod::Orca), &t);
    assert!(off.overlap_pair_steps > 0, "{off:?}");
    assert_eq!(orca.overlap_pair_steps, 0, "{orca:?}");
    assert_eq!(orca.reached, orca.agents);
}

#[test]
fn runs_are_deterministic() {
    let sc = Bench::CircleSwap(8).scenario(3, AvoidanceMethod::Orca);
    assert_eq!(hash_run(&sc, 600), hash_run(&sc, 600));
    let sep = Bench::Corridor.scenario(3, AvoidanceMethod::Separation);
    assert_eq!(hash_run(&sep, 300), hash_run(&sep, 300));
}

#[test]
fn neighbour_search_cost_per_agent_is_flat_at_constant_density() {
    // Agents on a lattice of 1.5 m (about 12 within the 3 m reach), at 400
    // and 3,600 agents: candidate pairs examined per agent per step.
    let t = table();
    let per_agent = |side: usize| {
        let mut sc = Bench::CircleSwap(8).scenario(1, AvoidanceMethod::Orca);
        sc.agents.clear();
        for i in 0..side * side {
            let (x, y) = ((i % side) as f32 * 1.5, (i / side) as f32 * 1.5);
            let mut a = Bench::CircleSwap(8)
                .scenario(1, AvoidanceMethod::Orca)
                .agents[0]
                .clone();
            a.x = x;
            a.y = y;
            a.goals[0].x = x + 10.0;
            a.goals[0].y = y;
            sc.agents.push(a);
        }
        let mut w = sc.world().unwrap();
        w.step(&t).unwrap();
        w.reset_avoidance_checks();
        for _ in 0..10 {
            w.step(&t).unwrap();
        }
        w.avoider().checks() as f64 / (10.0 * (side * side) as f64)
    };
    let (small, large) = (per_agent(20), per_agent(60));
    println!("candidate pairs per agent per step: 400 agents {small:.1}, 3,600 agents {large:.1}");
    assert!(large < 1.25 * small && large < 60.0, "{small} vs {large}");
}

#[test]
fn scenario_errors_name_the_field() {
    let base = r#"{"name": "a", "agents": [{"x": 0, "y": 0, "goals": [{"x": 3, "y": 0}]}]"#;
    let err = |extra: &str| {
        Scenario::from_json(&format!("{base}, {extra}}}"))
            .unwrap_err()
            .to_string()
    };
    assert_eq!(
        err(
            r#""obstacles": [{"kind": "disc", "x": 1, "y": 1, "radius": 1}, {"kind": "disc", "x": 1, "y": 1, "radius": -1}]"#
        ),
        "scenario is inconsistent: obstacles[1]: obstacle.radius = -1 is outside [0.01, 10000]"
    );
    assert!(
        err(r#""obstacles": [{"kind": "segment", "x1": 1, "y1": 1, "x2": 1, "y2": 1}]"#)
            .contains("obstacles[0]: a segment obstacle needs two different ends")
    );
    assert!(
        err(r#""obstacles": [{"kind": "disc", "x": 1, "y": 1, "r": 1}]"#)
            .contains("obstacles[0].r: unknown field")
    );
    assert!(err(r#""obstacles": [{"kind": "wall", "x": 1}]"#).contains("unknown variant `wall`"));
    assert!(err(r#""avoidance": {"method": "rvo"}"#).contains("unknown variant `rvo`"));
    assert!(err(r#""avoidance": {"method": "orca", "radius": 0}"#)
        .contains("avoidance.radius = 0 is outside"));
    assert!(err(r#""avoidance": {"method": "orca", "horizon": 0}"#)
        .contains("avoidance.horizon = 0 is outside"));
    assert!(err(r#""avoidance": {"method": "orca", "reach": 0.5}"#)
        .contains("avoidance.reach must be at least"));
    assert!(
        err(r#""avoidance": {"method": "orca", "maxNeighbours": 17}"#)
            .contains("avoidance.maxNeighbours = 17 is outside [1, 16]")
    );
    // Accepted, and written back only when set.
    let ok = Scenario::from_json(&format!(
        "{base}, \"avoidance\": {{\"method\": \"separation\"}}, \"obstacles\": [{{\"kind\": \"segment\", \"x1\": 0, \"y1\": 1, \"x2\": 3, \"y2\": 1}}]}}"
    ))
    .unwrap();
    assert_eq!(ok.avoidance.method, AvoidanceMethod::Separation);
    assert!(matches!(ok.obstacles[0], Obstacle::Segment { .. }));
    let plain = Scenario::from_json(&format!("{base}}}")).unwrap();
    let text = serde_json::to_string(&plain).unwrap();
    assert!(
        !text.contains("avoidance") && !text.contains("obstacles"),
        "{text}"
    );
}

#[test]
fn every_plan_rate_keeps_the_swap_apart_and_the_limits() {
    // `replanEvery` 1–4 (the core's range): the circle swap of 32 with
    // ORCA, one seed each; agents between plans keep their last command.
    // Measured: 0 overlapping pairs, 0 violations and 0 NaN at every rate,
    // every agent arrives.
    let t = table();
    for every in 1..=4u32 {
        let mut sc = Bench::CircleSwap(32).scenario(2, AvoidanceMethod::Orca);
        sc.avoidance.replan_every = every;
        let r = run(&sc, &t);
        println!("replanEvery {every}: {r:?}");
        assert_eq!(r.overlap_pair_steps, 0, "replanEvery {every}: {r:?}");
        assert_eq!((r.violations, r.nan), (0, 0), "replanEvery {every}");
        assert_eq!(r.reached, r.agents, "replanEvery {every}: {r:?}");
    }
}

#[test]
fn the_plan_rate_changes_mid_run_and_agents_come_and_go() {
    // A world switched from every step to every 3 steps and back, with an
    // agent added between, steps on: no NaN, every state within limits.
    let t = table();
    let sc = Bench::CircleSwap(8).scenario(1, AvoidanceMethod::Orca);
    let mut w = sc.world().unwrap();
    let mut cfg = *w.avoidance();
    let obstacles = w.obstacles().to_vec();
    for (k, every) in [1u32, 3, 2, 4, 1].into_iter().enumerate() {
        cfg.replan_every = every;
        w.set_avoidance(cfg, obstacles.clone()).unwrap();
        if k == 2 {
            let a = w.agents()[0].clone();
            w.add_agent(a.state, a.goals.clone()).unwrap();
        }
        for _ in 0..97 {
            w.step(&t).unwrap();
        }
    }
    assert_eq!(w.agents().len(), 9);
    for a in w.agents() {
        assert!(a.state.within_limits(w.params()), "{:?}", a.state);
    }
    cfg.replan_every = 5;
    assert!(w.set_avoidance(cfg, obstacles).is_err());
}
