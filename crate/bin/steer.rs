//! `steer`: the command-line runner (arguments: [`steering::cli::steer`];
//! `steer --help`, `steer run --help`, …).
//!
//! ```text
//! steer run SCENARIO.json --out TRAJ.csv|TRAJ.json|TRAJ.jsonl [--every N] [--table FILE] [--controller standard|relaxed|seek] [--reading paper|ours]
//! steer reach [--n N] [--seed S] [--table FILE] [--threads N]
//! steer relaxed [--n N] [--seed S] [--table FILE] [--scenarios DIR] [--reading paper|ours] [--aim entry|paper-arc] [--disk-margin F] [--orientation-margin F] [--threads N]
//! steer envelope [--n N] [--seed S] [--json FILE] [--table FILE] [--standard JSON] [--only NAMES] [--brief] [--vehicle VEHICLE.json] [--queries N]
//! steer avoid [--seeds N] [--seed S] [--only NAMES] [--replan-every N] [--write-presets DIR] [--table FILE] [--threads N]
//! steer report [--check] [--prune] [--records DIR] [--full-records DIR] [--store DIR] [--out FILE]
//! ```
//! `run` simulates a scenario file (schema: `crate/world/scenario.rs`)
//! and streams the per-step pose, speeds and mode of every agent plus its
//! metrics; `--controller` overrides the scenario's controller, `--reading
//! paper` its settings with the papers' algorithms as written. Its η table
//! is `--table` or the scenario's `table` (built for its vehicle, else an
//! error), else `tables/eta.bin` if it matches the vehicle, else the
//! matching table from the cache (`steering::cli::table_cache`), built
//! there if missing. `envelope --vehicle FILE` scales the
//! envelope study to a vehicle and prints its per-vehicle measures.
//! `reach` runs the seeded random reach study for every μ-bound variant and
//! prints reach, orientation on entry, errors, length against Dubins and
//! limit violations for each.
//! `relaxed` runs every `scenarios/p001_*_standard.json` preset with both
//! controllers, then the seeded random region-goal study, and prints the
//! comparison of paper 001 (path length, integrated |curvature|, reach),
//! like for like: both controllers of `--reading` (ours, or the papers').
//! Studies run on rayon; their output does not depend on `--threads`.
//! `reach`, `relaxed`, `envelope` and `avoid` take `--record`: their
//! summary also goes into a figures record (`steering::cli::records`),
//! from which `report` builds `docs/FIGURES.md`.

// `wasm-pack test` builds every binary for wasm32, where clap and rayon
// are not dependencies: there this binary is empty.
#![cfg_attr(target_arch = "wasm32", no_main)]
#![cfg(not(target_arch = "wasm32"))]

use std::path::Path;
use std::process::ExitCode;
use std::time::Instant;

use clap::Parser;
use steering::base::metrics::PathMetrics;
use steering::cli::steer::{
    AvoidArgs, Command, EnvelopeArgs, ReachArgs, RelaxedArgs, RunArgs, SteerCli,
};
use steering::cli::study_records;
use steering::cli::trajectory::{check_out_path, create_out, stream_run};
use steering::funnelling::config::{FunnelConfig, MuBound};
use steering::funnelling::controller::{Controller, ControllerKind, Reading};
use steering::funnelling::table::lookup::EtaTable;
use steering::studies::reach::{summarise, ReachStudy};
use steering::studies::region::{compare, Comparison, RegionStudy};
use steering::world::scenario::Scenario;

fn load_table(path: &Path) -> Result<EtaTable, String> {
    let shown = path.display();
    let bytes = std::fs::read(path).map_err(|e| {
        let hint = if e.kind() == std::io::ErrorKind::NotFound {
            " (the default is relative to the repository root: run from there, or pass --table PATH/TO/tables/eta.bin)"
        } else {
            ""
        };
        format!("cannot read η table {shown}: {e}{hint}")
    })?;
    EtaTable::from_bytes(&bytes).map_err(|e| format!("{shown}: {e}"))
}

