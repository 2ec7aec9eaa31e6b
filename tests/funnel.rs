//! Funnelling control (paper 000 §4–6): modes, limits, reach statistics,
//! asymptotic seek, moving and successive targets, scenario files.
#![cfg(not(target_arch = "wasm32"))]

use glam::Vec2;
use steering::base::angle::diff;
use steering::base::vehicle::{VehicleParams, VehicleState};
use steering::funnelling::config::FunnelConfig;
use steering::funnelling::goal::{FunnelMemory, Goal};
use steering::funnelling::table::lookup::EtaTable;
use steering::funnelling::update::{Mode, Update};
use steering::studies::reach::{run, summarise, ReachStudy};
use steering::world::scenario::Scenario;
use steering::world::{goals::GoalMotion, goals::GoalSpec, goals::SwitchRule, World};

mod common;
use common::table;

/// One plan of the funnelling update itself: the memory says the
/// short-range choice is made and is funnelling
/// (`steering::funnelling::short_range`), so Fig. 5's modes are what is tested.
fn plan(t: &EtaTable, s: VehicleState, g: &Goal) -> steering::funnelling::update::Internals {
    FunnelConfig::default().plan(&mut Update {
        table: t,
        params: &VehicleParams::default(),
        state: &mut s.clone(),
        goal: g,
        memory: &mut funnelling_memory(),
    })
}

/// A fresh memory whose short-range choice is funnelling.
fn funnelling_memory() -> FunnelMemory {
    FunnelMemory {
        short_range: steering::funnelling::goal::ShortRange::restored(),
        ..FunnelMemory::default()
    }
}

#[test]
fn mode_choice_follows_paper_fig5() {
    let t = table();
    let g = Goal {
        pos: Vec2::new(0.1, 0.0),
        beta: 0.0,
        ..Default::default()
    };
    // Inside both tolerances.
    assert_eq!(
        plan(&t, VehicleState::new(Vec2::ZERO, 0.02, 0.0, 0.0), &g).mode,
        Mode::EndOfSteering
    );
    // Inside the position tolerance, wrong heading.
    assert_eq!(
        plan(&t, VehicleState::new(Vec2::ZERO, 1.0, 0.0, 0.0), &g).mode,
        Mode::OrientationOnly
    );
    // Closer than D_η but outside D_tol: plain seek.
    let g = Goal {
        pos: Vec2::new(0.4, 0.0),
        beta: 2.0,
        ..Default::default()
    };
    assert_eq!(
        plan(&t, VehicleState::default(), &g).mode,
        Mode::PositionOnly
    );
    // Far, orientation already what seek would give: plain seek.
    let g = Goal {
        pos: Vec2::new(10.0, 0.0),
        beta: 0.0,
        ..Default::default()
    };
    let i = plan(&t, VehicleState::new(Vec2::ZERO, 0.0, 1.0, 0.0), &g);
    assert_eq!(i.mode, Mode::PositionOnly);
    assert!(i.eta.abs() < 0.01 && i.delta_eta.abs() < 0.05, "{i:?}");
    // Far, perpendicular orientation: funnelling, μ opposes Δη and is bounded.
    let g = Goal {
        pos: Vec2::new(10.0, 0.0),
        beta: 1.5,
        ..Default::default()
    };
    let i = plan(&t, VehicleState::new(Vec2::ZERO, 0.0, 1.0, 0.0), &g);
    assert_eq!(i.mode, Mode::Funnelling);
    assert!(
        i.mu < 0.0 && i.mu.abs() <= i.mu_max + 1e-6 && i.mu_max > 0.0,
        "{i:?}"
    );
    assert!((diff(i.gamma, i.alpha + i.mu)).abs() < 1e-5);
}

