//! The native peers of the figures report's Peers section, shared by
//! `tests/peers_avoidance.rs`, `tests/peers_dubins.rs` and
//! `benches/peers.rs` (included with `#[path]`: the wasm tests, which use
//! `tests/common/mod.rs`, never see the peers, native dev-dependencies):
//!
//! - the version `Cargo.lock` pins for a peer, so a record names what ran;
//! - the seeded Dubins queries, and dubins_paths' answer to one;
//! - dodgy_2d (ORCA, a Rust port of RVO2) run on our avoidance benchmarks
//!   ([`steering::studies::avoidance::Bench`]) with the scenario's radius,
//!   speeds, time step, neighbour reach and count, time horizons and
//!   walls. Its agents are holonomic discs with no heading: each step the
//!   velocity is `Agent::compute_avoiding_velocity`'s answer to a preferred
//!   velocity toward the current goal at the goal's speed (slowed on
//!   arrival as our vehicle brakes, never past the goal in one step), and
//!   the position moves by it. Nothing limits its acceleration or turn rate.
#![allow(dead_code)]

use std::borrow::Cow;

use dodgy_2d::{Agent as PeerAgent, AvoidanceOptions, Obstacle as PeerObstacle};
use glam::Vec2;
use steering::avoidance::config::Obstacle;
use steering::base::grid::NeighbourGrid;
use steering::base::rng::Rng;
use steering::world::scenario::Scenario;

/// The version `Cargo.lock` pins for the package `name` (the first entry of
/// that name).
pub fn locked_version(name: &str) -> String {
    let lock = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/Cargo.lock"))
        .expect("Cargo.lock");
    let mut lines = lock.lines();
    while let Some(l) = lines.next() {
        if l == format!("name = \"{name}\"") {
            if let Some(v) = lines.next().and_then(|v| v.strip_prefix("version = \"")) {
                return v.trim_end_matches('"').to_string();
            }
        }
    }
    panic!("{name} is not in Cargo.lock")
}

/// A seeded query: turning radius log-uniform in [0.1, 100] m; start
/// anywhere in a 200 m square at any heading; the goal at any heading and
/// bearing, half of the queries within 4 R of the start (where the
/// three-arc words win), half between 4 R and 40 R.
pub fn dubins_query(r: &mut Rng) -> ((f32, f32, f32), (f32, f32, f32), f32) {
    let rho = (r.range(0.1f32.ln(), 100f32.ln())).exp();
    let start = (
        r.range(-100.0, 100.0),
        r.range(-100.0, 100.0),
        r.range(-3.15, 3.15),
    );
    let d = if r.below(2) == 0 {
        r.range(0.0, 4.0)
    } else {
        r.range(4.0, 40.0)
    } * rho;
    let bearing = r.range(-3.15, 3.15);
    let goal = (
        start.0 + d * bearing.cos(),
        start.1 + d * bearing.sin(),
        r.range(-3.15, 3.15),
    );
    (start, goal, rho)
}

/// dubins_paths' shortest length (its f64 solve) for the same f32 query.
pub fn peer_length(s: (f32, f32, f32), g: (f32, f32, f32), rho: f32) -> f64 {
    use dubins_paths::f64::{DubinsPath as PeerPath, PosRot};
    let p = |q: (f32, f32, f32)| PosRot::from([f64::from(q.0), f64::from(q.1), f64::from(q.2)]);
    PeerPath::shortest_from(p(s), p(g), f64::from(rho))
        .expect("a forward Dubins path always exists")
        .length()
}

fn v29(v: Vec2) -> dodgy_2d::Vec2 {
    dodgy_2d::Vec2::new(v.x, v.y)
}

fn v34(v: dodgy_2d::Vec2) -> Vec2 {
    Vec2::new(v.x, v.y)
}

/// One goal of a peer agent: where, how near counts, at what speed, and
/// whether it halts there (the last) or is a waypoint passed through.
#[derive(Clone, Copy, Debug)]
struct PeerGoal {
    pos: Vec2,
    d_tol: f32,
    speed: f32,
    halting: bool,
}

/// A benchmark scenario run by dodgy_2d.
#[derive(Clone)]
pub struct PeerWorld {
    /// The agents as dodgy_2d sees them.
    pub agents: Vec<PeerAgent>,
    goals: Vec<Vec<PeerGoal>>,
    current: Vec<usize>,
    /// Time each agent arrived at its last goal (entered its D_tol), s.
    pub arrived_at: Vec<Option<f32>>,
    obstacles: Vec<Cow<'static, PeerObstacle>>,
    options: AvoidanceOptions,
    max_speed: f32,
    brake: f32,
    dt: f32,
    reach: f32,
    max_neighbours: usize,
    /// Simulated time, s.
    pub t: f32,
    grid: NeighbourGrid,
    pos: Vec<f32>,
    near: Vec<(f32, usize)>,
    next: Vec<dodgy_2d::Vec2>,
}

