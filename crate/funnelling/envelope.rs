//! The envelope study (issue 13): oriented arrival measured over the whole
//! operating envelope a user of the lab can reach, not at one operating
//! point. [`crate::study`] samples one point (D_tol 0.25 m, ε_tol 5°,
//! 1.3 m/s, D 1–30 m); the defaults tuned there did much worse on random
//! targets drawn over the sliders' range, so this is the study the
//! controller is tuned on (one seed) and judged on (another, held out).
//!
//! Every run is a one-agent [`World`], stepped exactly as the lab and
//! `steer run` step it (goal queues, moving goals, the braking after the
//! last halting goal), so what is measured is what a user sees.
//!
//! | sampled | range |
//! |---|---|
//! | distance D | 0.4–60 m, log-uniform (chain legs 0.4–20 m) |
//! | bearing, start heading, β | any |
//! | start speed | 0..v_max |
//! | start angular speed | uniform in the admissible ±min(ω_max, A/v) |
//! | D_tol | {0.1, 0.25, 0.5, 1, 2} m |
//! | ε_tol | {2, 5, 10, 20, 45}° |
//! | desired speed | {0.5, 1.0, 1.3, 1.8, 2.0} m/s |
//! | halting | half the static goals and the last goal of half the chains |
//! | moving goals | linear, 0–0.4 m/s in any direction, never halting ([`crate::world`] refuses halting on a goal that never stops) |
//! | chains | three goals in a row, switching on End_of_Steering |
//!
//! Each group (static, moving, chain) is run with every [`Variant`]: the
//! standard and the relaxed controller, each with the default settings and
//! with the paper's literal reading (gain 1, seek threshold 1,
//! [`MuBound::Literal`]). Scenario `i` of a group is the same for every
//! variant (paired comparison). Runs stop at [`EnvelopeStudy::max_time`]
//! per goal.
//!
//! What a run records ([`RunRecord`]): reach (enters the first goal's
//! disk), oriented on entry (heading within ε_tol of β at the first step
//! inside D_tol) and the entry error, End_of_Steering declared with both
//! tolerances met, for halting runs the rest pose inside both tolerances,
//! finished (every goal done), path length over the Dubins length (radius
//! at the desired speed, [`crate::dubins`]), non-finite values and limit
//! violations ([`crate::metrics`]), and orbits (never enters).

use core::f32::consts::PI;
use core::fmt::Write as _;

use glam::Vec2;
use serde::Serialize;

use crate::angle::diff;
use crate::dubins;
use crate::funnel::{FunnelConfig, Goal, Mode, MuBound};
use crate::metrics::percentile;
use crate::relaxed::{Controller, ControllerKind, RelaxedAim, RelaxedConfig};
use crate::rng::Rng;
use crate::table::EtaTable;
use crate::vehicle::{VehicleParams, VehicleState};
use crate::world::{GoalMotion, GoalSpec, SwitchRule, World};

/// Position tolerances sampled, m.
pub const D_TOLS: [f32; 5] = [0.1, 0.25, 0.5, 1.0, 2.0];
/// Orientation tolerances sampled, degrees.
pub const EPS_TOLS_DEG: [f32; 5] = [2.0, 5.0, 10.0, 20.0, 45.0];
/// Desired speeds sampled, m/s.
pub const SPEEDS: [f32; 5] = [0.5, 1.0, 1.3, 1.8, 2.0];
/// Distance bands of the tables, m: `[lo, hi)`.
pub const BANDS: [(f32, f32); 3] = [(0.4, 2.0), (2.0, 5.0), (5.0, 60.0)];
/// Distance range of static and moving goals, m (log-uniform).
pub const D_RANGE: (f32, f32) = (0.4, 60.0);
/// Distance range of each leg of a chain, m (log-uniform).
pub const CHAIN_LEG: (f32, f32) = (0.4, 20.0);
/// Largest speed of a moving goal, m/s.
pub const GOAL_SPEED_MAX: f32 = 0.4;
/// Time allowed after the last halting goal for the vehicle to come to
/// rest, s (braking from v_max takes 1.3 s).
pub const REST_TIME: f32 = 10.0;

/// The three goal families.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "camelCase")]
pub enum GoalKind {
    /// One static goal.
    Static,
    /// One goal moving at constant velocity.
    Moving,
    /// Three static goals in a row.
    Chain,
}

impl GoalKind {
    /// Every kind, in table order.
    pub const ALL: [Self; 3] = [Self::Static, Self::Moving, Self::Chain];

    fn stream(self) -> u64 {
        match self {
            Self::Static => 1,
            Self::Moving => 2,
            Self::Chain => 3,
        }
    }

    /// Lower-case name.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Self::Static => "static",
            Self::Moving => "moving",
            Self::Chain => "chain",
        }
    }
}

