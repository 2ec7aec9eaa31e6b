//! The core as a library user meets it: the table a `World` accepts on
//! every path that plans or steps, the agent bound and finite values on
//! every path that changes agents, what `done` and `at_rest`
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

/// A world of one agent for `p`, with avoidance `method`.
fn one_agent(p: VehicleParams, method: AvoidanceMethod) -> World {
    let mut w = World::new(p, FunnelConfig::default()).unwrap();
    w.add_agent(
        VehicleState::default(),
        vec![oriented(5.0, 0.0, 90.0, false)],
    )
    .unwrap();
    w.add_agent(
        VehicleState::new(Vec2::new(0.0, 3.0), 0.0, 0.0, 0.0),
        vec![oriented(5.0, 3.0, 90.0, false)],
    )
    .unwrap();
    w.set_avoidance(AvoidanceConfig::with_method(method), Vec::new())
        .unwrap();
    w
}

#[test]
fn a_mismatched_table_is_refused_on_every_path_that_plans_or_steps() {
    let table = common::table();
    let fast = VehicleParams {
        v_max: 3.0,
        ..VehicleParams::default()
    };
    let mismatch = TableError::ParamsMismatch {
        field: "vMax",
        table: 2.0,
        controller: 3.0,
    };
    assert_eq!(
        mismatch.to_string(),
        "η table was built for vMax = 2, but the controller uses 3: regenerate the table"
    );
    // A scenario's world, and a world slice (the lab's stepping workers).
    let scenario = Scenario::from_json(
        r#"{"name": "s", "vehicle": {"vMax": 3}, "agents": [{"x": 0, "y": 0, "goals": [{"x": 4, "y": 0}]}]}"#,
    )
    .unwrap()
    .world()
    .unwrap();
    let mut slice = one_agent(fast, AvoidanceMethod::Off);
    slice.retain_range(1..2).unwrap();
    let worlds = [
        ("plain", one_agent(fast, AvoidanceMethod::Off)),
        ("separation", one_agent(fast, AvoidanceMethod::Separation)),
        ("orca", one_agent(fast, AvoidanceMethod::Orca)),
        ("scenario", scenario),
        ("slice", slice),
    ];
    for (name, w) in worlds {
        let mut w = w;
        let before = w.clone();
        let mut out = vec![7.0; 3];
        assert_eq!(w.step(&table), Err(mismatch.clone()), "{name}: step");
        assert_eq!(
            w.step_writing(&table, &mut out),
            Err(mismatch.clone()),
            "{name}: step_writing"
        );
        assert_eq!(w.plan(&table), Err(mismatch.clone()), "{name}: plan");
        assert_eq!(w.check_table(&table), Err(mismatch.clone()), "{name}");
        assert_eq!(w, before, "{name}: nothing planned or stepped");
        assert_eq!(out, vec![7.0; 3], "{name}: nothing written");
        // Limits set back to the table's: it steps.
        w.set_params(VehicleParams::default()).unwrap();
        w.plan(&table).unwrap();
        w.step(&table).unwrap();
        w.step_writing(&table, &mut out).unwrap();
        assert!(w.time() > 0.0, "{name}");
        // And set away again after stepping: refused again.
        w.set_params(fast).unwrap();
        assert_eq!(
            w.step(&table),
            Err(mismatch.clone()),
            "{name}: after set_params"
        );
    }
    // Only a world told to accept another table's η (the lab's page, while
    // the table for new limits is built) steps on one.
    let mut w = one_agent(fast, AvoidanceMethod::Orca);
    w.allow_other_table(true);
    w.plan(&table).unwrap();
    w.step(&table).unwrap();
    assert_eq!(w.check_table(&table), Err(mismatch));
    w.allow_other_table(false);
    assert!(w.step(&table).is_err());
}

