//! The avoidance benchmarks and the seeded study behind
//! `steer avoid`: each scenario is built from a seed (small jitter of the
//! start poses), run once per method on the same seed, and measured
//! ([`crate::world::proximity`]); path lengths are compared with the
//! avoidance-free run of the same seed.
//!
//! - **circle swap**: N agents on a circle (spaced 2.5 body diameters
//!   along it), each to the antipodal point, arriving facing outward
//!   (ε_tol 10°, D_tol 0.3 m, halting);
//! - **corridor**: two groups of 12 crossing each other in a corridor 4 m
//!   wide (walls as segments);
//! - **doorway**: 10 agents through a gap of two body diameters in a wall;
//! - **paper 000 Fig. 6 and Fig. 8** with avoidance on (the presets).

use core::f32::consts::{PI, TAU};

use crate::avoidance::config::{AvoidanceConfig, AvoidanceMethod, Obstacle};
use crate::base::rng::Rng;
use crate::base::vehicle::VehicleParams;
use crate::funnelling::config::FunnelConfig;
use crate::funnelling::controller::ControllerKind;
use crate::funnelling::relaxed::RelaxedConfig;
use crate::funnelling::table::lookup::EtaTable;
use crate::world::proximity::Proximity;
use crate::world::scenario::{AgentSpec, GoalFile, Scenario};
use crate::world::{goals::GoalMotion, goals::SwitchRule};

/// Body radius used by the benchmarks, m.
pub const BODY_RADIUS: f32 = 0.3;

/// One benchmark.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Bench {
    /// Antipodal circle swap of N agents.
    CircleSwap(usize),
    /// Two groups crossing in a corridor.
    Corridor,
    /// A doorway two body diameters wide.
    Doorway,
    /// Paper 000 Fig. 6 (face to face).
    Fig6,
    /// Paper 000 Fig. 8 (80 agents, 5 targets).
    Fig8,
}

impl Bench {
    /// Every benchmark, in the order `steer avoid` reports them.
    pub const ALL: [Bench; 7] = [
        Bench::CircleSwap(8),
        Bench::CircleSwap(32),
        Bench::CircleSwap(100),
        Bench::Corridor,
        Bench::Doorway,
        Bench::Fig6,
        Bench::Fig8,
    ];

    /// Short name (`circle32`, `corridor`, …): the preset file's suffix.
    #[must_use]
    pub fn name(self) -> String {
        match self {
            Bench::CircleSwap(n) => format!("circle{n}"),
            Bench::Corridor => "corridor".into(),
            Bench::Doorway => "doorway".into(),
            Bench::Fig6 => "fig6".into(),
            Bench::Fig8 => "fig8".into(),
        }
    }

    /// True when the seed changes the scenario (the paper figures are fixed).
    #[must_use]
    pub fn seeded(self) -> bool {
        !matches!(self, Bench::Fig6 | Bench::Fig8)
    }

    /// The scenario for `seed` with `method` (default settings, radius
    /// [`BODY_RADIUS`]).
    #[must_use]
    pub fn scenario(self, seed: u64, method: AvoidanceMethod) -> Scenario {
        let mut sc = match self {
            Bench::CircleSwap(n) => circle_swap(n, seed),
            Bench::Corridor => corridor(seed),
            Bench::Doorway => doorway(seed),
            Bench::Fig6 => paper(include_str!("../../scenarios/p000_fig6_face_to_face.json")),
            Bench::Fig8 => paper(include_str!("../../scenarios/p000_fig8_eighty.json")),
        };
        sc.avoidance = AvoidanceConfig {
            method,
            radius: BODY_RADIUS,
            ..AvoidanceConfig::default()
        };
        sc
    }
}

fn paper(json: &str) -> Scenario {
    Scenario::from_json(json).expect("the paper presets are valid")
}

fn empty(name: String, description: &str, duration: f32) -> Scenario {
    Scenario {
        name,
        description: description.into(),
        source: "avoidance benchmark".into(),
        duration,
        vehicle: VehicleParams::default(),
        reading: None,
        funnel: FunnelConfig::default(),
        controller: ControllerKind::Standard,
        relaxed: RelaxedConfig::default(),
        avoidance: AvoidanceConfig::default(),
        obstacles: Vec::new(),
        agents: Vec::new(),
        claim: String::new(),
        measured: String::new(),
        table: None,
    }
}

