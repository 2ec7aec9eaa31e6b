//! A world split into slices (`crate/world/split.rs`, the
//! lab's stepping workers) steps every agent to the same bits as the whole
//! world; cuts never separate an agent from the agent its goal faces
//! (paper 000 Fig. 6); refused splits change nothing.
#![cfg(not(target_arch = "wasm32"))]

use steering::avoidance::{config::AvoidanceConfig, config::AvoidanceMethod};
use steering::base::vehicle::VehicleParams;
use steering::funnelling::config::FunnelConfig;
use steering::funnelling::table::lookup::EtaTable;
use steering::world::scenario::Scenario;
use steering::world::split::SplitError;
use steering::world::World;

mod common;
use common::table;

fn states(w: &World) -> Vec<u32> {
    let mut buf = Vec::new();
    w.write_state(&mut buf);
    buf.iter().map(|f| f.to_bits()).collect()
}

/// Steps `w` whole and in `parts` slices for `steps` steps; asserts the
/// slices' states, concatenated, equal the whole world's bit for bit at
/// every step. Returns the ranges.
fn whole_equals_slices(
    t: &EtaTable,
    w: &World,
    parts: usize,
    steps: usize,
) -> Vec<core::ops::Range<usize>> {
    let ranges = w.split_ranges(parts);
    let mut whole = w.clone();
    let mut slices: Vec<World> = ranges
        .iter()
        .map(|r| {
            let mut s = w.clone();
            s.retain_range(r.clone())
                .expect("split_ranges gives admissible ranges");
            s
        })
        .collect();
    for step in 0..steps {
        whole.step(t).unwrap();
        for s in &mut slices {
            s.step(t).unwrap();
        }
        let joined: Vec<u32> = slices.iter().flat_map(states).collect();
        assert_eq!(joined, states(&whole), "step {step}, ranges {ranges:?}");
    }
    ranges
}

fn preset(json: &str) -> World {
    Scenario::from_json(json).unwrap().world().unwrap()
}

/// `n` random agents in a square of side `extent` at 1.3 m/s (the lab's
/// performance world's recipe).
fn crowd(n: usize, seed: u64, extent: f32) -> World {
    let mut w = World::new(VehicleParams::default(), FunnelConfig::default()).unwrap();
    w.spawn_random(n, seed, extent, 1.3).unwrap();
    w
}

/// `w` with the ORCA avoidance on (a whole-world step).
fn with_orca(mut w: World) -> World {
    let cfg = AvoidanceConfig {
        method: AvoidanceMethod::Orca,
        ..Default::default()
    };
    w.set_avoidance(cfg, Vec::new()).unwrap();
    w
}

#[test]
fn random_crowd_in_two_three_and_seven_slices_equals_one_world() {
    let t = table();
    let w = crowd(1000, 7, 40.0);
    for parts in [2, 3, 7] {
        let r = whole_equals_slices(&t, &w, parts, 300);
        assert_eq!(r.len(), parts);
        let sizes: Vec<usize> = r.iter().map(|r| r.len()).collect();
        assert!(
            sizes.iter().all(|&s| s.abs_diff(1000 / parts) <= 1),
            "{sizes:?}"
        );
    }
}

#[test]
fn a_slice_of_the_random_crowd_is_spawned_alone_bit_for_bit() {
    let t = table();
    let whole = crowd(500, 11, 30.0);
    let mut kept = World::new(VehicleParams::default(), FunnelConfig::default()).unwrap();
    kept.spawn_random_kept(500, 11, 30.0, 1.3, 200..350)
        .unwrap();
    let mut retained = whole.clone();
    retained.retain_range(200..350).unwrap();
    assert_eq!(kept, retained);
    for _ in 0..120 {
        kept.step(&t).unwrap();
        retained.step(&t).unwrap();
    }
    assert_eq!(states(&kept), states(&retained));
}

