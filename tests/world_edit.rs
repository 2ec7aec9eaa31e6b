//! Edits of a running world as the lab page makes them (the logic lives
//! in the core, the bindings only convert): a pose reset or a
//! new goal restarts the queue and the mode memory (paper 000 Fig. 5), bad
//! input is an error that changes nothing, and the random crowd of the
//! performance runs is seeded, inside its square and under the agent limit.
#![cfg(not(target_arch = "wasm32"))]

use glam::Vec2;
use steering::base::vehicle::{VehicleParams, VehicleState};
use steering::funnelling::config::FunnelConfig;
use steering::funnelling::goal::{FunnelMemory, Goal};
use steering::world::edit::{EditError, MAX_AGENTS, RANDOM_GOALS};
use steering::world::{goals::GoalMotion, goals::GoalSpec, goals::SwitchRule, World};

mod common;
use common::table;

fn world() -> World {
    World::new(VehicleParams::default(), FunnelConfig::default()).unwrap()
}

fn spec(x: f32, beta: f32, switch: SwitchRule) -> GoalSpec {
    GoalSpec {
        goal: Goal {
            pos: Vec2::new(x, 0.0),
            beta,
            ..Default::default()
        },
        motion: GoalMotion::Static,
        switch,
    }
}

/// One agent at the origin with two goals: (3, 0) passed on entering its
/// tolerance, then (3.1, 0) facing back, which it enters at once and must
/// turn for (Orientation_only, position latched).
fn two_goal_world() -> World {
    let mut w = world();
    w.add_agent(
        VehicleState::default(),
        vec![
            spec(3.0, 0.0, SwitchRule::Tolerance),
            spec(3.1, core::f32::consts::PI, SwitchRule::EndOfSteering),
        ],
    )
    .unwrap();
    w
}

#[test]
fn a_pose_reset_restarts_the_queue_and_the_memory() {
    let t = table();
    let mut w = two_goal_world();
    let mut steps = 0;
    while !(w.agents()[0].current == 1 && w.agents()[0].memory.position_met) {
        w.step(&t).unwrap();
        steps += 1;
        assert!(steps < 2_000, "the first goal is passed within 20 s");
    }
    assert!(w.agents()[0].state.v > 0.0);
    w.set_pose(0, Vec2::new(-1.0, 2.0), 7.0).unwrap();
    let a = &w.agents()[0];
    assert_eq!(a.current, 0);
    assert_eq!(a.memory, FunnelMemory::default());
    assert_eq!(a.finished_at, None);
    assert_eq!(a.goal_now.pos, Vec2::new(3.0, 0.0));
    assert_eq!(a.state.pos, Vec2::new(-1.0, 2.0));
    assert_eq!((a.state.v, a.state.omega), (0.0, 0.0));
    // 7 rad wraps to 7 − 2π.
    assert!((a.state.theta - (7.0 - core::f32::consts::TAU)).abs() < 1e-5);
}

#[test]
fn a_finished_agent_starts_again_on_a_new_goal() {
    let t = table();
    let mut w = world();
    w.add_agent(
        VehicleState::default(),
        vec![spec(2.0, 0.0, SwitchRule::Tolerance)],
    )
    .unwrap();
    for _ in 0..1_000 {
        w.step(&t).unwrap();
    }
    assert!(w.agents()[0].done());
    assert!(w.agents()[0].finished_at.is_some());
    w.set_goals(0, vec![spec(-4.0, 1.0, SwitchRule::EndOfSteering)])
        .unwrap();
    let a = &w.agents()[0];
    assert!(!a.done());
    assert_eq!(a.finished_at, None);
    assert_eq!(a.goal_now.pos, Vec2::new(-4.0, 0.0));
    assert_eq!(a.goal_now.beta, 1.0);
}

#[test]
fn bad_edits_are_errors_that_change_nothing() {
    let mut w = two_goal_world();
    let before = w.clone();
    let e = w.set_pose(5, Vec2::ZERO, 0.0).unwrap_err();
    assert_eq!(e, EditError::NoAgent { index: 5, count: 1 });
    assert_eq!(e.to_string(), "no agent 5 (there are 1)");
    let e = w.set_pose(0, Vec2::new(f32::NAN, 0.0), 0.0).unwrap_err();
    assert!(matches!(e, EditError::Param(_)), "{e}");
    assert!(e.to_string().contains("pos.x"), "{e}");
    let e = w.set_pose(0, Vec2::ZERO, f32::INFINITY).unwrap_err();
    assert!(e.to_string().contains("theta"), "{e}");
    let e = w
        .set_goals(1, vec![spec(1.0, 0.0, SwitchRule::Tolerance)])
        .unwrap_err();
    assert_eq!(e, EditError::NoAgent { index: 1, count: 1 });
    let mut bad = spec(1.0, 0.0, SwitchRule::Tolerance);
    bad.goal.d_tol = 0.0;
    let e = w.set_goals(0, vec![bad]).unwrap_err();
    assert!(e.to_string().contains("goal.dTol"), "{e}");
    let mut moving = spec(1.0, 0.0, SwitchRule::Tolerance);
    moving.motion = GoalMotion::Linear {
        velocity: Vec2::new(0.0, f32::NAN),
    };
    let e = w.set_goals(0, vec![moving]).unwrap_err();
    assert!(e.to_string().contains("motion.velocity.y"), "{e}");
    assert_eq!(w, before);
}