/// The table `steer run` runs with: `--table` or the
/// scenario's `table` must match the vehicle (a mismatch is an error);
/// otherwise the committed table if it matches, else the cache's
/// (`steering::cli::table_cache`), built if missing. Never a table built
/// for other limits.
fn run_table(args: &RunArgs, sc: &Scenario) -> Result<EtaTable, String> {
    let named = args.table.clone().or_else(|| {
        sc.table.as_ref().map(|t| {
            let base = args.scenario.parent().unwrap_or(Path::new(""));
            base.join(t)
        })
    });
    if let Some(path) = named {
        let table = load_table(&path)?;
        table
            .check_params(&sc.vehicle)
            .map_err(|e| format!("{}: {e} (eta-table --vehicle builds one)", path.display()))?;
        return Ok(table);
    }
    let committed = Path::new("tables/eta.bin");
    if let Ok(t) = load_table(committed) {
        if t.check_params(&sc.vehicle).is_ok() {
            return Ok(t);
        }
    }
    let dir = steering::cli::table_cache::cache_dir();
    let t0 = Instant::now();
    let (table, source) = steering::cli::table_cache::table_for(&sc.vehicle, &dir)
        .map_err(|e| format!("{}: {e}", args.scenario.display()))?;
    match source {
        steering::cli::table_cache::Source::Cached(p) => {
            eprintln!(
                "steer: η table for this vehicle from the cache {}",
                p.display()
            );
        }
        steering::cli::table_cache::Source::Built(p) => eprintln!(
            "steer: built the η table for this vehicle in {:.1} s -> {}",
            t0.elapsed().as_secs_f32(),
            p.display()
        ),
    }
    Ok(table)
}

/// `steer run`: checks everything (output path included) before the first
/// step, then streams the trajectory (`steering::cli::trajectory`).
fn run(args: &RunArgs) -> Result<(), String> {
    let scenario = args.scenario.display();
    let format = check_out_path(&args.out, &args.scenario)?;
    let bytes =
        std::fs::read(&args.scenario).map_err(|e| format!("cannot read {scenario}: {e}"))?;
    let mut sc = Scenario::from_bytes(&bytes).map_err(|e| format!("{scenario}: {e}"))?;
    if let Some(c) = args.controller {
        sc.controller = c;
    }
    if let Some(r) = args.reading {
        sc.set_reading(r);
    }
    let table = run_table(args, &sc)?;
    sc.world().map_err(|e| format!("{scenario}: {e}"))?;
    let mut out = create_out(&args.out)?;
    let t0 = Instant::now();
    let mut shown = t0;
    let steps = sc.steps();
    let mut progress = |k: u32| {
        if k % 64 == 0 && shown.elapsed().as_secs_f32() >= 10.0 {
            shown = Instant::now();
            eprintln!(
                "steer: step {k} / {steps} ({:.1} %), {:.0} s",
                100.0 * f64::from(k) / f64::from(steps.max(1)),
                t0.elapsed().as_secs_f32()
            );
        }
    };
    let s = stream_run(&sc, &table, args.every, format, &mut out, &mut progress)
        .map_err(|e| format!("{scenario}: {e}"))?;
    out.commit()?;
    println!(
        "steer: {} ({}) — {} agents, {} steps, {} finished all goals, {} limit violations -> {}",
        sc.name,
        sc.controller_label(),
        s.agents,
        s.steps,
        s.finished,
        s.violations,
        args.out.display()
    );
    Ok(())
}