#[test]
fn facing_agents_stay_in_one_slice_and_step_as_in_one_world() {
    let t = table();
    // Fig. 6: pairs (0,1), (2,3), (4,5) … face each other.
    let w = preset(include_str!("../scenarios/p000_fig6_face_to_face.json"));
    let n = w.agents().len();
    let links: Vec<(usize, usize)> = w.face_links().collect();
    assert!(!links.is_empty());
    for parts in [2, 3, n] {
        let ranges = whole_equals_slices(&t, &w, parts, 900);
        for (a, b) in &links {
            assert!(
                ranges.iter().any(|r| r.contains(a) && r.contains(b)),
                "{a}->{b} cut by {ranges:?}"
            );
        }
        assert!(ranges.len() > 1, "pairs can be split apart: {ranges:?}");
    }
}

#[test]
fn a_long_link_moves_the_cut() {
    let t = table();
    // Agent 1 faces agent 7 of ten: no cut between 2 and 7.
    let mut w = crowd(10, 3, 20.0);
    let fig6 = preset(include_str!("../scenarios/p000_fig6_face_to_face.json"));
    let mut g = fig6.agents()[0].goals.clone();
    if let steering::world::goals::GoalMotion::FaceAgent { agent, .. } = &mut g[0].motion {
        *agent = 7;
    }
    w.set_goals(1, g).unwrap();
    let ranges = whole_equals_slices(&t, &w, 2, 600);
    assert_eq!(ranges, vec![0..8, 8..10]);
    // Retaining a range that cuts the link is refused, nothing changed.
    let mut cut = w.clone();
    assert_eq!(
        cut.retain_range(0..5),
        Err(SplitError::CutLink { agent: 1, faces: 7 })
    );
    assert_eq!(cut, w);
    assert!(matches!(
        cut.retain_range(4..4),
        Err(SplitError::BadRange { .. })
    ));
    assert!(matches!(
        cut.retain_range(0..11),
        Err(SplitError::BadRange { .. })
    ));
    assert_eq!(cut, w);
}

#[test]
fn avoidance_keeps_the_world_whole() {
    let mut w = with_orca(crowd(100, 1, 20.0));
    assert_eq!(w.split_ranges(4), vec![0..100]);
    let before = w.clone();
    assert_eq!(w.retain_range(0..50), Err(SplitError::Coupled));
    assert_eq!(w, before);
    assert!(
        World::new(VehicleParams::default(), FunnelConfig::default())
            .unwrap()
            .split_ranges(3)
            .is_empty()
    );
}

/// What a stepping worker calls (`Lab::stepInto`): one pass that steps and
/// writes each agent's record gives the floats of a step, then
/// `write_state`; the same with facing goals (the snapshot taken) and with
/// avoidance on (its own step, then the write).
#[test]
fn stepping_and_writing_in_one_pass_equals_a_step_then_the_state() {
    let t = table();
    let random = crowd(400, 5, 25.0);
    let fig6 = preset(include_str!("../scenarios/p000_fig6_face_to_face.json"));
    let avoiding = with_orca(random.clone());
    for w in [random, fig6, avoiding] {
        let (mut a, mut b) = (w.clone(), w);
        let mut buf = Vec::new();
        for _ in 0..150 {
            a.step_writing(&t, &mut buf).unwrap();
            b.step(&t).unwrap();
            assert_eq!(
                buf.iter().map(|f| f.to_bits()).collect::<Vec<_>>(),
                states(&b)
            );
        }
        assert_eq!(a, b);
    }
}

/// The lab's worlds keep no path metrics (`World::set_metrics(false)`, the
/// lab binding's `lab_world`): the states stay the same bits as with them,
/// plain and avoiding, and the metrics stay empty.
#[test]
fn a_world_without_metrics_steps_to_the_same_bits() {
    let t = table();
    for w in [crowd(400, 5, 25.0), with_orca(crowd(200, 9, 20.0))] {
        let (mut on, mut off) = (w.clone(), w);
        off.set_metrics(false);
        assert!(on.metrics_on() && !off.metrics_on());
        for step in 0..200 {
            on.step(&t).unwrap();
            off.step(&t).unwrap();
            assert_eq!(states(&on), states(&off), "step {step}");
        }
        assert!(on.agents().iter().all(|a| a.metrics.steps == 200));
        assert!(off.agents().iter().all(|a| a.metrics == Default::default()));
    }
}
