//! The JavaScript bindings in a real browser (`wasm-pack test --headless --chrome`):
//! the committed η table loads, a corrupt one is a `JsError` with a message,
//! agents step, and bulk state comes back as typed arrays.
#![cfg(target_arch = "wasm32")]

use steering::bindings::lab::{self as bindings, Lab};
use wasm_bindgen::JsValue;
use wasm_bindgen_test::*;

wasm_bindgen_test_configure!(run_in_browser);

mod common;
use common::message;

static TABLE: &[u8] = include_bytes!("../tables/eta.bin");

#[wasm_bindgen_test]
fn version_matches_the_crate() {
    assert_eq!(bindings::version(), env!("CARGO_PKG_VERSION"));
}

#[wasm_bindgen_test]
fn random_samples_are_seeded_and_in_range() {
    let a = bindings::random_samples(7, 64);
    let b = bindings::random_samples(7, 64);
    assert_eq!(a, b);
    assert!(a.iter().all(|x| (0.0..1.0).contains(x)));
    assert_ne!(a, bindings::random_samples(8, 64));
}

#[wasm_bindgen_test]
fn the_committed_table_loads_and_gives_a_field() {
    let lab = Lab::new(TABLE).map_err(message).unwrap();
    let field = lab.eta_field(1.0, 0.0, 1.3);
    assert!(
        field.len() >= 4 * 100 && field.len() % 4 == 0,
        "{}",
        field.len()
    );
    assert!(field.iter().all(|x| x.is_finite()));
    let ring = lab.eta_ring_at(3.0, 1.0, 0.0, 1.3);
    assert!(!ring.is_empty() && ring.len() % 4 == 0);
    let d0 = ring[0];
    assert!(ring.chunks(4).all(|c| c[0] == d0), "one ring, one distance");
}

#[wasm_bindgen_test]
fn corrupt_tables_are_errors_with_a_message() {
    let m = message(
        Lab::new(b"not a table")
            .err()
            .expect("garbage must be refused"),
    );
    assert!(m.contains("η table"), "{m}");
    let mut flipped = TABLE.to_vec();
    let mid = flipped.len() / 2;
    flipped[mid] ^= 0x40;
    let m = message(
        Lab::new(&flipped)
            .err()
            .expect("a flipped bit must be refused"),
    );
    assert!(m.contains("checksum") || m.contains("corrupt"), "{m}");
    let m = message(
        Lab::new(&TABLE[..TABLE.len() - 7])
            .err()
            .expect("truncation must be refused"),
    );
    assert!(m.contains("truncated") || m.contains("η table"), "{m}");
}

fn goal(x: f64, y: f64, beta: f64) -> JsValue {
    let o = js_sys::Object::new();
    for (k, v) in [
        ("x", x),
        ("y", y),
        ("beta", beta),
        ("dTol", 0.3),
        ("epsTol", 0.17),
        ("speed", 1.3),
    ] {
        js_sys::Reflect::set(&o, &k.into(), &v.into()).unwrap();
    }
    js_sys::Reflect::set(&o, &"halting".into(), &true.into()).unwrap();
    o.into()
}

fn agent(x: f64, y: f64, theta: f64, goals: &[JsValue]) -> JsValue {
    let o = js_sys::Object::new();
    for (k, v) in [("x", x), ("y", y), ("theta", theta)] {
        js_sys::Reflect::set(&o, &k.into(), &v.into()).unwrap();
    }
    let arr = js_sys::Array::new();
    for g in goals {
        arr.push(g);
    }
    js_sys::Reflect::set(&o, &"goals".into(), &arr).unwrap();
    o.into()
}

fn get(v: &JsValue, k: &str) -> JsValue {
    js_sys::Reflect::get(v, &k.into()).unwrap()
}

