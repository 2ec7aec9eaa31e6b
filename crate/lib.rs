//! # steering — the steering lab's core
//!
//! Steering for forward-only vehicles (a unicycle with speed, turn rate and
//! acceleration limits: a pedestrian, a car, a robot) towards **oriented
//! targets**: a position *and* a heading to arrive with, within tolerances,
//! at constant cost per update. It implements four papers (funnelling,
//! relaxed funnelling, crowded path following, random steering) as pure,
//! deterministic Rust (`f32`, [`glam`]): the same inputs give the same bits
//! natively and in WebAssembly, on one thread or many.
//!
//! What the core offers:
//! - **Funnelling** (paper 000): one agent steered to a target pose. A
//!   precomputed *η table* predicts where plain seek steering would arrive;
//!   the controller bends its heading by a bounded amount to arrive facing
//!   the target orientation β. [`EtaTable::for_vehicle`](funnelling::table::lookup::EtaTable::for_vehicle)
//!   gives the table of any vehicle.
//! - **Relaxed funnelling** (paper 001): region goals, a disk and an
//!   interval of headings, reached sooner.
//! - **Worlds** of many agents with goal queues, moving goals, goals that
//!   face other agents, avoidance (separation or ORCA) and static
//!   obstacles, scenario files; natively stepped on every core.
//! - **Crowds** following paths (paper 003) and **random steering**
//!   (paper 004).
//!
//! # Layers
//! Each folder uses only the ones above it in this table
//! (`tests/layers.rs` reads the `use` lines and fails on an import that
//! goes up or round in a cycle):
//!
//! | folder | paper | what |
//! |---|---|---|
//! | [`base`] | — | angles, deterministic trig, seeded random numbers, the vehicle and its limits, validation ranges, the neighbour grid, path metrics, Dubins and Reeds–Shepp paths, the parallel loops |
//! | [`funnelling`] | 000, 001 | funnelling and relaxed funnelling of one agent towards an oriented target, the η table |
//! | [`avoidance`] | 000 §7, 001 §7 | funnelling agents that avoid each other and static obstacles: separation or ORCA, adapted to the unicycle |
//! | [`crowd`] | 003 | crowded path following: Reynolds vs Parker seek with separation |
//! | [`wander`] | 004 | the random steering toolkit, seven components |
//! | [`world`] | 000 §6 | many agents with goal queues, stepped with or without avoidance; world edits, the split step, scenario files |
#![cfg_attr(
    feature = "studies",
    doc = "| [`studies`] | 000 §5, 001 §5 | the seeded studies behind the figures: reach, envelope, region, vehicle, avoidance benchmarks (feature `studies`) |"
)]
#![cfg_attr(
    not(feature = "studies"),
    doc = "| `studies` | 000 §5, 001 §5 | the seeded studies behind the figures: reach, envelope, region, vehicle, avoidance benchmarks (feature `studies`) |"
)]
//! | `bindings` | — | the JavaScript boundary (WebAssembly builds only; the npm package `steering-core`) |
//! | `cli` | — | the command lines' arguments, parsed with clap (feature `cli`, native only) |
//!
//! The `bindings` module is the only place that knows about JavaScript;
//! everything else runs the same natively and in WebAssembly. Each item
//! has one home (`steering::funnelling::funnel`, `steering::base::angle`,
//! …); the [`prelude`] gathers what a program using the core needs, and
//! [`glam`] is re-exported so its version always matches.
//!
//! # Guide
//! Angles are radians in Rust and degrees in files (keys ending in `Deg`):
//! see the [`prelude`]'s units.
//!
//! **A vehicle.** [`VehicleParams`](base::vehicle::VehicleParams) holds the
//! limits and the seek gains; the default is a walking pedestrian. The
//! reference car and robot come from [`funnelling::vehicle_file`], and any
//! other vehicle is a struct literal, validated:
//!
//! ```
//! use steering::prelude::*;
//! use steering::funnelling::vehicle_file;
//!
//! let pedestrian = VehicleParams::default();
//! let car = vehicle_file::reference("car").expect("a reference vehicle").vehicle;
//! assert!(car.v_max > pedestrian.v_max);
//! let jogger = VehicleParams { v_max: 3.0, ..VehicleParams::default() };
//! jogger.validate()?;
//! # Ok::<(), ParamError>(())
//! ```
//!
//! **Its η table.** [`EtaTable::for_vehicle`](funnelling::table::lookup::EtaTable::for_vehicle)
//! returns the pedestrian's table compiled into the library (feature
//! `embedded-table`, on by default) and generates any other vehicle's, on
//! every core (about a second; keep the table and share it by reference):
//!
//! ```
//! use steering::prelude::*;
//!
//! let table = EtaTable::for_vehicle(&VehicleParams::default())?;
//! assert_eq!(table.len(), 362_880);
//! # Ok::<(), TableError>(())
//! ```
//!
//! **An agent in a world, to an oriented target.** A [`World`](world::World)
//! holds agents with goal queues ([`GoalSpec`](world::goals::GoalSpec): the
//! [`Goal`](funnelling::goal::Goal), its motion and when the next goal takes
//! over). [`World::step`](world::World::step) refuses a table built for
//! other limits, and the agents are read through
//! [`World::agents`](world::World::agents) and changed only through the
//! world's edits, which validate; a halting goal ends with the agent
//! [at rest](world::Agent::at_rest) inside both tolerances:
//!
//! ```
//! use steering::prelude::*;
//!
//! let p = VehicleParams::default();
//! let table = EtaTable::for_vehicle(&p)?;
//! let mut world = World::new(p, FunnelConfig::default())?;
//! let target = Goal {
//!     pos: Vec2::new(8.0, 4.0),
//!     beta: 90f32.to_radians(), // arrive heading +y
//!     halting: true,            // and stop there
//!     ..Goal::default()         // D_tol 0.25 m, ε_tol 5°, 1.3 m/s
//! };
//! let start = VehicleState::new(Vec2::ZERO, 0.0, 0.0, 0.0);
//! world.add_agent(start, vec![GoalSpec { goal: target, ..GoalSpec::default() }])?;
//! while !world.agents()[0].at_rest() {
//!     world.step(&table)?;
//!     assert!(world.time() < 60.0, "arrives within a minute");
//! }
//! let s = world.agents()[0].state;
//! assert!((s.pos - target.pos).length() < target.d_tol);
//! assert!(steering::base::angle::diff(target.beta, s.theta).abs() < target.eps_tol);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```
//!
//! **One agent, no world.** The controller itself steps one state through
//! an [`Update`](funnelling::update::Update) (the table, the limits, the
//! agent's state, goal and memory of that goal) and reports the
//! [`Mode`](funnelling::update::Mode) of paper 000 Fig. 5:
//!
//! ```
//! use steering::prelude::*;
//!
//! let p = VehicleParams::default();
//! let table = EtaTable::for_vehicle(&p)?;
//! let controller = FunnelConfig::default();
//! let goal = Goal { pos: Vec2::new(-5.0, 6.0), beta: 0.0, ..Goal::default() };
//! let (mut state, mut memory) = (VehicleState::default(), FunnelMemory::default());
//! let mut steps = 0;
//! loop {
//!     let mut u = Update { table: &table, params: &p, state: &mut state, goal: &goal, memory: &mut memory };
//!     if controller.step(&mut u).mode == Mode::EndOfSteering {
//!         break;
//!     }
//!     steps += 1;
//!     assert!(steps < 60 * 60, "arrives within a minute");
//! }
//! assert!((state.pos - goal.pos).length() < goal.d_tol);
//! # Ok::<(), TableError>(())
//! ```
//!
//! **A scenario file** ([`world::scenario`]: agents, goal queues, vehicle,
//! controller, avoidance, obstacles; angles in degrees):
//!
//! ```
//! use steering::prelude::*;
//!
//! let scenario = Scenario::from_json(r#"{
//!     "name": "two crossing", "duration": 30,
//!     "agents": [
//!         {"x": -6, "y": 0, "goals": [{"x": 6, "y": 0, "betaDeg": 90}]},
//!         {"x": 0, "y": -6, "thetaDeg": 90, "goals": [{"x": 0, "y": 6, "betaDeg": 180}]}
//!     ]
//! }"#)?;
//! let table = EtaTable::for_vehicle(&scenario.vehicle)?;
//! let mut world = scenario.world()?;
//! for _ in 0..scenario.steps() {
//!     world.step(&table)?;
//! }
//! assert!(world.agents().iter().all(Agent::done));
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```
//!
//! **Threads.** Natively [`World::step`](world::World::step) updates the
//! agents of a big world on every core of the current rayon pool, to the
//! same bits as one thread; step inside a pool's `install` to choose the
//! threads. Worlds hold at most [`World::max_agents`](world::World::max_agents)
//! agents (a million unless set).
//!
//! **Features.** `studies` (default): the seeded studies behind the
//! figures. `embedded-table` (default): the pedestrian's η table compiled
//! in. `cli`: the command lines and clap. A library user needs neither
//! `cli` nor, if it builds or loads its own tables, the other two.

#![deny(unsafe_code)]
#![deny(missing_docs)]
#![warn(clippy::all)]

pub mod avoidance;
pub mod base;
#[cfg(all(feature = "cli", not(target_arch = "wasm32")))]
pub mod cli;
pub mod crowd;
pub mod funnelling;
pub mod prelude;
#[cfg(feature = "studies")]
pub mod studies;
pub mod wander;
pub mod world;

/// The vector type of the public API (`Vec2`), re-exported so that a
/// user's glam is always this crate's version.
pub use glam;

// Documented by its own inner doc: an outer doc here would make rustdoc
// resolve that module's links from the crate root.
#[cfg(target_arch = "wasm32")]
pub mod bindings;
