//! The envelope sampled: the values drawn ([`D_TOLS`], [`SPEEDS`], …),
//! the groups of scenarios ([`GoalKind`]) and the seeded study that draws
//! the `i`-th scenario of a group, the same for every variant.

use core::f32::consts::PI;

use glam::Vec2;
use serde::Serialize;

use crate::base::rng::Rng;
use crate::base::vehicle::{VehicleParams, VehicleState};
use crate::funnelling::goal::Goal;
use crate::funnelling::table::spec::VehicleScale;
use crate::world::{goals::GoalMotion, goals::GoalSpec, goals::SwitchRule};

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