/// A controller with its settings, named for the tables.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Variant {
    /// Name in the tables and the JSON.
    pub name: &'static str,
    /// The controller.
    pub controller: Controller,
}

/// The paper's literal reading of Fig. 4 and 5: μ = −Δη (gain 1), bounded
/// by the literal `|η(D, Δη, 0, v_c, v_dt)|`, seek when |Δη| < ε_tol.
#[must_use]
pub fn literal_config() -> FunnelConfig {
    FunnelConfig {
        bound: MuBound::Literal,
        gain: 1.0,
        seek_threshold: 1.0,
        aim: crate::funnel::Aim::Centre,
        min_bound_radius: 0.0,
        terminal: None,
    }
}

/// Paper 001 Fig. 7 read literally: the relaxed point on the ring arc 𝒜,
/// T searched over 0.8 of τ (the relaxed settings before issue 13).
#[must_use]
pub fn literal_relaxed_config() -> RelaxedConfig {
    RelaxedConfig {
        aim: RelaxedAim::PaperArc,
        disk_margin: 0.8,
        orientation_margin: 0.8,
        ..RelaxedConfig::default()
    }
}

/// The five variants: standard and relaxed, default and literal, and the
/// relaxed controller's paper arc with the default funnelling settings.
#[must_use]
pub fn variants() -> [Variant; 5] {
    let d = FunnelConfig::default();
    let l = literal_config();
    let r = RelaxedConfig::default();
    let rl = literal_relaxed_config();
    [
        Variant {
            name: "standard",
            controller: Controller::Standard(d),
        },
        Variant {
            name: "standard-literal",
            controller: Controller::Standard(l),
        },
        Variant {
            name: "relaxed",
            controller: Controller::Relaxed(d, r),
        },
        Variant {
            name: "relaxed-literal",
            controller: Controller::Relaxed(l, rl),
        },
        Variant {
            name: "relaxed-paper-arc",
            controller: Controller::Relaxed(
                d,
                RelaxedConfig {
                    aim: RelaxedAim::PaperArc,
                    ..r
                },
            ),
        },
    ]
}

/// One sampled scenario: a start state and a goal queue.
#[derive(Clone, Debug, PartialEq)]
pub struct EnvScenario {
    /// Family.
    pub kind: GoalKind,
    /// Index in the family.
    pub index: usize,
    /// Start state.
    pub start: VehicleState,
    /// Goal queue (one goal, or three for a chain).
    pub goals: Vec<GoalSpec>,
}

/// The study's settings.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct EnvelopeStudy {
    /// Seed of the sample.
    pub seed: u64,
    /// Static scenarios per variant.
    pub n_static: usize,
    /// Moving-goal scenarios per variant.
    pub n_moving: usize,
    /// Chains per variant.
    pub n_chain: usize,
    /// Time limit per goal, s.
    pub max_time: f32,
}

impl Default for EnvelopeStudy {
    fn default() -> Self {
        Self {
            seed: 1,
            n_static: 2000,
            n_moving: 400,
            n_chain: 400,
            max_time: 150.0,
        }
    }
}

/// Log-uniform in `[lo, hi)`.
fn log_uniform(r: &mut Rng, (lo, hi): (f32, f32)) -> f32 {
    lo * (hi / lo).powf(r.next_f32())
}

fn pick<T: Copy>(r: &mut Rng, xs: &[T]) -> T {
    xs[(r.next_u32() as usize) % xs.len()]
}

/// A random goal at `from + D·(cos, sin)(bearing)` with tolerances and
/// speed drawn from the envelope's sets.
fn random_goal(r: &mut Rng, from: Vec2, d_range: (f32, f32), halting: bool) -> Goal {
    let d = log_uniform(r, d_range);
    let bearing = r.range(-PI, PI);
    Goal {
        pos: from + crate::trig::unit(bearing) * d,
        beta: r.range(-PI, PI),
        d_tol: pick(r, &D_TOLS),
        eps_tol: pick(r, &EPS_TOLS_DEG).to_radians(),
        speed: pick(r, &SPEEDS),
        halting,
    }
}

impl EnvelopeStudy {
    /// Scenarios in `kind`'s group.
    #[must_use]
    pub fn count(&self, kind: GoalKind) -> usize {
        match kind {
            GoalKind::Static => self.n_static,
            GoalKind::Moving => self.n_moving,
            GoalKind::Chain => self.n_chain,
        }
    }