/// What a library user can do to a world's agents and settings: only the
/// world's methods change them, and each refuses a value that is not
/// finite, or an agent past the bound, naming the field, changing nothing.
#[test]
fn the_agent_bound_and_finite_values_hold_through_the_public_api() {
    let table = common::table();
    let mut w = one_agent(VehicleParams::default(), AvoidanceMethod::Orca);
    w.set_max_agents(3);
    let copy = w.agents()[0].clone();
    w.add_agent(copy.state, copy.goals.clone()).unwrap();
    let before = w.clone();
    let full = |adding| EditError::TooManyAgents {
        adding,
        count: 3,
        max: 3,
    };
    // Past the bound: every path that adds agents.
    assert_eq!(w.add_agent(copy.state, copy.goals.clone()), Err(full(1)));
    assert_eq!(w.spawn_random(1, 1, 10.0, 1.3), Err(full(1)));
    assert_eq!(w.spawn_random_kept(5, 1, 10.0, 1.3, 4..5), Err(full(5)));
    // Not finite: a state (with room for it), a pose, a goal, the limits,
    // the settings.
    let nan = f32::NAN;
    w.set_max_agents(4);
    let e = w
        .add_agent(
            VehicleState::new(Vec2::new(nan, 0.0), 0.0, 0.0, 0.0),
            Vec::new(),
        )
        .unwrap_err();
    assert_eq!(e.to_string(), "pos.x = NaN is not finite");
    let e = w
        .add_agent(
            VehicleState::new(Vec2::ZERO, 0.0, f32::INFINITY, 0.0),
            Vec::new(),
        )
        .unwrap_err();
    assert!(e.to_string().starts_with("v = inf"), "{e}");
    w.set_max_agents(3);
    let e = w.set_pose(0, Vec2::ZERO, nan).unwrap_err();
    assert!(e.to_string().starts_with("theta = NaN"), "{e}");
    let mut g = oriented(nan, 0.0, 0.0, false);
    let e = w.set_goals(0, vec![g]).unwrap_err();
    assert!(e.to_string().contains("NaN is not finite"), "{e}");
    g = oriented(1.0, 0.0, 0.0, false);
    g.goal.d_tol = f32::INFINITY;
    assert!(w.set_goals(1, vec![g]).is_err());
    assert!(w.spawn_random(0, 1, nan, 1.3).is_err());
    assert!(w.spawn_random(0, 1, 10.0, nan).is_err());
    let e = w
        .set_params(VehicleParams {
            v_max: nan,
            ..VehicleParams::default()
        })
        .unwrap_err();
    assert!(e.to_string().starts_with("vMax = NaN"), "{e}");
    let e = w
        .set_config(FunnelConfig {
            gain: nan,
            ..FunnelConfig::default()
        })
        .unwrap_err();
    assert!(e.to_string().contains("NaN"), "{e}");
    let mut orca = AvoidanceConfig::with_method(AvoidanceMethod::Orca);
    orca.radius = nan;
    assert!(w.set_avoidance(orca, Vec::new()).is_err());
    assert_eq!(w, before, "every refusal left the world as it was");
    // The world steps on (ORCA reads one value per agent: the bound and
    // the step buffers agree), every value finite.
    for _ in 0..120 {
        w.step(&table).unwrap();
    }
    let mut state = Vec::new();
    w.write_state(&mut state);
    assert_eq!(state.len(), 3 * STATE_STRIDE);
    assert!(state.iter().all(|x| x.is_finite()));
    // A slice (avoidance off: it couples every agent), then agents added
    // back up to the bound (not past it).
    w.set_avoidance(AvoidanceConfig::default(), Vec::new())
        .unwrap();
    w.retain_range(1..3).unwrap();
    w.add_agent(copy.state, copy.goals.clone()).unwrap();
    assert_eq!(w.add_agent(copy.state, copy.goals), Err(full(1)));
    w.step(&table).unwrap();
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
    assert_eq!(w.agents().len(), 3, "nothing added");

    // A slice keeps its world's bound (it only ever has fewer agents).
    w.retain_range(1..3).unwrap();
    assert_eq!(w.max_agents(), 3);
    w.spawn_random(1, 7, 10.0, 1.3).unwrap();
    assert!(w.spawn_random(1, 7, 10.0, 1.3).is_err());

    // A random crowd counts whole: none of it is added past the bound.
    let mut w = World::new(VehicleParams::default(), FunnelConfig::default()).unwrap();
    w.set_max_agents(10);
    assert!(w.spawn_random(11, 1, 10.0, 1.3).is_err());
    assert!(w.agents().is_empty());
    w.spawn_random(10, 1, 10.0, 1.3).unwrap();
    assert_eq!(w.agents()[0].goals.len(), RANDOM_GOALS);
}

#[test]
fn done_on_a_halting_goal_is_the_rest_pose_inside_both_tolerances_and_at_rest_follows() {
    let table = common::table();
    let mut w = World::new(VehicleParams::default(), FunnelConfig::default()).unwrap();
    let g = oriented(8.0, 4.0, 90.0, true);
    w.add_agent(VehicleState::default(), vec![g]).unwrap();
    let (mut done_at, mut moving_when_done) = (None, 0.0);
    while !w.agents()[0].at_rest() {
        w.step(&table).unwrap();
        let a = &w.agents()[0];
        if a.done() && done_at.is_none() {
            done_at = Some(w.time());
            moving_when_done = a.state.v;
        }
        assert!(w.time() < 60.0, "comes to rest within a minute");
    }
    let done_at = done_at.unwrap();
    assert!(
        moving_when_done > 0.0,
        "done while still braking ({moving_when_done} m/s)"
    );
    assert!(w.time() > done_at, "at rest after done");
    let a = &w.agents()[0];
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
        w.step(&table).unwrap();
    }
    assert!(w.agents()[0].done() && !w.agents()[0].at_rest());
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
                w.step(table).unwrap();
                w.write_state(&mut buf);
            } else {
                w.step_writing(table, &mut buf).unwrap();
            }
            common::fnv(&mut h, &buf);
        }
    });
    (h, w)
}

/// Every agent's state, memory and metrics as bits (f32 `==` would call
/// −0 and 0 equal).
fn bits(w: &World) -> Vec<u32> {
    w.agents()
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
        assert_eq!(w1.time().to_bits(), wn.time().to_bits());
        let moved = w1
            .agents()
            .iter()
            .filter(|a| a.metrics.length > 2.0)
            .count();
        assert!(
            moved > w1.agents().len() / 2,
            "{name}: only {moved} agents went 2 m"
        );
    }
}