#[test]
fn the_random_crowd_is_seeded_and_stays_in_its_square() {
    let mut a = world();
    let mut b = world();
    a.spawn_random(200, 9, 12.5, 1.3).unwrap();
    b.spawn_random(200, 9, 12.5, 1.3).unwrap();
    assert_eq!(a, b);
    let mut c = world();
    c.spawn_random(200, 10, 12.5, 1.3).unwrap();
    assert_ne!(a.agents()[0].state, c.agents()[0].state);
    assert_eq!(a.agents().len(), 200);
    let inside = |p: Vec2| p.x.abs() <= 12.5 && p.y.abs() <= 12.5;
    for ag in a.agents() {
        assert!(inside(ag.state.pos), "{:?}", ag.state.pos);
        assert_eq!((ag.state.v, ag.state.omega), (0.0, 0.0));
        assert_eq!(ag.goals.len(), RANDOM_GOALS);
        for g in &ag.goals {
            assert!(inside(g.goal.pos), "{:?}", g.goal.pos);
            assert_eq!(g.goal.speed, 1.3);
            assert_eq!(g.switch, SwitchRule::Tolerance);
        }
    }
    // Spread over the square, not bunched: each quadrant holds a quarter
    // of the 3,400 poses and goals (binomial σ ≈ 25).
    let points: Vec<Vec2> = a
        .agents()
        .iter()
        .flat_map(|ag| core::iter::once(ag.state.pos).chain(ag.goals.iter().map(|g| g.goal.pos)))
        .collect();
    assert_eq!(points.len(), 200 * (1 + RANDOM_GOALS));
    for (sx, sy) in [(1.0, 1.0), (-1.0, 1.0), (-1.0, -1.0), (1.0, -1.0)] {
        let n = points
            .iter()
            .filter(|p| p.x * sx > 0.0 && p.y * sy > 0.0)
            .count();
        assert!(
            (750..=950).contains(&n),
            "quadrant ({sx}, {sy}): {n} of 3,400"
        );
    }
    // The desired speed is clamped to [0.1, v_max].
    let mut d = world();
    d.spawn_random(1, 9, 12.5, 50.0).unwrap();
    assert_eq!(d.agents()[0].goals[0].goal.speed, d.params().v_max);
    // A random crowd steps like any other.
    let t = table();
    for _ in 0..50 {
        a.step(&t).unwrap();
    }
    assert!(a
        .agents()
        .iter()
        .all(|ag| ag.state.within_limits(a.params())));
}

#[test]
fn the_random_crowd_refuses_bad_squares_and_too_many_agents() {
    let mut w = world();
    for extent in [f32::NAN, 0.0, -3.0, 2e5] {
        let e = w.spawn_random(1, 1, extent, 1.0).unwrap_err();
        assert!(e.to_string().contains("extent"), "{extent}: {e}");
    }
    // The page's bound (a world's own is the caller's choice).
    w.set_max_agents(MAX_AGENTS);
    let e = w.spawn_random(MAX_AGENTS + 1, 1, 10.0, 1.0).unwrap_err();
    assert_eq!(
        e,
        EditError::TooManyAgents {
            adding: MAX_AGENTS + 1,
            count: 0,
            max: MAX_AGENTS
        }
    );
    w.spawn_random(1, 1, 10.0, 1.0).unwrap();
    let e = w.spawn_random(MAX_AGENTS, 1, 10.0, 1.0).unwrap_err();
    assert!(e.to_string().contains("would exceed 100001"), "{e}");
    assert_eq!(w.agents().len(), 1);
    assert!(w.check_room(MAX_AGENTS - 1).is_ok());
}

/// A queue replaced through the world (the only way: the agents are not
/// public) with a goal facing another agent: the step plans towards it (the
/// world keeps a copy of each current goal and a count of facing queues;
/// debug builds, as the tests run, check both at each plan).
#[test]
fn queues_set_through_the_world_are_picked_up() {
    let t = table();
    let mut w = world();
    w.spawn_random(2, 3, 10.0, 1.3).unwrap();
    let mut g = w.agents()[1].goals[0];
    g.motion = GoalMotion::FaceAgent {
        agent: 0,
        distance: 2.0,
    };
    w.set_goals(1, vec![g]).unwrap();
    let s0 = w.agents()[0].state;
    w.step(&t).unwrap();
    assert_eq!(w.agents()[1].current, 0);
    assert_eq!(w.agents()[1].goal_now.pos, s0.pos + s0.forward() * 2.0);
}
