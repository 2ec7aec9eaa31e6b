//! The gallery bindings in a real browser (`wasm-pack test --headless --chrome`):
//! `CrowdLab` steps a paper preset and returns per-boid typed arrays, bad
//! crowd input is a `JsError` with a message, `WanderLab` builds every
//! variant of every wander preset file through the JavaScript object path
//! and gives the same traces, bit for bit, as the native golden hashes of
//! `tests/wander_determinism.rs`.
#![cfg(target_arch = "wasm32")]

use steering::bindings::crowd::CrowdLab;
use steering::bindings::wander::WanderLab;
use steering::crowd::config::CrowdConfig;
use steering::wander::pipeline::WanderPreset;
use wasm_bindgen::JsValue;
use wasm_bindgen_test::*;

mod common;
use common::{crowd_golden_cases, crowd_hash_step, fnv, message, FNV_OFFSET, WANDER_PRESETS};

wasm_bindgen_test_configure!(run_in_browser);

/// A Rust value as the page would hand it over (a plain JS object).
fn js<T: serde::Serialize>(v: &T) -> JsValue {
    v.serialize(&serde_wasm_bindgen::Serializer::json_compatible())
        .unwrap()
}

fn crowd_preset(boids: usize) -> CrowdConfig {
    let mut cfg = CrowdConfig::paper_presets()
        .into_iter()
        .find(|c| c.boids == 300 && c.name.contains("parker 10%"))
        .expect("Test IV, Parker 10 % exists");
    cfg.boids = boids;
    cfg
}

#[wasm_bindgen_test]
fn crowd_steps_from_a_preset_and_returns_typed_arrays() {
    let mut lab = CrowdLab::new(js(&crowd_preset(300))).unwrap();
    assert_eq!(lab.count(), 300);
    let before = lab.positions();
    lab.step(10);
    assert_eq!(lab.time(), 10.0);
    let pos = lab.positions();
    assert_eq!(pos.len(), 600);
    assert_eq!(lab.velocities().len(), 600);
    assert!(pos.iter().all(|x| x.is_finite()));
    assert_ne!(pos, before);
    assert!(lab.trace().len() >= 2);
    assert!(lab.traced_boid() < 300);
    assert_eq!(lab.path_points().len(), 8);
    assert!(lab.metrics().unwrap().is_object());
    lab.set_boid_count(10_000).unwrap();
    lab.step(1);
    assert_eq!(lab.positions().len(), 20_000);
}

#[wasm_bindgen_test]
fn crowd_presets_cross_the_boundary() {
    let presets = CrowdLab::paper_presets().unwrap();
    let arr = js_sys::Array::from(&presets);
    assert_eq!(arr.length(), 20);
    for v in arr.iter() {
        let mut lab = CrowdLab::new(v).unwrap();
        lab.step(2);
    }
    let json = include_str!("../scenarios/crowd/test3_reynolds.json");
    let mut lab = CrowdLab::from_json(json).unwrap();
    lab.step(3);
    assert_eq!(lab.count(), 100);
}