    /// The `i`-th scenario of `kind`'s group; the same for every variant.
    #[must_use]
    pub fn scenario(&self, p: &VehicleParams, kind: GoalKind, i: usize) -> EnvScenario {
        let mut r = Rng::with_stream(self.seed, (kind.stream() << 40) | i as u64);
        let v = r.range(0.0, p.v_max);
        let w = r.range(-1.0, 1.0) * p.omega_limit(v);
        let start = VehicleState::new(Vec2::ZERO, r.range(-PI, PI), v, w);
        let goals = match kind {
            GoalKind::Static => {
                let halting = r.next_f32() < 0.5;
                vec![spec(random_goal(&mut r, start.pos, D_RANGE, halting))]
            }
            GoalKind::Moving => {
                let g = random_goal(&mut r, start.pos, D_RANGE, false);
                let velocity = crate::trig::unit(r.range(-PI, PI)) * r.range(0.0, GOAL_SPEED_MAX);
                vec![GoalSpec {
                    motion: GoalMotion::Linear { velocity },
                    ..spec(g)
                }]
            }
            GoalKind::Chain => {
                let halting = r.next_f32() < 0.5;
                let mut from = start.pos;
                (0..3)
                    .map(|k| {
                        let g = random_goal(&mut r, from, CHAIN_LEG, halting && k == 2);
                        from = g.pos;
                        spec(g)
                    })
                    .collect()
            }
        };
        EnvScenario {
            kind,
            index: i,
            start,
            goals,
        }
    }
}

fn spec(goal: Goal) -> GoalSpec {
    GoalSpec {
        goal,
        motion: GoalMotion::Static,
        switch: SwitchRule::EndOfSteering,
    }
}

/// What one run measured.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize)]
#[serde(rename_all = "camelCase")]
pub struct RunRecord {
    /// Index in its group.
    pub index: usize,
    /// Initial distance to the first goal, m.
    pub d0: f32,
    /// First goal's D_tol, m.
    pub d_tol: f32,
    /// First goal's ε_tol, degrees.
    pub eps_tol_deg: f32,
    /// First goal's desired speed, m/s.
    pub speed: f32,
    /// The last goal halts.
    pub halting: bool,
    /// Started inside the first goal's disk (no entry to judge: such runs
    /// are left out of the oriented-on-entry share and counted apart).
    pub starts_inside: bool,
    /// Entered the first goal's disk.
    pub reached: bool,
    /// Heading within ε_tol of β at the first step inside D_tol.
    pub oriented_on_entry: bool,
    /// |β − θ| at that step, degrees (NaN if never entered).
    pub entry_err_deg: f32,
    /// End_of_Steering declarations (one per goal done).
    pub eos: u32,
    /// Declarations with D < D_tol and |β − θ| < ε_tol at that step (and,
    /// for the last goal of a halting run, a rest pose inside both).
    pub eos_ok: u32,
    /// Halting runs: came to rest with both tolerances met.
    pub rest_ok: bool,
    /// Halting runs: distance and heading error at rest, m and degrees.
    pub rest_err: (f32, f32),
    /// Every goal done within the time limit.
    pub finished: bool,
    /// Path length until the last goal was done (or the limit), m.
    pub length: f32,
    /// Dubins length through the goal poses (radius at each goal's
    /// desired speed; moving goals where they were when done), m.
    pub dubins: f32,
    /// Steps with a non-finite value.
    pub nan: u32,
    /// Steps with a violated limit (includes the non-finite ones).
    pub violations: u32,
    /// Never entered the first goal's disk, still moving at the limit.
    pub orbit: bool,
    /// Time to finish, s (the limit if not finished).
    pub time: f32,
}