#[test]
fn reach_statistics_and_limits_on_seeded_random_scenarios() {
    // 2,000 of the reach study's scenarios in CI (`steer reach` runs
    // 10,000); limits are checked at every step of every run.
    let t = table();
    let p = VehicleParams::default();
    let study = ReachStudy {
        n: 2_000,
        seed: 5,
        ..Default::default()
    };
    let s = summarise(&study.run_all(&t, &p, &FunnelConfig::default()));
    eprintln!("{s:?}");
    assert_eq!(
        s.violations, 0,
        "a limit was violated or a value was not finite"
    );
    assert!(s.reach_rate >= 0.995, "reach {}", s.reach_rate);
    // Measured on these 2,000: reach 100 %, oriented on entry 96.8 %,
    // entry and final orientation error median 0.9°, p95 3.7°.
    assert!(
        s.oriented_rate >= 0.95,
        "oriented on entry {}",
        s.oriented_rate
    );
    assert!(
        s.entry_err_deg.1 <= 5.0,
        "entry orientation p95 {}",
        s.entry_err_deg.1
    );
    assert!(
        s.final_err_deg.1 <= 5.0,
        "final orientation p95 {}",
        s.final_err_deg.1
    );
    // The default bound was tuned on the whole envelope (`steer envelope`), where
    // its median is 1.09; at this single operating point its 8 turning
    // radii cost length: measured 1.167 (the 6 radii tuned here: 1.11).
    assert!(
        s.length_ratio.0 <= 1.2,
        "median length / Dubins {}",
        s.length_ratio.0
    );
}

/// Largest lateral deviation of the funnelling path from the plain seek
/// path over the first half of the path, for 200 targets at distance in
/// `[lo, hi]` (any bearing, any β): median, p90 and max, in metres.
fn deviation_from_seek(lo: f32, hi: f32) -> (f32, f32, f32) {
    let t = table();
    let p = VehicleParams::default();
    let cfg = FunnelConfig::default();
    let mut devs = Vec::new();
    let mut rng = steering::base::rng::Rng::new(11);
    for _ in 0..200 {
        let d = rng.range(lo, hi);
        let bearing = rng.range(-3.1, 3.1);
        let beta = rng.range(-3.1, 3.1);
        let start = VehicleState::new(Vec2::ZERO, 0.0, 1.0, 0.0);
        let g = Goal {
            pos: Vec2::from_angle(bearing) * d,
            beta,
            ..Default::default()
        };
        let steps = (4.0 * hi / g.speed / p.dt) as usize;
        let f = {
            let mut s = start;
            let mut mem = FunnelMemory::default();
            let mut pts = vec![s.pos];
            for _ in 0..steps {
                let mut u = Update {
                    table: &t,
                    params: &p,
                    state: &mut s,
                    goal: &g,
                    memory: &mut mem,
                };
                if cfg.step(&mut u).mode == Mode::EndOfSteering {
                    break;
                }
                pts.push(s.pos);
            }
            pts
        };
        // The plain seek path (paper 000 §3) to the same point.
        let sk = {
            let mut s = start;
            let mut pts = vec![s.pos];
            while (g.pos - s.pos).length() > g.d_tol && pts.len() < steps {
                steering::funnelling::seek::seek_point(&p, &mut s, g.pos, g.speed);
                pts.push(s.pos);
            }
            pts
        };
        // Distance from each point of the funnel's first half to the seek path.
        let half = f.len() / 2;
        let dev = f[..half]
            .iter()
            .map(|q| {
                sk.windows(2)
                    .map(|w| seg_dist(*q, w[0], w[1]))
                    .fold(f32::INFINITY, f32::min)
            })
            .fold(0.0f32, f32::max);
        devs.push(dev);
    }
    let med = steering::base::metrics::percentile(&mut devs, 0.5);
    let p90 = steering::base::metrics::percentile(&mut devs, 0.9);
    let max = steering::base::metrics::percentile(&mut devs, 1.0);
    eprintln!("lateral deviation from seek over the first half, D in [{lo}, {hi}] m: median {med:.2} m, p90 {p90:.2} m, max {max:.2} m");
    (med, p90, max)
}

/// Paper 000 §4: the μ bound vanishes as D grows, so distant targets are
/// approached like a seek. The deviation is bounded, and relative to the
/// distance it shrinks as the target gets farther.
#[test]
fn distant_targets_are_approached_like_a_seek() {
    let (med, _, max) = deviation_from_seek(20.0, 30.0);
    // Measured: median 3.4 m, p90 3.7 m, max 5.4 m (README figures).
    assert!(med < 4.5 && max < 8.0, "median {med}, max {max}");
    // Three times farther: measured median 3.4 m, max 3.7 m, the same
    // swing of a few turning radii, i.e. a third of the deviation per metre.
    let (far_med, _, far_max) = deviation_from_seek(60.0, 90.0);
    assert!(far_med / 75.0 < 0.7 * med / 25.0, "{far_med} vs {med}");
    assert!(far_max < 10.0, "{far_max}");
}

