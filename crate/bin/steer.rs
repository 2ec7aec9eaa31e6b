//! `steer`: the command-line runner (arguments: [`steering::cli::steer`];
//! `steer --help`, `steer run --help`, …).
//!
//! ```text
//! steer run SCENARIO.json --out TRAJ.json|TRAJ.csv [--every N] [--table FILE] [--controller standard|relaxed]
//! steer reach [--n N] [--seed S] [--table FILE] [--threads N]
//! steer relaxed [--n N] [--seed S] [--table FILE] [--scenarios DIR] [--aim entry|paper-arc] [--disk-margin F] [--orientation-margin F] [--threads N]
//! ```
//! `run` simulates a scenario file (schema: `crate/funnelling/scenario.rs`)
//! and writes the per-step pose, speeds and mode of every agent plus its
//! metrics; `--controller` overrides the scenario's controller.
//! `reach` runs the seeded random reach study for every μ-bound variant and
//! prints the acceptance figures of the funnelling issue.
//! `relaxed` runs every `scenarios/p001_*_standard.json` preset with both
//! controllers, then the seeded random region-goal study, and prints the
//! comparison of paper 001 (path length, integrated |curvature|, reach).
//! Studies run on rayon; their output does not depend on `--threads`.

// `wasm-pack test` builds every binary for wasm32, where clap and rayon
// are not dependencies: there this binary is empty.
#![cfg_attr(target_arch = "wasm32", no_main)]
#![cfg(not(target_arch = "wasm32"))]

use std::fmt::Write as _;
use std::process::ExitCode;

use std::path::Path;

use clap::Parser;
use serde::Serialize;
use steering::angle::diff;
use steering::cli::steer::{Command, EnvelopeArgs, ReachArgs, RelaxedArgs, RunArgs, SteerCli};
use steering::dubins;
use steering::funnel::{FunnelConfig, MuBound};
use steering::metrics::PathMetrics;
use steering::region_study::{compare, Comparison, RegionStudy};
use steering::relaxed::{Controller, ControllerKind, RelaxedConfig};
use steering::scenario::Scenario;
use steering::study::{summarise, ReachStudy};
use steering::table::EtaTable;

#[derive(Serialize, Default)]
#[serde(rename_all = "camelCase")]
struct Trace {
    t: Vec<f32>,
    x: Vec<f32>,
    y: Vec<f32>,
    theta: Vec<f32>,
    v: Vec<f32>,
    omega: Vec<f32>,
    mode: Vec<u8>,
}

#[derive(Serialize)]
#[serde(rename_all = "camelCase")]
struct AgentOut {
    trajectory: Trace,
    metrics: Metrics,
}

#[derive(Serialize)]
#[serde(rename_all = "camelCase")]
struct Metrics {
    path_length: f32,
    integrated_curvature: f32,
    goals_done: usize,
    goals: usize,
    time_to_reach: Option<f32>,
    arrival_position_error: f32,
    arrival_orientation_error_deg: f32,
    dubins_length: f32,
    limit_violations: u32,
}

#[derive(Serialize)]
#[serde(rename_all = "camelCase")]
struct RunOut {
    name: String,
    source: String,
    dt: f32,
    steps: u32,
    agents: Vec<AgentOut>,
}

fn load_table(path: &Path) -> Result<EtaTable, String> {
    let shown = path.display();
    let bytes = std::fs::read(path).map_err(|e| format!("cannot read η table {shown}: {e}"))?;
    EtaTable::from_bytes(&bytes).map_err(|e| format!("{shown}: {e}"))
}

