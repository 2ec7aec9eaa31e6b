//! Issue 16: fuzzing every entry point a user types into, seeded and
//! bounded. Each property feeds mutated real inputs (the presets in
//! `scenarios/`, argument vectors built from every flag) and asserts an
//! `Err` with a non-empty message, or a short run whose outputs are all
//! finite; a panic fails the test. [`CASES`] cases per entry point, fixed
//! seed (the same cases every run; a failure prints its input).

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
use steering::crowd::Crowd;
use steering::scenario::Scenario;
use steering::table::EtaTable;
use steering::wander::pipeline::Wanderer;

mod common;

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

/// Values a hostile or careless user writes.
fn hostile_value() -> impl Strategy<Value = Value> {
    prop_oneof![
        prop::sample::select(vec![
            0.0,
            -0.0,
            1.0,
            -1.0,
            0.5,
            1e-45,
            1e-7,
            0.01,
            2.0,
            100.0,
            1e3,
            1e5,
            999_980.0,
            1e6,
            1e7,
            3.4e38,
            -3.4e38,
            1e300,
            4_294_967_295.0,
            18_446_744_073_709_551_615.0,
        ])
        .prop_map(|x| serde_json::json!(x)),
        prop::sample::select(vec![
            0i64,
            1,
            -1,
            2,
            7,
            1000,
            100_000,
            1_000_001,
            i64::MAX,
            i64::MIN
        ])
        .prop_map(|x| serde_json::json!(x)),
        any::<f32>().prop_map(|x| serde_json::json!(x)),
        Just(Value::Null),
        any::<bool>().prop_map(Value::Bool),
        "[a-zA-Z]{0,8}".prop_map(Value::String),
        Just(serde_json::json!([])),
        Just(serde_json::json!([1, 2])),
        Just(serde_json::json!({})),
        Just(serde_json::json!({"kind": "circle", "center": [0, 0], "angularSpeed": 100})),
    ]
}

/// Every (path into `v`) to a value, objects and arrays included.
fn paths(v: &Value, here: &mut Vec<Value>, out: &mut Vec<Vec<Value>>) {
    out.push(here.clone());
    match v {
        Value::Object(m) => {
            for (k, x) in m {
                here.push(Value::String(k.clone()));
                paths(x, here, out);
                here.pop();
            }
        }
        Value::Array(a) => {
            for (i, x) in a.iter().enumerate() {
                here.push(serde_json::json!(i));
                paths(x, here, out);
                here.pop();
            }
        }
        _ => {}
    }
}

fn at<'a>(v: &'a mut Value, path: &[Value]) -> &'a mut Value {
    path.iter().fold(v, |v, k| match k {
        Value::String(s) => &mut v[s.as_str()],
        Value::Number(n) => &mut v[n.as_u64().unwrap() as usize],
        _ => unreachable!(),
    })
}

fn get<'a>(v: &'a Value, path: &[Value]) -> Option<&'a Value> {
    path.iter().try_fold(v, |v, k| match k {
        Value::String(s) => v.get(s.as_str()),
        Value::Number(n) => v.get(n.as_u64()? as usize),
        _ => None,
    })
}

/// One mutation: a field replaced, a field removed, an unknown field, or
/// raw bytes changed.
#[derive(Clone, Debug)]
enum Mutation {
    Set(prop::sample::Index, Value),
    Remove(prop::sample::Index),
    Unknown(prop::sample::Index, String),
    Byte(prop::sample::Index, u8),
    Truncate(prop::sample::Index),
    /// A number scaled (a near-valid edit: most stay in range).
    Scale(prop::sample::Index, f64),
}

