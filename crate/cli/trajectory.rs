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
//! Every JSON value is written by serde_json: the `.json` document is one
//! serialised value whose `frames` sequence simulates as it is written
//! (each frame is serialised from the world's state at its step, so the
//! document is well formed by construction and never held whole), the
//! `.jsonl` lines one value each. The per-agent metrics need only the
//! start poses and the world's running
//! [`PathMetrics`](crate::base::metrics::PathMetrics).
//!
//! The file is written under a temporary name beside `--out` and renamed
//! onto it only once complete ([`OutFile::commit`]): a run that fails or is
//! interrupted leaves any earlier file at `--out` as it was (a run killed
//! by a signal may leave its hidden `.NAME.PID.tmp` beside it).

use std::cell::RefCell;
use std::fs::File;
use std::io::{BufWriter, Write};
use std::path::{Path, PathBuf};

use serde::ser::{SerializeSeq, Serializer};
use serde::Serialize;

use crate::base::angle::diff;
use crate::base::vehicle::VehicleState;
use crate::funnelling::table::lookup::EtaTable;
use crate::world::scenario::Scenario;
use crate::world::World;

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

/// The trajectory file being written: buffered writes to a temporary file
/// beside `--out` (same folder, so the rename cannot cross file systems),
/// renamed onto `--out` by [`OutFile::commit`]. Dropped uncommitted (an
/// error, a panic), it removes the temporary file.
#[derive(Debug)]
pub struct OutFile {
    file: BufWriter<File>,
    tmp: PathBuf,
    dest: PathBuf,
    committed: bool,
}

/// Creates the output file (before simulating): a temporary file beside
/// `out`, or beside the file a symbolic link `out` points to.
///
/// # Errors
/// The file cannot be created, with the system's reason.
pub fn create_out(out: &Path) -> Result<OutFile, String> {
    let dest = match out.symlink_metadata() {
        Ok(m) if m.file_type().is_symlink() => out.canonicalize().unwrap_or_else(|_| out.into()),
        _ => out.to_path_buf(),
    };
    let name = dest.file_name().unwrap_or_default().to_string_lossy();
    let tmp = dest.with_file_name(format!(".{name}.{}.tmp", std::process::id()));
    let file =
        File::create(&tmp).map_err(|e| format!("cannot create --out {}: {e}", out.display()))?;
    Ok(OutFile {
        file: BufWriter::with_capacity(1 << 16, file),
        tmp,
        dest,
        committed: false,
    })
}

impl OutFile {
    /// Flushes the trajectory and renames it onto `--out`.
    ///
    /// # Errors
    /// The flush or the rename fails, with the system's reason.
    pub fn commit(mut self) -> Result<(), String> {
        self.file
            .flush()
            .and_then(|()| std::fs::rename(&self.tmp, &self.dest))
            .map_err(|e| format!("cannot write --out {}: {e}", self.dest.display()))?;
        self.committed = true;
        Ok(())
    }
}

impl Write for OutFile {
    fn write(&mut self, buf: &[u8]) -> std::io::Result<usize> {
        self.file.write(buf)
    }

    fn write_all(&mut self, buf: &[u8]) -> std::io::Result<()> {
        self.file.write_all(buf)
    }

    fn flush(&mut self) -> std::io::Result<()> {
        self.file.flush()
    }
}

impl Drop for OutFile {
    fn drop(&mut self) {
        if !self.committed {
            let _ = std::fs::remove_file(&self.tmp);
        }
    }
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

/// The first line of `.jsonl`, and the first keys of `.json`.
#[derive(Serialize)]
struct Header<'a> {
    name: &'a str,
    source: &'a str,
    dt: f32,
    steps: u32,
    every: u32,
    agents: usize,
}

/// One recorded step of every agent.
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

/// The last line of `.jsonl`.
#[derive(Serialize)]
struct MetricsLine<'a> {
    metrics: &'a [AgentMetrics],
}

/// The `.json` document: the header's keys, then `frames`, then `metrics`.
/// Serialising it runs the simulation: `frames` steps the world as each
/// frame is written, and `metrics` (serialised after it, in field order)
/// reads the world at the end.
#[derive(Serialize)]
struct Document<'h, 'r, 'a> {
    #[serde(flatten)]
    header: &'h Header<'h>,
    frames: Frames<'r, 'a>,
    metrics: Metrics<'r, 'a>,
}

/// The recorded steps of a [`Run`], simulated as they are serialised.
struct Frames<'r, 'a>(&'r RefCell<Run<'a>>);

impl Serialize for Frames<'_, '_> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let mut run = self.0.borrow_mut();
        let mut seq = s.serialize_seq(None)?;
        while let Some(frame) = run.next_frame() {
            seq.serialize_element(&frame)?;
        }
        seq.end()
    }
}

/// The per-agent metrics of a [`Run`] at its end.
struct Metrics<'r, 'a>(&'r RefCell<Run<'a>>);

