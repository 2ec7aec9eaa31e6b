//! The core as a library user meets it: the table a `World` accepts, the
//! agent bound on every path that adds agents, what `done` and `at_rest`
//! mean on a halting goal, and the parallel step (natively on every core
//! of the current rayon pool) giving the same bits as one thread.
#![cfg(not(target_arch = "wasm32"))]

mod common;

use steering::base::angle::diff;
use steering::funnelling::table::format::TableError;
use steering::prelude::*;
use steering::world::edit::RANDOM_GOALS;
use steering::world::DEFAULT_MAX_AGENTS;

fn oriented(x: f32, y: f32, beta_deg: f32, halting: bool) -> GoalSpec {
    GoalSpec {
        goal: Goal {
            pos: Vec2::new(x, y),
            beta: beta_deg.to_radians(),
            halting,
            ..Goal::default()
        },
        ..GoalSpec::default()
    }
}

#[test]
fn a_world_refuses_a_table_built_for_other_limits() {
    let table = common::table();
    let p = VehicleParams {
        v_max: 3.0,
        ..VehicleParams::default()
    };
    let mut w = World::new(p, FunnelConfig::default()).unwrap();
    w.add_agent(
        VehicleState::default(),
        vec![oriented(5.0, 0.0, 90.0, false)],
    )
    .unwrap();
    let before = w.clone();
    let e = w.try_step(&table).unwrap_err();
    assert_eq!(
        e,
        TableError::ParamsMismatch {
            field: "vMax",
            table: 2.0,
            controller: 3.0
        }
    );
    assert_eq!(
        e.to_string(),
        "η table was built for vMax = 2, but the controller uses 3: regenerate the table"
    );
    assert_eq!(w, before, "nothing stepped");
    assert_eq!(w.check_table(&table), Err(e));

    // The same world on its own vehicle's table steps.
    let mut ok = World::new(VehicleParams::default(), FunnelConfig::default()).unwrap();
    ok.add_agent(
        VehicleState::default(),
        vec![oriented(5.0, 0.0, 90.0, false)],
    )
    .unwrap();
    ok.try_step(&table).unwrap();
    assert!(ok.time > 0.0);
}

#[test]
fn the_agent_bound_is_the_callers_and_holds_on_every_path_that_adds_agents() {
    let mut w = World::new(VehicleParams::default(), FunnelConfig::default()).unwrap();
    assert_eq!(w.max_agents(), DEFAULT_MAX_AGENTS);
    w.set_max_agents(3);
    for k in 0..3 {
        let s = VehicleState::new(Vec2::new(k as f32, 0.0), 0.0, 0.0, 0.0);
        w.add_agent(s, vec![oriented(5.0, 5.0, 0.0, false)])
            .unwrap();
    }
    let full = EditError::TooManyAgents {
        adding: 1,
        count: 3,
        max: 3,
    };
    assert_eq!(
        w.add_agent(VehicleState::default(), Vec::new()),
        Err(full.clone())
    );
    assert_eq!(
        full.to_string(),
        "1 more agents would exceed 3 (there are 3)"
    );
    assert_eq!(w.spawn_random(1, 7, 10.0, 1.3), Err(full));
    assert_eq!(w.agents.len(), 3, "nothing added");

    // A slice keeps its world's bound (it only ever has fewer agents).
    w.retain_range(1..3).unwrap();
    assert_eq!(w.max_agents(), 3);
    w.spawn_random(1, 7, 10.0, 1.3).unwrap();
    assert!(w.spawn_random(1, 7, 10.0, 1.3).is_err());

    // A random crowd counts whole: none of it is added past the bound.
    let mut w = World::new(VehicleParams::default(), FunnelConfig::default()).unwrap();
    w.set_max_agents(10);
    assert!(w.spawn_random(11, 1, 10.0, 1.3).is_err());
    assert!(w.agents.is_empty());
    w.spawn_random(10, 1, 10.0, 1.3).unwrap();
    assert_eq!(w.agents[0].goals.len(), RANDOM_GOALS);
}