/// `steer envelope`: the envelope study (`steering::studies::envelope`).
fn envelope(args: &EnvelopeArgs) -> Result<(), String> {
    use steering::studies::envelope::EnvelopeStudy;
    let p = match &args.vehicle {
        None => steering::base::vehicle::VehicleParams::default(),
        Some(path) => {
            let text = std::fs::read_to_string(path)
                .map_err(|e| format!("cannot read {}: {e}", path.display()))?;
            steering::funnelling::vehicle_file::parse(&text)
                .map_err(|e| format!("{}: {e}", path.display()))?
                .vehicle
        }
    };
    let mut study = EnvelopeStudy {
        seed: args.seed,
        ..EnvelopeStudy::for_vehicle(&p)
    };
    (study.n_static, study.n_moving, study.n_chain) = (args.n, args.n / 5, args.n / 5);
    let table = match (load_table(&args.table), &args.vehicle) {
        (Ok(t), _) if t.check_params(&p).is_ok() => t,
        (_, Some(_)) => {
            let dir = steering::cli::table_cache::cache_dir();
            let (t, src) = steering::cli::table_cache::table_for(&p, &dir)?;
            eprintln!("steer: η table for this vehicle: {src:?}");
            t
        }
        (Ok(t), None) => {
            t.check_params(&p).map_err(|e| e.to_string())?;
            t
        }
        (Err(e), None) => return Err(e),
    };
    let mut vs = args.variants()?;
    if let Some(cfg) = args.standard_config()? {
        for v in &mut vs {
            match &mut v.controller {
                steering::funnelling::controller::Controller::Standard(f)
                    if v.name == "standard" =>
                {
                    *f = cfg
                }
                steering::funnelling::controller::Controller::Relaxed(f, _)
                    if v.name == "relaxed" =>
                {
                    *f = cfg
                }
                _ => {}
            }
        }
    }
    let report = study.run_all(&table, &p, &vs);
    if args.vehicle.is_some() {
        use steering::studies::vehicle::{accuracy, oriented_far};
        let r = steering::funnelling::table::spec::turn_radius(&p);
        let acc = accuracy(&table, &p, args.queries as usize, args.seed, 4.0);
        println!(
            "vehicle: vMax {} m/s, turning radius R = {r:.3} m (× {:.4} the pedestrian's), speeds × {:.4}; table key {}",
            p.v_max,
            study.scale.length,
            study.scale.speed,
            table.key()
        );
        println!(
            "η accuracy at D ≥ 4 R, {} off-grid queries (seed {}): {} both reachable, median {:.3}°, p95 {:.3}°, reachability agreement {:.2} %",
            acc.queries,
            args.seed,
            acc.both_reachable,
            acc.median_deg,
            acc.p95_deg,
            100.0 * acc.agreement
        );
        for v in &report.variants {
            let a = oriented_far(v);
            println!(
                "{}: reach {:.2} % of {} static runs; oriented on entry at D ≥ 5 R, ε_tol 5°: {:.1} % of {}",
                v.name,
                100.0 * a.reach,
                a.runs,
                100.0 * a.far_oriented,
                a.far_runs
            );
        }
        println!("(tables below: distances and D_tol in pedestrian-equivalent m = × {:.4} for this vehicle, speeds × {:.4})\n", study.scale.length, study.scale.speed);
    }
    if p.car_like() {
        // Its own envelope too, scaled to R_min (distance bands in turning
        // radii down to 0.15 R_min).
        use steering::studies::car_like;
        let runs = car_like::run_all(
            &table,
            &p,
            steering::funnelling::controller::ControllerKind::Standard,
            args.seed,
            args.n,
        );
        println!(
            "car-like, minTurnRadius R_min = {} m: {} runs scaled to R_min (seed {}), standard controller\n{}",
            p.r_min,
            args.n,
            args.seed,
            car_like::text(&p, &runs)
        );
    }
    let detail: &[&str] = if args.brief {
        &[]
    } else {
        &["standard", "standard-literal", "relaxed"]
    };
    print!("{}", report.tables(detail));
    println!(
        "\nenvelope targets (seed {}):\n{}",
        args.seed,
        report.targets()
    );
    if let Some(path) = &args.json {
        let body = serde_json::to_string_pretty(&report.to_json()).map_err(|e| e.to_string())?;
        std::fs::write(path, body).map_err(|e| format!("cannot write {}: {e}", path.display()))?;
    }
    let prefix = match &args.vehicle {
        None => "envelope".to_string(),
        Some(v) => format!(
            "envelope-{}",
            study_records::id_segment(&v.file_stem().unwrap_or_default().to_string_lossy())
        ),
    };
    args.record.write(
        study_records::funnel_seeds(args.seed),
        study_records::envelope(&prefix, &report),
    )
}

