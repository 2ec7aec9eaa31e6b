//! Fuzzing every entry point a user types into, seeded and
//! bounded. Each property feeds mutated real inputs (the presets in
//! `scenarios/`, argument vectors built from every flag) and asserts an
//! `Err` with a non-empty message (a scenario's naming the path of the
//! field at fault), or a short run whose outputs are all finite; a panic
//! fails the test. [`CASES`] cases per entry point, fixed seed (the same
//! cases every run; a failure prints its input). `fuzz/damage.rs` runs
//! damaged scenario files through `steer run` as a user does.

#![cfg(not(target_arch = "wasm32"))]

use std::sync::OnceLock;

use clap::Parser;
use proptest::prelude::*;
use proptest::test_runner::{Config, RngSeed};
use serde_json::Value;
use steering::cli::crowd_metrics::CrowdMetricsCli;
use steering::cli::eta_table::EtaTableCli;
use steering::cli::steer::{Command, SteerCli};
use steering::cli::trajectory::{check_out_path, stream_run, OutFormat};
use steering::crowd::config::CrowdConfig;
use steering::crowd::world::Crowd;
use steering::funnelling::table::lookup::EtaTable;
use steering::wander::pipeline::Wanderer;
use steering::world::scenario::Scenario;

mod common;
#[path = "fuzz/damage.rs"]
mod damage;
#[path = "fuzz/inputs.rs"]
mod inputs;

use inputs::{hostile_f32, mutate, mutation, other_args, steer_args};

/// Cases per entry point.
const CASES: u32 = 10_000;

fn config() -> Config {
    Config {
        cases: CASES,
        rng_seed: RngSeed::Fixed(16),
        failure_persistence: None,
        max_shrink_iters: 200,
        ..Config::default()
    }
}

fn table() -> &'static EtaTable {
    static T: OnceLock<EtaTable> = OnceLock::new();
    T.get_or_init(common::table)
}

/// Preset texts per folder of `scenarios/`, read once.
type PresetCache = std::sync::Mutex<Vec<(String, &'static [String])>>;

fn files(dir: &str) -> &'static [String] {
    static CACHE: OnceLock<PresetCache> = OnceLock::new();
    let cache = CACHE.get_or_init(Default::default);
    let mut c = cache.lock().unwrap();
    if let Some((_, v)) = c.iter().find(|(d, _)| d == dir) {
        return v;
    }
    let path = format!("{}/scenarios/{dir}", env!("CARGO_MANIFEST_DIR"));
    let mut names: Vec<_> = std::fs::read_dir(&path)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|x| x == "json"))
        .collect();
    names.sort();
    let texts: Vec<String> = names
        .iter()
        .map(|p| std::fs::read_to_string(p).unwrap())
        .collect();
    let leaked: &'static [String] = Box::leak(texts.into_boxed_slice());
    c.push((dir.to_owned(), leaked));
    leaked
}