impl PeerWorld {
    /// The scenario's agents, goals and walls, for dodgy_2d: radius the
    /// body radius plus `margin` (0: dodgy_2d's own use; ours avoids with
    /// the scenario's margin added), responsibility shared equally
    /// (reciprocal, as ours), walls kept at that radius (two-vertex closed
    /// obstacles: a segment seen from both sides).
    pub fn new(sc: &Scenario, margin: f32) -> Self {
        let r = sc.avoidance.radius + margin;
        let agents: Vec<PeerAgent> = sc
            .agents
            .iter()
            .map(|a| PeerAgent {
                position: dodgy_2d::Vec2::new(a.x, a.y),
                velocity: dodgy_2d::Vec2::ZERO,
                radius: r,
                avoidance_responsibility: 1.0,
            })
            .collect();
        let goals = sc
            .agents
            .iter()
            .map(|a| {
                a.goals
                    .iter()
                    .map(|g| PeerGoal {
                        pos: Vec2::new(g.x, g.y),
                        d_tol: g.d_tol,
                        speed: g.speed,
                        halting: g.halting,
                    })
                    .collect()
            })
            .collect();
        let obstacles = sc
            .obstacles
            .iter()
            .map(|o| {
                let vertices = match *o {
                    Obstacle::Segment { x1, y1, x2, y2 } => {
                        vec![dodgy_2d::Vec2::new(x1, y1), dodgy_2d::Vec2::new(x2, y2)]
                    }
                    // A disc as the 16-gon around it, counter-clockwise.
                    Obstacle::Disc { x, y, radius } => (0..16)
                        .map(|k| {
                            let a = k as f32 * core::f32::consts::TAU / 16.0;
                            let rr = radius / (core::f32::consts::PI / 16.0).cos();
                            dodgy_2d::Vec2::new(x + rr * a.cos(), y + rr * a.sin())
                        })
                        .collect(),
                };
                Cow::Owned(PeerObstacle::Closed { vertices })
            })
            .collect();
        let n = agents.len();
        Self {
            agents,
            goals,
            current: vec![0; n],
            arrived_at: vec![None; n],
            obstacles,
            options: AvoidanceOptions {
                obstacle_margin: r,
                time_horizon: sc.avoidance.horizon,
                obstacle_time_horizon: sc.avoidance.obstacle_horizon,
            },
            max_speed: sc.vehicle.v_max,
            brake: sc.vehicle.accel_max,
            dt: sc.vehicle.dt,
            reach: sc.avoidance.reach,
            max_neighbours: sc.avoidance.max_neighbours as usize,
            t: 0.0,
            grid: NeighbourGrid::new(),
            pos: Vec::with_capacity(2 * n),
            near: Vec::new(),
            next: vec![dodgy_2d::Vec2::ZERO; n],
        }
    }

    /// The goal agent `i` steers to now (its last once arrived).
    fn goal(&self, i: usize) -> PeerGoal {
        let g = &self.goals[i];
        g[self.current[i].min(g.len() - 1)]
    }

    /// Toward the current goal at its speed; toward a halting goal no
    /// faster than braking at the vehicle's deceleration allows, nor
    /// past the goal in one step.
    fn preferred(&self, i: usize) -> Vec2 {
        let g = self.goal(i);
        let to = g.pos - v34(self.agents[i].position);
        let d = to.length();
        if d < 1e-6 {
            return Vec2::ZERO;
        }
        let mut speed = g.speed;
        if g.halting {
            speed = speed.min((2.0 * self.brake * d).sqrt()).min(d / self.dt);
        }
        to * (speed / d)
    }

