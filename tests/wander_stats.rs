//! Statistical acceptance tests for the random steering toolkit (paper 004):
//! every distribution against its target (Kolmogorov–Smirnov or χ², fixed
//! seeds, thresholds at significance 0.001), the Markov chain's empirical
//! transition frequencies against its table, field interpolation
//! continuity, timed intervals, the bias formula and path following.
//! Run with `--nocapture` to see the statistics.

use glam::Vec2;
use steering::base::rng::Rng;
use steering::wander::distribution::{Curve, DistributionConfig, Sampler};
use steering::wander::field::{BiasNoise, FieldConfig, FieldSource, FieldValues, VectorField};
use steering::wander::markov::{Markov, MarkovConfig};
use steering::wander::noise;
use steering::wander::pipeline::Wanderer;
use steering::wander::time_fn::{Shape, SineTerm, TimeFn, TimeFnConfig, Weight};
use steering::wander::timed::{Hold, HoldConfig};

/// KS critical value at α = 0.001: 1.949 / √n (one sample).
fn ks_crit(n: usize) -> f64 {
    1.949 / (n as f64).sqrt()
}

/// One-sample KS statistic of `xs` against `cdf`.
fn ks(mut xs: Vec<f64>, cdf: impl Fn(f64) -> f64) -> f64 {
    xs.sort_by(f64::total_cmp);
    let n = xs.len() as f64;
    xs.iter()
        .enumerate()
        .map(|(i, &x)| {
            let f = cdf(x);
            (f - i as f64 / n).abs().max((f - (i + 1) as f64 / n).abs())
        })
        .fold(0.0, f64::max)
}

/// Two-sample KS statistic.
fn ks2(mut a: Vec<f64>, mut b: Vec<f64>) -> f64 {
    a.sort_by(f64::total_cmp);
    b.sort_by(f64::total_cmp);
    let (mut i, mut j, mut d) = (0, 0, 0.0f64);
    while i < a.len() && j < b.len() {
        let x = a[i].min(b[j]);
        while i < a.len() && a[i] <= x {
            i += 1;
        }
        while j < b.len() && b[j] <= x {
            j += 1;
        }
        d = d.max((i as f64 / a.len() as f64 - j as f64 / b.len() as f64).abs());
    }
    d
}

/// Pearson χ² of observed counts against expected probabilities.
fn chi2(observed: &[u64], probs: &[f64]) -> f64 {
    let n: u64 = observed.iter().sum();
    observed
        .iter()
        .zip(probs)
        .filter(|(_, &p)| p > 0.0)
        .map(|(&o, &p)| {
            let e = p * n as f64;
            (o as f64 - e).powi(2) / e
        })
        .sum()
}

/// χ² critical values at α = 0.001 by degrees of freedom.
fn chi2_crit(df: usize) -> f64 {
    match df {
        1 => 10.83,
        2 => 13.82,
        3 => 16.27,
        4 => 18.47,
        5 => 20.52,
        6 => 22.46,
        11 => 31.26,
        _ => panic!("no table entry for df {df}"),
    }
}

fn uniform_cdf(x: f64) -> f64 {
    ((x + 1.0) / 2.0).clamp(0.0, 1.0)
}

#[test]
fn uniform_distribution_ks() {
    let s = Sampler::new(&DistributionConfig::Uniform {}, &mut Rng::new(1)).unwrap();
    let mut rng = Rng::new(2);
    let n = 20_000;
    let xs: Vec<f64> = (0..n).map(|k| f64::from(s.sample(k, &mut rng))).collect();
    let d = ks(xs, uniform_cdf);
    println!(
        "uniform: KS D = {d:.4} (n = {n}, threshold {:.4})",
        ks_crit(n as usize)
    );
    assert!(d < ks_crit(n as usize));
}

