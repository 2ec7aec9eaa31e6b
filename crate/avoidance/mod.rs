//! Avoidance between moving funnelling agents and of static obstacles
//! (issue 18; paper 000 §7 and 001 §7 name it as the next step): agents
//! that still arrive at their targets oriented, once the way is clear.
//!
//! | module | source | what |
//! |---|---|---|
//! | [`config`] | — | the method (off, separation, ORCA), body radius and settings; disc and segment obstacles; their validation |
//! | [`orca`] | van den Berg et al. 2011 (RVO2) | the agents' and obstacles' half-planes, the 2D and 3D linear programs; why not `dodgy_2d` |
//! | [`avoider`] | — | one pass: neighbours through the crowd's grid, the method's velocity, turned into an admissible heading and speed of the forward-only unicycle |
//! | [`passing`] | — | keep right early: the funnel's velocity turned right by oncoming neighbours anywhere in reach and moving ones up to 8 m ahead, and an agent turning into its lane beside a mate drops back behind it, so that groups meeting head on pass in lanes (the corridor's deadlocks) |
//! | [`stalled`] | — | agents at rest in a jam: they seek their goal's direction (the funnel's γ turns with them), and the keep-right bias never points into a wall (the corridor's remaining deadlocks) |
//! | [`patience`] | — | an agent stalled in a jam for 3 s gives up its margin (keeps only the bodies' clearance) until it moves: the corridor's, doorway's and circle swap's last deadlocks |
//! | `world_step` | 000 §6 | the world's step with avoidance: plan every funnel, avoid, step |
//! | [`proximity`] | — | metrics: minimum pairwise distance, overlapping pairs, obstacle contacts, deadlocks, oriented entries |
//! | [`benchmarks`] | — | the benchmark scenarios (circle swap, corridor, doorway, paper figures with avoidance) and the seeded study behind `steer avoid` |

pub mod avoider;
pub mod config;
pub mod orca;
pub mod passing;
pub mod patience;
pub mod stalled;