fn mutation() -> impl Strategy<Value = Mutation> {
    prop_oneof![
        6 => (any::<prop::sample::Index>(), hostile_value()).prop_map(|(i, v)| Mutation::Set(i, v)),
        1 => any::<prop::sample::Index>().prop_map(Mutation::Remove),
        1 => (any::<prop::sample::Index>(), "[a-z]{1,6}").prop_map(|(i, k)| Mutation::Unknown(i, k)),
        1 => (any::<prop::sample::Index>(), any::<u8>()).prop_map(|(i, b)| Mutation::Byte(i, b)),
        1 => any::<prop::sample::Index>().prop_map(Mutation::Truncate),
        4 => (any::<prop::sample::Index>(), prop::sample::select(vec![0.5, 0.9, 1.1, 2.0, -1.0, 10.0]))
            .prop_map(|(i, f)| Mutation::Scale(i, f)),
    ]
}

/// `text` (JSON) with `muts` applied in order.
fn mutate(text: &str, muts: &[Mutation]) -> String {
    let mut s = text.to_owned();
    for m in muts {
        let Ok(mut v) = serde_json::from_str::<Value>(&s) else {
            // Already broken: keep mutating bytes.
            if let Mutation::Byte(i, _) | Mutation::Unknown(i, _) = m {
                let mut bytes = s.into_bytes();
                if !bytes.is_empty() {
                    let k = i.index(bytes.len());
                    bytes[k] = if let Mutation::Byte(_, b) = m {
                        *b
                    } else {
                        b'['
                    };
                }
                s = String::from_utf8_lossy(&bytes).into_owned();
            }
            continue;
        };
        let mut ps = Vec::new();
        paths(&v, &mut Vec::new(), &mut ps);
        match m {
            Mutation::Set(i, x) => *at(&mut v, &ps[i.index(ps.len())]) = x.clone(),
            Mutation::Scale(i, f) => {
                let numbers: Vec<&Vec<Value>> = ps
                    .iter()
                    .filter(|p| get(&v, p).is_some_and(Value::is_number))
                    .collect();
                if let Some(p) = numbers.get(i.index(numbers.len().max(1))) {
                    let x = at(&mut v, p);
                    let n = x.as_f64().unwrap_or(0.0) * f;
                    *x = if x.is_u64() && n >= 0.0 {
                        serde_json::json!(n.round() as u64)
                    } else {
                        serde_json::json!(n)
                    };
                }
            }
            Mutation::Remove(i) => {
                let p = &ps[i.index(ps.len())];
                if let Some((last, parent)) = p.split_last() {
                    match (at(&mut v, parent), last) {
                        (Value::Object(o), Value::String(k)) => {
                            o.remove(k);
                        }
                        (Value::Array(a), Value::Number(n)) => {
                            a.remove(n.as_u64().unwrap() as usize);
                        }
                        _ => {}
                    }
                }
            }
            Mutation::Unknown(i, k) => {
                if let Value::Object(o) = at(&mut v, &ps[i.index(ps.len())]) {
                    o.insert(k.clone(), Value::Null);
                }
            }
            Mutation::Byte(i, b) => {
                let mut bytes = v.to_string().into_bytes();
                let k = i.index(bytes.len());
                bytes[k] = *b;
                s = String::from_utf8_lossy(&bytes).into_owned();
                continue;
            }
            Mutation::Truncate(i) => {
                let t = v.to_string();
                let mut k = i.index(t.len());
                while !t.is_char_boundary(k) {
                    k -= 1;
                }
                s = t[..k].to_owned();
                continue;
            }
        }
        s = v.to_string();
    }
    s
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
            w.plan(table());
            w.step(table());
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
                Command::Envelope(a) => {
                    assert!((5..=steering::cli::steer::MAX_STUDY_N).contains(&a.n));
                    if let Err(e) = a.standard_config() {
                        err_has_message(&e);
                    }
                    if let Err(e) = a.variants() {
                        err_has_message(&e);
                    }
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
                assert!(n <= steering::table::format::MAX_ENTRIES);
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

/// Floats a drag, a slider or a URL can produce.
fn hostile_f32() -> impl Strategy<Value = f32> {
    prop_oneof![
        1 => prop::sample::select(vec![
            0.0f32, -0.0, 0.01, 0.05, 0.1, 1.3, 2.0, 50.0, 100.0, 1e3, 4e4, 1e5, 999_980.0, 1e6,
            -1e6, 3.4e38, f32::NAN, f32::INFINITY, f32::NEG_INFINITY, f32::MIN_POSITIVE,
        ]),
        3 => -1e3f32..1e3,
        1 => any::<f32>(),
    ]
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
        use steering::funnel::{FunnelConfig, Goal};
        use steering::vehicle::VehicleParams;
        use steering::world::{GoalMotion, GoalSpec, SwitchRule, World};
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
        let r = w.spawn_random(n, seed, extent, speed);
        if let Err(e) = r {
            err_has_message(&e);
        }
        for (i, x, y, a, b, c, goals) in edits {
            let mut before = Vec::new();
            w.write_state(&mut before);
            let r = if goals {
                let g = GoalSpec {
                    goal: Goal { pos: glam::Vec2::new(x, y), beta: a, d_tol: b, eps_tol: 0.1, speed: c, halting: false },
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
            w.step(table());
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

/// Numbers and words as typed: edge values, overflow, signs, junk.
fn arg_value() -> impl Strategy<Value = String> {
    prop_oneof![
        prop::sample::select(vec![
            "0",
            "1",
            "2",
            "-1",
            "7",
            "1000000",
            "1000001",
            "99999999999",
            "18446744073709551615",
            "1e3",
            "0x10",
            " 5",
            "+3",
            "",
            "NaN",
            "inf",
            "-0",
            "0.5",
            "1.5",
            "256",
            "257",
            "standard",
            "relaxed",
            "entry",
            "paper-arc",
            "standard,relaxed",
            "nope",
            "a.csv",
            "a.CSV",
            "a.json",
            "a.jsonl",
            "a.txt",
            "scenarios/p000_fig1_seek.json",
            "{\"gain\": 3}",
            "{\"gain\": -1}",
            "{}",
            "[1]",
            "max_force=0.3",
            "measure_steps=4294967295",
            "boids=1000000",
            "warmup_steps=-1",
            "=1",
            "seed=\"x\"",
            "16,36,5,9,9",
            "2,2,2,2,2",
            "4096,4096,4096,4096,4096",
            "1,2",
            "5000,2,2,2,2",
        ])
        .prop_map(str::to_owned),
        any::<u64>().prop_map(|n| n.to_string()),
        any::<i64>().prop_map(|n| n.to_string()),
        "[ -~]{0,12}",
    ]
}

fn steer_args() -> impl Strategy<Value = Vec<String>> {
    let flag = prop::sample::select(vec![
        "--n",
        "--every",
        "--seed",
        "--out",
        "--table",
        "--threads",
        "--controller",
        "--aim",
        "--disk-margin",
        "--orientation-margin",
        "--only",
        "--standard",
        "--json",
        "--scenarios",
        "--brief",
        "--help",
        "--version",
        "-h",
    ]);
    (
        prop::sample::select(vec!["run", "reach", "relaxed", "envelope", "walk", ""]),
        prop::collection::vec((flag, arg_value(), any::<bool>()), 0..6),
        arg_value(),
    )
        .prop_map(|(sub, flags, pos)| {
            let mut v = vec!["steer".to_owned(), sub.to_owned()];
            if sub == "run" {
                v.push(pos);
            }
            for (f, val, with_value) in flags {
                v.push(f.to_owned());
                if with_value {
                    v.push(val);
                }
            }
            v
        })
}

fn other_args(bin: &'static str) -> impl Strategy<Value = Vec<String>> {
    let flag = prop::sample::select(vec![
        "--set",
        "--set",
        "--write-presets",
        "--out",
        "--counts",
        "--threads",
        "--help",
    ]);
    prop::collection::vec((flag, arg_value()), 0..4).prop_map(move |flags| {
        let mut v = vec![bin.to_owned()];
        for (f, val) in flags {
            // --write-presets would write files: parse, never run it.
            v.push(f.to_owned());
            v.push(val);
        }
        v
    })
}