#[wasm_bindgen_test]
fn bad_crowd_input_is_a_js_error_with_a_message() {
    let mut cfg = crowd_preset(10);
    cfg.path.radius = -1.0;
    let e = CrowdLab::new(js(&cfg))
        .err()
        .expect("negative radius rejected");
    assert!(message(e).contains("radius"));

    let cfg = js(&crowd_preset(10));
    js_sys::Reflect::set(&cfg, &"boids".into(), &"ten".into()).unwrap();
    let m = message(CrowdLab::new(cfg).err().expect("a string boid count"));
    assert!(m.starts_with("crowd configuration, field `boids`"), "{m}");

    let e = CrowdLab::new(JsValue::from_str("not a config"))
        .err()
        .unwrap();
    assert!(message(e).starts_with("crowd configuration"));

    let e = CrowdLab::from_json("{").err().unwrap();
    assert!(!message(e).is_empty());

    let mut lab = CrowdLab::new(js(&crowd_preset(10))).unwrap();
    let e = lab.set_path_points(&[0.0, 0.0, f32::NAN, 1.0]).unwrap_err();
    assert!(message(e).starts_with("path points"));
    assert_eq!(lab.path_points().len(), 8, "unchanged after an error");
    let seek = js_sys::JSON::parse(r#"{"kind": "parker", "fraction": 2}"#).unwrap();
    assert!(!message(lab.set_seek(seek).unwrap_err()).is_empty());
    let seek = js_sys::JSON::parse(r#"{"kind": "reynolds", "fraction": 1}"#).unwrap();
    assert!(lab.set_seek(seek).is_err());
    assert!(lab.set_separation(true, f32::INFINITY).is_err());
    assert!(lab.set_path_radius(0.0).is_err());
    assert!(lab.select_traced(10).is_err());
    assert!(lab.set_boid_count(2_000_000).is_err());
    // Still usable.
    lab.step(5);
    assert_eq!(lab.positions().len(), 20);
}

#[wasm_bindgen_test]
fn a_dragged_path_point_moves_the_path() {
    let mut lab = CrowdLab::new(js(&crowd_preset(50))).unwrap();
    let mut pts = lab.path_points();
    pts[0] -= 40.0;
    lab.set_path_points(&pts).unwrap();
    assert_eq!(lab.path_points(), pts);
    lab.set_path_radius(30.0).unwrap();
    assert_eq!(lab.path_radius(), 30.0);
    lab.step(5);
}

#[wasm_bindgen_test]
fn wander_presets_give_the_native_traces_through_the_bindings() {
    for (name, json, golden) in WANDER_PRESETS {
        // The preset as the page receives it, each variant's config handed
        // back as a plain JS object.
        let parsed = WanderLab::parse_preset(json).unwrap();
        let variants = js_sys::Reflect::get(&parsed, &JsValue::from_str("variants")).unwrap();
        let variants = js_sys::Array::from(&variants);
        let preset = WanderPreset::from_json(json).unwrap();
        assert_eq!(variants.length() as usize, preset.variants.len());
        let mut h = FNV_OFFSET;
        for v in variants.iter() {
            let config = js_sys::Reflect::get(&v, &JsValue::from_str("config")).unwrap();
            let mut lab = WanderLab::new(config).unwrap();
            lab.run(preset.steps);
            let trace = lab.trace();
            assert_eq!(trace.len(), 3 * (preset.steps as usize + 1), "{name}");
            assert_eq!(lab.trace_len() as usize, preset.steps as usize + 1);
            fnv(&mut h, &trace);
            // Reset replays.
            lab.reset();
            lab.run(preset.steps);
            assert_eq!(lab.trace(), trace, "{name}: reset replays");
        }
        assert_eq!(h, golden, "preset {name}: got {h:#018x}");
    }
}

#[wasm_bindgen_test]
fn wander_paths_expose_the_generated_path_and_json_works() {
    let preset = WanderPreset::from_json(WANDER_PRESETS[6].1).unwrap();
    let cfg = serde_json::to_string(&preset.variants[0].config).unwrap();
    let lab = WanderLab::from_json(&cfg).unwrap();
    let pts = lab.path_points();
    assert!(pts.len() >= 4 && pts.len() % 2 == 0);
    assert_eq!(lab.pose().len(), 3);
}

#[wasm_bindgen_test]
fn misspelt_keys_in_gallery_configs_are_errors_naming_them() {
    let cfg = js(&crowd_preset(10));
    js_sys::Reflect::set(&cfg, &"boidz".into(), &5.into()).unwrap();
    let m = message(CrowdLab::new(cfg).err().expect("`boidz` refused"));
    assert!(m.contains("unknown field `boidz`"), "{m}");
    let cfg = js(&crowd_preset(10));
    let path = js_sys::Reflect::get(&cfg, &"path".into()).unwrap();
    js_sys::Reflect::set(&path, &"raduis".into(), &2.into()).unwrap();
    let m = message(CrowdLab::new(cfg).err().expect("`path.raduis` refused"));
    assert!(m.contains("unknown field `path.raduis`"), "{m}");
    let mut lab = CrowdLab::new(js(&crowd_preset(10))).unwrap();
    let seek =
        js_sys::JSON::parse(r#"{"kind": "parker", "fraction": 0.1, "fracton": 0.2}"#).unwrap();
    let m = message(lab.set_seek(seek).unwrap_err());
    assert!(m.contains("`fracton`"), "{m}");

    let preset = WanderPreset::from_json(WANDER_PRESETS[0].1).unwrap();
    let cfg = js(&preset.variants[0].config);
    let control = js_sys::Reflect::get(&cfg, &"control".into()).unwrap();
    js_sys::Reflect::set(&control, &"mode_".into(), &1.into()).unwrap();
    let m = message(WanderLab::new(cfg).err().expect("`control.mode_` refused"));
    assert!(
        m.starts_with("wander configuration: unknown field `control.mode_`"),
        "{m}"
    );
    WanderLab::new(js(&preset.variants[0].config)).unwrap();
}

#[wasm_bindgen_test]
fn bad_wander_input_is_a_js_error_with_a_message() {
    let e = WanderLab::from_json(r#"{"control": {"mode": "velocity", "max_velocity_deg": 500}, "source": {"kind": "random", "distribution": {"kind": "uniform"}}}"#)
        .err()
        .unwrap();
    assert!(message(e).contains("max_velocity_deg"));
    let e = WanderLab::new(JsValue::NULL).err().unwrap();
    assert!(message(e).starts_with("wander configuration"));
    assert!(WanderLab::parse_preset("[]").is_err());
}

/// The wander page's JSON box goes to `fromJson`: the native
/// parser's rules hold in the browser, a duplicate key is refused as in the
/// files, and a 5,000-deep nesting is a message, not a stack overflow
/// (the page also refuses more than 32 levels before parsing).
#[wasm_bindgen_test]
fn the_json_box_refuses_duplicate_keys_and_deep_nesting() {
    let ok = r#"{"seed": 3, "control": {"mode": "velocity", "max_velocity_deg": 10}, "source": {"kind": "random", "distribution": {"kind": "uniform"}}}"#;
    let lab = WanderLab::from_json(ok).map_err(message).unwrap();
    assert!(lab.config().is_ok());
    let dup = ok.replacen(r#""seed": 3,"#, r#""seed": 3, "seed": 4,"#, 1);
    let m = message(WanderLab::from_json(&dup).err().unwrap());
    assert!(m.contains("seed: given twice"), "{m}");
    let dup = ok.replacen(
        r#""mode": "velocity","#,
        r#""mode": "velocity", "mode": "velocity","#,
        1,
    );
    let m = message(WanderLab::from_json(&dup).err().unwrap());
    assert!(m.contains("control.mode: given twice"), "{m}");
    // serde_json refuses the wrong type at the first bracket (and stops at
    // 128 levels where a type could nest): a message either way.
    for deep in [
        format!("{}{}", "[".repeat(5000), "]".repeat(5000)),
        format!(r#"{{"seed": {}{}}}"#, "[".repeat(5000), "]".repeat(5000)),
    ] {
        let m = message(WanderLab::from_json(&deep).err().unwrap());
        assert!(m.starts_with("wander configuration: "), "{m}");
        assert!(m.contains("found a list"), "{m}");
    }
}

/// The crowd's golden trajectories (native, `tests/crowd_determinism.rs`)
/// through the bindings, on one core and as two vertical strips (the
/// stepping workers' calls: `loadState`, `stepStrip`, `ownedState`,
/// `observeStep`).
#[wasm_bindgen_test]
fn crowd_golden_hashes_through_the_bindings_whole_and_in_strips() {
    for (name, cfg, steps, golden) in crowd_golden_cases() {
        let mut lab = CrowdLab::new(js(&cfg)).unwrap();
        let mut h = FNV_OFFSET;
        for _ in 0..steps {
            lab.step(1);
            crowd_hash_step(&mut h, &lab.positions(), &lab.velocities());
        }
        fnv(&mut h, &lab.trace());
        assert_eq!(h, golden, "{name}: got {h:#018x}");

        let mut page = CrowdLab::new(js(&cfg)).unwrap();
        page.set_metrics_enabled(false);
        let n = page.count() as usize;
        let mut strips = [
            CrowdLab::new(js(&cfg)).unwrap(),
            CrowdLab::new(js(&cfg)).unwrap(),
        ];
        let mut state = page.state();
        let mut h = FNV_OFFSET;
        for t in 0..steps {
            let mut next = state.clone();
            for (w, s) in strips.iter_mut().enumerate() {
                s.load_state(&state, f64::from(t)).unwrap();
                let (lo, hi) = if w == 0 {
                    (f32::NEG_INFINITY, 0.0)
                } else {
                    (0.0, f32::INFINITY)
                };
                s.step_strip(lo, hi);
                let o = s.owned_state();
                for (k, &i) in s.owned_indices().iter().enumerate() {
                    let i = 2 * i as usize;
                    next[i..i + 2].copy_from_slice(&o[4 * k..4 * k + 2]);
                    next[2 * n + i..2 * n + i + 2].copy_from_slice(&o[4 * k + 2..4 * k + 4]);
                }
            }
            state = next;
            let tr = page.traced_boid() as usize;
            page.observe_step(state[2 * tr], state[2 * tr + 1]);
            crowd_hash_step(&mut h, &state[..2 * n], &state[2 * n..]);
        }
        fnv(&mut h, &page.trace());
        assert_eq!(h, golden, "{name} in two strips: got {h:#018x}");
    }
    let mut lab = CrowdLab::new(js(&crowd_preset(10))).unwrap();
    let m = message(lab.load_state(&[0.0; 8], 0.0).unwrap_err());
    assert!(m.contains("8 floats for 10 boids"), "{m}");
}
