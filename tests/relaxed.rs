//! Relaxed funnelling (paper 001 §4, Fig. 7): one unit test per branch of
//! the relaxed-direction procedure, a brute-force property test, the
//! controller's special situations (ring missing the disk, vehicle inside
//! the disk, disk behind across ±π), reach on seeded random region goals
//! and the paper 001 presets.
#![cfg(not(target_arch = "wasm32"))]

use core::f32::consts::PI;

use glam::Vec2;
use proptest::prelude::*;
use steering::base::vehicle::{VehicleParams, VehicleState};
use steering::funnelling::config::FunnelConfig;
use steering::funnelling::controller::{Controller, ControllerKind};
use steering::funnelling::goal::{FunnelMemory, Goal};
use steering::funnelling::relaxed::{
    interval_delta, relaxed_direction, Fig7Branch, RelaxedAim, RelaxedConfig, RelaxedInternals,
};
use steering::funnelling::table::lookup::EtaTable;
use steering::funnelling::update::Mode;
use steering::funnelling::update::Update;
use steering::studies::region::RegionStudy;
use steering::world::scenario::Scenario;
use steering::world::{goals::GoalMotion, goals::GoalSpec, goals::SwitchRule, World};

mod common;
use common::table;

fn close(a: f32, b: f32) -> bool {
    (a - b).abs() < 1e-4
}

// ---- Fig. 7, one test per branch -------------------------------------

#[test]
fn opposite_sign_centres_partial_overlap_goes_straight() {
    // F = [-0.5, 0.4] (centre < 0), T = [-0.1, 0.3] (centre > 0); F(0) =
    // -0.05 lies in T: Δη = 0, α_r = 0.
    let c = relaxed_direction(-0.3, 0.3, -0.5, 0.4, 0.1, 0.2);
    assert_eq!(c.branch, Fig7Branch::OppositeStraight);
    assert_eq!((c.alpha_r, c.delta_eta), (0.0, 0.0));
}

#[test]
fn opposite_sign_centres_overlap_takes_smallest_alpha_of_the_overlap() {
    // 𝒜 = [0.2, 0.6] excludes 0; F = [-0.2, 0.1], T = [0.05, 0.55]:
    // overlap [0.05, 0.1] maps to α ∈ [0.5333, 0.6]: α_r = 0.5333.
    let c = relaxed_direction(0.2, 0.6, -0.2, 0.1, 0.3, 0.25);
    assert_eq!(c.branch, Fig7Branch::OppositeOverlap);
    assert_eq!(c.delta_eta, 0.0);
    assert!(close(c.alpha_r, 0.2 + 0.25 / 0.3 * 0.4), "{c:?}");
}

#[test]
fn opposite_sign_centres_gap_takes_the_nearest_arc_end() {
    // F = [-0.6, -0.3], T = [0.2, 0.4]: the gap is 0.5 at α_max.
    let c = relaxed_direction(0.2, 0.6, -0.6, -0.3, 0.3, 0.1);
    assert_eq!(c.branch, Fig7Branch::OppositeGap);
    assert!(close(c.alpha_r, 0.6) && close(c.delta_eta, 0.5), "{c:?}");
}

#[test]
fn same_sign_centres_with_boundaries_straddling_zero_go_straight() {
    // F = [-0.2, 0.5], T = [-0.1, 0.3]: F(0) = 0.2667 ∈ T.
    let c = relaxed_direction(-0.4, 0.2, -0.2, 0.5, 0.1, 0.2);
    assert_eq!(c.branch, Fig7Branch::SameStraight);
    assert_eq!((c.alpha_r, c.delta_eta), (0.0, 0.0));
}

#[test]
fn same_sign_centres_overlap_and_gap() {
    // F = [0.5, 1.1] over 𝒜 = [0.3, 0.9].
    let c = relaxed_direction(0.3, 0.9, 0.5, 1.1, 0.9, 0.1);
    assert_eq!(c.branch, Fig7Branch::SameOverlap);
    assert_eq!(c.delta_eta, 0.0);
    assert!(close(c.alpha_r, 0.6), "{c:?}");
    let c = relaxed_direction(0.3, 0.9, 0.5, 1.1, 1.6, 0.1);
    assert_eq!(c.branch, Fig7Branch::SameGap);
    assert!(close(c.alpha_r, 0.9) && close(c.delta_eta, 0.4), "{c:?}");
    // Decreasing F (monotonic the other way): the overlap maps backwards.
    let c = relaxed_direction(0.3, 0.9, 1.1, 0.5, 0.9, 0.1);
    assert_eq!(c.delta_eta, 0.0);
    assert!(close(c.alpha_r, 0.3 + 0.1 / 0.6 * 0.6), "{c:?}");
}

