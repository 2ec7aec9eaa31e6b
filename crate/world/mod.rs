//! The world above the controllers (paper 000 §6: moving targets,
//! successive targets, many entities): agents, each with its own state,
//! goal queue and funnelling memory, stepped together, with or without
//! avoidance. Stepping allocates nothing: the only buffer, a snapshot of
//! the agents' states for goals that follow other agents, is sized when
//! agents are added.
//!
//! | module | paper | what |
//! |---|---|---|
//! | `world.rs` | 000 §6 | [`World`]: many agents stepped together, the plain step |
//! | `agent.rs` | 000 §6 | [`Agent`]: one agent's state, goal queue and memory; when it is done and at rest |
//! | `planner.rs` | 000 §6, Fig. 5 | planning one agent towards its current goal, the queue's advance, the [`provisional_plan`] before the η table |
//! | `state_field.rs` | — | the per-agent record the page reads: [`StateField`], [`STATE_STRIDE`] |
//! | [`goals`] | 000 §6 | goal-queue entries: motion (static, linear, circle, facing an agent), switch rule, which goals may halt |
//! | [`edit`] | 000 §6, Fig. 5 | edits of a running world: agents added (under the world's bound), pose reset, new goals (queue and memory restart), the seeded random crowd |
//! | [`avoid_step`] | 000 §7 | the step with avoidance: plan every funnel, avoid, step |
//! | [`split`] | 000 §6, Fig. 6 | a world split into contiguous slices that step alone (facing links kept inside one), for the lab's stepping workers |
//! | [`scenario`] | — | the scenario JSON schema (degrees in files) and its validation: positional arrays refused, agents × steps bounded |
//! | [`precision`] | — | the coordinate range where f32 resolves a quarter of one step (slowest goal speed × dt), measured; checked on every agent and goal |
//! | [`proximity`] | — | avoidance metrics: minimum pairwise distance, overlapping pairs, obstacle contacts, deadlocks, oriented entries |
//! | [`gpu_world`] | 000 §6 | a world as the GPU kernel steps it (agents, goal queues, settings as flat arrays), or why it cannot |
//! | [`entry_judge`] | — | goals left and entered oriented per agent: the verdict a GPU free run is compared on |

mod agent;
pub mod avoid_step;
pub mod edit;
pub mod entry_judge;
pub mod goals;
pub mod gpu_world;
mod planner;
pub mod precision;
pub mod proximity;
pub mod scenario;
pub mod split;
mod state_field;
// A type lives in the file named after it, `World` too.
#[allow(clippy::module_inception)]
mod world;

pub use agent::{Agent, REST_OMEGA};
pub use planner::provisional_plan;
pub use state_field::{StateField, STATE_STRIDE};
pub use world::{World, DEFAULT_MAX_AGENTS, PARALLEL_CHUNK};