/// Targets behind the vehicle: η flips sign there, so the modulated
/// heading can hop across the ±π seam of the heading error from one update
/// to the next. Fed to the plain PD law, each hop reversed the commanded
/// turn and these 23 of the 10,000 `steer reach` scenarios drove straight
/// away from their target for the whole minute; the funnel's committed
/// step (`seek::seek_step_committed`) keeps turning the way it turns, and
/// every one arrives.
#[test]
fn targets_behind_are_turned_to_not_chattered_at() {
    let t = table();
    let p = VehicleParams::default();
    let cfg = FunnelConfig::default();
    let study = ReachStudy::default();
    let chattered = [
        328, 763, 845, 856, 1166, 1606, 2448, 2547, 3557, 5222, 5226, 5290, 5422, 5604, 5875, 5901,
        6380, 6693, 8206, 8298, 8486, 9500, 9569,
    ];
    let mut plain_failures = 0;
    for i in chattered {
        let (start, g) = study.scenario(&p, i);
        let r = run(&t, &p, &cfg, start, &g, study.max_time);
        assert!(r.reached, "scenario {i} not reached");
        // The same plan with the plain (uncommitted) seek step, funnelling
        // (not turning first) near the target as well.
        let mut s = start;
        let mut mem = funnelling_memory();
        let arrived = (0..(study.max_time / p.dt) as u32).any(|_| {
            let o = cfg.plan(&mut Update {
                table: &t,
                params: &p,
                state: &mut s,
                goal: &g,
                memory: &mut mem,
            });
            steering::funnelling::seek::seek_step(&p, &mut s, o.gamma, o.v_dt);
            o.mode == Mode::EndOfSteering
        });
        plain_failures += usize::from(!arrived);
    }
    assert!(plain_failures >= 20, "{plain_failures} of 23");
}

fn seg_dist(q: Vec2, a: Vec2, b: Vec2) -> f32 {
    let ab = b - a;
    let t = ((q - a).dot(ab) / ab.length_squared().max(1e-12)).clamp(0.0, 1.0);
    (a + ab * t - q).length()
}

#[test]
fn halting_arrives_at_rest_inside_the_tolerance() {
    let t = table();
    let p = VehicleParams::default();
    let g = Goal {
        pos: Vec2::new(8.0, 3.0),
        beta: 1.0,
        halting: true,
        ..Default::default()
    };
    let r = run(
        &t,
        &p,
        &FunnelConfig::default(),
        VehicleState::new(Vec2::ZERO, 0.0, 1.2, 0.0),
        &g,
        60.0,
    );
    assert!(r.reached);
    let mut w = World::new(p, FunnelConfig::default()).unwrap();
    w.add_agent(
        VehicleState::new(Vec2::ZERO, 0.0, 1.2, 0.0),
        vec![GoalSpec {
            goal: g,
            ..Default::default()
        }],
    )
    .unwrap();
    for _ in 0..(30.0 / p.dt) as usize {
        w.step(&t).unwrap();
    }
    let a = &w.agents()[0];
    assert!(a.done());
    assert!(a.state.v < 1e-3, "speed {}", a.state.v);
    assert!((a.state.pos - g.pos).length() < g.d_tol + 0.05);
    assert!(diff(g.beta, a.state.theta).abs() < g.eps_tol);
}

