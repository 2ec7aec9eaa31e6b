//! One path per concept for a program that uses the core:
//! `use steering::prelude::*;` brings what it takes to build a vehicle, get
//! its η table, give agents oriented goals and step them, alone or in a
//! world, or to run a scenario file. Each item keeps its one home in its
//! layer (linked below); the prelude only gathers them.
//!
//! | concept | item | home |
//! |---|---|---|
//! | vector (re-exported [`glam`], so you need not match its version) | [`Vec2`] | [`glam`] |
//! | the vehicle: limits and gains, its state | [`VehicleParams`], [`VehicleState`], [`Integrator`] | [`crate::base::vehicle`] |
//! | the η table | [`EtaTable`] ([`EtaTable::for_vehicle`]), [`TableSpec`] (other sizes) | [`crate::funnelling::table`] |
//! | an oriented goal and the agent's memory of it | [`Goal`], [`FunnelMemory`] | [`crate::funnelling::goal`] |
//! | one controller update of one agent | [`Update`], [`Internals`], [`Mode`] | [`crate::funnelling::update`] |
//! | the controllers' settings | [`FunnelConfig`], [`RelaxedConfig`], [`ControllerKind`] | [`crate::funnelling`] |
//! | a goal in a queue: its motion and when the next takes over | [`GoalSpec`], [`GoalMotion`], [`SwitchRule`] | [`crate::world::goals`] |
//! | many agents stepped together | [`World`], [`Agent`], [`StateField`], [`STATE_STRIDE`] | [`crate::world`] |
//! | avoidance between agents and of obstacles | [`AvoidanceConfig`], [`AvoidanceMethod`], [`Obstacle`] | [`crate::avoidance::config`] |
//! | scenario files | [`Scenario`] | [`crate::world::scenario`] |
//! | why something was refused | [`ParamError`], [`TableError`], [`EditError`], [`ScenarioError`] | their modules |
//!
//! # Units
//! Rust values are SI with angles in **radians**: positions m, speeds m/s,
//! headings θ and orientations β rad, angular speeds rad/s, tolerances
//! `d_tol` m and `eps_tol` rad, times s. Every field's documentation
//! names its unit. Files (scenarios, vehicle files) use the same units
//! except the angles whose key ends in `Deg` (`thetaDeg`, `betaDeg`,
//! `epsTolDeg`, the avoidance's `biasDeg`), which are degrees; the
//! scenario types convert ([`GoalFile::to_spec`]). From degrees in code:
//! `f32::to_radians`, e.g. `Goal { beta: 90f32.to_radians(), ..Goal::default() }`.
//!
//! [`GoalFile::to_spec`]: crate::world::scenario::GoalFile::to_spec
//!
//! ```
//! use steering::prelude::*;
//!
//! let goal = Goal {
//!     pos: Vec2::new(6.0, 3.0),
//!     beta: 90f32.to_radians(), // facing +y
//!     eps_tol: 5f32.to_radians(),
//!     ..Goal::default()
//! };
//! assert!(goal.validate(&VehicleParams::default()).is_ok());
//! ```

pub use glam::Vec2;

pub use crate::avoidance::config::{AvoidanceConfig, AvoidanceMethod, Obstacle};
pub use crate::base::vehicle::{Integrator, ParamError, VehicleParams, VehicleState};
pub use crate::funnelling::config::FunnelConfig;
pub use crate::funnelling::controller::ControllerKind;
pub use crate::funnelling::goal::{FunnelMemory, Goal};
pub use crate::funnelling::relaxed::RelaxedConfig;
pub use crate::funnelling::table::format::TableError;
pub use crate::funnelling::table::lookup::EtaTable;
pub use crate::funnelling::table::spec::TableSpec;
pub use crate::funnelling::update::{Internals, Mode, Update};
pub use crate::world::edit::EditError;
pub use crate::world::goals::{GoalMotion, GoalSpec, SwitchRule};
pub use crate::world::scenario::{Scenario, ScenarioError};
pub use crate::world::{Agent, StateField, World, STATE_STRIDE};
