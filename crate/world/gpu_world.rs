//! A world as the GPU kernel steps it (docs/DESIGN.md §20): the agents, their
//! goal queues and the settings as flat arrays for storage buffers, or the
//! reason the kernel cannot step this world.
//!
//! The kernel (`web/src/gpu/`) mirrors the world's default step
//! ([`crate::funnelling::controller::ControllerKind::is_ours_unicycle`]: our standard controller on
//! a unicycle without a reverse gear) towards static goals, with avoidance off or with
//! separation between agents ([`AvoidanceMethod::Separation`] without
//! obstacles: the kernel builds the core's hashed neighbour grid,
//! [`crate::base::grid::NeighbourGrid`], by a counting sort and a prefix
//! sum, and plans on the core's cadence); anything else (ORCA, obstacles)
//! is refused here, with the reason, so a page falls back to the workers.
//!
//! With separation the kernel reads the settings the core's pass reads
//! (`crate::avoidance::planning`'s `Pass`), the size of the core's bucket
//! table for this many agents (so that neighbours come in the core's
//! gather order, and ties among equal distances are broken as the core
//! breaks them), the avoider's next step number
//! ([`crate::avoidance::avoider::Avoider::next_step`]) and the commands
//! agents hold between plans ([`GpuWorld::commands`]).
//!
//! The short-range choice ([`crate::funnelling::short_range::decide`]),
//! made once per near static goal at its first update by simulating the
//! ways in, stays on the CPU: the kernel follows the choice every update.
//! Packing a world makes the choice for each agent's current goal when its
//! first update is still to come (as that update would, from the same
//! state); when the kernel moves an agent on to its next goal it marks the
//! choice awaited, and the host makes it from the state after that step
//! ([`GpuWorld::decide_pending`]) before the next one. A host that steps
//! on without making it gets plain funnelling for that goal.
//!
//! Layout, 32-bit words (`f32` unless said):
//! - agents, [`GpuWorld::AGENT_WORDS`] each: `x, y, θ, v, ω`, flags (`u32`,
//!   bit 0: the position met, [`crate::funnelling::goal::FunnelMemory::position_met`];
//!   bit 1: the short-range choice for the current goal awaited from the
//!   host, [`GpuWorld::decide_pending`]), current goal (`u32`), first
//!   goal's index in `goals` (`u32`), goals in the queue (`u32`), goals
//!   entered oriented (`u32`, counted by the kernel), the last mode (`u32`),
//!   the table reads counted (`u32`), then the short-range choice
//!   ([`crate::funnelling::goal::ShortRange`]): the speed cap (0: none) and
//!   the side (`i32`, 0: funnelling);
//! - goals, [`GpuWorld::GOAL_WORDS`] each: `x, y, β, D_tol, ε_tol, speed`,
//!   flags (`u32`: bit 0 halting, bit 1 the End_of_Steering switch rule),
//!   padding;
//! - commands, [`GpuWorld::COMMAND_WORDS`] each, with separation only (else
//!   none): the command an agent holds between its plans, `heading, speed`,
//!   active (`u32`, 1: its last plan changed the funnel's), padding; none
//!   packed (empty) when the avoider keeps none for these agents: every
//!   agent takes its funnel's until it plans;
//! - settings, [`GpuWorld::SETTINGS`] floats, in [`GpuWorld::settings`]'s order.

use crate::avoidance::config::AvoidanceMethod;
use crate::base::vehicle::Integrator;
use crate::base::vehicle::VehicleState;
use crate::funnelling::config::{Aim, Deviations, MuBound};
use crate::funnelling::controller::ControllerKind;
use crate::funnelling::goal::{FunnelMemory, Goal, ShortRange};
use crate::funnelling::short_range::decide;
use crate::funnelling::table::lookup::EtaTable;
use crate::funnelling::table::spec::VehicleScale;
use crate::funnelling::update::Update;
use crate::world::goals::{GoalMotion, SwitchRule};
use crate::world::World;

/// A world's arrays for the GPU kernel (the module's doc gives the layout).
#[derive(Clone, Debug, PartialEq)]
pub struct GpuWorld {
    /// [`GpuWorld::AGENT_WORDS`] words per agent.
    pub agents: Vec<u32>,
    /// [`GpuWorld::GOAL_WORDS`] words per goal.
    pub goals: Vec<u32>,
    /// [`GpuWorld::COMMAND_WORDS`] words per agent with separation, the
    /// commands held between plans; empty: none held.
    pub commands: Vec<u32>,
    /// The vehicle, controller, table and avoidance numbers the kernel reads.
    pub settings: Vec<f32>,
}

