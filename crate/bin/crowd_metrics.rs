//! Metrics table for paper 003's Tests I–IV × five seek variants.
//!
//! `cargo run --release --bin crowd-metrics` loads every preset in
//! `scenarios/crowd/` (test1_reynolds.json … test4_parker0.1.json), runs
//! each with its warm-up and measurement window, and prints a markdown
//! table. `--write-presets` (re)writes those files from
//! `CrowdConfig::paper` instead. `--weight W` and `--max-force F`
//! override the separation weight and Reynolds' force limit of every preset
//! (sensitivity checks).

use std::path::PathBuf;
use std::time::Instant;

use steering::boid_seek::Seek;
use steering::crowd::Crowd;
use steering::crowd_config::{seek_tag, CrowdConfig, PaperTest};

fn fmt(v: Option<f32>, digits: usize) -> String {
    v.map_or_else(|| "–".to_owned(), |x| format!("{x:.digits$}"))
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("scenarios/crowd");
    let args: Vec<String> = std::env::args().skip(1).collect();
    let write = args.iter().any(|a| a == "--write-presets");
    let weight: Option<f32> = match args.iter().position(|a| a == "--weight") {
        Some(k) => Some(args.get(k + 1).ok_or("--weight needs a value")?.parse()?),
        None => None,
    };
    let max_force: Option<f32> = match args.iter().position(|a| a == "--max-force") {
        Some(k) => Some(
            args.get(k + 1)
                .ok_or("--max-force needs a value")?
                .parse()?,
        ),
        None => None,
    };
    if write {
        std::fs::create_dir_all(&dir)?;
    }
    println!("| Test | boids | sep | seek | laps | mean lap (steps) | mean dist | p95 dist | outside % | mean offset | overlaps/step | trace spread | steer | separation |");
    println!("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|");
    let t0 = Instant::now();
    for test in PaperTest::ALL {
        for seek in Seek::PAPER_VARIANTS {
            let file = dir.join(format!("test{}_{}.json", test.number(), seek_tag(&seek)));
            let mut cfg = if write {
                let c = CrowdConfig::paper(test, seek);
                std::fs::write(&file, c.to_json() + "\n")?;
                c
            } else {
                CrowdConfig::from_json(&std::fs::read_to_string(&file)?)?
            };
            if let Some(w) = weight {
                cfg.separation_weight = w;
            }
            if let Some(f) = max_force {
                cfg.max_force = f;
            }
            let mut crowd = Crowd::new(&cfg)?;
            let m = crowd.run_measured();
            println!(
                "| {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} |",
                test.number(),
                cfg.boids,
                if cfg.separation { "on" } else { "off" },
                cfg.seek.label(),
                m.laps,
                fmt(m.mean_lap_steps, 0),
                fmt(m.mean_distance, 1),
                fmt(m.p95_distance, 1),
                fmt(m.outside_share.map(|s| s * 100.0), 1),
                fmt(m.mean_offset, 1),
                fmt(m.overlapping_pairs_per_step, 1),
                fmt(m.trace_spread, 2),
                fmt(m.mean_steer, 3),
                fmt(m.mean_separation, 3),
            );
        }
    }
    eprintln!("ran 20 presets in {:.1} s", t0.elapsed().as_secs_f32());
    Ok(())
}