#[wasm_bindgen_test]
fn agents_step_and_state_comes_back_as_a_typed_array() {
    let mut lab = Lab::new(TABLE).map_err(message).unwrap();
    let i = lab
        .add_agent(agent(-4.0, 0.0, 0.0, &[goal(4.0, 2.0, 1.57)]))
        .map_err(message)
        .unwrap();
    assert_eq!(i, 0);
    let stride = Lab::state_stride() as usize;
    let s0 = lab.state();
    assert_eq!(s0.len(), stride);
    let inter = lab.internals(0).map_err(message).unwrap();
    let mode = get(&inter, "mode").as_f64().unwrap();
    assert!(
        mode == 2.0 || mode == 3.0,
        "far target: Position_only or Funnelling, got {mode}"
    );
    assert!(get(&inter, "d").as_f64().unwrap() > 8.0);
    lab.step(120).map_err(message).unwrap();
    let s1 = lab.state();
    assert!(s1[3] > 0.5, "moving after 2 s: v = {}", s1[3]);
    assert!((s1[0] - s0[0]).abs() > 0.5);
    assert!(s1.iter().all(|x| x.is_finite()));
    // The Float32Array the page sees.
    let arr = js_sys::Float32Array::from(&s1[..]);
    assert_eq!(arr.length() as usize, stride);
    // Target dragged onto the vehicle at speed: a halting goal counts as
    // met only where the vehicle can come to rest inside it, so
    // it brakes first (v_dt 0), comes round (11 s here) and turns to β
    // inside the tolerance.
    lab.set_goal(0, goal(f64::from(s1[0]), f64::from(s1[1]), 3.0))
        .map_err(message)
        .unwrap();
    let inter = lab.internals(0).map_err(message).unwrap();
    let m = get(&inter, "mode").as_f64().unwrap();
    assert_eq!(m, 2.0, "braking towards the centre first");
    assert_eq!(get(&inter, "vDt").as_f64().unwrap(), 0.0);
    let settled = (0..120).any(|_| {
        lab.step(10).map_err(message).unwrap();
        let m = get(&lab.internals(0).map_err(message).unwrap(), "mode")
            .as_f64()
            .unwrap();
        m == 1.0 || m == 0.0
    });
    assert!(settled, "Orientation_only or done within 20 s");
    // Many agents.
    lab.spawn_random(500.0, 3.0, 20.0, 1.3)
        .map_err(message)
        .unwrap();
    assert_eq!(lab.count(), 501);
    lab.step(10).map_err(message).unwrap();
    assert_eq!(lab.state().len(), 501 * stride);
    // A stepping worker's one pass: `stepInto` gives the bits of
    // `step(1)` then `stateInto`; a wrong length steps nothing.
    let mut other = lab.fork().map_err(message).unwrap();
    lab = lab.fork().map_err(message).unwrap();
    for l in [&mut lab, &mut other] {
        l.spawn_random(500.0, 3.0, 20.0, 1.3)
            .map_err(message)
            .unwrap();
    }
    let (a, b) = (
        js_sys::Float32Array::new_with_length(500 * stride as u32),
        js_sys::Float32Array::new_with_length(500 * stride as u32),
    );
    for _ in 0..30 {
        lab.step_into(&a).map_err(message).unwrap();
        other.step(1).map_err(message).unwrap();
        other.state_into(&b).map_err(message).unwrap();
        let bits = |x: &js_sys::Float32Array| -> Vec<u32> {
            x.to_vec().iter().map(|f| f.to_bits()).collect()
        };
        assert_eq!(bits(&a), bits(&b));
    }
    let t = lab.time();
    let short = js_sys::Float32Array::new_with_length(stride as u32);
    let e = message(lab.step_into(&short).unwrap_err());
    assert!(e.contains("stepInto"), "{e}");
    assert_eq!(lab.time(), t);
}

#[wasm_bindgen_test]
fn bad_inputs_are_errors_not_panics() {
    let mut lab = Lab::new(TABLE).map_err(message).unwrap();
    let m = message(lab.internals(3).err().unwrap());
    assert!(m.contains("no agent 3"), "{m}");
    let m = message(lab.add_agent(JsValue::from_str("nope")).err().unwrap());
    assert!(m.contains("agent"), "{m}");
    let m = message(lab.add_agent(agent(f64::NAN, 0.0, 0.0, &[])).err().unwrap());
    assert!(m.contains("pos.x") || m.contains("finite"), "{m}");
    let m = message(lab.set_pose(0, 0.0, 0.0, 0.0).err().unwrap());
    assert!(m.contains("no agent 0"), "{m}");
    let m = message(lab.load_scenario("{\"name\": 1}").err().unwrap());
    assert!(m.contains("scenario"), "{m}");
    let params = lab.params().map_err(message).unwrap();
    js_sys::Reflect::set(&params, &"vMax".into(), &(-1.0).into()).unwrap();
    let m = message(lab.set_params(params).err().unwrap());
    assert!(m.contains("vMax"), "{m}");
    let m = message(lab.spawn_random(1.0, 1.0, f32::NAN, 1.0).err().unwrap());
    assert!(m.contains("extent"), "{m}");
}