#[test]
fn wrap_around_compares_modulo_two_pi() {
    // F = [2.9, 3.5] crosses +π; T = [-3.0, -2.8] ≡ [3.283, 3.483].
    let c = relaxed_direction(2.0, 2.8, 2.9, 3.5, -2.9, 0.1);
    assert_eq!(c.delta_eta, 0.0, "{c:?}");
    let f_lo = -3.0 + 2.0 * PI;
    assert!(close(c.alpha_r, 2.0 + (f_lo - 2.9) / 0.6 * 0.8), "{c:?}");
    // T = [-2.6, -2.4] ≡ [3.683, 3.883]: gap 0.183 above α_max.
    let c = relaxed_direction(2.0, 2.8, 2.9, 3.5, -2.5, 0.1);
    assert!(close(c.alpha_r, 2.8), "{c:?}");
    assert!(close(c.delta_eta, -2.6 + 2.0 * PI - 3.5), "{c:?}");
    // And across -π with T given near +π.
    let c = relaxed_direction(-2.8, -2.0, -3.5, -2.9, 3.0, 0.1);
    assert_eq!(c.delta_eta, 0.0, "{c:?}");
    // T covering every orientation: always straight or nearest to 0.
    let c = relaxed_direction(0.5, 1.0, 2.0, 2.5, -1.0, PI);
    assert_eq!((c.delta_eta, c.alpha_r), (0.0, 0.5));
}

// ---- Brute force under the monotonic hypothesis ------------------------

/// Distance of f to T + 2πZ, in f64, computed independently.
fn brute_gap(f: f64, tc: f64, tau: f64) -> f64 {
    let tau2 = 2.0 * std::f64::consts::PI;
    (-4..=4)
        .map(|k| {
            let lo = tc - tau + tau2 * f64::from(k);
            let hi = tc + tau + tau2 * f64::from(k);
            if f < lo {
                lo - f
            } else if f > hi {
                f - hi
            } else {
                0.0
            }
        })
        .fold(f64::INFINITY, f64::min)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(3000))]
    #[test]
    fn matches_a_brute_force_scan_of_the_arc(
        a_min in -PI..PI,
        width in 0.0f32..2.0,
        eta0 in -PI..PI,
        span in -3.0f32..3.0,
        tc in -PI..PI,
        tau in 0.002f32..1.2,
    ) {
        let a_max = (a_min + width).min(PI);
        let f_min = a_min + eta0;
        let f_max = f_min + span;
        let c = relaxed_direction(a_min, a_max, f_min, f_max, tc, tau);
        prop_assert!(c.alpha_r >= a_min - 1e-6 && c.alpha_r <= a_max + 1e-6);
        let n = 20_000;
        let (mut best, mut best_alpha) = (f64::INFINITY, f64::INFINITY);
        for i in 0..=n {
            let u = f64::from(i) / f64::from(n);
            let a = f64::from(a_min) + u * f64::from(a_max - a_min);
            let f = f64::from(f_min) + u * f64::from(span);
            let g = brute_gap(f, f64::from(tc), f64::from(tau));
            if g < best - 1e-12 {
                best = g;
            }
            if g == 0.0 {
                best_alpha = best_alpha.min(a.abs());
            }
        }
        let tol = 0.5f64.to_radians();
        prop_assert!((f64::from(c.delta_eta.abs()) - best).abs() <= tol,
            "|Δη| {} vs brute {}", c.delta_eta, best);
        if best_alpha.is_finite() {
            prop_assert_eq!(c.delta_eta, 0.0);
            prop_assert!((f64::from(c.alpha_r.abs()) - best_alpha).abs() <= tol,
                "|α_r| {} vs brute {}", c.alpha_r, best_alpha);
        }
        // The returned Δη is the gap at α_r (sign: target − prediction).
        if c.delta_eta != 0.0 {
            let u = if a_max > a_min { (c.alpha_r - a_min) / (a_max - a_min) } else { 0.0 };
            let f = f_min + u * span;
            prop_assert!((interval_delta(f, tc, tau) - c.delta_eta).abs() < 1e-4);
        }
    }
}

// ---- The controller ----------------------------------------------------

