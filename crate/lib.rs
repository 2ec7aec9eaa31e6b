//! # steering — the steering lab's core
//!
//! A pure, deterministic (f32, [`glam`]) implementation of four source texts
//! (see `../shared/DESIGN.md` and the README's map), one folder per text:
//!
//! | folder | paper | what |
//! |---|---|---|
//! | [`avoidance`] | 000 §7, 001 §7 | funnelling agents that avoid each other and static obstacles: separation or ORCA, adapted to the unicycle |
//! | [`funnelling`] | 000, 001 | funnelling and relaxed funnelling towards oriented targets, the η table |
//! | [`crowd`] | 003 | crowded path following: Reynolds vs Parker seek with separation |
//! | [`wander`] | 004 | the random steering toolkit, seven components |
//! | [`base`] | — | angles, deterministic trig, seeded random numbers, path metrics, Dubins paths |
//! | `bindings` | — | the JavaScript boundary (WebAssembly builds only) |
//! | `cli` | — | the command lines' arguments, parsed with clap (native only) |
//!
//! The `bindings` module is the only place that knows about JavaScript;
//! everything else runs the same natively and in WebAssembly. The modules of
//! `funnelling` and `base` are re-exported at the root (`steering::funnelling::funnel`,
//! `steering::base::angle`, …), the paths the tests, benches and README use.

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