fn reach(args: &ReachArgs) -> Result<(), String> {
    let study = ReachStudy {
        n: args.n,
        seed: args.seed,
        ..ReachStudy::default()
    };
    let table_path = &args.table;
    let table = load_table(table_path)?;
    let p = steering::base::vehicle::VehicleParams::default();
    table.check_params(&p).map_err(|e| e.to_string())?;
    println!(
        "reach study: {} scenarios, seed {}, D in [{}, {}] m, D_tol {} m, eps_tol {:.0} deg, v_d {} m/s, limit {} s",
        study.n,
        study.seed,
        study.d_range.0,
        study.d_range.1,
        study.d_tol,
        study.eps_tol.to_degrees(),
        study.speed,
        study.max_time
    );
    println!("| μ bound | gain | seek threshold | reach | oriented on entry | entry err median / p95 (°) | final err median / p95 (°) | length/Dubins median / p90 | violations |");
    println!("|---|---|---|---|---|---|---|---|---|");
    // The paper's reading (gain 1, threshold 1) of each bound, then each
    // with the default gain and threshold.
    let variants = [
        (MuBound::Literal, 1.0, 1.0),
        (MuBound::ScaledLiteral { gain: 6.0 }, 1.0, 1.0),
        (MuBound::TurningRadius { factor: 6.0 }, 1.0, 1.0),
        (MuBound::Constant, 1.0, 1.0),
        (MuBound::Literal, 2.0, 0.25),
        (MuBound::ScaledLiteral { gain: 3.0 }, 2.0, 0.25),
        (MuBound::ScaledLiteral { gain: 6.0 }, 2.0, 0.25),
        (MuBound::TurningRadius { factor: 4.0 }, 2.0, 0.25),
        (MuBound::TurningRadius { factor: 6.0 }, 2.0, 0.25),
        (MuBound::TurningRadius { factor: 8.0 }, 2.0, 0.25),
        // The default with the paper's gain 1: the gain's effect alone.
        (MuBound::TurningRadius { factor: 8.0 }, 1.0, 0.25),
        (MuBound::Constant, 2.0, 0.25),
    ];
    let mut figures = Vec::new();
    for (bound, gain, th) in variants {
        let cfg = FunnelConfig {
            bound,
            gain,
            seek_threshold: th,
            ..FunnelConfig::default()
        };
        let s = summarise(&args.pool.install(|| study.run_all(&table, &p, &cfg))?);
        let default = if cfg == FunnelConfig::default() {
            " (default)"
        } else {
            ""
        };
        println!(
            "| {bound:?}{default} | {gain} | {th} | {:.2} % | {:.1} % | {:.1} / {:.1} | {:.1} / {:.1} | {:.3} / {:.3} | {} |",
            100.0 * s.reach_rate,
            100.0 * s.oriented_rate,
            s.entry_err_deg.0,
            s.entry_err_deg.1,
            s.final_err_deg.0,
            s.final_err_deg.1,
            s.length_ratio.0,
            s.length_ratio.1,
            s.violations
        );
        let (id, label) = study_records::reach_variant(&bound, gain, th);
        figures.extend(study_records::reach(&id, &label, &s));
    }
    args.record
        .write(study_records::funnel_seeds(args.seed), figures)
}

/// Runs a scenario to its duration; per agent: path metrics and whether
/// every goal was completed.
fn simulate(sc: &Scenario, table: &EtaTable) -> Result<Vec<(PathMetrics, bool)>, String> {
    let mut w = sc.world().map_err(|e| e.to_string())?;
    for _ in 0..sc.steps() {
        w.step(table).map_err(|e| e.to_string())?;
    }
    Ok(w.agents().iter().map(|a| (a.metrics, a.done())).collect())
}

fn print_row(name: &str, c: &Comparison) {
    println!(
        "| {name} | {} | {:.2} / {:.2} | {:.2} / {:.2} | {:.1} % | {:.1} % | {:.1} % / {:.1} % |",
        c.n,
        c.length.0,
        c.length.1,
        c.curvature.0,
        c.curvature.1,
        100.0 * c.relaxed_shorter,
        100.0 * c.relaxed_less_curved,
        100.0 * c.reach.0,
        100.0 * c.reach.1
    );
}