/// Runs one scenario with one controller.
#[must_use]
pub fn run(
    table: &EtaTable,
    p: &VehicleParams,
    ctl: &Controller,
    sc: &EnvScenario,
    max_time: f32,
) -> RunRecord {
    let (cfg, kind, rcfg) = match *ctl {
        Controller::Standard(f) => (f, ControllerKind::Standard, RelaxedConfig::default()),
        Controller::Relaxed(f, r) => (f, ControllerKind::Relaxed, r),
    };
    let first = sc.goals[0].goal;
    let last = sc.goals[sc.goals.len() - 1].goal;
    let mut rec = RunRecord {
        index: sc.index,
        d0: (first.pos - sc.start.pos).length(),
        d_tol: first.d_tol,
        eps_tol_deg: first.eps_tol.to_degrees(),
        speed: first.speed,
        halting: last.halting,
        starts_inside: (first.pos - sc.start.pos).length() < first.d_tol,
        entry_err_deg: f32::NAN,
        rest_err: (f32::NAN, f32::NAN),
        ..Default::default()
    };
    // Sampled scenarios are valid by construction; an invalid one would be
    // a bug in the sampler, reported as a run that never finishes.
    let Ok(mut w) = World::new(*p, cfg) else {
        return rec;
    };
    if w.set_controller(kind, rcfg).is_err() || w.add_agent(sc.start, sc.goals.clone()).is_err() {
        return rec;
    }
    // A goal moving away at 0.4 m/s from a vehicle asked for 0.5 m/s closes
    // at 0.1 m/s: 50 m take 500 s whatever the controller. Moving goals get
    // the time to close the initial distance at the speed difference on
    // top of the limit, so an unfinished run is the controller's doing.
    let chase = match sc.goals[0].motion {
        GoalMotion::Linear { velocity } => rec.d0 / (first.speed - velocity.length()).max(0.05),
        _ => 0.0,
    };
    let limit = ((max_time * sc.goals.len() as f32 + chase) / p.dt) as u32;
    let rest_limit = (REST_TIME / p.dt) as u32;
    let mut done_at: Option<u32> = None;
    let mut last_eos_ok = false;
    let mut dubins_from = (sc.start.pos.x, sc.start.pos.y, sc.start.theta);
    for k in 0..limit + rest_limit {
        let prev = w.agents[0].state;
        let cur = w.agents[0].current;
        if done_at.is_none() && k >= limit {
            break;
        }
        w.step(table);
        let a = &w.agents[0];
        if !a.state.pos.is_finite() || !a.state.theta.is_finite() || !a.state.v.is_finite() {
            rec.nan += 1;
        }
        if done_at.is_some() {
            if a.state.v == 0.0 && a.state.omega.abs() < 1e-3 {
                break;
            }
            continue;
        }
        let g = a.goal_now;
        let d = (g.pos - prev.pos).length();
        let err = diff(g.beta, prev.theta).abs();
        if cur == 0 && !rec.reached && d < g.d_tol {
            rec.reached = true;
            rec.entry_err_deg = err.to_degrees();
            rec.oriented_on_entry = err < g.eps_tol;
        }
        if a.current > cur && a.internals.mode == Mode::EndOfSteering {
            rec.eos += 1;
            last_eos_ok = d < g.d_tol && err < g.eps_tol;
            if last_eos_ok {
                rec.eos_ok += 1;
            }
            let to = (g.pos.x, g.pos.y, g.beta);
            rec.dubins += dubins::shortest_length(dubins_from, to, p.min_turn_radius(g.speed));
            dubins_from = to;
        }
        if a.done() {
            done_at = Some(k);
            rec.finished = true;
            rec.time = k as f32 * p.dt;
            rec.length = a.metrics.length;
            if !last.halting {
                break;
            }
        }
    }
    let a = &w.agents[0];
    rec.violations = a.metrics.violations;
    if !rec.finished {
        rec.time = limit as f32 * p.dt;
        rec.length = a.metrics.length;
        rec.orbit = !rec.reached && a.state.v > 0.05;
    }
    if last.halting && rec.finished {
        let g = a.goal_now;
        let d = (g.pos - a.state.pos).length();
        let e = diff(g.beta, a.state.theta).abs();
        rec.rest_err = (d, e.to_degrees());
        rec.rest_ok = a.state.v == 0.0 && d < g.d_tol && e < g.eps_tol;
        // A halting goal's End_of_Steering promised this rest pose too.
        if last_eos_ok && !rec.rest_ok {
            rec.eos_ok -= 1;
        }
    }
    rec
}

/// Summary of a set of runs (a group, a cell).
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize)]
#[serde(rename_all = "camelCase")]
pub struct CellSummary {
    /// Runs.
    pub n: usize,
    /// Share entering the first disk.
    pub reach: f32,
    /// Runs that started inside the first disk.
    pub n_inside: usize,
    /// Share oriented on entry, of the runs that started outside.
    pub oriented: f32,
    /// Entry error median and p90, degrees (runs that entered).
    pub entry_err_deg: (f32, f32),
    /// Share of End_of_Steering declarations with both tolerances met.
    pub eos_ok: f32,
    /// Halting runs.
    pub n_halting: usize,
    /// Share of halting runs at rest inside both tolerances.
    pub rest_ok: f32,
    /// Share finishing every goal.
    pub finished: f32,
    /// Path length / Dubins, median and p90 (finished runs).
    pub length_ratio: (f32, f32),
    /// Steps with non-finite values, all runs.
    pub nan: u32,
    /// Steps with limit violations, all runs.
    pub violations: u32,
    /// Runs that never entered and were still moving at the limit.
    pub orbits: usize,
}