/// The paper's literal reading (ring arc 𝒜, Fig. 7).
fn paper() -> RelaxedConfig {
    RelaxedConfig {
        aim: RelaxedAim::PaperArc,
        ..Default::default()
    }
}

fn plan(
    t: &EtaTable,
    s: VehicleState,
    g: &Goal,
) -> (steering::funnelling::update::Internals, RelaxedInternals) {
    plan_with(&paper(), t, s, g)
}

fn plan_with(
    c: &RelaxedConfig,
    t: &EtaTable,
    s: VehicleState,
    g: &Goal,
) -> (steering::funnelling::update::Internals, RelaxedInternals) {
    let mut ri = RelaxedInternals::default();
    let mut u = Update {
        table: t,
        params: &VehicleParams::default(),
        state: &mut s.clone(),
        goal: g,
        memory: &mut FunnelMemory::default(),
    };
    let i = c.plan(&FunnelConfig::default(), &mut u, &mut ri);
    (i, ri)
}

/// A 2 m disk 8.5 m ahead and to the left, β 1 rad, τ 0.2 rad.
fn wide_disk_ahead() -> (VehicleState, Goal) {
    let g = Goal {
        pos: Vec2::new(8.0, 3.0),
        beta: 1.0,
        d_tol: 2.0,
        eps_tol: 0.2,
        ..Default::default()
    };
    (VehicleState::new(Vec2::ZERO, 0.0, 1.0, 0.0), g)
}

#[test]
fn relaxed_point_lies_in_the_disk_on_a_sampled_ring() {
    let t = table();
    let (s, g) = wide_disk_ahead();
    let (i, ri) = plan(&t, s, &g);
    assert!(
        ri.ring_sampled && t.distances().contains(&ri.ring),
        "{ri:?}"
    );
    let p = Vec2::new(ri.point_x, ri.point_y);
    assert!((p - g.pos).length() <= 0.8 * g.d_tol + 1e-3, "{ri:?}");
    assert!((p.length() - ri.ring).abs() < 1e-3);
    assert!(ri.arc_min <= ri.alpha_r && ri.alpha_r <= ri.arc_max);
    assert!(close(ri.t_max - ri.t_min, 2.0 * 0.25 * g.eps_tol));
    assert_ne!(ri.branch, Fig7Branch::None);
    assert!(matches!(i.mode, Mode::Funnelling | Mode::PositionOnly));
}

#[test]
fn ring_missing_the_disk_uses_the_centre_distance() {
    let t = table();
    // A 0.1 m disk at 20 m: the sampled rings around 20 m are metres apart.
    let d = t.distances();
    let mid = d
        .windows(2)
        .find(|w| w[0] > 10.0)
        .map(|w| 0.5 * (w[0] + w[1]))
        .unwrap();
    let g = Goal {
        pos: Vec2::new(mid, 0.0),
        beta: 0.5,
        d_tol: 0.1,
        eps_tol: 0.1,
        ..Default::default()
    };
    let (_, ri) = plan(&t, VehicleState::new(Vec2::ZERO, 0.0, 1.0, 0.0), &g);
    assert!(!ri.ring_sampled, "{ri:?}");
    assert!(close(ri.ring, mid));
    let p = Vec2::new(ri.point_x, ri.point_y);
    assert!((p - g.pos).length() <= 0.08 + 1e-3, "{ri:?}");
}

#[test]
fn inside_the_disk_only_the_orientation_is_completed() {
    let t = table();
    let g = Goal {
        pos: Vec2::new(1.0, 0.0),
        beta: 2.0,
        d_tol: 2.0,
        eps_tol: 0.2,
        ..Default::default()
    };
    let (i, ri) = plan(&t, VehicleState::new(Vec2::ZERO, 0.0, 0.5, 0.0), &g);
    assert_eq!(i.mode, Mode::OrientationOnly);
    assert_eq!(ri.branch, Fig7Branch::None);
    let (i, _) = plan(&t, VehicleState::new(Vec2::ZERO, 1.95, 0.5, 0.0), &g);
    assert_eq!(i.mode, Mode::EndOfSteering);
}

#[test]
fn disk_behind_the_vehicle_clips_the_arc_at_pi() {
    let t = table();
    let g = Goal {
        pos: Vec2::new(-6.0, 0.3),
        beta: 0.0,
        d_tol: 2.0,
        eps_tol: 0.3,
        ..Default::default()
    };
    let (_, ri) = plan(&t, VehicleState::new(Vec2::ZERO, 0.0, 1.0, 0.0), &g);
    assert!(ri.arc_max <= PI && ri.arc_min > 0.0, "{ri:?}");
    assert!(ri.alpha_r.is_finite() && ri.point_x.is_finite());
}