/// Why the GPU kernel cannot step a world (shown to the user, who then
/// gets the workers).
pub const CAR_LIKE: &str = "the GPU path steers unicycles only: a car-like vehicle (minimum \
     turning radius above 0) arrives by Dubins manoeuvres, which run in the workers";

impl GpuWorld {
    /// Words per agent.
    pub const AGENT_WORDS: usize = 14;
    /// Agent flags' bit: the short-range choice is awaited from the host.
    pub const PENDING: u32 = 2;
    /// Words per goal.
    pub const GOAL_WORDS: usize = 8;
    /// Words per held command.
    pub const COMMAND_WORDS: usize = 4;
    /// Floats of settings.
    pub const SETTINGS: usize = 33;

    /// Why the kernel cannot step `w`, if it cannot: a car-like vehicle,
    /// another controller or reading, a μ bound other than the turning
    /// radius one, ORCA, obstacles with separation, or a goal that moves.
    #[must_use]
    pub fn refusal(w: &World) -> Option<String> {
        let why = if w.params.car_like() {
            CAR_LIKE
        } else if w.controller != ControllerKind::Standard {
            "the GPU path runs the standard controller only: relaxed funnelling and plain seek run in the workers"
        } else if w.config.deviations() != Deviations::OURS || !w.config.commit_turn {
            "the GPU path runs our reading of the standard controller only: the paper's reading and its switches run in the workers"
        } else if !matches!(w.config.bound, MuBound::TurningRadius { .. }) {
            "the GPU path bounds μ by turning radii only: the literal and constant bounds run in the workers"
        } else if w.avoidance.method == AvoidanceMethod::Orca {
            "the GPU path avoids by separation only: ORCA runs in the workers"
        } else if w.avoidance.method == AvoidanceMethod::Separation && !w.obstacles.is_empty() {
            "the GPU path has no obstacles: separation with obstacles runs in the workers"
        } else if w
            .agents
            .iter()
            .any(|a| a.goals.iter().any(|g| g.motion != GoalMotion::Static))
        {
            "the GPU path steers towards static goals only: moving goals run in the workers"
        } else {
            return None;
        };
        Some(why.to_owned())
    }

    /// The arrays of `w` stepped with `table`.
    ///
    /// # Errors
    /// [`GpuWorld::refusal`]'s reason.
    pub fn of(w: &World, table: &EtaTable) -> Result<Self, String> {
        if let Some(why) = Self::refusal(w) {
            return Err(why);
        }
        let mut agents = Vec::with_capacity(w.agents.len() * Self::AGENT_WORDS);
        let mut goals = Vec::new();
        for a in &w.agents {
            let s = &a.state;
            let first = (goals.len() / Self::GOAL_WORDS) as u32;
            for g in &a.goals {
                let flags = u32::from(g.goal.halting)
                    | (u32::from(g.switch == SwitchRule::EndOfSteering) << 1);
                let q = &g.goal;
                goals.extend(
                    [q.pos.x, q.pos.y, q.beta, q.d_tol, q.eps_tol, q.speed].map(f32::to_bits),
                );
                goals.extend([flags, 0]);
            }
            let sr = match a.goals.get(a.current) {
                Some(g) if !a.memory.short_range.decided => {
                    Self::choose(w, table, a.state, &g.goal, a.memory)
                }
                _ => a.memory.short_range,
            };
            agents.extend([s.pos.x, s.pos.y, s.theta, s.v, s.omega].map(f32::to_bits));
            agents.extend([
                u32::from(a.memory.position_met),
                a.current as u32,
                first,
                a.goals.len() as u32,
                0,
                a.internals.mode as u32,
                0,
                sr.speed_cap.to_bits(),
                i32::from(sr.side) as u32,
            ]);
        }
        let n = w.agents.len();
        let held = &w.avoider.commands;
        let commands = if w.avoidance.method == AvoidanceMethod::Separation && held.len() == n {
            held.iter()
                .flat_map(|c| {
                    [
                        c.heading.to_bits(),
                        c.speed.to_bits(),
                        u32::from(c.active),
                        0,
                    ]
                })
                .collect()
        } else {
            Vec::new()
        };
        Ok(Self {
            agents,
            goals,
            commands,
            settings: Self::settings(w, table, n, w.avoider.next_step()),
        })
    }