/// Tallies per entry point: (name, refused, ran); printed once all
/// [`CASES`] of an entry point ran (`--nocapture` shows them).
static TALLY: std::sync::Mutex<Vec<(&'static str, u32, u32)>> = std::sync::Mutex::new(Vec::new());

fn tally(name: &'static str, ran: bool) {
    let mut t = TALLY.lock().unwrap();
    let i = t.iter().position(|e| e.0 == name).unwrap_or_else(|| {
        t.push((name, 0, 0));
        t.len() - 1
    });
    if ran {
        t[i].2 += 1;
    } else {
        t[i].1 += 1;
    }
    if t[i].1 + t[i].2 == CASES {
        println!(
            "fuzz {name}: {CASES} cases, {} refused with a message, {} ran",
            t[i].1, t[i].2
        );
    }
    drop(t);
}

/// Edits (`set_pose`, `set_goals`) applied and refused, printed at the end
/// of the world-edit property.
static EDITS: std::sync::Mutex<(u32, u32)> = std::sync::Mutex::new((0, 0));

fn tally_edit(applied: bool) {
    let mut e = EDITS.lock().unwrap();
    if applied {
        e.0 += 1;
    } else {
        e.1 += 1;
    }
    drop(e);
}

fn err_has_message<E: std::fmt::Display>(e: &E) {
    assert!(!e.to_string().trim().is_empty(), "empty error message");
}

/// A scenario: refused with a message, or a few streamed steps, all finite.
fn check_scenario(text: &str) {
    match Scenario::from_json(text) {
        Err(e) => {
            tally("scenario", false);
            err_has_message(&e);
            let f = e.field();
            let shown = if f.path.is_empty() {
                steering::base::field_error::TOP_LEVEL
            } else {
                &f.path
            };
            assert!(e.to_string().contains(&format!(": {shown}: ")), "{e}");
        }
        Ok(mut sc) => {
            if let Err(e) = table().check_params(&sc.vehicle) {
                tally("scenario", false);
                return err_has_message(&e);
            }
            tally("scenario", true);
            sc.duration = sc.duration.min(4.0 * sc.vehicle.dt);
            let mut out = Vec::new();
            let mut w = sc.world().expect("a validated scenario builds");
            w.plan(table()).unwrap();
            w.step(table()).unwrap();
            let mut state = Vec::new();
            w.write_state(&mut state);
            assert!(state.iter().all(|x| x.is_finite()), "non-finite state");
            let s = stream_run(&sc, table(), 1, OutFormat::Json, &mut out, &mut |_| {})
                .expect("a validated scenario streams");
            assert_eq!(s.agents, sc.agents.len());
            let doc: Value = serde_json::from_slice(&out).expect("the stream is JSON");
            assert!(!out.windows(4).any(|w| w == b"null") || doc["source"].is_string());
        }
    }
}

proptest! {
    #![proptest_config(config())]

    #[test]
    fn mutated_scenarios_are_refused_or_run_finite(
        which in any::<prop::sample::Index>(),
        muts in prop::collection::vec(mutation(), 1..4),
    ) {
        let presets = files("");
        let text = mutate(&presets[which.index(presets.len())], &muts);
        check_scenario(&text);
    }

    #[test]
    fn mutated_crowd_configs_are_refused_or_run_finite(
        which in any::<prop::sample::Index>(),
        muts in prop::collection::vec(mutation(), 1..4),
    ) {
        let presets = files("crowd");
        let text = mutate(&presets[which.index(presets.len())], &muts);
        let r = CrowdConfig::from_json(&text).and_then(|c| c.check_batch().map(|()| c));
        tally("crowd config", r.is_ok());
        match r {
            Err(e) => err_has_message(&e),
            Ok(c) => {
                let mut crowd = Crowd::new(&c).expect("a validated config builds");
                if crowd.len() <= 20_000 {
                    crowd.run(3);
                }
                assert!(crowd.positions().iter().all(|x| x.is_finite()));
                assert!(crowd.velocities().iter().all(|x| x.is_finite()));
            }
        }
    }

    #[test]
    fn mutated_wander_configs_are_refused_or_run_finite(
        which in any::<prop::sample::Index>(),
        variant in any::<prop::sample::Index>(),
        muts in prop::collection::vec(mutation(), 1..4),
    ) {
        let presets = files("wander");
        let file: Value = serde_json::from_str(&presets[which.index(presets.len())]).unwrap();
        let vs = file["variants"].as_array().unwrap();
        let cfg = vs[variant.index(vs.len())]["config"].to_string();
        let text = mutate(&cfg, &muts);
        let r = Wanderer::from_json(&text);
        tally("wander config", r.is_ok());
        match r {
            Err(e) => err_has_message(&e),
            Ok(mut w) => {
                w.run(5);
                assert!(w.pose().iter().all(|x| x.is_finite()), "{:?}", w.pose());
            }
        }
    }

    #[test]
    fn steer_argument_vectors_are_refused_or_validated(args in steer_args()) {
        let r = SteerCli::try_parse_from(&args);
        tally("steer arguments (parsed)", r.is_ok());
        match r {
            Err(e) => err_has_message(&e),
            Ok(cli) => match cli.command {
                Command::Run(a) => {
                    if let Err(e) = check_out_path(&a.out, &a.scenario) {
                        err_has_message(&e);
                    }
                    assert!((1..=steering::cli::trajectory::MAX_EVERY).contains(&a.every));
                }
                Command::Reach(a) => {
                    assert!((1..=steering::cli::steer::MAX_STUDY_N).contains(&a.n));
                }
                Command::Relaxed(a) => {
                    assert!((1..=steering::cli::steer::MAX_STUDY_N).contains(&a.n));
                    if let Err(e) = a.relaxed_config() {
                        err_has_message(&e);
                    }
                }
                Command::Avoid(a) => {
                    assert!((1..=10_000).contains(&a.seeds));
                    if let Err(e) = a.benches() {
                        err_has_message(&e);
                    }
                }
                Command::Envelope(a) => {
                    assert!((5..=steering::cli::steer::MAX_STUDY_N).contains(&a.n));
                    if let Err(e) = a.standard_config() {
                        err_has_message(&e);
                    }
                    if let Err(e) = a.variants() {
                        err_has_message(&e);
                    }
                }
                Command::Report(a) => {
                    assert!(!(a.check && a.prune));
                }
            },
        }
    }

    #[test]
    fn eta_table_argument_vectors(args in other_args("eta-table")) {
        let r = EtaTableCli::try_parse_from(&args);
        tally("eta-table arguments (parsed)", r.is_ok());
        match r {
            Err(e) => err_has_message(&e),
            Ok(cli) => {
                let n: usize = cli.counts.iter().product();
                assert!(n <= steering::funnelling::table::format::MAX_ENTRIES);
            }
        }
    }

    #[test]
    fn crowd_metrics_argument_vectors(args in other_args("crowd-metrics")) {
        let r = CrowdMetricsCli::try_parse_from(&args);
        tally("crowd-metrics arguments (parsed)", r.is_ok());
        match r {
            Err(e) => err_has_message(&e),
            Ok(cli) => {
                // What crowd-metrics does with each preset, for one preset.
                let mut v: Value = serde_json::from_str(&files("crowd")[0]).unwrap();
                for (k, val) in &cli.overrides {
                    v[k.as_str()] = val.clone();
                }
                match CrowdConfig::from_json(&v.to_string()).and_then(|c| c.check_batch().map(|()| c)) {
                    Err(e) => err_has_message(&e),
                    Ok(c) => {
                        let mut crowd = Crowd::new(&c).expect("validated");
                        if crowd.len() <= 20_000 {
                            crowd.run(2);
                        }
                        assert!(crowd.positions().iter().all(|x| x.is_finite()));
                    }
                }
            }
        }
    }
}

proptest! {
    #![proptest_config(config())]

    /// The lab's edits of a running world (`Lab` passes them through).
    #[test]
    fn world_edits_are_refused_unchanged_or_run_finite(
        v_max in prop_oneof![4 => prop::sample::select(vec![0.01f32, 0.05, 0.5, 2.0, 100.0]), 1 => hostile_f32()],
        dt in prop_oneof![4 => prop::sample::select(vec![1.0f32 / 60.0, 0.005, 0.1, 1e-4]), 1 => hostile_f32()],
        n in 0usize..8,
        seed in any::<u64>(),
        extent in hostile_f32(),
        speed in hostile_f32(),
        edits in prop::collection::vec(
            (0usize..3, hostile_f32(), hostile_f32(), hostile_f32(), hostile_f32(), hostile_f32(), any::<bool>()),
            0..4,
        ),
    ) {
        use steering::funnelling::config::FunnelConfig;
        use steering::funnelling::goal::Goal;
        use steering::base::vehicle::VehicleParams;
        use steering::world::{goals::GoalMotion, goals::GoalSpec, goals::SwitchRule, World};
        let p = VehicleParams { v_max, dt, ..VehicleParams::default() };
        let mut w = match World::new(p, FunnelConfig::default()) {
            Err(e) => {
                tally("world edits (world built)", false);
                err_has_message(&e);
                return Ok(());
            }
            Ok(w) => w,
        };
        tally("world edits (world built)", true);
        // The limits are hostile, the table the pedestrian's: stepped anyway.
        w.allow_other_table(true);
        let r = w.spawn_random(n, seed, extent, speed);
        if let Err(e) = r {
            err_has_message(&e);
        }
        for (i, x, y, a, b, c, goals) in edits {
            let mut before = Vec::new();
            w.write_state(&mut before);
            let r = if goals {
                let g = GoalSpec {
                    goal: Goal { pos: glam::Vec2::new(x, y), beta: a, d_tol: b, eps_tol: 0.1, speed: c, halting: false, vel: glam::Vec2::ZERO },
                    motion: if c > 1.0 { GoalMotion::Circle { center: glam::Vec2::ZERO, angular_speed: a } } else { GoalMotion::Static },
                    switch: SwitchRule::Tolerance,
                };
                w.set_goals(i, vec![g])
            } else {
                w.set_pose(i, glam::Vec2::new(x, y), a)
            };
            tally_edit(r.is_ok());
            if let Err(e) = r {
                err_has_message(&e);
                let mut after = Vec::new();
                w.write_state(&mut after);
                assert_eq!(before.len(), after.len());
                assert!(before.iter().zip(&after).all(|(a, b)| a.to_bits() == b.to_bits()), "a refused edit changed the world");
            }
        }
        for _ in 0..3 {
            w.step(table()).unwrap();
        }
        let mut state = Vec::new();
        w.write_state(&mut state);
        assert!(state.iter().all(|x| x.is_finite()));
        let t = TALLY.lock().unwrap();
        if t.iter().any(|e| e.0 == "world edits (world built)" && e.1 + e.2 == CASES) {
            let e = EDITS.lock().unwrap();
            println!("fuzz world edits: set_pose / set_goals {} applied, {} refused unchanged", e.0, e.1);
        }
    }
}