    /// One step: every agent's avoiding velocity from the same snapshot
    /// (its nearest `max_neighbours` within `reach`, found by our grid),
    /// then every position moves by its new velocity.
    pub fn step(&mut self) {
        self.pos.clear();
        for a in &self.agents {
            self.pos.extend([a.position.x, a.position.y]);
        }
        self.grid.rebuild(&self.pos, self.reach);
        let mut neighbours: Vec<Cow<'_, PeerAgent>> = Vec::with_capacity(self.max_neighbours);
        for i in 0..self.agents.len() {
            self.near.clear();
            let near = &mut self.near;
            self.grid
                .for_each_neighbour(&self.pos, i, self.reach, |j, _, d2| near.push((d2, j)));
            near.sort_unstable_by(|a, b| a.0.total_cmp(&b.0).then(a.1.cmp(&b.1)));
            near.truncate(self.max_neighbours);
            neighbours.clear();
            neighbours.extend(near.iter().map(|&(_, j)| Cow::Borrowed(&self.agents[j])));
            self.next[i] = self.agents[i].compute_avoiding_velocity(
                &neighbours,
                &self.obstacles,
                v29(self.preferred(i)),
                self.max_speed,
                self.dt,
                &self.options,
            );
        }
        self.t += self.dt;
        for i in 0..self.agents.len() {
            let a = &mut self.agents[i];
            a.velocity = self.next[i];
            a.position += a.velocity * self.dt;
            let g = &self.goals[i];
            let k = self.current[i];
            if k < g.len() && (v34(a.position) - g[k].pos).length() <= g[k].d_tol {
                self.current[i] += 1;
                if self.current[i] == g.len() {
                    self.arrived_at[i] = Some(self.t);
                }
            }
        }
    }
}

/// What one dodgy_2d run measured (as [`steering::studies::avoidance::RunReport`]
/// measures ours).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct PeerRun {
    /// Agents.
    pub agents: usize,
    /// Agents that entered their last goal's D_tol.
    pub reached: usize,
    /// Time the last agent arrived, s (None when one did not).
    pub finish_time: Option<f32>,
    /// Σ path length, m.
    pub path_length: f32,
    /// Smallest centre distance between two agents, m.
    pub min_distance: f32,
    /// Σ over steps of the pairs closer than two radii.
    pub overlap_pair_steps: u64,
    /// Agent-steps closer than one radius to a wall.
    pub obstacle_contacts: u64,
    /// Agent-steps whose change of velocity is more than our vehicle may
    /// make in one step (its forward and normal acceleration limits
    /// together, √(a_max² + A²)).
    pub beyond_limits: u64,
    /// Agent-steps run.
    pub agent_steps: u64,
}

/// Runs `sc` with dodgy_2d (radius plus `margin`, [`PeerWorld::new`]) for its duration, or until every agent has
/// arrived and every one has been slower than 0.05 m/s for one second
/// (ours stops when every agent is done and at rest for one second).
pub fn run(sc: &Scenario, margin: f32) -> PeerRun {
    let mut w = PeerWorld::new(sc, margin);
    let n = w.agents.len();
    let r = sc.avoidance.radius;
    let p = sc.vehicle;
    let max_dv = (p.accel_max.hypot(p.normal_accel_max) * p.dt) * (1.0 + 1e-4);
    let mut out = PeerRun {
        agents: n,
        min_distance: f32::INFINITY,
        ..PeerRun::default()
    };
    let rest_steps = (1.0 / p.dt).round() as u32;
    let mut rest = 0;
    for _ in 0..sc.steps() {
        let before: Vec<(Vec2, Vec2)> = w
            .agents
            .iter()
            .map(|a| (v34(a.position), v34(a.velocity)))
            .collect();
        w.step();
        out.agent_steps += n as u64;
        let mut min2 = out.min_distance * out.min_distance;
        for (i, &(p0, v0)) in before.iter().enumerate() {
            let (pi, vi) = (v34(w.agents[i].position), v34(w.agents[i].velocity));
            out.path_length += (pi - p0).length();
            if (vi - v0).length() > max_dv {
                out.beyond_limits += 1;
            }
            for o in &sc.obstacles {
                if o.distance_normal(pi).0 < r {
                    out.obstacle_contacts += 1;
                }
            }
            for a in &w.agents[i + 1..] {
                let d2 = (v34(a.position) - pi).length_squared();
                min2 = min2.min(d2);
                if d2 < 4.0 * r * r {
                    out.overlap_pair_steps += 1;
                }
            }
        }
        out.min_distance = min2.sqrt();
        let all = w.arrived_at.iter().all(Option::is_some);
        if all && w.agents.iter().all(|a| a.velocity.length() < 0.05) {
            rest += 1;
            if rest >= rest_steps {
                break;
            }
        } else {
            rest = 0;
        }
    }
    out.reached = w.arrived_at.iter().filter(|a| a.is_some()).count();
    if out.reached == n {
        out.finish_time = Some(w.arrived_at.iter().flatten().fold(0.0f32, |a, &b| a.max(b)));
    }
    out
}
