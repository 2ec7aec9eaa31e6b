//! Fidelity (issue 19): what each figure of the four texts *claims*,
//! measured on its preset and asserted, so a claim that stops holding
//! fails a test. Every test prints its figures (`--nocapture`); the README's
//! table "figure | preset | claim | our measurement | agrees?" quotes them,
//! and each preset's `claim` / `measured` fields (shown in the lab's side
//! panel) carry the same sentence. Fast: the whole file runs in seconds in
//! release; long studies live in `steer`.

use core::f32::consts::{PI, TAU};

use glam::Vec2;
use steering::angle::diff;
use steering::funnel::{Aim, FunnelConfig, Mode, MuBound};
use steering::relaxed::{ControllerKind, Fig7Branch, RelaxedAim};
use steering::scenario::Scenario;
use steering::table::EtaTable;
use steering::world::World;

mod common;
use common::table;

fn preset(name: &str) -> Scenario {
    let path = format!("{}/scenarios/{name}.json", env!("CARGO_MANIFEST_DIR"));
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"));
    Scenario::from_json(&text).unwrap_or_else(|e| panic!("{name}: {e}"))
}

/// Runs `sc` for its duration, calling `visit(world)` after every step.
fn run(t: &EtaTable, sc: &Scenario, mut visit: impl FnMut(&World)) -> World {
    let mut w = sc.world().expect("preset builds");
    let steps = (sc.duration / w.params.dt).round() as u32;
    for _ in 0..steps {
        w.step(t);
        visit(&w);
    }
    w
}

/// The paper's relaxed point (paper 001 Fig. 7 literally: `aim: paperArc`).
fn paper_arc(mut sc: Scenario) -> Scenario {
    sc.controller = ControllerKind::Relaxed;
    sc.relaxed.aim = RelaxedAim::PaperArc;
    sc
}

fn mean(v: &[f32]) -> f32 {
    v.iter().sum::<f32>() / v.len().max(1) as f32
}

/// Circular standard deviation of angles, rad.
fn circ_std(a: &[f32]) -> f32 {
    let (s, c) = a.iter().fold((0.0f32, 0.0f32), |(s, c), x| (s + x.sin(), c + x.cos()));
    let r = (s * s + c * c).sqrt() / a.len().max(1) as f32;
    (-2.0 * r.max(1e-9).ln()).sqrt()
}

// ---------------------------------------------------------------- paper 000

#[test]
fn p000_fig1_plain_seek_never_funnels_and_reaches_every_target() {
    let t = table();
    let sc = preset("p000_fig1_seek");
    assert_eq!(sc.controller, ControllerKind::Seek);
    let mut funnelled = 0;
    let w = run(&t, &sc, |w| {
        funnelled += w
            .agents
            .iter()
            .filter(|a| matches!(a.internals.mode, Mode::Funnelling | Mode::OrientationOnly))
            .count();
    });
    for (i, a) in w.agents.iter().enumerate() {
        let g = a.goals[0].goal;
        let d = a.state.pos.distance(g.pos);
        println!("fig1 seek agent {i}: rest {d:.3} m from the target, finished {:?}", a.finished_at);
        assert!(a.done() && d < g.d_tol, "agent {i}: {d} m");
    }
    assert_eq!(funnelled, 0, "plain seek funnelled");
    // The old reading (standard controller, ε_tol 180°) funnels the agent
    // whose target lies behind it towards β.
    let mut old = sc.clone();
    old.controller = ControllerKind::Standard;
    let mut old_funnel = 0;
    run(&t, &old, |w| {
        old_funnel += usize::from(w.agents[2].internals.mode == Mode::Funnelling);
    });
    println!("fig1 under the standard controller with ε_tol 180°: agent 2 funnels {old_funnel} steps");
    assert!(old_funnel > 0);
}
