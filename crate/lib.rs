//! # steering — the steering lab's core
//!
//! A pure, deterministic (f32, [`glam`]) implementation of four source texts
//! (see `../shared/DESIGN.md` and the README's map), in layers, each folder
//! using only the ones above it in this table (`tests/layers.rs` reads the
//! `use` lines and fails on an import that goes up or round in a cycle):
//!
//! | folder | paper | what |
//! |---|---|---|
//! | [`base`] | — | angles, deterministic trig, seeded random numbers, the vehicle and its limits, validation ranges, the neighbour grid, path metrics, Dubins paths |
//! | [`funnelling`] | 000, 001 | funnelling and relaxed funnelling of one agent towards an oriented target, the η table |
//! | [`avoidance`] | 000 §7, 001 §7 | funnelling agents that avoid each other and static obstacles: separation or ORCA, adapted to the unicycle |
//! | [`crowd`] | 003 | crowded path following: Reynolds vs Parker seek with separation |
//! | [`wander`] | 004 | the random steering toolkit, seven components |
//! | [`world`] | 000 §6 | many agents with goal queues, stepped with or without avoidance; world edits, the split step, scenario files |
//! | `studies` | 000 §5, 001 §5 | the seeded studies behind the figures: reach, envelope, region, vehicle, avoidance benchmarks (feature `studies`, not in the page's wasm) |
//! | `bindings` | — | the JavaScript boundary (WebAssembly builds only) |
//! | `cli` | — | the command lines' arguments, parsed with clap (native only) |
//!
//! The `bindings` module is the only place that knows about JavaScript;
//! everything else runs the same natively and in WebAssembly. Each module
//! has one path (`steering::funnelling::funnel`, `steering::base::angle`,
//! …), with no re-exports at the root.

#![deny(unsafe_code)]
#![warn(missing_docs, clippy::all)]

pub mod avoidance;
pub mod base;
#[cfg(all(feature = "cli", not(target_arch = "wasm32")))]
pub mod cli;
pub mod crowd;
pub mod funnelling;
#[cfg(feature = "studies")]
pub mod studies;
pub mod wander;
pub mod world;

/// The JavaScript boundary (WebAssembly builds only).
#[cfg(target_arch = "wasm32")]
pub mod bindings;
