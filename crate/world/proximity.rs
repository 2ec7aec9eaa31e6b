//! What an avoidance run is measured by, accumulated step by
//! step: the smallest distance between two agents' centres, overlapping
//! pairs (centres closer than two body radii; counted per step), contacts
//! with obstacles (closer than one radius), deadlocks (an agent not
//! finished and slower than 0.05 m/s for 10 s in a row), and whether each
//! goal's tolerance disk was entered oriented (|θ − β| ≤ ε_tol at the
//! first step inside it, or the goal completed). Pairs are found through
//! the neighbour grid ([`crate::base::grid`]), so measuring costs about
//! as much as avoiding.

use crate::base::angle::diff;
use crate::base::grid::NeighbourGrid;
use crate::world::World;

/// Speed under which an unfinished agent counts as stuck, m/s.
pub const DEADLOCK_SPEED: f32 = 0.05;
/// How long it must stay stuck to count as a deadlock, s.
pub const DEADLOCK_TIME: f32 = 10.0;

/// Running proximity measures of a world.
#[derive(Clone, Debug, Default)]
pub struct Proximity {
    grid: NeighbourGrid,
    pos: Vec<f32>,
    radius: f32,
    /// Smallest distance between two agents' centres so far, m (∞ while no
    /// two came within four radii).
    pub min_distance: f32,
    /// Σ over steps of the pairs closer than two radii.
    pub overlap_pair_steps: u64,
    /// Most pairs overlapping at one step.
    pub max_overlapping: u64,
    /// Σ over steps of the agents closer than one radius to an obstacle.
    pub obstacle_contact_steps: u64,
    slow: Vec<f32>,
    /// Per agent: stuck for [`DEADLOCK_TIME`] at some point while unfinished.
    pub deadlocked: Vec<bool>,
    seen_goal: Vec<usize>,
    recorded: Vec<bool>,
    /// Goal entries judged.
    pub entries: u32,
    /// Of those, entered oriented.
    pub oriented: u32,
}

impl Proximity {
    /// Measures agents of body radius `radius`.
    #[must_use]
    pub fn new(radius: f32) -> Self {
        Self {
            radius,
            min_distance: f32::INFINITY,
            ..Self::default()
        }
    }

    /// Agents deadlocked at some point.
    #[must_use]
    pub fn deadlocks(&self) -> usize {
        self.deadlocked.iter().filter(|&&d| d).count()
    }

    /// Adds the world's state after a step.
    pub fn observe(&mut self, w: &World) {
        let n = w.agents.len();
        if self.slow.len() != n {
            self.slow = vec![0.0; n];
            self.deadlocked = vec![false; n];
            self.seen_goal = vec![0; n];
            self.recorded = vec![false; n];
        }
        self.pos.clear();
        for a in &w.agents {
            self.pos.push(a.state.pos.x);
            self.pos.push(a.state.pos.y);
        }
        let reach = 4.0 * self.radius;
        self.grid.rebuild(&self.pos, reach);
        let touch2 = 4.0 * self.radius * self.radius;
        let mut pairs = 0u64;
        let mut min2 = self.min_distance * self.min_distance;
        for i in 0..n {
            self.grid
                .for_each_neighbour(&self.pos, i, reach, |j, _, d2| {
                    if j > i {
                        min2 = min2.min(d2);
                        if d2 < touch2 {
                            pairs += 1;
                        }
                    }
                });
        }
        self.min_distance = min2.sqrt();
        self.overlap_pair_steps += pairs;
        self.max_overlapping = self.max_overlapping.max(pairs);
        let dt = w.params.dt;
        for (i, a) in w.agents.iter().enumerate() {
            for o in &w.obstacles {
                if o.distance_normal(a.state.pos).0 < self.radius {
                    self.obstacle_contact_steps += 1;
                }
            }
            if !a.done() && a.state.v < DEADLOCK_SPEED {
                self.slow[i] += dt;
                if self.slow[i] >= DEADLOCK_TIME {
                    self.deadlocked[i] = true;
                }
            } else {
                self.slow[i] = 0.0;
            }
            // Entries: `goal_now` is the goal this step was steered to (it
            // stays the completed one on the step the queue moves on).
            let g = a.goal_now;
            let completed = a.current > self.seen_goal[i];
            let inside = (a.state.pos - g.pos).length() <= g.d_tol;
            if !self.recorded[i] && !a.goals.is_empty() && (completed || (inside && !a.done())) {
                self.entries += 1;
                if diff(a.state.theta, g.beta).abs() <= g.eps_tol + 1e-6 {
                    self.oriented += 1;
                }
                self.recorded[i] = true;
            }
            if completed {
                self.seen_goal[i] = a.current;
                self.recorded[i] = false;
            }
        }
    }
}
