#![cfg(not(target_arch = "wasm32"))]
//! Property tests (native only: proptest needs OS entropy) for the random
//! steering toolkit's invariants: the clamps of paper 004 §1 are never
//! exceeded, whatever the source, hold or discrete set; and no input,
//! however bad, makes building a wanderer panic.

use proptest::prelude::*;
use steering::base::angle;
use steering::wander::pipeline::Wanderer;

fn source_json(kind: u8, seed: u64) -> String {
    match kind {
        0 => r#"{"kind": "random", "distribution": {"kind": "uniform"}}"#.into(),
        1 => r#"{"kind": "random", "distribution": {"kind": "smooth_noise", "period": 5}}"#.into(),
        2 => r#"{"kind": "random", "distribution": {"kind": "perlin", "period": 17, "octaves": 3}}"#
            .into(),
        3 => r#"{"kind": "random", "distribution": {"kind": "curve", "points": [[-1, 0], [0.5, 2], [1, 0.2]]}}"#.into(),
        4 => format!(
            r#"{{"kind": "field", "field": {{"cols": 6, "rows": 5, "cell": {}, "count": 2, "switch_every": 40, "jitter_deg": 3, "bias": {}}}}}"#,
            5 + seed % 40,
            seed % 2 == 0
        ),
        5 => r#"{"kind": "time_function", "function": {"terms": [{"amplitude": 2, "frequency": 1}, {"amplitude": 1, "frequency": 50, "weight": "blend"}], "blend": {"kind": "smooth", "period": 30}, "envelope": {"kind": "white"}}}"#.into(),
        7 => format!(
            r#"{{"kind": "mix", "parts": [{{"weight": 3, "source": {}}}, {{"weight": -2, "source": {}}}, {{"weight": 0.5, "source": {}}}]}}"#,
            source_json(0, seed),
            source_json(4, seed),
            source_json(6, seed)
        ),
        _ => r#"{"kind": "markov", "markov": {"edges_deg": [-170, -30, 0, 30, 170], "table": [[0.7, 0.1, 0.1, 0.1], [0.1, 0.7, 0.1, 0.1], [0.1, 0.1, 0.7, 0.1], [0.1, 0.1, 0.1, 0.7]], "change_probability": [0.5, 1, 1, 0.5]}}"#.into(),
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(160))]

    /// From the trace alone: displacement never leaves ±max_d around the
    /// start heading; the turn per step never exceeds max_v; the change of
    /// turn never exceeds max_a.
    #[test]
    fn clamps_are_never_exceeded(
        seed in any::<u64>(),
        mode in 0u8..3,
        kind in 0u8..8,
        max_d in 0.5f32..180.0,
        max_v in 0.5f32..170.0,
        max_a in 0.05f32..90.0,
        heading in -720.0f32..720.0,
        quantize in proptest::option::of(0.01f32..1.0),
        hold in proptest::option::of(1u32..20),
    ) {
        let mode_s = ["displacement", "velocity", "acceleration"][mode as usize];
        let scale = [max_d, max_v, max_a][mode as usize];
        let q = quantize.map_or(String::new(), |f| format!(r#", "quantize_deg": {}"#, f * scale));
        let h = hold.map_or(String::new(), |n| format!(r#", "hold": {{"kind": "random", "min": 1, "max": {n}}}"#));
        let json = format!(
            r#"{{"seed": {seed}, "agent": {{"heading_deg": {heading}, "speed": 3}},
              "control": {{"mode": "{mode_s}", "max_displacement_deg": {max_d},
              "max_velocity_deg": {max_v}, "max_acceleration_deg": {max_a}{q}}},
              "source": {src}{h}}}"#,
            src = source_json(kind, seed)
        );
        let mut w = Wanderer::from_json(&json).unwrap();
        w.run(300);
        let t = w.trace();
        let hs: Vec<f32> = t.chunks(3).map(|p| p[2]).collect();
        let base = hs[0];
        let tol = 2e-5;
        let (md, mv, ma) = (max_d.to_radians(), max_v.to_radians(), max_a.to_radians());
        let mut prev_v = 0.0f32;
        for (k, pair) in hs.windows(2).enumerate() {
            match mode {
                0 => prop_assert!(angle::diff(pair[1], base).abs() <= md + tol),
                _ => {
                    let v = angle::diff(pair[1], pair[0]);
                    prop_assert!(v.abs() <= mv + tol, "turn {} > {}", v, mv);
                    if mode == 2 {
                        prop_assert!((v - prev_v).abs() <= ma + 2.0 * tol, "step {}: Δturn {} > {}", k, v - prev_v, ma);
                    }
                    prev_v = v;
                }
            }
            // Constant forward speed.
            let (a, b) = (&t[k * 3..k * 3 + 2], &t[k * 3 + 3..k * 3 + 5]);
            prop_assert!((((b[0] - a[0]).powi(2) + (b[1] - a[1]).powi(2)).sqrt() - 3.0).abs() < 1e-3);
        }
    }

    /// Arbitrary numbers (NaN and infinities included, written as JSON
    /// strings they are rejected by serde; as huge literals they overflow
    /// to ∞) never panic: they build or give a typed error.
    #[test]
    fn bad_numbers_never_panic(
        a in prop_oneof![any::<f32>().prop_map(|x| format!("{x:e}")), Just("1e40".to_string()), Just("-0".to_string())],
        b in prop_oneof![any::<f32>().prop_map(|x| format!("{x:e}")), Just("-1e40".to_string())],
        n in any::<u32>(),
        which in 0u8..6,
    ) {
        let json = match which {
            0 => format!(r#"{{"control": {{"mode": "velocity", "max_velocity_deg": {a}}}, "source": {{"kind": "random", "distribution": {{"kind": "perlin", "period": {b}, "octaves": {n}}}}}}}"#),
            1 => format!(r#"{{"control": {{"mode": "acceleration", "max_acceleration_deg": {a}, "quantize_deg": {b}}}, "source": {{"kind": "random", "distribution": {{"kind": "smooth_noise", "period": {n}}}}}}}"#),
            2 => format!(r#"{{"control": {{"mode": "displacement"}}, "source": {{"kind": "field", "field": {{"cols": {n}, "rows": 3, "cell": {a}, "jitter_deg": {b}}}}}}}"#),
            3 => format!(r#"{{"control": {{"mode": "velocity"}}, "source": {{"kind": "markov", "markov": {{"edges_deg": [0, {a}, {b}], "table": [[{a}, 0.5], [0.5, {b}]]}}}}}}"#),
            4 => format!(r#"{{"control": {{"mode": "velocity"}}, "source": {{"kind": "path", "lookahead": {a}, "path": {{"kind": "circle", "center": [0, 0], "radius": {b}, "coefficients": [1, {a}], "samples": {n}}}}}}}"#),
            _ => format!(r#"{{"agent": {{"x": {a}, "speed": {b}}}, "control": {{"mode": "velocity"}}, "hold": {{"kind": "random", "min": {n}, "max": 3}}, "source": {{"kind": "time_function", "function": {{"dt": {a}, "terms": [{{"amplitude": {b}, "frequency": 1}}]}}}}}}"#),
        };
        if let Ok(mut w) = Wanderer::from_json(&json) {
            w.run(20);
            prop_assert!(w.pose().iter().all(|x| x.is_finite()));
        }
    }
}
