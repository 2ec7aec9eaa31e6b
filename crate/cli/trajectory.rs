//! `steer run`'s output, streamed: the trajectory is written as it is
//! simulated, one recorded step at a time, so peak memory is O(agents)
//! whatever the duration (a trace kept whole grows with agents × recorded
//! steps: 1,000 agents over the longest scenario, 3,600 s, would need
//! gigabytes).
//!
//! Formats, chosen by the output's extension (case-insensitive; anything
//! else is refused before the simulation starts):
//! - `.csv`: one row per agent per recorded step, time-ordered (all agents
//!   at t, then t + every·dt), header `agent,t,x,y,theta,v,omega,mode`.
//! - `.json`: one document, time-ordered:
//!   `{"name", "source", "dt", "steps", "every", "agents": N,
//!     "frames": [{"t", "x": [N], "y", "theta", "v", "omega", "mode"}, …],
//!     "metrics": [{"pathLength", …}; N]}` (metrics come last: they are
//!   known at the end).
//! - `.jsonl` (JSON Lines): the same content, one JSON value per line: the
//!   header object, then one frame object per recorded step, then
//!   `{"metrics": [...]}`.
//!
//! Writes go through a [`BufWriter`]; the per-agent metrics need only the
//! start poses and the world's running [`PathMetrics`](crate::base::metrics::PathMetrics).

use std::fs::File;
use std::io::{BufWriter, Write};
use std::path::{Path, PathBuf};

use serde::Serialize;

use crate::base::angle::diff;
use crate::funnelling::table::lookup::EtaTable;
use crate::world::scenario::Scenario;

/// Largest `--every` (the most steps a scenario has: 3,600 s at the
/// smallest time step, 1e-4 s).
pub const MAX_EVERY: u32 = 36_000_000;

/// The trajectory file's format, from its extension.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum OutFormat {
    /// `.csv`: one row per agent per recorded step.
    Csv,
    /// `.json`: one time-ordered document.
    Json,
    /// `.jsonl`: JSON Lines (header, frames, metrics).
    JsonLines,
}

impl OutFormat {
    /// The format of `path` from its extension, matched case-insensitively.
    ///
    /// # Errors
    /// Any other extension, or none.
    pub fn from_path(path: &Path) -> Result<Self, String> {
        let ext = path
            .extension()
            .map(|e| e.to_string_lossy().to_ascii_lowercase());
        match ext.as_deref() {
            Some("csv") => Ok(Self::Csv),
            Some("json") => Ok(Self::Json),
            Some("jsonl") => Ok(Self::JsonLines),
            _ => Err(format!(
                "--out {}: the extension must be .csv, .json or .jsonl (it chooses the format)",
                path.display()
            )),
        }
    }
}

/// `path` made absolute with its symbolic links resolved, as far as it
/// exists (a file not yet created: its folder resolved, its name kept).
fn resolved(path: &Path) -> Option<PathBuf> {
    if let Ok(p) = path.canonicalize() {
        return Some(p);
    }
    let parent = match path.parent() {
        Some(p) if !p.as_os_str().is_empty() => p,
        _ => Path::new("."),
    };
    Some(parent.canonicalize().ok()?.join(path.file_name()?))
}

/// Checks `--out` before anything is simulated: a known extension, and not
/// the scenario file itself (it would be overwritten).
///
/// # Errors
/// A message naming `--out`.
pub fn check_out_path(out: &Path, scenario: &Path) -> Result<OutFormat, String> {
    let format = OutFormat::from_path(out)?;
    if let (Some(a), Some(b)) = (resolved(out), resolved(scenario)) {
        if a == b {
            return Err(format!(
                "--out {} is the scenario file itself: choose another output file",
                out.display()
            ));
        }
    }
    Ok(format)
}

/// Creates the output file (before simulating), buffered.
///
/// # Errors
/// The file cannot be created, with the system's reason.
pub fn create_out(out: &Path) -> Result<BufWriter<File>, String> {
    File::create(out)
        .map(|f| BufWriter::with_capacity(1 << 16, f))
        .map_err(|e| format!("cannot create --out {}: {e}", out.display()))
}

/// One agent's summary, written after the last frame.
#[derive(Serialize)]
#[serde(rename_all = "camelCase")]
pub struct AgentMetrics {
    /// Path length, m.
    pub path_length: f32,
    /// Integrated |curvature|, rad.
    pub integrated_curvature: f32,
    /// Goals completed.
    pub goals_done: usize,
    /// Goals queued.
    pub goals: usize,
    /// When the last goal was completed, s.
    pub time_to_reach: Option<f32>,
    /// Distance to the last current goal at the end, m.
    pub arrival_position_error: f32,
    /// Orientation error to the last current goal at the end, degrees.
    pub arrival_orientation_error_deg: f32,
    /// Dubins lower bound through the goals, m.
    pub dubins_length: f32,
    /// Steps over a vehicle limit.
    pub limit_violations: u32,
}

/// What a run printed on its summary line.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct RunSummary {
    /// Agents simulated.
    pub agents: usize,
    /// Steps simulated.
    pub steps: u32,
    /// Agents that completed every goal.
    pub finished: usize,
    /// Limit violations, all agents.
    pub violations: u32,
    /// Recorded steps (frames).
    pub frames: u64,
}

#[derive(Serialize)]
struct Header<'a> {
    name: &'a str,
    source: &'a str,
    dt: f32,
    steps: u32,
    every: u32,
    agents: usize,
}

#[derive(Serialize)]
struct Frame<'a> {
    t: f32,
    x: &'a [f32],
    y: &'a [f32],
    theta: &'a [f32],
    v: &'a [f32],
    omega: &'a [f32],
    mode: &'a [u8],
}