#[wasm_bindgen_test]
fn the_presets_load() {
    let mut lab = Lab::new(TABLE).map_err(message).unwrap();
    for json in [
        include_str!("../scenarios/p000_fig1_seek.json"),
        include_str!("../scenarios/p000_fig3_funnel.json"),
        include_str!("../scenarios/p000_fig8_eighty.json"),
    ] {
        let info = lab.load_scenario(json).map_err(message).unwrap();
        assert!(get(&info, "agents").as_f64().unwrap() >= 1.0);
        lab.step(60).map_err(message).unwrap();
        assert!(lab.state().iter().all(|x| x.is_finite()));
    }
}

#[wasm_bindgen_test]
fn relaxed_goals_expose_the_arc_and_reach_the_region() {
    let mut lab = Lab::new(TABLE).map_err(message).unwrap();
    let g = goal(10.0, 3.0, 0.8);
    js_sys::Reflect::set(&g, &"relaxed".into(), &true.into()).unwrap();
    js_sys::Reflect::set(&g, &"dTol".into(), &1.5.into()).unwrap();
    js_sys::Reflect::set(&g, &"epsTol".into(), &0.26.into()).unwrap();
    lab.add_agent(agent(0.0, 0.0, 0.0, &[g]))
        .map_err(message)
        .unwrap();
    lab.step(30).map_err(message).unwrap();
    let arc = get(&lab.internals(0).map_err(message).unwrap(), "arc");
    assert!(arc.is_object(), "relaxed internals carry the arc 𝒜");
    let (a0, a1, ar) = (
        get(&arc, "alphaMin").as_f64().unwrap(),
        get(&arc, "alphaMax").as_f64().unwrap(),
        get(&arc, "alphaR").as_f64().unwrap(),
    );
    assert!(
        a0 <= ar + 1e-6 && ar <= a1 + 1e-6,
        "α_r in 𝒜: {a0} {ar} {a1}"
    );
    lab.step(1800).map_err(message).unwrap();
    let s = lab.state();
    let d = ((s[0] - 10.0).powi(2) + (s[1] - 3.0).powi(2)).sqrt();
    assert!(d < 1.5 + 0.3, "ends in the disk: {d}");
}

/// A funnel config object as the page builds it.
fn funnel_cfg(bound: JsValue, gain: f64, threshold: f64) -> JsValue {
    let o = js_sys::Object::new();
    js_sys::Reflect::set(&o, &"bound".into(), &bound).unwrap();
    js_sys::Reflect::set(&o, &"gain".into(), &gain.into()).unwrap();
    js_sys::Reflect::set(&o, &"seekThreshold".into(), &threshold.into()).unwrap();
    o.into()
}

fn bound(kind: &str, param: Option<(&str, f64)>) -> JsValue {
    let o = js_sys::Object::new();
    js_sys::Reflect::set(&o, &"kind".into(), &kind.into()).unwrap();
    if let Some((k, v)) = param {
        js_sys::Reflect::set(&o, &k.into(), &v.into()).unwrap();
    }
    o.into()
}