#[test]
fn relaxed_reach_on_seeded_random_region_goals() {
    let t = table();
    let p = VehicleParams::default();
    let study = RegionStudy::default();
    let ctl = Controller::Relaxed(FunnelConfig::default(), RelaxedConfig::default());
    let runs = study.run_all(&t, &p, &ctl);
    assert_eq!(runs.len(), 1000);
    let reached = runs.iter().filter(|r| r.reached).count();
    assert!(reached >= 995, "relaxed reach {reached} / 1000");
    assert_eq!(runs.iter().map(|r| r.path.violations).sum::<u32>(), 0);
}

#[test]
fn entry_aim_is_the_disk_entry_point_along_beta() {
    let t = table();
    let reach = t.params().reach_radius;
    let (s, g) = wide_disk_ahead();
    let (i, ri) = plan_with(&RelaxedConfig::default(), &t, s, &g);
    assert_eq!(ri.branch, Fig7Branch::EntryPoint);
    let aim = Vec2::new(ri.point_x, ri.point_y);
    let want = g.pos - Vec2::from_angle(g.beta) * (g.d_tol - reach);
    assert!((aim - want).length() < 1e-4, "{aim} vs {want}");
    assert!(close(ri.ring, aim.length()));
    assert!(matches!(i.mode, Mode::Funnelling | Mode::PositionOnly));
    // A disk no larger than the reach radius: the aim is the centre.
    let small = Goal { d_tol: 0.1, ..g };
    let (_, ri) = plan_with(&RelaxedConfig::default(), &t, s, &small);
    assert!((Vec2::new(ri.point_x, ri.point_y) - g.pos).length() < 1e-5);
}

/// Runs one start and goal queue in a world for at most `seconds`;
/// returns (closest approach to the first goal's centre, world).
fn drive(
    kind: ControllerKind,
    rc: RelaxedConfig,
    s: VehicleState,
    goals: &[Goal],
    seconds: f32,
) -> (f32, World) {
    let t = table();
    let p = VehicleParams::default();
    let mut w = World::new(p, FunnelConfig::default()).unwrap();
    w.set_controller(kind, rc).unwrap();
    let specs = goals
        .iter()
        .map(|g| GoalSpec {
            goal: *g,
            motion: GoalMotion::Static,
            switch: SwitchRule::EndOfSteering,
        })
        .collect();
    w.add_agent(s, specs).unwrap();
    let mut closest = f32::INFINITY;
    for _ in 0..(seconds / p.dt) as u32 {
        w.step(&t).unwrap();
        let a = &w.agents()[0];
        assert!(a.state.within_limits(&p), "{:?}", a.state);
        if a.current == 0 {
            closest = closest.min((a.state.pos - goals[0].pos).length());
        }
        if a.done() {
            break;
        }
    }
    (closest, w)
}

#[test]
fn issue_13_orbit_example_enters_the_disk_with_both_aims() {
    // At rest 1.18 m from a 0.1 m disk that lies behind; the paper's
    // relaxed point, inside the turning circle, is circled at 0.75 m/s for
    // the whole 150 s.
    let s = VehicleState::new(Vec2::new(11.155, 22.935), 165.44f32.to_radians(), 0.0, 0.0);
    let g = Goal {
        pos: Vec2::new(12.232, 22.456),
        beta: 144.28f32.to_radians(),
        d_tol: 0.1,
        eps_tol: 5f32.to_radians(),
        speed: 1.3,
        halting: false,
        vel: Vec2::ZERO,
    };
    for rc in [RelaxedConfig::default(), paper()] {
        let (closest, w) = drive(ControllerKind::Relaxed, rc, s, &[g], 150.0);
        assert!(closest < g.d_tol, "{:?}: closest {closest}", rc.aim);
        let done = w.agents()[0].finished_at.expect("finishes");
        assert!(done < 30.0, "{:?}: finished at {done} s", rc.aim);
    }
}