    /// The seeded random crowd of [`World::spawn_random`] for the kernel,
    /// without building it in `w` (a million agents fit on a GPU, not in
    /// the lab's world): the same agents bit for bit, each with the first
    /// `goals` goals of its queue (1 to [`crate::world::edit::RANDOM_GOALS`]); `w` gives
    /// the vehicle and settings.
    ///
    /// # Errors
    /// [`GpuWorld::refusal`]'s reason, or the crowd's out-of-range input.
    pub fn random_crowd(
        w: &World,
        table: &EtaTable,
        n: usize,
        seed: u64,
        extent: f32,
        speed: f32,
        goals: usize,
    ) -> Result<Self, String> {
        if let Some(why) = Self::refusal(w) {
            return Err(why);
        }
        let keep = goals.clamp(1, crate::world::edit::RANDOM_GOALS);
        let mut out = Self {
            agents: Vec::with_capacity(n * Self::AGENT_WORDS),
            goals: Vec::with_capacity(n * keep * Self::GOAL_WORDS),
            commands: Vec::new(),
            settings: Self::settings(w, table, n, 0),
        };
        World::random_crowd(&w.params, n, seed, extent, speed, |_, s, queue| {
            let first = (out.goals.len() / Self::GOAL_WORDS) as u32;
            for g in &queue[..keep] {
                let q = &g.goal;
                out.goals.extend(
                    [q.pos.x, q.pos.y, q.beta, q.d_tol, q.eps_tol, q.speed].map(f32::to_bits),
                );
                out.goals.extend([0, 0]);
            }
            let sr = Self::choose(w, table, s, &queue[0].goal, queue[0].fresh_memory());
            out.agents
                .extend([s.pos.x, s.pos.y, s.theta, s.v, s.omega].map(f32::to_bits));
            out.agents.extend([
                0,
                0,
                first,
                keep as u32,
                0,
                3,
                0,
                sr.speed_cap.to_bits(),
                i32::from(sr.side) as u32,
            ]);
        })
        .map_err(|e| e.to_string())?;
        Ok(out)
    }

    /// The short-range choice of the core's first update towards `g` from
    /// state `s` with memory `mem` ([`decide`]).
    fn choose(
        w: &World,
        table: &EtaTable,
        mut s: VehicleState,
        g: &Goal,
        mut mem: FunnelMemory,
    ) -> ShortRange {
        decide(
            &w.config,
            &mut Update {
                table,
                params: &w.params,
                state: &mut s,
                goal: g,
                memory: &mut mem,
            },
        );
        mem.short_range
    }

    /// Makes the short-range choice the kernel awaits ([`GpuWorld::PENDING`])
    /// for each agent of `agents` (words as the kernel left them after a
    /// step) towards its current goal in `goals`, from the agent's state
    /// and a goal's fresh memory, as the core's first update towards it
    /// does; `w` gives the vehicle and settings. Returns how many were made.
    pub fn decide_pending(w: &World, table: &EtaTable, agents: &mut [u32], goals: &[u32]) -> u32 {
        let f = f32::from_bits;
        let mut made = 0;
        for a in agents.chunks_exact_mut(Self::AGENT_WORDS) {
            if a[5] & Self::PENDING == 0 {
                continue;
            }
            a[5] &= !Self::PENDING;
            if a[6] >= a[8] {
                continue;
            }
            let at = (a[7] + a[6]) as usize * Self::GOAL_WORDS;
            let Some(q) = goals.get(at..at + Self::GOAL_WORDS) else {
                continue;
            };
            let g = Goal {
                pos: glam::Vec2::new(f(q[0]), f(q[1])),
                beta: f(q[2]),
                d_tol: f(q[3]),
                eps_tol: f(q[4]),
                speed: f(q[5]),
                halting: q[6] & 1 == 1,
                vel: glam::Vec2::ZERO,
            };
            let s = VehicleState::new(glam::Vec2::new(f(a[0]), f(a[1])), f(a[2]), f(a[3]), f(a[4]));
            let sr = Self::choose(w, table, s, &g, FunnelMemory::default());
            a[12] = sr.speed_cap.to_bits();
            a[13] = i32::from(sr.side) as u32;
            made += 1;
        }
        made
    }