#[wasm_bindgen_test]
fn funnel_settings_round_trip_and_change_the_bound() {
    let mut lab = Lab::new(TABLE).map_err(message).unwrap();
    let f = lab.funnel().map_err(message).unwrap();
    let b = get(&f, "bound");
    assert_eq!(get(&b, "kind").as_string().unwrap(), "turningRadius");
    assert_eq!(get(&b, "factor").as_f64(), Some(8.0));
    assert_eq!(get(&f, "gain").as_f64(), Some(2.0));
    assert_eq!(get(&f, "seekThreshold").as_f64(), Some(0.25));
    assert_eq!(get(&f, "aim").as_string().as_deref(), Some("entry"));
    assert_eq!(get(&f, "minBoundRadius").as_f64(), Some(1.0));
    assert_eq!(get(&get(&f, "terminal"), "lookahead").as_f64(), Some(1.0));

    // Every bound round-trips (values exactly representable in f32).
    for (kind, param) in [
        ("literal", None),
        ("scaledLiteral", Some(("gain", 6.0))),
        ("turningRadius", Some(("factor", 3.5))),
        ("constant", None),
    ] {
        lab.set_funnel(funnel_cfg(bound(kind, param), 1.75, 0.5))
            .map_err(message)
            .unwrap();
        let f = lab.funnel().map_err(message).unwrap();
        let b = get(&f, "bound");
        assert_eq!(get(&b, "kind").as_string().unwrap(), kind);
        if let Some((k, v)) = param {
            assert_eq!(get(&b, k).as_f64(), Some(v), "{kind}.{k}");
        }
        assert_eq!(get(&f, "gain").as_f64(), Some(1.75), "{kind}");
        assert_eq!(get(&f, "seekThreshold").as_f64(), Some(0.5), "{kind}");
    }

    // A funnelling agent: target 6 m ahead, to be reached facing left.
    lab.set_funnel(funnel_cfg(
        bound("turningRadius", Some(("factor", 6.0))),
        2.0,
        0.25,
    ))
    .map_err(message)
    .unwrap();
    lab.add_agent(agent(0.0, 0.0, 0.0, &[goal(6.0, 0.0, 1.57)]))
        .map_err(message)
        .unwrap();
    lab.step(30).map_err(message).unwrap();
    let mu_max = |lab: &Lab| {
        let i = lab.internals(0).map_err(message).unwrap();
        assert_eq!(get(&i, "mode").as_f64(), Some(3.0), "Funnelling");
        get(&i, "muMax").as_f64().unwrap()
    };
    let default = mu_max(&lab);
    lab.set_funnel(funnel_cfg(bound("literal", None), 2.0, 0.25))
        .map_err(message)
        .unwrap();
    let literal = mu_max(&lab);
    assert!(
        (literal - default).abs() > 1e-3,
        "literal μ_max {literal} vs default {default}"
    );
    lab.set_funnel(funnel_cfg(bound("constant", None), 2.0, 0.25))
        .map_err(message)
        .unwrap();
    assert!((mu_max(&lab) - core::f64::consts::FRAC_PI_2).abs() < 1e-6);
    // The agents keep running under the new settings.
    assert_eq!(lab.count(), 1);
    lab.step(30).map_err(message).unwrap();
    assert!(lab.state().iter().all(|x| x.is_finite()));
}

/// The reading selector: "paper" puts paper 000's standard and paper
/// 001's relaxed funnelling in force, named so; "ours" restores the
/// defaults; anything else is an error naming the field.
#[wasm_bindgen_test]
fn the_reading_selects_the_papers_algorithms_or_ours() {
    let mut lab = Lab::new(TABLE).map_err(message).unwrap();
    assert_eq!(lab.controller_label(), "ours standard");
    lab.set_reading("paper".into()).map_err(message).unwrap();
    assert_eq!(lab.controller_label(), "paper 000 standard");
    let f = lab.funnel().map_err(message).unwrap();
    assert_eq!(
        get(&get(&f, "bound"), "kind").as_string().unwrap(),
        "literal"
    );
    assert_eq!(
        get(&f, "reachability").as_string().as_deref(),
        Some("closest")
    );
    assert_eq!(get(&f, "tolerance").as_string().as_deref(), Some("fig5"));
    assert_eq!(
        get(&f, "orientationOnly").as_string().as_deref(),
        Some("keepSpeed")
    );
    assert_eq!(get(&f, "lead").as_bool(), Some(false));
    lab.add_agent(agent(0.0, 0.0, 0.0, &[goal(6.0, 0.0, 1.57)]))
        .map_err(message)
        .unwrap();
    lab.step(30).map_err(message).unwrap();
    assert!(lab.state().iter().all(|x| x.is_finite()));
    lab.set_reading("ours".into()).map_err(message).unwrap();
    assert_eq!(lab.controller_label(), "ours standard");
    let m = message(lab.set_reading("papers".into()).unwrap_err());
    assert!(m.contains("reading"), "{m}");
}

/// The learn page's cost of the η table: the seek simulations and the
/// lookups run on the same seeded samples (counts deterministic, bounded
/// by n), and both refuse a lab without its table or a count out of range.
#[wasm_bindgen_test]
fn seek_simulations_and_table_lookups_share_their_samples() {
    let lab = Lab::new(TABLE).map_err(message).unwrap();
    let reached = lab.seek_simulations(64, 7).map_err(message).unwrap();
    let found = lab.table_lookups(64, 7).map_err(message).unwrap();
    assert!(reached > 0 && reached <= 64, "{reached}");
    assert!(found > 0 && found <= 64, "{found}");
    assert_eq!(
        lab.seek_simulations(64, 7).map_err(message).unwrap(),
        reached
    );
    assert_eq!(lab.table_lookups(64, 7).map_err(message).unwrap(), found);
    let m = message(lab.table_lookups(2_000_000, 7).unwrap_err());
    assert!(m.contains('n'), "{m}");
    let empty = Lab::without_table().map_err(message).unwrap();
    let m = message(empty.seek_simulations(4, 7).unwrap_err());
    assert!(m.contains("η table"), "{m}");
}

