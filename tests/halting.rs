//! Halting goals: End_of_Steering on a
//! halting goal means the vehicle comes to rest inside both tolerances;
//! a goal that moves by itself cannot be halting; the first trajectory row
//! reports the mode chosen at t = 0.
#![cfg(not(target_arch = "wasm32"))]

use glam::Vec2;
use steering::base::vehicle::{VehicleParams, VehicleState};
use steering::funnelling::approach::halting_speed;
use steering::funnelling::approach::{braking_distance, rest_rotation};
use steering::funnelling::controller::ControllerKind;
use steering::funnelling::goal::Goal;
use steering::funnelling::relaxed::RelaxedConfig;
use steering::funnelling::seek::seek_step;
use steering::funnelling::table::lookup::EtaTable;
use steering::funnelling::update::Mode;
use steering::studies::envelope::{run, variants, EnvelopeStudy, GoalKind};
use steering::world::scenario::Scenario;
use steering::world::{
    goals::GoalMotion, goals::GoalSpec, goals::SwitchRule, goals::MOVING_HALTING, World,
};

mod common;
use common::table;

fn state(x: f32, y: f32, theta_deg: f32, v: f32) -> VehicleState {
    VehicleState::new(Vec2::new(x, y), theta_deg.to_radians(), v, 0.0)
}

fn halting_goal(x: f32, y: f32, beta_deg: f32, d_tol: f32, eps_deg: f32, speed: f32) -> GoalSpec {
    GoalSpec {
        goal: Goal {
            pos: Vec2::new(x, y),
            beta: beta_deg.to_radians(),
            d_tol,
            eps_tol: eps_deg.to_radians(),
            speed,
            halting: true,
            vel: Vec2::ZERO,
        },
        motion: GoalMotion::Static,
        switch: SwitchRule::EndOfSteering,
    }
}

/// Runs one agent to its End_of_Steering and then to rest; returns the
/// distance and heading error (degrees) at the declaration and at rest.
fn run_to_rest(
    table: &EtaTable,
    kind: ControllerKind,
    start: VehicleState,
    g: GoalSpec,
) -> [f32; 4] {
    let p = VehicleParams::default();
    let mut w = World::new(p, Default::default()).unwrap();
    w.set_controller(kind, RelaxedConfig::default()).unwrap();
    w.add_agent(start, vec![g]).unwrap();
    let err = |s: &VehicleState| {
        (
            (g.goal.pos - s.pos).length(),
            steering::base::angle::diff(g.goal.beta, s.theta)
                .abs()
                .to_degrees(),
        )
    };
    let mut at_eos = None;
    for _ in 0..60 * 120 {
        let before = w.agents()[0].state;
        w.step(table).unwrap();
        let a = &w.agents()[0];
        if at_eos.is_none() && a.done() {
            assert_eq!(a.internals.mode, Mode::EndOfSteering);
            at_eos = Some(err(&before));
        }
        if at_eos.is_some() && a.state.v == 0.0 && a.state.omega.abs() < 1e-4 {
            break;
        }
    }
    let (d0, e0) = at_eos.expect("End_of_Steering declared within two minutes");
    let a = &w.agents()[0];
    assert_eq!(a.state.v, 0.0, "at rest");
    let (d1, e1) = err(&a.state);
    [d0, e0, d1, e1]
}

#[test]
fn issue_examples_rest_inside_both_tolerances() {
    let table = table();
    // Rested 13° off (ε_tol 10°): End_of_Steering was declared while the
    // vehicle still turned.
    let [d0, e0, d1, e1] = run_to_rest(
        &table,
        ControllerKind::Standard,
        state(4.736, 49.603, -154.97, 1.756),
        halting_goal(3.17, 53.364, -96.93, 0.25, 10.0, 1.0),
    );
    assert!(d0 < 0.25 && e0 < 10.0, "declared at {d0} m, {e0}°");
    assert!(d1 < 0.25 && e1 < 10.0, "rests at {d1} m, {e1}°");
    // Rested 1.14 m from the centre (D_tol 1 m): it started inside the
    // disk at 1.68 m/s, braked out of it and declared End_of_Steering there.
    let [d0, e0, d1, e1] = run_to_rest(
        &table,
        ControllerKind::Standard,
        state(48.796, -23.11, 92.58, 1.678),
        halting_goal(49.364, -22.96, -108.2, 1.0, 2.0, 2.0),
    );
    assert!(d0 < 1.0 && e0 < 2.0, "declared at {d0} m, {e0}°");
    assert!(d1 < 1.0 && e1 < 2.0, "rests at {d1} m, {e1}°");
}

