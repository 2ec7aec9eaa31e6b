//! Step cost of the crowd (paper 003) at 300, 3,000, 30,000 and 100,000 boids.
//!
//! The pathway is scaled with the boid count (perimeter ∝ boids, same
//! radius), so crowd density — and the work separation does per boid — is
//! that of the paper's Test IV at every size: near-linear growth means a
//! flat cost per boid. Throughput is per boid, so criterion prints
//! boids/s; ns per boid per step = 1e9 / that.
//!
//! Groups:
//! * `crowd_step` — wall-clock time, metrics on (the live default);
//! * `crowd_step_cpu` — the same step timed with this thread's CPU clock
//!   (Linux `CLOCK_THREAD_CPUTIME_ID`), so time spent preempted on a busy
//!   shared machine is not counted; falls back to wall time elsewhere;
//! * `crowd_step_cpu_no_metrics` — CPU time with metrics off;
//! * `crowd_overlaps_no_sep` — the overlap metric where it costs most:
//!   30,000 boids of Test IV's pathway run without separation (twice as
//!   dense), counted from both sides of each pair (`both_sides`) and from
//!   one side (`one_sided`, the step's), same positions.
//!
//! Run with `cargo bench --bench crowd -- --warm-up-time 1 --measurement-time 2`.

use std::hint::black_box;
use std::time::{Duration, Instant};

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use steering::base::grid::NeighbourGrid;
use steering::crowd::boid_seek::Seek;
use steering::crowd::config::{CrowdConfig, PaperTest};
use steering::crowd::separation::{count_overlaps, count_overlaps_both_sides};
use steering::crowd::world::Crowd;

#[path = "cpu_clock.rs"]
mod cpu_clock;

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

/// Runs `iters` steps and returns their CPU time (wall time if no CPU clock).
fn cpu_timed(w: &mut Crowd, iters: u64) -> Duration {
    let (t0, w0) = (cpu_clock::thread_ns(), Instant::now());
    for _ in 0..iters {
        w.step();
        black_box(w.positions()[0]);
    }
    match (t0, cpu_clock::thread_ns()) {
        (Some(a), Some(b)) => Duration::from_nanos((b - a) as u64),
        _ => w0.elapsed(),
    }
}

fn bench(c: &mut Criterion) {
    for (group_name, metrics, cpu) in [
        ("crowd_step", true, false),
        ("crowd_step_cpu", true, true),
        ("crowd_step_cpu_no_metrics", false, true),
    ] {
        let mut g = c.benchmark_group(group_name);
        for n in [300usize, 3_000, 30_000, 100_000] {
            let mut w = crowd(n, metrics);
            g.throughput(Throughput::Elements(n as u64));
            g.bench_function(BenchmarkId::from_parameter(n), |b| {
                if cpu {
                    b.iter_custom(|iters| cpu_timed(&mut w, iters));
                } else {
                    b.iter(|| {
                        w.step();
                        black_box(w.positions()[0]);
                    });
                }
            });
        }
        g.finish();
    }
    let mut cfg = CrowdConfig::paper(PaperTest::IV, Seek::Parker { fraction: 0.1 });
    cfg.boids = 30_000;
    cfg.separation = false;
    let mut w = Crowd::new(&cfg).expect("valid preset");
    w.run(20);
    let pos = w.positions().to_vec();
    let mut grid = NeighbourGrid::new();
    let mut g = c.benchmark_group("crowd_overlaps_no_sep");
    g.throughput(Throughput::Elements(cfg.boids as u64));
    g.bench_function("both_sides", |b| {
        b.iter(|| black_box(count_overlaps_both_sides(&mut grid, &pos, cfg.boid_radius)));
    });
    g.bench_function("one_sided", |b| {
        b.iter(|| black_box(count_overlaps(&mut grid, &pos, cfg.boid_radius)));
    });
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