    /// The settings: the vehicle (`dt, v_max, accel_max, ω_max, ω̇_max, A,
    /// kp, kd`, the integrator 0 explicit / 1 semi-implicit Euler), the
    /// funnel (gain, seek threshold, the bound's factor and smallest radius,
    /// the terminal pursuit's lookahead, heading (−1: off) and range, 1 for
    /// the entry aim), the vehicle's scale (length, speed, time), the
    /// table's reach radius, `D_η` and lowest desired speed, and the
    /// speed term of [`FunnelMemory::release_radius`]; then the avoidance
    /// ([`GpuWorld::avoidance_settings`]) for `n` agents whose first step
    /// is the avoider's step number `step`.
    #[must_use]
    pub fn settings(w: &World, table: &EtaTable, n: usize, step: u32) -> Vec<f32> {
        let mut out = Self::funnel_settings(w, table);
        out.extend(Self::avoidance_settings(w, n, step));
        out
    }

    /// The avoidance's settings as the core's pass reads them
    /// (`crate::avoidance::planning`'s `Pass`): 1 for separation (0: off),
    /// the radius avoided with (body plus margin), the reach squared, the
    /// grid's inverse cell (`1 / reach`, as `NeighbourGrid::rebuild`
    /// computes it), the neighbours kept (at most
    /// [`crate::avoidance::orca::MAX_NEIGHBOURS`]), the separation weight,
    /// the planning cadence (at least 1), the bucket count of the core's
    /// grid for `n` agents (`(4n)` rounded up to a power of two, at least
    /// 64) and the first step's number `step`.
    #[must_use]
    pub fn avoidance_settings(w: &World, n: usize, step: u32) -> [f32; 9] {
        let c = &w.avoidance;
        let on = c.method == AvoidanceMethod::Separation;
        let every = c.replan_every.max(1);
        [
            if on { 1.0 } else { 0.0 },
            c.radius + c.margin,
            c.reach * c.reach,
            1.0 / c.reach,
            (c.max_neighbours as usize).min(crate::avoidance::orca::MAX_NEIGHBOURS) as f32,
            c.separation_weight,
            every as f32,
            (4 * n).next_power_of_two().max(64) as f32,
            (step % every) as f32,
        ]
    }

    /// The vehicle, funnel and table settings ([`GpuWorld::settings`]'s first 24).
    fn funnel_settings(w: &World, table: &EtaTable) -> Vec<f32> {
        let p = &w.params;
        let c = &w.config;
        let sc = VehicleScale::of(p);
        let factor = match c.bound {
            MuBound::TurningRadius { factor } => factor,
            _ => 0.0,
        };
        let (look, heading, range) = c
            .terminal
            .map_or((0.0, -1.0, 0.0), |t| (t.lookahead, t.heading, t.range));
        let semi = if p.integrator == Integrator::SemiImplicitEuler {
            1.0
        } else {
            0.0
        };
        vec![
            p.dt,
            p.v_max,
            p.accel_max,
            p.omega_max,
            p.omega_accel_max,
            p.normal_accel_max,
            p.kp,
            p.kd,
            semi,
            c.gain,
            c.seek_threshold,
            factor,
            c.min_bound_radius,
            look,
            heading,
            range,
            if c.aim == Aim::Entry { 1.0 } else { 0.0 },
            sc.length,
            sc.speed,
            sc.time(),
            table.params().reach_radius,
            table.d_eta(),
            table.axis(4)[0],
            // The release radius's speed term (FunnelMemory::release_radius
            // less its 2·D_tol): the same for every goal of the world.
            FunnelMemory::release_radius(
                p,
                &crate::funnelling::goal::Goal {
                    d_tol: 0.0,
                    ..Default::default()
                },
            ),
        ]
    }
}

#[cfg(all(test, not(target_arch = "wasm32")))]
mod tests {
    use super::*;
    use crate::base::vehicle::VehicleParams;
    use crate::funnelling::config::FunnelConfig;

    fn table() -> EtaTable {
        let bytes = std::fs::read(concat!(env!("CARGO_MANIFEST_DIR"), "/tables/eta.bin")).unwrap();
        EtaTable::from_bytes(&bytes).unwrap()
    }

    /// The choice in an agent's words.
    fn words(agents: &[u32], i: usize) -> (f32, i32) {
        let a = &agents[i * GpuWorld::AGENT_WORDS..];
        (f32::from_bits(a[12]), a[13] as i32)
    }

    fn of(sr: ShortRange) -> (f32, i32) {
        (sr.speed_cap, i32::from(sr.side))
    }