impl Serialize for Metrics<'_, '_> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        self.0.borrow_mut().metrics().serialize(s)
    }
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

/// A scenario's simulation, stepped on demand: [`Run::next_frame`] steps
/// the world to the next recorded step (every `every`-th, from t = 0) and
/// copies it into the reused [`FrameBuf`]; memory O(agents).
struct Run<'a> {
    world: World,
    table: &'a EtaTable,
    starts: Vec<VehicleState>,
    steps: u32,
    every: u32,
    /// The step the world is at; `None` before the first frame.
    at: Option<u32>,
    frames: u64,
    buf: FrameBuf,
    metrics: Option<Vec<AgentMetrics>>,
    progress: &'a mut dyn FnMut(u32),
}

fn io(e: impl std::fmt::Display) -> String {
    format!("cannot write the trajectory: {e}")
}

/// Simulates `sc` for its duration and streams every `every`-th step to
/// `out` in `format`; `progress(k)` is called after each step `k`.
/// Memory: O(agents).
///
/// # Errors
/// An invalid scenario, a table built for other limits, or a failed write.
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
    world.plan(table).map_err(|e| e.to_string())?;
    let n = world.agents().len();
    let header = Header {
        name: &sc.name,
        source: &sc.source,
        dt: world.params().dt,
        steps: sc.steps(),
        every,
        agents: n,
    };
    let mut run = Run {
        starts: world.agents().iter().map(|a| a.state).collect(),
        world,
        table,
        steps: sc.steps(),
        every,
        at: None,
        frames: 0,
        buf: FrameBuf::default(),
        metrics: None,
        progress,
    };
    match format {
        OutFormat::Csv => write_csv(&mut run, out),
        OutFormat::Json => {
            let cell = RefCell::new(run);
            let doc = Document {
                header: &header,
                frames: Frames(&cell),
                metrics: Metrics(&cell),
            };
            serde_json::to_writer(&mut *out, &doc).map_err(io)?;
            run = cell.into_inner();
            out.write_all(b"\n").map_err(io)
        }
        OutFormat::JsonLines => {
            serde_json::to_writer(&mut *out, &header).map_err(io)?;
            out.write_all(b"\n").map_err(io)?;
            while let Some(frame) = run.next_frame() {
                serde_json::to_writer(&mut *out, &frame).map_err(io)?;
                out.write_all(b"\n").map_err(io)?;
            }
            let line = MetricsLine {
                metrics: run.metrics(),
            };
            serde_json::to_writer(&mut *out, &line).map_err(io)?;
            out.write_all(b"\n").map_err(io)
        }
    }?;
    out.flush().map_err(io)?;
    let (steps, frames) = (run.steps, run.frames);
    let metrics = run.metrics();
    Ok(RunSummary {
        agents: n,
        steps,
        finished: metrics.iter().filter(|m| m.goals_done == m.goals).count(),
        violations: metrics.iter().map(|m| m.limit_violations).sum(),
        frames,
    })
}

/// `.csv`: the header row, then one row per agent per recorded step.
fn write_csv(run: &mut Run, out: &mut dyn Write) -> Result<(), String> {
    out.write_all(b"agent,t,x,y,theta,v,omega,mode\n")
        .map_err(io)?;
    while let Some(f) = run.next_frame() {
        for i in 0..f.x.len() {
            writeln!(
                out,
                "{i},{:.4},{:.5},{:.5},{:.5},{:.5},{:.5},{}",
                f.t, f.x[i], f.y[i], f.theta[i], f.v[i], f.omega[i], f.mode[i]
            )
            .map_err(io)?;
        }
    }
    Ok(())
}

impl Run<'_> {
    /// Steps the world to the next recorded step and returns it; `None`
    /// once the world has taken every step of the scenario.
    fn next_frame(&mut self) -> Option<Frame<'_>> {
        loop {
            let k = match self.at {
                None => 0,
                Some(k) if k < self.steps => {
                    // Checked by `plan` before the first row; the limits
                    // do not change during a run.
                    self.world
                        .step(self.table)
                        .expect("the table was checked before the run");
                    (self.progress)(k + 1);
                    k + 1
                }
                Some(_) => return None,
            };
            self.at = Some(k);
            if k % self.every == 0 {
                self.frames += 1;
                self.buf.fill(self.world.agents());
                return Some(self.buf.frame(self.world.time()));
            }
        }
    }

    /// Every agent's summary at the end of the run (the remaining steps
    /// simulated first, unrecorded).
    fn metrics(&mut self) -> &[AgentMetrics] {
        while self.next_frame().is_some() {}
        let (world, starts) = (&self.world, &self.starts);
        self.metrics
            .get_or_insert_with(|| agent_metrics(world, starts))
    }
}

/// Each agent's [`AgentMetrics`] in `world`, from its start pose.
fn agent_metrics(world: &World, starts: &[VehicleState]) -> Vec<AgentMetrics> {
    let p = *world.params();
    world
        .agents()
        .iter()
        .zip(starts)
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
        .collect()
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
