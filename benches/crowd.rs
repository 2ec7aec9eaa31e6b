//! Step cost of the crowd (paper 003) at 300, 3,000 and 30,000 boids.
//!
//! The pathway is scaled with the boid count (perimeter ∝ boids, same
//! radius), so crowd density — and the work separation does per boid — is
//! that of the paper's Test IV at every size: near-linear growth means a
//! flat cost per boid. Throughput is per boid, so criterion prints
//! boids/s; `ns per boid per step` = 1e9 / that. Run with
//! `cargo bench --bench crowd -- --warm-up-time 1 --measurement-time 2`.

use std::hint::black_box;

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use steering::boid_seek::Seek;
use steering::crowd::Crowd;
use steering::crowd_config::{CrowdConfig, PaperTest};

fn crowd(n: usize, metrics: bool) -> Crowd {
    let scale = n as f32 / 300.0;
    let mut cfg = CrowdConfig::paper(PaperTest::IV, Seek::Reynolds);
    cfg.boids = n;
    for p in &mut cfg.path.points {
        p[0] *= scale;
        p[1] *= scale;
    }
    let mut c = Crowd::new(&cfg).expect("valid preset");
    c.set_metrics_enabled(metrics);
    // Let the spawn settle into a moving crowd.
    c.run(100);
    c
}

fn bench(c: &mut Criterion) {
    for (group_name, metrics) in [("crowd_step", true), ("crowd_step_no_metrics", false)] {
        let mut g = c.benchmark_group(group_name);
        for n in [300usize, 3_000, 30_000] {
            let mut w = crowd(n, metrics);
            g.throughput(Throughput::Elements(n as u64));
            g.bench_function(BenchmarkId::from_parameter(n), |b| {
                b.iter(|| {
                    w.step();
                    black_box(w.positions()[0]);
                });
            });
        }
        g.finish();
    }
}

criterion_group!(benches, bench);
criterion_main!(benches);