#[test]
fn smooth_noise_knots_uniform_midpoints_triangular() {
    let period = 8;
    let s = Sampler::new(
        &DistributionConfig::SmoothNoise { period },
        &mut Rng::new(3),
    )
    .unwrap();
    let mut rng = Rng::new(0);
    let n = 10_000u32;
    // Knots are white noise: uniform.
    let knots: Vec<f64> = (0..n)
        .map(|k| f64::from(s.sample(k * period, &mut rng)))
        .collect();
    let d1 = ks(knots, uniform_cdf);
    // Midpoints of non-overlapping knot pairs are (a + b)/2: triangular.
    let mids: Vec<f64> = (0..n)
        .map(|k| f64::from(s.sample(2 * k * period + period / 2, &mut rng)))
        .collect();
    let tri = |x: f64| {
        if x < 0.0 {
            0.5 * (x + 1.0).powi(2)
        } else {
            1.0 - 0.5 * (1.0 - x).powi(2)
        }
        .clamp(0.0, 1.0)
    };
    let d2 = ks(mids, tri);
    let c = ks_crit(n as usize);
    println!("smooth noise: knots KS D = {d1:.4}, midpoints vs triangular D = {d2:.4} (n = {n}, threshold {c:.4})");
    assert!(d1 < c && d2 < c);
    // Between knots it is exactly the linear interpolation.
    let (a, b) = (s.sample(0, &mut rng), s.sample(period, &mut rng));
    let q = s.sample(period / 4, &mut rng);
    assert!((q - (a + 0.25 * (b - a))).abs() < 1e-6);
}

#[test]
fn perlin_matches_its_definition_and_is_symmetric() {
    // Reference: the defining formula with independent gradient slopes,
    // drawn from a different generator.
    let fade = |t: f64| t * t * t * (t * (t * 6.0 - 15.0) + 10.0);
    let mut r = Rng::new(77);
    let n = 10_000;
    let reference: Vec<f64> = (0..n)
        .map(|_| {
            let (g0, g1, f) = (
                f64::from(r.range(-1.0, 1.0)),
                f64::from(r.range(-1.0, 1.0)),
                f64::from(r.next_f32()),
            );
            2.0 * (g0 * f + fade(f) * (g1 * (f - 1.0) - g0 * f))
        })
        .collect();
    // Ours: one sample in every other lattice cell (no shared gradients).
    let mut r = Rng::new(78);
    let ours: Vec<f64> = (0..n)
        .map(|k| f64::from(noise::perlin1(12345, (2 * k) as f32 + r.next_f32())))
        .collect();
    let neg: Vec<f64> = ours.iter().map(|x| -x).collect();
    let c2 = 1.949 * (2.0 / n as f64).sqrt();
    let d = ks2(ours.clone(), reference);
    let ds = ks2(ours.clone(), neg);
    println!("perlin: two-sample KS vs definition D = {d:.4}, vs its mirror D = {ds:.4} (threshold {c2:.4})");
    assert!(d < c2 && ds < c2);
    assert!(ours.iter().all(|x| (-1.0..=1.0).contains(x)));
}

#[test]
fn hand_drawn_curve_inverse_cdf_ks() {
    let pts = [
        [-1.0, 0.0],
        [-0.6, 1.0],
        [-0.2, 0.1],
        [0.2, 0.1],
        [0.6, 1.0],
        [1.0, 0.0],
    ];
    let cfg = DistributionConfig::Curve {
        points: pts.to_vec(),
    };
    let s = Sampler::new(&cfg, &mut Rng::new(1)).unwrap();
    // Reference CDF by fine trapezoid integration of the density.
    let density = |x: f64| {
        for w in pts.windows(2) {
            let (x0, x1) = (f64::from(w[0][0]), f64::from(w[1][0]));
            if x >= x0 && x <= x1 {
                let t = (x - x0) / (x1 - x0);
                return f64::from(w[0][1]) * (1.0 - t) + f64::from(w[1][1]) * t;
            }
        }
        0.0
    };
    let m = 20_000;
    let mut cum = vec![0.0f64; m + 1];
    for k in 0..m {
        let (a, b) = (
            -1.0 + 2.0 * k as f64 / m as f64,
            -1.0 + 2.0 * (k + 1) as f64 / m as f64,
        );
        cum[k + 1] = cum[k] + 0.5 * (density(a) + density(b)) * (b - a);
    }
    let total = cum[m];
    let cdf = |x: f64| {
        let p = ((x + 1.0) / 2.0 * m as f64).clamp(0.0, m as f64);
        let k = (p.floor() as usize).min(m - 1);
        (cum[k] + (cum[k + 1] - cum[k]) * (p - k as f64)) / total
    };
    let mut rng = Rng::new(5);
    let n = 20_000;
    let xs: Vec<f64> = (0..n).map(|k| f64::from(s.sample(k, &mut rng))).collect();
    let d = ks(xs, cdf);
    println!(
        "curve: KS D = {d:.4} (n = {n}, threshold {:.4})",
        ks_crit(n as usize)
    );
    assert!(d < ks_crit(n as usize));
    // Endpoints and a zero-density gap are handled.
    let c = Curve::new(&[[-1.0, 1.0], [0.0, 0.0], [0.5, 0.0], [1.0, 1.0]]).unwrap();
    for k in 0..1000 {
        let x = c.inverse_cdf(k as f32 / 1000.0);
        assert!(!(0.0 + 1e-4..0.5 - 1e-4).contains(&x), "{x} in the gap");
    }
}

