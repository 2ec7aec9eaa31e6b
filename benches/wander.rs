//! ns per step of each random steering component (paper 004), relative to
//! a baseline measured in the same run: plain uniform displacement.
//!
//! `cargo bench --bench wander -- --warm-up-time 1 --measurement-time 2`
//! Every case is one `Wanderer::step` (source → hold → quantize → control
//! → agent → trace ring), built from the shipped presets.

use std::hint::black_box;

use criterion::{criterion_group, criterion_main, Criterion};
use steering::wander::{pipeline::WanderPreset, pipeline::Wanderer};

const CASES: [(&str, &str, usize); 20] = [
    (
        "baseline: uniform displacement",
        include_str!("../scenarios/wander/control.json"),
        0,
    ),
    (
        "§1 velocity (uniform)",
        include_str!("../scenarios/wander/control.json"),
        4,
    ),
    (
        "§1 acceleration (uniform)",
        include_str!("../scenarios/wander/control.json"),
        10,
    ),
    (
        "§2 smooth noise",
        include_str!("../scenarios/wander/distributions.json"),
        0,
    ),
    (
        "§2 perlin (2 octaves)",
        include_str!("../scenarios/wander/distributions.json"),
        1,
    ),
    (
        "§2 curve (inverse CDF)",
        include_str!("../scenarios/wander/distributions.json"),
        3,
    ),
    (
        "§2 discrete set 90°",
        include_str!("../scenarios/wander/distributions.json"),
        5,
    ),
    (
        "§2 discrete perlin 90°",
        include_str!("../scenarios/wander/distributions.json"),
        9,
    ),
    (
        "§3 field → displacement",
        include_str!("../scenarios/wander/fields.json"),
        0,
    ),
    (
        "§3 field switching (3)",
        include_str!("../scenarios/wander/fields.json"),
        5,
    ),
    (
        "§3 field bias",
        include_str!("../scenarios/wander/fields.json"),
        6,
    ),
    (
        "§4 sum of 3 sines",
        include_str!("../scenarios/wander/time-functions.json"),
        3,
    ),
    (
        "§4 perlin blend",
        include_str!("../scenarios/wander/time-functions.json"),
        6,
    ),
    (
        "§5 timed (random hold)",
        include_str!("../scenarios/wander/timed.json"),
        1,
    ),
    (
        "§6 markov table",
        include_str!("../scenarios/wander/markov.json"),
        0,
    ),
    (
        "§6 two-table markov",
        include_str!("../scenarios/wander/markov.json"),
        1,
    ),
    (
        "§7 fractal path follow",
        include_str!("../scenarios/wander/paths.json"),
        0,
    ),
    (
        "§7 circle-sines path follow",
        include_str!("../scenarios/wander/paths.json"),
        2,
    ),
    (
        "§7 random circle path follow",
        include_str!("../scenarios/wander/paths.json"),
        3,
    ),
    (
        "mix: sines + uniform",
        include_str!("../scenarios/wander/composed.json"),
        0,
    ),
];

fn wander(c: &mut Criterion) {
    let mut g = c.benchmark_group("wander_step");
    for (name, json, index) in CASES {
        let preset = WanderPreset::from_json(json).expect("preset");
        let config = preset.variants[index].config.clone();
        g.bench_function(name, |b| {
            let mut w = Wanderer::new(config.clone()).expect("builds");
            b.iter(|| {
                w.step();
                black_box(w.pose())
            });
        });
    }
    g.finish();
}

criterion_group!(benches, wander);
criterion_main!(benches);