    /// With separation the kernel gets the core's pass settings, the
    /// grid's bucket count, the avoider's next step and the commands held;
    /// ORCA and obstacles are refused.
    #[test]
    fn separation_is_packed_and_orca_and_obstacles_are_refused() {
        use crate::avoidance::config::{AvoidanceConfig, Obstacle};
        let t = table();
        let mut w = World::new(VehicleParams::default(), FunnelConfig::default()).unwrap();
        w.spawn_random(300, 5, 6.0, 1.3).unwrap();
        let sep = AvoidanceConfig::with_method(AvoidanceMethod::Separation);
        w.set_avoidance(sep, Vec::new()).unwrap();
        let fresh = GpuWorld::of(&w, &t).unwrap();
        assert!(fresh.commands.is_empty(), "no command held before a step");
        for _ in 0..3 {
            w.step(&t).unwrap();
        }
        let g = GpuWorld::of(&w, &t).unwrap();
        assert_eq!(g.settings.len(), GpuWorld::SETTINGS);
        let s = &g.settings[24..];
        assert_eq!(s[0], 1.0);
        assert_eq!(s[1], sep.radius + sep.margin);
        assert_eq!(s[2], sep.reach * sep.reach);
        assert_eq!(s[3], 1.0 / sep.reach);
        assert_eq!(s[4], sep.max_neighbours as f32);
        assert_eq!(s[6], sep.replan_every as f32);
        assert_eq!(s[7], 2048.0, "4 × 300 rounded up to a power of two");
        assert_eq!(s[8], (3 % sep.replan_every) as f32);
        assert_eq!(g.commands.len(), 300 * GpuWorld::COMMAND_WORDS);
        let active = g.commands.chunks_exact(4).filter(|c| c[2] == 1).count();
        assert!(active > 0, "some agents are pushed");
        for (c, h) in g.commands.chunks_exact(4).zip(&w.avoider.commands) {
            assert_eq!(
                (f32::from_bits(c[0]), f32::from_bits(c[1])),
                (h.heading, h.speed)
            );
        }
        let orca = AvoidanceConfig::with_method(AvoidanceMethod::Orca);
        w.set_avoidance(orca, Vec::new()).unwrap();
        assert!(GpuWorld::refusal(&w).unwrap().contains("ORCA"));
        let disc = Obstacle::Disc {
            x: 0.0,
            y: 0.0,
            radius: 1.0,
        };
        w.set_avoidance(sep, vec![disc]).unwrap();
        assert!(GpuWorld::refusal(&w).unwrap().contains("obstacles"));
        w.set_avoidance(AvoidanceConfig::default(), vec![disc])
            .unwrap();
        assert_eq!(GpuWorld::refusal(&w), None, "off: obstacles are not read");
    }

    #[test]
    fn the_packed_and_the_awaited_choices_are_the_cores_own() {
        let t = table();
        let mut w = World::new(VehicleParams::default(), FunnelConfig::default()).unwrap();
        // A small square: most goals are near, many turned first.
        w.spawn_random(200, 3, 4.0, 1.3).unwrap();
        let packed = GpuWorld::of(&w, &t).unwrap();
        w.step(&t).unwrap();
        let mut turned = 0;
        for (i, a) in w.agents.iter().enumerate() {
            if a.current == 0 {
                assert_eq!(
                    words(&packed.agents, i),
                    of(a.memory.short_range),
                    "agent {i}"
                );
                turned += usize::from(a.memory.short_range.side != 0);
            }
        }
        assert!(turned > 0, "no agent turns first");
        // Goals moved on to: awaited after the kernel's step, made by the
        // host from the state after it, as the core's next update makes it.
        let mut moved = 0;
        for _ in 0..600 {
            let before: Vec<usize> = w.agents.iter().map(|a| a.current).collect();
            w.step(&t).unwrap();
            let mut g = GpuWorld::of(&w, &t).unwrap();
            let switched: Vec<usize> = (0..w.agents.len())
                .filter(|&i| w.agents[i].current != before[i] && !w.agents[i].done())
                .collect();
            for &i in &switched {
                let a = &mut g.agents[i * GpuWorld::AGENT_WORDS..];
                a[5] |= GpuWorld::PENDING;
                a[12] = 0;
                a[13] = 0;
            }
            let made = GpuWorld::decide_pending(&w, &t, &mut g.agents, &g.goals);
            assert_eq!(made as usize, switched.len());
            let now: Vec<usize> = w.agents.iter().map(|a| a.current).collect();
            w.step(&t).unwrap();
            for &i in switched.iter().filter(|&&i| w.agents[i].current == now[i]) {
                assert_eq!(words(&g.agents, i), of(w.agents[i].memory.short_range));
                assert_eq!(
                    g.agents[i * GpuWorld::AGENT_WORDS + 5] & GpuWorld::PENDING,
                    0
                );
            }
            moved += switched.len();
        }
        assert!(moved > 0, "no agent moved on to a goal");
    }
}