fn discrete_headings(step_deg: f32, seed: u64, perlin: bool, n: u32) -> Vec<f32> {
    let dist = if perlin {
        r#"{"kind": "perlin", "period": 40, "octaves": 2}"#
    } else {
        r#"{"kind": "uniform"}"#
    };
    let json = format!(
        r#"{{"seed": {seed}, "trace_capacity": {cap}, "control": {{"mode": "displacement",
        "quantize_deg": {step_deg}}}, "source": {{"kind": "random", "distribution": {dist}}}}}"#,
        cap = n + 1
    );
    let mut w = Wanderer::from_json(&json).unwrap();
    w.run(n);
    w.trace().chunks(3).skip(1).map(|p| p[2]).collect()
}

#[test]
fn discrete_angle_sets_are_uniform_chi_square() {
    for step in [90.0f32, 72.0, 60.0, 30.0] {
        let k = (360.0 / step).round() as usize;
        let n = 12_000;
        let hs = discrete_headings(step, 9, false, n);
        let mut counts = vec![0u64; k];
        for h in hs {
            let q = h.to_degrees() / step;
            assert!(
                (q - q.round()).abs() < 1e-3,
                "heading {h} not on the {step}° set"
            );
            counts[(q.round() as i64).rem_euclid(k as i64) as usize] += 1;
        }
        let x2 = chi2(&counts, &vec![1.0 / k as f64; k]);
        println!(
            "discrete {step}°: chi2 = {x2:.2} (df {}, threshold {})",
            k - 1,
            chi2_crit(k - 1)
        );
        assert!(x2 < chi2_crit(k - 1), "{step}°: {counts:?}");
    }
}

#[test]
fn discrete_perlin_holds_directions_longer() {
    let runs = |hs: &[f32]| {
        let changes = hs.windows(2).filter(|w| w[0] != w[1]).count().max(1);
        hs.len() as f64 / changes as f64
    };
    let white = runs(&discrete_headings(90.0, 4, false, 5000));
    let perlin = runs(&discrete_headings(90.0, 4, true, 5000));
    println!(
        "mean run of one direction: discrete uniform {white:.2} steps, discrete Perlin {perlin:.2}"
    );
    assert!(perlin > 5.0 * white);
}

fn paper_table() -> Vec<Vec<f32>> {
    vec![
        vec![0.9, 0.07, 0.03],
        vec![0.15, 0.8, 0.05],
        vec![0.1, 0.2, 0.7],
    ]
}

#[test]
fn markov_transition_frequencies_match_table() {
    let cfg = MarkovConfig {
        edges_deg: vec![0.0, 15.0, 30.0, 45.0],
        table: paper_table(),
        change_probability: None,
        initial_range: 0,
        response_curve: false,
    };
    let mut m = Markov::new(&cfg).unwrap();
    let mut rng = Rng::new(11);
    let mut counts = [[0u64; 3]; 3];
    for _ in 0..90_000 {
        let from = m.range();
        let v = m.sample(&mut rng).to_degrees();
        let to = m.range();
        let e = &cfg.edges_deg;
        assert!(
            v >= e[to] - 1e-3 && v <= e[to + 1] + 1e-3,
            "{v} outside range {to}"
        );
        counts[from][to] += 1;
    }
    for (i, row) in counts.iter().enumerate() {
        let probs: Vec<f64> = cfg.table[i].iter().map(|&p| f64::from(p)).collect();
        let x2 = chi2(row, &probs);
        let n: u64 = row.iter().sum();
        let freq: Vec<String> = row
            .iter()
            .map(|&c| format!("{:.3}", c as f64 / n as f64))
            .collect();
        println!(
            "markov row {i}: freq {freq:?} vs {:?}, chi2 = {x2:.2} (df 2, threshold 13.82)",
            cfg.table[i]
        );
        assert!(x2 < chi2_crit(2));
    }
}