#[test]
fn three_goal_chain_that_stalled_finishes() {
    // Envelope chain (harness seed 1, case 21): the 0.1 m, 5° second goal
    // 0.58 m past the first was orbited by the paper's relaxed point.
    let s = VehicleState::new(Vec2::ZERO, 1.995_957, 0.672_546, -0.970_759);
    let goal = |x: f32, y: f32, beta: f32, d_tol: f32, eps_deg: f32, speed: f32| Goal {
        pos: Vec2::new(x, y),
        beta,
        d_tol,
        eps_tol: eps_deg.to_radians(),
        speed,
        halting: false,
        vel: Vec2::ZERO,
    };
    let goals = [
        goal(-29.003_305, -7.177_213, -2.860_961, 0.25, 20.0, 1.8),
        goal(-28.424_64, -7.252_057, 1.046_839, 0.1, 5.0, 2.0),
        goal(-32.582_22, -7.292_28, 1.669_705, 0.5, 10.0, 2.0),
    ];
    for rc in [RelaxedConfig::default(), paper()] {
        let (_, w) = drive(ControllerKind::Relaxed, rc, s, &goals, 450.0);
        assert!(
            w.agents()[0].done(),
            "{:?}: stuck on goal {}",
            rc.aim,
            w.agents()[0].current
        );
    }
}

#[test]
fn p001_presets_run_with_both_controllers() {
    let t = table();
    let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/scenarios");
    let mut n = 0;
    for e in std::fs::read_dir(dir).unwrap() {
        let path = e.unwrap().path();
        let name = path.file_name().unwrap().to_string_lossy().into_owned();
        if !name.starts_with("p001_") || !name.ends_with(".json") {
            continue;
        }
        let sc = Scenario::from_json(&std::fs::read_to_string(&path).unwrap()).unwrap();
        let want = if name.ends_with("_relaxed.json") {
            ControllerKind::Relaxed
        } else {
            ControllerKind::Standard
        };
        assert_eq!(sc.controller, want, "{name}");
        let mut w = sc.world().unwrap();
        assert_eq!(w.controller(), want);
        let mut saw_relaxed = false;
        for _ in 0..sc.steps() {
            w.step(&t).unwrap();
            saw_relaxed |= w.relaxed_internals(0).unwrap().branch != Fig7Branch::None;
        }
        assert_eq!(saw_relaxed, want == ControllerKind::Relaxed, "{name}");
        for (i, a) in w.agents().iter().enumerate() {
            assert_eq!(a.metrics.violations, 0, "{name} agent {i}");
            assert!(a.done(), "{name} agent {i} did not finish its goals");
        }
        n += 1;
    }
    assert!(n >= 16, "{n} p001 presets");
}

#[test]
fn scenario_controller_field_is_parsed_and_checked() {
    let sc = Scenario::from_json(
        r#"{"name": "x", "controller": "relaxed", "relaxed": {"diskMargin": 0.5}, "agents": []}"#,
    )
    .unwrap();
    assert_eq!(sc.controller, ControllerKind::Relaxed);
    assert_eq!(sc.relaxed.disk_margin, 0.5);
    let sc = Scenario::from_json(r#"{"name": "x", "agents": []}"#).unwrap();
    assert_eq!(sc.controller, ControllerKind::Standard);
    let e = Scenario::from_json(r#"{"name": "x", "controller": "lax", "agents": []}"#)
        .unwrap_err()
        .to_string();
    assert!(e.contains("lax"), "{e}");
    let e = Scenario::from_json(r#"{"name": "x", "relaxed": {"diskMargin": 3}, "agents": []}"#)
        .unwrap_err()
        .to_string();
    assert!(e.contains("diskMargin"), "{e}");
}

#[test]
fn ring_linear_eta_matches_the_table_at_samples_and_stays_close() {
    let t = table();
    let p = VehicleParams::default();
    let (n2, n3, n4) = (t.axis(2).len(), t.axis(3).len(), t.axis(4).len());
    let mut checked = 0;
    for ring in [0, 5, t.distances().len() - 1] {
        for ia in [0, 7, 20, t.axis(1).len() - 1] {
            let idx = [ring, ia, n2 / 2, n3 / 2, n4 / 2];
            let (eta, _, flags) = t.entry(idx);
            let v = t.axis(3)[idx[3]];
            let omega = t.axis(2)[idx[2]] * p.omega_limit(v);
            let got = t.eta_ring_linear(ring, t.axis(1)[ia], omega, v, t.axis(4)[idx[4]]);
            if flags & steering::funnelling::table::format::FLAG_ETA_VALID != 0 {
                assert!(
                    (got.unwrap() - eta).abs() < 1e-5,
                    "{idx:?}: {got:?} vs {eta}"
                );
                checked += 1;
            }
        }
    }
    assert!(checked > 0);
    assert_eq!(t.eta_ring_linear(999, 0.0, 0.0, 1.0, 1.0), None);
}
