//! The core's validation ranges through the bindings, in headless Chromium
//! (one source for ranges): `ranges()` exports exactly the
//! core's table (`steering::base::ranges::ALL`), and a value just outside each
//! range is refused by the binding that takes it, with the field named: the
//! page that derives its inputs from `ranges()` and the core agree at both
//! ends of every range.
#![cfg(target_arch = "wasm32")]

use steering::base::ranges::{FieldRange, ALL};
use steering::bindings::lab::{self as bindings, Lab};
use wasm_bindgen::JsValue;
use wasm_bindgen_test::*;

wasm_bindgen_test_configure!(run_in_browser);

mod common;
use common::message;

static TABLE: &[u8] = include_bytes!("../tables/eta.bin");

fn get(v: &JsValue, k: &str) -> JsValue {
    js_sys::Reflect::get(v, &k.into()).unwrap()
}

fn json(text: &str) -> JsValue {
    js_sys::JSON::parse(text).unwrap_or_else(|e| panic!("{text}: {e:?}"))
}

#[wasm_bindgen_test]
fn the_exported_ranges_are_the_cores_table() {
    let out = js_sys::Array::from(&bindings::ranges().map_err(message).unwrap());
    assert_eq!(out.length() as usize, ALL.len());
    for (i, r) in ALL.iter().enumerate() {
        let o = out.get(i as u32);
        assert_eq!(get(&o, "key").as_string().unwrap(), r.key);
        assert_eq!(get(&o, "min").as_f64().unwrap(), r.min, "{}", r.key);
        assert_eq!(get(&o, "max").as_f64().unwrap(), r.max, "{}", r.key);
        assert_eq!(get(&o, "unit").as_string().unwrap(), r.unit);
        assert_eq!(get(&o, "integer").as_bool().unwrap(), r.integer);
        assert_eq!(get(&o, "atMost").as_string().as_deref(), r.at_most);
        assert!(r.at_most.is_some() || get(&o, "atMost").is_null());
    }
}

/// A JavaScript object from JSON text, with `path` (keys, array indices as
/// digits) set to `v` (NaN included, which JSON text cannot carry).
fn with(text: &str, path: &[&str], v: f64) -> JsValue {
    let root = json(text);
    let mut o = root.clone();
    for k in &path[..path.len() - 1] {
        o = get(&o, k);
    }
    js_sys::Reflect::set(&o, &(*path.last().unwrap()).into(), &v.into()).unwrap();
    root
}

/// The playground's agent: at the origin, one goal.
const AGENT: &str = r#"{"x": 0, "y": 0, "theta": 0, "v": 0, "omega": 0, "goals": [{"x": 3, "y": 1, "beta": 0, "dTol": 0.3, "epsTol": 0.1, "speed": 1.3, "halting": false, "relaxed": false}]}"#;
const FUNNEL: &str = r#"{"bound": {"kind": "literal"}, "gain": 2, "seekThreshold": 0.25}"#;

/// A scenario of two agents, agent 0's goal moving by `motion`.
fn scenario(motion: &str, duration: f64) -> String {
    format!(
        r#"{{"name": "r", "duration": {duration}, "agents": [{{"x": 0, "y": 0, "goals": [{{"x": 3, "y": 1, "motion": {motion}}}]}}, {{"x": 5, "y": 5}}]}}"#
    )
}