#[test]
fn two_table_markov_changes_with_its_probability() {
    let change = vec![0.1f32, 0.2, 0.4];
    let cfg = MarkovConfig {
        edges_deg: vec![0.0, 15.0, 30.0, 45.0],
        table: paper_table(),
        change_probability: Some(change.clone()),
        initial_range: 1,
        response_curve: false,
    };
    let mut m = Markov::new(&cfg).unwrap();
    let mut rng = Rng::new(12);
    let mut tries = [0u64; 3];
    let mut changed = [0u64; 3];
    let mut prev = f32::NAN;
    for _ in 0..120_000 {
        let from = m.range();
        let v = m.sample(&mut rng);
        tries[from] += 1;
        if v != prev {
            changed[from] += 1;
        }
        prev = v;
    }
    for i in 0..3 {
        let p = f64::from(change[i]);
        let n = tries[i] as f64;
        let z = (changed[i] as f64 - n * p) / (n * p * (1.0 - p)).sqrt();
        println!(
            "two-table range {i}: change rate {:.4} vs {p}, z = {z:.2} (|z| < 3.29)",
            changed[i] as f64 / n
        );
        assert!(z.abs() < 3.29);
    }
}

#[test]
fn field_interpolation_is_continuous_and_exact_at_nodes() {
    let cell = 10.0f32;
    let f = VectorField::random(7, 5, cell, FieldValues::Uniform, &mut Rng::new(3));
    let mut rng = Rng::new(4);
    let h = 1e-2f32;
    let mut worst = 0.0f32;
    for _ in 0..200 {
        // Random lines that cross cells and the periodic seams.
        let mut p = Vec2::new(rng.range(-150.0, 150.0), rng.range(-150.0, 150.0));
        let a = rng.range(0.0, core::f32::consts::TAU);
        let d = Vec2::new(a.cos(), a.sin()) * h;
        let mut v = f.vector_at(p);
        for _ in 0..2000 {
            p += d;
            let w = f.vector_at(p);
            // Bilinear of unit vectors: |∇v| ≤ 2·√2 / cell.
            let jump = (w - v).length();
            worst = worst.max(jump / h);
            assert!(
                jump <= 2.0 * core::f32::consts::SQRT_2 * h / cell + 1e-5,
                "jump {jump} at {p}"
            );
            if v.length() > 0.2 && w.length() > 0.2 {
                let dang = steering::base::angle::diff(w.y.atan2(w.x), v.y.atan2(v.x)).abs();
                assert!(dang <= 3.0 * jump / 0.2 + 1e-4, "angle jump {dang} at {p}");
            }
            v = w;
        }
    }
    println!(
        "field: largest |Δv|/h = {worst:.4} (bound {:.4})",
        2.0 * core::f32::consts::SQRT_2 / cell
    );
    // Nodes carry unit vectors, also one period away.
    for (i, j) in [(0, 0), (3, 2), (6, 4)] {
        let n = f.vector_at(Vec2::new(i as f32 * cell, j as f32 * cell));
        let m = f.vector_at(Vec2::new((i + 7) as f32 * cell, (j - 5) as f32 * cell));
        assert!((n.length() - 1.0).abs() < 1e-5 && (n - m).length() < 1e-4);
    }
}