fn goal(x: f32, y: f32, beta: f32) -> GoalFile {
    GoalFile {
        x,
        y,
        beta_deg: beta.to_degrees(),
        d_tol: 0.3,
        eps_tol_deg: 10.0,
        speed: 1.3,
        halting: true,
        switch: SwitchRule::EndOfSteering,
        motion: GoalMotion::Static,
    }
}

fn agent(x: f32, y: f32, theta: f32, g: GoalFile) -> AgentSpec {
    AgentSpec {
        x,
        y,
        theta_deg: theta.to_degrees(),
        v: 0.0,
        omega: 0.0,
        goals: vec![g],
    }
}

/// Circle radius of the swap: 2.5 body diameters of arc per agent, at
/// least 4 m.
#[must_use]
pub fn circle_radius(n: usize) -> f32 {
    (n as f32 * 2.5 * 2.0 * BODY_RADIUS / TAU).max(4.0)
}

/// The antipodal circle swap: agent i at angle 2πi/N (jittered by up to a
/// tenth of the spacing and 5 cm radially), facing the centre, to the
/// antipodal point, arriving facing outward.
#[must_use]
pub fn circle_swap(n: usize, seed: u64) -> Scenario {
    let mut rng = Rng::with_stream(seed, 18);
    let r = circle_radius(n);
    let mut sc = empty(
        format!("avoid_circle{n}"),
        "Antipodal circle swap: each agent to the opposite point of the circle, arriving facing outward.",
        30.0 + 2.0 * r / 1.3 * 2.0,
    );
    for i in 0..n {
        let phi = TAU * (i as f32 + rng.range(-0.1, 0.1)) / n as f32;
        let ri = r + rng.range(-0.05, 0.05);
        let u = crate::base::trig::unit(phi);
        let (x, y) = (ri * u.x, ri * u.y);
        let out = crate::base::angle::wrap(phi + PI);
        sc.agents
            .push(agent(x, y, out, goal(-r * u.x, -r * u.y, out)));
    }
    sc
}

/// Two groups of 12 (3 × 4 on a jittered 1 m lattice) crossing each
/// other in a corridor 4 m wide and 12 m long, from an open space at one end to
/// one at the other, arriving facing along the corridor. Each group keeps
/// its formation translated (its front column goes deepest) on a 2 m
/// lattice of targets: with targets 1 m apart the first arrivals would
/// halt in a wall across the corridor that the rest of their own group
/// cannot pass, a blockage of the layout for any controller without a
/// path planner, not an avoidance deadlock.
#[must_use]
pub fn corridor(seed: u64) -> Scenario {
    let mut rng = Rng::with_stream(seed, 19);
    let mut sc = empty(
        "avoid_corridor".into(),
        "Two groups of 12 crossing each other in a corridor 4 m wide.",
        90.0,
    );
    sc.obstacles = vec![
        Obstacle::Segment {
            x1: -6.0,
            y1: 2.0,
            x2: 6.0,
            y2: 2.0,
        },
        Obstacle::Segment {
            x1: -6.0,
            y1: -2.0,
            x2: 6.0,
            y2: -2.0,
        },
    ];
    for side in [-1.0f32, 1.0] {
        for c in 0..3 {
            for row in 0..4 {
                let x = side * (7.0 + c as f32) + rng.range(-0.1, 0.1);
                let y = -1.5 + row as f32 + rng.range(-0.1, 0.1);
                let heading = if side < 0.0 { 0.0 } else { PI };
                let gx = -side * (8.0 + 2.0 * (2 - c) as f32);
                let gy = -3.0 + 2.0 * row as f32;
                sc.agents.push(agent(x, y, heading, goal(gx, gy, heading)));
            }
        }
    }
    sc
}