#[test]
fn done_on_a_halting_goal_is_the_rest_pose_inside_both_tolerances_and_at_rest_follows() {
    let table = common::table();
    let mut w = World::new(VehicleParams::default(), FunnelConfig::default()).unwrap();
    let g = oriented(8.0, 4.0, 90.0, true);
    w.add_agent(VehicleState::default(), vec![g]).unwrap();
    let (mut done_at, mut moving_when_done) = (None, 0.0);
    while !w.agents[0].at_rest() {
        w.try_step(&table).unwrap();
        let a = &w.agents[0];
        if a.done() && done_at.is_none() {
            done_at = Some(w.time);
            moving_when_done = a.state.v;
        }
        assert!(w.time < 60.0, "comes to rest within a minute");
    }
    let done_at = done_at.unwrap();
    assert!(
        moving_when_done > 0.0,
        "done while still braking ({moving_when_done} m/s)"
    );
    assert!(w.time > done_at, "at rest after done");
    let a = &w.agents[0];
    assert_eq!(a.state.v, 0.0);
    assert!((a.state.pos - g.goal.pos).length() < g.goal.d_tol);
    assert!(diff(g.goal.beta, a.state.theta).abs() < g.goal.eps_tol);
    // Past a non-halting goal the agent cruises on: done, never at rest.
    let mut w = World::new(VehicleParams::default(), FunnelConfig::default()).unwrap();
    w.add_agent(
        VehicleState::default(),
        vec![oriented(4.0, 0.0, 0.0, false)],
    )
    .unwrap();
    for _ in 0..60 * 30 {
        w.step(&table);
    }
    assert!(w.agents[0].done() && !w.agents[0].at_rest());
}

/// FNV-1a over every agent's record at every step, and the final worlds.
fn run(threads: usize, w: &World, table: &EtaTable, steps: u32) -> (u64, World) {
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .unwrap();
    let mut w = w.clone();
    let mut h = common::FNV_OFFSET;
    let mut buf = Vec::new();
    pool.install(|| {
        for k in 0..steps {
            // Both stepping paths: plain, and with the records written.
            if k % 2 == 0 {
                w.step(table);
                w.write_state(&mut buf);
            } else {
                w.step_writing(table, &mut buf);
            }
            common::fnv(&mut h, &buf);
        }
    });
    (h, w)
}

/// Every agent's state, memory and metrics as bits (f32 `==` would call
/// −0 and 0 equal).
fn bits(w: &World) -> Vec<u32> {
    w.agents
        .iter()
        .flat_map(|a| {
            let s = a.state;
            let m = &a.metrics;
            [
                s.pos.x,
                s.pos.y,
                s.theta,
                s.v,
                s.omega,
                m.length,
                m.curvature,
            ]
            .map(f32::to_bits)
            .into_iter()
            .chain([a.current as u32, m.steps, u32::from(a.memory.position_met)])
        })
        .collect()
}

fn crowd(n: usize) -> World {
    let mut w = World::new(VehicleParams::default(), FunnelConfig::default()).unwrap();
    w.spawn_random(n, 11, 5.0, 1.3).unwrap();
    w
}

#[test]
fn the_parallel_step_equals_one_thread_bit_for_bit() {
    // (Same bits, so comparing the times of the two runs would say
    // nothing here: benches/parallel_step.rs measures the speed-up.)
    let table = common::table();
    let threads = 4;
    // Big enough for several parallel tasks (`PARALLEL_CHUNK` agents each).
    let plain = crowd(3_000);
    // Every tenth agent's queue faces its neighbour (paper 000 Fig. 6):
    // goals read the snapshot of the start of the step.
    let mut facing = crowd(3_000);
    for i in (0..3_000).step_by(10) {
        let g = GoalSpec {
            goal: Goal {
                d_tol: 0.5,
                ..Goal::default()
            },
            motion: GoalMotion::FaceAgent {
                agent: i + 1,
                distance: 2.0,
            },
            switch: SwitchRule::Tolerance,
        };
        facing.set_goals(i, vec![g]).unwrap();
    }
    // With avoidance on, the plans and the steps run on every core and
    // the avoidance between them on one thread.
    let mut orca = World::new(VehicleParams::default(), FunnelConfig::default()).unwrap();
    orca.spawn_random(1_500, 11, 40.0, 1.3).unwrap();
    orca.set_avoidance(
        AvoidanceConfig::with_method(AvoidanceMethod::Orca),
        Vec::new(),
    )
    .unwrap();
    for (name, w) in [("plain", &plain), ("facing", &facing), ("orca", &orca)] {
        let (h1, w1) = run(1, w, &table, 400);
        let (hn, wn) = run(threads, w, &table, 400);
        assert_eq!(h1, hn, "{name}: the records differ");
        assert_eq!(bits(&w1), bits(&wn), "{name}: the final states differ");
        assert_eq!(w1.time.to_bits(), wn.time.to_bits());
        let moved = w1.agents.iter().filter(|a| a.metrics.length > 2.0).count();
        assert!(
            moved > w1.agents.len() / 2,
            "{name}: only {moved} agents went 2 m"
        );
    }
}