/// A value of the wrong type names its field, for every config (serde's
/// own message carries no path).
#[wasm_bindgen_test]
fn mistyped_values_name_their_field() {
    let mut lab = Lab::new(TABLE).map_err(message).unwrap();
    let p = lab.params().map_err(message).unwrap();
    js_sys::Reflect::set(&p, &"vMax".into(), &"fast".into()).unwrap();
    let m = message(lab.set_params(p).unwrap_err());
    assert!(
        m.starts_with("vehicle parameters, field `vMax`: expected a number, found the string"),
        "{m}"
    );
    let a = agent(0.0, 0.0, 0.0, &[goal(4.0, 0.0, 0.0)]);
    js_sys::Reflect::set(&a, &"theta".into(), &JsValue::TRUE).unwrap();
    let m = message(lab.add_agent(a).unwrap_err());
    assert!(m.starts_with("agent, field `theta`"), "{m}");
    // A mistyped required field and a bad optional one.
    let a = agent(0.0, 0.0, 0.0, &[]);
    js_sys::Reflect::set(&a, &"goals".into(), &"none".into()).unwrap();
    let m = message(lab.add_agent(a).unwrap_err());
    assert!(m.starts_with("agent, field `goals`"), "{m}");
    let a = agent(0.0, 0.0, 0.0, &[goal(4.0, 0.0, 0.0)]);
    js_sys::Reflect::set(&a, &"omega".into(), &"spin".into()).unwrap();
    let m = message(lab.add_agent(a).unwrap_err());
    assert!(m.starts_with("agent, field `omega`"), "{m}");
    // A missing field is named as itself, a nested one by its path.
    let g = goal(4.0, 0.0, 0.0);
    js_sys::Reflect::delete_property(&js_sys::Object::from(g.clone()), &"x".into()).unwrap();
    let m = message(
        lab.add_agent(agent(0.0, 0.0, 0.0, &[goal(1.0, 1.0, 0.0), g]))
            .unwrap_err(),
    );
    assert!(m.starts_with("agent, field `goals[1].x`: missing"), "{m}");
    let g = goal(4.0, 0.0, 0.0);
    js_sys::Reflect::set(&g, &"y".into(), &js_sys::Array::of1(&1.0.into())).unwrap();
    let m = message(lab.add_agent(agent(0.0, 0.0, 0.0, &[g])).unwrap_err());
    assert!(
        m.starts_with("agent, field `goals[0].y`: expected a number, found a list"),
        "{m}"
    );
    assert_eq!(lab.count(), 0);
    // A scenario file (the page's `loadScenario`) names the path too.
    let m = message(
        lab.load_scenario(r#"{"name": "s", "agents": [{"x": 0, "y": [1]}]}"#)
            .unwrap_err(),
    );
    assert!(
        m.contains("agents[0].y: expected a number, found a list"),
        "{m}"
    );
}

/// serde-wasm-bindgen never sees a key a struct does not declare; the
/// boundary checks the keys itself, so a misspelt one is an error naming it
/// (at any depth) instead of a silently used default.
#[wasm_bindgen_test]
fn misspelt_keys_are_errors_naming_them() {
    let mut lab = Lab::new(TABLE).map_err(message).unwrap();
    let set = |o: &JsValue, k: &str, v: JsValue| {
        js_sys::Reflect::set(o, &k.into(), &v).unwrap();
    };
    let tr = || bound("turningRadius", Some(("factor", 6.0)));

    let cfg = funnel_cfg(tr(), 2.0, 0.25);
    set(&cfg, "gian", 3.0.into());
    let m = message(lab.set_funnel(cfg).expect_err("`gian` must be refused"));
    assert!(
        m.contains("unknown field `gian`") && m.contains("gain"),
        "{m}"
    );
    let b = tr();
    set(&b, "factr", 4.0.into());
    let m = message(lab.set_funnel(funnel_cfg(b, 2.0, 0.25)).unwrap_err());
    assert!(m.contains("`bound.factr`"), "{m}");
    // Explicit undefined / null keys ask for nothing and pass.
    let cfg = funnel_cfg(tr(), 2.0, 0.25);
    set(&cfg, "note", JsValue::UNDEFINED);
    lab.set_funnel(cfg).map_err(message).unwrap();

    // A declared field the decoded value does not serialise at its
    // default (the unicycle's `minTurnRadius: 0`) is known, not misspelt.
    let p = lab.params().map_err(message).unwrap();
    set(&p, "minTurnRadius", 0.0.into());
    lab.set_params(p).map_err(message).unwrap();

    let p = lab.params().map_err(message).unwrap();
    set(&p, "maxSpeeed", 9.0.into());
    let m = message(lab.set_params(p).unwrap_err());
    assert!(
        m.starts_with("vehicle parameters: unknown field `maxSpeeed`"),
        "{m}"
    );

    let g = goal(4.0, 0.0, 0.0);
    set(&g, "dtol", 1.0.into());
    let m = message(
        lab.add_agent(agent(0.0, 0.0, 0.0, &[goal(1.0, 1.0, 0.0), g]))
            .unwrap_err(),
    );
    assert!(
        m.contains("unknown field `goals[1].dtol`") && m.contains("dTol"),
        "{m}"
    );
    assert_eq!(lab.count(), 0, "nothing added");
    lab.add_agent(agent(0.0, 0.0, 0.0, &[goal(4.0, 0.0, 0.0)]))
        .map_err(message)
        .unwrap();
    assert_eq!(lab.count(), 1);
}

#[wasm_bindgen_test]
fn invalid_funnel_settings_are_errors_naming_the_field() {
    let mut lab = Lab::new(TABLE).map_err(message).unwrap();
    let tr = || bound("turningRadius", Some(("factor", 6.0)));
    for (cfg, field) in [
        (funnel_cfg(tr(), f64::NAN, 0.25), "gain"),
        (funnel_cfg(tr(), -1.0, 0.25), "gain"),
        (funnel_cfg(tr(), 2.0, 2.0), "seekThreshold"),
        (funnel_cfg(bound("bogus", None), 2.0, 0.25), "bound"),
        (funnel_cfg(bound("scaledLiteral", None), 2.0, 0.25), "gain"),
        (funnel_cfg(tr(), 2.0, f64::INFINITY), "seekThreshold"),
    ] {
        let m = message(lab.set_funnel(cfg).expect_err("must be refused"));
        assert!(m.contains("funnel") && m.contains(field), "{field}: {m}");
    }
    let m = message(
        lab.set_funnel(funnel_cfg(bound("bogus", None), 2.0, 0.25))
            .err()
            .unwrap(),
    );
    assert!(m.contains("bogus") && m.contains("literal"), "{m}");
    let m = message(lab.set_funnel(JsValue::from_str("nope")).err().unwrap());
    assert!(m.contains("funnel settings"), "{m}");
    let bad_type = funnel_cfg(tr(), 2.0, 0.25);
    js_sys::Reflect::set(&bad_type, &"gain".into(), &"2".into()).unwrap();
    let m = message(lab.set_funnel(bad_type).err().unwrap());
    assert!(m.contains("funnel.gain"), "{m}");
    // A refused config leaves the one in force.
    let f = lab.funnel().map_err(message).unwrap();
    assert_eq!(get(&f, "gain").as_f64(), Some(2.0));
    assert_eq!(
        get(&get(&f, "bound"), "kind").as_string().unwrap(),
        "turningRadius"
    );
}

/// The layout the page reads by name (`StateField`, `Mode`) is where the
/// core writes each quantity: pose and goal as given, internals as
/// `Lab::internals` computes them for the same state.
#[wasm_bindgen_test]
fn the_exported_layout_matches_the_state_buffer() {
    use steering::bindings::layout::{Mode, StateField as F};
    let stride = Lab::state_stride() as usize;
    assert_eq!(F::GoalEpsTol as usize + 1, stride);
    let mut lab = Lab::new(TABLE).map_err(message).unwrap();
    lab.add_agent(agent(-4.0, 0.0, 0.3, &[goal(4.0, 2.0, 1.5)]))
        .map_err(message)
        .unwrap();
    let s = lab.state();
    let at = |s: &[f32], f: F| f64::from(s[f as usize]);
    for (f, want) in [
        (F::X, -4.0),
        (F::Y, 0.0),
        (F::Theta, 0.3),
        (F::V, 0.0),
        (F::Omega, 0.0),
        (F::GoalX, 4.0),
        (F::GoalY, 2.0),
        (F::GoalBeta, 1.5),
        (F::GoalDTol, 0.3),
        (F::GoalEpsTol, 0.17),
    ] {
        assert!(
            (at(&s, f) - want).abs() < 1e-6,
            "{f:?}: {} != {want}",
            at(&s, f)
        );
    }
    // One update from this state: the record holds what internals() computes for it.
    let before = lab.internals(0).map_err(message).unwrap();
    lab.step(1).map_err(message).unwrap();
    let s = lab.state();
    let mode = get(&before, "mode").as_f64().unwrap();
    assert_eq!(at(&s, F::Mode), mode);
    assert!(
        mode == f64::from(Mode::PositionOnly as u8) || mode == f64::from(Mode::Funnelling as u8),
        "far target: {mode}"
    );
    assert!(
        (at(&s, F::D) - 68f64.sqrt()).abs() < 1e-4,
        "D {}",
        at(&s, F::D)
    );
    for (f, key) in [
        (F::D, "d"),
        (F::Alpha, "alpha"),
        (F::Eta, "eta"),
        (F::DeltaEta, "deltaEta"),
        (F::Mu, "mu"),
        (F::Gamma, "gamma"),
        (F::VDt, "vDt"),
    ] {
        let want = get(&before, key).as_f64().unwrap();
        assert!(
            (at(&s, f) - want).abs() < 1e-5,
            "{f:?}: {} != {key} {want}",
            at(&s, f)
        );
    }
    let reachable = get(&before, "reachable").as_bool().unwrap();
    assert_eq!(at(&s, F::Reachable), if reachable { 1.0 } else { 0.0 });
    assert!(at(&s, F::V) > 0.0, "accelerating: v = {}", at(&s, F::V));
}

/// The ghost path through the bindings. Its η is the table's
/// within the interpolation error (the native `tests/ghost.rs` measures
/// the distribution); a forked lab shares the table and starts empty.
#[wasm_bindgen_test]
fn the_ghost_is_the_seek_the_update_asked_about_and_forks_share_the_table() {
    let mut lab = Lab::new(TABLE).map_err(message).unwrap();
    lab.add_agent(agent(-4.0, -1.0, 0.0, &[goal(3.0, 1.5, 1.57)]))
        .map_err(message)
        .unwrap();
    let inter = lab.internals(0).map_err(message).unwrap();
    let g = lab.ghost(0).map_err(message).unwrap();
    assert_eq!(get(&g, "reached").as_bool(), Some(true));
    let eta = get(&g, "eta").as_f64().unwrap();
    let table_eta = get(&inter, "eta").as_f64().unwrap();
    assert!(
        (eta - table_eta).abs().to_degrees() < 2.0,
        "ghost η {eta} vs table η {table_eta}"
    );
    let pts = js_sys::Float32Array::from(get(&g, "points"));
    let n = pts.length() as usize;
    assert!(n >= 4 && n % 2 == 0 && n <= 512, "{n}");
    assert_eq!((pts.get_index(0), pts.get_index(1)), (-4.0, -1.0));
    // The free-state form: straight ahead, η = 0, ends 0.25 m short.
    let g = lab
        .ghost_from(0.0, 0.0, 0.0, 1.0, 0.0, 10.0, 0.0, 1.3)
        .map_err(message)
        .unwrap();
    assert!(get(&g, "eta").as_f64().unwrap().abs() < 1e-3);
    let pts = js_sys::Float32Array::from(get(&g, "points"));
    let end = pts.get_index(pts.length() - 2);
    assert!((end - 9.75).abs() < 1e-3, "{end}");
    // Bad input names its field; nothing panics.
    let m = message(lab.ghost(7).expect_err("no agent 7"));
    assert!(m.contains("agent"), "{m}");
    let m = message(
        lab.ghost_from(0.0, 0.0, 0.0, 1.0, 0.0, f32::NAN, 0.0, 1.3)
            .expect_err("NaN target"),
    );
    assert!(m.contains("ghost.tx"), "{m}");
    let fork = lab.fork().map_err(message).unwrap();
    assert_eq!(fork.count(), 0);
    assert!(!fork.eta_field(1.0, 0.0, 1.3).is_empty());
}

/// The first frame without the table: a lab made without its table
/// shows the scene at t = 0 (provisional internals: γ the bearing, seek
/// ghost, no field), refuses to step, and once the table arrives runs the
/// very trajectory a lab made with the table runs, bit for bit: the
/// playground's agent with random ones, and a preset loaded before the
/// table.
#[wasm_bindgen_test]
fn a_lab_without_its_table_draws_then_runs_the_same_bits() {
    let build = |lab: &mut Lab, preset: Option<&str>| match preset {
        Some(json) => {
            lab.load_scenario(json).map_err(message).unwrap();
        }
        None => {
            lab.add_agent(agent(-4.0, 1.0, 0.3, &[goal(6.0, 2.0, 1.57)]))
                .map_err(message)
                .unwrap();
            lab.spawn_random(40.0, 5.0, 12.0, 1.3)
                .map_err(message)
                .unwrap();
        }
    };
    for preset in [
        None,
        Some(include_str!("../scenarios/p000_fig8_eighty.json")),
        Some(include_str!(
            "../scenarios/p001_fig12_successive_relaxed.json"
        )),
    ] {
        let mut with = Lab::new(TABLE).map_err(message).unwrap();
        build(&mut with, preset);
        let mut pending = Lab::without_table().map_err(message).unwrap();
        assert!(!pending.has_table());
        assert_eq!(
            pending.table_key(),
            with.table_key(),
            "the key it waits for"
        );
        build(&mut pending, preset);
        // Before the table: the scene at t = 0, seek steering, no η.
        assert_eq!(pending.count(), with.count());
        let inter = pending.internals(0).map_err(message).unwrap();
        let d = get(&inter, "d").as_f64().unwrap();
        assert!(d > 0.0 && d.is_finite());
        let ghost = pending.ghost(0).map_err(message).unwrap();
        assert!(js_sys::Float32Array::from(get(&ghost, "points")).length() >= 4);
        assert!(pending.eta_field(1.0, 0.0, 1.3).is_empty());
        let m = message(pending.step(1).expect_err("no step without a table"));
        assert!(m.contains("η table"), "{m}");
        assert!(message(pending.table_info().err().unwrap()).contains("not loaded"));
        // The table arrives: same plan, same trajectory.
        pending.set_table(TABLE, None).map_err(message).unwrap();
        assert!(pending.has_table());
        // Poses at t = 0 (random agents added after the playground's are
        // planned now, where `new` left them provisional until the first
        // step: only their internals differ, not what the step does).
        let (a, b) = (pending.state(), with.state());
        assert_eq!(a.len(), b.len());
        let stride = Lab::state_stride() as usize;
        assert!(
            a.chunks(stride).zip(b.chunks(stride)).all(|(x, y)| x[..5]
                .iter()
                .zip(&y[..5])
                .all(|(p, q)| p.to_bits() == q.to_bits())),
            "poses at t = 0 differ"
        );
        for _ in 0..20 {
            pending.step(30).map_err(message).unwrap();
            with.step(30).map_err(message).unwrap();
        }
        let (a, b) = (pending.state(), with.state());
        assert!(
            a.iter().zip(&b).all(|(x, y)| x.to_bits() == y.to_bits()),
            "trajectories differ after 10 s"
        );
    }
}

/// Many agents in one call, all or none, a refusal naming the agent;
/// per-agent `done` / `atRest` / `mode`; a missing field named itself.
#[wasm_bindgen_test]
fn agents_added_in_one_call_and_asked_whether_they_are_done() {
    let mut lab = Lab::new(TABLE).map_err(message).unwrap();
    let list = js_sys::Array::new();
    for k in 0..3 {
        list.push(&agent(
            f64::from(k),
            0.0,
            0.0,
            &[goal(3.0, f64::from(k), 0.0)],
        ));
    }
    let bad = js_sys::Array::from(&JsValue::from(list.clone()));
    bad.push(&agent(f64::NAN, 0.0, 0.0, &[]));
    let m = message(lab.add_agents(bad.into()).unwrap_err());
    assert!(m.starts_with("agents[3]"), "{m}");
    assert_eq!(lab.count(), 0);
    assert_eq!(lab.add_agents(list.into()).map_err(message).unwrap(), 0);
    assert_eq!(lab.count(), 3);
    assert!(!lab.done(0).map_err(message).unwrap());
    for _ in 0..1200 {
        lab.step(1).map_err(message).unwrap();
    }
    for i in 0..3 {
        assert!(lab.at_rest(i).map_err(message).unwrap(), "agent {i}");
        assert!(lab.done(i).map_err(message).unwrap());
        assert_eq!(lab.mode(i).map_err(message).unwrap(), bindings_mode());
    }
    assert_eq!(lab.modes(), vec![0, 0, 0]);
    let m = message(lab.done(3).unwrap_err());
    assert!(m.contains("no agent 3"), "{m}");
    let a = agent(0.0, 0.0, 0.0, &[goal(4.0, 0.0, 0.0)]);
    js_sys::Reflect::delete_property(&js_sys::Object::from(a.clone()), &"theta".into()).unwrap();
    let m = message(lab.add_agent(a).unwrap_err());
    assert!(m.starts_with("agent, field `theta`: missing"), "{m}");
}

fn bindings_mode() -> steering::bindings::layout::Mode {
    steering::bindings::layout::Mode::EndOfSteering
}
