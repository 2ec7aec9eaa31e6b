//! Times the crowd's step natively (and its separation and grid rebuild alone).
//!
//! N boids of Test IV's pathway scaled with N
//! (its density), Parker 10 %, metrics off (the workers' mode), STEPS steps
//! after 100 settling ones; then separation alone and its grid rebuild
//! alone on the last positions (`--only-rebuild` or `ONLY_REBUILD=1`: 500
//! rebuilds, for `perf record`; `--only-step` or `ONLY_STEP=1`: the steps
//! alone). `cargo run --release --example crowd_profile -- N STEPS`.

// clap is a native dev-dependency: under `wasm-pack test` (wasm32) this
// diagnostic is empty.
#![cfg_attr(target_arch = "wasm32", no_main)]
#![cfg(not(target_arch = "wasm32"))]
use clap::builder::FalseyValueParser;
use clap::Parser;
use steering::crowd::boid_seek::Seek;
use steering::crowd::config::{CrowdConfig, PaperTest};
use steering::crowd::world::Crowd;

/// Crowd step cost natively, Test IV's pathway scaled with N.
#[derive(Parser)]
struct Args {
    /// Boids.
    #[arg(default_value_t = 100_000)]
    n: usize,
    /// Timed steps.
    #[arg(default_value_t = 100)]
    steps: u32,
    /// Settling steps before timing.
    #[arg(long, env = "SETTLE", default_value_t = 100)]
    settle: u32,
    /// Time the steps alone.
    #[arg(long, env = "ONLY_STEP", value_parser = FalseyValueParser::new())]
    only_step: bool,
    /// Also time the rebuild of the positions sorted by bucket.
    #[arg(long, env = "SORTED", value_parser = FalseyValueParser::new())]
    sorted: bool,
    /// Time the grid rebuild alone, `--rebuilds` times.
    #[arg(long, env = "ONLY_REBUILD", value_parser = FalseyValueParser::new())]
    only_rebuild: bool,
    /// Rebuilds with `--only-rebuild`.
    #[arg(long, env = "REBUILDS", default_value_t = 500)]
    rebuilds: u32,
}

fn main() {
    let args = Args::parse();
    let (n, steps) = (args.n, args.steps);
    let scale = n as f32 / 300.0;
    let mut cfg = CrowdConfig::paper(PaperTest::IV, Seek::Parker { fraction: 0.1 });
    cfg.boids = n;
    for p in &mut cfg.path.points {
        p[0] *= scale;
        p[1] *= scale;
    }
    let mut c = Crowd::new(&cfg).unwrap();
    c.set_metrics_enabled(false);
    c.run(args.settle);
    let t = std::time::Instant::now();
    c.run(steps);
    let dt = t.elapsed().as_secs_f64() / f64::from(steps);
    let h = c.positions().iter().fold(0u64, |h, v| {
        h.wrapping_mul(31).wrapping_add(u64::from(v.to_bits()))
    });
    if args.only_step {
        println!("{n} boids: {:.2} ms per step", dt * 1e3);
        return;
    }
    let mut grid = steering::base::grid::NeighbourGrid::new();
    let mut out = vec![0.0f32; 2 * n];
    let pos = c.positions().to_vec();
    let t = std::time::Instant::now();
    for _ in 0..steps {
        steering::crowd::separation::separate(
            &mut grid,
            &pos,
            cfg.boid_radius,
            cfg.separation_weight,
            &mut out,
        );
    }
    let ds = t.elapsed().as_secs_f64() / f64::from(steps);
    if args.sorted {
        grid.rebuild(&pos, 2.0 * cfg.boid_radius);
        let sorted: Vec<f32> = (0..n)
            .flat_map(|k| {
                let i = grid.boid_in_bucket_order(k);
                [pos[2 * i], pos[2 * i + 1]]
            })
            .collect();
        let t = std::time::Instant::now();
        for _ in 0..500 {
            grid.rebuild(&sorted, 2.0 * cfg.boid_radius);
        }
        println!(
            "rebuild of spatially sorted {:.3} ms",
            t.elapsed().as_secs_f64() * 2.0
        );
    }
    if args.only_rebuild {
        let t = std::time::Instant::now();
        let reps = args.rebuilds;
        for _ in 0..reps {
            grid.rebuild(&pos, 2.0 * cfg.boid_radius);
        }
        println!(
            "rebuild {:.3} ms",
            t.elapsed().as_secs_f64() * 1e3 / f64::from(reps)
        );
        return;
    }
    let t = std::time::Instant::now();
    for _ in 0..steps {
        grid.rebuild(&pos, 2.0 * cfg.boid_radius);
    }
    let dr = t.elapsed().as_secs_f64() / f64::from(steps);
    println!(
        "separate {:.2} ms (rebuild {:.2} ms), {:.1} candidates per boid",
        ds * 1e3,
        dr * 1e3,
        grid.checks() as f64 / (f64::from(steps) * n as f64)
    );
    println!(
        "{n} boids: {:.2} ms per step, {:.1} ns per boid; hash {h:016x}",
        dt * 1e3,
        dt * 1e9 / n as f64
    );
}