fn relaxed(args: &RelaxedArgs) -> Result<(), String> {
    let study = RegionStudy {
        n: args.n,
        seed: args.seed,
        ..RegionStudy::default()
    };
    let table_path = &args.table;
    let dir = args.scenarios.display();
    let rcfg = args.relaxed_config()?;
    let table = load_table(table_path)?;
    let p = steering::base::vehicle::VehicleParams::default();
    table.check_params(&p).map_err(|e| e.to_string())?;
    let f = args.reading.funnel();
    println!(
        "Reading: {} against {}",
        Reading::label(ControllerKind::Standard, &f, &rcfg),
        Reading::label(ControllerKind::Relaxed, &f, &rcfg)
    );
    println!("Relaxed settings: {rcfg:?}");
    println!("Paper 001 presets (per agent, whole run; reach = finished every goal):");
    println!("| preset | agents | mean length std / rel (m) | mean ∫|κ| std / rel (rad) | relaxed shorter | relaxed less curved | reach std / rel |");
    println!("|---|---|---|---|---|---|---|");
    let mut names: Vec<String> = std::fs::read_dir(&args.scenarios)
        .map_err(|e| format!("cannot read {dir}: {e} (relative to the repository root: run from there, or pass --scenarios DIR)"))?
        .filter_map(|e| e.ok().map(|e| e.file_name().to_string_lossy().into_owned()))
        .filter(|n| n.starts_with("p001_") && n.ends_with("_standard.json"))
        .collect();
    names.sort();
    let (mut all_s, mut all_r) = (Vec::new(), Vec::new());
    let variant = study_records::relaxed_variant(&rcfg);
    let mut figures = Vec::new();
    for n in &names {
        let path = format!("{dir}/{n}");
        let text = std::fs::read_to_string(&path).map_err(|e| format!("{path}: {e}"))?;
        let mut sc = Scenario::from_json(&text).map_err(|e| format!("{path}: {e}"))?;
        sc.funnel = f;
        sc.controller = ControllerKind::Standard;
        let st = simulate(&sc, &table)?;
        sc.controller = ControllerKind::Relaxed;
        sc.relaxed = rcfg;
        let re = simulate(&sc, &table)?;
        let name = n.trim_end_matches("_standard.json");
        let c = compare(&st, &re);
        print_row(name, &c);
        figures.extend(study_records::relaxed(&variant, name, &c));
        all_s.extend(st);
        all_r.extend(re);
    }
    let c = compare(&all_s, &all_r);
    print_row("all presets", &c);
    figures.extend(study_records::relaxed(&variant, "all presets", &c));
    println!(
        "\nRandom region goals: {} scenarios, seed {}, D in [{}, {}] m, radius in [{}, {}] m, tau in [{:.0}, {:.0}] deg, v_d {} m/s, limit {} s (reach = ends inside the disk with heading inside T):",
        study.n,
        study.seed,
        study.d_range.0,
        study.d_range.1,
        study.r_range.0,
        study.r_range.1,
        study.tau_range.0.to_degrees(),
        study.tau_range.1.to_degrees(),
        study.speed,
        study.max_time
    );
    println!("| study | n | mean length std / rel (m) | mean ∫|κ| std / rel (rad) | relaxed shorter | relaxed less curved | reach std / rel |");
    println!("|---|---|---|---|---|---|---|");
    let (rs, rr) = args.pool.install(|| {
        (
            study.run_all(&table, &p, &Controller::Standard(f)),
            study.run_all(&table, &p, &Controller::Relaxed(f, rcfg)),
        )
    })?;
    let pick = |v: &[steering::studies::region::RegionRun]| -> Vec<(PathMetrics, bool)> {
        v.iter().map(|r| (r.path, r.reached)).collect()
    };
    let c = compare(&pick(&rs), &pick(&rr));
    print_row("random", &c);
    figures.extend(study_records::relaxed(&variant, "random", &c));
    let both: Vec<usize> = (0..rs.len().min(rr.len()))
        .filter(|&i| rs[i].reached && rr[i].reached)
        .collect();
    let sub = |v: &[steering::studies::region::RegionRun]| -> Vec<(PathMetrics, bool)> {
        both.iter().map(|&i| (v[i].path, v[i].reached)).collect()
    };
    let c = compare(&sub(&rs), &sub(&rr));
    print_row("random, both reached", &c);
    figures.extend(study_records::relaxed(&variant, "random, both reached", &c));
    let mean = |v: &[steering::studies::region::RegionRun],
                f: fn(&steering::studies::region::RegionRun) -> f32| {
        v.iter().map(|r| f64::from(f(r))).sum::<f64>() / v.len().max(1) as f64
    };
    println!(
        "∫|κ| split, std / rel: on the way {:.2} / {:.2} rad, turning in Orientation_only {:.2} / {:.2} rad; runs needing an in-place turn {:.1} % / {:.1} %",
        mean(&rs, |r| r.path.curvature - r.in_place_turn),
        mean(&rr, |r| r.path.curvature - r.in_place_turn),
        mean(&rs, |r| r.in_place_turn),
        mean(&rr, |r| r.in_place_turn),
        100.0 * mean(&rs, |r| f32::from(u8::from(r.in_place_turn > 1e-3))),
        100.0 * mean(&rr, |r| f32::from(u8::from(r.in_place_turn > 1e-3)))
    );
    let viol: u32 = rr.iter().map(|r| r.path.violations).sum();
    println!("relaxed limit violations: {viol}");
    args.record
        .write(study_records::funnel_seeds(args.seed), figures)
}