/// Summarises `runs`.
#[must_use]
pub fn summarise<'a>(runs: impl IntoIterator<Item = &'a RunRecord>) -> CellSummary {
    let runs: Vec<&RunRecord> = runs.into_iter().collect();
    let n = runs.len();
    let share = |k: usize, of: usize| {
        if of == 0 {
            f32::NAN
        } else {
            k as f32 / of as f32
        }
    };
    let outside: Vec<&&RunRecord> = runs.iter().filter(|r| !r.starts_inside).collect();
    let mut entry: Vec<f32> = outside
        .iter()
        .filter(|r| r.reached)
        .map(|r| r.entry_err_deg)
        .collect();
    let mut ratio: Vec<f32> = runs
        .iter()
        .filter(|r| r.finished && r.dubins > 1e-3)
        .map(|r| r.length / r.dubins)
        .collect();
    let halting: Vec<&&RunRecord> = runs.iter().filter(|r| r.halting).collect();
    let eos: u32 = runs.iter().map(|r| r.eos).sum();
    let eos_ok: u32 = runs.iter().map(|r| r.eos_ok).sum();
    CellSummary {
        n,
        reach: share(runs.iter().filter(|r| r.reached).count(), n),
        n_inside: n - outside.len(),
        oriented: share(
            outside.iter().filter(|r| r.oriented_on_entry).count(),
            outside.len(),
        ),
        entry_err_deg: (percentile(&mut entry, 0.5), percentile(&mut entry, 0.9)),
        eos_ok: share(eos_ok as usize, eos as usize),
        n_halting: halting.len(),
        rest_ok: share(halting.iter().filter(|r| r.rest_ok).count(), halting.len()),
        finished: share(runs.iter().filter(|r| r.finished).count(), n),
        length_ratio: (percentile(&mut ratio, 0.5), percentile(&mut ratio, 0.9)),
        nan: runs.iter().map(|r| r.nan).sum(),
        violations: runs.iter().map(|r| r.violations).sum(),
        orbits: runs.iter().filter(|r| r.orbit).count(),
    }
}

/// The runs of one variant on one group.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[serde(rename_all = "camelCase")]
pub struct GroupRuns {
    /// Family.
    pub kind: GoalKind,
    /// One record per scenario, in index order.
    pub runs: Vec<RunRecord>,
}

/// Everything one variant measured.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[serde(rename_all = "camelCase")]
pub struct VariantReport {
    /// Variant name.
    pub name: &'static str,
    /// Settings, as text.
    pub settings: String,
    /// Per group.
    pub groups: Vec<GroupRuns>,
}

impl VariantReport {
    /// Runs of `kind`'s group.
    #[must_use]
    pub fn runs(&self, kind: GoalKind) -> &[RunRecord] {
        self.groups
            .iter()
            .find(|g| g.kind == kind)
            .map_or(&[], |g| &g.runs)
    }
}

/// Missed runs kept per variant in the JSON (regenerate any of them with
/// [`EnvelopeStudy::scenario`] from the seed, group and index).
pub const MISSES_KEPT: usize = 5000;

/// The whole study's result.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[serde(rename_all = "camelCase")]
pub struct EnvelopeReport {
    /// Seed of the sample.
    pub seed: u64,
    /// Time limit per goal, s.
    pub max_time: f32,
    /// Per variant.
    pub variants: Vec<VariantReport>,
}

impl EnvelopeStudy {
    /// Runs every group for `variants` on rayon's pool (results do not
    /// depend on its size). Scenarios are
    /// sampled once and shared by the variants.
    #[cfg(not(target_arch = "wasm32"))]
    #[must_use]
    pub fn run_all(
        &self,
        table: &EtaTable,
        p: &VehicleParams,
        variants: &[Variant],
    ) -> EnvelopeReport {
        let scenarios: Vec<Vec<EnvScenario>> = GoalKind::ALL
            .iter()
            .map(|&k| (0..self.count(k)).map(|i| self.scenario(p, k, i)).collect())
            .collect();
        let jobs: Vec<(usize, &EnvScenario)> = (0..variants.len())
            .flat_map(|v| scenarios.iter().flatten().map(move |s| (v, s)))
            .collect();
        let records = crate::base::parallel::map_indices(jobs.len(), |j| {
            let (v, sc) = jobs[j];
            run(table, p, &variants[v].controller, sc, self.max_time)
        });
        let mut it = records.into_iter();
        let variants = variants
            .iter()
            .map(|v| VariantReport {
                name: v.name,
                settings: format!("{:?}", v.controller),
                groups: GoalKind::ALL
                    .iter()
                    .map(|&kind| GroupRuns {
                        kind,
                        runs: it.by_ref().take(self.count(kind)).collect(),
                    })
                    .collect(),
            })
            .collect();
        EnvelopeReport {
            seed: self.seed,
            max_time: self.max_time,
            variants,
        }
    }
}