fn run(args: &RunArgs) -> Result<(), String> {
    let scenario = args.scenario.display();
    let out = args.out.display().to_string();
    let (every, table_path, controller) = (args.every, &args.table, args.controller);
    let text = std::fs::read_to_string(&args.scenario)
        .map_err(|e| format!("cannot read {scenario}: {e}"))?;
    let mut sc = Scenario::from_json(&text).map_err(|e| format!("{scenario}: {e}"))?;
    if let Some(c) = controller {
        sc.controller = c;
    }
    let table = load_table(table_path)?;
    table
        .check_params(&sc.vehicle)
        .map_err(|e| format!("{}: {e}", table_path.display()))?;
    let mut world = sc.world().map_err(|e| format!("{scenario}: {e}"))?;
    // The first row reports the mode the controller chooses at t = 0.
    world.plan(&table);
    let starts: Vec<_> = world.agents.iter().map(|a| a.state).collect();
    let mut traces: Vec<Trace> = world.agents.iter().map(|_| Trace::default()).collect();
    let steps = sc.steps();
    for k in 0..=steps {
        if k % every == 0 {
            for (a, tr) in world.agents.iter().zip(&mut traces) {
                tr.t.push(world.time);
                tr.x.push(a.state.pos.x);
                tr.y.push(a.state.pos.y);
                tr.theta.push(a.state.theta);
                tr.v.push(a.state.v);
                tr.omega.push(a.state.omega);
                tr.mode.push(a.internals.mode as u8);
            }
        }
        if k < steps {
            world.step(&table);
        }
    }
    let p = world.params;
    let agents: Vec<AgentOut> = world
        .agents
        .iter()
        .zip(traces)
        .zip(&starts)
        .map(|((a, trajectory), s0)| {
            let last = a.goal_now;
            let mut dub = 0.0;
            let mut from = (s0.pos.x, s0.pos.y, s0.theta);
            for g in &a.goals {
                let to = (g.goal.pos.x, g.goal.pos.y, g.goal.beta);
                dub += dubins::shortest_length(from, to, p.min_turn_radius(g.goal.speed));
                from = to;
            }
            AgentOut {
                trajectory,
                metrics: Metrics {
                    path_length: a.metrics.length,
                    integrated_curvature: a.metrics.curvature,
                    goals_done: a.current,
                    goals: a.goals.len(),
                    time_to_reach: a.finished_at,
                    arrival_position_error: (last.pos - a.state.pos).length(),
                    arrival_orientation_error_deg: diff(last.beta, a.state.theta)
                        .abs()
                        .to_degrees(),
                    dubins_length: dub,
                    limit_violations: a.metrics.violations,
                },
            }
        })
        .collect();
    let result = RunOut {
        name: sc.name.clone(),
        source: sc.source.clone(),
        dt: p.dt,
        steps,
        agents,
    };
    let body = if out.ends_with(".csv") {
        let mut s = String::from("agent,t,x,y,theta,v,omega,mode\n");
        for (i, a) in result.agents.iter().enumerate() {
            let tr = &a.trajectory;
            for k in 0..tr.t.len() {
                let _ = writeln!(
                    s,
                    "{i},{:.4},{:.5},{:.5},{:.5},{:.5},{:.5},{}",
                    tr.t[k], tr.x[k], tr.y[k], tr.theta[k], tr.v[k], tr.omega[k], tr.mode[k]
                );
            }
        }
        s
    } else {
        serde_json::to_string(&result).map_err(|e| e.to_string())?
    };
    std::fs::write(&out, body).map_err(|e| format!("cannot write {out}: {e}"))?;
    let done = result
        .agents
        .iter()
        .filter(|a| a.metrics.goals_done == a.metrics.goals)
        .count();
    let viol: u32 = result
        .agents
        .iter()
        .map(|a| a.metrics.limit_violations)
        .sum();
    println!(
        "steer: {} ({}) — {} agents, {steps} steps, {done} finished all goals, {viol} limit violations -> {out}",
        sc.name,
        sc.controller.name(),
        result.agents.len()
    );
    Ok(())
}

/// `steer envelope`: the envelope study (`steering::funnelling::envelope`).
fn envelope(args: &EnvelopeArgs) -> Result<(), String> {
    use steering::funnelling::envelope::{variants, EnvelopeStudy};
    let mut study = EnvelopeStudy {
        seed: args.seed,
        ..EnvelopeStudy::default()
    };
    (study.n_static, study.n_moving, study.n_chain) = (args.n, args.n / 5, args.n / 5);
    let table = load_table(&args.table)?;
    let p = steering::vehicle::VehicleParams::default();
    table.check_params(&p).map_err(|e| e.to_string())?;
    let mut vs = variants().to_vec();
    if let Some(json) = &args.standard {
        let cfg: steering::funnel::FunnelConfig =
            serde_json::from_str(json).map_err(|e| format!("--standard: {e}"))?;
        cfg.validate().map_err(|e| format!("--standard: {e}"))?;
        for v in &mut vs {
            match &mut v.controller {
                steering::relaxed::Controller::Standard(f) if v.name == "standard" => *f = cfg,
                steering::relaxed::Controller::Relaxed(f, _) if v.name == "relaxed" => *f = cfg,
                _ => {}
            }
        }
    }
    if let Some(only) = &args.only {
        vs.retain(|v| only.split(',').any(|n| n == v.name));
    }
    let report = study.run_all(&table, &p, &vs);
    let detail: &[&str] = if args.brief {
        &[]
    } else {
        &["standard", "standard-literal", "relaxed"]
    };
    print!("{}", report.tables(detail));
    println!(
        "\nissue 13 targets (seed {}):\n{}",
        args.seed,
        report.targets()
    );
    if let Some(path) = &args.json {
        let body = serde_json::to_string_pretty(&report.to_json()).map_err(|e| e.to_string())?;
        std::fs::write(path, body).map_err(|e| format!("cannot write {}: {e}", path.display()))?;
    }
    Ok(())
}