/// `steer avoid`: the avoidance benchmarks, every method on the same
/// seeds, one table row per benchmark and method; or `--write-presets`.
fn avoid(args: &AvoidArgs) -> Result<(), String> {
    use steering::avoidance::config::AvoidanceMethod;
    use steering::studies::avoidance::{study, Bench};
    let benches = args.benches()?;
    if let Some(dir) = &args.write_presets {
        for b in &benches {
            let sc = b.scenario(args.seed, AvoidanceMethod::Orca);
            let name = format!("avoid_{}", b.name());
            let mut sc = sc;
            if !b.seeded() {
                sc.description = format!("{} With ORCA avoidance.", sc.description);
            }
            sc.name = name.clone();
            let text = serde_json::to_string_pretty(&sc).map_err(|e| e.to_string())? + "\n";
            let path = dir.join(format!("{name}.json"));
            std::fs::write(&path, text).map_err(|e| format!("{}: {e}", path.display()))?;
            println!("wrote {}", path.display());
        }
        return Ok(());
    }
    let table = load_table(&args.table)?;
    println!(
        "avoidance benchmarks: {} seeded runs per benchmark and method from seed {} (paper figures once); radius {} m; avoidance planned every {} step(s); deadlock = unfinished and < 0.05 m/s for 10 s",
        args.seeds,
        args.seed,
        steering::studies::avoidance::BODY_RADIUS,
        args.replan_every
    );
    println!("| benchmark | method | runs | reach | oriented entries | runs finished | median finish s | length / off (median, max) | min distance m | runs with overlap | overlap pair-steps (max at once) | obstacle contacts | deadlocked agents (runs) | violations | NaN |");
    println!("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|");
    let mut figures = Vec::new();
    for b in benches {
        let t0 = Instant::now();
        let cells = args
            .pool
            .install(|| study(b, args.seeds, args.seed, &table, args.replan_every))?;
        for (m, c) in cells {
            println!(
                "| {} | {} | {} | {:.2} % | {:.1} % ({}/{}) | {} | {:.1} | {:.3}, {:.3} | {:.3} | {} | {} ({}) | {} | {} ({}) | {} | {} |",
                b.name(),
                m.name(),
                c.runs,
                100.0 * c.reached as f64 / c.agents.max(1) as f64,
                100.0 * c.oriented as f64 / c.entries.max(1) as f64,
                c.oriented,
                c.entries,
                c.finished_runs,
                c.median_finish,
                c.median_length_ratio,
                c.max_length_ratio,
                c.min_distance,
                c.runs_with_overlap,
                c.overlap_pair_steps,
                c.max_overlapping,
                c.obstacle_contacts,
                c.deadlocks,
                c.runs_with_deadlock,
                c.violations,
                c.nan
            );
            figures.extend(study_records::avoid(&b.name(), m.name(), &c));
        }
        let _ = Bench::ALL;
        eprintln!("{}: {:.1} s", b.name(), t0.elapsed().as_secs_f32());
    }
    args.record
        .write(study_records::avoid_seeds(args.seed, args.seeds), figures)
}

fn main() -> ExitCode {
    let cli = SteerCli::parse();
    let result = match &cli.command {
        Command::Run(a) => run(a),
        Command::Reach(a) => reach(a),
        Command::Envelope(a) => envelope(a),
        Command::Relaxed(a) => relaxed(a),
        Command::Avoid(a) => avoid(a),
        Command::Report(a) => steering::cli::report::run(a).map(|m| println!("{m}")),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("steer: {e}");
            ExitCode::FAILURE
        }
    }
}
