//! The JavaScript boundary (WebAssembly builds only): the one place that
//! knows about wasm-bindgen. Thin by rule: conversion only, every value from
//! JavaScript checked by the core, every error a `JsError`, never a panic.
//!
//! | module | page | what |
//! |---|---|---|
//! | [`lab`] | `index.html` | `Lab`: a funnelling [`World`](crate::world::World) and its η table |
//! | `lab_types` | `index.html` | what crosses for `Lab`: the TypeScript interfaces and their serde shapes (goal, agent, internals, table and scenario info) |
//! | [`tables`] | `index.html` workers | η tables built in the browser: `tableJob` (key, entries), `tableSlice` (a worker's share), `assembleTable` (the file's bytes), `tableKeyOf`, `referenceVehicles` |
//! | [`crowd`] | `crowd.html` | `CrowdLab`: crowded path following (paper 003) |
//! | [`wander`] | `wander.html` | `WanderLab`: the random steering toolkit (paper 004) |
//! | [`avoid`] | `index.html` | `Lab`'s avoidance: the method in force, the obstacles as a flat array for drawing and dragging, the overlap count |
//! | `split` | `index.html` workers | `Lab.splitRanges` / `retainRange`, a world's slices for the stepping workers, and a hash of the state |
//! | `boundary` | — | `from_js` / `to_js` / `js_err`: decoding that names the field at fault |
//! | [`layout`] | all | `Mode`, `StateField`: the core's numbers by name, checked at compile time |

pub mod avoid;
mod boundary;
pub mod crowd;
pub mod lab;
mod lab_types;
pub mod layout;
mod split;
pub mod tables;
pub mod wander;