/// Ten agents (2 × 5 on a jittered 1 m lattice) behind a wall at x = 0
/// with a gap of two body diameters, to a 2 × 5 lattice of targets 2 m
/// apart beyond it, arriving facing +x.
#[must_use]
pub fn doorway(seed: u64) -> Scenario {
    let mut rng = Rng::with_stream(seed, 20);
    let mut sc = empty(
        "avoid_doorway".into(),
        "Ten agents through a doorway two body diameters wide.",
        120.0,
    );
    let half = 2.0 * BODY_RADIUS;
    sc.obstacles = vec![
        Obstacle::Segment {
            x1: 0.0,
            y1: half,
            x2: 0.0,
            y2: 10.0,
        },
        Obstacle::Segment {
            x1: 0.0,
            y1: -10.0,
            x2: 0.0,
            y2: -half,
        },
    ];
    for c in 0..2 {
        for row in 0..5 {
            let x = -4.0 - c as f32 + rng.range(-0.1, 0.1);
            let y = -2.0 + row as f32 + rng.range(-0.1, 0.1);
            // Targets on a 2 m lattice (an agent passes between two that
            // have halted), the front column deepest.
            let gx = 4.0 + 2.0 * (1 - c) as f32;
            let gy = -4.0 + 2.0 * row as f32;
            // Funnelling plans no path: the doorway is a waypoint, entered
            // facing through it (switch on the position tolerance).
            let door = GoalFile {
                d_tol: 0.5,
                eps_tol_deg: 20.0,
                halting: false,
                switch: SwitchRule::Tolerance,
                ..goal(1.0, 0.0, 0.0)
            };
            let mut a = agent(x, y, 0.0, door);
            a.goals.push(goal(gx, gy, 0.0));
            sc.agents.push(a);
        }
    }
    sc
}

/// What one run measured.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct RunReport {
    /// Agents.
    pub agents: usize,
    /// Agents that completed every goal.
    pub reached: usize,
    /// Goal entries judged and, of those, oriented (|θ − β| ≤ ε_tol).
    pub entries: u32,
    /// Oriented entries.
    pub oriented: u32,
    /// Time the last agent finished, s (None when one did not).
    pub finish_time: Option<f32>,
    /// Σ path length, m.
    pub path_length: f32,
    /// Smallest centre distance between two agents, m.
    pub min_distance: f32,
    /// Σ over steps of overlapping pairs.
    pub overlap_pair_steps: u64,
    /// Most pairs overlapping at once.
    pub max_overlapping: u64,
    /// Agent-steps closer than one radius to an obstacle.
    pub obstacle_contacts: u64,
    /// Agents deadlocked.
    pub deadlocks: usize,
    /// Steps breaking a vehicle limit (all agents).
    pub violations: u64,
    /// Agents with a non-finite state at the end.
    pub nan: usize,
    /// Steps in which the avoidance changed an agent's plan (agent-steps).
    pub active_steps: u64,
}

/// Runs `sc` for its duration, or until every agent has finished and
/// rested for one second.
#[must_use]
pub fn run(sc: &Scenario, table: &EtaTable) -> RunReport {
    let mut w = sc.world().expect("benchmark scenarios are valid");
    w.plan(table).expect("the table is built for these limits");
    let mut prox = Proximity::new(sc.avoidance.radius);
    let mut active = 0u64;
    let mut rest = 0u32;
    let rest_steps = (1.0 / sc.vehicle.dt).round() as u32;
    for _ in 0..sc.steps() {
        w.step(table).expect("the table is built for these limits");
        prox.observe(&w);
        active += w.avoider().commands.iter().filter(|c| c.active).count() as u64;
        if w.agents().iter().all(|a| a.done() && a.state.v == 0.0) {
            rest += 1;
            if rest >= rest_steps {
                break;
            }
        }
    }
    let reached = w.agents().iter().filter(|a| a.done()).count();
    RunReport {
        agents: w.agents().len(),
        reached,
        entries: prox.entries,
        oriented: prox.oriented,
        finish_time: if reached == w.agents().len() {
            Some(
                w.agents()
                    .iter()
                    .filter_map(|a| a.finished_at)
                    .fold(0.0f32, f32::max),
            )
        } else {
            None
        },
        path_length: w.agents().iter().map(|a| a.metrics.length).sum(),
        min_distance: prox.min_distance,
        overlap_pair_steps: prox.overlap_pair_steps,
        max_overlapping: prox.max_overlapping,
        obstacle_contacts: prox.obstacle_contact_steps,
        deadlocks: prox.deadlocks(),
        violations: w
            .agents()
            .iter()
            .map(|a| u64::from(a.metrics.violations))
            .sum(),
        nan: w
            .agents()
            .iter()
            .filter(|a| {
                !(a.state.pos.is_finite() && a.state.theta.is_finite() && a.state.v.is_finite())
            })
            .count(),
        active_steps: active,
    }
}