#[test]
fn field_bias_formula_halves_the_field_on_average() {
    // E[r1·f + (1 − r1)·r2] = f/2 for r1 ~ U[0,1), r2 ~ U[-1,1).
    let cfg = FieldConfig {
        cols: 4,
        rows: 4,
        cell: 10.0,
        values: FieldValues::Uniform,
        count: 1,
        switch_every: 0,
        jitter_deg: 0.0,
        bias: true,
        bias_r2: BiasNoise::Signed,
    };
    let src = FieldSource::new(&cfg, &mut Rng::new(8)).unwrap();
    let plain = FieldSource::new(
        &FieldConfig {
            bias: false,
            ..cfg.clone()
        },
        &mut Rng::new(8),
    )
    .unwrap();
    let p = Vec2::new(13.0, 27.0);
    let f = f64::from(plain.sample(0, p, &mut Rng::new(0)));
    let mut rng = Rng::new(9);
    let n = 40_000;
    let xs: Vec<f64> = (0..n)
        .map(|_| f64::from(src.sample(0, p, &mut rng)))
        .collect();
    let mean = xs.iter().sum::<f64>() / n as f64;
    let var = xs.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / n as f64;
    let z = (mean - f / 2.0) / (var / n as f64).sqrt();
    println!(
        "field bias: field u = {f:.4}, mean {mean:.4} vs f/2 = {:.4}, z = {z:.2} (|z| < 3.29)",
        f / 2.0
    );
    assert!(z.abs() < 3.29);
    assert!(xs.iter().all(|x| (-1.0..=1.0).contains(x)));
}

#[test]
fn field_switching_cycles_fields() {
    let cfg = FieldConfig {
        cols: 8,
        rows: 8,
        cell: 10.0,
        values: FieldValues::Perlin,
        count: 3,
        switch_every: 50,
        jitter_deg: 0.0,
        bias: false,
        bias_r2: BiasNoise::Signed,
    };
    let src = FieldSource::new(&cfg, &mut Rng::new(1)).unwrap();
    let p = Vec2::new(33.0, 41.0);
    let a: Vec<f32> = (0..3).map(|k| src.active(k * 50).angle_at(p)).collect();
    assert!(a[0] != a[1] && a[1] != a[2]);
    assert_eq!(src.active(150).angle_at(p), a[0]);
    assert_eq!(src.active(49).angle_at(p), a[0]);
}

#[test]
fn timed_intervals_fixed_and_uniform() {
    let mut h = Hold::new(&HoldConfig::Fixed { every: 7 }).unwrap();
    let mut rng = Rng::new(1);
    let due: Vec<u32> = (0..30).filter(|_| h.due(&mut rng)).collect();
    assert_eq!(due.len(), 5);
    let mut h = Hold::new(&HoldConfig::Random { min: 3, max: 9 }).unwrap();
    let mut counts = [0u64; 7];
    let mut last = 0u32;
    let mut first = true;
    for s in 0..200_000u32 {
        if h.due(&mut rng) {
            if !first {
                counts[(s - last - 3) as usize] += 1;
            }
            first = false;
            last = s;
        }
    }
    let x2 = chi2(&counts, &[1.0 / 7.0; 7]);
    println!("timed random intervals 3..=9: chi2 = {x2:.2} (df 6, threshold 22.46)");
    assert!(x2 < chi2_crit(6));
}

#[test]
fn time_function_is_the_sum_of_sines() {
    let cfg = TimeFnConfig {
        terms: vec![
            SineTerm {
                amplitude: 0.5,
                frequency: 1.0,
                phase: 0.0,
                weight: Weight::One,
                shape: Shape::Sine,
            },
            SineTerm {
                amplitude: 0.3,
                frequency: 10.0,
                phase: 0.2,
                weight: Weight::One,
                shape: Shape::Sine,
            },
            SineTerm {
                amplitude: 0.2,
                frequency: 50.0,
                phase: 0.0,
                weight: Weight::One,
                shape: Shape::Sine,
            },
        ],
        dt: 0.01,
        envelope: None,
        blend: None,
        horizon: 1000,
    };
    let f = TimeFn::new(&cfg, &mut Rng::new(1)).unwrap();
    for s in 0..5000u32 {
        let t = s as f32 * 0.01;
        let want = 0.5 * t.sin() + 0.3 * (10.0 * t + 0.2).sin() + 0.2 * (50.0 * t).sin();
        assert!((f.value(s) - want).abs() < 2e-5, "step {s}");
    }
}