/// The static cells of `runs` in distance band `band` (`None`: all D):
/// (ε_tol in degrees, column, column value, summary) for every ε_tol ×
/// D_tol and ε_tol × desired-speed cell, in that order.
fn static_cells(
    runs: &[RunRecord],
    band: Option<usize>,
) -> Vec<(f32, &'static str, f32, CellSummary)> {
    type Column = (&'static str, &'static [f32], fn(&RunRecord) -> f32);
    let columns: [Column; 2] = [
        ("dTol", &D_TOLS, |r| r.d_tol),
        ("speed", &SPEEDS, |r| r.speed),
    ];
    let mut out = Vec::new();
    for e in EPS_TOLS_DEG {
        for (key, values, f) in columns {
            for &c in values {
                let sum = summarise(runs.iter().filter(|r| {
                    band.is_none_or(|b| band_of(r.d0) == b)
                        && r.eps_tol_deg.round() == e
                        && f(r) == c
                }));
                out.push((e, key, c, sum));
            }
        }
    }
    out
}

fn band_of(d: f32) -> usize {
    BANDS
        .iter()
        .position(|&(_, hi)| d < hi)
        .unwrap_or(BANDS.len() - 1)
}

fn pct(x: f32) -> String {
    if x.is_nan() {
        "—".into()
    } else {
        format!("{:.1}", 100.0 * x)
    }
}

/// The summary row of a group, markdown.
fn summary_row(name: &str, kind: GoalKind, s: &CellSummary) -> String {
    format!(
        "| {name} | {} | {} ({} inside) | {} % | {} % | {:.1} / {:.1} | {} % | {} % ({}) | {} % | {:.3} / {:.3} | {} | {} | {} |",
        kind.name(),
        s.n,
        s.n_inside,
        pct(s.reach),
        pct(s.oriented),
        s.entry_err_deg.0,
        s.entry_err_deg.1,
        pct(s.eos_ok),
        pct(s.rest_ok),
        s.n_halting,
        pct(s.finished),
        s.length_ratio.0,
        s.length_ratio.1,
        s.nan,
        s.violations,
        s.orbits
    )
}

const SUMMARY_HEAD: &str = "| variant | group | n | reach | oriented on entry (of runs starting outside) | entry err med / p90 (°) | EoS in both tol | halting at rest in both tol (n) | finished | length/Dubins med / p90 | NaN | violations | orbits |\n|---|---|---|---|---|---|---|---|---|---|---|---|---|";

/// Oriented-on-entry matrix of static runs in `band` (`None`: all D):
/// rows ε_tol, columns from `col` (D_tol or desired speed).
fn matrix(
    runs: &[RunRecord],
    band: Option<usize>,
    col_name: &str,
    cols: &[f32],
    col: fn(&RunRecord) -> f32,
) -> String {
    let mut s = format!("| ε_tol \\ {col_name} |");
    for c in cols {
        let _ = write!(s, " {c} |");
    }
    s.push_str(" all |\n|---|");
    for _ in 0..=cols.len() {
        s.push_str("---|");
    }
    s.push('\n');
    let in_band = |r: &&RunRecord| band.is_none_or(|b| band_of(r.d0) == b);
    let cell = |f: &dyn Fn(&RunRecord) -> bool| {
        let c = summarise(runs.iter().filter(in_band).filter(|r| f(r)));
        format!(" {} ({}) |", pct(c.oriented), c.n - c.n_inside)
    };
    for e in EPS_TOLS_DEG {
        let _ = write!(s, "| {e}° |");
        for &c in cols {
            s.push_str(&cell(&|r| r.eps_tol_deg.round() == e && col(r) == c));
        }
        s.push_str(&cell(&|r| r.eps_tol_deg.round() == e));
        s.push('\n');
    }
    s.push_str("| all |");
    for &c in cols {
        s.push_str(&cell(&|r| col(r) == c));
    }
    s.push_str(&cell(&|_| true));
    s.push('\n');
    s
}

impl EnvelopeReport {
    /// The tables, markdown: one summary row per variant and group, then
    /// for each variant named in `detail` the oriented-on-entry share of
    /// the static group per cell (percent, with the run count): ε_tol ×
    /// D_tol and ε_tol × desired speed, for each distance band and all D.
    #[must_use]
    pub fn tables(&self, detail: &[&str]) -> String {
        let mut s = String::new();
        let _ = writeln!(
            s,
            "envelope study: seed {}, limit {} s per goal",
            self.seed, self.max_time
        );
        s.push_str(SUMMARY_HEAD);
        s.push('\n');
        for v in &self.variants {
            for g in &v.groups {
                s.push_str(&summary_row(v.name, g.kind, &summarise(&g.runs)));
                s.push('\n');
            }
        }
        for v in self.variants.iter().filter(|v| detail.contains(&v.name)) {
            let runs = v.runs(GoalKind::Static);
            let bands = BANDS
                .iter()
                .enumerate()
                .map(|(i, &(lo, hi))| (Some(i), format!("D {lo}–{hi} m")))
                .chain(core::iter::once((None, "all D".to_string())));
            for (band, label) in bands {
                let _ = writeln!(
                    s,
                    "\n{}, static, {label}: oriented on entry, % (runs)",
                    v.name
                );
                s.push_str(&matrix(runs, band, "D_tol (m)", &D_TOLS, |r| r.d_tol));
                s.push('\n');
                s.push_str(&matrix(runs, band, "v_d (m/s)", &SPEEDS, |r| r.speed));
            }
        }
        s
    }

