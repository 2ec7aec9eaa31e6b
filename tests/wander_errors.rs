//! Bad wander configurations come back as typed errors, never panics
//! (project convention; the gallery shows these messages to users).
//! No proptest here, so it also runs as a wasm-bindgen test.

#[cfg(target_arch = "wasm32")]
wasm_bindgen_test::wasm_bindgen_test_configure!(run_in_browser);

use steering::base::range::RangeError;
use steering::wander::{error::WanderError, pipeline::WanderPreset, pipeline::Wanderer};

fn build(control: &str, source: &str) -> Result<Wanderer, WanderError> {
    Wanderer::from_json(&format!(r#"{{"control": {control}, "source": {source}}}"#))
}

const UNIFORM: &str = r#"{"kind": "random", "distribution": {"kind": "uniform"}}"#;
const VEL: &str = r#"{"mode": "velocity", "max_velocity_deg": 10}"#;

#[test]
#[cfg_attr(target_arch = "wasm32", wasm_bindgen_test::wasm_bindgen_test)]
fn clamps_must_be_positive_finite_and_at_most_180() {
    let e = build(r#"{"mode": "velocity", "max_velocity_deg": -5}"#, UNIFORM).unwrap_err();
    assert!(
        matches!(
            e,
            WanderError::Range(RangeError {
                field: "control.max_velocity_deg",
                ..
            })
        ),
        "{e}"
    );
    let e = build(
        r#"{"mode": "velocity", "max_acceleration_deg": 0}"#,
        UNIFORM,
    )
    .unwrap_err();
    assert!(matches!(e, WanderError::NotPositive { .. }), "{e}");
    let e = build(
        r#"{"mode": "velocity", "max_displacement_deg": 200}"#,
        UNIFORM,
    )
    .unwrap_err();
    assert!(matches!(e, WanderError::Range(_)), "{e}");
    let e = build(
        r#"{"mode": "velocity", "max_velocity_deg": 10, "quantize_deg": 30}"#,
        UNIFORM,
    )
    .unwrap_err();
    assert!(
        matches!(
            e,
            WanderError::Range(RangeError {
                field: "control.quantize_deg",
                ..
            })
        ),
        "{e}"
    );
    // NaN cannot be written in JSON; a literal too large for f32 becomes ∞.
    let e = build(
        r#"{"mode": "velocity", "max_velocity_deg": 1e300}"#,
        UNIFORM,
    )
    .unwrap_err();
    assert!(
        matches!(e, WanderError::Range(ref r) if r.not_finite()),
        "{e}"
    );
}

#[test]
#[cfg_attr(target_arch = "wasm32", wasm_bindgen_test::wasm_bindgen_test)]
fn schema_errors_are_json_errors() {
    for bad in [
        r#"{"control": {"mode": "velocity", "max_velocity": 10}, "source": {"kind": "random", "distribution": {"kind": "uniform"}}}"#,
        r#"{"control": {"mode": "sideways"}, "source": {"kind": "random", "distribution": {"kind": "uniform"}}}"#,
        r#"{"control": {"mode": "velocity"}, "source": {"kind": "random", "distribution": {"kind": "gaussian"}}}"#,
        r#"{"control": {"mode": "velocity"}, "source": {"kind": "random", "distribution": {"kind": "uniform", "x": 1}}}"#,
        r#"{"control": {"mode": "velocity"}, "source": {"kind": "random", "distribution": {"kind": "perlin", "period": NaN}}}"#,
        r#"{"control": {"mode": "velocity"}}"#,
        "not json",
    ] {
        let e = Wanderer::from_json(bad).unwrap_err();
        assert!(matches!(e, WanderError::Json(_)), "{bad}: {e}");
    }
}

#[test]
#[cfg_attr(target_arch = "wasm32", wasm_bindgen_test::wasm_bindgen_test)]
fn distribution_errors() {
    let src = |d: &str| format!(r#"{{"kind": "random", "distribution": {d}}}"#);
    type Check = fn(&WanderError) -> bool;
    let cases: [(&str, Check); 7] = [
        (r#"{"kind": "smooth_noise", "period": 0}"#, |e| {
            matches!(e, WanderError::Range(_))
        }),
        (r#"{"kind": "perlin", "period": -1}"#, |e| {
            matches!(e, WanderError::NotPositive { .. })
        }),
        (r#"{"kind": "perlin", "period": 5, "octaves": 0}"#, |e| {
            matches!(e, WanderError::Range(_))
        }),
        (r#"{"kind": "curve", "points": []}"#, |e| {
            matches!(e, WanderError::ShapeMismatch { .. })
        }),
        (r#"{"kind": "curve", "points": [[0, 1], [-0.5, 1]]}"#, |e| {
            matches!(e, WanderError::NotIncreasing { .. })
        }),
        (r#"{"kind": "curve", "points": [[-1, 0], [1, 0]]}"#, |e| {
            matches!(e, WanderError::NotPositive { .. })
        }),
        (r#"{"kind": "curve", "points": [[-1, 1], [1, -2]]}"#, |e| {
            matches!(e, WanderError::Range(_))
        }),
    ];
    for (d, ok) in cases {
        let e = build(VEL, &src(d)).unwrap_err();
        assert!(ok(&e), "{d}: {e}");
    }
}