/// One cell of the study: a benchmark and a method over seeds.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct CellSummary {
    /// Runs.
    pub runs: usize,
    /// Agents over all runs.
    pub agents: usize,
    /// Agents that finished.
    pub reached: usize,
    /// Entries judged / oriented.
    pub entries: u64,
    /// Oriented entries.
    pub oriented: u64,
    /// Runs where every agent finished.
    pub finished_runs: usize,
    /// Median finishing time of the finished runs, s.
    pub median_finish: f32,
    /// Median path length ratio to the avoidance-free run of the same seed.
    pub median_length_ratio: f32,
    /// Worst (largest) length ratio.
    pub max_length_ratio: f32,
    /// Smallest centre distance over all runs, m.
    pub min_distance: f32,
    /// Runs with at least one overlapping pair.
    pub runs_with_overlap: usize,
    /// Σ overlapping pair-steps.
    pub overlap_pair_steps: u64,
    /// Most pairs overlapping at once, over all runs.
    pub max_overlapping: u64,
    /// Σ obstacle contact agent-steps.
    pub obstacle_contacts: u64,
    /// Σ deadlocked agents, and runs with one.
    pub deadlocks: usize,
    /// Runs with a deadlock.
    pub runs_with_deadlock: usize,
    /// Σ limit violations.
    pub violations: u64,
    /// Σ non-finite agents.
    pub nan: usize,
}

/// Summarises runs `r` against the avoidance-free runs `base` of the same
/// seeds.
#[must_use]
pub fn summarise(r: &[RunReport], base: &[RunReport]) -> CellSummary {
    let mut finish: Vec<f32> = r.iter().filter_map(|x| x.finish_time).collect();
    let mut ratio: Vec<f32> = r
        .iter()
        .zip(base)
        .map(|(x, b)| x.path_length / b.path_length.max(1e-6))
        .collect();
    CellSummary {
        runs: r.len(),
        agents: r.iter().map(|x| x.agents).sum(),
        reached: r.iter().map(|x| x.reached).sum(),
        entries: r.iter().map(|x| u64::from(x.entries)).sum(),
        oriented: r.iter().map(|x| u64::from(x.oriented)).sum(),
        finished_runs: finish.len(),
        median_finish: crate::base::metrics::percentile(&mut finish, 0.5),
        max_length_ratio: ratio.iter().copied().fold(f32::NAN, f32::max),
        median_length_ratio: crate::base::metrics::percentile(&mut ratio, 0.5),
        min_distance: r
            .iter()
            .map(|x| x.min_distance)
            .fold(f32::INFINITY, f32::min),
        runs_with_overlap: r.iter().filter(|x| x.overlap_pair_steps > 0).count(),
        overlap_pair_steps: r.iter().map(|x| x.overlap_pair_steps).sum(),
        max_overlapping: r.iter().map(|x| x.max_overlapping).max().unwrap_or(0),
        obstacle_contacts: r.iter().map(|x| x.obstacle_contacts).sum(),
        deadlocks: r.iter().map(|x| x.deadlocks).sum(),
        runs_with_deadlock: r.iter().filter(|x| x.deadlocks > 0).count(),
        violations: r.iter().map(|x| x.violations).sum(),
        nan: r.iter().map(|x| x.nan).sum(),
    }
}

/// Runs `bench` with every method over `seeds` seeds from `seed0`
/// (the paper figures once), in parallel, each agent planning its
/// avoidance every `replan_every` steps
/// ([`AvoidanceConfig::replan_every`]), and summarises each method
/// against `off`.
#[must_use]
pub fn study(
    bench: Bench,
    seeds: usize,
    seed0: u64,
    table: &EtaTable,
    replan_every: u32,
) -> Vec<(AvoidanceMethod, CellSummary)> {
    let n = if bench.seeded() { seeds } else { 1 };
    let methods = [
        AvoidanceMethod::Off,
        AvoidanceMethod::Separation,
        AvoidanceMethod::Orca,
    ];
    let all = crate::base::parallel::map_indices(n * methods.len(), |k| {
        let (s, m) = (k / methods.len(), methods[k % methods.len()]);
        let mut sc = bench.scenario(seed0 + s as u64, m);
        sc.avoidance.replan_every = replan_every;
        run(&sc, table)
    });
    let per = |m: usize| -> Vec<RunReport> {
        all.iter().skip(m).step_by(methods.len()).copied().collect()
    };
    let base = per(0);
    methods
        .iter()
        .enumerate()
        .map(|(k, &m)| (m, summarise(&per(k), &base)))
        .collect()
}
