//! The JavaScript boundary (WebAssembly builds only): the one place that
//! knows about wasm-bindgen. Thin by rule: conversion only, every value from
//! JavaScript checked by the core, every error a `JsError`, never a panic.
//!
//! | module | page | what |
//! |---|---|---|
//! | [`lab`] | `index.html` | `Lab`: a funnelling [`World`](crate::world::World) and its η table |
//! | `lab_table` | `index.html` | `Lab`'s η table: its axes, a new one in force, its cache key |
//! | `lab_settings` | `index.html` | `Lab`'s settings: vehicle parameters, funnelling and relaxed settings, readings, the controller's label |
//! | `lab_probes` | `index.html`, `learn.html` | `Lab`'s η probes: the η field and rings (paper 001 Figs. 3, 4), seek simulations against table lookups |
//! | `lab_world` | `index.html` | `Lab`'s world: agents added, posed and given goals, random crowds, stepping, the state records |
//! | `lab_ghost` | `index.html` | `Lab`'s look inside an agent: internals, the ghost path, the η ring at its distance |
//! | `lab_gpu` | `index.html`, `gpu.html` | `Lab` for the GPU kernel: the η table's and the world's arrays as it reads them (or why it cannot step the world), the core's lookups at probes and a run's arrival counts for the parity checks |
//! | `lab_scenario` | `index.html` | `Lab`'s scenarios: a scenario file's world in force |
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
mod lab_ghost;
mod lab_gpu;
mod lab_probes;
mod lab_scenario;
mod lab_settings;
mod lab_table;
mod lab_types;
mod lab_world;
pub mod layout;
mod split;
pub mod tables;
pub mod wander;
