//! Fidelity of paper 004 (random steering) beyond the gallery presets of
//! `tests/fidelity.rs`: readings of the text that change a figure, each
//! measured both ways. Each test asserts its claim, or its refutation
//! with the numbers, and writes one row of the fidelity table
//! (`common::figures`).

mod common;

use common::figures::{record_claim, Claim, Figure, Seeds, Verdict};
use glam::Vec2;
use steering::base::rng::Rng;
use steering::wander::field::{BiasNoise, FieldConfig, FieldSource, FieldValues};

const BIAS: &str = "p004_sec3_a_field_biases_random_angles";

/// `(mean of u − field/2, correlation of u with the field)` over `n`
/// positions drawn uniformly over the field, one biased draw `u` each.
fn bias_stats(r2: BiasNoise, n: usize) -> (f64, f64) {
    let cfg = FieldConfig {
        cols: 32,
        rows: 32,
        cell: 40.0,
        values: FieldValues::Uniform,
        count: 1,
        switch_every: 0,
        jitter_deg: 0.0,
        bias: true,
        bias_r2: r2,
    };
    // The same field twice (same seed): one biased, one read plainly.
    let biased = FieldSource::new(&cfg, &mut Rng::new(4)).unwrap();
    let plain = FieldSource::new(
        &FieldConfig {
            bias: false,
            ..cfg.clone()
        },
        &mut Rng::new(4),
    )
    .unwrap();
    let (mut where_, mut draw) = (Rng::new(5), Rng::new(6));
    let side = 32.0 * 40.0;
    let pairs: Vec<(f64, f64)> = (0..n)
        .map(|_| {
            let p = Vec2::new(where_.range(0.0, side), where_.range(0.0, side));
            let f = f64::from(plain.sample(0, p, &mut draw));
            (f, f64::from(biased.sample(0, p, &mut draw)))
        })
        .collect();
    let k = n as f64;
    let shift = pairs.iter().map(|(f, u)| u - f / 2.0).sum::<f64>() / k;
    let (mf, mu) = (
        pairs.iter().map(|p| p.0).sum::<f64>() / k,
        pairs.iter().map(|p| p.1).sum::<f64>() / k,
    );
    let cov = pairs.iter().map(|(f, u)| (f - mf) * (u - mu)).sum::<f64>();
    let vf = pairs.iter().map(|(f, _)| (f - mf).powi(2)).sum::<f64>();
    let vu = pairs.iter().map(|(_, u)| (u - mu).powi(2)).sum::<f64>();
    (shift, cov / (vf * vu).sqrt())
}

#[test]
fn p004_sec3_a_field_biases_random_angles() {
    // "Vector fields can also be used to bias random numbers. [...] Thus
    // the field will only 'influence' the behavior of an agent, and not
    // control it directly. [...] displacement = r_1 * vec(x, y) + (1 – r_1)
    // * r_2 [...] r_1 and r_2 are two random numbers", where "a random
    // number" is uniform on [0, 1). Commands are normalised angles (±1 =
    // ±180°). Our reading draws r₂ on [−1, 1) (`bias_r2: signed`, the
    // default); the literal one on [0, 1) (`bias_r2: unit`). With r₁ on
    // [0, 1), the mean command is field/2 + E[r₂]/2: unbiased for ours, a
    // quarter turn-unit (45° of displacement at ±180°) to the left for the
    // literal reading.
    let n = 40_000;
    let (ours, literal) = (
        bias_stats(BiasNoise::Signed, n),
        bias_stats(BiasNoise::Unit, n),
    );
    for (name, (shift, corr)) in [
        ("ours, r₂ in [−1, 1)", ours),
        ("literal, r₂ in [0, 1)", literal),
    ] {
        println!("004 §3 field bias, {name}: mean command − field/2 {:+.1}° (at ±180° displacement), correlation with the field {corr:.2}", 180.0 * shift);
    }
    record_claim(
        &format!("tests/fidelity_wander.rs::{BIAS}"),
        &format!("cargo test --release --features cli --test fidelity_wander {BIAS}"),
        &Seeds { tuning: vec![], report: vec![4, 5, 6] },
        &Claim {
            paper: "004".into(),
            place: "§3".into(),
            claim: "a field used as a bias, r₁·field + (1 − r₁)·r₂, only influences the angle and does not control it".into(),
            reading: "ours".into(),
            verdict: Verdict::Reproduced,
        },
        &[
            Figure::new("p004.sec3.bias.ours.shift", "r₂ on [−1, 1) (ours): mean command minus half the field angle, as displacement at ±180° (40,000 draws over a uniform field)", 180.0 * ours.0, "°", 1),
            Figure::new("p004.sec3.bias.ours.correlation", "r₂ on [−1, 1): correlation of the command with the field angle", ours.1, "", 2),
            Figure::new("p004.sec3.bias.literal.shift", "r₂ on [0, 1) (the text's \"random number\"): mean command minus half the field angle", 180.0 * literal.0, "°", 1),
            Figure::new("p004.sec3.bias.literal.correlation", "r₂ on [0, 1): correlation of the command with the field angle", literal.1, "", 2),
        ],
    );
    // Both readings influence without controlling: the command follows the
    // field in part (a control would correlate 1, noise 0)…
    for (shift, corr) in [ours, literal] {
        assert!(corr > 0.4 && corr < 0.9, "{shift} {corr}");
    }
    // …ours around the field's half, the literal one turned left by a
    // quarter of the range (45° at ±180°), whatever the field.
    assert!(ours.0.abs() < 0.01, "{ours:?}");
    assert!((literal.0 - 0.25).abs() < 0.01, "{literal:?}");
}

#[test]
fn the_literal_bias_range_is_selected_in_json_and_the_default_writes_as_before() {
    let json = |r2: &str| format!(r#"{{"cols": 4, "rows": 4, "cell": 10, "bias": true{r2}}}"#);
    let default: FieldConfig = serde_json::from_str(&json("")).unwrap();
    let literal: FieldConfig = serde_json::from_str(&json(r#", "bias_r2": "unit""#)).unwrap();
    assert_eq!(default.bias_r2, BiasNoise::Signed);
    assert_eq!(literal.bias_r2, BiasNoise::Unit);
    // A configuration written before the field existed writes unchanged.
    assert!(!serde_json::to_string(&default).unwrap().contains("bias_r2"));
    assert!(serde_json::to_string(&literal)
        .unwrap()
        .contains(r#""bias_r2":"unit""#));
    assert!(serde_json::from_str::<FieldConfig>(&json(r#", "bias_r2": "half""#)).is_err());
}
