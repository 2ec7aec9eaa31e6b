//! `steer`: the command-line runner.
//!
//! ```text
//! steer run SCENARIO.json --out TRAJ.json|TRAJ.csv [--every N] [--table FILE]
//! steer reach [--n N] [--seed S] [--table FILE]
//! ```
//! `run` simulates a scenario file (schema: `crate/scenario.rs`) and writes
//! the per-step pose, speeds and mode of every agent plus its metrics.
//! `reach` runs the seeded random reach study for every μ-bound variant and
//! prints the acceptance figures of the funnelling issue.

// `wasm-pack test` builds every binary for wasm32, where the threaded
// studies do not exist: there this binary is empty.
#![cfg_attr(target_arch = "wasm32", no_main)]
#![cfg(not(target_arch = "wasm32"))]

use std::fmt::Write as _;
use std::process::ExitCode;

use serde::Serialize;
use steering::angle::diff;
use steering::dubins;
use steering::funnel::{FunnelConfig, MuBound};
use steering::scenario::Scenario;
use steering::study::{summarise, ReachStudy};
use steering::table::EtaTable;

const USAGE: &str = "usage:\n  steer run SCENARIO.json --out TRAJ.json|TRAJ.csv [--every N] [--table FILE]\n  steer reach [--n N] [--seed S] [--table FILE]";

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

fn load_table(path: &str) -> Result<EtaTable, String> {
    let bytes = std::fs::read(path).map_err(|e| format!("cannot read η table {path}: {e}"))?;
    EtaTable::from_bytes(&bytes).map_err(|e| format!("{path}: {e}"))
}

fn run(args: &[String]) -> Result<(), String> {
    let mut scenario = None;
    let mut out = None;
    let mut every = 1u32;
    let mut table_path = "tables/eta.bin".to_string();
    let mut it = args.iter();
    while let Some(a) = it.next() {
        match a.as_str() {
            "--out" => out = it.next().cloned(),
            "--every" => {
                every = it
                    .next()
                    .and_then(|s| s.parse().ok())
                    .filter(|&n| n > 0)
                    .ok_or("--every wants a positive integer")?
            }
            "--table" => table_path = it.next().cloned().ok_or("--table wants a file")?,
            s if !s.starts_with('-') && scenario.is_none() => scenario = Some(s.to_string()),
            s => return Err(format!("unknown argument `{s}`\n{USAGE}")),
        }
    }
    let scenario = scenario.ok_or(USAGE)?;
    let out = out.ok_or("--out TRAJ.json|TRAJ.csv is required")?;
    let text =
        std::fs::read_to_string(&scenario).map_err(|e| format!("cannot read {scenario}: {e}"))?;
    let sc = Scenario::from_json(&text).map_err(|e| format!("{scenario}: {e}"))?;
    let table = load_table(&table_path)?;
    table
        .check_params(&sc.vehicle)
        .map_err(|e| format!("{table_path}: {e}"))?;
    let mut world = sc.world().map_err(|e| format!("{scenario}: {e}"))?;
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
        "steer: {} — {} agents, {steps} steps, {done} finished all goals, {viol} limit violations -> {out}",
        sc.name,
        result.agents.len()
    );
    Ok(())
}

fn reach(args: &[String]) -> Result<(), String> {
    let mut study = ReachStudy::default();
    let mut table_path = "tables/eta.bin".to_string();
    let mut it = args.iter();
    while let Some(a) = it.next() {
        match a.as_str() {
            "--n" => {
                study.n = it
                    .next()
                    .and_then(|s| s.parse().ok())
                    .ok_or("--n wants an integer")?
            }
            "--seed" => {
                study.seed = it
                    .next()
                    .and_then(|s| s.parse().ok())
                    .ok_or("--seed wants an integer")?
            }
            "--table" => table_path = it.next().cloned().ok_or("--table wants a file")?,
            s => return Err(format!("unknown argument `{s}`\n{USAGE}")),
        }
    }
    let table = load_table(&table_path)?;
    let p = steering::vehicle::VehicleParams::default();
    table.check_params(&p).map_err(|e| e.to_string())?;
    let threads = std::thread::available_parallelism().map_or(2, |n| n.get());
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
    println!("| μ bound | seek threshold | reach | oriented on entry | entry err median / p95 (°) | final err median / p95 (°) | length/Dubins median / p90 | violations |");
    println!("|---|---|---|---|---|---|---|---|");
    let variants = [
        (MuBound::Literal, 1.0),
        (MuBound::ScaledLiteral { gain: 6.0 }, 1.0),
        (MuBound::ScaledLiteral { gain: 6.0 }, 0.5),
        (MuBound::TurningRadius { factor: 2.0 }, 1.0),
        (MuBound::TurningRadius { factor: 12.0 }, 1.0),
        (MuBound::Constant, 1.0),
        (MuBound::Constant, 0.25),
    ];
    for (bound, th) in variants {
        let cfg = FunnelConfig {
            bound,
            seek_threshold: th,
        };
        let s = summarise(&study.run_all(&table, &p, &cfg, threads));
        let default = if cfg == FunnelConfig::default() {
            " (default)"
        } else {
            ""
        };
        println!(
            "| {bound:?}{default} | {th} | {:.2} % | {:.1} % | {:.1} / {:.1} | {:.1} / {:.1} | {:.3} / {:.3} | {} |",
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

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let result = match args.first().map(String::as_str) {
        Some("run") => run(&args[1..]),
        Some("reach") => reach(&args[1..]),
        Some("-h" | "--help") => {
            println!("{USAGE}");
            Ok(())
        }
        _ => Err(USAGE.to_string()),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("steer: {e}");
            ExitCode::FAILURE
        }
    }
}