#[test]
#[cfg_attr(target_arch = "wasm32", wasm_bindgen_test::wasm_bindgen_test)]
fn markov_errors() {
    let m = |edges: &str, table: &str, extra: &str| {
        build(
            VEL,
            &format!(r#"{{"kind": "markov", "markov": {{"edges_deg": {edges}, "table": {table}{extra}}}}}"#),
        )
        .unwrap_err()
    };
    // The paper's cumulative-table typo: 0.15 + 0.8 + 0.15.
    let e = m(
        "[0, 15, 30, 45]",
        "[[0.9, 0.07, 0.03], [0.15, 0.8, 0.15], [0.1, 0.2, 0.7]]",
        "",
    );
    assert!(matches!(e, WanderError::RowSum { row: 1, .. }), "{e}");
    let e = m("[0, 15, 30]", "[[1, 0], [0.5, 0.5], [0.5, 0.5]]", "");
    assert!(
        matches!(
            e,
            WanderError::ShapeMismatch {
                what: "markov.table",
                ..
            }
        ),
        "{e}"
    );
    let e = m("[0, 15, 30]", "[[1, 0], [0.5]]", "");
    assert!(matches!(e, WanderError::ShapeMismatch { .. }), "{e}");
    let e = m("[0, 30, 15]", "[[1, 0], [0, 1]]", "");
    assert!(matches!(e, WanderError::NotIncreasing { .. }), "{e}");
    let e = m("[0]", "[]", "");
    assert!(matches!(e, WanderError::ShapeMismatch { .. }), "{e}");
    let e = m("[0, 15, 30]", "[[1.5, -0.5], [0, 1]]", "");
    assert!(matches!(e, WanderError::Range(_)), "{e}");
    let e = m(
        "[0, 15, 30]",
        "[[1, 0], [0, 1]]",
        r#", "change_probability": [0.5]"#,
    );
    assert!(matches!(e, WanderError::ShapeMismatch { .. }), "{e}");
    let e = m(
        "[0, 15, 30]",
        "[[1, 0], [0, 1]]",
        r#", "change_probability": [0.5, 2]"#,
    );
    assert!(matches!(e, WanderError::Range(_)), "{e}");
    let e = m("[0, 15, 30]", "[[1, 0], [0, 1]]", r#", "initial_range": 2"#);
    assert!(matches!(e, WanderError::Range(_)), "{e}");
}

#[test]
#[cfg_attr(target_arch = "wasm32", wasm_bindgen_test::wasm_bindgen_test)]
fn field_time_hold_and_path_errors() {
    let field = |f: &str| build(VEL, &format!(r#"{{"kind": "field", "field": {f}}}"#)).unwrap_err();
    assert!(matches!(
        field(r#"{"cols": 1, "rows": 4, "cell": 10}"#),
        WanderError::Range(_)
    ));
    assert!(matches!(
        field(r#"{"cols": 4, "rows": 4, "cell": 0}"#),
        WanderError::Range(_)
    ));
    assert!(matches!(
        field(r#"{"cols": 4, "rows": 4, "cell": 5, "count": 4}"#),
        WanderError::Range(_)
    ));

    let tf = |f: &str| {
        build(
            VEL,
            &format!(r#"{{"kind": "time_function", "function": {f}}}"#),
        )
        .unwrap_err()
    };
    assert!(matches!(tf(r#"{"terms": []}"#), WanderError::Empty { .. }));
    assert!(matches!(
        tf(r#"{"terms": [{"amplitude": 1, "frequency": 1}], "dt": 0}"#),
        WanderError::NotPositive { .. }
    ));
    assert!(matches!(
        tf(r#"{"terms": [{"amplitude": 1, "frequency": 1, "weight": "blend"}]}"#),
        WanderError::Empty {
            what: "time_function.blend"
        }
    ));

    let hold = |h: &str| {
        Wanderer::from_json(&format!(
            r#"{{"control": {VEL}, "source": {UNIFORM}, "hold": {h}}}"#
        ))
        .unwrap_err()
    };
    assert!(matches!(
        hold(r#"{"kind": "fixed", "every": 0}"#),
        WanderError::Range(_)
    ));
    assert!(matches!(
        hold(r#"{"kind": "random", "min": 5, "max": 2}"#),
        WanderError::Range(_)
    ));

    let path = |p: &str, mode: &str| {
        build(
            &format!(r#"{{"mode": "{mode}"}}"#),
            &format!(r#"{{"kind": "path", "lookahead": 5, "path": {p}}}"#),
        )
        .unwrap_err()
    };
    let circle = r#"{"kind": "circle", "center": [0, 0], "radius": 10, "coefficients": [1]}"#;
    assert_eq!(
        path(circle, "displacement"),
        WanderError::PathNeedsVelocityMode
    );
    let e = path(
        r#"{"kind": "circle", "center": [0, 0], "radius": 10, "coefficients": [6, 5]}"#,
        "velocity",
    );
    assert!(matches!(e, WanderError::Range(_)), "{e}");
    let e = path(
        r#"{"kind": "fractal", "start": [0, 0], "end": [1, 0], "depth": 16, "roughness": 0.2, "rule": "thirds"}"#,
        "velocity",
    );
    assert!(matches!(e, WanderError::TooLarge { .. }), "{e}");
    let e = path(
        r#"{"kind": "fractal", "start": [1, 1], "end": [1, 1], "depth": 3, "roughness": 0.2, "rule": "midpoint"}"#,
        "velocity",
    );
    assert!(matches!(e, WanderError::NotPositive { .. }), "{e}");

    let e = Wanderer::from_json(&format!(
        r#"{{"control": {VEL}, "source": {UNIFORM}, "trace_capacity": 0}}"#
    ))
    .unwrap_err();
    assert!(matches!(e, WanderError::Range(_)));
    // Messages are readable.
    assert_eq!(
        WanderError::RowSum { row: 1, sum: 1.1 }.to_string(),
        "transition table row 1 must sum to 1 (sums to 1.1)"
    );
}

#[test]
#[cfg_attr(target_arch = "wasm32", wasm_bindgen_test::wasm_bindgen_test)]
fn mix_errors() {
    let mix =
        |parts: &str| build(VEL, &format!(r#"{{"kind": "mix", "parts": {parts}}}"#)).unwrap_err();
    assert_eq!(mix("[]"), WanderError::Empty { what: "mix.parts" });
    let path = r#"{"kind": "path", "lookahead": 5, "path": {"kind": "circle", "center": [0, 0], "radius": 10, "coefficients": []}}"#;
    assert_eq!(
        mix(&format!(r#"[{{"weight": 1, "source": {path}}}]"#)),
        WanderError::NotMixable { what: "path" }
    );
    let inner = format!(r#"{{"kind": "mix", "parts": [{{"weight": 1, "source": {UNIFORM}}}]}}"#);
    assert_eq!(
        mix(&format!(r#"[{{"weight": 1, "source": {inner}}}]"#)),
        WanderError::NotMixable { what: "mix" }
    );
    let e = mix(&format!(r#"[{{"weight": 1e300, "source": {UNIFORM}}}]"#));
    assert!(
        matches!(e, WanderError::Range(ref r) if r.not_finite()),
        "{e}"
    );
    let e = mix(
        r#"[{"weight": 1, "source": {"kind": "random", "distribution": {"kind": "smooth_noise", "period": 0}}}]"#,
    );
    assert!(matches!(e, WanderError::Range(_)), "{e}");
}

#[test]
#[cfg_attr(target_arch = "wasm32", wasm_bindgen_test::wasm_bindgen_test)]
fn presets_reject_empty_variant_lists() {
    let e =
        WanderPreset::from_json(r#"{"title": "t", "section": "s", "steps": 10, "variants": []}"#)
            .unwrap_err();
    assert_eq!(
        e,
        WanderError::Empty {
            what: "preset.variants"
        }
    );
}