    /// The worst cell of `variant`'s static runs in distance band `band`
    /// (`None`: all D) whose ε_tol satisfies `eps`: (share oriented on
    /// entry, label), over the ε_tol × D_tol and ε_tol × speed cells.
    #[must_use]
    pub fn worst_cell(
        &self,
        variant: &str,
        band: Option<usize>,
        eps: fn(f32) -> bool,
    ) -> (f32, String) {
        let Some(v) = self.variants.iter().find(|v| v.name == variant) else {
            return (f32::NAN, String::new());
        };
        let mut worst = (f32::INFINITY, String::new());
        for (e, key, c, sum) in static_cells(v.runs(GoalKind::Static), band) {
            if eps(e) && sum.oriented < worst.0 {
                worst = (
                    sum.oriented,
                    format!("ε_tol {e}°, {key} {c} ({} runs)", sum.n - sum.n_inside),
                );
            }
        }
        worst
    }

    /// The issue-13 targets against this report, markdown (standard =
    /// `standard`, relaxed = `relaxed`).
    #[must_use]
    pub fn targets(&self) -> String {
        let get = |name: &str, kind: GoalKind| {
            self.variants
                .iter()
                .find(|v| v.name == name)
                .map(|v| summarise(v.runs(kind)))
                .unwrap_or_default()
        };
        let far = Some(BANDS.len() - 1);
        let mut s = String::from("| target | measured | goal | met |\n|---|---|---|---|\n");
        let mut row = |what: &str, val: String, goal: &str, ok: bool| {
            let _ = writeln!(
                s,
                "| {what} | {val} | {goal} | {} |",
                if ok { "yes" } else { "NO" }
            );
        };
        let (w5, c5) = self.worst_cell("standard", far, |e| e >= 5.0);
        row(
            "standard, oriented on entry, D ≥ 5 m, worst cell ε_tol ≥ 5°",
            format!("{} % ({c5})", pct(w5)),
            "≥ 95 %",
            w5 >= 0.95,
        );
        let (w2, c2) = self.worst_cell("standard", far, |e| e < 5.0);
        row(
            "standard, oriented on entry, D ≥ 5 m, worst cell ε_tol 2°",
            format!("{} % ({c2})", pct(w2)),
            "≥ 90 %",
            w2 >= 0.9,
        );
        let st = get("standard", GoalKind::Static);
        row(
            "standard, oriented on entry, all D",
            format!("{} %", pct(st.oriented)),
            "≥ 80 %",
            st.oriented >= 0.8,
        );
        // End_of_Steering, static goals (single and chained) apart from
        // moving ones, whose met position is latched (FunnelMemory).
        let (mut eos, mut eos_ok, mut rest, mut nh) = ([0.0f32; 2], [0.0f32; 2], 0.0, 0.0);
        let ours = ["standard", "relaxed"];
        for v in self.variants.iter().filter(|v| ours.contains(&v.name)) {
            for g in &v.groups {
                let c = summarise(&g.runs);
                let k = g.runs.iter().map(|r| r.eos).sum::<u32>() as f32;
                let m = usize::from(g.kind == GoalKind::Moving);
                eos[m] += k;
                eos_ok[m] += c.eos_ok * k;
                if c.n_halting > 0 {
                    rest += c.rest_ok * c.n_halting as f32;
                    nh += c.n_halting as f32;
                }
            }
        }
        row(
            "End_of_Steering with both tolerances met (standard and relaxed; static and chained goals)",
            format!("{} %", pct(eos_ok[0] / eos[0])),
            "≥ 99.5 %",
            eos_ok[0] / eos[0] >= 0.995,
        );
        row(
            "same, moving goals (met position latched: the disk may move off while the vehicle turns)",
            format!("{} %", pct(eos_ok[1] / eos[1])),
            "≥ 99.5 %",
            eos_ok[1] / eos[1] >= 0.995,
        );
        row(
            "halting: rest pose inside both tolerances (standard and relaxed)",
            format!("{} % of {nh}", pct(rest / nh)),
            "100 %",
            rest >= nh,
        );
        let rx = get("relaxed", GoalKind::Static);
        row(
            "relaxed reach (enters the disk), orbits",
            format!("{} %, {} orbits", pct(rx.reach), rx.orbits),
            "≥ 99.5 %, 0",
            rx.reach >= 0.995 && rx.orbits == 0,
        );
        // Relaxed against standard, cell by cell.
        let mut worse = Vec::new();
        if let (Some(a), Some(b)) = (
            self.variants.iter().find(|v| v.name == "relaxed"),
            self.variants.iter().find(|v| v.name == "standard"),
        ) {
            let (ra, rb) = (a.runs(GoalKind::Static), b.runs(GoalKind::Static));
            for (bd, &(lo, hi)) in BANDS.iter().enumerate() {
                for e in EPS_TOLS_DEG {
                    for dt in D_TOLS {
                        let f = |r: &&RunRecord| {
                            band_of(r.d0) == bd && r.eps_tol_deg.round() == e && r.d_tol == dt
                        };
                        let (x, y) = (
                            summarise(ra.iter().filter(f)),
                            summarise(rb.iter().filter(f)),
                        );
                        if x.oriented < y.oriented {
                            worse.push(format!(
                                "D {lo}–{hi} m, ε {e}°, D_tol {dt}: {} vs {}",
                                pct(x.oriented),
                                pct(y.oriented)
                            ));
                        }
                    }
                }
            }
        }
        row(
            "relaxed, oriented on entry, cells below standard (band × ε_tol × D_tol)",
            format!(
                "{} of {} {}",
                worse.len(),
                BANDS.len() * 25,
                worse.join("; ")
            ),
            "0",
            worse.is_empty(),
        );
        for name in ["standard", "relaxed"] {
            for kind in [GoalKind::Moving, GoalKind::Chain] {
                let c = get(name, kind);
                row(
                    &format!("{name}, {} finish", kind.name()),
                    format!("{} %", pct(c.finished)),
                    "≥ 99 %",
                    c.finished >= 0.99,
                );
            }
        }
        row(
            "standard, static: length / Dubins median (p90)",
            format!("{:.3} ({:.3})", st.length_ratio.0, st.length_ratio.1),
            "≤ 1.15",
            st.length_ratio.0 <= 1.15,
        );
        let (nan, viol): (u32, u32) = self
            .variants
            .iter()
            .flat_map(|v| &v.groups)
            .flat_map(|g| &g.runs)
            .fold((0, 0), |(a, b), r| (a + r.nan, b + r.violations));
        row(
            "NaN, limit violations (all runs)",
            format!("{nan}, {viol}"),
            "0, 0",
            nan == 0 && viol == 0,
        );
        s
    }

