//! # steering — the steering lab's core
//!
//! A pure, deterministic (f32, [`glam`]) implementation of four source texts
//! (see `../shared/DESIGN.md` and the README's map):
//! funnelling control towards oriented targets, relaxed funnelling towards
//! oriented region goals, crowded path following, and the random steering
//! toolkit. The `bindings` module is the only place that knows about
//! JavaScript; everything else runs the same natively and in WebAssembly.

#![deny(unsafe_code)]
#![warn(missing_docs, clippy::all)]

pub mod angle;
pub mod boid_seek;
pub mod crowd;
pub mod crowd_config;
pub mod crowd_error;
pub mod crowd_metrics;
pub mod dubins;
pub mod funnel;
pub mod grid;
pub mod metrics;
pub mod path;
pub mod path_follow;
pub mod region_study;
pub mod relaxed;
pub mod rng;
pub mod scenario;
pub mod seek;
pub mod separation;
pub mod study;
pub mod table;
pub mod table_gen;
pub mod trig;
pub mod vehicle;
pub mod wander;
pub mod world;

/// The JavaScript boundary (WebAssembly builds only).
#[cfg(target_arch = "wasm32")]
pub mod bindings;
/// The JavaScript boundary of crowded path following (WebAssembly builds only).
#[cfg(target_arch = "wasm32")]
pub mod bindings_crowd;
/// The JavaScript boundary of the random steering toolkit (WebAssembly builds only).
#[cfg(target_arch = "wasm32")]
pub mod bindings_wander;
/// Conversions shared by the binding modules (WebAssembly builds only).
#[cfg(target_arch = "wasm32")]
mod boundary;
