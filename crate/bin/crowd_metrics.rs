//! Metrics table for paper 003's Tests I–IV × five seek variants
//! (arguments: [`steering::cli::crowd_metrics`]; `crowd-metrics --help`).
//!
//! `cargo run --release --bin crowd-metrics` loads every preset in
//! `scenarios/crowd/` (test1_reynolds.json … test4_parker0.1.json), runs
//! each with its warm-up and measurement window, and prints a markdown
//! table. `--write-presets` (re)writes those files from
//! `CrowdConfig::paper` instead. `--set key=value` (repeatable,
//! value in JSON) overrides a config field of every preset, for sensitivity
//! checks, e.g. `--set max_force=0.3` or `--set separation_weight=1`.

// `wasm-pack test` builds every binary for wasm32, where clap is not a
// dependency: there this binary is empty.
#![cfg_attr(target_arch = "wasm32", no_main)]
#![cfg(not(target_arch = "wasm32"))]

use std::path::PathBuf;
use std::process::ExitCode;
use std::time::Instant;

use clap::Parser;
use steering::cli::crowd_metrics::CrowdMetricsCli;

use steering::crowd::boid_seek::Seek;
use steering::crowd::config::{seek_tag, CrowdConfig, PaperTest};
use steering::crowd::world::Crowd;

fn fmt(v: Option<f32>, digits: usize) -> String {
    v.map_or_else(|| "–".to_owned(), |x| format!("{x:.digits$}"))
}

fn main() -> ExitCode {
    match metrics(&CrowdMetricsCli::parse()) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("crowd-metrics: {e}");
            ExitCode::FAILURE
        }
    }
}

fn metrics(cli: &CrowdMetricsCli) -> Result<(), Box<dyn std::error::Error>> {
    let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("scenarios/crowd");
    let (write, overrides) = (cli.write_presets, &cli.overrides);
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
            if !overrides.is_empty() {
                let mut v = serde_json::to_value(&cfg)?;
                for (k, val) in overrides {
                    v[k.as_str()] = val.clone();
                }
                cfg = CrowdConfig::from_json(&v.to_string())?;
            }
            cfg.check_batch()?;
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
