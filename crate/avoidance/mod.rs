//! Avoidance between moving funnelling agents and of static obstacles
//! (paper 000 §7 and 001 §7 name it as the next step): agents that still
//! arrive at their targets oriented, once the way is clear.
//!
//! | module | source | what |
//! |---|---|---|
//! | [`config`] | — | the method (off, separation, ORCA), body radius and settings; disc and segment obstacles; their validation |
//! | [`orca`] | van den Berg et al. 2011 (RVO2) | the agents' and obstacles' half-planes, the 2D and 3D linear programs; why not `dodgy_2d` |
//! | [`stalled`] | — | agents at rest in a jam: they seek their goal's direction (the funnel's γ turns with them), and the keep-right bias never points into a wall |
//! | [`passing`] | — | keep right early: the funnel's velocity turned right by oncoming neighbours anywhere in reach and moving ones up to 8 m ahead, and an agent turning into its lane beside a mate drops back behind it, so that groups meeting head on pass in lanes |
//! | [`patience`] | — | an agent stalled in a jam for 3 s gives up its margin (keeps only the bodies' clearance) until it moves: a forward-only vehicle cannot back out of a jam packed at the margins |
//! | [`avoider`] | — | one pass, in phases: held commands, the grid and the agents' records, then each planning agent's obstacles and way sought, neighbours gathered and ranked, the method's command |
//! | [`planning`] | — | what one agent's plan reads: the pass's settings, the planning agent and the way it seeks; the speed an agent steps aside at |
//! | `neighbours.rs` | — | the agents' records in the grid's bucket order, the candidates in reach gathered four at a time, the k nearest ranked by a sorting network |
//! | [`orca_plan`] | van den Berg et al. 2011 | ORCA's command: the obstacles' and neighbours' half-planes with right of way by progress, the way sought or the linear program's velocity |
//! | [`keep_right`] | — | the keep-right rule in a plan: the look ahead, the turn into the lane, the velocity turned right by an oncoming neighbour |
//! | `separation.rs` | — | separation's command: a push away from what is too near |
//! | [`command`] | — | what an agent is told to do, and the method's velocity turned into an admissible heading and speed of the forward-only unicycle |
//!
//! Above them, in `world`: the world's step with avoidance
//! (`world::avoid_step`: plan every funnel, avoid, step) and what a run is
//! measured by (`world::proximity`); in `studies`, the benchmark scenarios
//! and the seeded study behind `steer avoid` (`studies::avoidance`).

pub mod avoider;
pub mod command;
pub mod config;
pub mod keep_right;
mod neighbours;
pub mod orca;
pub mod orca_plan;
pub mod passing;
pub mod patience;
pub mod planning;
mod separation;
pub mod stalled;