/// One recorded step of every agent, reused from frame to frame.
#[derive(Default)]
struct FrameBuf {
    x: Vec<f32>,
    y: Vec<f32>,
    theta: Vec<f32>,
    v: Vec<f32>,
    omega: Vec<f32>,
    mode: Vec<u8>,
}

fn io(e: impl std::fmt::Display) -> String {
    format!("cannot write the trajectory: {e}")
}

/// Simulates `sc` for its duration and streams every `every`-th step to
/// `out` in `format`; `progress(k)` is called after each step `k`.
/// Memory: O(agents).
///
/// # Errors
/// An invalid scenario or a failed write.
pub fn stream_run(
    sc: &Scenario,
    table: &EtaTable,
    every: u32,
    format: OutFormat,
    out: &mut dyn Write,
    progress: &mut dyn FnMut(u32),
) -> Result<RunSummary, String> {
    if !(1..=MAX_EVERY).contains(&every) {
        return Err(format!("--every {every} is outside [1, {MAX_EVERY}]"));
    }
    let mut world = sc.world().map_err(|e| e.to_string())?;
    // The first row reports the mode the controller chooses at t = 0.
    world.plan(table);
    let starts: Vec<_> = world.agents.iter().map(|a| a.state).collect();
    let steps = sc.steps();
    let n = world.agents.len();
    let header = Header {
        name: &sc.name,
        source: &sc.source,
        dt: world.params.dt,
        steps,
        every,
        agents: n,
    };
    match format {
        OutFormat::Csv => out.write_all(b"agent,t,x,y,theta,v,omega,mode\n"),
        OutFormat::Json => {
            let h = serde_json::to_string(&header).map_err(io)?;
            write!(out, "{},\"frames\":[", &h[..h.len() - 1])
        }
        OutFormat::JsonLines => {
            serde_json::to_writer(&mut *out, &header).map_err(io)?;
            out.write_all(b"\n")
        }
    }
    .map_err(io)?;
    let mut buf = FrameBuf::default();
    let mut frames = 0u64;
    for k in 0..=steps {
        if k % every == 0 {
            let t = world.time;
            if format == OutFormat::Csv {
                for (i, a) in world.agents.iter().enumerate() {
                    let s = &a.state;
                    writeln!(
                        out,
                        "{i},{t:.4},{:.5},{:.5},{:.5},{:.5},{:.5},{}",
                        s.pos.x, s.pos.y, s.theta, s.v, s.omega, a.internals.mode as u8
                    )
                    .map_err(io)?;
                }
            } else {
                buf.fill(&world.agents);
                if format == OutFormat::Json && frames > 0 {
                    out.write_all(b",").map_err(io)?;
                }
                serde_json::to_writer(&mut *out, &buf.frame(t)).map_err(io)?;
                if format == OutFormat::JsonLines {
                    out.write_all(b"\n").map_err(io)?;
                }
            }
            frames += 1;
        }
        if k < steps {
            world.step(table);
            progress(k + 1);
        }
    }
    let p = world.params;
    let metrics: Vec<AgentMetrics> = world
        .agents
        .iter()
        .zip(&starts)
        .map(|(a, s0)| {
            let last = a.goal_now;
            let mut dubins_length = 0.0;
            let mut from = (s0.pos.x, s0.pos.y, s0.theta);
            for g in &a.goals {
                let to = (g.goal.pos.x, g.goal.pos.y, g.goal.beta);
                dubins_length +=
                    crate::base::dubins::shortest_length(from, to, p.min_turn_radius(g.goal.speed));
                from = to;
            }
            AgentMetrics {
                path_length: a.metrics.length,
                integrated_curvature: a.metrics.curvature,
                goals_done: a.current,
                goals: a.goals.len(),
                time_to_reach: a.finished_at,
                arrival_position_error: (last.pos - a.state.pos).length(),
                arrival_orientation_error_deg: diff(last.beta, a.state.theta).abs().to_degrees(),
                dubins_length,
                limit_violations: a.metrics.violations,
            }
        })
        .collect();
    match format {
        OutFormat::Csv => Ok(()),
        OutFormat::Json => {
            out.write_all(b"],\"metrics\":").map_err(io)?;
            serde_json::to_writer(&mut *out, &metrics).map_err(io)?;
            out.write_all(b"}\n")
        }
        OutFormat::JsonLines => {
            out.write_all(b"{\"metrics\":").map_err(io)?;
            serde_json::to_writer(&mut *out, &metrics).map_err(io)?;
            out.write_all(b"}\n")
        }
    }
    .map_err(io)?;
    out.flush().map_err(io)?;
    Ok(RunSummary {
        agents: n,
        steps,
        finished: metrics.iter().filter(|m| m.goals_done == m.goals).count(),
        violations: metrics.iter().map(|m| m.limit_violations).sum(),
        frames,
    })
}

impl FrameBuf {
    fn fill(&mut self, agents: &[crate::world::Agent]) {
        self.x.clear();
        self.y.clear();
        self.theta.clear();
        self.v.clear();
        self.omega.clear();
        self.mode.clear();
        for a in agents {
            let s = &a.state;
            self.x.push(s.pos.x);
            self.y.push(s.pos.y);
            self.theta.push(s.theta);
            self.v.push(s.v);
            self.omega.push(s.omega);
            self.mode.push(a.internals.mode as u8);
        }
    }

    fn frame(&self, t: f32) -> Frame<'_> {
        Frame {
            t,
            x: &self.x,
            y: &self.y,
            theta: &self.theta,
            v: &self.v,
            omega: &self.omega,
            mode: &self.mode,
        }
    }
}
