//! The envelope study: oriented arrival measured over the whole operating
//! envelope a user of the lab can reach, not at one operating point.
//! [`crate::studies::reach`] samples one point (D_tol 0.25 m, ε_tol 5°,
//! 1.3 m/s, D 1–30 m); settings tuned there do much worse on random
//! targets drawn over the sliders' range, so this is the study the
//! controller is tuned on (seed 1) and judged on (seed 2, held out).
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
//! with the paper's literal reading ([`FunnelConfig::paper_000`],
//! [`RelaxedConfig::paper_001`]). Scenario `i` of a group is the same for every
//! variant (paired comparison). Runs stop at [`EnvelopeStudy::max_time`]
//! per goal.
//!
//! What a run records ([`RunRecord`]): reach (enters the first goal's
//! disk), oriented on entry (heading within ε_tol of β at the first step
//! inside D_tol) and the entry error, End_of_Steering declared with both
//! tolerances met, for halting runs the rest pose inside both tolerances,
//! finished (every goal done), path length over the Dubins length (radius
//! at the desired speed, [`crate::base::dubins`]), non-finite values and limit
//! violations ([`crate::base::metrics`]), and orbits (never enters).
//!
//! | module | what |
//! |---|---|
//! | this one | the sampled envelope, the variants, one run and its record |
//! | [`report`] | per-cell summaries, the runs of every variant, the parallel run |
//! | [`tables`] | markdown tables per cell, the targets, the per-cell JSON |

use core::f32::consts::PI;

use glam::Vec2;
use serde::Serialize;

use crate::base::angle::diff;
use crate::base::dubins;
use crate::base::rng::Rng;
use crate::base::vehicle::{VehicleParams, VehicleState};
use crate::funnelling::config::FunnelConfig;
use crate::funnelling::controller::{Controller, ControllerKind};
use crate::funnelling::goal::Goal;
use crate::funnelling::relaxed::{RelaxedAim, RelaxedConfig};
use crate::funnelling::table::lookup::EtaTable;
use crate::funnelling::table::spec::VehicleScale;
use crate::funnelling::update::Mode;
use crate::world::{goals::GoalMotion, goals::GoalSpec, goals::SwitchRule, World};

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

/// The paper's literal standard funnelling ([`FunnelConfig::paper_000`]:
/// Figs. 4 and 5 as written, nothing of ours added).
#[must_use]
pub fn literal_config() -> FunnelConfig {
    FunnelConfig::paper_000()
}

/// Paper 001 Fig. 7 as written ([`RelaxedConfig::paper_001`]): the relaxed
/// point on the ring arc 𝒜, the whole disk and T searched.
#[must_use]
pub fn literal_relaxed_config() -> RelaxedConfig {
    RelaxedConfig::paper_001()
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
    /// Time limit per goal, s (at scale 1; multiplied by the time scale).
    pub max_time: f32,
    /// The vehicle's scale ([`EnvelopeStudy::for_vehicle`]):
    /// sampled distances and tolerances are multiplied by `scale.length`,
    /// speeds by `scale.speed`. The records keep the pedestrian-equivalent
    /// values (divided back), so the tables' cells are the same for every
    /// vehicle: a D of 13.3 there is 5 turning radii. 1 and 1 for the
    /// pedestrian, whose samples are unchanged.
    pub scale: VehicleScale,
}

impl Default for EnvelopeStudy {
    fn default() -> Self {
        Self {
            seed: 1,
            n_static: 2000,
            n_moving: 400,
            n_chain: 400,
            max_time: 150.0,
            scale: VehicleScale {
                length: 1.0,
                speed: 1.0,
            },
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
fn random_goal(
    r: &mut Rng,
    from: Vec2,
    d_range: (f32, f32),
    halting: bool,
    scale: VehicleScale,
) -> Goal {
    let d = log_uniform(r, d_range) * scale.length;
    let bearing = r.range(-PI, PI);
    Goal {
        pos: from + crate::base::trig::unit(bearing) * d,
        beta: r.range(-PI, PI),
        // A robot's smallest tolerance (0.1 × 0.0625 m) is below the
        // core's D_tol range: run at its minimum (0.01 m).
        d_tol: (pick(r, &D_TOLS) * scale.length).max(crate::base::ranges::GOAL_D_TOL.min as f32),
        eps_tol: pick(r, &EPS_TOLS_DEG).to_radians(),
        speed: pick(r, &SPEEDS) * scale.speed,
        halting,
        vel: Vec2::ZERO,
    }
}

impl EnvelopeStudy {
    /// The default study scaled to vehicle `p` (see [`EnvelopeStudy::scale`]).
    #[must_use]
    pub fn for_vehicle(p: &VehicleParams) -> Self {
        Self {
            scale: VehicleScale::of(p),
            ..Self::default()
        }
    }

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
                vec![spec(random_goal(
                    &mut r, start.pos, D_RANGE, halting, self.scale,
                ))]
            }
            GoalKind::Moving => {
                let g = random_goal(&mut r, start.pos, D_RANGE, false, self.scale);
                let velocity = crate::base::trig::unit(r.range(-PI, PI))
                    * (r.range(0.0, GOAL_SPEED_MAX) * self.scale.speed);
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
                        let g = random_goal(&mut r, from, CHAIN_LEG, halting && k == 2, self.scale);
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

pub mod report;
pub mod tables;