#[test]
fn followers_stay_on_generated_paths() {
    let preset = steering::wander::pipeline::WanderPreset::from_json(include_str!(
        "../scenarios/wander/paths.json"
    ))
    .unwrap();
    for v in &preset.variants {
        let mut w = Wanderer::new(v.config.clone()).unwrap();
        w.run(preset.steps);
        let path: Vec<Vec2> = w
            .path_points()
            .chunks(2)
            .map(|p| Vec2::new(p[0], p[1]))
            .collect();
        let closed = v.label.starts_with("Circle");
        let segs = if closed { path.len() } else { path.len() - 1 };
        let dist = |p: Vec2| {
            (0..segs)
                .map(|k| {
                    let (a, b) = (path[k], path[(k + 1) % path.len()]);
                    let t = ((p - a).dot(b - a) / (b - a).length_squared()).clamp(0.0, 1.0);
                    p.distance(a + t * (b - a))
                })
                .fold(f32::INFINITY, f32::min)
        };
        let trace = w.trace();
        let ds: Vec<f32> = trace
            .chunks(3)
            .map(|p| dist(Vec2::new(p[0], p[1])))
            .collect();
        let worst = ds.iter().copied().fold(0.0, f32::max);
        let mean = ds.iter().sum::<f32>() / ds.len() as f32;
        // The tightest turn at constant speed has radius speed / max turn;
        // turning round at the end of an open path costs one diameter.
        let radius = v.config.agent.speed / v.config.control.max_velocity_deg.to_radians();
        println!(
            "path '{}': {} points, mean distance {mean:.2}, worst {worst:.2} (bound {:.2})",
            v.label,
            path.len(),
            2.0 * radius + 4.0
        );
        // Look-ahead cuts corners, by design: on average stay within a
        // third of it.
        let lookahead = match &v.config.source {
            steering::wander::config::SourceConfig::Path { lookahead, .. } => *lookahead,
            _ => unreachable!("paths.json holds path sources only"),
        };
        assert!(mean < lookahead / 3.0, "{}: mean {mean}", v.label);
        assert!(worst < 2.0 * radius + 4.0, "{}: {worst}", v.label);
        if !closed {
            // Open paths are followed back and forth.
            let (first, last) = (path[0], path[path.len() - 1]);
            let near = |p: &[f32], q: Vec2| Vec2::new(p[0], p[1]).distance(q) < 2.0 * lookahead;
            let at_end = trace
                .chunks(3)
                .position(|p| near(p, last))
                .expect("reaches the end");
            assert!(
                trace.chunks(3).skip(at_end).any(|p| near(p, first)),
                "{}: no return",
                v.label
            );
        }
    }
}

#[test]
fn mix_is_the_weighted_sum_of_its_parts() {
    // Two time functions mixed with weights 0.25 and 0.75 drive the agent
    // like one time function with those amplitudes.
    let tf = |a: f32, f: f32| {
        format!(
            r#"{{"kind": "time_function", "function": {{"terms": [{{"amplitude": {a}, "frequency": {f}}}]}}}}"#
        )
    };
    let control = r#"{"mode": "velocity", "max_velocity_deg": 20}"#;
    let mixed = format!(
        r#"{{"control": {control}, "source": {{"kind": "mix", "parts": [{{"weight": 0.25, "source": {}}}, {{"weight": 0.75, "source": {}}}]}}}}"#,
        tf(1.0, 3.0),
        tf(1.0, 17.0)
    );
    let single = format!(
        r#"{{"control": {control}, "source": {{"kind": "time_function", "function": {{"terms": [{{"amplitude": 0.25, "frequency": 3}}, {{"amplitude": 0.75, "frequency": 17}}]}}}}}}"#
    );
    let mut a = Wanderer::from_json(&mixed).unwrap();
    let mut b = Wanderer::from_json(&single).unwrap();
    for _ in 0..300 {
        a.step();
        b.step();
        assert!((a.command() - b.command()).abs() < 1e-5);
    }
}

#[test]
fn saw_and_square_waves() {
    use core::f32::consts::PI;
    for k in -40..40 {
        let x = k as f32 * 0.3 + 0.01;
        let s = Shape::Square.eval(x);
        assert_eq!(s, if x.sin() > 0.0 { 1.0 } else { -1.0 }, "square at {x}");
        let w = Shape::Saw.eval(x);
        let want = (x + PI).rem_euclid(2.0 * PI) / PI - 1.0;
        assert!((w - want).abs() < 1e-4, "saw at {x}: {w} vs {want}");
    }
}