fn reach(args: &ReachArgs) -> Result<(), String> {
    let study = ReachStudy {
        n: args.n,
        seed: args.seed,
        ..ReachStudy::default()
    };
    let table_path = &args.table;
    let table = load_table(table_path)?;
    let p = steering::vehicle::VehicleParams::default();
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
        (MuBound::Constant, 2.0, 0.25),
    ];
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
    }
    Ok(())
}

/// Runs a scenario to its duration; per agent: path metrics and whether
/// every goal was completed.
fn simulate(sc: &Scenario, table: &EtaTable) -> Result<Vec<(PathMetrics, bool)>, String> {
    let mut w = sc.world().map_err(|e| e.to_string())?;
    for _ in 0..sc.steps() {
        w.step(table);
    }
    Ok(w.agents.iter().map(|a| (a.metrics, a.done())).collect())
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
    let mut rcfg = RelaxedConfig::default();
    if let Some(aim) = args.aim {
        rcfg.aim = aim;
    }
    if let Some(m) = args.disk_margin {
        rcfg.disk_margin = m;
    }
    if let Some(m) = args.orientation_margin {
        rcfg.orientation_margin = m;
    }
    rcfg.validate().map_err(|e| e.to_string())?;
    let table = load_table(table_path)?;
    let p = steering::vehicle::VehicleParams::default();
    table.check_params(&p).map_err(|e| e.to_string())?;
    println!("Relaxed settings: {rcfg:?}");
    println!("Paper 001 presets (per agent, whole run; reach = finished every goal):");
    println!("| preset | agents | mean length std / rel (m) | mean ∫|κ| std / rel (rad) | relaxed shorter | relaxed less curved | reach std / rel |");
    println!("|---|---|---|---|---|---|---|");
    let mut names: Vec<String> = std::fs::read_dir(&args.scenarios)
        .map_err(|e| format!("cannot read {dir}: {e}"))?
        .filter_map(|e| e.ok().map(|e| e.file_name().to_string_lossy().into_owned()))
        .filter(|n| n.starts_with("p001_") && n.ends_with("_standard.json"))
        .collect();
    names.sort();
    let (mut all_s, mut all_r) = (Vec::new(), Vec::new());
    for n in &names {
        let path = format!("{dir}/{n}");
        let text = std::fs::read_to_string(&path).map_err(|e| format!("{path}: {e}"))?;
        let mut sc = Scenario::from_json(&text).map_err(|e| format!("{path}: {e}"))?;
        sc.controller = ControllerKind::Standard;
        let st = simulate(&sc, &table)?;
        sc.controller = ControllerKind::Relaxed;
        sc.relaxed = rcfg;
        let re = simulate(&sc, &table)?;
        print_row(n.trim_end_matches("_standard.json"), &compare(&st, &re));
        all_s.extend(st);
        all_r.extend(re);
    }
    print_row("all presets", &compare(&all_s, &all_r));
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
    let f = FunnelConfig::default();
    let (rs, rr) = args.pool.install(|| {
        (
            study.run_all(&table, &p, &Controller::Standard(f)),
            study.run_all(&table, &p, &Controller::Relaxed(f, rcfg)),
        )
    })?;
    let pick = |v: &[steering::region_study::RegionRun]| -> Vec<(PathMetrics, bool)> {
        v.iter().map(|r| (r.path, r.reached)).collect()
    };
    print_row("random", &compare(&pick(&rs), &pick(&rr)));
    let both: Vec<usize> = (0..rs.len().min(rr.len()))
        .filter(|&i| rs[i].reached && rr[i].reached)
        .collect();
    let sub = |v: &[steering::region_study::RegionRun]| -> Vec<(PathMetrics, bool)> {
        both.iter().map(|&i| (v[i].path, v[i].reached)).collect()
    };
    print_row("random, both reached", &compare(&sub(&rs), &sub(&rr)));
    let mean = |v: &[steering::region_study::RegionRun],
                f: fn(&steering::region_study::RegionRun) -> f32| {
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
    Ok(())
}

fn main() -> ExitCode {
    let cli = SteerCli::parse();
    let result = match &cli.command {
        Command::Run(a) => run(a),
        Command::Reach(a) => reach(a),
        Command::Envelope(a) => envelope(a),
        Command::Relaxed(a) => relaxed(a),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("steer: {e}");
            ExitCode::FAILURE
        }
    }
}