#[test]
fn moving_and_successive_targets() {
    let t = table();
    let p = VehicleParams::default();
    let mut w = World::new(p, FunnelConfig::default()).unwrap();
    let moving = GoalSpec {
        goal: Goal {
            pos: Vec2::new(10.0, 0.0),
            beta: 1.57,
            d_tol: 0.4,
            eps_tol: 0.17,
            ..Default::default()
        },
        motion: GoalMotion::Linear {
            velocity: Vec2::new(0.0, 0.3),
        },
        switch: SwitchRule::EndOfSteering,
    };
    let second = GoalSpec {
        goal: Goal {
            pos: Vec2::new(0.0, 8.0),
            beta: 3.0,
            halting: true,
            ..Default::default()
        },
        switch: SwitchRule::Tolerance,
        ..Default::default()
    };
    w.add_agent(VehicleState::default(), vec![moving, second])
        .unwrap();
    let mut first_done_at = None;
    for _ in 0..(90.0 / p.dt) as usize {
        w.step(&t).unwrap();
        if first_done_at.is_none() && w.agents()[0].current == 1 {
            first_done_at = Some(w.time());
            let a = &w.agents()[0];
            let g = moving.at(w.time(), &[]);
            assert!(
                (a.state.pos - g.pos).length() < 0.6,
                "caught the moving target"
            );
        }
    }
    assert!(first_done_at.is_some(), "moving target never reached");
    assert!(w.agents()[0].done(), "second target never reached");
    assert_eq!(w.agents()[0].metrics.violations, 0);
}

#[test]
fn world_is_deterministic() {
    let t = table();
    let sc = Scenario::from_json(
        &std::fs::read_to_string(concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/scenarios/p000_fig7_variety.json"
        ))
        .unwrap(),
    )
    .unwrap();
    let run_it = || {
        let mut w = sc.world().unwrap();
        for _ in 0..1000 {
            w.step(&t).unwrap();
        }
        let mut buf = Vec::new();
        w.write_state(&mut buf);
        buf.iter().map(|x| x.to_bits()).collect::<Vec<_>>()
    };
    assert_eq!(run_it(), run_it());
}

#[test]
fn every_preset_loads_runs_and_finishes_without_violations() {
    let t = table();
    let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/scenarios");
    let mut n = 0;
    for e in std::fs::read_dir(dir).unwrap() {
        let path = e.unwrap().path();
        if path.extension().is_none_or(|x| x != "json")
            || !path
                .file_name()
                .unwrap()
                .to_string_lossy()
                .starts_with("p000")
        {
            continue;
        }
        let sc = Scenario::from_json(&std::fs::read_to_string(&path).unwrap()).unwrap();
        t.check_params(&sc.vehicle).unwrap();
        let mut w = sc.world().unwrap();
        for _ in 0..sc.steps() {
            w.step(&t).unwrap();
        }
        for (i, a) in w.agents().iter().enumerate() {
            assert_eq!(a.metrics.violations, 0, "{path:?} agent {i}");
            assert!(a.done(), "{path:?} agent {i} did not finish its goals");
        }
        n += 1;
    }
    assert!(n >= 5);
}

#[test]
fn bad_scenarios_get_clear_errors() {
    let e = Scenario::from_json("{\"name\": \"x\", \"agents\": [], \"speeed\": 1}")
        .unwrap_err()
        .to_string();
    assert!(e.contains("unknown field") && e.contains("speeed"), "{e}");
    let e = Scenario::from_json("{\"name\": \"x\", \"agents\": [{\"x\": 0, \"y\": 0, \"v\": 9}]}")
        .unwrap_err()
        .to_string();
    assert!(e.contains('v'), "{e}");
    let e = Scenario::from_json("{\"name\": \"x\", \"vehicle\": {\"kp\": -1}, \"agents\": []}")
        .unwrap_err()
        .to_string();
    assert!(e.contains("kp"), "{e}");
    let bad_face = r#"{"name": "x", "agents": [{"x": 0, "y": 0, "goals": [{"x": 1, "y": 1, "motion": {"kind": "faceAgent", "agent": 5, "distance": 0}}]}]}"#;
    assert!(Scenario::from_json(bad_face)
        .unwrap_err()
        .to_string()
        .contains("agent 5"));
    assert!(Scenario::from_json("not json")
        .unwrap_err()
        .to_string()
        .contains("line 1"));
    let nan_goal =
        r#"{"name": "x", "agents": [{"x": 0, "y": 0, "goals": [{"x": 1, "y": 1, "dTol": -1}]}]}"#;
    assert!(Scenario::from_json(nan_goal)
        .unwrap_err()
        .to_string()
        .contains("dTol"));
}