#[test]
fn rest_prediction_bounds_the_simulated_braking() {
    // Braking with the heading held (End_of_Steering, and the world after
    // the last halting goal): the path is never longer than
    // braking_distance and the heading turns by rest_rotation within a
    // degree, over the whole admissible (v, ω) range.
    let p = VehicleParams::default();
    let mut worst_turn = 0.0f32;
    for i in 0..=20 {
        for j in -10..=10 {
            let v = p.v_max * i as f32 / 20.0;
            let w = p.omega_limit(v) * j as f32 / 10.0;
            let mut s = VehicleState::new(Vec2::ZERO, 0.0, v, w);
            let mut length = 0.0;
            let mut turn = 0.0;
            for _ in 0..600 {
                let (p0, th0) = (s.pos, s.theta);
                let hold = s.theta;
                seek_step(&p, &mut s, hold, 0.0);
                length += (s.pos - p0).length();
                turn += steering::base::angle::diff(s.theta, th0);
            }
            assert!(s.v == 0.0 && s.omega.abs() < 1e-6, "{s:?}");
            assert!(length <= braking_distance(&p, v) + 1e-5, "v {v}: {length}");
            let pred = rest_rotation(&p, w);
            assert!(
                pred.abs() >= turn.abs() - 1e-5 && pred * turn >= 0.0,
                "ω {w}: {pred} vs {turn}"
            );
            worst_turn = worst_turn.max((pred - turn).abs());
        }
    }
    assert!(
        worst_turn < 1f32.to_radians(),
        "margin {}°",
        worst_turn.to_degrees()
    );
    // The halting cap and the braking disk agree: at the cap's speed the
    // vehicle 0.95·D_tol from the centre can still stop inside D_tol.
    let d_tol = 0.25;
    let v = halting_speed(&p, 0.95 * d_tol - 0.9 * d_tol);
    assert!(0.9 * d_tol + braking_distance(&p, v) < d_tol);
}

#[test]
fn every_halting_run_of_the_envelope_rests_inside_both_tolerances() {
    // Seed 3 (tests only; seed 1 tunes, seed 2 reports): every halting run
    // of the standard controller, static and chained, rests inside both
    // tolerances, and every End_of_Steering on a halting goal is declared
    // inside both.
    let study = EnvelopeStudy {
        seed: 3,
        n_static: 400,
        n_moving: 0,
        n_chain: 80,
        ..Default::default()
    };
    let p = VehicleParams::default();
    let table = table();
    let std = variants()[0];
    assert_eq!(std.name, "standard");
    let mut halting = 0;
    for kind in [GoalKind::Static, GoalKind::Chain] {
        for i in 0..study.count(kind) {
            let sc = study.scenario(&p, kind, i);
            let r = run(&table, &p, &std.controller, &sc, study.max_time);
            assert!(r.finished, "{kind:?} #{i}: {r:?}");
            if r.halting {
                halting += 1;
                assert!(r.rest_ok, "{kind:?} #{i}: {r:?}");
                if kind == GoalKind::Static {
                    assert_eq!(r.eos_ok, r.eos, "{kind:?} #{i}: {r:?}");
                }
            }
        }
    }
    assert!(halting > 200, "{halting} halting runs");
}

#[test]
fn a_goal_that_moves_by_itself_cannot_be_halting() {
    let p = VehicleParams::default();
    let mut w = World::new(p, Default::default()).unwrap();
    let g = halting_goal(5.0, 0.0, 0.0, 0.25, 5.0, 1.3);
    let linear = GoalSpec {
        motion: GoalMotion::Linear {
            velocity: Vec2::new(0.3, 0.0),
        },
        ..g
    };
    let circle = GoalSpec {
        motion: GoalMotion::Circle {
            center: Vec2::ZERO,
            angular_speed: 0.2,
        },
        ..g
    };
    for spec in [linear, circle] {
        let e = w
            .add_agent(VehicleState::default(), vec![spec])
            .unwrap_err();
        assert!(
            e.to_string().starts_with("a moving goal cannot be halting"),
            "{e}"
        );
        assert_eq!(e.to_string(), MOVING_HALTING);
        // Not halting, the same goal is fine.
        let mut ok = spec;
        ok.goal.halting = false;
        w.add_agent(VehicleState::default(), vec![ok]).unwrap();
    }
    // A goal that does not move, or follows an agent that may stop, may halt.
    let still = GoalSpec {
        motion: GoalMotion::Linear {
            velocity: Vec2::ZERO,
        },
        ..g
    };
    let face = GoalSpec {
        motion: GoalMotion::FaceAgent {
            agent: 0,
            distance: 1.0,
        },
        ..g
    };
    w.add_agent(VehicleState::default(), vec![g, still, face])
        .unwrap();

    // Scenario files say which agent.
    let json = r#"{ "name": "x", "agents": [
        { "x": 0, "y": 0, "goals": [{ "x": 5, "y": 0 }] },
        { "x": 0, "y": 1, "goals": [{ "x": 5, "y": 1, "halting": true,
            "motion": { "kind": "linear", "velocity": [0.3, 0] } }] } ] }"#;
    let e = Scenario::from_json(json).unwrap_err().to_string();
    assert!(
        e.contains("agents[1].goals[0]: a moving goal cannot be halting"),
        "{e}"
    );
    assert!(Scenario::from_json(&json.replace("true", "false")).is_ok());
}