    /// The per-cell JSON: every variant's group summaries, and for the
    /// static group one summary per (band, ε_tol, D_tol) and per (band,
    /// ε_tol, speed) cell; plus the records of every run that missed
    /// something (for regression cases).
    #[must_use]
    pub fn to_json(&self) -> serde_json::Value {
        use serde_json::json;
        let variants: Vec<serde_json::Value> = self
            .variants
            .iter()
            .map(|v| {
                let groups: Vec<serde_json::Value> = v
                    .groups
                    .iter()
                    .map(|g| json!({ "group": g.kind, "summary": summarise(&g.runs) }))
                    .collect();
                let runs = v.runs(GoalKind::Static);
                let mut cells = Vec::new();
                for (b, &(lo, hi)) in BANDS.iter().enumerate() {
                    for (e, key, c, sum) in static_cells(runs, Some(b)) {
                        cells.push(json!({
                            "band": [lo, hi], "epsTolDeg": e, key: c, "summary": sum
                        }));
                    }
                }
                let misses: Vec<serde_json::Value> = v
                    .groups
                    .iter()
                    .flat_map(|g| {
                        g.runs
                            .iter()
                            .filter(|r| missed(r))
                            .map(move |r| json!({ "group": g.kind, "run": r }))
                    })
                    .take(MISSES_KEPT)
                    .collect();
                json!({
                    "name": v.name, "settings": v.settings, "groups": groups,
                    "staticCells": cells, "misses": misses
                })
            })
            .collect();
        json!({ "seed": self.seed, "maxTime": self.max_time, "variants": variants })
    }
}

/// A run that missed a target: started outside and not oriented on entry, an End_of_Steering
/// outside a tolerance, a halting rest outside one, not finished, NaN or a
/// violated limit.
#[must_use]
pub fn missed(r: &RunRecord) -> bool {
    (!r.starts_inside && !r.oriented_on_entry)
        || r.eos_ok < r.eos
        || !r.finished
        || (r.halting && !r.rest_ok)
        || r.nan > 0
        || r.violations > 0
}