/// Sets the field `r.key` to `v` through the binding that takes it; the
/// error message if it was refused. `None` for NaN where only JSON text
/// reaches the field (scenarios: JSON has no NaN).
fn try_value(r: &FieldRange, v: f64) -> Option<Option<String>> {
    let mut lab = Lab::new(TABLE).map_err(message).unwrap();
    let key = r.key;
    let last = key.rsplit('.').next().unwrap();
    let text_only = key.starts_with("motion.")
        || key.starts_with("avoidance.")
        || key.starts_with("obstacle.")
        || key == "duration";
    let avoid = |fields: String, obstacles: &str| {
        format!(
            r#"{{"name": "r", "avoidance": {{"method": "orca", {fields}}}, "obstacles": [{obstacles}], "agents": [{{"x": 0, "y": 0, "goals": [{{"x": 3, "y": 1}}]}}]}}"#
        )
    };
    if text_only && v.is_nan() {
        return None;
    }
    let result = match key {
        "dt" | "vMax" | "accelMax" | "omegaMax" | "omegaAccelMax" | "normalAccelMax" | "kp"
        | "kd" | "minTurnRadius" | "vReverse" | "gearChangeCost" => {
            let p = lab.params().map_err(message).unwrap();
            js_sys::Reflect::set(&p, &key.into(), &v.into()).unwrap();
            lab.set_params(p).map(|_| ())
        }
        "pos.x" | "pos.y" | "theta" | "v" | "omega" => {
            lab.add_agent(with(AGENT, &[last], v)).map(|_| ())
        }
        "goal.pos.x" | "goal.pos.y" | "goal.beta" | "goal.dTol" | "goal.epsTol" | "goal.speed" => {
            lab.add_agent(with(AGENT, &["goals", "0", last], v))
                .map(|_| ())
        }
        "motion.velocity.x" => lab
            .load_scenario(&scenario(
                &format!(r#"{{"kind": "linear", "velocity": [{v}, 0]}}"#),
                10.0,
            ))
            .map(|_| ()),
        "motion.velocity.y" => lab
            .load_scenario(&scenario(
                &format!(r#"{{"kind": "linear", "velocity": [0, {v}]}}"#),
                10.0,
            ))
            .map(|_| ()),
        "motion.center.x" => lab
            .load_scenario(&scenario(
                &format!(r#"{{"kind": "circle", "center": [{v}, 0], "angularSpeed": 0.001}}"#),
                10.0,
            ))
            .map(|_| ()),
        "motion.center.y" => lab
            .load_scenario(&scenario(
                &format!(r#"{{"kind": "circle", "center": [0, {v}], "angularSpeed": 0.001}}"#),
                10.0,
            ))
            .map(|_| ()),
        "motion.angularSpeed" => lab
            .load_scenario(&scenario(
                &format!(r#"{{"kind": "circle", "center": [3, 0.5], "angularSpeed": {v}}}"#),
                10.0,
            ))
            .map(|_| ()),
        "motion.distance" => lab
            .load_scenario(&scenario(
                &format!(r#"{{"kind": "faceAgent", "agent": 1, "distance": {v}}}"#),
                10.0,
            ))
            .map(|_| ()),
        "duration" => lab
            .load_scenario(&scenario(r#"{"kind": "static"}"#, v))
            .map(|_| ()),
        "funnel.seekThreshold" | "funnel.gain" => lab.set_funnel(with(FUNNEL, &[last], v)),
        "funnel.bound.gain" => lab.set_funnel(with(
            &FUNNEL.replace(r#""literal""#, r#""scaledLiteral", "gain": 6"#),
            &["bound", "gain"],
            v,
        )),
        "funnel.bound.factor" => lab.set_funnel(with(
            &FUNNEL.replace(r#""literal""#, r#""turningRadius", "factor": 8"#),
            &["bound", "factor"],
            v,
        )),
        "relaxed.diskMargin" | "relaxed.orientationMargin" => {
            lab.set_relaxed(with("{}", &[last], v))
        }
        // The lab's random agents come on top of the playground agent.
        "agents" => {
            lab.add_agent(json(AGENT)).map_err(message).unwrap();
            lab.check_room(v)
        }
        "seed" => lab.spawn_random(1.0, v, 10.0, 1.3),
        // Scenario files only (the reach must cover two radii
        // plus the margin at both ends of those ranges).
        "avoidance.radius" | "avoidance.margin" => lab
            .load_scenario(&avoid(format!(r#""{last}": {v}, "reach": 1000"#), ""))
            .map(|_| ()),
        "avoidance.reach" => lab
            .load_scenario(&avoid(
                format!(r#""radius": 0.01, "margin": 0, "reach": {v}"#),
                "",
            ))
            .map(|_| ()),
        "avoidance.horizon"
        | "avoidance.obstacleHorizon"
        | "avoidance.maxNeighbours"
        | "avoidance.separationWeight"
        | "avoidance.biasDeg"
        | "avoidance.replanEvery" => lab
            .load_scenario(&avoid(format!(r#""{last}": {v}"#), ""))
            .map(|_| ()),
        "obstacle.x" => lab
            .load_scenario(&avoid(
                "\"radius\": 0.3".into(),
                &format!(r#"{{"kind": "disc", "x": {v}, "y": 0, "radius": 1}}"#),
            ))
            .map(|_| ()),
        "obstacle.y" => lab
            .load_scenario(&avoid(
                "\"radius\": 0.3".into(),
                &format!(r#"{{"kind": "disc", "x": 0, "y": {v}, "radius": 1}}"#),
            ))
            .map(|_| ()),
        "obstacle.radius" => lab
            .load_scenario(&avoid(
                "\"radius\": 0.3".into(),
                &format!(r#"{{"kind": "disc", "x": 0, "y": 9, "radius": {v}}}"#),
            ))
            .map(|_| ()),
        "extent" => lab.spawn_random(1.0, 1.0, v as f32, 1.3),
        other => panic!("no binding takes {other}: add it here"),
    };
    Some(result.err().map(message))
}

/// The bound a field has with the default vehicle (2 m/s, 2 rad/s) and
/// the playground agent: positions also stay where f32 resolves a step of
/// the agent's goal (`precision::agent_limit`, 45,438 m at 1.3 m/s and
/// 1/60 s; the range's ±1e6 m is the cap for fast, coarse vehicles), a
/// circle's centre so that its far side does.
fn effective_max(r: &FieldRange) -> f64 {
    let on_circle = r.key.starts_with("motion.center");
    if r.key.ends_with("pos.x") || r.key.ends_with("pos.y") || on_circle {
        let p = steering::base::vehicle::VehicleParams::default();
        let goal = steering::world::goals::GoalSpec {
            goal: steering::funnelling::goal::Goal {
                speed: 1.3,
                d_tol: 0.3,
                ..Default::default()
            },
            ..Default::default()
        };
        let limit = f64::from(steering::world::precision::agent_limit(&p, &[goal]));
        // A circle's far side (2·centre − goal, the goal at (3, 1)) must
        // stay inside too.
        return if on_circle {
            (limit - 3.0) / 2.0
        } else {
            limit
        };
    }
    match r.at_most {
        Some("vMax") => r.max.min(2.0),
        Some("omegaMax") => r.max.min(2.0),
        Some(other) => panic!("unknown bound {other}"),
        None => r.max,
    }
}

#[wasm_bindgen_test]
fn a_value_just_outside_each_range_is_refused_with_the_field_named() {
    check_ends(ALL.iter());
}

/// The avoidance ranges alone (scenario files: avoidance settings, obstacles).
#[wasm_bindgen_test]
fn the_avoidance_ranges_are_refused_outside_and_accepted_at_both_ends() {
    check_ends(
        ALL.iter()
            .filter(|r| r.key.starts_with("avoidance.") || r.key.starts_with("obstacle.")),
    );
}

fn check_ends<'a>(ranges: impl Iterator<Item = &'a FieldRange>) {
    for r in ranges {
        let max = effective_max(r);
        let min = if r.min < 0.0 && (r.at_most.is_some() || max < r.max) {
            -max
        } else {
            r.min
        };
        let (below, above) = if r.integer {
            (min - 1.0, max + 1.0)
        } else {
            (
                min - (min.abs() * 1e-3).max(1e-3),
                max + (max.abs() * 1e-3).max(1e-3),
            )
        };
        for v in [below, above, f64::NAN] {
            let Some(refused) = try_value(r, v) else {
                continue;
            };
            let m = refused.unwrap_or_else(|| panic!("{} = {v} was accepted", r.key));
            let field = r.key.rsplit('.').next().unwrap();
            assert!(m.contains(field), "{} = {v}: {m}", r.key);
        }
        // Both ends are accepted.
        for v in [min, max] {
            assert_eq!(try_value(r, v), Some(None), "{} = {v} was refused", r.key);
        }
    }
}