#[test]
fn every_shipped_scenario_still_loads() {
    // No preset combines halting with a goal that moves by itself (Fig. 6
    // faces other agents, which is allowed).
    let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/scenarios");
    let mut n = 0;
    for e in std::fs::read_dir(dir).unwrap() {
        let path = e.unwrap().path();
        if path.extension().is_some_and(|x| x == "json") {
            let text = std::fs::read_to_string(&path).unwrap();
            Scenario::from_json(&text)
                .and_then(|s| s.world())
                .unwrap_or_else(|e| panic!("{}: {e}", path.display()));
            n += 1;
        }
    }
    assert!(n >= 20, "{n} scenarios");
}

/// The first row's internals (after `plan`) are exactly what the first
/// step computes from the same state.
fn first_row_matches_first_step(json: &str, kind: ControllerKind) -> Vec<Mode> {
    let table = table();
    let mut sc = Scenario::from_json(json).unwrap();
    sc.controller = kind;
    let mut w = sc.world().unwrap();
    w.plan(&table).unwrap();
    let planned: Vec<_> = w
        .agents()
        .iter()
        .map(|a| (a.internals, a.relaxed))
        .collect();
    let states: Vec<_> = w.agents().iter().map(|a| a.state).collect();
    // Planning moves nothing.
    w.plan(&table).unwrap();
    assert_eq!(
        states,
        w.agents().iter().map(|a| a.state).collect::<Vec<_>>()
    );
    w.step(&table).unwrap();
    for (a, (i, r)) in w.agents().iter().zip(&planned) {
        assert_eq!(a.internals, *i);
        assert_eq!(a.relaxed, *r);
    }
    planned.iter().map(|(i, _)| i.mode).collect()
}

#[test]
fn first_trajectory_row_reports_the_mode_chosen_at_t0() {
    let json = r#"{ "name": "t0", "agents": [
        { "x": 0, "y": 0, "thetaDeg": 0, "v": 1,
          "goals": [{ "x": 8, "y": 3, "betaDeg": -90, "halting": true }] },
        { "x": 0, "y": 5, "thetaDeg": 0,
          "goals": [{ "x": 8, "y": 5, "betaDeg": 0 }] },
        { "x": 0, "y": 10, "thetaDeg": 3,
          "goals": [{ "x": 0.1, "y": 10, "betaDeg": 0, "epsTolDeg": 5 }] },
        { "x": 0, "y": 15, "thetaDeg": 90,
          "goals": [{ "x": 0.1, "y": 15, "betaDeg": 0 }] },
        { "x": 0, "y": 20, "goals": [] }
    ] }"#;
    let modes = first_row_matches_first_step(json, ControllerKind::Standard);
    assert_eq!(
        modes,
        [
            Mode::Funnelling,
            Mode::PositionOnly,
            Mode::EndOfSteering,
            Mode::OrientationOnly,
            Mode::EndOfSteering
        ]
    );
    let relaxed = first_row_matches_first_step(json, ControllerKind::Relaxed);
    assert_eq!(relaxed[2..], modes[2..]);
    // Fig. 6's agents face each other: goals that follow other agents.
    first_row_matches_first_step(
        include_str!("../scenarios/p000_fig6_face_to_face.json"),
        ControllerKind::Standard,
    );
    // Before any plan, the table-free part is already right inside the
    // tolerance and never claims End_of_Steering far from the goal.
    let w = Scenario::from_json(json).unwrap().world().unwrap();
    let provisional: Vec<Mode> = w.agents().iter().map(|a| a.internals.mode).collect();
    assert_eq!(provisional[0], Mode::Funnelling);
    assert_eq!(provisional[2..], modes[2..]);
}
